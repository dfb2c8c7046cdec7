//! The edges of the domain as named regression tests: μ at and near μ_ms, sideways
//! arches whose least states grow without bound, very large finite μ, and LPs one back
//! end cannot decide. Each reference value was computed independently (in the issue that
//! reported the case, or as said at the test) and is written here, never in `src/`.

use crate::cli::json_of;
use arch_enum::{solve, Arch, Outcome, Settings, WeightModel};

/// The `eta`, `status` and `attained` of `solve --json` with these arguments.
fn solved(args: &[&str]) -> (String, f64, Option<bool>) {
    let mut all = vec!["solve"];
    all.extend_from_slice(args);
    let (v, code) = json_of(&all);
    assert!(code == 0 || code == 1, "{all:?}: exit {code}, {v}");
    (
        v["status"].as_str().unwrap().to_string(),
        v["eta"].as_f64().unwrap_or(f64::NAN),
        v["attained"].as_bool(),
    )
}

/// Both LP paths fail on one margin LP near this sideways arch's infimum (the dense
/// simplex's optimum touches its box, HiGHS stops with "HiGHS error while solving
/// model"): the dense simplex in HiGHS's retry box decides it, and the answer is the
/// infimum found at μ = 1.7 (the same weightless line of thrust), not "unresolved".
#[test]
fn an_lp_one_back_end_cannot_solve_is_solved_another_way() {
    let (status, eta, attained) = solved(&[
        "--beta-right",
        "-1.4325646298716197",
        "--beta-left",
        "0.15906317839841866",
        "--mu",
        "1.7181703989942783",
    ]);
    assert_eq!(status, "ok");
    assert!((eta - 0.353351604289215).abs() < 1e-14, "{eta}");
    assert_eq!(attained, Some(false));
}

/// A μ within the resolution band above μ_ms is not left unresolved when the arch
/// stands at no η < 2 even without sliding (μ = ∞): admissibility only grows with μ, so
/// no friction makes it stand. (Reference: the independent check, and `solve
/// --mu inf` on this arch.)
#[test]
fn near_mu_ms_an_arch_that_stands_at_no_friction_has_no_equilibrium() {
    let arch = [
        "--beta-right",
        "1.3173171303776912",
        "--beta-left",
        "4.513760350322722",
        "--weight",
        "centroid",
    ];
    for mu in ["5.053055364696166", "inf"] {
        let mut args = arch.to_vec();
        args.extend(["--mu", mu]);
        let (status, _, _) = solved(&args);
        assert_eq!(status, "no_equilibrium", "mu = {mu}");
    }
}

/// `solve --mu ms` is the corner of the vertical branch: the paper's η_ms and the joints
/// of its pattern (reference-values.md, 8 digits as printed), the sliding contacts of the
/// vertical branch, and "not unique" (a purely sliding limit state at every η ≥ η_ms).
#[test]
fn mu_ms_is_the_corner_of_the_vertical_branch() {
    let (v, code) = json_of(&["solve", "--alpha", "0", "--mu", "ms"]);
    assert_eq!(code, 0, "{v}");
    let close = |a: f64, b: f64, tol: f64| (a - b).abs() <= tol;
    assert!(
        close(v["mu"].as_f64().unwrap(), 0.30921544, 5e-9),
        "{}",
        v["mu"]
    );
    assert!(
        close(v["eta"].as_f64().unwrap(), 0.20063732, 5e-9),
        "{}",
        v["eta"]
    );
    let beta_of = |kind: &str| -> Vec<f64> {
        v["pattern"]
            .as_array()
            .unwrap()
            .iter()
            .filter(|c| c["kind"] == kind && c["at"] == "interior")
            .map(|c| c["beta"].as_f64().unwrap())
            .collect()
    };
    let (n, t) = (beta_of("hinge_intrados"), beta_of("slide_minus"));
    assert!(
        n.iter().any(|&b| close(b, 0.51463788, 5e-8)),
        "beta_N {n:?}"
    );
    assert!(t.iter().any(|&b| close(b, 1.0710004, 5e-7)), "beta_T {t:?}");
    assert_eq!(v["unique"], false);
    assert_eq!(v["vertical_branch"]["mode"], "purely_sliding");
    assert_eq!(v["vertical_branch"]["eta_min"], v["eta"]);
    let sliding = v["vertical_branch"]["pattern"].as_array().unwrap();
    assert!(sliding
        .iter()
        .all(|c| c["kind"].as_str().unwrap().starts_with("slide")));
}

