//! `arch-enum atlas`: the JSON contract, and the regions against `solve` at random held-out
//! points away from the boundaries (a point-in-polygon test on the document's polygons
//! against the limit-state search run afresh at that point).

use crate::cli::json_of;
use crate::search_reference::Rng;
use arch_enum::limit_states::survey;
use arch_enum::{least_friction, Arch, Outcome, Settings, WeightModel};
use serde_json::Value;

/// Even-odd ray casting: whether (a, m) lies inside the closed polygon.
fn inside(poly: &[[f64; 2]], a: f64, m: f64) -> bool {
    let mut c = false;
    let n = poly.len();
    for i in 0..n {
        let (p, q) = (poly[i], poly[(i + 1) % n]);
        if (p[1] > m) != (q[1] > m) {
            let x = p[0] + (m - p[1]) * (q[0] - p[0]) / (q[1] - p[1]);
            if a < x {
                c = !c;
            }
        }
    }
    c
}

/// The kinds of the regions holding (a, m) (one where the regions tile the plane).
fn kinds_at(regions: &[(String, Vec<[f64; 2]>)], a: f64, m: f64) -> Vec<String> {
    regions
        .iter()
        .filter(|(_, p)| inside(p, a, m))
        .map(|(k, _)| k.clone())
        .collect()
}

/// The kind `solve` gives at (arch, μ), read from the survey's own fields (`None`: the search
/// did not decide).
fn solve_kind(arch: &Arch, mu: f64) -> Option<&'static str> {
    let sv = survey(arch, mu, &Settings::default()).unwrap();
    if matches!(sv.solution.outcome, Outcome::NoEquilibrium { .. }) {
        return Some("no_equilibrium");
    }
    let Ok(s) = sv.states.as_ref() else {
        // not searched to the end: non-unique where η_s carries a limit state and another
        // was found (as `atlas` classifies it), else undecided
        let at_eta_s = sv.limit_at_eta_s().is_some();
        return (at_eta_s && sv.unique() == Some(false)).then_some("non_unique");
    };
    Some(if !s.mechanism_at_eta_s || !s.attained {
        "no_mechanism_at_eta"
    } else if sv.unique()? {
        "unique"
    } else {
        "non_unique"
    })
}

fn regions_of(doc: &Value) -> Vec<(String, Vec<[f64; 2]>)> {
    doc["regions"]
        .as_array()
        .unwrap()
        .iter()
        .map(|r| {
            let poly: Vec<[f64; 2]> = serde_json::from_value(r["polygon"].clone()).unwrap();
            assert!(poly.len() >= 3, "a polygon of {} vertices", poly.len());
            (r["kind"].as_str().unwrap().to_string(), poly)
        })
        .collect()
}

/// Random (α, μ) in the rectangle, μ = μ_ms (1 + d) with d log-uniform in [1e-4, K − 1] (the
/// polygons follow μ_ms by chords within ~1e-5 at these spacings), and a
/// fifth of them below μ_ms (d in [−0.5, −0.05]); a point is compared only where the regions
/// give one kind at it and at its neighbours (± half a column in α, d scaled by 0.7 and
/// 1.3): away from every boundary.
fn agrees_with_solve(
    flags: &[&str],
    blocks: Option<usize>,
    (a0, a1, k): (f64, f64, f64),
    want: usize,
) {
    let mut args = vec!["atlas"];
    args.extend_from_slice(flags);
    let (doc, code) = json_of(&args);
    assert_eq!(code, 0, "{doc}");
    let regions = regions_of(&doc);
    let columns = doc["rectangle"]["columns"].as_u64().unwrap() as f64;
    let half = 0.5 * (a1 - a0) / (columns - 1.0);
    let mut rng = Rng(0x9e37_79b9_7f4a_7c15 ^ blocks.unwrap_or(0) as u64);
    let (mut compared, mut near, mut undecided) = (0, 0, 0);
    let mut seen = std::collections::BTreeSet::new();
    while compared < want {
        assert!(
            compared + near + undecided < 20 * want,
            "too few points away from the boundaries"
        );
        let alpha = a0 + (a1 - a0) * rng.next();
        let arch_at = |a: f64| {
            let arch = Arch::symmetric(a, WeightModel::Centreline).unwrap();
            blocks.map_or(arch.clone(), |n| arch.with_blocks(n).unwrap())
        };
        let ms_at = |a: f64| {
            least_friction(&arch_at(a), &Settings::default())
                .unwrap()
                .unwrap()
        };
        let (arch, ms) = (arch_at(alpha), ms_at(alpha));
        // d = mu/mu_ms - 1: negative below mu_ms
        let d = if rng.next() < 0.2 {
            -0.5 + 0.45 * rng.next()
        } else {
            1e-4 * ((k - 1.0) / 1e-4).powf(rng.next())
        };
        let mu = ms * (1.0 + d);
        let here = kinds_at(&regions, alpha, mu);
        // the neighbours: half a column either side, d scaled by 0.7 and 1.3 (the samples'
        // spacing is geometric in d)
        let around: Vec<Vec<String>> = [-half, half]
            .iter()
            .flat_map(|&da| {
                let a = (alpha + da).clamp(a0, a1);
                let m = ms_at(a);
                [0.7, 1.3].map(|f| kinds_at(&regions, a, m * (1.0 + d * f)))
            })
            .collect();
        if here.len() != 1 || around.iter().any(|k| *k != here) {
            near += 1;
            continue;
        }
        let Some(kind) = solve_kind(&arch, mu) else {
            undecided += 1;
            continue;
        };
        assert_eq!(
            kind, here[0],
            "alpha = {alpha}, mu = {mu} (mu_ms = {ms}), flags {flags:?}"
        );
        seen.insert(kind);
        compared += 1;
    }
    assert!(
        seen.contains("non_unique") && seen.contains("unique") && seen.contains("no_equilibrium"),
        "{seen:?}"
    );
    eprintln!("atlas {flags:?}: {compared} compared, {near} near a boundary, {undecided} undecided by solve");
}

/// 24 voussoirs over a rectangle that holds the band and the sliver at α = 1.1 (μ/μ_ms ≈
/// 2.142): the regions, with the band's top among their vertices, agree with `solve`.
#[test]
fn voussoir_regions_with_a_sliver_agree_with_solve() {
    agrees_with_solve(
        &[
            "--alpha-min",
            "0.55",
            "--alpha-max",
            "1.15",
            "--columns",
            "25",
            "--mu-max-factor",
            "2.5",
            "--samples",
            "24",
            "--blocks",
            "24",
        ],
        Some(24),
        (0.55, 1.15, 2.5),
        200,
    );
}

#[test]
fn regions_agree_with_solve_away_from_boundaries() {
    // the continuous arch, the horseshoes where the non-unique band lies
    agrees_with_solve(
        &[
            "--alpha-min",
            "0.4",
            "--alpha-max",
            "1.0",
            "--columns",
            "25",
            "--mu-max-factor",
            "1.5",
            "--samples",
            "24",
        ],
        None,
        (0.4, 1.0, 1.5),
        200,
    );
    // twelve voussoirs (the exact sweep), over a wider rectangle
    agrees_with_solve(
        &[
            "--alpha-min",
            "-0.4",
            "--alpha-max",
            "1.1",
            "--columns",
            "31",
            "--mu-max-factor",
            "3",
            "--samples",
            "24",
            "--blocks",
            "12",
        ],
        Some(12),
        (-0.4, 1.1, 3.0),
        150,
    );
}

