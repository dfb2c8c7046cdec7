//! η*(μ) under perturbed solver settings (scan density, bracket width, candidate
//! threshold): the refined value must not move. Prints the largest relative spread.
//!
//! `cargo run --release --example settings_stability`
use arch_enum::{solve, Arch, Outcome, Settings, WeightModel};

fn main() {
    let variants: Vec<(&str, Settings)> = vec![
        ("default", Settings::default()),
        (
            "scan_points 48",
            Settings {
                scan_points: 48,
                ..Settings::default()
            },
        ),
        (
            "scan_points 400",
            Settings {
                scan_points: 400,
                ..Settings::default()
            },
        ),
        (
            "bracket_rel 1e-6",
            Settings {
                bracket_rel: 1e-6,
                ..Settings::default()
            },
        ),
        (
            "candidate_rel 1e-3",
            Settings {
                candidate_rel: 1e-3,
                ..Settings::default()
            },
        ),
    ];
    println!(
        "| alpha | mu | eta* (default) | max relative spread over {} settings |",
        variants.len()
    );
    println!("|---:|---:|---:|---:|");
    for alpha in [-1.2, -0.3, 0.0, 0.5, 1.0, 1.15] {
        for mu in [f64::INFINITY, 3.0, 1.2, 0.5, 0.35] {
            let arch = Arch::symmetric(alpha, WeightModel::Centreline).unwrap();
            let etas: Vec<f64> = variants
                .iter()
                .filter_map(|(_, s)| match solve(&arch, mu, s).unwrap().outcome {
                    Outcome::Limit(ls) => Some(ls.eta),
                    _ => None,
                })
                .collect();
            if etas.len() < variants.len() {
                if !etas.is_empty() {
                    println!(
                        "| {alpha} | {mu} | – | solved by only {} of {} settings |",
                        etas.len(),
                        variants.len()
                    );
                }
                continue;
            }
            let (lo, hi) = etas
                .iter()
                .fold((f64::INFINITY, 0.0f64), |(a, b), &e| (a.min(e), b.max(e)));
            println!(
                "| {alpha} | {mu} | {:.15} | {:.1e} |",
                etas[0],
                (hi - lo) / etas[0]
            );
        }
    }
}
