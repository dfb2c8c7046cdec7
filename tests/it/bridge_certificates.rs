//! Certificates of a bridge (bridge spec §2–§4): a vehicle spread through the fill, or as
//! point loads, on an arch with fill, certified by `certify_load` and re-proved by `verify`
//! (whose fill and pressure are its own interval arithmetic); they agree with the survey,
//! hold on random bridges, and fail when the fill or the vehicle is tampered with.

use crate::search_reference::{equal_joints, Rng};
use arch_enum::bridge::{Deck, Fill, Vehicle};
use arch_enum::certificate::{certify_load, verify, Certificate, Claim};
use arch_enum::load::LiveLoad;
use arch_enum::multiplier::{survey, LoadOutcome};
use arch_enum::{Arch, Settings, WeightModel};

/// The ten-metre deck of the README's bridge (r = 5.3 m, 20 kN/m³, 1 m barrel).
fn deck(dispersal: f64) -> Deck {
    Deck::new(5.3, 20.0, 1.0, dispersal).unwrap()
}

fn holds(c: &Certificate, what: &str) {
    let text = serde_json::to_string(c).unwrap();
    let back: Certificate = serde_json::from_str(&text).unwrap();
    assert_eq!(
        serde_json::to_string(&back).unwrap(),
        text,
        "{what}: round trip"
    );
    if let Err(r) = verify(&back) {
        panic!("{what}: rejected: {}", r.0)
    }
}

/// The certificate's claim agrees with the survey: the same kind of answer, λ_static inside
/// the bracket, and the same number of limit states with the same least λ.
fn agrees(arch: &Arch, eta: f64, mu: f64, load: &LiveLoad, c: &Certificate, what: &str) {
    let outcome = survey(arch, eta, mu, load, &Settings::default()).unwrap();
    match (outcome, c.claim) {
        (Ok(LoadOutcome::Limits(s)), Claim::LargestMultiplier) => {
            let top = s.lambda_static.expect("bounded").0;
            let (lo, hi) = c.lambda_bracket().unwrap();
            let slack = 1e-9 * top;
            assert!(
                lo - slack <= top && top <= hi + slack,
                "{what}: {top} vs [{lo}, {hi}]"
            );
            let listed = &c
                .load_search
                .as_ref()
                .expect("the search's evidence")
                .limit_states;
            assert_eq!(listed.len(), s.limit_states.len(), "{what}: limit states");
            if let (Some(a), Some(b)) = (listed.first(), s.lambda()) {
                assert!(
                    (a.lambda - b).abs() <= 1e-9 * b,
                    "{what}: {} vs {b}",
                    a.lambda
                );
            }
        }
        (Ok(LoadOutcome::NoEquilibrium), Claim::NoEquilibrium) => {}
        (Ok(LoadOutcome::NoCollapse { .. }), Claim::UnboundedMultiplier) => {}
        (other, claim) => panic!("{what}: survey {other:?}, certificate {claim:?}"),
    }
}

/// A vehicle spread through the fill, the same as point loads (no dispersal), and on the
/// bare ring, on continuous and discrete arches of three shapes: every certificate holds,
/// agrees with the survey, and names the fill and the pressure it proves.
#[test]
fn vehicle_certificates_hold_and_agree_with_the_survey() {
    let eta = 0.6 / 5.3;
    let fill = Fill::new(0.9, 0.3 / 5.3).unwrap();
    let two = Vehicle::new(&[100.0, 100.0], &[1.2]).unwrap();
    let semi = Arch::symmetric(0.0, WeightModel::Centreline).unwrap();
    let horseshoe = Arch::symmetric(-0.15, WeightModel::Centroid).unwrap();
    let segment = Arch::symmetric(0.4, WeightModel::Centreline).unwrap();
    let mut compared = 0;
    for (name, bare) in [
        ("semicircle", semi),
        ("horseshoe", horseshoe),
        ("segment", segment),
    ] {
        for blocks in [None, Some(16)] {
            let bare = match blocks {
                Some(n) => bare.clone().with_blocks(n).unwrap(),
                None => bare.clone(),
            };
            for (with_fill, dispersal, at) in
                [(true, 0.5, 2.6), (true, 0.0, 6.3), (false, 0.5, 3.1)]
            {
                let arch = match with_fill {
                    true => bare.clone().with_fill(fill),
                    false => bare.clone(),
                };
                let load = deck(dispersal).place(&arch, eta, &two, at).unwrap();
                let what =
                    format!("{name} {blocks:?} fill {with_fill} dispersal {dispersal} at {at}");
                let c = certify_load(&arch, eta, 0.6, &load, 1e-10, &Settings::default())
                    .unwrap_or_else(|e| panic!("{what}: {}", e.0));
                holds(&c, &what);
                agrees(&arch, eta, 0.6, &load, &c, &what);
                assert_eq!(c.arch.fill.is_some(), with_fill, "{what}");
                let report = verify(&c).unwrap();
                assert!(report.statement().contains("vertical pressure"), "{what}");
                assert_eq!(
                    report.arch_text().contains("with fill"),
                    with_fill,
                    "{what}"
                );
                compared += 1;
            }
        }
    }
    assert_eq!(compared, 18);
}

