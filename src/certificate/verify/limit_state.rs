//! The floating-point consistency checks of a listed limit state of either problem
//! (evidence, not proof): the pattern active (one sliding sense per section under a load),
//! B λ̇ = 0, λ̇ ≥ 0, Σ λ̇ = 1, the total external power ≥ 0 and, under a live load, the live
//! power > 0 and as stated; and the state admissible at every joint, or at samples of each
//! piece of a continuous arch (both sides of a loaded section).

use super::joints::check_pattern;
use super::live::{sections, side_text, Span, StateAt};
use super::mechanism::{column, weight_work};
use super::report::{reject, Rejection};
use super::statics::{kinds, phi, Model, LIMIT_STATE_TOL};
use crate::certificate::format::{
    ContactKind, LimitStateCert, LoadLimitStateCert, PatternJoint, Side,
};
use crate::certificate::interval::Interval as I;

/// Samples per piece of a continuous arch for the floating-point admissibility check of a
/// listed limit state.
const SAMPLES: usize = 2000;

/// A listed limit state of either problem: the state, its pattern and mechanism rates, and
/// under a live load the stated live power.
pub(super) struct Listed<'a> {
    /// The state (x at η, and λ under a load).
    pub(super) state: StateAt<'a>,
    /// The active pattern.
    pub(super) pattern: &'a [PatternJoint],
    /// Mechanism rates, one per pattern joint.
    pub(super) rates: &'a [f64],
    /// The stated live power (load certificates).
    pub(super) live_power: f64,
}

impl Listed<'_> {
    /// A limit state of the thickness problem.
    pub(super) fn thickness(ls: &LimitStateCert) -> Listed<'_> {
        Listed {
            state: StateAt::bare(ls.x, ls.eta),
            pattern: &ls.pattern,
            rates: &ls.rates,
            live_power: 0.0,
        }
    }
}

/// The thickness certificate's limit state: η in [η_lo, η_hi] and consistent
/// ([`check_listed`]).
pub(super) fn check_limit_state(
    model: &Model,
    mu: Option<f64>,
    ls: &LimitStateCert,
    eta_lo: f64,
    eta_hi: f64,
) -> Result<(), Rejection> {
    if !(ls.eta >= eta_lo && ls.eta <= eta_hi) {
        return reject(format!(
            "limit state: eta = {} outside [eta_lo, eta_hi]",
            ls.eta
        ));
    }
    check_listed(model, mu, &Listed::thickness(ls), "limit state")
}

/// A limit state listed under the load: finite, its pattern valid, consistent and
/// admissible.
pub(super) fn check_load_limit_state(
    model: &Model,
    state: StateAt,
    mu: Option<f64>,
    ls: &LoadLimitStateCert,
    whose: &str,
) -> Result<(), Rejection> {
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
    check_pattern(model, &ls.pattern, mu, state.splits(), whose)?;
    let listed = Listed {
        state,
        pattern: &ls.pattern,
        rates: &ls.rates,
        live_power: ls.live_power,
    };
    check_listed(model, mu, &listed, whose)?;
    check_admissible(model, mu, state, whose)
}

/// The rates one non-negative number per pattern joint summing to 1, the pattern active
/// (one sliding sense per section under a load), and the mechanism of the rates.
pub(super) fn check_listed(
    model: &Model,
    mu: Option<f64>,
    ls: &Listed,
    whose: &str,
) -> Result<(), Rejection> {
    if ls.rates.len() != ls.pattern.len() || ls.rates.iter().any(|&r| r < 0.0) {
        return reject(format!(
            "{whose}: rates must be one non-negative number per pattern joint"
        ));
    }
    if (ls.rates.iter().sum::<f64>() - 1.0).abs() > LIMIT_STATE_TOL {
        return reject(format!("{whose}: rates do not sum to 1"));
    }
    check_active(model, mu, ls, whose)?;
    check_mechanism(model, ls, whose)
}

/// The pattern is active at the state; under a load, one sliding sense per section.
fn check_active(model: &Model, mu: Option<f64>, ls: &Listed, whose: &str) -> Result<(), Rejection> {
    let state = ls.state;
    for (i, j) in ls.pattern.iter().enumerate() {
        let v = phi(j.kind, 0, &state.ntm(model, j.beta, j.side), state.eta, mu).mid();
        if v.is_nan() || v.abs() > LIMIT_STATE_TOL * state.scale() {
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
        if both && state.load.is_some() {
            return reject(format!(
                "{whose}: the section at beta = {} slides both ways at once",
                j.beta
            ));
        }
    }
    Ok(())
}

/// The state admissible at every joint, or at [`SAMPLES`] angles of each piece of a
/// continuous arch (the whole arch without a load; both sides of a loaded section).
pub(super) fn check_admissible(
    model: &Model,
    mu: Option<f64>,
    state: StateAt,
    whose: &str,
) -> Result<(), Rejection> {
    let splits = state.splits();
    let whole = [Span::whole(model)];
    let pieces = match state.live() {
        Some(live) => live.pieces(),
        None => &whole[..],
    };
    let angles: Vec<(f64, Option<Side>)> = match &model.joints {
        Some(js) => js
            .iter()
            .flat_map(|&b| sections(b, splits).into_iter().map(move |s| (b, s)))
            .collect(),
        None => pieces
            .iter()
            .flat_map(|&Span { a, b, at, .. }| {
                (0..=SAMPLES).map(move |i| {
                    let beta = if i == SAMPLES {
                        b
                    } else {
                        a + (b - a) * i as f64 / SAMPLES as f64
                    };
                    // at the loaded angle, the piece's own side of the section
                    let side = splits
                        .contains(&beta)
                        .then_some(if at.beta == beta && at.after {
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
            let v = phi(k, 0, &a, state.eta, mu).mid();
            if v.is_nan() || v > LIMIT_STATE_TOL * state.scale() {
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

/// The mechanism of the rates: B λ̇ = 0, total external power ≥ 0 and, under a load, live
/// power > 0 and as stated.
fn check_mechanism(model: &Model, ls: &Listed, whose: &str) -> Result<(), Rejection> {
    let tol = LIMIT_STATE_TOL;
    let state = ls.state;
    let kept: Vec<(f64, ContactKind, _)> = ls
        .pattern
        .iter()
        .map(|j| (j.beta, j.kind, j.side))
        .collect();
    let columns: Vec<[I; 3]> = kept
        .iter()
        .map(|&(b, k, _)| column(k, b, state.eta))
        .collect();
    let work = weight_work(model, I::point(state.eta), &kept, &columns);
    let live = state.load.map(|(live, lambda)| {
        let q: Vec<f64> = live
            .power(model, &kept, &columns)
            .iter()
            .map(|q| q.mid())
            .collect();
        (q, lambda)
    });
    let mut b = [0.0; 3];
    let (mut total, mut live_power) = (0.0, 0.0);
    for (i, &r) in ls.rates.iter().enumerate() {
        for k in 0..3 {
            b[k] += r * columns[i][k].mid();
        }
        total += r * match &live {
            Some((q, lambda)) => {
                live_power += r * q[i];
                -work[i].mid() + lambda * q[i]
            }
            None => -work[i].mid(),
        };
    }
    if b.iter().any(|v| v.abs() > tol) {
        return reject(format!("{whose}: B lambda = {b:?} is not zero"));
    }
    if live.is_none() {
        if total < -tol {
            return reject(format!(
                "{whose}: external power L_e = {total:e} is negative"
            ));
        }
        return Ok(());
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
