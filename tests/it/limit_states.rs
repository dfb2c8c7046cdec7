//! The sweep of `limit_states` against the brute-force reference of `search_reference`
//! (written independently from the formulation): on random small discrete arches, the
//! same least admissible thickness, whether it carries a mechanism, and the same limit
//! states above it (η to 1e-10 relative).

use crate::continuum_reference::Cont;
use crate::search_reference::{
    brute_force, brute_force_filled, least_friction, random_joints, RefSearch, Rng,
};
use arch_enum::limit_states::{search, LimitState};
use arch_enum::{Arch, Settings, WeightModel};
use std::f64::consts::PI;

/// One arch compared; `Err` describes the disagreement.
fn compare(br: f64, bl: f64, joints: &[f64], centroid: bool, mu: f64) -> Result<usize, String> {
    compare_with(
        &brute_force(br, bl, joints, centroid, mu),
        joints,
        centroid,
        mu,
        None,
    )
}

/// [`compare`] with the reference already computed.
fn compare_with(
    reference: &RefSearch,
    joints: &[f64],
    centroid: bool,
    mu: f64,
    fill: Option<(f64, f64)>,
) -> Result<usize, String> {
    let (br, bl) = (joints[0], joints[joints.len() - 1]);
    let weight = if centroid {
        WeightModel::Centroid
    } else {
        WeightModel::Centreline
    };
    let mut arch = Arch::new(br, bl, weight)
        .unwrap()
        .with_joints(joints)
        .unwrap();
    if let Some((g, h)) = fill {
        arch = arch.with_fill(arch_enum::fill::Fill::new(g, h).unwrap());
    }
    let ref_above: Vec<f64> = reference
        .states
        .iter()
        .map(|s| s.eta)
        .filter(|&e| e > reference.eta_s * (1.0 + 1e-9))
        .collect();
    let found = search(&arch, mu, &Settings::default()).unwrap();
    let r = match found {
        Ok(r) => r,
        Err(e) => {
            // no search (no least state: the arch stands at every η > 0, or none stands):
            // the reference must find no limit state either
            return if (reference.eta_s.is_finite() && reference.attained)
                || !reference.states.is_empty()
            {
                Err(format!(
                    "search failed ({e}); reference eta_s {} states {ref_above:?}",
                    reference.eta_s
                ))
            } else {
                Ok(0)
            };
        }
    };
    let above: Vec<f64> = r.above.iter().map(|s| s.t).collect();
    let close = |a: f64, b: f64| (a - b).abs() <= 1e-10 * b.abs().max(1e-300);
    if !close(r.eta_s, reference.eta_s) {
        return Err(format!(
            "eta_s {} vs reference {}",
            r.eta_s, reference.eta_s
        ));
    }
    if r.mechanism_at_eta_s != reference.mechanism_at_eta_s {
        return Err(format!(
            "mechanism at eta_s: {} vs reference {}",
            r.mechanism_at_eta_s, reference.mechanism_at_eta_s
        ));
    }
    if above.len() != ref_above.len() || !above.iter().zip(&ref_above).all(|(a, b)| close(*a, *b)) {
        return Err(format!("above eta_s: {above:?} vs reference {ref_above:?}"));
    }
    Ok(above.len())
}

#[test]
fn sweep_matches_brute_force_on_random_discrete_arches() {
    let mut rng = Rng(0x51ee_7a11_0000_0001);
    let mut failures = Vec::new();
    let (mut cases, mut nonunique) = (0, 0);
    // SWEEP_CASES=N runs more (the CI runs 40)
    let count = crate::cases_from_env("SWEEP_CASES", 40);
    for case in 0..count {
        let n = 3 + (rng.next() * 5.0) as usize;
        let br = -1.0 + 1.6 * rng.next();
        let mut bl = PI - 1.0 + 1.6 * rng.next();
        if std::env::var("SWEEP_WILD").is_ok() {
            // springings anywhere (shallow, steep and unsymmetric arches)
            bl = br + 0.3 + 4.0 * rng.next();
        }
        let joints = random_joints(&mut rng, br, bl, n);
        let centroid = rng.next() < 0.3;
        let ms = least_friction(br, bl, &joints);
        let u = rng.next();
        let mu = if u < 0.15 {
            f64::INFINITY
        } else {
            ms * (1.0 + 1e-3) + 2.0 * u * u
        };
        cases += 1;
        match compare(br, bl, &joints, centroid, mu) {
            Ok(k) => nonunique += usize::from(k > 0),
            Err(e) => failures.push(format!(
                "case {case}: beta_r {br:?} beta_l {bl:?} joints {joints:?} centroid {centroid} mu {mu:?}: {e}"
            )),
        }
    }
    println!(
        "{cases} arches, {nonunique} with limit states above eta_s, {} disagreements",
        failures.len()
    );
    assert!(failures.is_empty(), "{}", failures.join("\n"));
}

/// A symmetric horseshoe (α = 1, six voussoirs) on its mixed branch has a mirror pair of
/// sliding limit states above η_s (found by the brute force): the paper's uniqueness for
/// symmetric arches does not hold for this discrete one.
#[test]
fn symmetric_horseshoe_has_a_mirror_pair_above_eta_s() {
    let arch = Arch::symmetric(1.0, WeightModel::Centreline)
        .unwrap()
        .with_blocks(6)
        .unwrap();
    let joints: Vec<f64> = (0..=6)
        .map(|i| -1.0 + (PI + 2.0) * i as f64 / 6.0)
        .collect();
    let mu = 1.5856196872768473;
    compare(-1.0, PI + 1.0, &joints, false, mu).unwrap();
    let r = search(&arch, mu, &Settings::default()).unwrap().unwrap();
    assert!((r.eta_s - 0.865444979502).abs() < 1e-11, "{}", r.eta_s);
    assert!(r.mechanism_at_eta_s);
    assert_eq!(
        r.above.len(),
        2,
        "{:?}",
        r.above.iter().map(|s| s.t).collect::<Vec<_>>()
    );
    for s in &r.above {
        assert!((s.t - 0.905960101783).abs() < 1e-11, "{}", s.t);
    }
}

