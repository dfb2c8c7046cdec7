//! Certificates: `certify` then `verify` over the snapshot openings at several μ
//! (∞, just above μ_ms, on the mixed branch) and discrete arches; tampering is caught;
//! below μ_ms a friction-only Farkas certificate is accepted.

use arch_enum::certificate::verify;
use arch_enum::certificate::{certify, Certificate, Claim};
use arch_enum::{least_friction, Arch, Settings, WeightModel};
use assert_cmd::Command;

fn cert(arch: &Arch, mu: f64) -> Certificate {
    certify(arch, mu, 1e-12, &Settings::default())
        .unwrap_or_else(|e| panic!("{arch:?} mu = {mu}: {e:?}"))
}

fn holds(c: &Certificate) {
    if let Err(r) = verify(c) {
        panic!("rejected: {r:?}");
    }
}

#[test]
fn certify_then_verify_across_openings() {
    let s = Settings::default();
    for alpha in [
        -1.2,
        -0.5235987755982988,
        -0.3,
        0.0,
        0.5235987755982988,
        0.8,
        1.0,
        1.1,
        1.15,
    ] {
        let arch = Arch::symmetric(alpha, WeightModel::Centreline).unwrap();
        let mu_ms = least_friction(&arch, &s).unwrap().unwrap();
        for mu in [f64::INFINITY, mu_ms * 1.001, mu_ms * 1.1, mu_ms * 3.0] {
            let c = cert(&arch, mu);
            holds(&c);
            assert_eq!(c.claim, Claim::LeastThickness);
            let rel = c.gap_relative.unwrap();
            assert!(rel <= 1e-9, "alpha {alpha} mu {mu}: relative gap {rel}");
        }
    }
}

#[test]
fn certify_discrete_and_unsymmetric_and_centroid() {
    let base = Arch::symmetric(0.0, WeightModel::Centreline).unwrap();
    for arch in [
        base.clone().with_blocks(12).unwrap(),
        base.clone().with_blocks(400).unwrap(),
        Arch::new(-0.3, std::f64::consts::PI + 0.1, WeightModel::Centreline).unwrap(),
        Arch::symmetric(0.0, WeightModel::Centroid).unwrap(),
    ] {
        for mu in [f64::INFINITY, 0.6, 0.36] {
            let c = cert(&arch, mu);
            holds(&c);
        }
    }
}

#[test]
fn below_mu_ms_certifies_no_equilibrium() {
    let arch = Arch::symmetric(0.0, WeightModel::Centreline).unwrap();
    let c = cert(&arch, 0.3);
    assert_eq!(c.claim, Claim::NoEquilibrium);
    holds(&c);
    let arch = Arch::symmetric(1.0, WeightModel::Centreline).unwrap();
    let c = cert(&arch, 1.5);
    assert_eq!(c.claim, Claim::NoEquilibrium);
    holds(&c);
}

#[test]
fn tampering_is_caught() {
    let arch = Arch::symmetric(0.0, WeightModel::Centreline).unwrap();
    let good = cert(&arch, 0.35);
    holds(&good);
    let rejected = |c: &Certificate, what: &str| {
        let r = verify(c).expect_err(what);
        assert!(!r.0.is_empty());
        r.0
    };
    // one digit of x (the 4th significant digit of h)
    let mut c = good.clone();
    let h = c.safe.as_ref().unwrap().x[0];
    c.safe.as_mut().unwrap().x[0] = h + 1e-4 * h;
    let why = rejected(&c, "changed digit of h");
    assert!(why.contains("safe side"), "{why}");
    // the sign of a multiplier
    let mut c = good.clone();
    c.collapse.as_mut().unwrap().joints[1].y *= -1.0;
    let why = rejected(&c, "flipped multiplier");
    assert!(why.contains("multiplier"), "{why}");
    // drop a Farkas joint
    let mut c = good.clone();
    c.collapse.as_mut().unwrap().joints.pop();
    let why = rejected(&c, "dropped joint");
    assert!(why.contains("exactly 4 joints"), "{why}");
    // eta_hi shifted below eta*
    let mut c = good.clone();
    let ls_eta = c.limit_state.as_ref().unwrap().eta;
    c.safe.as_mut().unwrap().eta = ls_eta * (1.0 - 1e-9);
    c.collapse.as_mut().unwrap().eta = Some(ls_eta * (1.0 - 2e-9));
    c.gap = None;
    let why = rejected(&c, "eta_hi below eta*");
    assert!(why.contains("safe side"), "{why}");
    // eta_lo moved above eta* (the Farkas side must fail)
    let mut c = good.clone();
    c.collapse.as_mut().unwrap().eta = Some(ls_eta * (1.0 + 1e-13));
    c.safe.as_mut().unwrap().eta = ls_eta * (1.0 + 2e-12);
    c.gap = None;
    assert!(verify(&c).is_err(), "eta_lo above eta* accepted");
    // a wrong version
    let mut c = good.clone();
    c.version = 99;
    assert!(rejected(&c, "version").contains("version"));
}

#[test]
fn cli_certify_verify_roundtrip_and_exit_codes() {
    let dir = std::env::temp_dir().join(format!("arch-enum-cert-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let file = dir.join("c.json");
    let out = Command::cargo_bin("arch-enum")
        .unwrap()
        .args([
            "certify",
            "--alpha",
            "0.5235987755982988",
            "--mu",
            "0.8",
            "--out",
        ])
        .arg(&file)
        .output()
        .unwrap();
    assert_eq!(
        out.status.code(),
        Some(0),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let ok = Command::cargo_bin("arch-enum")
        .unwrap()
        .arg("verify")
        .arg(&file)
        .output()
        .unwrap();
    assert_eq!(ok.status.code(), Some(0));
    assert!(String::from_utf8_lossy(&ok.stdout).contains("certificate holds"));
    // tamper in the file: change one digit of w
    let mut v: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(&file).unwrap()).unwrap();
    let w = v["safe"]["x"][2].as_f64().unwrap();
    v["safe"]["x"][2] = serde_json::json!(w + 0.01);
    std::fs::write(&file, serde_json::to_string(&v).unwrap()).unwrap();
    let bad = Command::cargo_bin("arch-enum")
        .unwrap()
        .arg("verify")
        .arg(&file)
        .output()
        .unwrap();
    assert_eq!(bad.status.code(), Some(1));
    assert!(String::from_utf8_lossy(&bad.stdout).contains("REJECTED"));
    // not a certificate: exit 2
    std::fs::write(&file, "{\"hello\": 1}").unwrap();
    let junk = Command::cargo_bin("arch-enum")
        .unwrap()
        .arg("verify")
        .arg(&file)
        .output()
        .unwrap();
    assert_eq!(junk.status.code(), Some(2));
    std::fs::remove_dir_all(&dir).ok();
}
