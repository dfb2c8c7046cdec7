//! The η–μ limit curve (`modes`): published corners to their printed digits, the hard
//! openings' branches, and digit-stable snapshots of `modes --json` so that any change
//! of a mode transition shows up as a snapshot diff.

use crate::cli::{json_of, round};
use arch_enum::assess::safest_state;
use arch_enum::limit_curve::{trace, LimitCurve};
use arch_enum::{
    solve, Arch, CollapseMode, ContactKind, LeastLimitState, Location, Outcome, Settings,
    WeightModel,
};
use std::f64::consts::PI;

fn curve(alpha: f64) -> LimitCurve {
    trace(
        &Arch::symmetric(alpha, WeightModel::Centreline).unwrap(),
        &Settings::default(),
    )
}

/// The limit state at η*(μ) of the symmetric arch of opening `alpha`, solved on its own
/// (not taken from the traced curve).
fn limit_at(alpha: f64, mu: f64) -> LeastLimitState {
    let arch = Arch::symmetric(alpha, WeightModel::Centreline).unwrap();
    match solve(&arch, mu, &Settings::default()).unwrap().outcome {
        Outcome::Limit(ls) => ls,
        o => panic!("alpha = {alpha}, mu = {mu}: no limit state: {o:?}"),
    }
}

/// Whether the symmetric arch of opening `alpha` has a statically admissible state at
/// (η, μ): the LP of the safest state, not the solver of η*.
fn stands(alpha: f64, eta: f64, mu: f64) -> bool {
    let arch = Arch::symmetric(alpha, WeightModel::Centreline).unwrap();
    safest_state(&arch, eta, mu, &Settings::default()).is_some()
}

/// Asserts |value − printed| ≤ half a unit of the last of `digits` significant digits.
fn assert_digits(what: &str, value: f64, printed: f64, digits: i32) {
    let ulp = 10f64.powi(printed.abs().log10().floor() as i32 - digits + 1);
    assert!(
        (value - printed).abs() <= 0.5 * ulp,
        "{what}: computed {value:.12}, published {printed}"
    );
}

fn right_interior(c: &arch_enum::limit_curve::Corner, slide: bool) -> f64 {
    c.pattern
        .iter()
        .find(|j| {
            j.at == Location::Interior
                && j.beta < PI / 2.0 - 1e-9
                && j.kind.is_hinge() != slide
                && (slide || j.kind == ContactKind::HingeIntrados)
        })
        .unwrap_or_else(|| panic!("no joint in {:?}", c.pattern))
        .beta
}

/// Published corners (shared/spec/reference-values.md), 8 significant digits.
#[test]
fn published_corners() {
    for (alpha, eta_rm, bn_rm, mu_rm, mu_ms, eta_ms, bn_ms, bt_ms) in [
        (
            0.0, 0.10742645, 0.61965572, 0.39583204, 0.30921544, 0.20063732, 0.51463788, 1.0710004,
        ),
        (
            PI / 6.0,
            0.32654664,
            0.45365963,
            0.82361489,
            0.73904014,
            0.45943411,
            0.44355547,
            1.1453296,
        ),
    ] {
        let c = curve(alpha);
        assert_eq!(c.corners.len(), 2, "alpha = {alpha}: {:?}", c.corners);
        let (rm, ms) = (&c.corners[0], &c.corners[1]);
        assert!(rm.exact && ms.exact);
        assert_digits("mu_rm", rm.mu, mu_rm, 8);
        assert_digits("eta_rm", rm.t, eta_rm, 8);
        assert_digits("beta_N at mu_rm", right_interior(rm, false), bn_rm, 8);
        assert_digits("mu_ms", ms.mu, mu_ms, 8);
        assert_digits("mu_min", c.mu_ms.unwrap(), mu_ms, 8);
        assert_digits("eta_ms", ms.t, eta_ms, 8);
        assert_digits("beta_N at mu_ms", right_interior(ms, false), bn_ms, 8);
        assert_digits("beta_T at mu_ms", right_interior(ms, true), bt_ms, 8);
        let modes: Vec<CollapseMode> = c.branches.iter().map(|b| b.mode).collect();
        assert_eq!(
            modes,
            [
                CollapseMode::PurelyRotational,
                CollapseMode::MixedSlidingRotational,
                CollapseMode::PurelySliding
            ]
        );
        // The rotational branch reaches infinite friction (its mu_max is ∞): above mu_rm
        // η_s no longer depends on μ and the pattern stays rotational.
        for mu in [1.5 * rm.mu, 1e3 * rm.mu] {
            let ls = limit_at(alpha, mu);
            assert_eq!(
                ls.mode,
                CollapseMode::PurelyRotational,
                "alpha = {alpha}, mu = {mu}"
            );
            assert!(
                (ls.eta - rm.t).abs() <= 1e-12 * rm.t,
                "alpha = {alpha}: eta_s({mu}) = {} differs from eta_rm = {}",
                ls.eta,
                rm.t
            );
        }
        // The purely sliding branch is vertical at mu_ms (its mu_min equals its mu_max):
        // just below mu_ms not even a thick arch stands; just above, η a little above η_ms
        // stands and a little below does not.
        let (below, above) = (ms.mu * (1.0 - 1e-6), ms.mu * (1.0 + 1e-6));
        assert!(
            !stands(alpha, 1.5, below),
            "alpha = {alpha}: eta = 1.5 stands below mu_ms"
        );
        assert!(
            stands(alpha, 1.5, above),
            "alpha = {alpha}: eta = 1.5 falls above mu_ms"
        );
        assert!(
            stands(alpha, ms.t * (1.0 + 1e-3), above),
            "alpha = {alpha}: 1.001 eta_ms falls just above mu_ms"
        );
        assert!(
            !stands(alpha, ms.t * (1.0 - 1e-3), above),
            "alpha = {alpha}: 0.999 eta_ms stands just above mu_ms"
        );
    }
}