/// Three contacts whose compatibility columns become dependent at one η (a slide at the
/// springing parallel to the line through two hinges) carry a mechanism there; the sweep
/// checks the vertex paths for it (found by the 300-arch comparison).
#[test]
fn three_contact_limit_states() {
    let joints = [
        -0.5527213062436992,
        0.5674960118886844,
        1.699831711477676,
        2.4944476355166096,
        3.473194916317591,
    ];
    assert_eq!(
        compare(joints[0], joints[4], &joints, false, 0.7840135591071118),
        Ok(2)
    );
    let joints = [
        -0.8267114543097964,
        -0.12461322939120767,
        0.9193745997441067,
        2.3229218950128856,
    ];
    assert_eq!(
        compare(joints[0], joints[3], &joints, false, 1.1444780404907526),
        Ok(3)
    );
}

/// No mechanism at η_s; the only limit state lies just above it (true-centroid weight).
#[test]
fn gap_above_eta_s_centroid() {
    let joints = [
        -0.568778191168789,
        -0.056449719170271195,
        0.30495434919698894,
        0.7789335630266991,
        1.1355877561557521,
        1.8745647497900773,
        2.5372897601358275,
        3.1937014044750986,
    ];
    let k = compare(joints[0], joints[7], &joints, true, 0.7936030995826601).unwrap();
    assert_eq!(k, 1);
}

/// The polynomial toolkit of the sweep: every root found is a root, none is missed (against
/// dense sampling), and the Bernstein bounds enclose the values on the interval.
#[test]
fn polynomial_roots_and_bounds() {
    use arch_enum::limit_states::poly::Poly;
    let mut rng = Rng(0x0b0b_5eed);
    for _ in 0..300 {
        let deg = 1 + (rng.next() * 5.0) as usize;
        // roots placed on purpose, some inside [0, 2], times a random factor
        let mut p = Poly::constant(1.0 + rng.next());
        let mut inside = Vec::new();
        for _ in 0..deg {
            let r = -0.5 + 3.0 * rng.next();
            if (0.0..=2.0).contains(&r) {
                inside.push(r);
            }
            p = p.mul(&Poly::linear(-r, 1.0));
        }
        let roots = p.roots_in(0.0, 2.0, 1e-15, 1.0).unwrap();
        inside.sort_by(f64::total_cmp);
        inside.dedup_by(|a, b| (*a - *b).abs() < 1e-6);
        for r in &inside {
            assert!(
                roots.iter().any(|f| (f - r).abs() < 1e-6),
                "{r} not in {roots:?}"
            );
        }
        for f in &roots {
            assert!(
                inside.iter().any(|r| (f - r).abs() < 1e-6),
                "spurious {f}: {inside:?}"
            );
        }
        let (lo, hi) = (0.3 * rng.next(), 0.5 + 1.5 * rng.next());
        let (bmin, bmax) = p.bernstein_bounds(lo, hi);
        for i in 0..=200 {
            let t = lo + (hi - lo) * i as f64 / 200.0;
            let v = p.eval(t);
            let slack = 1e-12 * (1.0 + v.abs());
            assert!(
                v >= bmin - slack && v <= bmax + slack,
                "{v} outside [{bmin}, {bmax}]"
            );
        }
    }
}

/// `Poly::bernstein_sign` decides as the signs of `Poly::bernstein_bounds` do, on
/// polynomials of the sweep's degrees whose sign on the interval is clear, unclear or
/// mixed (so both its shortcut, from the shifted coefficients' signs, and its full path are
/// taken), for either sign asked and for empty and reversed intervals.
#[test]
fn bernstein_sign_decides_as_the_bounds() {
    use arch_enum::limit_states::poly::Poly;
    let mut rng = Rng(0x0b0b_5eef);
    let (mut shortcut_cases, mut yes, mut no) = (0, 0, 0);
    for _ in 0..20_000 {
        let deg = (rng.next() * 8.0) as usize;
        let offset = 4.0 * rng.next() - 2.0;
        let c: Vec<f64> = (0..=deg)
            .map(|k| {
                let v = rng.next() - 0.5;
                if k == 0 {
                    offset + v
                } else {
                    v * 10f64.powf(-3.0 * rng.next())
                }
            })
            .collect();
        let p = Poly::from_coeffs(&c);
        let lo = 2.0 * rng.next() - 0.5;
        let hi = match (rng.next() * 10.0) as usize {
            0 => lo,
            1 => lo - 0.1,
            _ => lo + 2.0 * rng.next(),
        };
        let (bmin, bmax) = p.bernstein_bounds(lo, hi);
        for sign in [1.0, -1.0] {
            let expected = if sign > 0.0 { bmin > 0.0 } else { bmax < 0.0 };
            assert_eq!(
                p.bernstein_sign(lo, hi, sign),
                expected,
                "{c:?} on [{lo}, {hi}], sign {sign}: bounds [{bmin}, {bmax}]"
            );
            // the coefficients in η − lo: p^(k)(lo) / k!, all of the sign asked (the
            // shortcut's case, counted so that the test sees it taken)
            let (mut d, mut f) = (p, 1.0);
            let shifted = (0..=deg).all(|k| {
                let a = d.eval(lo) / f;
                d = d.derivative();
                f *= (k + 1) as f64;
                sign * a > 1e-9
            });
            shortcut_cases += usize::from(hi > lo && shifted);
            if expected {
                yes += 1;
            } else {
                no += 1;
            }
        }
    }
    assert!(yes > 5_000 && no > 5_000, "{yes} yes, {no} no");
    assert!(shortcut_cases > 100, "{shortcut_cases}");
    assert!(!Poly::from_coeffs(&[]).bernstein_sign(0.0, 1.0, 1.0));
    assert!(!Poly::constant(1.0).bernstein_sign(0.0, 1.0, f64::NAN));
}

/// `Poly::sum_of_products` gives the bits of folding `mul` and `add` (the sweep's crossing
/// polynomials were formed so), for terms of every length the sweep meets, empty included.
#[test]
fn sum_of_products_has_the_bits_of_mul_and_add() {
    use arch_enum::limit_states::poly::Poly;
    let mut rng = Rng(0x50b5_0f1d);
    let random = |rng: &mut Rng| {
        let n = (rng.next() * 6.0) as usize;
        let c: Vec<f64> = (0..n).map(|_| rng.next() - 0.5).collect();
        Poly::from_coeffs(&c)
    };
    for _ in 0..5_000 {
        let t: Vec<(Poly, Poly)> = (0..4)
            .map(|_| (random(&mut rng), random(&mut rng)))
            .collect();
        let folded = t[1..]
            .iter()
            .fold(t[0].0.mul(&t[0].1), |acc, (a, b)| acc.add(&a.mul(b)));
        let fused = Poly::sum_of_products([
            (&t[0].0, &t[0].1),
            (&t[1].0, &t[1].1),
            (&t[2].0, &t[2].1),
            (&t[3].0, &t[3].1),
        ]);
        let bits = |p: &Poly| p.coeffs().iter().map(|v| v.to_bits()).collect::<Vec<_>>();
        assert_eq!(bits(&fused), bits(&folded), "{t:?}");
    }
}