#[test]
fn the_contract() {
    let (doc, code) = json_of(&[
        "atlas",
        "--alpha-min",
        "0.6",
        "--alpha-max",
        "0.8",
        "--columns",
        "5",
        "--mu-max-factor",
        "1.2",
        "--samples",
        "12",
    ]);
    assert_eq!(code, 0);
    for key in [
        "version",
        "status",
        "weight",
        "blocks",
        "rectangle",
        "regions",
        "boundaries",
        "undecided",
        "columns",
    ] {
        assert!(doc.get(key).is_some(), "missing {key}");
    }
    let kinds = [
        "unique",
        "non_unique",
        "no_mechanism_at_eta",
        "no_equilibrium",
    ];
    for r in doc["regions"].as_array().unwrap() {
        assert!(kinds.contains(&r["kind"].as_str().unwrap()));
    }
    // the band: at α = 0.7 the first samples above μ_ms are non-unique, with three limit
    // states (η_s and a mirror pair above it), and a boundary to unique lies above them
    let col = &doc["columns"][2];
    assert!((col["alpha"].as_f64().unwrap() - 0.7).abs() < 1e-12);
    assert_eq!(col["samples"][0]["kind"], "non_unique");
    assert_eq!(col["samples"][0]["etas"].as_array().unwrap().len(), 3);
    let pairs: Vec<&Value> = doc["boundaries"]
        .as_array()
        .unwrap()
        .iter()
        .map(|b| &b["between"])
        .collect();
    assert!(
        pairs
            .iter()
            .any(|p| p[0] == "non_unique" && p[1] == "unique"),
        "{pairs:?}"
    );
    for b in doc["boundaries"].as_array().unwrap() {
        for p in b["points"].as_array().unwrap() {
            let br = p["bracket"].as_array().unwrap();
            let (lo, hi) = (br[0].as_f64().unwrap(), br[1].as_f64().unwrap());
            let mu = p["mu"].as_f64().unwrap();
            // where a branch's end is solved from its defining condition, the bracket
            // (where the solver's kinds, decided to tolerances, change) lies within
            // rounding and those tolerances of it
            let slack = if p["exact"] == true { 1e-9 * mu } else { 0.0 };
            assert!(lo - slack <= mu && mu <= hi + slack, "{p}");
            assert_eq!(p["certified"], false);
        }
    }
    // bad input names the argument
    for (flag, value) in [
        ("--alpha-min", "2"),
        ("--mu-max-factor", "1"),
        ("--columns", "1"),
        ("--samples", "0"),
    ] {
        let (err, code) = json_of(&["atlas", flag, value]);
        assert_eq!(code, 2, "{flag} {value}");
        assert!(err["message"].as_str().unwrap().contains(flag), "{err}");
    }
}

/// `--certify` on twelve voussoirs across the band: every located bracket, every μ_ms
/// bracket and one sample of every run is stated by a certificate that the verifier accepted
/// (for voussoir arches its ridge evidence proves the list of limit states complete).
#[test]
fn certified_brackets() {
    let (doc, code) = json_of(&[
        "atlas",
        "--certify",
        "--blocks",
        "12",
        "--alpha-min",
        "0.55",
        "--alpha-max",
        "1.0",
        "--columns",
        "10",
        "--mu-max-factor",
        "1.3",
        "--samples",
        "16",
    ]);
    assert_eq!(code, 0);
    let mut pairs = std::collections::BTreeSet::new();
    for b in doc["boundaries"].as_array().unwrap() {
        for p in b["points"].as_array().unwrap() {
            assert_eq!(p["certified"], true, "{p}");
            // ridge evidence: the verifier proved each list of limit states complete
            assert_eq!(p["list_proved_complete"], true, "{p}");
            let cb = p["certified_bracket"].as_array().unwrap();
            assert!(cb[0].as_f64().unwrap() <= p["mu"].as_f64().unwrap() * (1.0 + 1e-12));
            assert!(cb[1].as_f64().unwrap() >= p["mu"].as_f64().unwrap() * (1.0 - 1e-12));
        }
        pairs.insert(b["between"].to_string());
    }
    assert!(pairs.len() >= 3, "{pairs:?}");
    let mut runs = 0;
    for c in doc["columns"].as_array().unwrap() {
        for r in c["runs"].as_array().unwrap() {
            let cert = &r["certified"];
            assert_eq!(cert["holds"], true, "{r}");
            assert_eq!(cert["list_proved_complete"], true, "{r}");
            let mu = cert["mu"].as_f64().unwrap();
            assert!(mu > r["mu_from"].as_f64().unwrap() && mu < r["mu_to"].as_f64().unwrap());
            runs += 1;
        }
    }
    assert!(runs >= 15, "{runs} runs");
    // the band's two tips on the μ_ms curve, to neighbouring floats of α, each side of the
    // bracket classified afresh at its own μ_ms (1 + 1e-6)
    let tips = doc["tips"].as_array().unwrap();
    assert_eq!(tips.len(), 2, "{tips:?}");
    for t in tips {
        assert!(t.get("stopped").is_none(), "{t}");
        let b = t["alpha_bracket"].as_array().unwrap();
        let (lo, hi) = (b[0].as_f64().unwrap(), b[1].as_f64().unwrap());
        assert_eq!(hi, lo.next_up(), "{t}");
        for (alpha, want) in [(lo, &t["between"][0]), (hi, &t["between"][1])] {
            let arch = Arch::symmetric(alpha, WeightModel::Centreline)
                .and_then(|a| a.with_blocks(12))
                .unwrap();
            let ms = least_friction(&arch, &Settings::default())
                .unwrap()
                .unwrap();
            let kind = solve_kind(&arch, ms * (1.0 + 1e-6)).expect("decided");
            assert_eq!(kind, want.as_str().unwrap(), "alpha = {alpha}");
        }
    }
}

