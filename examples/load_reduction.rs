//! Where non-associative friction lowers the collapse acceleration below the static maximum:
//! the ratio λ_c/λ_static of a horizontal body force (towards the right springing) on
//! continuous symmetric arches, centreline weight, over a grid of openings α and
//! thicknesses η = f η*(α, μ) (f the thickness factor over the arch's own least
//! thickness), at a few friction coefficients. Each cell is `multiplier::survey` (λ_static
//! exact; the limit states below it from two discretisations refined on the continuum).
//!
//! Prints, per μ, the cells answered, those with a reduction (λ_c < λ_static by more than
//! 10⁻⁹ relative), the largest reduction and where, and the semicircle's largest; then the
//! largest reductions with their patterns. A sampled map, not a proof: a reduction window
//! narrower than the grid's spacing is not seen.
//!
//! Run: `cargo run --release --example load_reduction [-- --alphas N --factors M]`.

use arch_enum::load::LiveLoad;
use arch_enum::multiplier::{survey, LoadOutcome};
use arch_enum::{solve, threads, Arch, Outcome, Settings, WeightModel};
use std::time::Instant;

/// One answered cell: (α, η, λ_static, λ_c, the least limit state's mode and pattern).
type Cell = (f64, f64, f64, f64, String);

/// The argument after `name`, or `default`.
fn arg(name: &str, default: usize) -> usize {
    let a: Vec<String> = std::env::args().collect();
    a.iter()
        .position(|x| x == name)
        .and_then(|i| a.get(i + 1))
        .and_then(|v| v.parse().ok())
        .unwrap_or(default)
}

/// The cell at (α, f) and μ: `None` where the arch does not stand or the survey gives no
/// decided λ_c (counted apart).
fn cell(alpha: f64, f: f64, mu: f64, s: &Settings) -> Result<Option<Cell>, String> {
    let arch = Arch::symmetric(alpha, WeightModel::Centreline).map_err(|e| e.to_string())?;
    let eta_star = match solve(&arch, mu, s).map_err(|e| e.to_string())?.outcome {
        Outcome::Limit(ls) => ls.eta_static,
        _ => return Ok(None),
    };
    let eta = f * eta_star;
    if eta >= 1.9 {
        return Ok(None);
    }
    let load = LiveLoad::Horizontal {
        towards_right: true,
    };
    match survey(&arch, eta, mu, &load, s).map_err(|e| e.to_string())? {
        Ok(LoadOutcome::Limits(sv)) => {
            let (Some((ls, _)), Some(lc)) = (sv.lambda_static, sv.lambda()) else {
                return Ok(None);
            };
            let least = &sv.limit_states[0];
            let pattern: Vec<String> = least
                .pattern
                .iter()
                .map(|c| format!("{}@{:.4}", c.kind.name(), c.beta))
                .collect();
            let what = format!("{} {}", least.mode.name(), pattern.join(" "));
            Ok(Some((alpha, eta, ls, lc, what)))
        }
        Ok(_) => Ok(None),
        Err(e) => Err(format!("alpha = {alpha}, eta = {eta}, mu = {mu}: {e}")),
    }
}

fn main() {
    let s = Settings::default();
    let (na, nf) = (arg("--alphas", 23), arg("--factors", 12));
    let mut alphas: Vec<f64> = (0..na)
        .map(|k| -1.0 + 2.2 * k as f64 / (na - 1).max(1) as f64)
        .collect();
    if !alphas.iter().any(|&a| a.abs() < 1e-12) {
        alphas.push(0.0); // the semicircle, always
    }
    // the semicircle exactly (not −1 + 2.2 k/(n − 1) rounded)
    alphas
        .iter_mut()
        .filter(|a| a.abs() < 1e-12)
        .for_each(|a| *a = 0.0);
    let factors: Vec<f64> = (0..nf)
        .map(|k| 1.02 * (4.0f64 / 1.02).powf(k as f64 / (nf - 1).max(1) as f64))
        .collect();
    let cores = threads::available();
    println!("| mu | cells answered | undecided | with a reduction | largest reduction | at alpha, eta | semicircle's largest |");
    println!("|---:|---:|---:|---:|---:|---|---:|");
    let mut top: Vec<(f64, f64, Cell)> = Vec::new();
    let start = Instant::now();
    for mu in [0.4, 0.6, 0.8, 1.0, 1.5] {
        let grid: Vec<(f64, f64)> = alphas
            .iter()
            .flat_map(|&a| factors.iter().map(move |&f| (a, f)))
            .collect();
        let out = threads::map(&grid, cores, |_, &(a, f)| cell(a, f, mu, &s));
        let undecided = out.iter().filter(|c| c.is_err()).count();
        let cells: Vec<Cell> = out.into_iter().filter_map(|c| c.ok().flatten()).collect();
        let red = |c: &Cell| 1.0 - c.3 / c.2;
        let reducing: Vec<&Cell> = cells.iter().filter(|c| red(c) > 1e-9).collect();
        let best = reducing.iter().max_by(|a, b| red(a).total_cmp(&red(b)));
        let semi = cells
            .iter()
            .filter(|c| c.0 == 0.0)
            .map(red)
            .fold(0.0f64, f64::max);
        println!(
            "| {mu} | {} | {undecided} | {} | {} | {} | {:.3e} |",
            cells.len(),
            reducing.len(),
            best.map_or("-".into(), |c| format!("{:.4}", red(c))),
            best.map_or("-".into(), |c| format!("{:.3}, {:.4}", c.0, c.1)),
            semi
        );
        top.extend(reducing.iter().map(|c| (mu, red(c), (*c).clone())));
    }
    top.sort_by(|a, b| b.1.total_cmp(&a.1));
    println!("\nthe largest reductions:\n");
    println!("| mu | alpha | eta | lambda_static | lambda_c | reduction | least limit state |");
    println!("|---:|---:|---:|---:|---:|---:|---|");
    for (mu, r, c) in top.iter().take(12) {
        println!(
            "| {mu} | {:.4} | {:.5} | {:.6} | {:.6} | {r:.4} | {} |",
            c.0, c.1, c.2, c.3, c.4
        );
    }
    eprintln!("{:.1} s on {cores} threads", start.elapsed().as_secs_f64());
}