/// At μ exactly μ_ms of a discrete arch (as `modes` prints it) η_s is the corner η_ms,
/// the limit of η_s(μ) as μ falls to μ_ms: it jumped to 0.9758 ("5 contacts, all
/// sliding"). Reference: the issue's independent value 0.2009 at that μ, and the linear
/// extrapolation of η_s from two frictions above the band, computed here.
#[test]
fn at_mu_ms_a_discrete_arch_gives_the_corner() {
    let arch = ["--alpha", "0", "--blocks", "6"];
    let at = |mu: &str| {
        let mut a = arch.to_vec();
        a.extend(["--mu", mu]);
        solved(&a)
    };
    let (status, eta, _) = at("0.3089884870289604");
    assert_eq!(status, "ok");
    assert!((eta - 0.2009).abs() < 5e-5, "{eta}");
    let mu_ms = 0.3089884870289604_f64;
    let (m1, m2) = (mu_ms * (1.0 + 1e-5), mu_ms * (1.0 + 2e-5));
    let (e1, e2) = (at(&m1.to_string()).1, at(&m2.to_string()).1);
    let extrapolated = e1 - (e2 - e1) / (m2 - m1) * (m1 - mu_ms);
    assert!(
        (eta - extrapolated).abs() < 1e-9 * eta,
        "{eta} vs {extrapolated}"
    );
}

/// η_s(μ) never rises as μ grows, through the band just above μ_ms where the margin LP
/// no longer resolves admissibility (μ_ms (1 + 1e-8) to μ_ms (1 + 1e-4)): in 21 of 35
/// arches tried it went up between neighbouring μ there. Discrete and continuous,
/// symmetric and not.
#[test]
fn eta_s_does_not_rise_through_the_band_above_mu_ms() {
    let arches: [&[&str]; 4] = [
        &["--alpha", "0", "--blocks", "6"],
        &["--alpha", "0.3", "--blocks", "11"],
        &["--beta-right", "-0.2", "--beta-left", "2.9"],
        &["--beta-right", "0.1", "--beta-left", "3.3", "--blocks", "9"],
    ];
    for arch in arches {
        let mut a = vec!["solve"];
        a.extend_from_slice(arch);
        a.extend(["--mu", "ms"]);
        let (v, code) = json_of(&a);
        assert_eq!(code, 0, "{arch:?}: {v}");
        let (mu_ms, mut last) = (v["mu"].as_f64().unwrap(), v["eta"].as_f64().unwrap());
        for rel in [1e-8, 1e-7, 5e-7, 9.99e-7, 1.001e-6, 3e-6, 1e-5, 1e-4] {
            let mu = (mu_ms * (1.0 + rel)).to_string();
            let mut b = arch.to_vec();
            b.extend(["--mu", mu.as_str()]);
            let (status, eta, _) = solved(&b);
            assert_eq!(status, "ok", "{arch:?} mu {mu}");
            assert!(
                eta <= last * (1.0 + 1e-12),
                "{arch:?} mu {mu}: {eta} > {last}"
            );
            assert!(
                eta >= last * (1.0 - 1e-3),
                "{arch:?} mu {mu}: {eta} << {last}"
            );
            last = eta;
        }
    }
}

/// Below μ_ms by more than its rounding (the paper's printed 0.30921544 is) no thickness
/// stands; `--mu ms` on an arch that needs no friction is bad input naming `--mu`.
#[test]
fn below_mu_ms_no_equilibrium_and_ms_without_one_is_refused() {
    let (status, _, _) = solved(&["--alpha", "0", "--mu", "0.30921544"]);
    assert_eq!(status, "no_equilibrium");
    let out = crate::cli::arch_enum()
        .args(["solve", "--alpha", "0", "--blocks", "2", "--mu", "ms"])
        .output()
        .unwrap();
    let err = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(2), "{err}");
    assert!(err.contains("--mu ms"), "{err}");
}