/// The load map (`atlas --horizontal`): on the continuous arches around α = 0.5 at μ = 1,
/// the largest reduction of the collapse acceleration below the static maximum, 12.5 % at
/// α = 0.45 (η = 0.6090, a mixed mode; the limit state λ = 0.23659 is found by 96 and 192
/// pieces, missed by 48), is the largest over the cells, and every answered cell is the
/// load survey run on its own; with `--certify` each of the three reductions is proved by a
/// verified load certificate (λ_static ≥ the proved λ_lo > a listed limit state's λ), to
/// within 1e-6 of its size; on five voussoirs each cell's collapse multiplier
/// is the least limit state of the brute force (`load_reference`: every pattern of contacts,
/// an LP each), and "no collapse" where it finds none. Bad flags are refused by name.
#[test]
fn the_load_map_finds_the_reduction_and_agrees_with_the_brute_force() {
    use arch_enum::atlas::loads::{load_map, CellAnswer, LoadGrid};
    use arch_enum::atlas::Rectangle;
    use arch_enum::load::LiveLoad;
    use arch_enum::multiplier::{survey as load_survey, LoadOutcome};
    let settings = Settings::default();
    let rect = |alpha_min, alpha_max, blocks| Rectangle {
        alpha_min,
        alpha_max,
        mu_max_factor: 10.0,
        weight: WeightModel::Centreline,
        blocks,
        columns: 3,
        samples: 40,
        certify: false,
    };
    let grid = LoadGrid {
        rect: rect(0.45, 0.55, None),
        mus: vec![1.0],
        factors: 12,
        factor_max: 4.0,
    };
    let map = load_map(&grid, &settings, 2, &|_, _| {}).unwrap();
    let best = map.largest(1.0).unwrap();
    assert_eq!(best.alpha, 0.45);
    let r = best.reduction().unwrap();
    assert!(
        (r - 0.1251).abs() < 5e-4 && (best.eta.unwrap() - 0.6090).abs() < 1e-3,
        "{best:?}"
    );
    let most = map
        .cells
        .iter()
        .filter_map(|c| c.reduction())
        .fold(0.0, f64::max);
    assert_eq!(r, most);
    // certified: a verified load certificate proves lambda_static >= lambda_lo and lists a
    // limit state below it, at every reduced cell (and only there)
    let certified = load_map(
        &LoadGrid {
            rect: Rectangle {
                certify: true,
                ..grid.rect
            },
            ..grid.clone()
        },
        &settings,
        2,
        &|_, _| {},
    )
    .unwrap();
    for (c, plain) in certified.cells.iter().zip(&map.cells) {
        assert_eq!(c.answer, plain.answer);
        match (&c.certified, c.reduction().filter(|_| c.reduced())) {
            (Some(Ok(at_least)), Some(r)) => {
                assert!(*at_least <= r && *at_least >= r - 1e-6, "{c:?}")
            }
            (None, None) => {}
            other => panic!("{c:?}: {other:?}"),
        }
    }
    assert_eq!(
        certified
            .cells
            .iter()
            .filter(|c| c.certified.is_some())
            .count(),
        3
    );
    // the boundaries' reduced ends: certified where the survey decides there (α = 0.45, both
    // ends, the survey alone), each at least its reduction less the certificate's gap
    for b in certified.boundaries.iter().filter(|b| b.alpha == 0.45) {
        match &b.certified {
            Some(Ok(at_least)) => assert!(
                *at_least > 0.0 && *at_least <= b.reduction && *at_least >= b.reduction - 1e-6,
                "{b:?}"
            ),
            other => panic!("{b:?}: {other:?}"),
        }
    }
    assert!(map.boundaries.iter().all(|b| b.certified.is_none()));
    let horizontal = LiveLoad::Horizontal {
        towards_right: true,
    };
    // where the reduction begins and ends in η at α = 0.45, bisected to 1e-9 by the survey
    // alone: it begins where the load's limit state below λ_static is born (no limit state
    // at all on the thinner side: no collapse) and ends where it vanishes (reduced on the
    // thinner side, not on the thicker)
    let at: Vec<_> = map.boundaries.iter().filter(|b| b.alpha == 0.45).collect();
    assert_eq!(at.len(), 2, "{:?}", map.boundaries);
    let (begin, b) = (at[0], at[1]);
    for x in [begin, b] {
        assert!(
            x.stopped.is_none() && x.followed == 0 && !x.at_least,
            "{x:?}"
        );
        assert!(x.etas.1 - x.etas.0 <= 2e-9 * x.etas.1, "{x:?}");
    }
    assert!(!begin.reduced_below && b.reduced_below, "{at:?}");
    assert!(
        begin.etas.1 < best.eta.unwrap() && b.etas.0 > best.eta.unwrap(),
        "{at:?}"
    );
    // born at λ_static: the reduction starts from nothing
    assert!(begin.reduction < 1e-6 && b.reduction > r, "{at:?}");
    let arch = Arch::symmetric(0.45, WeightModel::Centreline).unwrap();
    let reduced = |eta: f64| match load_survey(&arch, eta, 1.0, &horizontal, &settings).unwrap() {
        Ok(LoadOutcome::Limits(sv)) => sv.lambda().is_some_and(|l| {
            1.0 - l / sv.lambda_static.unwrap().0 > arch_enum::atlas::loads::REDUCTION_TOL
        }),
        Ok(LoadOutcome::NoCollapse { .. }) => false,
        other => panic!("{other:?}"),
    };
    assert!(!reduced(begin.etas.0) && reduced(begin.etas.1), "{begin:?}");
    assert!(reduced(b.etas.0) && !reduced(b.etas.1), "{b:?}");
    // α = 0.5: near where its reduction ends the survey does not decide (its 48-, 96- and
    // 192-piece lists do not settle); the bisection follows the reduced side's limit state
    // there and locates the end to 1e-9, where the reduction is larger than the cell's
    let b = map
        .boundaries
        .iter()
        .find(|b| b.alpha == 0.5 && b.reduced_below)
        .unwrap();
    // (its reduction then a lower bound: λ_c is at most the followed state's λ)
    assert!(
        b.reduced_below && b.stopped.is_none() && b.followed > 0 && b.at_least,
        "{b:?}"
    );
    assert!(b.etas.1 - b.etas.0 <= 2e-9 * b.etas.1, "{b:?}");
    let cell = map
        .cells
        .iter()
        .find(|c| c.alpha == 0.5 && c.reduced())
        .unwrap();
    assert!(b.reduction > cell.reduction().unwrap() + 0.05, "{b:?}");
    assert!(!reduced(b.etas.1), "{b:?}");
    // independently: the cell's least limit state followed to the reduced end in eight steps
    // gives the same reduction, and it is a limit state of the discrete arch whose joints are
    // the springings and its contacts (the brute force of `load_reference`: its own statics
    // and kinematic LP)
    let arch = Arch::symmetric(0.5, WeightModel::Centreline).unwrap();
    let (eta_c, eta_b) = (cell.eta.unwrap(), b.etas.0);
    let Ok(LoadOutcome::Limits(sv)) =
        load_survey(&arch, eta_c, 1.0, &horizontal, &settings).unwrap()
    else {
        panic!("the cell's survey")
    };
    let mut st = sv.limit_states[0].clone();
    for k in 1..=8 {
        let eta = eta_c + (eta_b - eta_c) * k as f64 / 8.0;
        st = arch_enum::multiplier::follow(&arch, (eta, 1.0), &horizontal, &st, &settings)
            .unwrap_or_else(|e| panic!("eta = {eta}: {e}"));
    }
    let top = match arch_enum::multiplier::static_range(&arch, eta_b, 1.0, &horizontal, &settings)
        .unwrap()
        .unwrap()
    {
        arch_enum::multiplier::StaticRange::Interval { max: Some(m), .. } => m.0,
        other => panic!("{other:?}"),
    };
    assert!(
        (1.0 - st.t / top - b.reduction).abs() < 1e-9,
        "{st:?} vs {b:?}"
    );
    let mut joints = vec![arch.beta_right(), arch.beta_left()];
    joints.extend(st.pattern.iter().map(|c| c.beta));
    joints.sort_by(f64::total_cmp);
    joints.dedup_by(|a, b| (*a - *b).abs() < 1e-12);
    let listed =
        crate::load_reference::Case::new(&joints, false, eta_b, 1.0, horizontal).brute_force();
    eprintln!(
        "alpha 0.5: reduction {} at eta {eta_b} ({} midpoints followed); joints {joints:?}, brute force {listed:?}",
        b.reduction, b.followed
    );
    assert!(
        listed.iter().any(|l| (l - st.t).abs() <= 1e-8 * st.t),
        "{:?}: lambda = {} not among {listed:?}",
        joints,
        st.t
    );
    for c in map.cells.iter().filter(|c| c.eta.is_some()).step_by(5) {
        let arch = Arch::symmetric(c.alpha, WeightModel::Centreline).unwrap();
        let alone = load_survey(&arch, c.eta.unwrap(), c.mu, &horizontal, &settings).unwrap();
        if let (CellAnswer::Ratio { lambda_c, .. }, Ok(LoadOutcome::Limits(sv))) =
            (&c.answer, &alone)
        {
            assert_eq!(Some(*lambda_c), sv.lambda(), "{c:?}");
        }
    }
    let grid = LoadGrid {
        rect: rect(-0.2, 0.6, Some(5)),
        mus: vec![0.6, 1.0],
        factors: 3,
        factor_max: 2.5,
    };
    let map = load_map(&grid, &settings, 2, &|_, _| {}).unwrap();
    let mut compared = 0;
    for c in &map.cells {
        let Some(eta) = c.eta else { continue };
        let arch = Arch::symmetric(c.alpha, WeightModel::Centreline)
            .unwrap()
            .with_blocks(5)
            .unwrap();
        let arch_enum::JointLayout::Discrete(joints) = arch.layout() else {
            unreachable!("five voussoirs")
        };
        let reference =
            crate::load_reference::Case::new(joints, false, eta, c.mu, horizontal).brute_force();
        match &c.answer {
            CellAnswer::Ratio { lambda_c, .. } => {
                let least = reference.first().copied().unwrap_or(f64::NAN);
                assert!(
                    (lambda_c - least).abs() <= 1e-8 * least.abs().max(1.0),
                    "{c:?} vs {reference:?}"
                );
            }
            CellAnswer::NoCollapse => assert!(reference.is_empty(), "{c:?} vs {reference:?}"),
            other => panic!("{c:?}: {other:?}"),
        }
        compared += 1;
    }
    assert!(compared >= 12, "only {compared} cells compared");
    let (v, code) = json_of(&["atlas", "--horizontal", "--mu", "1", "--factors", "1"]);
    assert_eq!(code, 2, "{v}");
    assert!(v["message"].as_str().unwrap().contains("--factors"), "{v}");
}

/// The atlas document of two columns, α = `alpha_min` and `alpha_max`, 12 samples up to
/// 1.2 μ_ms, with `extra` flags; the columns have `points` boundary points of the band.
fn band_doc(alpha_min: &str, alpha_max: &str, extra: &[&str], points: usize) -> Value {
    let flags = [
        "atlas",
        "--alpha-min",
        alpha_min,
        "--alpha-max",
        alpha_max,
        "--columns",
        "2",
        "--mu-max-factor",
        "1.2",
        "--samples",
        "12",
    ];
    let (doc, code) = json_of(&[&flags[..], extra].concat());
    assert_eq!(code, 0);
    assert_eq!(band_points(&doc).len(), points, "{doc}");
    doc
}

/// The boundary points between `non_unique` and `unique` of an atlas document.
fn band_points(doc: &Value) -> Vec<&Value> {
    doc["boundaries"]
        .as_array()
        .unwrap()
        .iter()
        .filter(|b| b["between"] == serde_json::json!(["non_unique", "unique"]))
        .flat_map(|b| b["points"].as_array().unwrap())
        .collect()
}

