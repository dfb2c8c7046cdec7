//! Speed against error: for several openings and friction coefficients (one on every
//! branch, and within 1e-6 of every corner), the wall time and the error |η − η_ref| of
//!
//! * a dense fixed-grid LP with n joints (η* by bisection to 1e-13; n = 16 … 65 536),
//! * the constraint-generation LP over the continuum (η* by bisection, no fixed grid),
//! * the exact pattern solve (`arch_enum::solve`),
//!
//! where η_ref is the midpoint of a verified certificate (relative gap ≤ 1e-12); the
//! error printed is |η − η_ref| + half the certified gap, an upper bound of the true error.
//! Also: the cost of the exact solve on discrete arches of N = 10 … 10⁴ voussoirs.
//! Prints Markdown tables and writes `speed_vs_error.svg` (time against error).
//!
//! `cargo run --release --example speed_vs_error [-- OUT.svg]`

use arch_enum::admissibility::{margin_over_arch, Goal, WorkingSet};
use arch_enum::certificate::certify;
use arch_enum::limit_curve::trace;
use arch_enum::statics::{actions, Affine};
use arch_enum::{solve, Arch, CollapseMode, ContactKind, Outcome, Settings, WeightModel};
use plotters::prelude::*;
use std::f64::consts::PI;
use std::time::Instant;

/// Median wall time (seconds) of `reps` runs, and the last result.
fn time<T>(reps: usize, mut f: impl FnMut() -> T) -> (f64, T) {
    let mut times = Vec::new();
    let mut out = None;
    for _ in 0..reps {
        let t = Instant::now();
        out = Some(f());
        times.push(t.elapsed().as_secs_f64());
    }
    times.sort_by(f64::total_cmp);
    (times[times.len() / 2], out.unwrap())
}

fn grid_eta(arch: &Arch, mu: f64, n: usize) -> f64 {
    let (a, b) = (arch.beta_right(), arch.beta_left());
    let joints: Vec<f64> = (0..=n).map(|i| a + (b - a) * i as f64 / n as f64).collect();
    let feasible = |eta: f64| {
        let rows: Vec<Affine> = joints
            .iter()
            .flat_map(|&beta| {
                let act = actions(arch, eta, beta);
                ContactKind::active_at(mu)
                    .iter()
                    .map(move |&m| act.activation(m, 0, eta, mu))
            })
            .collect();
        arch_enum::lp::dense::max_margin(&rows, arch.span(), 1e-13)
            .or_else(|_| arch_enum::lp::highs::max_margin(&rows, arch.span(), 1e-10))
            .is_ok_and(|(_, s)| s >= 0.0)
    };
    let (mut lo, mut hi) = (0.0, 1.999);
    while hi - lo > 1e-13 * hi {
        let mid = 0.5 * (lo + hi);
        if feasible(mid) {
            hi = mid;
        } else {
            lo = mid;
        }
    }
    hi
}

fn cg_eta(arch: &Arch, mu: f64, s: &Settings) -> f64 {
    let mut ws = WorkingSet::initial(arch);
    let (mut lo, mut hi) = (0.0, 1.999);
    while hi - lo > 1e-13 * hi {
        let mid = 0.5 * (lo + hi);
        let m = margin_over_arch(
            arch,
            mid,
            mu,
            ContactKind::active_at(mu),
            &mut ws,
            Goal::Decide,
            s,
        )
        .unwrap();
        if m.margin >= 0.0 {
            hi = mid;
        } else {
            lo = mid;
        }
    }
    hi
}

