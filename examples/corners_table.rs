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
use arch_enum::render::table::{corner_rows, CORNER_HEADER};
use arch_enum::{Arch, Settings, WeightModel};
use std::f64::consts::PI;

fn main() {
    let args: Vec<f64> = std::env::args()
        .skip(1)
        .map(|a| a.parse().expect("openings in radians"))
        .collect();
    let openings = if args.is_empty() {
        vec![
            -1.2,
            -PI / 6.0,
            -0.3,
            0.0,
            PI / 6.0,
            0.8,
            1.0,
            1.05,
            1.1,
            1.15,
        ]
    } else {
        args
    };
    let settings = Settings::default();
    println!("{CORNER_HEADER}");
    for alpha in openings {
        let arch = match Arch::symmetric(alpha, WeightModel::Centreline) {
            Ok(a) => a,
            Err(e) => {
                eprintln!("skipping {alpha}: {e}");
                continue;
            }
        };
        let curve = trace(&arch, &settings);
        for row in corner_rows(&arch, &curve) {
            println!("{row}");
        }
    }
}