/// The unsymmetric arch: η_s is monotone in μ (the old "widened" answer was not),
/// and at μ = 0.96 the least admissible state carries no mechanism while one limit state
/// lies above it.
#[test]
fn unsymmetric_gap_is_decided() {
    let arch = Arch::new(-0.67, 2.72, WeightModel::Centreline).unwrap();
    let s = Settings::default();
    let etas: Vec<f64> = [0.94, 0.96, 1.0]
        .iter()
        .map(|&mu| search(&arch, mu, &s).unwrap().unwrap().eta_s)
        .collect();
    assert!(etas[0] > etas[1] && etas[1] > etas[2], "{etas:?}");
    let r = search(&arch, 0.96, &s).unwrap().unwrap();
    assert!(!r.mechanism_at_eta_s);
    assert_eq!(r.above.len(), 1);
    assert!(
        r.above[0].t > r.eta_s * 1.1,
        "{} vs {}",
        r.above[0].t,
        r.eta_s
    );
}

/// A continuous symmetric arch (α = 0.8) just above μ_ms: a mirror pair of unsymmetric
/// limit states above η_s, found by both discretisations and refined on the continuum.
#[test]
fn continuous_symmetric_mirror_pair() {
    let arch = Arch::symmetric(0.8, WeightModel::Centreline).unwrap();
    let r = search(&arch, 1.1540692474221415, &Settings::default())
        .unwrap()
        .unwrap();
    assert!(r.mechanism_at_eta_s);
    assert_eq!(r.above.len(), 2);
    assert_mirror_pair(&r.above[0], &r.above[1]);
}

/// Two limit states of a symmetric arch are mirror images: the same η, and β ↦ π − β,
/// S+ ↔ S− between their contacts.
fn assert_mirror_pair(a: &LimitState, b: &LimitState) {
    assert!((a.t - b.t).abs() < 1e-10 * a.t);
    for c in &a.pattern {
        assert!(
            b.pattern
                .iter()
                .any(|d| d.kind == c.kind.mirrored() && (d.beta - (PI - c.beta)).abs() < 1e-7),
            "{c:?} has no mirror in {:?}",
            b.pattern
        );
    }
}

/// Near where a branch of limit states is born or dies, a coarse discretisation searched at
/// μ only (`carry_shift` = `carry_almost_rate` = 0) can miss it. Continuous arch α = 0.7 at μ
/// = 1.0408: the 48-piece search finds no limit state above η_s, the 96-piece one a mirror
/// pair; with one doubling only the search is undecided; with three the pieces are doubled
/// again and 96 and 192 agree on the pair, which the independent reference of
/// `continuum_reference` finds admissible over the whole arch with its contacts active.
/// With the default `carry_shift` the 48-piece discretisation, searched a little above and
/// below μ too, finds the pair, and 48 and 96 agree on it. At α = 0.65, μ = 0.9257 the
/// lists alternate (the pair found by 48 × 2 and 48 × 8 pieces, missed by 48 and 48 × 4):
/// no list is taken, and the message lists all four; but η_s carries a limit state and the
/// pair found is verified on the continuum, so `unique` is decided `false` all the same
/// (`solve --json` would list the three, with `search.complete` false). With the default
/// the four agree (`solve --json`: the three listed, the search complete).
#[test]
fn finer_discretisations_decide_where_two_differ() {
    use arch_enum::undecided::Undecided;
    let arch = Arch::symmetric(0.7, WeightModel::Centreline).unwrap();
    let mu = 1.0408;
    let at_mu = Settings {
        carry_shift: 0.0,
        carry_almost_rate: 0.0,
        ..Settings::default()
    };
    let once = Settings {
        sweep_doublings: 1,
        ..at_mu.clone()
    };
    match search(&arch, mu, &once).unwrap() {
        Err(Undecided::Discretisation(t)) => assert!(t.contains("48 and 96 pieces"), "{t}"),
        other => panic!("expected two discretisations that differ, got {other:?}"),
    }
    let r = search(&arch, mu, &at_mu).unwrap().unwrap();
    assert_eq!(r.method, "refined 96/192 (ridge)");
    let d = search(&arch, mu, &Settings::default()).unwrap().unwrap();
    assert_eq!(d.method, "refined 48/96 (ridge)");
    assert_eq!(d.above.len(), 2);
    for (p, q) in d.above.iter().zip(&r.above) {
        assert!((p.t - q.t).abs() <= 1e-12 * q.t, "{} vs {}", p.t, q.t);
    }
    assert!(r.mechanism_at_eta_s);
    assert_eq!(r.above.len(), 2);
    assert_mirror_pair(&r.above[0], &r.above[1]);
    let reference = Cont::of(&arch, mu);
    for s in &r.above {
        assert!(s.t > 1.3 * r.eta_s, "{} vs {}", s.t, r.eta_s);
        let x = [s.x[0], s.x[1], s.x[2]];
        let worst = reference.worst(s.t, &x);
        assert!(
            worst <= 1e-9,
            "the state at {} is violated by {worst:e}",
            s.t
        );
        for c in &s.pattern {
            let g = reference.g(c.kind as usize, s.t, &x, c.beta);
            assert!(g.abs() <= 1e-9, "{c:?} is not active: {g:e}");
        }
    }
    let alternating = Arch::symmetric(0.65, WeightModel::Centreline).unwrap();
    match search(&alternating, 0.9257, &at_mu).unwrap() {
        Err(Undecided::Discretisation(t)) => assert!(
            t.contains("48, 96, 192 and 384 pieces do not settle: [] vs [0.5593"),
            "{t}"
        ),
        other => panic!("expected lists that do not settle, got {other:?}"),
    }
    let sv = arch_enum::limit_states::survey(&alternating, 0.9257, &at_mu).unwrap();
    assert!(sv.states.is_err());
    assert_eq!(sv.found.len(), 2);
    assert_mirror_pair(&sv.found[0], &sv.found[1]);
    assert_eq!(sv.unique(), Some(false));
    let (v, code) = crate::cli::json_of(&["solve", "--alpha", "0.65", "--mu", "0.9257"]);
    assert_eq!(code, 0);
    assert_eq!(v["unique"], false);
    assert_eq!(v["search"]["complete"], true);
    let listed: Vec<f64> = v["limit_states"]
        .as_array()
        .unwrap()
        .iter()
        .map(|l| l["eta"].as_f64().unwrap())
        .collect();
    assert_eq!(listed.len(), 3, "{listed:?}");
    assert_eq!(listed[0], v["eta"].as_f64().unwrap());
    assert_eq!(&listed[1..], &[sv.found[0].t, sv.found[1].t]);
}

