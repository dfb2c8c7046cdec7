//! η*(μ) sampled over a range of friction coefficients (the `curve` command).

use crate::arch::{Arch, InputError};
use crate::limit::{solve_continued, solve_near, Outcome};
use crate::search::RootGuess;
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

/// Consecutive friction coefficients of [`sample`] solved in one chain, each bracket of η_s
/// started from the previous answer (a fixed length, so the answers do not depend on the
/// number of threads).
const CHAIN: usize = 16;
/// The expected relative distance of the first guess of a chain from its root; later
/// guesses expect twice the last step of η_s.
const CHAIN_GUESS_REL: (f64, f64, f64) = (1e-2, 1e-9, 0.25);

/// Solves η*(μ) at every μ of `mus` on `threads` threads (0 is taken as 1), in chains of
/// `CHAIN` consecutive values, each started from the previous answer ([`solve_near`]: the
/// same algorithm and root as [`crate::solve`], fewer margin LPs); `progress(done, total)`
/// is called after each, from whichever thread finished it. A bad μ is reported as the
/// first one in `mus` order.
pub fn sample(
    arch: &Arch,
    mus: &[f64],
    settings: &Settings,
    threads: usize,
    progress: &(dyn Fn(usize, usize) + Sync),
) -> Result<Vec<CurvePoint>, InputError> {
    let done = AtomicUsize::new(0);
    let chains: Vec<&[f64]> = mus.chunks(CHAIN).collect();
    let (first, least, most) = CHAIN_GUESS_REL;
    let solved = crate::threads::map(&chains, threads, |_, chain| {
        let (mut guess, mut last) = (None, None::<f64>);
        let mut prior = None;
        let mut points = Vec::with_capacity(chain.len());
        for &mu in chain.iter() {
            let solved = match (guess, &prior) {
                (Some(g), Some(p)) => solve_continued(arch, mu, g, p, settings),
                _ => solve_near(arch, mu, guess, settings),
            };
            prior = solved.as_ref().ok().and_then(|s| match &s.outcome {
                Outcome::Limit(ls) => Some(ls.clone()),
                _ => None,
            });
            let point = solved.map(|s| CurvePoint {
                mu,
                outcome: s.outcome,
            });
            let eta = point.as_ref().ok().and_then(|p| least_static(&p.outcome));
            guess = eta.map(|e| RootGuess {
                eta: e,
                rel: last.map_or(first, |l| (2.0 * (e - l).abs() / e).clamp(least, most)),
            });
            last = eta;
            progress(done.fetch_add(1, Ordering::Relaxed) + 1, mus.len());
            points.push(point);
        }
        points
    });
    solved.into_iter().flatten().collect()
}

/// The least statically admissible η of an outcome, where it has one.
fn least_static(o: &Outcome) -> Option<f64> {
    match o {
        Outcome::Limit(ls) => Some(ls.eta_static),
        Outcome::Unresolved {
            least_static: Some((eta, _)),
            ..
        } => Some(*eta),
        _ => None,
    }
}
