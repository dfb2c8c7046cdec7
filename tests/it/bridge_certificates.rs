//! Certificates of a bridge: a vehicle through the fill on an arch with fill, certified by
//! `certify_load` and re-proved by `verify`.

use arch_enum::bridge::{Deck, Fill, Vehicle};
use arch_enum::certificate::{certify_load, verify};
use arch_enum::Settings;

#[test]
fn scratch_vehicle_with_fill() {
    let arch = arch_enum::Arch::symmetric(0.0, arch_enum::WeightModel::Centreline)
        .unwrap()
        .with_fill(Fill::new(0.9, 0.3 / 5.3).unwrap());
    let eta = 0.6 / 5.3;
    let deck = Deck::new(5.3, 20.0, 1.0, 0.5).unwrap();
    let vehicle = Vehicle::new(&[100.0, 100.0], &[1.2]).unwrap();
    for at in [1.0, 2.6, 4.0, 7.5] {
        let load = deck.place(&arch, eta, &vehicle, at).unwrap();
        let t = std::time::Instant::now();
        let c = certify_load(&arch, eta, 0.6, &load, 1e-12, &Settings::default());
        match c {
            Ok(c) => {
                let r = verify(&c);
                println!(
                    "at {at}: {:?} {:?} {:?} {:?}",
                    c.claim,
                    c.lambda_bracket(),
                    r.map(|r| r.claim),
                    t.elapsed()
                );
            }
            Err(e) => println!("at {at}: not certified {e:?}"),
        }
    }
}

#[test]
fn scratch_gaps() {
    use arch_enum::load::LiveLoad;
    let semi = arch_enum::Arch::symmetric(0.0, arch_enum::WeightModel::Centreline).unwrap();
    let filled = semi.clone().with_fill(Fill::new(0.9, 0.3 / 5.3).unwrap());
    let eta = 0.6 / 5.3;
    let deck = Deck::new(5.3, 20.0, 1.0, 0.5).unwrap();
    let deck0 = Deck::new(5.3, 20.0, 1.0, 0.0).unwrap();
    let vehicle = Vehicle::new(&[100.0, 100.0], &[1.2]).unwrap();
    let twelve = filled.clone().with_blocks(12).unwrap();
    let seg = arch_enum::Arch::symmetric(0.6, arch_enum::WeightModel::Centroid)
        .unwrap()
        .with_fill(Fill::new(0.8, 0.1).unwrap());
    let cases: Vec<(&str, arch_enum::Arch, LiveLoad)> = vec![
        ("point bare", semi.clone(), LiveLoad::Point { beta: 1.2 }),
        (
            "point filled",
            filled.clone(),
            LiveLoad::Point { beta: 1.2 },
        ),
        (
            "vehicle filled",
            filled.clone(),
            deck.place(&filled, eta, &vehicle, 2.6).unwrap(),
        ),
        (
            "vehicle no dispersal",
            filled.clone(),
            deck0.place(&filled, eta, &vehicle, 2.6).unwrap(),
        ),
        (
            "vehicle bare",
            semi.clone(),
            deck.place(&semi, eta, &vehicle, 2.6).unwrap(),
        ),
        (
            "vehicle 12 blocks",
            twelve.clone(),
            deck.place(&twelve, eta, &vehicle, 2.6).unwrap(),
        ),
        (
            "vehicle 12 no dispersal",
            twelve.clone(),
            deck0.place(&twelve, eta, &vehicle, 2.6).unwrap(),
        ),
        (
            "vehicle segmental",
            seg.clone(),
            deck.place(&seg, eta, &vehicle, 2.6).unwrap(),
        ),
    ];
    for (what, arch, load) in cases {
        let t = std::time::Instant::now();
        match certify_load(&arch, eta, 0.6, &load, 1e-12, &Settings::default()) {
            Ok(c) => {
                let r = verify(&c);
                let gap = c.lambda_bracket().map(|(lo, hi)| (hi - lo) / hi);
                println!(
                    "{what}: {:?} gap {gap:?} {:?} search {:?} {:?}",
                    c.claim,
                    r.map(|r| r.claim),
                    c.load_search
                        .as_ref()
                        .map(|s| (s.method, s.limit_states.len())),
                    t.elapsed()
                );
            }
            Err(e) => println!("{what}: not certified {e:?}"),
        }
    }
}
