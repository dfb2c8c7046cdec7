//! Published reference values (shared/spec/reference-values.md, from the founding
//! paper's tables, printed to 8 significant digits; Milankovitch 1907 / Ochsendorf
//! 2002 for the true-centroid value, printed to 4). Tolerances match the printed digits:
//! half a unit in the last printed place.

use arch_enum::{
    least_friction, solve, Arch, ContactKind, LeastLimitState, Outcome, Settings, WeightModel,
};
use std::f64::consts::PI;

fn limit(alpha: f64, mu: f64, weight: WeightModel) -> LeastLimitState {
    let arch = Arch::symmetric(alpha, weight).unwrap();
    match solve(&arch, mu, &Settings::default()).unwrap().outcome {
        Outcome::Limit(ls) => ls,
        other => panic!("alpha = {alpha}, mu = {mu}: expected a limit state, got {other:?}"),
    }
}

/// Asserts |value − printed| ≤ half a unit of the last of `digits` significant digits.
fn assert_digits(what: &str, value: f64, printed: f64, digits: i32) {
    let ulp = 10f64.powi(printed.abs().log10().floor() as i32 - digits + 1);
    assert!(
        (value - printed).abs() <= 0.5 * ulp,
        "{what}: computed {value:.12}, published {printed} ({digits} significant digits)"
    );
}

fn intrados_hinges(ls: &LeastLimitState) -> Vec<f64> {
    ls.pattern
        .iter()
        .filter(|c| c.kind == ContactKind::HingeIntrados)
        .map(|c| c.beta)
        .collect()
}

#[test]
fn couplet_heyman_semicircle() {
    let ls = limit(0.0, f64::INFINITY, WeightModel::Centreline);
    assert_digits("eta_CH", ls.eta, 0.10742645, 8);
    let b = intrados_hinges(&ls);
    assert_eq!(b.len(), 2, "two intrados hinges: {:?}", ls.pattern);
    assert_digits("beta_N", b[0], 0.61965572, 8);
    assert_digits("pi - beta_N", PI - b[1], 0.61965572, 8);
    assert_eq!(ls.mode.name(), "purely_rotational");
}

#[test]
fn over_complete_pi_over_6_rotational() {
    let ls = limit(PI / 6.0, f64::INFINITY, WeightModel::Centreline);
    assert_digits("eta_rm", ls.eta, 0.32654664, 8);
    assert_digits("beta_N", intrados_hinges(&ls)[0], 0.45365963, 8);
}

#[test]
fn milankovitch_true_centroid() {
    let ls = limit(0.0, f64::INFINITY, WeightModel::Centroid);
    assert_digits("eta (true centroid)", ls.eta, 0.1075, 4);
    // the intrados hinge is about 54.5 degrees from the crown
    let from_crown = (PI / 2.0 - intrados_hinges(&ls)[0]).to_degrees();
    assert!((from_crown - 54.5).abs() < 0.1, "{from_crown}");
}

#[test]
fn infinite_friction_is_the_limit_of_large_friction() {
    // mu above mu_rm (0.39583204) gives the Couplet-Heyman state, mu below it does not.
    let above = limit(0.0, 0.3959, WeightModel::Centreline);
    assert_digits("eta at mu = 0.3959", above.eta, 0.10742645, 8);
    let below = limit(0.0, 0.3958, WeightModel::Centreline);
    assert!(below.eta > 0.10742645 + 1e-9, "{}", below.eta);
    assert_ne!(below.mode.name(), "purely_rotational");
}

#[test]
fn least_friction_mu_ms() {
    let s = Settings::default();
    let m0 = least_friction(&Arch::symmetric(0.0, WeightModel::Centreline).unwrap(), &s)
        .unwrap()
        .unwrap();
    assert_digits("mu_ms (alpha = 0)", m0, 0.30921544, 8);
    let m6 = least_friction(
        &Arch::symmetric(PI / 6.0, WeightModel::Centreline).unwrap(),
        &s,
    )
    .unwrap()
    .unwrap();
    assert_digits("mu_ms (alpha = pi/6)", m6, 0.73904014, 8);
}

/// The sliding joints of the friction-limiting state: beta_T at the mu_ms corner.
#[test]
fn friction_limit_sliding_joints() {
    let s = Settings::default();
    for (alpha, beta_t) in [(0.0, 1.0710004), (PI / 6.0, 1.1453296)] {
        let arch = Arch::symmetric(alpha, WeightModel::Centreline).unwrap();
        let f = arch_enum::friction_limit(&arch, &s).unwrap().unwrap();
        assert!(f.exact);
        let interior: Vec<f64> = f
            .pattern
            .iter()
            .filter(|c| c.at == arch_enum::Location::Interior)
            .map(|c| c.beta)
            .collect();
        assert_eq!(interior.len(), 2, "{:?}", f.pattern);
        assert_digits("beta_T", interior[0], beta_t, 8);
        assert_digits("pi - beta_T", PI - interior[1], PI - (PI - beta_t), 8);
    }
}

#[test]
fn below_mu_ms_there_is_no_equilibrium() {
    let arch = Arch::symmetric(0.0, WeightModel::Centreline).unwrap();
    match solve(&arch, 0.309, &Settings::default()).unwrap().outcome {
        Outcome::NoEquilibrium { mu_ms: Some(m), .. } => assert_digits("mu_ms", m, 0.30921544, 8),
        other => panic!("{other:?}"),
    }
}

#[test]
fn eta_approaches_eta_ms_at_mu_ms() {
    // just above mu_ms the least thickness is close to eta_ms = 0.20063732
    let ls = limit(0.0, 0.30921545, WeightModel::Centreline);
    assert!((ls.eta - 0.20063732).abs() < 1e-5, "{}", ls.eta);
}
