//! The two small LPs of the method, and the one place that chooses who solves them.
//!
//! * the static margin LP in x = (h, v, w): maximise the margin s of a finite set of
//!   activation functions, each row scaled to unit gradient norm so that s is a distance
//!   in x-space (formulation §5, static LP);
//! * the kinematic LP in the rates λ of a pattern: B λ = 0, L_e ≥ 0, Σ λ = 1, λ ≥ 0
//!   (formulation §4–5);
//! * the multiplier LP of a live load in z = (h, v, w, λ): the least or largest λ ≥ 0
//!   subject to affine rows (the load problem).
//!
//! Back ends, one file each: [`dense`] (exact small solvers, the fast path) and
//! [`highs`] (HiGHS through good_lp, the reference path). [`Settings::lp_backend`]
//! selects; the dense path falls back to HiGHS whenever it does not apply. No other
//! module imports good_lp or picks a back end.

pub mod dense;
pub mod highs;
mod outcome;

pub use outcome::LpOutcome;

use crate::settings::{LpBackend, Settings};
use crate::statics::{Affine, Reactions};

/// Maximises s subject to `row(x) + s·‖∇row‖ ≤ 0` for every row and `s ≤ cap`; returns the
/// optimal x and s. The LP is always feasible (s may be very negative).
pub fn max_margin(
    rows: &[Affine],
    cap: f64,
    settings: &Settings,
) -> Result<(Reactions, f64), LpOutcome> {
    let reference = || highs::max_margin(rows, cap, settings.lp_tol);
    let first = match settings.lp_backend {
        LpBackend::Highs => reference(),
        LpBackend::Dense => {
            dense::max_margin(rows, cap, settings.dense_lp_tol).or_else(|_| reference())
        }
    };
    // A back end that fails is not an answer: the exact dense simplex then solves the LP
    // with the reactions boxed as HiGHS's own retry boxes them (its optimum on the box
    // is that LP's optimum, as HiGHS's would be).
    match first {
        Err(LpOutcome::Failed(e)) => {
            let tol = settings.dense_lp_tol;
            dense::margin_in_box(rows, cap, tol, highs::REACTION_BOX, true)
                .map_err(|d| LpOutcome::Failed(format!("{e}; then the dense simplex: {d:?}")))
        }
        other => other,
    }
}

/// Maximises `objective · λ` subject to Σ_j λ_j c_j = 0 for the 3-vectors `columns`,
/// `power · λ ≥ 0`, Σ λ = 1, λ ≥ 0. Returns λ, or `Infeasible` when no such rates exist.
pub fn kinematic(
    columns: &[[f64; 3]],
    power: &[f64],
    objective: &[f64],
    settings: &Settings,
) -> Result<Vec<f64>, LpOutcome> {
    Kinematic::new(columns, power, settings).solve(objective)
}

/// The kinematic LP of one pattern ([`kinematic`]) for several objectives: which back end
/// solves it is decided once, and the dense path's vertices (the basic feasible solutions,
/// independent of the objective) are enumerated once.
pub struct Kinematic<'a> {
    columns: &'a [[f64; 3]],
    power: &'a [f64],
    settings: &'a Settings,
    /// The dense path's vertices (none: infeasible, its equality rows inconsistent);
    /// `None`: HiGHS solves it.
    vertices: Option<Vec<Vec<f64>>>,
}

impl<'a> Kinematic<'a> {
    /// The LP of these compatibility columns and powers.
    pub fn new(columns: &'a [[f64; 3]], power: &'a [f64], settings: &'a Settings) -> Self {
        let rows = match settings.lp_backend {
            LpBackend::Dense => dense::kinematic_rows(columns, power),
            LpBackend::Highs => dense::KinematicRows::Other,
        };
        let vertices = match rows {
            // (`None`: kept rows so nearly dependent that no basis passed: HiGHS)
            dense::KinematicRows::Independent(rows) => {
                dense::kinematic_vertices(columns, power, rows, settings.rate_tol)
            }
            dense::KinematicRows::Inconsistent => Some(Vec::new()),
            dense::KinematicRows::Other => None,
        };
        Kinematic {
            columns,
            power,
            settings,
            vertices,
        }
    }