/// Issue 10: an arch whose springings lie nearly one above the other (a steep segment):
/// its least thickness is an infimum approached only as the reactions grow without bound
/// (the brute force finds it as the least η of a weightless recession direction). It used
/// to come back as an ordinary limit state at η_s with reactions ~5e9 and a virtual-work
/// mismatch; now η_s is reported as not attained and carries no limit state, as the
/// reference says.
#[test]
fn infimum_is_not_a_limit_state() {
    let joints = [
        -0.38915676526385157,
        -0.1936390113304968,
        -0.056548071547972256,
        0.17513886376402904,
    ];
    compare(joints[0], joints[3], &joints, false, f64::INFINITY).unwrap();
    let arch = Arch::new(joints[0], joints[3], WeightModel::Centreline)
        .unwrap()
        .with_joints(&joints)
        .unwrap();
    let r = search(&arch, f64::INFINITY, &Settings::default())
        .unwrap()
        .unwrap();
    assert!(!r.attained);
    assert!(!r.mechanism_at_eta_s);
}

/// Two- and three-voussoir arches with springings anywhere (issue 10), both weight models,
/// μ = ∞ on about one case in six: the cases where a state without tension is admissible at
/// vanishing thickness (η_s = 0, the arch stands at every η > 0) and still has limit states
/// above, where four contacts meet with a sliding mechanism, and the two-voussoir arches
/// at μ = ∞ whose state at η = 0 is in tension (once reported as standing at every η).
/// `SMALL_CASES=N` runs more (the CI runs 40).
#[test]
fn few_voussoir_arches_match_brute_force() {
    let mut rng = Rng(0x2233_0001);
    let count = crate::cases_from_env("SMALL_CASES", 40);
    let mut failures = Vec::new();
    let (mut zero, mut zero_above) = (0, 0);
    for case in 0..count {
        let blocks = 2 + (rng.next() * 2.0) as usize;
        let br = -1.2 + 2.4 * rng.next();
        let bl = br + 0.3 + 4.0 * rng.next();
        let joints = random_joints(&mut rng, br, bl, blocks);
        let centroid = rng.next() < 0.3;
        let ms = least_friction(br, bl, &joints);
        let u = rng.next();
        let mu = if u < 0.15 {
            f64::INFINITY
        } else {
            ms * (1.0 + 1e-4) + 2.0 * u * u * u
        };
        let reference = brute_force(br, bl, &joints, centroid, mu);
        match compare_with(&reference, &joints, centroid, mu, None) {
            Ok(k) => {
                if reference.eta_s == 0.0 {
                    zero += 1;
                    zero_above += usize::from(k > 0);
                }
            }
            Err(e) => failures.push(format!(
                "case {case}: joints {joints:?} centroid {centroid} mu {mu:?}: {e}"
            )),
        }
    }
    println!(
        "{count} arches of 2 and 3 voussoirs, {zero} standing at every eta > 0 ({zero_above} of them with limit states above), {} disagreements",
        failures.len()
    );
    assert!(failures.is_empty(), "{}", failures.join("\n"));
}

/// Two-voussoir arches (three joints, issue 10): where two contacts sit at one joint (a
/// hinge and a slide) and a springing contact is active too, the active set used to drop
/// a joint whose neighbour had the same value (a local-maximum filter over the joints),
/// so η_s was reported without its mechanism; most such arches stand at every η > 0
/// (`no_collapse`), and the reference must then find no limit state either.
#[test]
fn two_voussoir_arches_match_brute_force() {
    let mut rng = Rng(0x2222);
    let mut failures = Vec::new();
    for case in 0..40 {
        let br = -1.0 + 1.6 * rng.next();
        let bl = PI - 1.0 + 1.6 * rng.next();
        let joints = random_joints(&mut rng, br, bl, 2);
        let ms = least_friction(br, bl, &joints);
        let mu = ms * (1.0 + 1e-3) + 2.0 * rng.next();
        if let Err(e) = compare(br, bl, &joints, false, mu) {
            failures.push(format!("case {case}: joints {joints:?} mu {mu:?}: {e}"));
        }
    }
    // the case that exposed the dropped joint
    let j = [-0.4789088407912342, 1.125298612377978, 3.621918195256505];
    if let Err(e) = compare(j[0], j[2], &j, false, 0.8169115459030362) {
        failures.push(format!("dropped-joint case: {e}"));
    }
    assert!(failures.is_empty(), "{}", failures.join("\n"));
}

/// A continuous steep segment (springings nearly one above the other): η_s is the infimum
/// η = 2 tan²(Δ/4) at which a straight weightless line of thrust fits (formulation §3 with
/// no weight: the chord of the span Δ at distance 1 − η/2 from the centre must reach the
/// extrados at the ends). The crate approaches it with growing reactions: `attained` is
/// false, no limit state at η_s, and η_s equals the closed form to 1e-9 relative.
#[test]
fn continuous_infimum_matches_the_closed_form() {
    // span 1.2 used to end in "HiGHS error while solving model: Error" (the margin LP
    // unbounded near the infimum; the LP now boxes the reactions at 1e12)
    for span in [0.3, 0.5, 0.8, 1.0, 1.2, 1.5, 2.0] {
        let br = -0.2 - span / 2.0;
        let arch = Arch::new(br, br + span, WeightModel::Centreline).unwrap();
        let r = search(&arch, f64::INFINITY, &Settings::default())
            .unwrap()
            .unwrap();
        let exact = 2.0 * (span / 4.0f64).tan().powi(2);
        assert!(!r.attained && !r.mechanism_at_eta_s, "{span}");
        assert!(
            (r.eta_s - exact).abs() <= 1e-9 * exact,
            "{span}: {} vs {exact}",
            r.eta_s
        );
    }
}

