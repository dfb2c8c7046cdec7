//! The good_lp back end: the reference path of both LPs, and the only file of the crate
//! that imports good_lp. The solver is chosen here by cargo feature: HiGHS (`highs`, the
//! default and the reference), else microlp (`microlp`, pure Rust: no C++ compiler, cmake
//! or libclang; the Python wheel's build; used when `highs` is off). microlp takes no
//! options: `tol` is not passed on (its fixed tolerance is 1e-10, the default of
//! `Settings::lp_tol`).
//!
//! Two small LPs are solved here:
//! * the static margin LP in x = (h, v, w): maximise the margin s of a finite set of
//!   activation functions, each row scaled to unit gradient norm so that s is a
//!   distance in x-space (formulation §5, static LP);
//! * the kinematic LP in the rates λ of a pattern: B λ = 0, L_e ≥ 0, Σ λ = 1, λ ≥ 0
//!   (formulation §4–5).

use super::outcome::LpOutcome;
use crate::statics::{Affine, Reactions};
use good_lp::{variable, Expression, ProblemVariables, Solution, SolverModel};

#[cfg(not(any(feature = "highs", feature = "microlp")))]
compile_error!("arch-enum needs an LP back end: enable the feature `highs` (default) or `microlp`");

#[cfg(feature = "highs")]
use good_lp::{highs as lp_solver, solvers::highs::HighsProblem as Problem};
#[cfg(all(feature = "microlp", not(feature = "highs")))]
use good_lp::{microlp as lp_solver, solvers::microlp::MicroLpProblem as Problem};

/// The LP solver of this build (`"HiGHS"` or `"microlp"`).
#[cfg(feature = "highs")]
pub const SOLVER: &str = "HiGHS";
/// The LP solver of this build (`"HiGHS"` or `"microlp"`).
#[cfg(all(feature = "microlp", not(feature = "highs")))]
pub const SOLVER: &str = "microlp";

#[cfg(feature = "highs")]
fn configure(problem: Problem, tol: f64) -> Problem {
    problem
        .set_option("primal_feasibility_tolerance", tol)
        .set_option("dual_feasibility_tolerance", tol)
        .set_option("output_flag", false)
        .set_option("presolve", "off")
        .set_threads(1)
}

#[cfg(all(feature = "microlp", not(feature = "highs")))]
fn configure(problem: Problem, _tol: f64) -> Problem {
    problem
}

/// Half-width of the box on (h, v, w) in the margin LP (units of γ t d r).
pub const REACTION_BOX: f64 = 1e12;

/// Maximises s subject to `row(x) + s·‖∇row‖ ≤ 0` for every row and `s ≤ s_cap`.
/// Returns the optimal x and s. The LP is always feasible (s may be very negative).
/// Solved with free reactions; only if HiGHS fails is it solved again with the reactions
/// boxed at [`REACTION_BOX`] (near an infimum approached with growing reactions the free
/// LP ends in "HiGHS error ... Error"; the box is not imposed otherwise because HiGHS can
/// stumble on bounds that far from the data's scale).
pub fn max_margin(rows: &[Affine], s_cap: f64, tol: f64) -> Result<(Reactions, f64), LpOutcome> {
    match margin_lp(rows, s_cap, tol, None) {
        Err(LpOutcome::Failed(_)) => margin_lp(rows, s_cap, tol, Some(REACTION_BOX)),
        other => other,
    }
}

fn margin_lp(
    rows: &[Affine],
    s_cap: f64,
    tol: f64,
    reaction_box: Option<f64>,
) -> Result<(Reactions, f64), LpOutcome> {
    let mut vars = ProblemVariables::new();
    let bound = |v: good_lp::VariableDefinition| match reaction_box {
        Some(b) => v.min(-b).max(b),
        None => v,
    };
    let h = vars.add(bound(variable()));
    let v = vars.add(bound(variable()));
    let w = vars.add(bound(variable()));
    let s = vars.add(variable().max(s_cap));
    let mut problem = configure(vars.maximise(s).using(lp_solver), tol);
    for row in rows {
        let norm = row.grad_norm();
        let scale = if norm > 0.0 { 1.0 / norm } else { 1.0 };
        let mut e = Expression::with_capacity(4);
        e.add_mul(row.g[0] * scale, h);
        e.add_mul(row.g[1] * scale, v);
        e.add_mul(row.g[2] * scale, w);
        e.add_mul(if norm > 0.0 { 1.0 } else { 0.0 }, s);
        problem = problem.with(e.leq(-row.c * scale));
    }
    match problem.solve() {
        Ok(sol) => Ok(([sol.value(h), sol.value(v), sol.value(w)], sol.value(s))),
        Err(good_lp::ResolutionError::Infeasible) => Err(LpOutcome::Infeasible),
        Err(e) => Err(LpOutcome::Failed(e.to_string())),
    }
}