/// Near the top of the continuous band the discretised search, run at μ only, loses a
/// branch of limit states before the continuum does: at α = 0.7 the 48- and 96-piece
/// searches agree on no limit state above η_s a little below where the branch ends (with
/// `carry_shift` = `carry_almost_rate` = 0; the default finds it). The atlas follows the
/// non-unique end's states (Newton on each pattern) as it bisects, so its boundary point is
/// where the branch ends: at the point's lower end a followed state is still a limit state,
/// and the search finds it there, and `why` says how the branch ends (its state leaves the
/// admissible set or loses its mechanism), never that a state goes on. At α = 0.65 the
/// branch ends by losing its mechanism (the interior slide's rate reaches 0).
#[test]
fn boundary_points_are_where_the_branches_end() {
    let doc = band_doc("0.65", "0.7", &[], 2);
    let points = band_points(&doc);
    let settings = Settings::default();
    for p in points {
        let (alpha, lo) = (
            p["alpha"].as_f64().unwrap(),
            p["bracket"][0].as_f64().unwrap(),
        );
        let why = p["why"].as_str().unwrap();
        assert!(p["tight"].as_bool().unwrap(), "{p}");
        assert!(!why.contains("still one"), "{why}");
        assert!(
            why.contains("is not admissible") || why.contains("carries no mechanism"),
            "{why}"
        );
        if alpha == 0.65 {
            assert!(why.contains("carries no mechanism"), "{why}");
        }
        let arch = Arch::symmetric(alpha, WeightModel::Centreline).unwrap();
        if alpha == 0.7 {
            // the search alone finds the branch 1e-9 inside the point (within ~1e-12 of
            // the end the state's violation is at `adm_tol` and rounding decides): its
            // discretisations, searched at μ only, miss it from μ = 1.049559 on (it said
            // `unique` there), and find it searched a little lower
            // (`Settings::carry_shift`) and carried to μ
            let lo = lo * (1.0 - 1e-9);
            let sv = survey(&arch, lo, &settings).unwrap();
            assert_eq!(sv.unique(), Some(false), "alpha = {alpha}, mu = {lo}");
            let former = Settings {
                carry_shift: 0.0,
                carry_almost_rate: 0.0,
                ..Settings::default()
            };
            let sv = survey(&arch, lo, &former).unwrap();
            assert_eq!(sv.unique(), Some(true), "alpha = {alpha}, mu = {lo}");
            // the branch the search finds at μ = 1.0495, followed there on its patterns
            // (steps halving towards the end: the branch's two members close on each other
            // there, like a fold), is still one
            let start = survey(&arch, 1.0495, &settings).unwrap();
            let mut states = start.states.unwrap().above;
            assert!(!states.is_empty());
            for k in 1..=60 {
                let mu = lo - (lo - 1.0495) * 0.5f64.powi(k);
                states = states
                    .iter()
                    .filter_map(|s| arch_enum::limit_states::follow(&arch, mu, s, &settings).ok())
                    .collect();
            }
            let eta_s = sv.states.as_ref().unwrap().eta_s;
            assert!(
                states.iter().any(|s| s.t > 1.2 * eta_s),
                "no limit state of the branch reaches mu = {lo}"
            );
        }
    }
}

/// The boundary points of the non-unique band are solved from what ends the branch there
/// (`exact`): at α = 0.65 the rate of an interior slide falls to 0, at α = 0.75 the hinge at
/// the right springing reaches its limit. Checked apart from the solver's verdicts: at the
/// end the state meets its defining condition by the independent continuum reference
/// (every listed contact active, admissible over 20 001 angles; at α = 0.65 the other three
/// contacts' compatibility matrix singular, its columns written out again in
/// `model::column`), and the branch changes there: followed on its pattern to 1e-8 inside
/// the end it is a limit state, to 1e-8 beyond it is none. With `--certify` the end itself
/// is the certified bracket's non-unique end.
#[test]
fn boundary_points_are_solved_from_what_ends_the_branch() {
    use crate::continuum_reference::Cont;
    use arch_enum::limit_states::{branch_end, follow, EndCondition};
    let doc = band_doc("0.65", "0.75", &["--certify"], 2);
    let points = band_points(&doc);
    let settings = Settings::default();
    for p in points {
        let f = |k: &str| p[k].as_f64().unwrap_or_else(|| panic!("{k} in {p}"));
        let (alpha, mu, lo, hi) = (
            f("alpha"),
            f("mu"),
            p["bracket"][0].as_f64().unwrap(),
            p["bracket"][1].as_f64().unwrap(),
        );
        assert!(
            p["exact"].as_bool().unwrap() && f("residual") <= 1e-12,
            "{p}"
        );
        assert!(p["certified"].as_bool().unwrap(), "{p}");
        assert_eq!(p["certified_bracket"][0].as_f64(), Some(mu), "{p}");
        let condition = p["condition"].as_str().unwrap();
        // the branch, found inside the band
        let arch = Arch::symmetric(alpha, WeightModel::Centreline).unwrap();
        let inside_mu = lo * (1.0 - 1e-4);
        let sv = survey(&arch, inside_mu, &settings).unwrap();
        let states: Vec<_> = match &sv.states {
            Ok(l) => l.above.clone(),
            Err(_) => sv.found.clone(),
        };
        assert!(
            !states.is_empty(),
            "alpha = {alpha}: no branch at mu = {inside_mu}"
        );
        // to just inside the bracket (at its end rounding decides whether the mechanism LP
        // still finds the vanishing rate)
        let near = lo * (1.0 - 1e-9);
        let states: Vec<_> = states
            .iter()
            .filter_map(|s| follow(&arch, near, s, &settings).ok())
            .collect();
        let (s, end) = states
            .iter()
            .filter_map(|s| {
                branch_end(&arch, s, (near, hi), &settings)
                    .ok()
                    .map(|e| (s, e))
            })
            .min_by(|a, b| (a.1.mu - mu).abs().total_cmp(&(b.1.mu - mu).abs()))
            .unwrap_or_else(|| panic!("alpha = {alpha}: no branch ends in {lo}..{hi}"));
        assert!((end.mu - mu).abs() <= 1e-14 * mu, "{} vs {mu}", end.mu);
        // the end state by the reference: admissible, its contacts active
        let reference = Cont::of(&arch, end.mu);
        let e = &end.state;
        let x = [e.x[0], e.x[1], e.x[2]];
        let worst = reference.worst(e.t, &x);
        assert!(
            worst <= 1e-9,
            "alpha = {alpha}: the end is violated by {worst:e}"
        );
        for c in &e.pattern {
            let g = reference.g(c.kind as usize, e.t, &x, c.beta);
            assert!(g.abs() <= 1e-9, "{c:?} is not active: {g:e}");
        }
        match end.condition {
            EndCondition::Admissibility(c) => {
                assert!(
                    alpha == 0.75 && condition.contains("reaches its limit"),
                    "{p}"
                );
                // the branch's four contacts, and the one that reaches its limit
                assert_eq!(e.pattern.len(), 5, "{:?}", e.pattern);
                assert_eq!(s.pattern.len(), 4, "{:?}", s.pattern);
                assert!(!s
                    .pattern
                    .iter()
                    .any(|q| q.kind == c.kind && (q.beta - c.beta).abs() < 1e-3));
            }
            EndCondition::Mechanism(c) => {
                assert!(alpha == 0.65 && condition.contains("falls to 0"), "{p}");
                let cols: Vec<[f64; 3]> = e
                    .pattern
                    .iter()
                    .filter(|q| q.kind != c.kind || (q.beta - c.beta).abs() > 1e-9)
                    .map(|q| crate::model::column(q.kind, q.beta, e.t))
                    .collect();
                assert_eq!(cols.len(), 3);
                let m = nalgebra::Matrix3::from_fn(|r, k| cols[k][r]);
                let size: f64 = cols
                    .iter()
                    .map(|v| v.iter().map(|a| a * a).sum::<f64>().sqrt())
                    .product();
                assert!(
                    m.determinant().abs() <= 1e-12 * size,
                    "det {:e}",
                    m.determinant()
                );
            }
        }
        // the branch followed on its pattern: a limit state just inside, none just beyond
        assert!(
            follow(&arch, end.mu * (1.0 - 1e-8), s, &settings).is_ok(),
            "alpha = {alpha}"
        );
        let beyond = follow(&arch, end.mu * (1.0 + 1e-8), s, &settings);
        assert!(
            beyond.is_err(),
            "alpha = {alpha}: still a limit state beyond the end"
        );
    }
}