/// `plot arch --mu ms --eta E` above η_ms draws the paper's purely sliding figure: a
/// limit state of the vertical branch with its sliding mechanism.
#[test]
fn plot_arch_at_mu_ms_draws_a_purely_sliding_limit_state() {
    let dir = std::env::temp_dir().join(format!("arch-enum-ms-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let out = dir.join("ms.svg");
    let run = crate::cli::arch_enum()
        .args([
            "plot", "arch", "--alpha", "0", "--mu", "ms", "--eta", "0.3", "--out",
        ])
        .arg(&out)
        .output()
        .unwrap();
    assert!(
        run.status.success(),
        "{}",
        String::from_utf8_lossy(&run.stderr)
    );
    let svg = std::fs::read_to_string(&out).unwrap();
    assert!(svg.contains("mode purely_sliding"), "title of the figure");
    assert!(svg.contains("η = 0.300"));
    let _ = std::fs::remove_dir_all(&dir);
}

/// A sideways two-voussoir arch at μ = 1e6: η_s is the infimum of μ = ∞ (a weightless
/// line of thrust through E, I, E, crossing every joint at T/N ≤ tan 0.95 ≪ 1e6), not
/// attained. The issue that reported the case proposed 0.528951759880497, attained; the
/// tests' own LP (model.rs, written apart from the crate) finds admissible states at
/// thicknesses between the two, so that value is not the least, and none below the
/// infimum.
#[test]
fn large_finite_friction_keeps_the_infimum_of_a_weightless_line() {
    let args = [
        "--beta-right",
        "-1.4",
        "--beta-left",
        "0.5",
        "--blocks",
        "2",
    ];
    let mut a = args.to_vec();
    a.extend(["--mu", "1e6"]);
    let (status, eta, attained) = solved(&a);
    assert_eq!(status, "ok");
    assert!((eta - 0.5289516127758643).abs() < 1e-15, "{eta}");
    assert_eq!(attained, Some(false));
    let joints = [-1.4, -0.45, 0.5];
    for between in [0.52895165, 0.5289517] {
        assert!(
            crate::model::grid_feasible(-1.4, &joints, between, 1e6),
            "{between}"
        );
    }
    assert!(!crate::model::grid_feasible(-1.4, &joints, 0.5289515, 1e6));
}

/// The continuous sideways arch at μ = 1e6: η_s is an infimum whatever the search above
/// it says, and the state found there (reactions ~1e9, external power 0.0178 against no
/// dissipation) is reported as no limit state: `attained` false, no mechanism at η_s.
#[test]
fn an_infimum_is_no_limit_state_even_when_the_search_above_is_incomplete() {
    for mu in ["1e3", "1e6", "1e9", "inf"] {
        let (v, code) = json_of(&[
            "solve",
            "--beta-right",
            "-1.1",
            "--beta-left",
            "1.0",
            "--mu",
            mu,
        ]);
        assert!(code == 0 || code == 1, "{v}");
        assert_eq!(v["status"], "ok", "mu {mu}");
        let eta = v["eta"].as_f64().unwrap();
        assert!((eta - 0.670991807454598).abs() < 1e-14, "mu {mu}: {eta}");
        assert_eq!(v["attained"], false, "mu {mu}");
        assert_eq!(v["mechanism_at_eta"], false, "mu {mu}");
        if v["search"]["complete"] == false {
            assert!(
                v["mechanism"].is_null() && v["reactions"].is_null(),
                "mu {mu}: {v}"
            );
        }
    }
}

/// μ_ms of a sideways arch whose friction limit is a weightless line of thrust along the
/// chord is tan(Δ/2) to the last digit (the LP bracket gave 9 digits: 1.229076281153).
/// Reference: the closed form, computed here.
#[test]
fn mu_ms_of_a_weightless_chord_line_is_tan_of_half_the_opening() {
    let (br, bl) = (-1.2494380567094454_f64, 0.5261739770329115_f64);
    let (v, _) = json_of(&[
        "solve",
        "--beta-right",
        &br.to_string(),
        "--beta-left",
        &bl.to_string(),
        "--mu",
        "1e-9",
    ]);
    assert_eq!(v["status"], "no_equilibrium");
    let mu_ms = v["mu_ms"].as_f64().unwrap();
    let exact = (0.5 * (bl - br)).tan();
    assert!(
        (mu_ms - exact).abs() <= 4.0 * f64::EPSILON * exact,
        "{mu_ms} vs {exact}"
    );
}

/// A sideways arch with a near-vertical chord (true-centroid weight) near μ = 2.1622,
/// where the least states' reactions exceed 1e6 and a weightless direction lies just
/// above them: η_s was snapped up to that direction's η_rec (0.8173472049946352) over a
/// band of μ 2e-7 wide, flat where the boundary falls with slope about −0.16, and above
/// admissible states found below it. η_s must fall strictly through the band, and keep the
/// independent reference's 0.8173471727285947 at μ = 2.162176106125 (issue text).
#[test]
fn eta_s_is_not_snapped_above_a_finite_state_on_a_near_vertical_chord() {
    let arch = [
        "--beta-right",
        "-1.0480193077958069",
        "--beta-left",
        "1.2271778497692674",
        "--weight",
        "centroid",
    ];
    let at = |mu: &str| {
        let mut a = arch.to_vec();
        a.extend(["--mu", mu]);
        solved(&a).1
    };
    assert!((at("2.162176106125") - 0.8173471727285947).abs() < 1e-12);
    let etas: Vec<f64> = ["2.1621762", "2.1621761", "2.162176", "2.1621759"]
        .iter()
        .map(|m| at(m))
        .collect();
    for w in etas.windows(2) {
        assert!(w[1] > w[0] + 1e-9, "eta_s must rise as mu falls: {etas:?}");
    }
}

/// A campaign arch of 39 voussoirs (η_s an infimum) with its joint 20 moved by 4.9e-10 rad:
/// three intrados rows there and at joint 19 have a root of their determinant 8.6e-12 below
/// η_rec, where a ray of the weightless cone is admissible but the cone does not open. The
/// solve took that root (0.26158493183507614); its certificate proves no state at
/// 0.2615849318435665 with rows that do not involve joint 20. η_rec is the least root above
/// which the cone opens: the unedited arch's 0.2615849318436973, to rounding.
#[test]
fn an_infimum_is_the_root_where_the_weightless_cone_opens() {
    let joints = [
        -1.2047345923244206,
        -1.1691332775467893,
        -1.1335319627691578,
        -1.0979306479915265,
        -1.0623293332138952,
        -1.0267280184362637,
        -0.9911267036586324,
        -0.955525388881001,
        -0.9199240741033696,
        -0.8843227593257382,
        -0.8487214445481068,
        -0.8131201297704755,
        -0.7775188149928441,
        -0.7419175002152127,
        -0.7063161854375815,
        -0.67071487065995,
        -0.6351135558823187,
        -0.5995122411046873,
        -0.5639109263270559,
        -0.5283096115494246,
        -0.4927082962790848,
        -0.4571069819941618,
        -0.4215056672165304,
        -0.385904352438899,
        -0.3503030376612677,
        -0.3147017228836364,
        -0.2791004081060048,
        -0.2434990933283735,
        -0.2078977785507422,
        -0.1722964637731108,
        -0.1366951489954793,
        -0.10109383421784801,
        -0.06549251944021672,
        -0.029891204662585213,
        0.005710110115046074,
        0.041311424892677584,
        0.07691273967030887,
        0.11251405444794016,
        0.14811536922557145,
        0.18371668400320296,
    ];
    let arch = Arch::new(joints[0], joints[joints.len() - 1], WeightModel::Centreline)
        .unwrap()
        .with_joints(&joints)
        .unwrap();
    let sol = solve(&arch, 6.79195980557732, &Settings::default()).unwrap();
    let Outcome::Limit(ls) = sol.outcome else {
        panic!("{:?}", sol.outcome)
    };
    assert!(!ls.attained);
    assert!(ls.eta_static >= 0.2615849318435665, "{}", ls.eta_static);
    assert!(
        (ls.eta_static - 0.2615849318436973).abs() < 1e-15,
        "{}",
        ls.eta_static
    );
}