/// Random bridges: shape, weight model, continuous or 8–20 equal voussoirs, fill, μ
/// (finite or not), one to three axles spread or not, and the vehicle anywhere on the
/// middle half of its crossing. Every certificate holds and agrees with the survey.
#[test]
fn random_bridge_certificates_hold() {
    let mut rng = Rng(0x5eed_b41d);
    // BRIDGE_CERT_CASES=N for a longer campaign
    let cases = crate::cases_from_env("BRIDGE_CERT_CASES", 16);
    for case in 0..cases {
        let alpha = -0.2 + 0.9 * rng.next();
        let weight = match rng.next() < 0.5 {
            true => WeightModel::Centreline,
            false => WeightModel::Centroid,
        };
        let bare = Arch::symmetric(alpha, weight).unwrap();
        let bare = match rng.next() < 0.5 {
            true => bare.clone(),
            false => {
                let n = 8 + (12.0 * rng.next()) as usize;
                let joints = equal_joints(bare.beta_right(), bare.beta_left(), n);
                bare.with_joints(&joints).unwrap()
            }
        };
        let fill = Fill::new(0.6 + 0.6 * rng.next(), 0.2 * rng.next()).unwrap();
        let arch = bare.with_fill(fill);
        let eta = 0.08 + 0.2 * rng.next();
        let mu = match rng.next() < 0.2 {
            true => f64::INFINITY,
            false => 0.4 + 0.6 * rng.next(),
        };
        let axles: Vec<f64> = (0..1 + (3.0 * rng.next()) as usize)
            .map(|_| 50.0 + 100.0 * rng.next())
            .collect();
        let vehicle = Vehicle::new(&axles, &[1.0 + rng.next()]).unwrap();
        let d = deck(if rng.next() < 0.3 { 0.0 } else { 0.5 });
        // on the arch: a vehicle wholly off it loads nothing, and its unbounded multiplier
        // has no certificate (no direction decreases every activation function strictly)
        let (first, last) = d.crossing(&arch, eta, &vehicle);
        let at = first + (last - first) * (0.25 + 0.5 * rng.next());
        let load = d.place(&arch, eta, &vehicle, at).unwrap();
        let what = format!(
            "case {case}: alpha {alpha} {weight:?} {:?} eta {eta} mu {mu} axles {axles:?} at {at}",
            arch.layout()
        );
        let c = certify_load(&arch, eta, mu, &load, 1e-9, &Settings::default())
            .unwrap_or_else(|e| panic!("{what}: {}", e.0));
        holds(&c, &what);
        agrees(&arch, eta, mu, &load, &c, &what);
    }
}

/// A change made to a certificate.
type Tamper = fn(&mut Certificate);

