//! η*(μ) sampled over a range of friction coefficients (the `curve` command).

use crate::arch::{Arch, InputError};
use crate::limit::{solve, Outcome};
use crate::settings::Settings;
use std::sync::atomic::{AtomicUsize, Ordering};

/// One sample of the limit curve.
#[derive(Debug, Clone)]
pub struct CurvePoint {
    /// Friction coefficient μ.
    pub mu: f64,
    /// What the solver found there.
    pub outcome: Outcome,
}

/// Checks the ends of a μ range, either of which may be left to a default: each in
/// 0 < μ ≤ [`crate::arch::MU_MAX_FINITE`], and `mu_max ≥ mu_min` when both are given.
pub fn check_mu_range(mu_min: Option<f64>, mu_max: Option<f64>) -> Result<(), InputError> {
    let top = crate::arch::MU_MAX_FINITE;
    if let Some(lo) = mu_min.filter(|&lo| !(lo > 0.0 && lo <= top)) {
        return Err(InputError::OutOfRange {
            arg: "--mu-min",
            value: crate::arch::fmt_value(lo),
            range: format!("0 < mu-min <= {top:e}"),
        });
    }
    let floor = mu_min.unwrap_or(0.0);
    if let Some(hi) = mu_max.filter(|&hi| !(hi > 0.0 && hi >= floor && hi <= top)) {
        let range = match mu_min {
            Some(lo) => format!("mu-min ({lo}) <= mu-max <= {top:e}"),
            None => format!("0 < mu-max <= {top:e}"),
        };
        return Err(InputError::OutOfRange {
            arg: "--mu-max",
            value: crate::arch::fmt_value(hi),
            range,
        });
    }
    Ok(())
}

/// `points` friction coefficients from `mu_min` to `mu_max`, geometrically spaced
/// (0 < mu_min ≤ mu_max ≤ 1e200, points ≥ 1; one point when mu_min = mu_max).
pub fn mu_grid(mu_min: f64, mu_max: f64, points: usize) -> Result<Vec<f64>, InputError> {
    check_mu_range(Some(mu_min), Some(mu_max))?;
    if points == 0 || points > 100_000 {
        return Err(InputError::OutOfRange {
            arg: "--points",
            value: points.to_string(),
            range: "whole numbers 1 to 100000".into(),
        });
    }
    if points == 1 {
        return Ok(vec![mu_min]);
    }
    let r = (mu_max / mu_min).ln();
    Ok((0..points)
        .map(|i| {
            if i + 1 == points {
                mu_max
            } else {
                mu_min * (r * i as f64 / (points - 1) as f64).exp()
            }
        })
        .collect())
}

/// Solves η*(μ) at every μ of `mus` on `threads` threads (each solve is independent and
/// deterministic, so the answer does not depend on the count; 0 is taken as 1);
/// `progress(done, total)` is called after each, from whichever thread finished it. A bad μ
/// is reported as the first one in `mus` order.
pub fn sample(
    arch: &Arch,
    mus: &[f64],
    settings: &Settings,
    threads: usize,
    progress: &(dyn Fn(usize, usize) + Sync),
) -> Result<Vec<CurvePoint>, InputError> {
    let done = AtomicUsize::new(0);
    crate::threads::map(mus, threads, |_, &mu| {
        let point = solve(arch, mu, settings).map(|s| CurvePoint {
            mu,
            outcome: s.outcome,
        });
        progress(done.fetch_add(1, Ordering::Relaxed) + 1, mus.len());
        point
    })
    .into_iter()
    .collect()
}
