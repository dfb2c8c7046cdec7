//! Where non-associative friction lowers the collapse acceleration below the static maximum:
//! the load map of the atlas (`arch-enum atlas --horizontal`, [`arch_enum::atlas::loads`])
//! on continuous symmetric arches, centreline weight, openings α in [−1, 1.2] (the
//! semicircle among them), thicknesses η = f η*(α, μ) with f from 1.02 to 4, at five
//! friction coefficients.
//!
//! Prints, per μ, the cells answered, those with a reduction (λ_c < λ_static by more than
//! 10⁻⁹ relative), the largest reduction and where, and the semicircle's largest; then the
//! largest reductions. A sampled map, not a proof: a reduction window narrower than the
//! grid's spacing is not seen.
//!
//! Run: `cargo run --release --example load_reduction [-- --alphas N --factors M]`.

use arch_enum::atlas::loads::{load_map, CellAnswer, LoadGrid};
use arch_enum::atlas::Rectangle;
use arch_enum::{threads, Settings, WeightModel};
use std::time::Instant;

/// The argument after `name`, or `default`.
fn arg(name: &str, default: usize) -> usize {
    let a: Vec<String> = std::env::args().collect();
    a.iter()
        .position(|x| x == name)
        .and_then(|i| a.get(i + 1))
        .and_then(|v| v.parse().ok())
        .unwrap_or(default)
}

fn main() {
    let grid = LoadGrid {
        rect: Rectangle {
            alpha_min: -1.0,
            alpha_max: 1.2,
            mu_max_factor: 10.0,
            weight: WeightModel::Centreline,
            blocks: None,
            columns: arg("--alphas", 23),
            samples: 2,
            certify: false,
        },
        mus: vec![0.4, 0.6, 0.8, 1.0, 1.5],
        factors: arg("--factors", 12),
        factor_max: 4.0,
    };
    let cores = threads::available();
    let start = Instant::now();
    let map = load_map(&grid, &Settings::default(), cores, &|_, _| {}).unwrap();
    println!("| mu | cells answered | undecided | with a reduction | largest reduction | at alpha, eta | semicircle's largest |");
    println!("|---:|---:|---:|---:|---:|---|---:|");
    for &mu in &grid.mus {
        let answered = map.at(mu).filter(|c| c.reduction().is_some()).count();
        let undecided = map
            .at(mu)
            .filter(|c| matches!(c.answer, CellAnswer::Undecided(_)))
            .count();
        let best = map.largest(mu);
        println!(
            "| {mu} | {answered} | {undecided} | {} | {} | {} | {:.3e} |",
            map.at(mu).filter(|c| c.reduced()).count(),
            best.map_or("-".into(), |c| format!("{:.4}", c.reduction().unwrap())),
            best.map_or("-".into(), |c| format!(
                "{:.3}, {:.4}",
                c.alpha,
                c.eta.unwrap()
            )),
            map.semicircle(mu).unwrap_or(f64::NAN)
        );
    }
    let mut top: Vec<_> = map.cells.iter().filter(|c| c.reduced()).collect();
    top.sort_by(|a, b| b.reduction().unwrap().total_cmp(&a.reduction().unwrap()));
    println!("\nthe largest reductions:\n");
    println!("| mu | alpha | eta | lambda_static | lambda_c | reduction | least limit state |");
    println!("|---:|---:|---:|---:|---:|---:|---|");
    for c in top.iter().take(12) {
        let Some((lambda_static, lambda_c, mode)) = c.ratio() else {
            continue;
        };
        println!(
            "| {} | {:.4} | {:.5} | {lambda_static:.6} | {lambda_c:.6} | {:.4} | {} |",
            c.mu,
            c.alpha,
            c.eta.unwrap(),
            c.reduction().unwrap(),
            mode.name()
        );
    }
    eprintln!("{:.1} s on {cores} threads", start.elapsed().as_secs_f64());
}