/// alpha = 1: a mixed rotational-sliding branch (rotation at the shoulders, sliding near
/// the crown) between the rotational and the sliding branches; the sliding joint is
/// already active at mu_rm.
#[test]
fn alpha_one_mixed_rotational_sliding() {
    let c = curve(1.0);
    let modes: Vec<CollapseMode> = c.branches.iter().map(|b| b.mode).collect();
    assert_eq!(
        modes,
        [
            CollapseMode::PurelyRotational,
            CollapseMode::MixedRotationalSliding,
            CollapseMode::PurelySliding
        ]
    );
    let rm = &c.corners[0];
    assert!(rm.exact);
    let bt = right_interior(rm, true);
    let bn = right_interior(rm, false);
    assert!(
        bn < bt && bt < PI / 2.0,
        "beta_T {bt} between the haunch {bn} and the crown"
    );
}

/// alpha = 1.15: no horizontal branch; the mixed branch approaches the overturning
/// limit (N = 0 at the crown) as mu -> inf, and at the corner with the purely sliding
/// branch the shoulders rotate and slide at once.
#[test]
fn alpha_1_15_overturning_asymptote() {
    let c = curve(1.15);
    assert!(c
        .branches
        .iter()
        .all(|b| b.mode != CollapseMode::PurelyRotational));
    // the asymptote is not a kink: it is listed with the transitions
    let top = &c.transitions[0];
    assert!(top.mu.is_infinite() && !top.detail.kink);
    assert!(c.corners.iter().all(|k| k.mu.is_finite() && k.detail.kink));
    assert_eq!(top.between()[1], CollapseMode::Overturning);
    // The mixed branch reaches infinite friction (its mu_max is ∞) and approaches the
    // overturning limit η(∞) from above: η_s(μ) − η(∞) is positive and falls at least ten
    // times per decade of μ (it goes as 1/μ²: 8.3e-3, 8.3e-5, 8.3e-7), in the branch's
    // mode (not the overturning one). Beyond μ = 10³ the gap nears the rounding of η.
    let mut gap = f64::INFINITY;
    for mu in [1e1, 1e2, 1e3] {
        let ls = limit_at(1.15, mu);
        let g = ls.eta - top.t;
        assert_eq!(ls.mode, c.branches[0].mode, "mu = {mu}");
        assert!(
            g > 0.0 && g < 0.1 * gap,
            "mu = {mu}: eta_s - eta(inf) = {g:e} after {gap:e} at mu / 10"
        );
        gap = g;
    }
    assert!(gap < 1e-5 * top.t, "eta_s(1e3) - eta(inf) = {gap:e}");
    let last = c.corners.last().unwrap();
    assert!(last.exact);
    assert_eq!(last.detail.mode, CollapseMode::RotationalSlidingShoulders);
    assert_eq!(last.between()[1], CollapseMode::PurelySliding);
}

