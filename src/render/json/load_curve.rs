//! The `load-curve --json` document: the samples of the λ–μ curve and its corners.

use super::common::{ArchJson, JSON_VERSION};
use super::load::{load_json, pattern_json, LoadJson, PatternContact};
use crate::load::LiveLoad;
use crate::multiplier::{LoadAnswer, LoadCurve, LoadOutcome};
use crate::render::live_load::{LoadQuestion, CONTINUOUS_TOL};
use schemars::JsonSchema;
use serde::Serialize;

/// One sample of the λ–μ curve at fixed η.
#[derive(Debug, Serialize, JsonSchema)]
pub struct LoadCurveRow {
    pub(crate) mu: Option<f64>,
    pub(crate) status: &'static str,
    pub(crate) lambda: Option<f64>,
    pub(crate) lambda_static: Option<f64>,
    pub(crate) reduction: Option<f64>,
    pub(crate) unique: Option<bool>,
    pub(crate) mode: Option<&'static str>,
    pub(crate) limit_states: usize,
    /// `unresolved` with a limit state found all the same: the least λ found (the collapse
    /// multiplier is at most this), as in `load --json`. Absent otherwise.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub(crate) lambda_at_most: Option<f64>,
    /// `unresolved` with a limit state found below λ_static: 1 − `lambda_at_most` /
    /// `lambda_static`, the least the collapse multiplier lies below the static maximum.
    /// Absent otherwise.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub(crate) reduction_at_least: Option<f64>,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub(crate) message: Option<String>,
}

/// The `load-curve --json` document.
#[derive(Debug, Serialize, JsonSchema)]
pub struct LoadCurveDoc {
    version: u32,
    status: &'static str,
    arch: ArchJson,
    eta: f64,
    load: LoadJson,
    points: Vec<LoadCurveRow>,
    corners: Vec<CornerJson>,
}

pub(crate) fn curve_row(mu: f64, outcome: &LoadAnswer) -> LoadCurveRow {
    let mut row = LoadCurveRow {
        mu: mu.is_finite().then_some(mu),
        status: "ok",
        lambda: None,
        lambda_static: None,
        reduction: None,
        unique: None,
        mode: None,
        limit_states: 0,
        lambda_at_most: None,
        reduction_at_least: None,
        message: None,
    };
    match outcome {
        // what an undecided survey decided all the same: λ_static, the states it found
        Err(u) => {
            row.status = "unresolved";
            row.message = Some(u.why.to_string());
            row.lambda_static = u.lambda_static;
            row.unique = u.unique();
            row.limit_states = u.found.len();
            row.lambda_at_most = u.lambda_at_most();
            row.reduction_at_least = u.reduction_at_least();
        }
        Ok(LoadOutcome::NoEquilibrium) => row.status = "no_equilibrium",
        Ok(LoadOutcome::NoCollapse { .. }) => row.status = "no_collapse",
        Ok(LoadOutcome::Limits(s)) => {
            row.lambda = s.lambda();
            row.lambda_static = s.lambda_static.map(|m| m.0);
            row.reduction = s.reduction();
            row.unique = Some(s.unique());
            row.mode = s.limit_states.first().map(|l| l.mode.name());
            row.limit_states = s.limit_states.len();
        }
    }
    row
}

/// One side of a corner of the λ–μ curve: the sample's row, and the least limit state's
/// pattern.
#[derive(Debug, Serialize, JsonSchema)]
struct CornerSide {
    #[serde(flatten)]
    row: LoadCurveRow,
    pattern: Vec<PatternContact>,
}

/// A corner of the λ–μ curve in `load-curve --json`.
#[derive(Debug, Serialize, JsonSchema)]
struct CornerJson {
    /// The corner's friction coefficient: exact (five activation functions vanish at one
    /// state, Newton in (h, v, w, λ, μ)) when `exact`, else null (see the bracket).
    mu: Option<f64>,
    /// λ at the exact corner.
    lambda: Option<f64>,
    exact: bool,
    /// The bisection's bracket: answers at μ just below and just above (neighbouring floats
    /// when `bracketed`; around an exact corner, the survey's active-set tolerance widens it).
    mu_below: f64,
    mu_above: Option<f64>,
    bracketed: bool,
    /// Changes of branch bracketed here (more than 1 without `exact`: the answer flickers
    /// in this stretch).
    changes: usize,
    /// λ continuous across the corner (two limit states cross) or not (a jump).
    continuous: bool,
    below: CornerSide,
    above: CornerSide,
}

fn corner_side(load: &LiveLoad, (mu, o): &(f64, LoadAnswer)) -> CornerSide {
    let pattern = match o {
        Ok(LoadOutcome::Limits(sv)) => sv
            .limit_states
            .first()
            .map_or(Vec::new(), |l| pattern_json(load, l)),
        _ => Vec::new(),
    };
    CornerSide {
        row: curve_row(*mu, o),
        pattern,
    }
}

/// The `load-curve --json` document: the samples and the corners.
pub fn load_curve(q: &LoadQuestion, curve: &LoadCurve) -> LoadCurveDoc {
    LoadCurveDoc {
        version: JSON_VERSION,
        status: "ok",
        arch: ArchJson::new(q.arch),
        eta: q.eta,
        load: load_json(q),
        points: curve
            .samples
            .iter()
            .map(|(mu, o)| curve_row(*mu, o))
            .collect(),
        corners: curve
            .corners
            .iter()
            .map(|c| CornerJson {
                mu: c.exact.then_some(c.mu),
                lambda: c.exact.then_some(c.t),
                exact: c.exact,
                mu_below: c.below().0,
                mu_above: c.above().0.is_finite().then_some(c.above().0),
                bracketed: c.detail.bracketed,
                changes: c.detail.changes,
                continuous: c.continuous(CONTINUOUS_TOL),
                below: corner_side(&q.load, c.below()),
                above: corner_side(&q.load, c.above()),
            })
            .collect(),
    }
}
