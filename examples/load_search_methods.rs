//! The two searches for a load's limit states below λ_static side by side, in one run:
//! the sweep in λ (the default up to `settings.load_sweep_max_joints` joints) and the face
//! search (beyond it; here forced by `load_sweep_max_joints = 2`), library time of
//! `multiplier::survey` (median of 3) and whether both give the same λ and limit states,
//! on discrete arches of 32–511 voussoirs and on continuous arches (whose search runs on
//! two discretisations). Run: `cargo run --release --example load_search_methods`.

use arch_enum::load::LiveLoad;
use arch_enum::multiplier::{survey, LoadOutcome};
use arch_enum::{Arch, Settings, WeightModel};
use std::time::Instant;

/// Median time [ms] of three surveys, and what they answer (λ and the limit states' λ).
fn run(arch: &Arch, (eta, mu): (f64, f64), load: &LiveLoad, s: &Settings) -> (f64, String) {
    let mut t: Vec<f64> = (0..3)
        .map(|_| {
            let start = Instant::now();
            let _ = survey(arch, eta, mu, load, s).expect("valid input");
            start.elapsed().as_secs_f64() * 1e3
        })
        .collect();
    t.sort_by(f64::total_cmp);
    let answer = match survey(arch, eta, mu, load, s).expect("valid input") {
        Ok(LoadOutcome::Limits(sv)) => format!(
            "{:?} {:?}",
            sv.lambda(),
            sv.limit_states.iter().map(|l| l.t).collect::<Vec<_>>()
        ),
        other => format!("{other:?}"),
    };
    (t[1], answer)
}

fn main() {
    let sweep = Settings::default();
    let faces = Settings {
        load_sweep_max_joints: 2,
        ..Settings::default()
    };
    let loads = [
        (
            "point at 40°",
            LiveLoad::Point {
                beta: 40f64.to_radians(),
            },
        ),
        (
            "horizontal",
            LiveLoad::Horizontal {
                towards_right: true,
            },
        ),
    ];
    println!("| arch | voussoirs | load | sweep [ms] | face search [ms] | same answer |");
    println!("|---|---:|---|---:|---:|---|");
    for (alpha, eta, mu) in [(0.0, 0.3, 0.6), (-0.4, 0.15, 0.5), (0.0, 0.2, 0.4)] {
        let continuous = Arch::symmetric(alpha, WeightModel::Centreline).expect("an opening");
        for n in [0, 32, 128, 511] {
            let arch = if n == 0 {
                continuous.clone()
            } else {
                continuous.clone().with_blocks(n).expect("a voussoir count")
            };
            for (name, load) in &loads {
                let (a, ra) = run(&arch, (eta, mu), load, &sweep);
                let (b, rb) = run(&arch, (eta, mu), load, &faces);
                let blocks = if n == 0 {
                    "continuous".to_string()
                } else {
                    n.to_string()
                };
                println!(
                    "| α = {alpha}, η = {eta}, μ = {mu} | {blocks} | {name} | {a:.1} | {b:.1} | {} |",
                    if ra == rb { "yes".to_string() } else { format!("no: {ra} vs {rb}") }
                );
            }
        }
    }
}