/// The branches of the five openings of the founding paper's Table 1 carry the paper's
/// names: sliding at the shoulders with rotation at the crown below α = 1 ("mixed
/// sliding–rotational"), rotation at the shoulders with sliding near the crown at α = 1,
/// and at α = 1.15 (whose upper branch the paper's Fig. 21 calls "mixed
/// rotational–sliding", although a crown hinge lies inside its sliding joints).
#[test]
fn branch_names_are_the_papers() {
    use CollapseMode::*;
    let expected: [(f64, &[CollapseMode]); 5] = [
        (
            -PI / 6.0,
            &[PurelyRotational, MixedSlidingRotational, PurelySliding],
        ),
        (
            0.0,
            &[PurelyRotational, MixedSlidingRotational, PurelySliding],
        ),
        (
            PI / 6.0,
            &[PurelyRotational, MixedSlidingRotational, PurelySliding],
        ),
        (
            1.0,
            &[PurelyRotational, MixedRotationalSliding, PurelySliding],
        ),
        (1.15, &[MixedRotationalSliding, PurelySliding]),
    ];
    for (alpha, modes) in expected {
        let c = curve(alpha);
        let got: Vec<CollapseMode> = c.branches.iter().map(|b| b.mode).collect();
        assert_eq!(got, modes, "alpha = {alpha}");
    }
    // the 1.15 branch: hinges at the springings and at the crown, sliding just beside it
    let ls = limit_at(1.15, 5.0);
    let slides: Vec<f64> = ls
        .pattern
        .iter()
        .filter(|c| !c.kind.is_hinge())
        .map(|c| (c.beta - PI / 2.0).abs())
        .collect();
    assert!(
        slides.len() == 2 && slides.iter().all(|d| *d < 0.2),
        "{slides:?}"
    );
    assert!(ls
        .pattern
        .iter()
        .any(|c| c.kind.is_hinge() && (c.beta - PI / 2.0).abs() < 1e-9));
}

fn snapshot(name: &str, args: &[&str]) {
    let mut a = vec!["modes"];
    a.extend_from_slice(args);
    let (v, code) = json_of(&a);
    assert_eq!(code, 0);
    let mut snap = round(&v);
    for c in snap["corners"].as_array_mut().unwrap() {
        c["residual"] = serde_json::Value::Null;
    }
    insta::with_settings!({ snapshot_path => "../../snapshots", prepend_module_to_snapshot => false }, {
        insta::assert_json_snapshot!(name, snap);
    });
}

#[test]
fn snapshots_of_modes() {
    for (name, alpha) in [
        ("modes_alpha_-1.2", "-1.2"),
        ("modes_alpha_-pi_6", "-0.5235987755982988"),
        ("modes_alpha_-0.3", "-0.3"),
        ("modes_alpha_0", "0"),
        ("modes_alpha_pi_6", "0.5235987755982988"),
        ("modes_alpha_0.8", "0.8"),
        ("modes_alpha_1.0", "1.0"),
        ("modes_alpha_1.1", "1.1"),
        ("modes_alpha_1.15", "1.15"),
    ] {
        snapshot(name, &["--alpha", alpha]);
    }
    snapshot(
        "modes_unsymmetric",
        &["--beta-right", "-0.3", "--beta-left", "3.2415926535897933"],
    );
    snapshot(
        "modes_discrete_20_blocks",
        &["--alpha", "0", "--blocks", "20"],
    );
}