/// Wild random arches (issue 10): an arch balanced on the extrados edge of its right
/// springing with the left springing fully detached (N = T = M = 0 there: the whole arch
/// cantilevers from the right springing, x = (0, W, w)). Its mechanism — a rotation about
/// that edge, the left joint opening and sliding — does no work (L_e = 0: the centre of
/// mass is directly above the edge) and dissipates nothing (N = 0 where it slides). The
/// brute force used to reject it: its L_e ≥ 0 test was relative to Σ|λ_i ℓ_i|, itself
/// rounding noise when L_e cancels exactly, so whether the state was seen depended on the
/// last bits of the build (10 of the 12 wild disagreements). Independent check: with the
/// weight on the centreline, G_x = (sin β_L − sin β_R)/Δ = (1 + η/2) cos β_R, i.e.
/// η = 2 [(sin β_L − sin β_R)/(Δ cos β_R) − 1].
#[test]
fn balanced_on_one_springing_edge() {
    let cases: [(&[f64], bool, f64, usize); 3] = [
        // η_s attained, no mechanism there; the balanced state is the only one above
        (
            &[
                -0.9690698810058832,
                -0.6707848425293645,
                -0.30447332102707225,
                0.4105522938447438,
                0.9740878243588463,
                1.3858921883746107,
            ],
            false,
            3.103692812129597,
            1,
        ),
        // η_s an infimum; a sliding limit state and then the balanced one above it
        (
            &[
                -0.32196753082506324,
                -0.24253358901213173,
                -0.17027533502632738,
                -0.06459929802088032,
                -0.009963277670958448,
                0.0457219846190452,
                0.08475889533425279,
                0.11752509828593088,
            ],
            false,
            1.015575512939957,
            2,
        ),
        // true-centroid weight: G_x = ρ (sin β_L − sin β_R)/Δ with ρ = 1 + η²/12
        (
            &[
                -0.47433409434347573,
                -0.22221367223207272,
                -0.11925108268694451,
                0.07412090254192016,
                0.3573448006245217,
                0.5705955650263492,
            ],
            true,
            0.6665413511381322,
            1,
        ),
    ];
    for (joints, centroid, mu, count) in cases {
        let (br, bl) = (joints[0], joints[joints.len() - 1]);
        assert_eq!(
            compare(br, bl, joints, centroid, mu),
            Ok(count),
            "{joints:?}"
        );
        let weight = if centroid {
            WeightModel::Centroid
        } else {
            WeightModel::Centreline
        };
        let arch = Arch::new(br, bl, weight)
            .unwrap()
            .with_joints(joints)
            .unwrap();
        let r = search(&arch, mu, &Settings::default()).unwrap().unwrap();
        let s = r.above.last().unwrap();
        let span = bl - br;
        let chord = (bl.sin() - br.sin()) / span;
        // (1 + η/2) cos β_R = ρ(η) · chord, solved for η (a quadratic for the centroid)
        let exact = if centroid {
            let (a, b, c) = (chord / 12.0, -0.5 * br.cos(), chord - br.cos());
            (-b - (b * b - 4.0 * a * c).sqrt()) / (2.0 * a)
        } else {
            2.0 * (chord / br.cos() - 1.0)
        };
        assert!((s.t - exact).abs() <= 1e-12 * exact, "{} vs {exact}", s.t);
        assert!(s.x[0].abs() <= 1e-12 * span && (s.x[1] - span).abs() <= 1e-12 * span);
        assert!(s.mechanism.power.abs() <= 1e-12 && s.mechanism.dissipation.abs() <= 1e-12);
    }
}

/// A two-voussoir arch at μ = ∞ (issue 10): at η = 0 the hinge conditions |M| ≤ ηN/2
/// reduce to M = 0, which one state meets at all three joints of any two-voussoir arch —
/// here in tension (N < 0 at a joint), so it stands at no small η. Without friction rows
/// nothing enforced N ≥ 0 there, and the arch was reported to stand at every η > 0
/// (`no_collapse`); the brute force finds η_s ≈ 0.1467 with an overturning limit state
/// (the left springing detached). The check at vanishing thickness now requires N ≥ 0.
#[test]
fn two_voussoirs_at_infinite_friction_need_no_tension() {
    let j = [-0.4440108037418231, 0.2601892230910603, 0.9178524646018502];
    assert_eq!(compare(j[0], j[2], &j, false, f64::INFINITY), Ok(0));
    let arch = Arch::new(j[0], j[2], WeightModel::Centreline)
        .unwrap()
        .with_joints(&j)
        .unwrap();
    let r = search(&arch, f64::INFINITY, &Settings::default())
        .unwrap()
        .unwrap();
    assert!(r.attained && r.mechanism_at_eta_s);
    assert!((r.eta_s - 0.146707847974).abs() < 1e-11, "{}", r.eta_s);
}

/// Issue 10: a discrete arch that stands at every η > 0 (`no_collapse`: a state without
/// tension is admissible at vanishing thickness) can still have a limit state above, where
/// four contacts meet with a sliding mechanism — here two voussoirs, two hinges and two
/// slides at η ≈ 1.542 (found by the brute force on random two-voussoir arches, about one
/// in 250 of those that stand at every η). The search sweeps such arches from η = 0 and
/// reports η_s = 0, no limit state at η_s, and every limit state above. The issue's own
/// arch has none (the brute force agrees): `no_collapse` was right there.
#[test]
fn stands_at_every_eta_with_a_limit_state_above() {
    let j = [
        -1.0088581668631282,
        -0.003043959170128341,
        3.0728660500786775,
    ];
    let mu = 0.9387641729551759;
    assert_eq!(compare(j[0], j[2], &j, false, mu), Ok(1));
    let arch = Arch::new(j[0], j[2], WeightModel::Centreline)
        .unwrap()
        .with_joints(&j)
        .unwrap();
    let r = search(&arch, mu, &Settings::default()).unwrap().unwrap();
    assert_eq!(r.eta_s, 0.0);
    assert!(!r.mechanism_at_eta_s);
    assert_eq!(r.above.len(), 1);
    assert!(
        (r.above[0].t - 1.542014859695).abs() < 1e-11,
        "{}",
        r.above[0].t
    );
    assert!(r.above[0].mechanism.dissipation > 0.0);
    // the arch: two equal voussoirs, standing at every η > 0, no limit state
    let (br, bl) = (0.1590279471705356, 2.295640677370236);
    let j = [br, 0.5 * (br + bl), bl];
    assert_eq!(compare(br, bl, &j, false, 0.7823739813428994), Ok(0));
    let arch = Arch::new(br, bl, WeightModel::Centreline)
        .unwrap()
        .with_blocks(2)
        .unwrap();
    let r = search(&arch, 0.7823739813428994, &Settings::default())
        .unwrap()
        .unwrap();
    assert!(r.eta_s == 0.0 && r.above.is_empty());
}