fn main() {
    let out = std::env::args()
        .nth(1)
        .unwrap_or_else(|| "speed_vs_error.svg".into());
    let s = Settings::default();
    let grids = [16usize, 64, 256, 1024, 4096, 16384, 65536];
    let mut points: Vec<(String, f64, f64)> = Vec::new(); // (method, seconds, error)
    println!("| α | μ | where | η_ref (certified) | method | time | error bound |");
    println!("|---:|---:|:---|---:|:---|---:|---:|");
    for alpha in [-PI / 6.0, 0.0, 1.0, 1.15] {
        let arch = Arch::symmetric(alpha, WeightModel::Centreline).unwrap();
        let curve = trace(&arch, &s);
        let mut cases: Vec<(f64, String)> = Vec::new();
        for b in curve
            .branches
            .iter()
            .filter(|b| b.mode != CollapseMode::PurelySliding)
        {
            let mu = if b.mu_max.is_finite() {
                (b.mu_min * b.mu_max).sqrt()
            } else {
                2.0 * b.mu_min
            };
            cases.push((mu, format!("on {}", b.mode.name())));
        }
        for c in curve.corners.iter().filter(|c| c.mu.is_finite()) {
            cases.push((c.mu * (1.0 + 1e-6), format!("corner μ={:.6} +1e-6", c.mu)));
        }
        for (mu, place) in cases {
            let Ok(cert) = certify(&arch, mu, 1e-12, &s) else {
                continue;
            };
            let (hi, lo) = (
                cert.safe.as_ref().unwrap().eta,
                cert.collapse.as_ref().unwrap().eta.unwrap(),
            );
            let eta_ref = 0.5 * (hi + lo);
            let half_gap = 0.5 * (hi - lo);
            let (t, sol) = time(5, || solve(&arch, mu, &s).unwrap());
            let Outcome::Limit(ls) = sol.outcome else {
                continue;
            };
            let mut row = |method: &str, t: f64, eta: f64| {
                // an upper bound of the true error: η* is only known to ± half the gap
                let err = (eta - eta_ref).abs() + half_gap;
                println!("| {alpha:.4} | {mu:.6} | {place} | {eta_ref:.13} | {method} | {:.3} ms | {err:.1e} |", t * 1e3);
                points.push((
                    method.split(' ').next().unwrap().to_string(),
                    t,
                    err.max(1e-17),
                ));
            };
            row("exact pattern solve", t, ls.eta);
            let (t, e) = time(1, || cg_eta(&arch, mu, &s));
            row("constraint-generation LP", t, e);
            for n in grids {
                let (t, e) = time(1, || grid_eta(&arch, mu, n));
                row(&format!("grid n={n}"), t, e);
            }
        }
    }
    println!("\n| N voussoirs (α = 0, μ = 0.35) | exact solve | η* |");
    println!("|---:|---:|---:|");
    let arch = Arch::symmetric(0.0, WeightModel::Centreline).unwrap();
    for n in [10usize, 100, 1000, 10000] {
        let d = arch.clone().with_blocks(n).unwrap();
        let (t, sol) = time(5, || solve(&d, 0.35, &s).unwrap());
        if let Outcome::Limit(ls) = sol.outcome {
            println!("| {n} | {:.3} ms | {:.12} |", t * 1e3, ls.eta);
        }
    }
    // the plot: time against error, one colour per method family
    let mut svg = String::new();
    {
        let root = SVGBackend::with_string(&mut svg, (900, 600)).into_drawing_area();
        root.fill(&WHITE).unwrap();
        let mut ch = ChartBuilder::on(&root)
            .caption(
                "Speed against error (α ∈ {−π/6, 0, 1, 1.15}, μ on every branch and near corners)",
                ("DejaVu Sans", 16),
            )
            .margin(16)
            .x_label_area_size(50)
            .y_label_area_size(70)
            .build_cartesian_2d((1e-17f64..1.0).log_scale(), (1e-5f64..100.0).log_scale())
            .unwrap();
        ch.configure_mesh()
            .x_desc("error |η − η_ref| (η_ref certified to 1e-12 relative)")
            .y_desc("wall time [s]")
            .x_label_formatter(&|v| format!("{v:.0e}"))
            .y_label_formatter(&|v| format!("{v:.0e}"))
            .draw()
            .unwrap();
        for (name, color) in [
            ("exact", RGBColor(31, 119, 180)),
            ("constraint-generation", RGBColor(44, 160, 44)),
            ("grid", RGBColor(214, 39, 40)),
        ] {
            ch.draw_series(
                points
                    .iter()
                    .filter(|p| p.0 == name)
                    .map(|p| Circle::new((p.2, p.1), 4, color.filled())),
            )
            .unwrap()
            .label(if name == "grid" {
                "dense grid LP, n = 16 … 65 536"
            } else {
                name
            })
            .legend(move |(x, y)| Circle::new((x + 8, y), 4, color.filled()));
        }
        ch.configure_series_labels()
            .border_style(BLACK)
            .background_style(WHITE)
            .draw()
            .unwrap();
        root.present().unwrap();
    }
    std::fs::write(&out, &svg).expect("write the plot");
    let png = out.trim_end_matches(".svg").to_string() + ".png";
    std::fs::write(
        &png,
        arch_enum::render::plot::svg_to_png(&svg, 900).expect("png"),
    )
    .expect("write the png");
    eprintln!("wrote {out} and {png}");
}