/// Twelve digits, by independent routes: the corner mu_rm equals the friction the
/// infinite-friction state needs (max |T|/N over the arch, found here with the test's
/// own formulas and a golden-section search), the corner eta_rm equals eta*(inf), and
/// the mu_ms corner (a union system in x, eta, mu) equals the friction-only limit (a
/// different system in h, v, mu).
#[test]
fn corners_agree_with_independent_routes_to_12_digits() {
    use crate::model::ntm;
    let s = Settings::default();
    for alpha in [-0.3, 0.0, PI / 6.0, 0.8] {
        let arch = Arch::symmetric(alpha, WeightModel::Centreline).unwrap();
        let c = trace(&arch, &s);
        let arch_enum::Outcome::Limit(inf) =
            arch_enum::solve(&arch, f64::INFINITY, &s).unwrap().outcome
        else {
            panic!()
        };
        let ratio = |b: f64| {
            let (n, t, _) = ntm(arch.beta_right(), 1.0, inf.x, b);
            t.abs() / n
        };
        // dense sampling, then golden-section refinement of the best interior sample,
        // and the springings themselves
        let (a, bl) = (arch.beta_right(), arch.beta_left());
        let m = 20000;
        let best = (0..=m)
            .map(|i| a + (bl - a) * i as f64 / m as f64)
            .max_by(|x, y| ratio(*x).total_cmp(&ratio(*y)))
            .unwrap();
        let (mut lo, mut hi) = (
            (best - (bl - a) / m as f64).max(a),
            (best + (bl - a) / m as f64).min(bl),
        );
        let g = (5f64.sqrt() - 1.0) / 2.0;
        for _ in 0..200 {
            let (x1, x2) = (hi - g * (hi - lo), lo + g * (hi - lo));
            if ratio(x1) < ratio(x2) {
                lo = x1;
            } else {
                hi = x2;
            }
        }
        let mu_rm = ratio(0.5 * (lo + hi)).max(ratio(a)).max(ratio(bl));
        let rm = &c.corners[0];
        assert!(
            (rm.mu - mu_rm).abs() <= 1e-12 * mu_rm,
            "alpha {alpha}: corner {} vs max|T|/N {mu_rm}",
            rm.mu
        );
        assert!(
            (rm.t - inf.eta).abs() <= 1e-12 * inf.eta,
            "alpha {alpha}: {} vs {}",
            rm.t,
            inf.eta
        );
        let f = arch_enum::friction_limit(&arch, &s).unwrap().unwrap();
        let ms = c.corners.last().unwrap();
        assert!(
            (ms.mu - f.mu).abs() <= 1e-12 * f.mu,
            "alpha {alpha}: {} vs {}",
            ms.mu,
            f.mu
        );
    }
}

/// An opening too large to stand at any thickness: no branch, exit 1, said plainly.
#[test]
fn opening_too_large_has_no_branch() {
    let (v, code) = json_of(&["modes", "--alpha", "1.3"]);
    assert_eq!(code, 1);
    assert!(v["branches"].as_array().unwrap().is_empty());
    assert_eq!(v["status"], "no_equilibrium");
    assert!(v["unresolved"].as_array().unwrap().is_empty());
    assert_eq!(v["no_equilibrium"].as_array().unwrap().len(), 1);
}

/// A single voussoir is statically determinate: it stands at every thickness, and `modes`
/// says so (as `solve` does), not "no thickness stands".
#[test]
fn one_voussoir_has_no_collapse() {
    let (v, code) = json_of(&["modes", "--alpha", "0", "--blocks", "1"]);
    assert_eq!(code, 1);
    assert_eq!(v["status"], "no_collapse");
    assert!(v["branches"].as_array().unwrap().is_empty());
    assert!(!v["no_collapse"].as_array().unwrap().is_empty());
    let (s, code) = json_of(&["solve", "--alpha", "0", "--blocks", "1", "--mu", "0.5"]);
    assert_eq!(code, 1);
    assert_eq!(s["status"], "no_collapse");
}

/// The crown curvature of the intrados activation function at the least state of a
/// symmetric centreline arch, from the test's own formulas (formulation §3: at β = π/2,
/// N = h, M'' = N − 1, N'' = 2 − N, so φ_I'' = −M'' − η N''/2 = 1 − h − η (1 − h/2)).
fn crown_curvature(alpha: f64, mu: f64) -> f64 {
    let arch = Arch::symmetric(alpha, WeightModel::Centreline).unwrap();
    let sol = arch_enum::limit::solve(&arch, mu, &Settings::default()).unwrap();
    let (eta, x) = match sol.outcome {
        arch_enum::limit::Outcome::Limit(ls) => (ls.eta_static, ls.x_static),
        other => panic!("{other:?}"),
    };
    1.0 - x[0] - eta * (1.0 - 0.5 * x[0])
}