/// The top of the continuous band (its largest μ/μ_ms) is a corner: between α = 0.69 (the
/// last branch to end loses its mechanism) and 0.70 (the last one reaches a contact's
/// limit) the two branch-end curves cross, and the golden section over exact boundary
/// points (continued in α from the columns' ends) closes on that opening to ~1e-12 with the
/// two conditions on its two sides; the default rectangle (53 columns) finds the same top
/// to 1e-12 (`docs/uniqueness.md`).
#[test]
fn the_top_of_the_band_is_where_two_branch_ends_cross() {
    use arch_enum::atlas::{atlas, Rectangle};
    let rect = Rectangle {
        alpha_min: 0.69,
        alpha_max: 0.70,
        mu_max_factor: 1.2,
        weight: WeightModel::Centreline,
        blocks: None,
        columns: 2,
        samples: 12,
        certify: false,
    };
    let a = atlas(&rect, &Settings::default(), 2, &|_, _| {}).unwrap();
    let top = a.top.as_ref().expect("a top of the band");
    let (lo, hi) = top.alpha_bracket;
    assert!(lo > 0.69 && hi < 0.70 && hi - lo <= 1e-11, "{top:?}");
    assert!((top.alpha - 0.6952734673).abs() < 1e-9, "{top:?}");
    assert!((top.ratio - 1.0754879034).abs() < 1e-9, "{top:?}");
    assert!((top.mu / top.mu_ms - top.ratio).abs() < 1e-15);
    assert!(top.conditions.0.contains("falls to 0"), "{top:?}");
    assert!(top.conditions.1.contains("reaches its limit"), "{top:?}");
    // a vertex of the band's region and of the unique one above it
    for kind in [
        arch_enum::atlas::Kind::NonUnique,
        arch_enum::atlas::Kind::Unique,
    ] {
        assert!(
            a.regions
                .iter()
                .any(|(k, p)| *k == kind && p.contains(&[top.alpha, top.mu])),
            "{kind:?}"
        );
    }
    // above both columns' own (exact) boundary points
    for c in &a.columns {
        let p = &c.boundaries[0];
        assert!(p.exact(), "{p:?}");
        assert!(p.mu() / c.mu_ms.unwrap() < top.ratio - 1e-4, "{p:?}");
    }
}

/// `solve`'s search finds a branch of limit states up to where it ends. On the continuous
/// band (α = 0.64 to 0.90, every 0.02; the ends of branches that lose their mechanism at α
/// ≤ 0.69 and of branches whose state leaves the admissible set above) the search is
/// non-unique 10⁻³ to 10⁻⁹ (relative) inside each solved boundary point and unique 10⁻⁸
/// beyond it; every state it lists above η_s 10⁻⁵ inside is admissible over 20 001 angles
/// by the independent continuum reference. Searched at μ only (`carry_shift` =
/// `carry_almost_rate` = 0) the discretisations lose the branch before its end and the search
/// said `unique` (wrongly) inside 10 or more of these points.
#[test]
fn the_search_finds_every_branch_up_to_its_end() {
    use crate::continuum_reference::Cont;
    let (doc, code) = json_of(&[
        "atlas",
        "--alpha-min",
        "0.64",
        "--alpha-max",
        "0.9",
        "--columns",
        "14",
        "--mu-max-factor",
        "1.2",
        "--samples",
        "12",
    ]);
    assert_eq!(code, 0);
    // one per column, and at 0.68 (sampled at the corners of η*(μ)) a second one: the
    // lower branch's end below the notch of uniqueness there
    let points = band_points(&doc);
    assert_eq!(points.len(), 15, "{doc}");
    let settings = Settings::default();
    let at_mu = Settings {
        carry_shift: 0.0,
        carry_almost_rate: 0.0,
        ..Settings::default()
    };
    let (mut checked, mut missed_at_mu) = (0, 0);
    // where a branch is born (a notch of uniqueness below it): its birth, at each opening
    let births: Vec<(f64, f64)> = doc["boundaries"]
        .as_array()
        .unwrap()
        .iter()
        .filter(|b| b["between"] == serde_json::json!(["unique", "non_unique"]))
        .flat_map(|b| b["points"].as_array().unwrap())
        .map(|p| (p["alpha"].as_f64().unwrap(), p["mu"].as_f64().unwrap()))
        .collect();
    for p in points {
        assert!(p["exact"].as_bool().unwrap(), "{p}");
        let (alpha, end) = (p["alpha"].as_f64().unwrap(), p["mu"].as_f64().unwrap());
        let arch = Arch::symmetric(alpha, WeightModel::Centreline).unwrap();
        let ms = least_friction(&arch, &settings).unwrap().unwrap();
        // the branch lives above μ_ms and above its birth, where it has one below its end
        let born = births
            .iter()
            .filter(|b| b.0 == alpha && b.1 < end)
            .map(|b| b.1)
            .fold(ms * (1.0 + 1e-6), f64::max);
        for r in [1e-3, 1e-5, 1e-7, 1e-9] {
            let mu = end * (1.0 - r);
            if mu <= born {
                continue;
            }
            let sv = survey(&arch, mu, &settings).unwrap();
            assert_eq!(sv.unique(), Some(false), "alpha = {alpha}, mu = {mu}");
            checked += 1;
            let former = survey(&arch, mu, &at_mu).unwrap();
            missed_at_mu += usize::from(former.unique() == Some(true));
            if r != 1e-5 {
                continue;
            }
            let above = match &sv.states {
                Ok(l) => l.above.clone(),
                Err(_) => sv.found.clone(),
            };
            assert!(!above.is_empty(), "alpha = {alpha}, mu = {mu}");
            let reference = Cont::of(&arch, mu);
            for s in &above {
                let worst = reference.worst(s.t, &[s.x[0], s.x[1], s.x[2]]);
                assert!(worst <= 1e-9, "alpha = {alpha}, eta = {}: {worst:e}", s.t);
            }
        }
        let beyond = end * (1.0 + 1e-8);
        let sv = survey(&arch, beyond, &settings).unwrap();
        assert_eq!(sv.unique(), Some(true), "alpha = {alpha}, mu = {beyond}");
    }
    assert!(checked >= 50, "{checked}");
    eprintln!("searched at mu only, unique (wrongly) at {missed_at_mu} of {checked}");
    assert!(missed_at_mu >= 10, "{missed_at_mu} of {checked}");
}

/// The top of a voussoir arch's band (48 voussoirs): its boundary points are bisected to
/// neighbouring floats by the exact search (what ends a branch is not solved there), and the
/// top is the largest of them over α by golden section. At the top the search says
/// non-unique 10⁻⁹ below its μ and unique 10⁻⁸ above it, and the openings 10⁻⁴ either side
/// have lower points (a maximum), both columns' points below it.
#[test]
fn a_voussoir_band_has_a_top_of_bisected_points() {
    use arch_enum::atlas::{atlas, Kind, Rectangle};
    let rect = Rectangle {
        alpha_min: 0.66,
        alpha_max: 0.67,
        mu_max_factor: 1.2,
        weight: WeightModel::Centreline,
        blocks: Some(48),
        columns: 2,
        samples: 12,
        certify: false,
    };
    let settings = Settings::default();
    let a = atlas(&rect, &settings, 2, &|_, _| {}).unwrap();
    let top = a.top.as_ref().expect("a top of the band");
    assert_eq!(top.shape(), "the largest of bisected points", "{top:?}");
    assert!((top.ratio - 1.0803056377).abs() < 1e-9, "{top:?}");
    let unique_at = |alpha: f64, mu: f64| {
        let arch = Arch::symmetric(alpha, WeightModel::Centreline)
            .unwrap()
            .with_blocks(48)
            .unwrap();
        survey(&arch, mu, &settings).unwrap().unique()
    };
    assert_eq!(unique_at(top.alpha, top.mu * (1.0 - 1e-9)), Some(false));
    assert_eq!(unique_at(top.alpha, top.mu * (1.0 + 1e-8)), Some(true));
    for side in [-1e-4, 1e-4] {
        let alpha = top.alpha + side;
        let arch = Arch::symmetric(alpha, WeightModel::Centreline)
            .unwrap()
            .with_blocks(48)
            .unwrap();
        let ms = least_friction(&arch, &settings).unwrap().unwrap();
        assert_eq!(
            unique_at(alpha, ms * top.ratio * (1.0 - 1e-7)),
            Some(true),
            "alpha = {alpha}"
        );
    }
    for c in &a.columns {
        for p in c
            .boundaries
            .iter()
            .filter(|p| p.between == [Kind::NonUnique, Kind::Unique])
        {
            assert!(p.bracket.0 / c.mu_ms.unwrap() < top.ratio, "{p:?}");
        }
    }
}

