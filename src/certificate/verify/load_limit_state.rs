//! The floating-point consistency checks of a limit state listed under a live load
//! (evidence, not proof): admissible at every joint, or at samples of each piece of a
//! continuous arch; the pattern active, one sliding sense per section; B λ̇ = 0, λ̇ ≥ 0,
//! Σ λ̇ = 1, total power ≥ 0 and live power > 0.

use super::joints::check_pattern;
use super::limit_state::LIMIT_STATE_TOL;
use super::live::{sections, side_text, Live};
use super::mechanism::{column, weight_work, StateAt};
use super::report::{reject, Rejection};
use super::statics::{kinds, phi, Model};
use crate::certificate::format::{ContactKind, LoadLimitStateCert, Side};
use crate::certificate::interval::Interval as I;

/// Samples per piece of a continuous arch for the floating-point admissibility check of a
/// listed limit state.
const SAMPLES: usize = 2000;

/// The state at λ under the live load, at the load's thickness.
pub(super) fn state_at(live: &Live, lambda: f64, x: [f64; 3]) -> StateAt<'_> {
    StateAt {
        x,
        eta: live.eta,
        load: Some((live, lambda)),
    }
}

/// The floating-point consistency checks of a listed limit state under the load.
pub(super) fn check_limit_state(
    model: &Model,
    live: &Live,
    mu: Option<f64>,
    ls: &LoadLimitStateCert,
    whose: &str,
) -> Result<(), Rejection> {
    let tol = LIMIT_STATE_TOL;
    let finite = ls.lambda.is_finite()
        && ls.lambda >= 0.0
        && ls.live_power.is_finite()
        && ls.x.iter().all(|v| v.is_finite())
        && ls.rates.iter().all(|v| v.is_finite())
        && ls.pattern.iter().all(|j| j.beta.is_finite())
        && ls
            .continuum
            .as_ref()
            .is_none_or(|c| c.to.is_none_or(|t| t.is_finite() && t >= ls.lambda));
    if !finite {
        return reject(format!(
            "{whose}: every number must be finite, lambda >= 0 and a continuum's end not below it"
        ));
    }
    check_pattern(model, &ls.pattern, mu, live.split(), whose)?;
    if ls.rates.len() != ls.pattern.len() || ls.rates.iter().any(|&r| r < 0.0) {
        return reject(format!(
            "{whose}: rates must be one non-negative number per pattern joint"
        ));
    }
    if (ls.rates.iter().sum::<f64>() - 1.0).abs() > tol {
        return reject(format!("{whose}: rates do not sum to 1"));
    }
    let state = state_at(live, ls.lambda, ls.x);
    check_active(model, live, mu, ls, state, whose)?;
    check_admissible(model, live, mu, ls, state, whose)?;
    check_mechanism(model, live, ls, whose)
}

/// The pattern is active at the state; one sliding sense per section.
fn check_active(
    model: &Model,
    live: &Live,
    mu: Option<f64>,
    ls: &LoadLimitStateCert,
    state: StateAt,
    whose: &str,
) -> Result<(), Rejection> {
    let tol = LIMIT_STATE_TOL;
    let scale = 1.0 + ls.x.iter().map(|v| v.abs()).sum::<f64>();
    for (i, j) in ls.pattern.iter().enumerate() {
        let v = phi(j.kind, 0, &state.ntm(model, j.beta, j.side), live.eta, mu).mid();
        if v.is_nan() || v.abs() > tol * scale {
            return reject(format!(
                "{whose}: {} at beta = {}{} is not active (phi = {v:e})",
                j.kind.name(),
                j.beta,
                side_text(j.side)
            ));
        }
        let both = ls.pattern.iter().enumerate().any(|(k, o)| {
            k != i
                && o.beta == j.beta
                && o.side == j.side
                && j.kind == ContactKind::SlidePlus
                && o.kind == ContactKind::SlideMinus
                && ls.rates[i] > 0.0
                && ls.rates[k] > 0.0
        });
        if both {
            return reject(format!(
                "{whose}: the section at beta = {} slides both ways at once",
                j.beta
            ));
        }
    }
    Ok(())
}

/// The state admissible at every joint, or at [`SAMPLES`] angles of each piece of a
/// continuous arch (both sides of a loaded section).
fn check_admissible(
    model: &Model,
    live: &Live,
    mu: Option<f64>,
    ls: &LoadLimitStateCert,
    state: StateAt,
    whose: &str,
) -> Result<(), Rejection> {
    let tol = LIMIT_STATE_TOL;
    let scale = 1.0 + ls.x.iter().map(|v| v.abs()).sum::<f64>();
    let angles: Vec<(f64, Option<Side>)> = match &model.joints {
        Some(js) => js
            .iter()
            .flat_map(|&b| sections(b, live.split()).into_iter().map(move |s| (b, s)))
            .collect(),
        None => live
            .pieces(model)
            .into_iter()
            .flat_map(|(a, b, carries)| {
                (0..=SAMPLES).map(move |i| {
                    let beta = if i == SAMPLES {
                        b
                    } else {
                        a + (b - a) * i as f64 / SAMPLES as f64
                    };
                    // at the loaded angle, the piece's own side of the section
                    let side = (live.split() == Some(beta)).then_some(if carries {
                        Side::After
                    } else {
                        Side::Before
                    });
                    (beta, side)
                })
            })
            .collect(),
    };
    for &(b, side) in &angles {
        let a = state.ntm(model, b, side);
        for &k in kinds(mu) {
            let v = phi(k, 0, &a, live.eta, mu).mid();
            if v.is_nan() || v > tol * scale {
                return reject(format!(
                    "{whose}: not admissible, {} = {v:e} > 0 at beta = {b}{}",
                    k.name(),
                    side_text(side)
                ));
            }
        }
    }
    Ok(())
}

/// The mechanism of the rates: B λ̇ = 0, total power ≥ 0, live power > 0 (and as stated).
fn check_mechanism(
    model: &Model,
    live: &Live,
    ls: &LoadLimitStateCert,
    whose: &str,
) -> Result<(), Rejection> {
    let tol = LIMIT_STATE_TOL;
    let kept: Vec<(f64, ContactKind, Option<Side>)> = ls
        .pattern
        .iter()
        .map(|j| (j.beta, j.kind, j.side))
        .collect();
    let columns: Vec<[I; 3]> = kept
        .iter()
        .map(|&(b, k, _)| column(k, b, live.eta))
        .collect();
    let work = weight_work(model, live.eta, &kept, &columns);
    let q = live.power(model, &kept, &columns);
    let mut b = [0.0; 3];
    let (mut total, mut live_power) = (0.0, 0.0);
    for (i, &r) in ls.rates.iter().enumerate() {
        for k in 0..3 {
            b[k] += r * columns[i][k].mid();
        }
        total += r * (-work[i].mid() + ls.lambda * q[i].mid());
        live_power += r * q[i].mid();
    }
    if b.iter().any(|v| v.abs() > tol) {
        return reject(format!("{whose}: B lambda = {b:?} is not zero"));
    }
    if total < -tol {
        return reject(format!(
            "{whose}: total external power {total:e} is negative"
        ));
    }
    if live_power <= 0.0 || (live_power - ls.live_power).abs() > tol * (1.0 + live_power.abs()) {
        return reject(format!(
            "{whose}: the live power of the rates is {live_power:e}, stated {:e} (must be positive and equal)",
            ls.live_power
        ));
    }
    Ok(())
}