/// α = 1.05 (issue 10): the two mixed branches meet smoothly — the two intrados hinges of
/// the upper branch cross the sliding joints, then reach the crown from both sides and go
/// on as one (φ_I'' = 0 there). No corner between them; the merge, located exactly, equal
/// to an independent
/// route (bisection in μ on the sign of φ_I''(π/2) at the least state) to 1e-11, and the
/// issue's 2.3351897612 to its 11 digits.
#[test]
fn alpha_1_05_smooth_transition_between_mixed_branches() {
    let c = curve(1.05);
    let mixed = |m: CollapseMode| {
        matches!(
            m,
            CollapseMode::MixedRotationalSliding | CollapseMode::MixedSlidingRotational
        )
    };
    assert!(
        c.corners
            .iter()
            .all(|k| !(mixed(k.between()[0]) && mixed(k.between()[1]))),
        "{:?}",
        c.corners
    );
    assert!(c.corners.iter().all(|k| k.detail.kink));
    // two smooth changes: the intrados hinges crossing the sliding joints (μ ≈ 2.4013),
    // then merging at the crown
    assert_eq!(c.transitions.len(), 2, "{:?}", c.transitions);
    assert!(c.transitions.iter().all(|t| t.exact && !t.detail.kink));
    let cross = &c.transitions[0];
    assert!(cross
        .pattern
        .iter()
        .any(|i| i.kind == ContactKind::HingeIntrados
            && cross
                .pattern
                .iter()
                .any(|s| s.kind == ContactKind::SlideMinus && (s.beta - i.beta).abs() < 1e-9)));
    let t = &c.transitions[1];
    assert!((t.sides[0].slope - t.sides[1].slope).abs() < 1e-6 * t.sides[0].slope.abs());
    // independent route
    let (mut lo, mut hi) = (2.30, 2.40);
    assert!(crown_curvature(1.05, lo) < 0.0 && crown_curvature(1.05, hi) > 0.0);
    for _ in 0..60 {
        let mid = 0.5 * (lo + hi);
        if crown_curvature(1.05, mid) < 0.0 {
            lo = mid;
        } else {
            hi = mid;
        }
    }
    assert!((t.mu - lo).abs() < 1e-11 * lo, "{} vs {lo}", t.mu);
    assert_digits("mu of the transition", t.mu, 2.3351897612, 11);
    // every corner's η is η_s at its μ
    for k in c.corners.iter().filter(|k| k.mu.is_finite()) {
        let arch = Arch::symmetric(1.05, WeightModel::Centreline).unwrap();
        let up = arch_enum::limit::solve(&arch, k.mu * (1.0 + 1e-9), &Settings::default()).unwrap();
        if let arch_enum::limit::Outcome::Limit(ls) = up.outcome {
            assert!(
                (ls.eta_static - k.t).abs() < 1e-7 * k.t,
                "{} vs {}",
                ls.eta_static,
                k.t
            );
        }
    }
}

/// α = 0.8 just above μ_ms: the limit-state diagram has a branch of limit states above the
/// static boundary (a mirror pair of unsymmetric sliding states), so this symmetric
/// continuous arch is not unique. Each state is re-checked here by the independent
/// reference of `search_reference` (its own statics and kinematics): admissible at 4 000
/// joints and at the contacts themselves, the contacts active, B λ = 0, λ ≥ 0, L_e ≥ 0 and
/// the virtual-work identity.
#[test]
fn symmetric_continuous_non_uniqueness_is_independently_checked() {
    use crate::search_reference::{check_state, RefLimitState};
    let alpha = 0.8;
    let arch = Arch::symmetric(alpha, WeightModel::Centreline).unwrap();
    let mu = 1.1540692474221415;
    let r = arch_enum::limit_states::search(&arch, mu, &Settings::default())
        .unwrap()
        .unwrap();
    assert_eq!(r.above.len(), 2);
    let (br, bl) = (-alpha, PI + alpha);
    for s in &r.above {
        assert!(s.t > r.eta_s * (1.0 + 1e-6), "{} vs {}", s.t, r.eta_s);
        let mut joints: Vec<f64> = (0..=4000)
            .map(|i| br + (bl - br) * i as f64 / 4000.0)
            .collect();
        joints.extend(s.mechanism.contacts.iter().map(|c| c.beta));
        joints.sort_by(f64::total_cmp);
        joints.dedup_by(|a, b| (*a - *b).abs() < 1e-12);
        let kind = |k: ContactKind| match k {
            ContactKind::HingeExtrados => 0u8,
            ContactKind::HingeIntrados => 1,
            ContactKind::SlidePlus => 2,
            ContactKind::SlideMinus => 3,
        };
        let mut active: Vec<((usize, u8), f64)> = s
            .mechanism
            .contacts
            .iter()
            .zip(&s.mechanism.rates)
            .map(|(c, &rate)| {
                let j = joints
                    .iter()
                    .position(|&b| (b - c.beta).abs() < 1e-12)
                    .unwrap();
                ((j, kind(c.kind)), rate)
            })
            .collect();
        active.sort_by_key(|a| a.0);
        let state = RefLimitState {
            eta: s.t,
            x: s.x,
            active: active.iter().map(|a| a.0).collect(),
            rates: active.iter().map(|a| a.1).collect(),
            slides: active.iter().any(|a| a.0 .1 >= 2 && a.1 > 1e-12),
            interval_end: None,
        };
        check_state(br, bl, &joints, false, mu, &state).unwrap();
        assert!(state.slides);
    }
}