/// Maximises `objective · λ` subject to Σ_j λ_j c_j = 0 for the 3-vectors `columns`,
/// `power · λ ≥ 0`, Σ λ = 1, λ ≥ 0. Returns λ, or `Infeasible` when no such rates exist.
pub fn kinematic(
    columns: &[[f64; 3]],
    power: &[f64],
    objective: &[f64],
    tol: f64,
) -> Result<Vec<f64>, LpOutcome> {
    let mut vars = ProblemVariables::new();
    let lambda: Vec<_> = columns
        .iter()
        .map(|_| vars.add(variable().min(0.0)))
        .collect();
    let mut obj = Expression::with_capacity(lambda.len());
    for (&l, &c) in lambda.iter().zip(objective) {
        obj.add_mul(c, l);
    }
    let mut problem = configure(vars.maximise(obj).using(lp_solver), tol);
    for i in 0..3 {
        let mut e = Expression::with_capacity(lambda.len());
        for (&l, col) in lambda.iter().zip(columns) {
            e.add_mul(col[i], l);
        }
        problem = problem.with(e.eq(0.0));
    }
    let mut p = Expression::with_capacity(lambda.len());
    let mut total = Expression::with_capacity(lambda.len());
    for (&l, &c) in lambda.iter().zip(power) {
        p.add_mul(c, l);
        total.add_mul(1.0, l);
    }
    problem = problem.with(p.geq(0.0)).with(total.eq(1.0));
    match problem.solve() {
        Ok(sol) => Ok(lambda.iter().map(|&l| sol.value(l).max(0.0)).collect()),
        Err(good_lp::ResolutionError::Infeasible) => Err(LpOutcome::Infeasible),
        Err(e) => Err(LpOutcome::Failed(e.to_string())),
    }
}

/// The Farkas alternative of [`kinematic`]: maximises z ∈ [0, 1] subject to
/// `c_j · y + z + u p_j ≤ 0` for every column c_j with power p_j, u ≥ 0 (y and u boxed at
/// 1e6). A solution with z > 0 proves that no rates λ ≥ 0 with B λ = 0, Σ λ = 1 and
/// p · λ ≥ 0 exist (multiply by λ and sum: 0 + z + u p·λ ≤ 0, impossible). Returns
/// (y, z, u).
pub fn kinematic_farkas(
    columns: &[[f64; 3]],
    power: &[f64],
    tol: f64,
) -> Result<([f64; 3], f64, f64), LpOutcome> {
    const BOUND: f64 = 1e6;
    let mut vars = ProblemVariables::new();
    let y: Vec<_> = (0..3)
        .map(|_| vars.add(variable().min(-BOUND).max(BOUND)))
        .collect();
    let z = vars.add(variable().min(0.0).max(1.0));
    let u = vars.add(variable().min(0.0).max(BOUND));
    let mut problem = configure(vars.maximise(z).using(lp_solver), tol);
    for (col, &p) in columns.iter().zip(power) {
        let mut e = Expression::with_capacity(5);
        for k in 0..3 {
            e.add_mul(col[k], y[k]);
        }
        e.add_mul(1.0, z);
        e.add_mul(p, u);
        problem = problem.with(e.leq(0.0));
    }
    match problem.solve() {
        Ok(sol) => Ok((
            [sol.value(y[0]), sol.value(y[1]), sol.value(y[2])],
            sol.value(z),
            sol.value(u),
        )),
        Err(good_lp::ResolutionError::Infeasible) => Err(LpOutcome::Infeasible),
        Err(e) => Err(LpOutcome::Failed(e.to_string())),
    }
}

/// Optimises the multiplier λ, the last of the unknowns z = (h, v, w, λ), subject to
/// `a · z + c ≤ 0` for every row (a, c) and λ ≥ 0: the largest λ when `maximise`, else
/// the least; the rows of `equal` hold with equality. Rows are scaled to unit gradient
/// norm. `Ok(None)` when λ is unbounded, `Err(Infeasible)` when no state with λ ≥ 0
/// satisfies the rows.
pub fn multiplier_extreme(
    rows: &[([f64; 4], f64)],
    equal: &[([f64; 4], f64)],
    maximise: bool,
    tol: f64,
) -> Result<Option<[f64; 4]>, LpOutcome> {
    // as for the margin LP: free reactions first, boxed ones only as a retry after a
    // failure (near an unbounded multiplier HiGHS can end in "Unknown")
    match multiplier_lp(rows, equal, maximise, tol, None) {
        // the caller judges an optimum on the box (see `REACTION_BOX` and
        // `lp::multiplier_extreme`)
        Err(LpOutcome::Failed(_)) => multiplier_lp(rows, equal, maximise, tol, Some(REACTION_BOX)),
        other => other,
    }
}

fn multiplier_lp(
    rows: &[([f64; 4], f64)],
    equal: &[([f64; 4], f64)],
    maximise: bool,
    tol: f64,
    reaction_box: Option<f64>,
) -> Result<Option<[f64; 4]>, LpOutcome> {
    let mut vars = ProblemVariables::new();
    let z: Vec<_> = (0..4)
        .map(|k| {
            vars.add(match (k, reaction_box) {
                (3, _) => variable().min(0.0),
                (_, Some(b)) => variable().min(-b).max(b),
                (_, None) => variable(),
            })
        })
        .collect();
    let objective = if maximise {
        vars.maximise(z[3])
    } else {
        vars.minimise(z[3])
    };
    let mut problem = configure(objective.using(lp_solver), tol);
    for (i, (a, c)) in rows.iter().chain(equal).enumerate() {
        let norm = a.iter().map(|v| v * v).sum::<f64>().sqrt();
        let scale = if norm > 0.0 { 1.0 / norm } else { 1.0 };
        let mut e = Expression::with_capacity(4);
        for k in 0..4 {
            e.add_mul(a[k] * scale, z[k]);
        }
        problem = problem.with(if i < rows.len() {
            e.leq(-c * scale)
        } else {
            e.eq(-c * scale)
        });
    }
    match problem.solve() {
        Ok(sol) => Ok(Some([
            sol.value(z[0]),
            sol.value(z[1]),
            sol.value(z[2]),
            sol.value(z[3]),
        ])),
        Err(good_lp::ResolutionError::Unbounded) => Ok(None),
        Err(good_lp::ResolutionError::Infeasible) => Err(LpOutcome::Infeasible),
        Err(e) => Err(LpOutcome::Failed(e.to_string())),
    }
}
