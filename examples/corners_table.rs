//! Prints, as a Markdown table in the layout of a paper's results table, the corners
//! of the η–μ limit curve for a list of symmetric openings α_s (radians):
//!
//! ```sh
//! cargo run --release --example corners_table                 # the default list
//! cargo run --release --example corners_table -- 0 0.5 1.0    # openings of your choice
//! ```
//!
//! Columns: α_s, the corner's μ and friction angle φ = atan μ (degrees), η, the intrados
//! hinge β_N and the sliding joint β_T in the right half (radians, from the horizontal),
//! and the two modes the corner separates.

use arch_enum::limit_curve::trace;
use arch_enum::render::table::right_half_angle;
use arch_enum::{Arch, ContactKind, Settings, WeightModel};
use std::f64::consts::PI;

fn main() {
    let args: Vec<f64> = std::env::args()
        .skip(1)
        .map(|a| a.parse().expect("openings in radians"))
        .collect();
    let openings = if args.is_empty() {
        vec![-1.2, -PI / 6.0, -0.3, 0.0, PI / 6.0, 0.8, 1.0, 1.1, 1.15]
    } else {
        args
    };
    let settings = Settings::default();
    println!("| α_s | μ | φ [°] | η | β_N | β_T | between |");
    println!("|---:|---:|---:|---:|---:|---:|:---|");
    for alpha in openings {
        let arch = match Arch::symmetric(alpha, WeightModel::Centreline) {
            Ok(a) => a,
            Err(e) => {
                eprintln!("skipping {alpha}: {e}");
                continue;
            }
        };
        let curve = trace(&arch, &settings);
        for c in &curve.corners {
            let f = |v: Option<f64>| v.map_or("–".to_string(), |b| format!("{b:.8}"));
            let (mu, phi) = if c.mu.is_finite() {
                (
                    format!("{:.8}", c.mu),
                    format!("{:.4}", c.mu.atan().to_degrees()),
                )
            } else {
                ("∞".to_string(), "90".to_string())
            };
            println!(
                "| {alpha:.6} | {mu} | {phi} | {:.8} | {} | {} | {} / {}{} |",
                c.eta,
                f(right_half_angle(&arch, &c.joints, |j| j.kind == ContactKind::HingeIntrados)),
                f(right_half_angle(&arch, &c.joints, |j| !j.kind.is_hinge())),
                c.between[0].name(),
                c.between[1].name(),
                if c.exact { "" } else { " (bracketed only)" }
            );
        }
    }
}