/// An unsymmetric arch (found by a sweep of 60 random arches through `modes`) where, at one
/// sample, the least admissible state was refined inside the LP bracket but carried no
/// mechanism while another pattern gave a verified limit state above the bracket: that
/// sample used to be `unresolved` and the μ_ms corner bracketed only. Now η_s is that
/// least state (the non-associative gap), no sample is unresolved, every change is exact.
#[test]
fn gap_at_a_sample_is_decided() {
    let arch = Arch::new(
        -0.7311981743252693,
        3.259202420641531,
        WeightModel::Centreline,
    )
    .unwrap();
    let c = trace(&arch, &Settings::default());
    assert!(c.unresolved.is_empty(), "{:?}", c.unresolved);
    assert!(c.corners.iter().chain(&c.transitions).all(|k| k.exact));
    assert!(c.corners.iter().all(|k| k.detail.kink));
}

/// An unsymmetric arch with true-centroid weight (from the random `modes` sweep) whose
/// boundary reaches the thickness limit η → 2 at μ ≈ 2.063, above μ_ms = 1.9626: no
/// thickness η < 2 stands below it, so there is no purely-sliding corner (it would need
/// η_ms ≥ 2) — it used to be reported as a bracketed corner at μ_ms with the lowest
/// sample's η. Its top branch is a three-contact (curved, KKT) pattern, where a sliding
/// contact joins smoothly (zero multiplier at onset): located by root finding along the
/// branch, not by Newton on the union (not a determined system there).
#[test]
fn boundary_reaching_the_thickness_limit() {
    let arch = Arch::new(
        -1.0782022579731156,
        3.007207693287576,
        WeightModel::Centroid,
    )
    .unwrap();
    let s = Settings::default();
    let c = trace(&arch, &s);
    assert!(c.unresolved.is_empty(), "{:?}", c.unresolved);
    let t = c.thickness_limit.as_ref().expect("a thickness limit");
    assert!(t.eta > 2.0 * (1.0 - 1e-6));
    let mu_ms = c.mu_ms.unwrap();
    assert!(t.mu > mu_ms * 1.01, "{} vs {mu_ms}", t.mu);
    // just above: it stands (η_s < 2); just below: nothing stands
    let at = |mu: f64| arch_enum::limit::solve(&arch, mu, &s).unwrap().outcome;
    assert!(matches!(
        at(t.mu * (1.0 + 1e-9)),
        arch_enum::limit::Outcome::Limit(_)
            | arch_enum::limit::Outcome::Unresolved {
                least_static: Some(_),
                ..
            }
    ));
    assert!(matches!(
        at(t.mu * (1.0 - 1e-9)),
        arch_enum::limit::Outcome::NoEquilibrium { .. }
    ));
    assert!(c
        .branches
        .iter()
        .all(|b| b.mode != CollapseMode::PurelySliding));
    // the first change (the horizontal branch meeting the sliding one) is exact and smooth
    let first = c.transitions.iter().find(|k| k.mu.is_finite()).unwrap();
    assert!(first.exact);
    assert!((first.t - c.branches[0].eta_min).abs() < 1e-12);
}

