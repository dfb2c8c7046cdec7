//! The `atlas --horizontal --json` document: the load map.

use super::common::JSON_VERSION;
use crate::atlas::loads::{CellAnswer, LoadBoundary, LoadCell, LoadMap};
use schemars::JsonSchema;
use serde::Serialize;

#[derive(Debug, Serialize, JsonSchema)]
struct LargestJson {
    alpha: f64,
    eta: Option<f64>,
    factor: f64,
    reduction: Option<f64>,
}

#[derive(Debug, Serialize, JsonSchema)]
struct SummaryJson {
    mu: f64,
    cells: usize,
    answered: usize,
    undecided: usize,
    reduced: usize,
    largest: Option<LargestJson>,
    /// The boundary whose reduced end has the largest reduction (at least this where its
    /// limit state was followed there).
    largest_at_boundary: Option<LargestJson>,
    /// The semicircle's largest reduction (null: the map holds no semicircle).
    semicircle_largest: Option<f64>,
}

#[derive(Debug, Serialize, JsonSchema)]
struct CellJson {
    alpha: f64,
    factor: f64,
    mu: f64,
    eta: Option<f64>,
    /// `ratio`, `at_most` (the survey did not settle but found a limit state below
    /// λ_static, verified: `lambda_c` is the least found, λ_c does not exceed it, and
    /// `reduction` is a lower bound), `no_collapse`, `no_ring` or `undecided`.
    status: &'static str,
    lambda_static: Option<f64>,
    lambda_c: Option<f64>,
    reduction: Option<f64>,
    mode: Option<&'static str>,
    #[serde(skip_serializing_if = "Option::is_none")]
    message: Option<String>,
    /// With `--certify`, at a reduced cell: the reduction a verified load certificate proves
    /// at least (λ_static ≥ the proved λ_lo, a listed limit state at λ_c below it).
    #[serde(skip_serializing_if = "Option::is_none")]
    certified_reduction: Option<f64>,
    /// With `--certify`, at a reduced cell: why it is not certified.
    #[serde(skip_serializing_if = "Option::is_none")]
    not_certified: Option<String>,
}

/// Where a reduction begins or ends along η, bisected between two cells.
#[derive(Debug, Serialize, JsonSchema)]
struct BoundaryJson {
    alpha: f64,
    mu: f64,
    /// The side of the reduction: `thinner` (reduced below the bracket, not above) or
    /// `thicker`.
    reduced_side: &'static str,
    /// The last thickness of the thinner side's answer and the first of the thicker's.
    eta_bracket: [f64; 2],
    factor_bracket: [f64; 2],
    /// Why the bisection stopped before its resolution (a midpoint without a ratio, or
    /// undecided where the reduced side's limit state could not be followed).
    #[serde(skip_serializing_if = "Option::is_none")]
    stopped: Option<String>,
    /// 1 − λ/λ_static of the limit state at the bracket's reduced end: the survey's least
    /// (λ_c), or the one followed there (then the reduction is at least this).
    reduction: f64,
    /// Present (true) where `reduction` is only a lower bound: the reduced end was decided
    /// by a followed limit state or by a survey that did not settle (λ_c is at most that
    /// state's λ). Absent where a settled survey gave it.
    #[serde(skip_serializing_if = "std::ops::Not::not")]
    at_least: bool,
    /// Midpoints the survey did not decide, decided reduced by the reduced side's least
    /// limit state followed there (Newton on its pattern, verified over the arch, a
    /// mechanism with positive live power, below λ_static).
    followed: usize,
    /// Midpoints the survey did not settle and following did not decide, decided reduced by
    /// a limit state the survey found below λ_static (verified; cells of status `at_most`);
    /// then the reduction is at least `reduction`. Absent when none.
    #[serde(skip_serializing_if = "is_zero")]
    bounded: usize,
    /// With `--certify`: the reduction a verified load certificate proves at least at the
    /// bracket's reduced end.
    #[serde(skip_serializing_if = "Option::is_none")]
    certified_reduction: Option<f64>,
    /// With `--certify`: why the reduced end is not certified.
    #[serde(skip_serializing_if = "Option::is_none")]
    not_certified: Option<String>,
}

fn is_zero(n: &usize) -> bool {
    *n == 0
}

