//! Regenerates the gallery into a folder: for α_s ∈ {−π/6, 0, π/6, 1, 1.15} one arch
//! figure per collapse mode present on its limit curve (at the middle of each branch; on
//! the vertical branch at μ_ms, a purely sliding limit state at 1.25 η_ms),
//! the limit curves of all five in one figure, the semicircle's curve with fill, and one
//! margin map; SVG and PNG of each.
//!
//! ```sh
//! cargo run --release --example gallery -- docs/gallery
//! ```

use arch_enum::figures::{self, MapGrid};
use arch_enum::limit_curve::available_threads;
use arch_enum::limit_curve::trace;
use arch_enum::render::{plot::svg_to_png, plot_arch, plot_curve, plot_ecc, plot_map};
use arch_enum::{Arch, CollapseMode, Settings, WeightModel};
use std::f64::consts::PI;
use std::path::Path;

fn save(dir: &Path, name: &str, svg: &str) {
    std::fs::write(dir.join(format!("{name}.svg")), svg).expect("write svg");
    std::fs::write(
        dir.join(format!("{name}.png")),
        svg_to_png(svg, 1000).expect("png"),
    )
    .expect("write png");
    println!("wrote {name}.svg/.png");
}

fn main() {
    let dir = std::env::args().nth(1).unwrap_or_else(|| "gallery".into());
    let dir = Path::new(&dir);
    std::fs::create_dir_all(dir).expect("create the gallery folder");
    let s = Settings::default();
    let openings = [
        ("alpha_-pi_6", -PI / 6.0),
        ("alpha_0", 0.0),
        ("alpha_pi_6", PI / 6.0),
        ("alpha_1", 1.0),
        ("alpha_1.15", 1.15),
    ];
    let mut arches = Vec::new();
    for (name, alpha) in openings {
        let arch = Arch::symmetric(alpha, WeightModel::Centreline).unwrap();
        let curve = trace(&arch, &s);
        for b in &curve.branches {
            // the vertical branch at μ_ms: a purely sliding limit state a quarter above η_ms
            let (mu, eta) = if b.mode == CollapseMode::PurelySliding {
                (b.mu_min, Some(1.25 * b.eta_min))
            } else if b.mu_max.is_finite() {
                ((b.mu_min * b.mu_max).sqrt(), None)
            } else {
                (3.0 * b.mu_min, None)
            };
            match figures::scene(&arch, mu, eta, &s) {
                Ok(scene) => save(
                    dir,
                    &format!("arch_{name}_{}", b.mode.name()),
                    &plot_arch::svg(&scene).expect("arch figure"),
                ),
                Err(e) => eprintln!("{name} {}: {e:?}", b.mode.name()),
            }
        }
        arches.push(arch);
    }
    save(
        dir,
        "curves",
        &plot_curve::svg(&figures::curves(&arches, &s).expect("curves"), false)
            .expect("curve figure"),
    );
    // the semicircle with fill: μ_min(η), the least friction where the curve turns
    let filled = arches[1]
        .clone()
        .with_fill(arch_enum::bridge::Fill::new(0.9, 0.0566).expect("fill"));
    let fill_curve = figures::fill_curve::fill_curve(&filled, &s, available_threads());
    save(
        dir,
        "fill_curve_alpha_0",
        &arch_enum::render::plot_fill_curve::svg(&fill_curve.expect("fill curve"))
            .expect("fill curve figure"),
    );
    save(
        dir,
        "eccentricity_alpha_0_mu_0.35",
        &plot_ecc::svg(&figures::scene(&arches[1], 0.35, None, &s).expect("state"))
            .expect("eccentricity"),
    );
    // Stockdale et al. (2018): 27 voussoirs, point load at the 8th joint, mu = inf
    let (ri, t) = (1.806, 0.1661 * 1.806);
    let stockdale = Arch::symmetric(0.0, WeightModel::Centroid)
        .and_then(|a| a.with_blocks(27))
        .expect("arch");
    let load = arch_enum::load::LiveLoad::Point {
        beta: 8.0 * std::f64::consts::PI / 27.0,
    };
    save(
        dir,
        "load_stockdale",
        &plot_arch::svg_panels(
            &figures::load_scenes(&stockdale, t / (ri + t / 2.0), f64::INFINITY, &load, &s)
                .expect("load scenes"),
        )
        .expect("load figure"),
    );
    // the lambda-mu curve of an unsymmetric six-voussoir arch under a horizontal load
    let six = Arch::new(0.2442, 3.1489, WeightModel::Centreline)
        .and_then(|a| a.with_joints(&[0.2442, 0.8409, 1.2686, 2.0653, 2.3805, 2.7970, 3.1489]))
        .expect("arch");
    let left = arch_enum::load::LiveLoad::Horizontal {
        towards_right: false,
    };
    let mut mus: Vec<f64> = (0..30)
        .map(|i| 0.6 * (2.0f64 / 0.6).powf(i as f64 / 29.0))
        .collect();
    mus.push(f64::INFINITY);
    let traced =
        arch_enum::multiplier::trace(&six, 0.6364, &left, &mus, &s, &|_, _| {}).expect("curve");
    save(
        dir,
        "load_curve",
        &arch_enum::render::plot_load_curve::svg(
            "β_R = 0.244, β_L = 3.149 — horizontal acceleration, η = 0.6364: λ against μ",
            &traced,
        )
        .expect("load curve figure"),
    );
    let grid = MapGrid {
        n_eta: 36,
        n_mu: 48,
        log_eta: false,
    };
    let map = figures::map(&arches[1], grid, available_threads(), &s, &|done, total| {
        if done == total {
            eprintln!("map: {total} cells");
        }
    })
    .expect("map");
    save(
        dir,
        "map_alpha_0",
        &plot_map::svg(&map, false).expect("map figure"),
    );
}