/// An intrados hinge crossing a sliding joint (issue 10's "a hinge crossing a sliding
/// joint"), on an unsymmetric arch from the random `modes` sweep: above the change the
/// hinge lies on the right of the sliding joint, below it on the left; at the change both
/// sit at one joint. Located exactly (the two angles equal as the extra condition), η equal
/// to the solver's η_s there, and the order of the two contacts in the solver's own
/// patterns just above and below is reversed.
#[test]
fn hinge_crossing_a_sliding_joint() {
    let arch = Arch::new(
        -1.0478837979981601,
        3.0669448626338407,
        WeightModel::Centreline,
    )
    .unwrap();
    let s = Settings::default();
    let c = trace(&arch, &s);
    assert!(c.corners.iter().chain(&c.transitions).all(|k| k.exact));
    let t = c
        .transitions
        .iter()
        .find(|k| {
            let i = k
                .pattern
                .iter()
                .find(|j| j.kind == ContactKind::HingeIntrados);
            let sl = k.pattern.iter().find(|j| j.kind == ContactKind::SlideMinus);
            matches!((i, sl), (Some(i), Some(sl)) if (i.beta - sl.beta).abs() < 1e-9)
        })
        .expect("a transition where I and S- meet");
    // the solver's least admissible state and its active contacts (not the limit state
    // above it, which `ls.pattern` is when η_s carries no mechanism)
    let order = |mu: f64| {
        let sol = arch_enum::limit::solve(&arch, mu, &s).unwrap();
        let (eta, x) = match sol.outcome {
            arch_enum::limit::Outcome::Limit(ls) => (ls.eta_static, ls.x_static),
            arch_enum::limit::Outcome::Unresolved {
                least_static: Some(st),
                ..
            } => st,
            other => panic!("{other:?}"),
        };
        let st = arch_enum::state::State {
            arch: &arch,
            eta,
            mu,
            x,
        };
        let active = st.verdict(ContactKind::active_at(mu), &s).active;
        let b = |k: ContactKind| {
            active
                .iter()
                .filter(|j| j.kind == k && j.at == Location::Interior)
                .map(|j| j.beta)
                .fold(f64::INFINITY, f64::min)
        };
        (
            eta,
            b(ContactKind::HingeIntrados) < b(ContactKind::SlideMinus),
        )
    };
    let (above, below) = (order(t.mu * (1.0 + 1e-4)), order(t.mu * (1.0 - 1e-4)));
    assert_ne!(above.1, below.1, "the order must reverse");
    let (eta, _) = order(t.mu);
    assert!((eta - t.t).abs() < 1e-10 * eta, "{eta} vs {}", t.t);
}

/// Issue 10: for α ∈ [1.030, 1.076] the "corners" between the two mixed branches used to
/// be smooth pattern changes placed up to 4e-3 off. Across the range, every corner is a
/// kink at either end of the mixed branches (the Couplet–Heyman end and μ_ms), every
/// change between the mixed branches is a smooth transition, and all are exact.
#[test]
fn mixed_branches_meet_smoothly_across_alpha() {
    let mixed = |m: CollapseMode| {
        matches!(
            m,
            CollapseMode::MixedRotationalSliding | CollapseMode::MixedSlidingRotational
        )
    };
    for alpha in [1.03, 1.04, 1.06, 1.07] {
        let c = curve(alpha);
        assert!(c.unresolved.is_empty(), "{alpha}: {:?}", c.unresolved);
        assert!(!c.transitions.is_empty(), "{alpha}");
        for k in c.corners.iter().chain(&c.transitions) {
            assert!(k.exact, "{alpha}: {k:?}");
        }
        for k in &c.corners {
            assert!(
                k.detail.kink && !(mixed(k.between()[0]) && mixed(k.between()[1])),
                "{alpha}: {k:?}"
            );
        }
    }
}

/// The unresolved hard case of the first round (an unsymmetric arch whose four binding
/// contacts make a nearly singular system at η_s) is decided: η_s inside the old LP
/// bracket [0.660876184503, 0.660876184525], a limit state there, unique.
#[test]
fn nearly_singular_unsymmetric_case_is_decided() {
    let arch = Arch::new(-0.8826, 3.1084, WeightModel::Centreline).unwrap();
    let sv =
        arch_enum::limit_states::survey(&arch, 1.3310409406771477, &Settings::default()).unwrap();
    let arch_enum::limit::Outcome::Limit(ls) = &sv.solution.outcome else {
        panic!("{:?}", sv.solution.outcome)
    };
    assert!(
        (0.660876184503..=0.660876184525).contains(&ls.eta_static),
        "{}",
        ls.eta_static
    );
    assert_eq!(sv.unique(), Some(true));
}