fn boundary_json(b: &LoadBoundary) -> BoundaryJson {
    BoundaryJson {
        alpha: b.alpha,
        mu: b.mu,
        reduced_side: if b.reduced_below {
            "thinner"
        } else {
            "thicker"
        },
        eta_bracket: [b.etas.0, b.etas.1],
        factor_bracket: [b.factors.0, b.factors.1],
        stopped: b.stopped.clone(),
        reduction: b.reduction,
        at_least: b.at_least,
        followed: b.followed,
        bounded: b.bounded,
        certified_reduction: b.certified.clone().and_then(Result::ok),
        not_certified: b.certified.clone().and_then(Result::err),
    }
}

/// The load map as JSON.
#[derive(Debug, Serialize, JsonSchema)]
pub struct LoadMapJson {
    version: u32,
    status: &'static str,
    load: &'static str,
    weight: &'static str,
    blocks: Option<usize>,
    alphas: Vec<f64>,
    factors: Vec<f64>,
    mus: Vec<f64>,
    reduction_tol: f64,
    summary: Vec<SummaryJson>,
    cells: Vec<CellJson>,
    /// Where the reduction begins or ends between neighbouring cells of one opening,
    /// bisected in η to `boundary_rel` (relative).
    boundaries: Vec<BoundaryJson>,
    boundary_rel: f64,
}

fn cell_json(c: &LoadCell) -> CellJson {
    let (status, lambdas, mode, message) = match &c.answer {
        CellAnswer::Ratio {
            lambda_static,
            lambda_c,
            mode,
            at_most,
        } => (
            if *at_most { "at_most" } else { "ratio" },
            Some((*lambda_static, *lambda_c)),
            Some(mode.name()),
            None,
        ),
        CellAnswer::NoCollapse => ("no_collapse", None, None, None),
        CellAnswer::NoRing => ("no_ring", None, None, None),
        CellAnswer::Undecided(why) => ("undecided", None, None, Some(why.clone())),
    };
    CellJson {
        alpha: c.alpha,
        factor: c.factor,
        mu: c.mu,
        eta: c.eta,
        status,
        lambda_static: lambdas.map(|l| l.0),
        lambda_c: lambdas.map(|l| l.1),
        reduction: c.reduction(),
        mode,
        message,
        certified_reduction: c.certified.clone().and_then(Result::ok),
        not_certified: c.certified.clone().and_then(Result::err),
    }
}

/// The summary of the cells at one μ.
fn summary(map: &LoadMap, mu: f64) -> SummaryJson {
    let undecided = map
        .at(mu)
        .filter(|c| matches!(c.answer, CellAnswer::Undecided(_)))
        .count();
    SummaryJson {
        mu,
        cells: map.at(mu).count(),
        answered: map.at(mu).filter(|c| c.reduction().is_some()).count(),
        undecided,
        reduced: map.at(mu).filter(|c| c.reduced()).count(),
        largest: map.largest(mu).map(|c| LargestJson {
            alpha: c.alpha,
            eta: c.eta,
            factor: c.factor,
            reduction: c.reduction(),
        }),
        largest_at_boundary: map.largest_at_boundary(mu).map(|b| LargestJson {
            alpha: b.alpha,
            eta: Some(b.reduced_end().1),
            factor: b.reduced_end().0,
            reduction: Some(b.reduction),
        }),
        semicircle_largest: map.semicircle(mu),
    }
}

/// `atlas --horizontal --json`.
pub fn load_map(map: &LoadMap) -> LoadMapJson {
    LoadMapJson {
        version: JSON_VERSION,
        status: "ok",
        load: "horizontal",
        weight: map.grid.rect.weight.name(),
        blocks: map.grid.rect.blocks,
        alphas: map.alphas.clone(),
        factors: map.factors.clone(),
        mus: map.grid.mus.clone(),
        reduction_tol: crate::atlas::loads::REDUCTION_TOL,
        summary: map.grid.mus.iter().map(|&mu| summary(map, mu)).collect(),
        cells: map.cells.iter().map(cell_json).collect(),
        boundaries: map.boundaries.iter().map(boundary_json).collect(),
        boundary_rel: crate::atlas::loads::BOUNDARY_REL,
    }
}
