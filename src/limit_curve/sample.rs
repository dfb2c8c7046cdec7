//! η*(μ) sampled over a range of friction coefficients (the `curve` command).

use crate::arch::{Arch, InputError};
use crate::limit::{solve, Outcome};
use crate::settings::Settings;

/// One sample of the limit curve.
#[derive(Debug, Clone)]
pub struct CurvePoint {
    /// Friction coefficient μ.
    pub mu: f64,
    /// What the solver found there.
    pub outcome: Outcome,
}

/// `points` friction coefficients from `mu_min` to `mu_max`, geometrically spaced
/// (0 < mu_min ≤ mu_max < ∞, points ≥ 1; one point when mu_min = mu_max).
pub fn mu_grid(mu_min: f64, mu_max: f64, points: usize) -> Result<Vec<f64>, InputError> {
    if !(mu_min.is_finite() && mu_min > 0.0) {
        return Err(InputError::OutOfRange {
            arg: "--mu-min",
            value: crate::arch::fmt_value(mu_min),
            range: "0 < mu-min < inf".into(),
        });
    }
    if !(mu_max.is_finite() && mu_max >= mu_min) {
        return Err(InputError::OutOfRange {
            arg: "--mu-max",
            value: crate::arch::fmt_value(mu_max),
            range: format!("mu-min ({mu_min}) <= mu-max < inf"),
        });
    }
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

/// Solves η*(μ) at every μ of `mus`; `progress(done, total)` is called after each.
pub fn sample(
    arch: &Arch,
    mus: &[f64],
    settings: &Settings,
    progress: &dyn Fn(usize, usize),
) -> Result<Vec<CurvePoint>, InputError> {
    mus.iter()
        .enumerate()
        .map(|(i, &mu)| {
            let outcome = solve(arch, mu, settings)?.outcome;
            progress(i + 1, mus.len());
            Ok(CurvePoint { mu, outcome })
        })
        .collect()
}
