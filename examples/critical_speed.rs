//! What `load --critical` costs (bridge spec §4): the issue's 10 m semicircle (ring 0.6 m,
//! 20 kN/m³, μ = 0.6, 1 m strip) with and without fill, one axle and a two-axle train, on the
//! continuous arch and on 40 voussoirs. For each: the complete searches (surveys) and the
//! static maxima alone run, the wall time on one thread and on two, and X* and λ_c (the
//! answer does not depend on the threads: checked). One run, one machine: read the ratios, not the absolute times.
//!
//! ```text
//! cargo run --release --example critical_speed
//! ```

use arch_enum::bridge::{critical, Deck, Fill, Intrados, Search, Vehicle};
use arch_enum::{Arch, Settings, WeightModel};
use std::time::Instant;

fn main() {
    let settings = Settings::default();
    let ring = Intrados::new(10.0, 5.0).unwrap().ring(0.6).unwrap();
    let eta = ring.eta;
    let deck = Deck::new(ring.radius, 20.0, 1.0, 0.5).unwrap();
    let fill = Fill::new(18.0 / 20.0, 0.3 / ring.radius).unwrap();
    let bare = Arch::symmetric(0.0, WeightModel::Centreline).unwrap();
    let axle = Vehicle::new(&[100.0], &[]).unwrap();
    let pair = Vehicle::new(&[100.0, 100.0], &[1.2]).unwrap();
    println!(
        "{:<34} {:>8} {:>8} {:>10} {:>10} {:>14} {:>14}",
        "case", "surveys", "statics", "1 thread s", "2 thr. s", "X* (m)", "lambda_c"
    );
    for (name, arch, vehicle) in [
        ("continuous, bare, one axle", bare.clone(), &axle),
        (
            "continuous, fill, one axle",
            bare.clone().with_fill(fill),
            &axle,
        ),
        (
            "continuous, fill, two axles",
            bare.clone().with_fill(fill),
            &pair,
        ),
        (
            "40 voussoirs, bare, one axle",
            bare.clone().with_blocks(40).unwrap(),
            &axle,
        ),
        (
            "40 voussoirs, fill, one axle",
            bare.clone().with_blocks(40).unwrap().with_fill(fill),
            &axle,
        ),
        (
            "40 voussoirs, fill, two axles",
            bare.clone().with_blocks(40).unwrap().with_fill(fill),
            &pair,
        ),
    ] {
        let mut times = Vec::new();
        let mut found = Vec::new();
        for threads in [1, 2] {
            let search = Search {
                samples: 41,
                bracket_m: 1e-6,
                threads,
            };
            let t = Instant::now();
            let c = critical(&arch, eta, 0.6, &deck, vehicle, search, &settings).unwrap();
            times.push(t.elapsed().as_secs_f64());
            found.push((
                (c.surveys, c.statics),
                c.minima.first().map(|m| (m.at_m, m.lambda)),
            ));
        }
        assert_eq!(
            found[0], found[1],
            "{name}: the answer depends on the threads"
        );
        let ((surveys, statics), best) = found[0];
        let (x, l) = best.unwrap_or((f64::NAN, f64::NAN));
        println!(
            "{name:<34} {surveys:>8} {statics:>8} {:>10.3} {:>10.3} {x:>14.9} {l:>14.10}",
            times[0], times[1],
        );
    }
}
