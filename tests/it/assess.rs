//! `assess`: factors of safety and μ_min(η), the inverse of the limit curve, checked by
//! round trips through `solve` (an independent route: bracketing in η at fixed μ).

use crate::cli::json_of;
use arch_enum::assess::{assess, LeastFriction};
use arch_enum::{solve, Arch, Outcome, Settings, WeightModel};

fn eta_star(arch: &Arch, mu: f64) -> f64 {
    match solve(arch, mu, &Settings::default()).unwrap().outcome {
        Outcome::Limit(ls) => ls.eta,
        o => panic!("{o:?}"),
    }
}

fn mu_min(arch: &Arch, eta: f64) -> LeastFriction {
    assess(arch, eta, f64::INFINITY, &Settings::default())
        .unwrap()
        .least_friction
}

/// The case the issue names, through the CLI: each figure to 10 digits.
#[test]
fn semicircle_eta_0_2_mu_0_35() {
    let (v, code) = json_of(&["assess", "--alpha", "0", "--eta", "0.2", "--mu", "0.35"]);
    assert_eq!(code, 0);
    assert_eq!(v["status"], "ok");
    assert_eq!(v["version"], 2);
    assert_eq!(v["stands"], true);
    let arch = Arch::symmetric(0.0, WeightModel::Centreline).unwrap();
    let es = eta_star(&arch, 0.35);
    let rel = |a: f64, b: f64| (a - b).abs() / b.abs();
    assert!(rel(v["eta_min"].as_f64().unwrap(), es) < 1e-10);
    assert!(rel(v["geometric_factor"].as_f64().unwrap(), 0.2 / es) < 1e-10);
    let m = v["mu_min"].as_f64().unwrap();
    assert_eq!(v["mu_min_exact"], true);
    // η*(μ_min) = 0.2, by the thickness solver
    assert!(
        rel(eta_star(&arch, m), 0.2) < 1e-10,
        "{}",
        eta_star(&arch, m)
    );
    assert!(rel(v["friction_factor"].as_f64().unwrap(), 0.35 / m) < 1e-12);
    assert_eq!(v["mode"], "mixed_sliding_rotational");
    assert!(v["safest_state"]["margin"].as_f64().unwrap() > 0.0);
}

/// μ_min(η*(μ)) = μ on the mixed branches of several openings (round trip), μ_ms on the
/// vertical branch, none below the infinite-friction least thickness.
#[test]
fn least_friction_inverts_the_limit_curve() {
    for (alpha, mus) in [
        (0.0, vec![0.32, 0.35, 0.38]),
        (std::f64::consts::FRAC_PI_6, vec![0.75, 0.8]),
        (1.0, vec![1.8, 2.2]),
        (-0.3, vec![0.18, 0.2]),
    ] {
        let arch = Arch::symmetric(alpha, WeightModel::Centreline).unwrap();
        for mu in mus {
            let eta = eta_star(&arch, mu);
            match mu_min(&arch, eta) {
                LeastFriction::Finite { mu: m, exact, .. } => {
                    assert!(exact, "alpha {alpha} mu {mu}");
                    assert!((m - mu).abs() <= 1e-9 * mu, "alpha {alpha}: {m} vs {mu}");
                }
                LeastFriction::Never => panic!("alpha {alpha} mu {mu}: never"),
            }
        }
        let ms = arch_enum::least_friction(&arch, &Settings::default())
            .unwrap()
            .unwrap();
        let eta_ms = eta_star(&arch, ms * (1.0 + 1e-6));
        match mu_min(&arch, (eta_ms * 1.2).min(1.99)) {
            LeastFriction::Finite { mu: m, .. } => assert!((m - ms).abs() <= 1e-12 * ms),
            LeastFriction::Never => panic!("never"),
        }
        let e_inf = eta_star(&arch, f64::INFINITY);
        assert_eq!(mu_min(&arch, e_inf * 0.99), LeastFriction::Never);
    }
}

/// Below η*(μ) the arch does not stand; factors below one.
#[test]
fn too_thin_does_not_stand() {
    let (v, code) = json_of(&["assess", "--alpha", "0", "--eta", "0.15", "--mu", "0.35"]);
    assert_eq!(code, 0);
    assert_eq!(v["stands"], false);
    assert!(v["geometric_factor"].as_f64().unwrap() < 1.0);
    assert!(v["friction_factor"].as_f64().unwrap() < 1.0);
    assert!(v["safest_state"].is_null());
}