/// The `non_unique`/`unique` boundary is traced between two columns by continuation in α
/// (`traced`): every traced point is non-unique just inside it and unique just beyond it
/// by the search itself, and the polygons pass through the points. Between α = 0.68 and
/// 0.69 the curve bends away from the chord; a point between the chord and the curve has
/// the kind `solve` gives it in the polygons too (the chord alone puts it on the other side).
/// Inside the strip `solve` also shows a notch of uniqueness (docs/uniqueness.md): at
/// α = 0.685 the first branch ends near μ = 1.0156 and the second is born at the corner of
/// η*(μ), μ = 1.02096. The traced points locate it (`notch`: the lower end and the birth,
/// each checked by the search on both sides) and the polygons hold it. The column at
/// 0.68, sampled on both sides of the corner, crosses the notch too (three boundary
/// points: the lower end, the birth, the band's boundary) and joins the next column through
/// the band's boundary above it.
#[test]
fn the_boundary_is_traced_between_columns() {
    let doc = band_doc("0.68", "0.69", &[], 3);
    let traced = doc["traced"].as_array().unwrap();
    assert_eq!(traced.len(), 1, "{doc}");
    let t = &traced[0];
    let points = t["points"].as_array().unwrap();
    // the regular openings, and more where the curve bends or the notch begins
    assert!(points.len() >= arch_enum::atlas::TRACE_STEPS - 1, "{t}");
    let alphas: Vec<f64> = points
        .iter()
        .map(|p| p["alpha"].as_f64().unwrap())
        .collect();
    assert!(alphas.windows(2).all(|w| w[0] < w[1]), "{alphas:?}");
    let kind = |alpha: f64, mu: f64| {
        solve_kind(
            &Arch::symmetric(alpha, WeightModel::Centreline).unwrap(),
            mu,
        )
    };
    let mut notches = 0;
    for p in points {
        let (alpha, mu) = (p["alpha"].as_f64().unwrap(), p["mu"].as_f64().unwrap());
        assert_eq!(kind(alpha, mu * (1.0 - 1e-6)), Some("non_unique"), "{p}");
        assert_eq!(kind(alpha, mu * (1.0 + 1e-8)), Some("unique"), "{p}");
        let Some(n) = p.get("notch") else { continue };
        notches += 1;
        let end = n["mu_end"].as_f64().unwrap();
        let birth = n["birth_bracket"].as_array().unwrap();
        let (b0, b1) = (birth[0].as_f64().unwrap(), birth[1].as_f64().unwrap());
        assert!(end < b0 && b1 < mu, "{p}");
        assert_eq!(kind(alpha, end * (1.0 - 1e-6)), Some("non_unique"), "{p}");
        assert_eq!(kind(alpha, end * (1.0 + 1e-8)), Some("unique"), "{p}");
        assert_eq!(kind(alpha, b0), Some("unique"), "{p}");
        assert_eq!(kind(alpha, b1), Some("non_unique"), "{p}");
    }
    assert!(notches >= 3, "{notches} notches: {t}");
    // the column's own notch at 0.68, by the search and the polygons
    for (mu, want) in [
        (1.0138, "unique"),
        (1.0145, "non_unique"),
        (1.0152, "unique"),
    ] {
        assert_eq!(kind(0.68, mu), Some(want), "mu = {mu}");
        assert_eq!(
            kinds_at(&regions_of(&doc), 0.68 + 1e-9, mu),
            vec![want],
            "mu = {mu}"
        );
    }
    // the point at α = 0.68625 (the fifth regular opening) and the chord there
    let p = points
        .iter()
        .find(|p| (p["alpha"].as_f64().unwrap() - 0.68625).abs() < 1e-12)
        .expect("a point at 0.68625");
    let alpha = 0.68625;
    let (from, to) = (t["mu_from"].as_f64().unwrap(), t["mu_to"].as_f64().unwrap());
    let chord = from + (to - from) * 0.625;
    let curve = p["mu"].as_f64().unwrap();
    assert!(
        (curve - chord).abs() > 1e-4 * chord,
        "curve {curve}, chord {chord}"
    );
    let mu = 0.5 * (chord + curve);
    let want = if curve > chord {
        "non_unique"
    } else {
        "unique"
    };
    assert_eq!(kind(alpha, mu), Some(want));
    assert_eq!(kinds_at(&regions_of(&doc), alpha, mu), vec![want]);
    // the notch: the first branch, none, the second branch, by the search and the polygons
    for (mu, want) in [
        (1.015, "non_unique"),
        (1.018, "unique"),
        (1.0225, "non_unique"),
    ] {
        assert_eq!(kind(0.685, mu), Some(want), "mu = {mu}");
        assert_eq!(
            kinds_at(&regions_of(&doc), 0.685, mu),
            vec![want],
            "mu = {mu}"
        );
    }
}

/// Where the band ends on the μ_ms curve between two columns, its boundary is traced from
/// the column to the tip, and the two groups of columns meet at the tip (not in the middle
/// of the strip): at α = 0.9155, beyond the middle of the strip 0.91–0.92, the arch is
/// still non-unique just above μ_ms (the tip lies at α ≈ 0.91636), and the polygons say so.
#[test]
fn the_band_is_traced_to_its_tip() {
    let doc = band_doc("0.91", "0.92", &[], 1);
    let traced = doc["traced"].as_array().unwrap();
    assert_eq!(traced.len(), 1, "{doc}");
    let tip = traced[0]["tip"].as_array().unwrap();
    let tip_alpha = tip[0].as_f64().unwrap();
    assert!(tip_alpha > 0.916 && tip_alpha < 0.9165, "{tip:?}");
    let points = traced[0]["points"].as_array().unwrap();
    assert!(points.len() >= arch_enum::atlas::TRACE_STEPS - 1);
    for p in points {
        let (alpha, mu) = (p["alpha"].as_f64().unwrap(), p["mu"].as_f64().unwrap());
        let arch = Arch::symmetric(alpha, WeightModel::Centreline).unwrap();
        assert!(alpha > 0.91 && alpha < tip_alpha, "{p}");
        assert_eq!(
            solve_kind(&arch, mu * (1.0 - 1e-6)),
            Some("non_unique"),
            "{p}"
        );
        assert_eq!(solve_kind(&arch, mu * (1.0 + 1e-8)), Some("unique"), "{p}");
    }
    let alpha = 0.9155;
    let arch = Arch::symmetric(alpha, WeightModel::Centreline).unwrap();
    let ms = least_friction(&arch, &Settings::default())
        .unwrap()
        .unwrap();
    let mu = ms * (1.0 + 1e-4);
    assert_eq!(solve_kind(&arch, mu), Some("non_unique"));
    assert_eq!(kinds_at(&regions_of(&doc), alpha, mu), vec!["non_unique"]);
}

/// A branch that ends last only between two columns (the extrados hinge's, between 0.65 and
/// 0.70, left of the top) is continued in the strip from the ends the top's search solved:
/// the polygons do not take the lower branch's end (a notch's lower edge) for the band's
/// boundary there.
#[test]
fn a_branch_known_only_between_columns_is_traced() {
    let doc = band_doc("0.65", "0.7", &[], 2);
    for (alpha, mu) in [(0.6875, 1.026), (0.69375, 1.0395)] {
        let arch = Arch::symmetric(alpha, WeightModel::Centreline).unwrap();
        assert_eq!(solve_kind(&arch, mu), Some("non_unique"));
        assert_eq!(
            kinds_at(&regions_of(&doc), alpha, mu),
            vec!["non_unique"],
            "{alpha}"
        );
    } // the strip is refined where a notch begins or ends and where the curve bends: the
      // notch (α ≈ 0.676-0.69) is located at more than the two regular openings inside it
      // (0.68125, 0.6875), and the polygons hold it at 0.685 as the search does
    let points = doc["traced"][0]["points"].as_array().unwrap();
    let notches = points.iter().filter(|p| p.get("notch").is_some()).count();
    assert!(notches >= 6, "{notches}: {points:?}");
    let arch = Arch::symmetric(0.685, WeightModel::Centreline).unwrap();
    for (mu, want) in [
        (1.015, "non_unique"),
        (1.018, "unique"),
        (1.0225, "non_unique"),
    ] {
        assert_eq!(solve_kind(&arch, mu), Some(want), "mu = {mu}");
        assert_eq!(
            kinds_at(&regions_of(&doc), 0.685, mu),
            vec![want],
            "mu = {mu}"
        );
    }
}

