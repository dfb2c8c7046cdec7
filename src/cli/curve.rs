//! `arch-enum curve`: η*(μ) sampled over a range of friction coefficients.

use super::arch_args::ArchArgs;
use super::bridge_args::ArchFillArgs;
use super::io::{to_json, Exit, Io};
use super::threads_arg::ThreadsArg;
use crate::arch::InputError;
use crate::friction::least_friction;
use crate::limit_curve::{check_mu_range, mu_grid, sample};
use crate::render::{json, table};
use crate::settings::Settings;
use clap::Args;

#[derive(Args, Debug)]
pub(crate) struct CurveArgs {
    #[command(flatten)]
    arch: ArchArgs,
    #[command(flatten)]
    fill: ArchFillArgs,
    /// Smallest mu (default: mu_ms (1 + 1e-6), just above the least friction admitting
    /// equilibrium; with fill, where mu_ms depends on eta, it must be given).
    #[arg(long, allow_hyphen_values = true)]
    mu_min: Option<f64>,
    /// Largest mu (default: 10 * mu_min).
    #[arg(long, allow_hyphen_values = true)]
    mu_max: Option<f64>,
    /// Number of samples (1 to 100000).
    #[arg(long, default_value_t = 20, allow_hyphen_values = true)]
    points: usize,
    #[command(flatten)]
    threads: ThreadsArg,
    /// Print one JSON document instead of tables.
    #[arg(long)]
    pub(crate) json: bool,
}

pub(crate) fn run(a: CurveArgs, settings: &Settings, io: &mut Io) -> Exit {
    let built = if a.fill.given() {
        a.fill.build(&a.arch)
    } else {
        a.arch.build_without_ring().map(|arch| (arch, None))
    };
    let (arch, fill) = match built {
        Ok(b) => b,
        Err(e) => return io.bad_input(&e),
    };
    if let Err(e) = check_mu_range(a.mu_min, a.mu_max) {
        return io.bad_input(&e);
    }
    if fill.is_some() && a.mu_min.is_none() {
        return io.bad_input(&InputError::Inconsistent {
            arg: "--mu-min",
            reason: "with fill the least friction is a curve mu_ms(eta), not one number: give the range's --mu-min".into(),
        });
    }
    let mu_ms = least_friction(&arch, settings).ok().flatten();
    let lo = a
        .mu_min
        .unwrap_or_else(|| mu_ms.map_or(0.01, |m| (m * (1.0 + 1e-6)).max(1e-6)));
    let hi = a.mu_max.unwrap_or(10.0 * lo);
    let grid = match mu_grid(lo, hi, a.points) {
        Ok(g) => g,
        Err(e) => return io.bad_input(&e),
    };
    let threads = match a.threads.count() {
        Ok(t) => t,
        Err(e) => return io.bad_input(&e),
    };
    let bar = super::progress::Progress::new("curve");
    let pts = match sample(&arch, &grid, settings, threads, &|done, total| {
        bar.update(done, total)
    }) {
        Ok(p) => p,
        Err(e) => return io.bad_input(&e),
    };
    if a.json {
        let mut doc = json::curve(&arch, mu_ms, &pts);
        doc.fill = fill;
        io.out(&to_json(&doc));
    } else {
        io.out(&table::curve(&arch, mu_ms, fill.as_ref(), &pts));
    }
    Exit::Answered
}
