//! Library time of the load-multiplier answer (`multiplier::survey`), in one run: the
//! continuous semicircle under a horizontal acceleration at μ = ∞ (exact λ_static by the
//! exchange method and Newton; the only limit state), the same at finite μ (two discrete
//! sweeps, 48 and 96 pieces, carried over to the continuum), and discrete arches (static
//! range plus the complete sweep in λ). Medians of 9. Run:
//! `cargo run --release --example load_speed`.

use arch_enum::load::LiveLoad;
use arch_enum::multiplier::{survey, LoadOutcome};
use arch_enum::{Arch, Settings, WeightModel};
use std::time::Instant;

fn main() {
    let s = Settings::default();
    let right = LiveLoad::Horizontal {
        towards_right: true,
    };
    let semi = |w| Arch::symmetric(0.0, w).unwrap();
    let mut cases: Vec<(String, Arch, f64, f64, LiveLoad)> = Vec::new();
    for w in [WeightModel::Centreline, WeightModel::Centroid] {
        for eta in [0.12, 0.15, 0.2, 0.3] {
            cases.push((
                format!("continuous semicircle, {}, eta = {eta}, mu = inf", w.name()),
                semi(w),
                eta,
                f64::INFINITY,
                right,
            ));
        }
    }
    cases.push((
        "continuous semicircle, point load at 60 deg, eta = 0.2, mu = inf".into(),
        semi(WeightModel::Centreline),
        0.2,
        f64::INFINITY,
        LiveLoad::Point {
            beta: std::f64::consts::PI / 3.0,
        },
    ));
    cases.push((
        "continuous semicircle, centreline, eta = 0.2, mu = 0.6".into(),
        semi(WeightModel::Centreline),
        0.2,
        0.6,
        right,
    ));
    for blocks in [20, 100] {
        cases.push((
            format!("{blocks} blocks, eta = 0.3, mu = 0.8"),
            semi(WeightModel::Centreline).with_blocks(blocks).unwrap(),
            0.3,
            0.8,
            right,
        ));
    }
    println!("| case | lambda_static | lambda | limit states | median [ms] |");
    println!("|---|---:|---:|---:|---:|");
    for (name, arch, eta, mu, load) in cases {
        let mut t: Vec<f64> = (0..9)
            .map(|_| {
                let start = Instant::now();
                let _ = survey(&arch, eta, mu, &load, &s).unwrap();
                start.elapsed().as_secs_f64() * 1e3
            })
            .collect();
        t.sort_by(f64::total_cmp);
        let (ls, l, n) = match survey(&arch, eta, mu, &load, &s).unwrap() {
            Ok(LoadOutcome::Limits(sv)) => (
                sv.lambda_static
                    .map_or("unbounded".into(), |m| format!("{:.13}", m.0)),
                sv.lambda().map_or("none".into(), |l| format!("{l:.13}")),
                sv.limit_states.len(),
            ),
            other => (format!("{other:?}"), String::new(), 0),
        };
        println!("| {name} | {ls} | {l} | {n} | {:.3} |", t[4]);
    }
}