/// A voussoir arch's η*(μ) has corners where a branch of limit states is born that is far
/// narrower than the samples' spacing: at α = 1.1 with 24 voussoirs a mirror pair of
/// states with the joints next to the crown sliding lies just above η_s for μ from
/// 4.41833 to 4.41861 only (μ/μ_ms ≈ 2.14). The column samples both sides of every corner
/// of η*(μ), so it holds the sliver as the search does (40 samples alone did not).
#[test]
fn a_sliver_born_at_a_corner_is_sampled() {
    let (doc, code) = json_of(&[
        "atlas",
        "--blocks",
        "24",
        "--alpha-min",
        "1.1",
        "--alpha-max",
        "1.1001",
        "--columns",
        "2",
        "--mu-max-factor",
        "3",
        "--samples",
        "12",
    ]);
    assert_eq!(code, 0);
    let column = &doc["columns"][0];
    let runs: Vec<(&str, f64)> = column["runs"]
        .as_array()
        .unwrap()
        .iter()
        .map(|r| (r["kind"].as_str().unwrap(), r["mu_to"].as_f64().unwrap()))
        .collect();
    let kinds: Vec<&str> = runs.iter().map(|r| r.0).collect();
    assert_eq!(kinds, ["unique", "non_unique", "unique"], "{runs:?}");
    let (from, to) = (runs[0].1, runs[1].1);
    assert!(from > 4.418 && to < 4.419 && to - from < 1e-3, "{runs:?}");
    let arch = Arch::symmetric(1.1, WeightModel::Centreline)
        .unwrap()
        .with_blocks(24)
        .unwrap();
    for (mu, want) in [
        (from * (1.0 - 1e-4), "unique"),
        (0.5 * (from + to), "non_unique"),
        (to * (1.0 + 1e-4), "unique"),
    ] {
        assert_eq!(solve_kind(&arch, mu), Some(want), "mu = {mu}");
        assert_eq!(
            kinds_at(&regions_of(&doc), 1.1 + 1e-6, mu),
            vec![want],
            "mu = {mu}"
        );
    }
}

/// The semicircle is not free of a reduction: at μ = 1 a horizontal acceleration's collapse
/// multiplier lies below its static maximum for thick rings, η from 0.5430468 (where a
/// limit state below λ_static is born, none at all below it) to 0.5914202 (where it
/// vanishes, 5.8 % below), which the default map (η ≤ 4 η* = 0.43) does not reach; and at
/// μ = 10 every ring from η ≈ 0.958 (7.7 % at η = 1.48: a wedge slides out near the left
/// springing). Independently of the crate: λ_static of the continuum reference (its own statics and
/// exchange LP), the crate's least limit state admissible on a dense grid of the reference's
/// statics, and a limit state of the discrete arch of its contacts for the brute force of
/// `load_reference` (its own kinematic LP).
#[test]
fn the_semicircle_is_not_free_of_a_reduction() {
    let semi = Arch::symmetric(0.0, WeightModel::Centreline).unwrap();
    let (reduction, _) = reduced_independently(&semi, 0.5701, 1.0);
    assert!(reduction > 0.03 && reduction < 0.04, "{reduction}");
    // and in thick rings at large friction (7.7 % at mu = 10, eta = 1.48)
    let (reduction, _) = reduced_independently(&semi, 1.48, 10.0);
    assert!(reduction > 0.07 && reduction < 0.085, "{reduction}");
    // the map over rings from 1.02 eta* to 5.3 eta* (inside the reduced stretch): where the
    // reduction begins, bisected to 1e-9
    let map = two_by_two_load_map((0.0, 0.1), 1.0, 5.3);
    assert_eq!(map.semicircle(1.0).map(|r| r > 0.03), Some(true));
    let begin: Vec<_> = map.boundaries.iter().filter(|b| b.alpha == 0.0).collect();
    assert_eq!(begin.len(), 1, "{:?}", map.boundaries);
    let b = begin[0];
    assert!(!b.reduced_below && b.stopped.is_none(), "{b:?}");
    assert!(
        (b.etas.0 - 0.5430468).abs() < 1e-6 && b.etas.1 - b.etas.0 <= 2e-9 * b.etas.1,
        "{b:?}"
    );
}

/// Near where a branch of load limit states ends the discretisations of a continuous arch
/// do not settle (at α = 0.5, μ = 1, η = 0.6125: 48 pieces find the reduced state, 96 and
/// 192 miss it, 384 are beyond the sweep's budget), so the collapse multiplier is not
/// decided; what is decided stays in the answer: λ_static (exact), the reduced state found
/// (a limit state of the continuum, checked independently as below), hence "not unique"
/// and the bound λ_c ≤ 0.18133 (at least 16.6 % below λ_static). The load map's cell at that
/// ring takes the bound (`at_most`: reduced by at least as much).
#[test]
fn an_unsettled_load_survey_keeps_what_it_decided() {
    let (doc, code) = json_of(&[
        "load",
        "--alpha",
        "0.5",
        "--eta",
        "0.6125",
        "--mu",
        "1",
        "--horizontal",
    ]);
    assert_eq!((code, doc["status"].as_str()), (1, Some("unresolved")));
    assert!(
        doc["lambda"].is_null() && doc["reduction"].is_null(),
        "{doc}"
    );
    assert_eq!(doc["unique"], false);
    assert_eq!(doc["mechanism_at_static"], true);
    let at_most = doc["lambda_at_most"].as_f64().unwrap();
    let top = doc["lambda_static"].as_f64().unwrap();
    let arch = Arch::symmetric(0.5, WeightModel::Centreline).unwrap();
    let horizontal = arch_enum::load::LiveLoad::Horizontal {
        towards_right: true,
    };
    let settings = Settings::default();
    let Ok(Err(u)) =
        arch_enum::multiplier::survey_partial(&arch, 0.6125, 1.0, &horizontal, &settings)
    else {
        panic!("the survey decided at eta = 0.6125")
    };
    assert_eq!(u.found.len(), 2, "{:?}", u.found);
    assert_eq!((u.found[0].t, u.found[1].t), (at_most, top));
    let reduction = checked_independently(&arch, (0.6125, 1.0), &u.found[0], top);
    assert!((reduction - 0.166).abs() < 1e-3, "{reduction}");
    let r = doc["reduction_at_least"].as_f64().unwrap();
    assert!((r - reduction).abs() < 1e-9, "{r} vs {reduction}");
    // a load-curve sample there keeps the same bound, in its JSON row and its table row
    let samples =
        arch_enum::multiplier::sample(&arch, 0.6125, &horizontal, &[1.0], &settings, &|_, _| {})
            .unwrap();
    let curve = arch_enum::multiplier::LoadCurve {
        samples,
        corners: Vec::new(),
    };
    let q = arch_enum::render::load::LoadQuestion {
        arch: &arch,
        eta: 0.6125,
        mu: 1.0,
        load: horizontal,
        dims: None,
        vehicle_kn: None,
    };
    let rows = serde_json::to_value(arch_enum::render::json::load_curve(&q, &curve)).unwrap();
    let row = &rows["points"][0];
    assert_eq!(row["status"], "unresolved", "{row}");
    assert_eq!(
        (
            row["lambda_at_most"].as_f64(),
            row["lambda_static"].as_f64()
        ),
        (Some(at_most), Some(top)),
        "{row}"
    );
    assert_eq!(
        (row["limit_states"].as_u64(), &row["unique"]),
        (Some(2), &serde_json::json!(false))
    );
    assert!(
        (row["reduction_at_least"].as_f64().unwrap() - r).abs() < 1e-15,
        "{row}"
    );
    let table = arch_enum::render::table::load_curve(&q, &curve);
    assert!(
        table
            .contains("unresolved (lambda <= 0.181329002871, at least 0.1660 below lambda_static)"),
        "{table}"
    );
    // the load map takes that bound: its cell at this ring is reduced by at least r
    let Outcome::Limit(ls) = arch_enum::limit::solve(&arch, 1.0, &settings)
        .unwrap()
        .outcome
    else {
        panic!("eta* at alpha = 0.5")
    };
    let map = two_by_two_load_map((0.5, 0.55), 1.0, 0.6125 / ls.eta_static);
    let cell = map
        .cells
        .iter()
        .filter(|c| c.alpha == 0.5)
        .max_by(|a, b| a.factor.total_cmp(&b.factor))
        .unwrap();
    assert!((cell.eta.unwrap() - 0.6125).abs() < 1e-12, "{cell:?}");
    assert!(cell.at_least() && cell.reduced(), "{cell:?}");
    assert!((cell.reduction().unwrap() - r).abs() < 1e-9, "{cell:?}");
}

