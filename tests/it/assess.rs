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

/// With fill (bridge spec §2): whether a thickness stands is decided at that thickness
/// (admissibility need not grow with η), η/η* is a factor only where the admissible
/// thicknesses form an interval, and μ_min(η) is the root of admissibility in μ: just above it
/// the thickness stands, just below it does not. On the README's bridge and on a horseshoe
/// under heavy shallow fill whose admissible thicknesses stop at an upper η.
#[test]
fn assessed_with_fill() {
    use arch_enum::bridge::Fill;
    use std::f64::consts::PI;
    let s = Settings::default();
    let stands = |arch: &Arch, eta: f64, mu: f64| assess(arch, eta, mu, &s).unwrap().stands;
    let root = |arch: &Arch, eta: f64| {
        let LeastFriction::Finite { mu, exact, .. } = mu_min(arch, eta) else {
            panic!("no mu_min at eta {eta}")
        };
        assert!(exact, "mu_min at eta {eta} not exact");
        assert!(
            stands(arch, eta, mu * (1.0 + 1e-6)),
            "eta {eta} falls above mu_min {mu}"
        );
        assert!(
            !stands(arch, eta, mu * (1.0 - 1e-6)),
            "eta {eta} stands below mu_min {mu}"
        );
        mu
    };
    let bridge = Arch::symmetric(0.0, WeightModel::Centreline)
        .unwrap()
        .with_fill(Fill::new(0.9, 0.3 / 5.3).unwrap());
    let a = assess(&bridge, 0.6 / 5.3, 0.6, &s).unwrap();
    assert!(a.stands);
    let es = eta_star(&bridge, 0.6);
    assert!((a.geometric_factor.unwrap() - 0.6 / 5.3 / es).abs() < 1e-12);
    let mu = root(&bridge, 0.6 / 5.3);
    assert!((a.friction_factor.unwrap() - 0.6 / mu).abs() < 1e-12);
    // the horseshoe of fill_thickness.rs: admissible from eta_s to about 0.93 only
    let alpha = 0.1825328807489831;
    let (br, bl) = (-alpha, PI + alpha);
    let horseshoe = Arch::new(br, bl, WeightModel::Centreline)
        .unwrap()
        .with_joints(&crate::search_reference::equal_joints(br, bl, 64))
        .unwrap()
        .with_fill(Fill::new(1.4170008626893624, 0.030118768852026835).unwrap());
    let mu = 0.3972687290844831;
    for (eta, standing) in [(0.5, true), (1.5, false)] {
        let a = assess(&horseshoe, eta, mu, &s).unwrap();
        assert_eq!(a.stands, standing, "eta {eta}");
        assert!(
            a.geometric_factor.is_none(),
            "eta {eta}: a factor over a gap"
        );
        let m = root(&horseshoe, eta);
        assert_eq!(m < mu, standing, "eta {eta}: mu_min {m}");
    }
}

/// `assess` takes the fill flags: the fill's line and JSON key, the bridge's scope.
#[test]
fn assess_takes_the_fill_flags() {
    let mut args = vec!["assess", "--mu", "0.6"];
    args.extend(crate::bridge::DIMENSIONS);
    args.extend(crate::bridge::FILL);
    let (v, code) = json_of(&args);
    assert_eq!(code, 0);
    assert_eq!(v["fill"]["weight_ratio"], 0.9);
    assert_eq!(v["stands"], true);
    let out = assert_cmd::Command::cargo_bin("arch-enum")
        .unwrap()
        .args(&args)
        .output()
        .unwrap();
    let text = String::from_utf8(out.stdout).unwrap();
    assert!(
        text.contains("fill                18.0000 kN/m^3"),
        "{text}"
    );
    assert!(text.contains("the fill a vertical dead load"), "{text}");
    let (v, code) = json_of(&["assess", "--alpha", "0", "--eta", "0.2", "--mu", "0.35"]);
    assert_eq!(code, 0);
    assert!(
        v.get("fill").is_none(),
        "a bare arch's document has no fill key"
    );
}