/// A discrete arch: a hinge moving to the next joint is a pattern change (a kink of
/// η_s(μ), the least state jumps between vertices), not a continuation of the branch.
/// Twenty voussoirs of the semicircle: on the mixed branch the intrados hinges move from
/// the joints at 36° to those at 27°; the corner is exact, both hinges active there, and
/// the solver's own least states on either side have the hinge at one joint each.
#[test]
fn discrete_hinge_moving_to_the_next_joint_is_a_corner() {
    let arch = Arch::symmetric(0.0, WeightModel::Centreline)
        .unwrap()
        .with_blocks(20)
        .unwrap();
    let s = Settings::default();
    let c = trace(&arch, &s);
    let (j27, j36) = (27f64.to_radians(), 36f64.to_radians());
    let k = c
        .corners
        .iter()
        .find(|k| {
            let has = |b: f64| {
                k.pattern
                    .iter()
                    .any(|j| j.kind == ContactKind::HingeIntrados && (j.beta - b).abs() < 1e-9)
            };
            has(j27) && has(j36)
        })
        .expect("the corner where the hinge moves from 36 to 27 degrees");
    assert!(k.exact && k.detail.kink, "{k:?}");
    let hinge_at = |mu: f64| {
        let sol = arch_enum::limit::solve(&arch, mu, &s).unwrap();
        let arch_enum::limit::Outcome::Limit(ls) = sol.outcome else {
            panic!("{:?}", sol.outcome)
        };
        assert_eq!(ls.eta, ls.eta_static);
        ls.pattern
            .iter()
            .find(|j| j.kind == ContactKind::HingeIntrados)
            .unwrap()
            .beta
    };
    assert!((hinge_at(k.mu * (1.0 + 1e-6)) - j36).abs() < 1e-9);
    assert!((hinge_at(k.mu * (1.0 - 1e-6)) - j27).abs() < 1e-9);
}

/// Issue 10: symmetric openings from −1.4 to 1.2 (step 0.2) are all decided — no
/// unresolved sample, every corner and transition exact, every corner a kink — with the
/// limit-state search at every sample. (Non-uniqueness near μ_ms for α ≈ 0.7–0.9 is a
/// finding, checked independently for α = 0.8 above, not asserted here.)
#[test]
fn symmetric_openings_are_decided() {
    for i in 0..=13 {
        let alpha = -1.4 + 0.2 * i as f64;
        let c = curve(alpha);
        assert!(c.unresolved.is_empty(), "{alpha}: {:?}", c.unresolved);
        assert!(!c.branches.is_empty(), "{alpha}");
        for k in c.corners.iter().chain(&c.transitions) {
            assert!(k.exact, "{alpha}: {k:?}");
        }
        assert!(c.corners.iter().all(|k| k.detail.kink), "{alpha}");
    }
}

/// A discrete arch whose near-vertical chord makes two intrados hinges tie along the
/// boundary: each corner once (the same corner was located from several sample pairs:
/// 105 corners, 73 duplicates, zero-width branches between them), every branch of
/// positive width, and no slope that rises (η_s is non-increasing in μ).
#[test]
fn each_corner_once_and_no_rising_slope_on_a_near_vertical_chord() {
    let (v, code) = crate::cli::json_of(&[
        "modes",
        "--blocks",
        "34",
        "--beta-right",
        "-1.4177333410457853",
        "--beta-left",
        "1.5001011218600866",
    ]);
    assert_eq!(code, 0, "{v}");
    let corners = v["corners"].as_array().unwrap();
    assert!(!corners.is_empty());
    for (i, a) in corners.iter().enumerate() {
        for b in &corners[i + 1..] {
            let same = |k: &str| {
                let (x, y) = (a[k].as_f64(), b[k].as_f64());
                matches!((x, y), (Some(x), Some(y)) if (x - y).abs() <= 1e-9 * x.abs())
            };
            assert!(!(same("mu") && same("eta")), "duplicate corner {a} / {b}");
        }
    }
    for br in v["branches"].as_array().unwrap() {
        let (lo, hi) = (br["mu_min"].as_f64().unwrap(), br["mu_max"].as_f64());
        assert!(
            hi.is_none_or(|hi| hi > lo * (1.0 + 1e-9)),
            "zero-width branch {br}"
        );
    }
    // η_s at the corners falls as μ grows
    let mut pts: Vec<(f64, f64)> = corners
        .iter()
        .filter_map(|c| Some((c["mu"].as_f64()?, c["eta"].as_f64()?)))
        .collect();
    pts.sort_by(|a, b| a.0.total_cmp(&b.0));
    for w in pts.windows(2) {
        assert!(w[1].1 <= w[0].1 * (1.0 + 1e-12), "eta rises with mu: {w:?}");
    }
}