/// A certificate proves its own bridge only: a heavier or shallower fill, no fill, a patch
/// heavier or moved, an axle that does not spread, each is rejected; and a least-thickness
/// certificate does not carry fill.
#[test]
fn tampered_bridge_certificates_are_rejected() {
    let eta = 0.6 / 5.3;
    let fill = Fill::new(0.9, 0.3 / 5.3).unwrap();
    let two = Vehicle::new(&[100.0, 100.0], &[1.2]).unwrap();
    for bare in [
        Arch::symmetric(0.0, WeightModel::Centroid)
            .unwrap()
            .with_blocks(16)
            .unwrap(),
        Arch::symmetric(0.0, WeightModel::Centreline).unwrap(),
    ] {
        let arch = bare.with_fill(fill);
        let load = deck(0.5).place(&arch, eta, &two, 2.6).unwrap();
        let good = certify_load(&arch, eta, 0.6, &load, 1e-10, &Settings::default()).unwrap();
        assert_eq!(good.claim, Claim::LargestMultiplier);
        verify(&good).unwrap();
        let tampered: [(&str, Tamper); 5] = [
            ("heavier fill", |c| {
                c.arch.fill.as_mut().unwrap().weight_ratio *= 1.01
            }),
            ("shallower fill", |c| {
                c.arch.fill.as_mut().unwrap().depth *= 0.9
            }),
            ("no fill", |c| c.arch.fill = None),
            ("heavier patch", |c| {
                c.load.as_mut().unwrap().patches.as_mut().unwrap()[0].q *= 1.01
            }),
            ("moved patch", |c| {
                let p = &mut c.load.as_mut().unwrap().patches.as_mut().unwrap()[1];
                p.x_lo += 0.01;
                p.x_hi += 0.01;
            }),
        ];
        for (what, change) in tampered {
            let mut t = good.clone();
            change(&mut t);
            assert!(
                verify(&t).is_err(),
                "{what}: a tampered certificate was accepted"
            );
        }
        // the pressure without its patches is not a load
        let mut t = good.clone();
        t.load.as_mut().unwrap().patches = Some(Vec::new());
        let why = verify(&t).unwrap_err().0;
        assert!(why.contains("at least one patch"), "{why}");
    }
    // fill written into a least-thickness certificate
    let bare = Arch::symmetric(0.0, WeightModel::Centreline)
        .unwrap()
        .with_blocks(12)
        .unwrap();
    let mut c = arch_enum::certificate::certify(&bare, 0.6, 1e-10, &Settings::default()).unwrap();
    verify(&c).unwrap();
    c.arch.fill = Some(arch_enum::certificate::FillSpec {
        weight_ratio: 0.9,
        depth: 0.05,
    });
    let why = verify(&c).unwrap_err().0;
    assert!(why.contains("arch.fill"), "{why}");
}

/// The command line: `certify` with the bridge flags writes a certificate of the vehicle where
/// it stands (`at_m`) on the arch with its fill, and `verify` holds it; without a load the
/// fill flags are refused by name (no least-thickness certificate with fill).
#[test]
fn certify_takes_the_bridge_flags() {
    use crate::cli::json_of;
    let dir = std::env::temp_dir().join(format!("arch-enum-bridgecert-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let file = dir.join("bridge.json");
    let file = file.to_str().unwrap();
    let mut bridge = vec!["certify", "--mu", "0.6"];
    bridge.extend(crate::bridge::DIMENSIONS);
    bridge.extend(crate::bridge::FILL);
    let mut args = bridge.to_vec();
    args.extend([
        "--axles",
        "100,100",
        "--spacing",
        "1.2",
        "--at",
        "4.0",
        "--blocks",
        "16",
    ]);
    args.extend(["--gap", "1e-10", "--out", file]);
    let (v, code) = json_of(&args);
    assert_eq!(code, 0, "{v}");
    assert_eq!(v["status"], "ok");
    assert_eq!(v["at_m"], 4.0);
    assert_eq!(v["load"]["kind"], "pressure");
    assert_eq!(v["certificate"]["arch"]["fill"]["weight_ratio"], 0.9);
    let (w, code) = crate::cli::json_of(&["verify", file]);
    assert_eq!(code, 0, "{w}");
    assert_eq!(w["status"], "ok");
    // without a vehicle: the least thickness of the arch with its fill, the ring fixing r
    // and so the fill's depth ratio (as for `solve`)
    bridge.extend(["--blocks", "16", "--gap", "1e-10", "--out", file]);
    let (e, code) = json_of(&bridge);
    assert_eq!(code, 0, "{e}");
    assert_eq!(e["claim"], "least_thickness");
    let fill = &e["certificate"]["arch"]["fill"];
    assert_eq!(fill["weight_ratio"], 0.9);
    assert!(
        (fill["depth"].as_f64().unwrap() - 0.3 / 5.3).abs() < 1e-15,
        "{fill}"
    );
    assert!(!e["certificate"]["collapse_cells"]
        .as_array()
        .unwrap()
        .is_empty());
    let (w, code) = crate::cli::json_of(&["verify", file]);
    assert_eq!(code, 0, "{w}");
    std::fs::remove_dir_all(&dir).unwrap();
}