/// Issue 10: where η_s is an infimum (approached only as the reactions grow without
/// bound), it is the least η with a weightless admissible direction — for a steep segment
/// of span Δ with a joint at its middle, the straight line through the extrados points of
/// the springings touching the intrados at the middle joint:
/// (1 + η/2) cos(Δ/2) = 1 − η/2, i.e. η = 2 tan²(Δ/4), the continuous arch's value too.
/// The Newton state of `solve` only approximated it (to ~1e-12, its equations holding
/// relative to reactions of 1e9); η_s is now the root of the direction's three contacts,
/// exact to rounding. Not attained, so no limit state at η_s.
#[test]
fn discrete_infimum_is_exact() {
    for blocks in [2usize, 4, 6] {
        for span in [0.3, 0.8, 1.2, 2.0] {
            let br = -0.2 - span / 2.0;
            let arch = Arch::new(br, br + span, WeightModel::Centreline)
                .unwrap()
                .with_blocks(blocks)
                .unwrap();
            let exact = 2.0 * (span / 4.0f64).tan().powi(2);
            // μ = ∞, and a friction the straight line of thrust needs (its angle with the
            // joint normals is at most Δ/2) with room to spare
            for mu in [f64::INFINITY, 1.0 + (span / 2.0f64).tan()] {
                let r = search(&arch, mu, &Settings::default()).unwrap().unwrap();
                assert!(!r.attained && !r.mechanism_at_eta_s, "{blocks} {span} {mu}");
                assert!(
                    (r.eta_s - exact).abs() <= 4.0 * f64::EPSILON * exact,
                    "{blocks} voussoirs, span {span}, mu {mu}: {} vs {exact}",
                    r.eta_s
                );
            }
        }
    }
}

/// Issue 10 (wild random arch, case 73 of the 300): η_s an infimum. Bracketing η_s, the
/// margin LP at η ≈ η_s (1 + 4e-10), where the best states are ~1e11, failed in HiGHS
/// ("Unbounded", with the reactions boxed or not), and `solve` gave up: no least state, no
/// search. A weightless admissible direction with room (the recession cone's margin, a
/// well-scaled LP) now shows that P(η) is not empty there, with an explicit far state.
#[test]
fn infimum_bracket_survives_lp_failure() {
    let joints = [
        -0.8672693602209524,
        -0.8103573333201234,
        -0.7501073716082238,
        -0.6822258064690885,
        -0.5515312936453811,
        -0.4626748946390806,
        -0.34139218787629644,
    ];
    assert_eq!(
        compare(joints[0], joints[6], &joints, false, 0.3254103135334804),
        Ok(1)
    );
    // a two-voussoir arch where the same happened (random 2- and 3-voussoir arches)
    let joints = [
        -0.6945466631754706,
        -0.3942441977385743,
        -0.24431511437101922,
    ];
    assert_eq!(
        compare(joints[0], joints[2], &joints, false, 0.47611544543675866),
        Ok(1)
    );
}

/// Issue 10: where η_s is an infimum the least state has reactions ~1e9, outside the
/// sweep's box (|x_k| ≤ 1e7). The sweep used to start there (its vertex paths outside the
/// box, the box's vertices never followed) or, finding no vertex, gave up ("no vertex of
/// the admissible set found just above eta_s"). It now starts at the least η at which P(η)
/// meets the box, from the point where it does; there the three contacts of the weightless
/// direction form a vertex with a determinant of ~1e-12 (relative), no longer taken for a
/// dependent triple (case 128: both sliding limit states above were missed that way).
#[test]
fn infimum_sweep_starts_inside_the_box() {
    let joints = [
        -0.17809391187591528,
        -0.08467456974260745,
        0.014412117707159111,
        0.17586341813073253,
    ];
    assert_eq!(
        compare(joints[0], joints[3], &joints, false, 0.5288872447493357),
        Ok(2)
    );
    let joints = [-1.106921546502596, -0.8982894601080077, -0.7865727551852193];
    assert_eq!(
        compare(joints[0], joints[2], &joints, false, 0.2870169351378892),
        Ok(1)
    );
    // a least state taken as bounded (the threshold raised to 1e12) but outside the box
    // (reactions ~1e9): the sweep starts inside the box all the same (from the state
    // itself it found no vertex and gave up)
    let arch = Arch::new(joints[0], joints[2], WeightModel::Centreline)
        .unwrap()
        .with_joints(&joints)
        .unwrap();
    let raised = Settings {
        unbounded_reactions: 1e12,
        ..Settings::default()
    };
    let etas = |s: &Settings| -> Vec<f64> {
        let r = search(&arch, 0.2870169351378892, s).unwrap().unwrap();
        r.above.iter().map(|a| a.t).collect()
    };
    assert_eq!(etas(&raised), etas(&Settings::default()));
    let joints = [-0.965545198893314, -0.7856270637541098, -0.6415860867560821];
    assert_eq!(
        compare(joints[0], joints[2], &joints, true, 0.8586901158065834),
        Ok(1)
    );
}