    /// Maximises `objective · λ` (see [`kinematic`]).
    pub fn solve(&self, objective: &[f64]) -> Result<Vec<f64>, LpOutcome> {
        match &self.vertices {
            Some(v) => dense::kinematic_best(v, objective),
            None => highs::kinematic(self.columns, self.power, objective, self.settings.lp_tol),
        }
    }
}

/// The Farkas alternative of [`kinematic`] (used by certificates; HiGHS always): the
/// largest z ∈ [0, 1] with `c_j · y + z + u p_j ≤ 0` for every column, u ≥ 0. z > 0
/// proves that the kinematic LP is infeasible. Returns (y, z, u).
pub fn kinematic_farkas(
    columns: &[[f64; 3]],
    power: &[f64],
    settings: &Settings,
) -> Result<([f64; 3], f64, f64), LpOutcome> {
    highs::kinematic_farkas(columns, power, settings.lp_tol)
}

/// The least or largest multiplier λ ≥ 0 of a load problem (unknowns (h, v, w, λ), rows
/// `a · z + c ≤ 0`, and `= 0` for `equal`; HiGHS). `Ok(None)`: λ unbounded;
/// `Err(Infeasible)`: no state. After a back-end failure the LP is solved again with the
/// reactions boxed at [`highs::REACTION_BOX`]: an optimum with a reaction on that box
/// (see [`on_box`]) is no optimum of the problem, and the caller must say so.
///
/// HiGHS always, whatever [`Settings::lp_backend`]: a discrete arch's λ_static is often
/// attained on a face of states, and the state this returns there (a vertex, the back end's
/// choice) picks the active contacts reported at λ_static — the dense path's vertex has the
/// same λ but can carry another pattern (and move the corners of the λ–μ curve). The
/// continuous exchange, whose answer Newton refines on the whole arch, uses
/// [`multiplier_extreme_warm`].
pub fn multiplier_extreme(
    rows: &[([f64; 4], f64)],
    equal: &[([f64; 4], f64)],
    maximise: bool,
    settings: &Settings,
) -> Result<Option<[f64; 4]>, LpOutcome> {
    highs::multiplier_extreme(rows, equal, maximise, settings.lp_tol)
}

/// The optimal basis of the last dense solve of [`multiplier_extreme_warm`] (none after a
/// HiGHS solve): it starts the next one.
#[derive(Debug, Clone, Default)]
pub struct WarmStart(Option<[usize; 4]>);

/// [`multiplier_extreme`] without equality rows, started from `warm` and leaving the new
/// optimal basis there: for a sequence of LPs each of which appends rows to the last
/// (the exchange method), where the previous optimum stays dual feasible. Any `warm` is
/// safe: the dense path checks it and starts cold when it does not fit. With the dense
/// back end ([`Settings::lp_backend`]) the dense path ([`dense::multiplier_extreme`]) solves
/// it, in the box of [`dense::BOX`], then of [`highs::REACTION_BOX`], and HiGHS wherever
/// it cannot decide (unbounded, infeasible, an optimum on its box).
pub fn multiplier_extreme_warm(
    rows: &[([f64; 4], f64)],
    maximise: bool,
    settings: &Settings,
    warm: &mut WarmStart,
) -> Result<Option<[f64; 4]>, LpOutcome> {
    if settings.lp_backend == LpBackend::Dense {
        // the box of the margin LP first; an optimum on it again in HiGHS's retry box
        // (states far out along a direction in which λ grows, at a caller's cap on λ)
        for reaction_box in [dense::BOX, highs::REACTION_BOX] {
            let tol = settings.dense_lp_tol;
            match dense::multiplier_extreme(rows, maximise, tol, warm.0, reaction_box) {
                Ok((z, basis)) => {
                    warm.0 = Some(basis);
                    return Ok(Some(z));
                }
                Err(LpOutcome::Failed(e)) if e.contains("box") => continue,
                Err(_) => break,
            }
        }
        warm.0 = None;
    }
    highs::multiplier_extreme(rows, &[], maximise, settings.lp_tol)
}

/// Whether a solution of [`multiplier_extreme`] has a reaction on the retry's box (λ then
/// grows with the reactions without bound on these rows).
pub fn on_box(z: &[f64; 4]) -> bool {
    z[..3]
        .iter()
        .any(|v| v.abs() >= 0.999 * highs::REACTION_BOX)
}