/// The load map of a horizontal acceleration at friction `mu` over the two openings `alphas`
/// (continuous, centreline weight) and the two rings 1.02 η\* and `factor_max` η\* of each,
/// with its boundaries bisected.
fn two_by_two_load_map(
    (alpha_min, alpha_max): (f64, f64),
    mu: f64,
    factor_max: f64,
) -> arch_enum::atlas::loads::LoadMap {
    use arch_enum::atlas::loads::{load_map, LoadGrid};
    use arch_enum::atlas::Rectangle;
    let grid = LoadGrid {
        rect: Rectangle {
            alpha_min,
            alpha_max,
            mu_max_factor: 10.0,
            weight: WeightModel::Centreline,
            blocks: None,
            columns: 2,
            samples: 40,
            certify: false,
        },
        mus: vec![mu],
        factors: 2,
        factor_max,
    };
    load_map(&grid, &Settings::default(), 2, &|_, _| {}).unwrap()
}

/// The least limit state of a horizontal acceleration (towards the right springing) on the
/// continuous `arch` at (η, μ), checked independently of the crate: λ_static by the
/// continuum reference of `load_continuum_reference` (its own statics and exchange LP), the
/// state admissible on a dense grid of that reference's statics, its λ a limit state of the
/// discrete arch whose joints are the springings and its contacts for the brute force of
/// `load_reference` (its own kinematic LP). Returns the reduction 1 − λ_c/λ_static (with the
/// reference's λ_static) and the state.
fn reduced_independently(
    arch: &Arch,
    eta: f64,
    mu: f64,
) -> (f64, arch_enum::limit_states::LimitState) {
    use arch_enum::load::LiveLoad;
    use arch_enum::multiplier::{survey as load_survey, LoadOutcome};
    let horizontal = LiveLoad::Horizontal {
        towards_right: true,
    };
    let Ok(LoadOutcome::Limits(sv)) =
        load_survey(arch, eta, mu, &horizontal, &Settings::default()).unwrap()
    else {
        panic!("the load survey at eta = {eta}")
    };
    let least = sv.limit_states[0].clone();
    let top = sv.lambda_static.unwrap().0;
    (checked_independently(arch, (eta, mu), &least, top), least)
}

/// `least`, a limit state of a horizontal acceleration (towards the right springing) on the
/// continuous `arch` at (η, μ) below the static maximum `top` the crate gives, checked as
/// [`reduced_independently`] says; returns 1 − λ/λ_static with the reference's λ_static.
fn checked_independently(
    arch: &Arch,
    (eta, mu): (f64, f64),
    least: &arch_enum::limit_states::LimitState,
    top: f64,
) -> f64 {
    let horizontal = arch_enum::load::LiveLoad::Horizontal {
        towards_right: true,
    };
    let reference = crate::load_continuum_reference::LoadedCont::of(arch, eta, mu, horizontal);
    let reference_top = match reference.lambda_static().unwrap() {
        crate::load_continuum_reference::RefLambda::Static { lambda, .. } => lambda,
        other => panic!("{other:?}"),
    };
    assert!((reference_top - top).abs() < 1e-9 * top, "{reference_top}");
    let z = [least.x[0], least.x[1], least.x[2], least.t];
    reference.dense_check(&z).unwrap();
    let mut joints = vec![arch.beta_right(), arch.beta_left()];
    joints.extend(least.pattern.iter().map(|c| c.beta));
    joints.sort_by(f64::total_cmp);
    joints.dedup_by(|a, b| (*a - *b).abs() < 1e-12);
    let listed =
        crate::load_reference::Case::new(&joints, false, eta, mu, horizontal).brute_force();
    assert!(
        listed
            .iter()
            .any(|l| (l - least.t).abs() <= 1e-8 * least.t.max(1e-3)),
        "{joints:?}: lambda = {} not among {listed:?}",
        least.t
    );
    1.0 - least.t / reference_top
}

/// A horizontal acceleration λ g is gravity tilted by ψ = atan λ (towards the left), so a
/// symmetric arch of opening α under it is the arch of springings (−α − ψ, π + α − ψ) under
/// self-weight alone. At μ = 1 and η = 0.59 the reduced limit state of α = 0.2, 0.5 and
/// 0.6974 moves only the blocks from the right springing to its intrados hinge, so it
/// depends on the tilt α + ψ alone: α + atan λ_c is one number (0.6974667578) for every
/// opening, and the tilted arch under self-weight has its own limit state at η = 0.59 (the
/// thickness search, a second implementation of the statics). As α approaches that number
/// λ_c falls to 0 while λ_static stays about 0.017: at α = 0.6974 the collapse acceleration
/// is 99.6 % below the static maximum, checked independently of the crate.
#[test]
fn a_horizontal_acceleration_is_tilted_gravity() {
    let settings = Settings::default();
    let mut tilts = Vec::new();
    for alpha in [0.2, 0.5, 0.6974] {
        let arch = Arch::symmetric(alpha, WeightModel::Centreline).unwrap();
        let (reduction, least) = reduced_independently(&arch, 0.59, 1.0);
        let psi = least.t.atan();
        tilts.push(alpha + psi);
        let tilted = Arch::new(
            -alpha - psi,
            std::f64::consts::PI + alpha - psi,
            WeightModel::Centreline,
        )
        .unwrap();
        let found = survey(&tilted, 1.0, &settings).unwrap();
        let etas: Vec<f64> = match &found.states {
            Ok(ls) => ls.above.iter().map(|s| s.t).collect(),
            Err(e) => panic!("alpha = {alpha}: {e:?}"),
        };
        assert!(
            etas.iter().any(|e| (e - 0.59).abs() < 1e-9),
            "alpha = {alpha}: the tilted arch's limit states {etas:?}"
        );
        if alpha == 0.6974 {
            assert!(reduction > 0.99, "{reduction}");
        }
    }
    for t in &tilts {
        assert!((t - tilts[0]).abs() < 1e-9, "{tilts:?}");
    }
}

/// The top of the band is the band's: on 24 voussoirs the α = 1.1 column holds a sliver of
/// `non_unique` at μ/μ_ms ≈ 2.142, far above the band and not joined to it through
/// neighbouring columns; the top is the band's largest μ/μ_ms (1.08454 at α ≈ 0.6346),
/// between the continuous band's 1.0755 and the 12-voussoir band's 1.0921.
#[test]
fn the_top_is_the_bands_not_a_slivers() {
    let (doc, code) = json_of(&[
        "atlas",
        "--blocks",
        "24",
        "--alpha-min",
        "0.6",
        "--alpha-max",
        "1.1",
        "--columns",
        "11",
        "--mu-max-factor",
        "2.5",
    ]);
    assert_eq!(code, 0);
    let last = &doc["columns"][10];
    let ms = last["mu_ms"].as_f64().unwrap();
    let sliver: Vec<f64> = last["runs"]
        .as_array()
        .unwrap()
        .iter()
        .filter(|r| r["kind"] == "non_unique")
        .map(|r| r["mu_from"].as_f64().unwrap() / ms)
        .collect();
    assert!(sliver.len() == 1 && sliver[0] > 2.0, "{sliver:?}");
    let top = &doc["top"];
    let (alpha, ratio) = (
        top["alpha"].as_f64().unwrap(),
        top["ratio"].as_f64().unwrap(),
    );
    assert!((ratio - 1.08454).abs() < 1e-5, "{top}");
    assert!(alpha > 0.6 && alpha < 0.7, "{top}");
}