/// The complete search of a discrete arch is bounded (`settings.sweep_max_joints`): beyond
/// it `solve` still answers η_s exactly and fast, says the search was not done and leaves
/// uniqueness undecided (it used to run for minutes at 1000 voussoirs); `load` at finite
/// friction says it could not decide and gives the exact λ_static; at μ = ∞ `load`
/// needs no search (associative) and answers.
#[test]
fn search_budget_is_said_not_hidden() {
    // the ridge walk (centreline weight) goes in chunks with the joints proved near each,
    // about linear in n: 1000 and 3000 voussoirs (the latter beyond the budget of 2048
    // joints it had when it scanned every row on every piece) are searched completely
    for blocks in ["1000", "3000"] {
        let (v, code) =
            crate::cli::json_of(&["solve", "--alpha", "0", "--blocks", blocks, "--mu", "0.5"]);
        assert_eq!(code, 0);
        assert_eq!(v["search"]["complete"], true, "{blocks}");
        assert_eq!(v["search"]["method"], "ridge");
        assert_eq!(v["unique"], true);
    }
    // the true centroid needs the sweep, which has one
    let (v, code) = crate::cli::json_of(&[
        "solve", "--alpha", "0", "--blocks", "1000", "--mu", "0.5", "--weight", "centroid",
    ]);
    assert_eq!(code, 0);
    assert_eq!(v["status"], "ok");
    assert!(v["eta"].as_f64().unwrap() > 0.1);
    assert_eq!(v["unique"], serde_json::Value::Null);
    assert_eq!(v["search"]["complete"], false);
    assert!(v["search"]["reason"]
        .as_str()
        .unwrap()
        .contains("sweep_max_joints"));
    // beyond the load sweep's budget (512 joints) the face search: 1000 voussoirs decided
    // `load` of the semicircle at η = 0.3: voussoirs, μ and the load's arguments
    let semicircle = |blocks: &str, mu: &str, load: &[&str]| {
        let mut args = vec!["load", "--alpha", "0", "--blocks", blocks, "--eta", "0.3"];
        args.extend(["--mu", mu]);
        args.extend(load);
        crate::cli::json_of(&args)
    };
    let horizontal = |blocks: &str| semicircle(blocks, "0.8", &["--horizontal"]);
    let (v, code) = horizontal("1000");
    assert_eq!(code, 0, "{v}");
    assert_eq!(v["search"]["method"], "faces");
    assert!(v["unique"].is_boolean() && v["lambda"].is_f64(), "{v}");
    // at its budget, a point load (its LPs from neighbours' optima: a nearly singular
    // basis there once gave a vertex at lambda = -1e13 and no answer)
    let point = |blocks: &str| semicircle(blocks, "0.6", &["--point-load-deg", "40"]);
    let (v, code) = point("4095");
    assert_eq!(code, 0, "{}", v["message"]);
    assert_eq!(v["search"]["method"], "faces");
    assert_eq!(v["unique"], true);
    let (lambda, top) = (
        v["lambda"].as_f64().unwrap(),
        v["lambda_static"].as_f64().unwrap(),
    );
    assert!((lambda - top).abs() <= 1e-12 * top, "{lambda} vs {top}");
    // beyond its budget (4096 joints) not searched, and said so
    let (v, code) = horizontal("5000");
    assert_eq!(code, 1);
    assert_eq!(v["status"], "unresolved");
    let message = v["message"].as_str().unwrap();
    assert!(message.contains("load_face_max_joints"), "{message}");
    assert!(
        message.contains("lambda_static of these 5001 joints = "),
        "{message}"
    );
    // decided without the search: the static maximum and the states there (the face's
    // state has λ_static to rounding)
    let top = v["lambda_static"].as_f64().unwrap();
    let at_most = v["lambda_at_most"].as_f64().unwrap();
    assert!((at_most - top).abs() <= 1e-14 * top, "{at_most} vs {top}");
    assert_eq!(v["limit_states"][0]["lambda"].as_f64(), Some(at_most));
    assert!(v["lambda"].is_null() && v["mechanism_at_static"] == true);
    // a state at λ_static is no reduction, whatever its rounding
    assert!(v["reduction_at_least"].is_null(), "{v}");
    let (v, code) = crate::cli::json_of(&[
        "load",
        "--alpha",
        "0",
        "--blocks",
        "1000",
        "--eta",
        "0.3",
        "--mu",
        "inf",
        "--horizontal",
    ]);
    assert_eq!(code, 0);
    assert_eq!(v["unique"], true);
    // the load's sweep in λ has its own budget, twice the joints (its vertices move along
    // lines): 400 voussoirs under a point load are searched to the end
    let (v, code) = point("400");
    assert_eq!(code, 0, "{v}");
    assert_eq!(v["search"]["method"], "sweep");
    assert!(v["unique"].is_boolean() && v["lambda"].is_f64(), "{v}");
}

/// A search that reaches no decision says which step stopped it, typed: the sweep over more
/// joints than its budget is `Undecided::Budget` (for thickness and load alike), its text
/// naming the setting (the sweep in η `sweep_max_joints`; for a load, beyond the sweep's
/// `load_sweep_max_joints` the face search, and beyond its `load_face_max_joints` nothing);
/// a smaller budget on the same arch is the same failure, and each budget bounds its own
/// search only.
#[test]
fn undecided_search_names_its_step() {
    use arch_enum::multiplier::{survey as load_survey, LoadOutcome};
    use arch_enum::undecided::Undecided;
    let arch = Arch::symmetric(0.0, WeightModel::Centroid)
        .unwrap()
        .with_blocks(40)
        .unwrap();
    let settings = Settings {
        sweep_max_joints: 20,
        ..Settings::default()
    };
    match search(&arch, 0.5, &settings).unwrap() {
        Err(Undecided::Budget(t)) => assert!(t.contains("sweep_max_joints"), "{t}"),
        other => panic!("expected a budget failure, got {other:?}"),
    }
    let load = arch_enum::load::LiveLoad::Horizontal {
        towards_right: true,
    };
    // the thickness sweep's budget does not bound the load's sweep
    assert!(matches!(
        load_survey(&arch, 0.3, 0.8, &load, &settings).unwrap(),
        Ok(LoadOutcome::Limits(_))
    ));
    // beyond the load sweep's budget the face search decides, with the sweep's answer
    // (`load_seam::the_face_search_finds_what_the_sweep_finds`); beyond its own budget
    // nothing does, and the text names that budget
    let faces = Settings {
        load_sweep_max_joints: 20,
        ..Settings::default()
    };
    match load_survey(&arch, 0.3, 0.8, &load, &faces).unwrap() {
        Ok(LoadOutcome::Limits(s)) => assert_eq!(s.method, "faces"),
        other => panic!("expected the face search's answer, got {other:?}"),
    }
    let settings = Settings {
        load_sweep_max_joints: 20,
        load_face_max_joints: 30,
        ..Settings::default()
    };
    match load_survey(&arch, 0.3, 0.8, &load, &settings).unwrap() {
        Err(Undecided::Budget(t)) => {
            assert!(t.contains("settings.load_face_max_joints = 30"), "{t}")
        }
        Err(other) => panic!("expected a budget failure, got {other:?}"),
        Ok(o) => panic!(
            "expected a budget failure, got an answer ({})",
            matches!(o, LoadOutcome::Limits(_))
        ),
    }
    // nor the load's budget the thickness sweep; with the default budgets the same arch
    // is searched to the end
    assert!(search(&arch, 0.5, &settings).unwrap().is_ok());
    assert!(search(&arch, 0.5, &Settings::default()).unwrap().is_ok());
}

/// `solve --json`'s `eta` is η_s even when the search above it is incomplete: here the
/// least admissible state carries no mechanism and, searched at μ only (`carry_shift` =
/// `carry_almost_rate` = 0), the discretisations of 48 to 384 pieces do not settle (a limit
/// state at η = 0.6233 found by 48 and 192 pieces, missed by 96 and 384); the JSON's `eta`
/// and `checks.eta_static` both give η_s = 0.449815368139. It used to print the η of the
/// state found above as `eta`. (With the default `carry_shift` the search settles there.)
#[test]
fn json_eta_is_eta_static_when_the_search_is_incomplete() {
    let arch = Arch::new(
        -0.6847873579095128,
        3.428723873012637,
        WeightModel::Centreline,
    )
    .unwrap();
    let at_mu = Settings {
        carry_shift: 0.0,
        carry_almost_rate: 0.0,
        ..Settings::default()
    };
    let sv = arch_enum::limit_states::survey(&arch, 1.015, &at_mu).unwrap();
    let doc = arch_enum::render::json::solve(&sv, false, &sv.rays(&at_mu));
    let v = serde_json::to_value(&doc).unwrap();
    assert_eq!(v["search"]["complete"], false);
    let eta = v["eta"].as_f64().unwrap();
    assert!((eta - 0.449815368139).abs() < 1e-12, "{eta}");
    assert_eq!(v["checks"]["eta_static"].as_f64().unwrap(), eta);
    assert_eq!(v["mechanism_at_eta"], false);
}

/// Arches with fill (bridge spec §2): the limit-state search (the sweep, on the rows times
/// η) against the brute force with the fill written again (Simpson quadrature of the
/// spec's pressure), on random small discrete arches, both weight models, finite and
/// infinite friction: the same η_s, the same mechanism at η_s, the same limit states
/// above it. `FILL_SWEEP_CASES=N` runs more.
#[test]
fn filled_arches_match_brute_force() {
    let mut rng = Rng(0xf111_5ee9_0000_0023);
    let count = crate::cases_from_env("FILL_SWEEP_CASES", 16);
    let mut failures = Vec::new();
    let (mut nonunique, mut compared, mut declined) = (0, 0, 0);
    for case in 0..count {
        let n = 3 + (rng.next() * 4.0) as usize;
        let br = -0.5 + 1.0 * rng.next();
        // a third of the arches with springings anywhere (shallow, steep, unsymmetric)
        let bl = if case % 3 == 2 {
            br + 0.3 + 4.0 * rng.next()
        } else {
            PI - 0.5 + 1.0 * rng.next()
        };
        let joints = random_joints(&mut rng, br, bl, n);
        let centroid = rng.next() < 0.3;
        let fill = (0.1 + 1.2 * rng.next(), 0.01 + 0.3 * rng.next());
        let u = rng.next();
        let mu = if u < 0.2 {
            f64::INFINITY
        } else {
            0.15 + 1.5 * u * u
        };
        let reference = brute_force_filled(&joints, centroid, mu, fill);
        if !reference.eta_s.is_finite() {
            continue;
        }
        if !reference.attained {
            // an infimum: the crate declines the search (and must say so)
            declined += 1;
            let arch = Arch::new(br, bl, WeightModel::Centreline)
                .unwrap()
                .with_joints(&joints)
                .unwrap()
                .with_fill(arch_enum::fill::Fill::new(fill.0, fill.1).unwrap());
            let found = search(&arch, mu, &Settings::default()).unwrap();
            if !found.as_ref().is_err_and(|e| e.text().contains("infimum")) {
                failures.push(format!(
                    "case {case}: an infimum with fill searched: {found:?}"
                ));
            }
            continue;
        }
        compared += 1;
        match compare_with(&reference, &joints, centroid, mu, Some(fill)) {
            Ok(k) => nonunique += usize::from(k > 0),
            Err(e) => failures.push(format!(
                "case {case}: joints {joints:?} centroid {centroid} mu {mu:?} fill {fill:?}: {e} (reference LP bisection {})",
                reference.eta_s_lp
            )),
        }
    }
    println!(
        "{compared} arches with fill compared ({nonunique} with limit states above eta_s), {declined} infima declined, {} disagreements",
        failures.len()
    );
    assert!(failures.is_empty(), "{}", failures.join("\n"));
    assert!(compared > count / 2);
}

/// With the true centroid a point of P(η) can leave P at a larger η (the band of w at a
/// fixed (h, v) is not monotone in η: a pair's width gains (η²/12)(s_k − s_j), which shrinks
/// it where N is small): why the ridge, whose height is the least η closing the band, is
/// walked for the centreline weight only (docs/design/limit-states-on-boundary.md). The
/// centreline's band only widens where N ≥ 0.
#[test]
fn true_centroid_band_is_not_monotone_in_eta() {
    use arch_enum::statics::actions;
    use arch_enum::{ContactKind, JointLayout};
    let x = [
        0.272_886_908_730_373_1,
        2.131_802_739_906_716_8,
        -0.371_131_027_404_948_1,
    ];
    let mu = 0.988_686_369_496_438_5;
    let worst = |weight, eta: f64| {
        let arch = Arch::new(-0.325_326_482_653_878_4, 2.539_928_795_571_390_7, weight)
            .unwrap()
            .with_blocks(3)
            .unwrap();
        let JointLayout::Discrete(joints) = arch.layout() else {
            unreachable!("voussoirs")
        };
        joints
            .iter()
            .flat_map(|&b| {
                let a = actions(&arch, eta, b);
                ContactKind::ALL.map(|k| a.activation(k, 0, eta, mu).at(&x))
            })
            .fold(f64::NEG_INFINITY, f64::max)
    };
    let (thin, thick) = (0.966_554_911_120_090_7, 1.2);
    // admissible at the thinner ring (an intrados row active to rounding) ...
    assert!(worst(WeightModel::Centroid, thin) <= 1e-12);
    // ... not at the thicker one
    assert!(worst(WeightModel::Centroid, thick) > 0.02);
    // with the centreline weight the worst row at this x only falls as η grows (N > 0 at
    // every joint here, and each hinge row is M ∓ η N / 2)
    let mut last = worst(WeightModel::Centreline, thin);
    for k in 1..=20 {
        let eta = thin + (2.0 - thin) * f64::from(k) / 20.0;
        let now = worst(WeightModel::Centreline, eta);
        assert!(now <= last, "{eta}: {now} > {last}");
        last = now;
    }
}
