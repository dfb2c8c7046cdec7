//! A small exact LP solver for the static margin LP — the fast path; HiGHS
//! ([`super::highs`]) stays the reference path and the two are cross-checked in tests.
//!
//! The margin LP, max s subject to ĝᵢ·x + s ≤ rᵢ (rows normalised, ‖ĝᵢ‖ = 1) and s ≤ cap,
//! has only four variables z = (h, v, w, s). Its dual, min rᵀy subject to
//! Σ yᵢ (ĝᵢ, 1) = (0, 0, 0, 1), y ≥ 0, has four equality rows, so the revised simplex
//! method on the dual works with a 4 × 4 basis: each iteration prices every primal row
//! (its reduced cost is the primal slack at the current point z = B⁻ᵀ r_B), lets the
//! most violated row enter, and does a ratio test on B⁻¹(ĝⱼ, 1). A box |x_k| ≤ `BOX`
//! (rows that never bind in practice) gives a dual-feasible starting basis together
//! with the cap. Dantzig pricing, Bland's rule after degenerate steps (no cycling).

use super::outcome::LpOutcome;
use crate::statics::{Affine, Reactions};
use nalgebra::{Matrix4, Vector4};

/// Half-width of the box on (h, v, w) that starts the simplex (units of γ t d r).
pub const BOX: f64 = 1e6;

/// Pivot elements below this are not used in the ratio test (rows normalised to 1).
const PIVOT_TOL: f64 = 1e-12;
/// Ratios closer than this tie (Bland's rule decides); a step this short is degenerate.
const RATIO_TIE: f64 = 1e-15;
/// Rank threshold and smallest |det| of a basis in the kinematic enumeration (columns
/// of order one: B columns, power, ones).
const BASIS_TOL: f64 = 1e-12;
/// A basic solution replaces the best one only if its objective is larger by this.
const IMPROVE_TOL: f64 = 1e-14;

/// Maximises s subject to `row(x) + s·‖∇row‖ ≤ 0` for every row and s ≤ `cap`
/// (the same problem as [`super::highs::max_margin`]). `tol` is the feasibility tolerance
/// on normalised rows.
pub fn max_margin(rows: &[Affine], cap: f64, tol: f64) -> Result<(Reactions, f64), LpOutcome> {
    margin_in_box(rows, cap, tol, BOX, false)
}

/// [`max_margin`] with the reactions boxed at `reaction_box`; with `on_box_ok`, an optimum
/// on the box is returned (the optimum of the boxed LP: a state near an infimum that is
/// approached with growing reactions), otherwise it is a `Failed` that names the box.
pub fn margin_in_box(
    rows: &[Affine],
    cap: f64,
    tol: f64,
    reaction_box: f64,
    on_box_ok: bool,
) -> Result<(Reactions, f64), LpOutcome> {
    // constraint columns a_j ∈ R⁴ and right-hand sides b_j of the primal a_j·z ≤ b_j
    let mut a: Vec<[f64; 4]> = Vec::with_capacity(rows.len() + 7);
    let mut b: Vec<f64> = Vec::with_capacity(rows.len() + 7);
    // 0: cap, 1..=3: x_k ≤ BOX, 4..=6: −x_k ≤ BOX
    a.push([0.0, 0.0, 0.0, 1.0]);
    b.push(cap);
    for k in 0..3 {
        let mut e = [0.0; 4];
        e[k] = 1.0;
        a.push(e);
        b.push(reaction_box);
    }
    for k in 0..3 {
        let mut e = [0.0; 4];
        e[k] = -1.0;
        a.push(e);
        b.push(reaction_box);
    }
    for r in rows {
        let n = r.grad_norm();
        if n > 0.0 {
            a.push([r.g[0] / n, r.g[1] / n, r.g[2] / n, 1.0]);
            b.push(-r.c / n);
        } else {
            // a constant row: c + s·0 ≤ 0 (the HiGHS path treats it the same way)
            if r.c > tol {
                return Err(LpOutcome::Infeasible);
            }
        }
    }
    let unused: [bool; 3] = std::array::from_fn(|k| a[7..].iter().all(|r| r[k] == 0.0));
    match dual_simplex(&a, &b, S, [0, 1, 2, 3], 3, tol)? {
        End::Optimal { z, basis, .. } => {
            // A box row still basic: its coordinate sits on the box. That is harmless only
            // for a coordinate no row involves (w in the friction-only problem), which is
            // then set to 0; otherwise let the caller fall back to the reference path.
            let mut x = [z[0], z[1], z[2]];
            for &i in &basis {
                if (1..=6).contains(&i) {
                    let k = (i - 1) % 3;
                    if unused[k] {
                        x[k] = 0.0;
                    } else if !on_box_ok {
                        return Err(LpOutcome::Failed(
                            "the optimum touches the starting box".into(),
                        ));
                    }
                }
            }
            Ok((x, z[3]))
        }
        End::DualUnbounded => Err(LpOutcome::Failed(
            "dual unbounded: primal infeasible".into(),
        )),
    }
}

/// The objective e₄ of the margin LP (maximise s).
const S: [f64; 4] = [0.0, 0.0, 0.0, 1.0];

/// How [`dual_simplex`] ended.
enum End {
    /// Every row holds at z (to the tolerance): the optimal vertex z = B⁻ᵀ b_B and its
    /// basis (dual values B⁻¹c ≥ 0).
    Optimal { z: Vector4<f64>, basis: [usize; 4] },
    /// The entering row has no positive pivot: the dual is unbounded, the primal (with
    /// every row given, box rows included) infeasible.
    DualUnbounded,
}

/// The revised simplex method on the dual of max cᵀz subject to a_j·z ≤ b_j (z ∈ R⁴),
/// from the dual-feasible `basis` (B⁻¹c ≥ 0): each iteration prices every row (its
/// reduced cost is the primal slack at z = B⁻ᵀ b_B), lets the most violated one enter
/// (Bland's rule, the first violated, after more than 8 degenerate steps) and does the
/// ratio test on B⁻¹ a_j. A row is violated when its slack is below −`tol` × (1 + the
/// 1-norm of the first `scale_dims` coordinates of z).
fn dual_simplex(
    a: &[[f64; 4]],
    b: &[f64],
    c: [f64; 4],
    mut basis: [usize; 4],
    scale_dims: usize,
    tol: f64,
) -> Result<End, LpOutcome> {
    let m = a.len();
    let mut in_basis = vec![false; m];
    for &i in &basis {
        in_basis[i] = true;
    }
    let c = Vector4::from_row_slice(&c);
    let mut degenerate = 0usize;
    for _ in 0..(50 * m + 100) {
        let bmat = Matrix4::from_fn(|r, c| a[basis[c]][r]);
        let lu = bmat.lu();
        // primal point z solves Bᵀ z = b_B
        let bt = bmat.transpose().lu();
        let z = bt
            .solve(&Vector4::from_fn(|i, _| b[basis[i]]))
            .ok_or_else(|| LpOutcome::Failed("singular basis".into()))?;
        // dual values y_B solve B y = c
        let y = lu
            .solve(&c)
            .ok_or_else(|| LpOutcome::Failed("singular basis".into()))?;
        // pricing: the most violated primal row (Bland: the first one after stalls)
        let scale = z.iter().take(scale_dims).fold(1.0, |s, v| s + v.abs());
        let mut enter = None;
        let mut worst = -tol * scale;
        for j in 0..m {
            if in_basis[j] {
                continue;
            }
            let slack = b[j] - (a[j][0] * z[0] + a[j][1] * z[1] + a[j][2] * z[2] + a[j][3] * z[3]);
            if slack < worst {
                enter = Some(j);
                if degenerate > 8 {
                    break; // Bland: lowest index
                }
                worst = slack;
            }
        }
        let Some(j) = enter else {
            return Ok(End::Optimal { z, basis });
        };
        // ratio test on d = B⁻¹ a_j
        let d = lu
            .solve(&Vector4::from_row_slice(&a[j]))
            .ok_or_else(|| LpOutcome::Failed("singular basis".into()))?;
        let mut leave: Option<(usize, f64)> = None;
        for k in 0..4 {
            if d[k] > PIVOT_TOL {
                let ratio = y[k].max(0.0) / d[k];
                let better = match leave {
                    None => true,
                    Some((l, best)) => {
                        ratio < best - RATIO_TIE
                            || (ratio <= best + RATIO_TIE && basis[k] < basis[l])
                    }
                };
                if better {
                    leave = Some((k, ratio));
                }
            }
        }
        let Some((k, ratio)) = leave else {
            return Ok(End::DualUnbounded);
        };
        degenerate = if ratio <= RATIO_TIE {
            degenerate + 1
        } else {
            0
        };
        in_basis[basis[k]] = false;
        in_basis[j] = true;
        basis[k] = j;
    }
    Err(LpOutcome::Failed("iteration limit".into()))
}

/// The kinematic LP of [`super::highs::kinematic`] (maximise `objective · λ` subject to
/// Σ λ_j c_j = 0, `power · λ ≥ 0`, Σ λ = 1, λ ≥ 0) for small patterns, by enumerating the
/// basic solutions of its five equality rows (power with a slack), or of the independent
/// ones among them: where [`kinematic_rows`] is [`KinematicRows::Independent`],
/// [`kinematic_vertices`] once per pattern, then [`kinematic_best`] for each objective
/// (`Infeasible` when there is no vertex). Elsewhere HiGHS solves it.
/// The equality rows of the kinematic LP with the power slack: λ_j → (c_j, p_j, 1), the
/// slack → (0, 0, 0, −1, 0).
fn kinematic_column(columns: &[[f64; 3]], power: &[f64], j: usize) -> [f64; 5] {
    if j < columns.len() {
        [columns[j][0], columns[j][1], columns[j][2], power[j], 1.0]
    } else {
        [0.0, 0.0, 0.0, -1.0, 0.0]
    }
}

/// What the dense path makes of a kinematic LP's equality rows (independent of the
/// objective: decided once for several solves).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum KinematicRows {
    /// 1 to 12 rates, and these rows (bit k: row k) independent, every other row a
    /// combination of them right-hand side included (all five where the rows have full
    /// rank): the enumeration of bases of that many columns applies.
    Independent(u8),
    /// 1 to 12 rates and rows that contradict each other whatever the signs of the rates
    /// (the right-hand side outside their span, e.g. hinges whose rotations must sum to
    /// zero and to one): the LP is infeasible.
    Inconsistent,
    /// Anything else (HiGHS solves it).
    Other,
}

/// Classifies the equality rows of the kinematic LP of these rates ([`KinematicRows`]):
/// the rows are taken in order, each kept when it raises the rank of the kept rows with
/// their right-hand side; a right-hand side outside the span of the columns makes the
/// rows inconsistent.
pub fn kinematic_rows(columns: &[[f64; 3]], power: &[f64]) -> KinematicRows {
    use nalgebra::DMatrix;
    let n = columns.len();
    if n == 0 || n > 12 {
        return KinematicRows::Other;
    }
    let rows = DMatrix::from_fn(5, n + 1, |r, c| kinematic_column(columns, power, c)[r]);
    if surely_full_rank(&rows, 1e2 * BASIS_TOL) {
        return KinematicRows::Independent(0b11111);
    }
    let rank = rows.rank(1e2 * BASIS_TOL);
    if rank >= 5 {
        return KinematicRows::Independent(0b11111);
    }
    // the right-hand side (0, 0, 0, 0, 1) appended as a column: a greater rank puts it
    // outside the rows' span
    let mut with_rhs = rows.insert_column(n + 1, 0.0);
    with_rhs[(4, n + 1)] = 1.0;
    if with_rhs.rank(1e2 * BASIS_TOL) > rank {
        return KinematicRows::Inconsistent;
    }
    let (mut kept, mut mask) = (0, 0u8);
    for r in 0..5 {
        let trial = mask | 1 << r;
        let picked: Vec<usize> = (0..5).filter(|k| trial & 1 << k != 0).collect();
        if with_rhs.select_rows(picked.iter()).rank(1e2 * BASIS_TOL) > kept {
            kept += 1;
            mask = trial;
        }
    }
    KinematicRows::Independent(mask)
}

/// Whether the five rows of `m` have rank 5 at the threshold `tol` of
/// `DMatrix::rank` (singular values above it), shown without the SVD: Gaussian elimination
/// with complete pivoting picks five columns M, and σ₅(m) ≥ σ₅(M) ≥ |det M| / ‖M‖_F⁴ (the
/// singular values of m are at least those of its five columns, and |det M| = σ₁⋯σ₅ ≤
/// σ₅ ‖M‖_F⁴). `false` says nothing (the SVD decides).
pub fn surely_full_rank(m: &nalgebra::DMatrix<f64>, tol: f64) -> bool {
    let (rows, cols) = m.shape();
    if rows != 5 || cols < 5 {
        return false;
    }
    let mut a = m.clone();
    let (mut det, mut picked) = (1.0f64, [0usize; 5]);
    let mut free: Vec<usize> = (0..cols).collect();
    for k in 0..5 {
        // the largest entry of rows k.. in the columns not yet picked
        let (mut best, mut at) = (0.0f64, (k, 0));
        for r in k..5 {
            for (f, &c) in free.iter().enumerate() {
                if a[(r, c)].abs() > best {
                    (best, at) = (a[(r, c)].abs(), (r, f));
                }
            }
        }
        if best == 0.0 {
            return false;
        }
        let (r, c) = (at.0, free.swap_remove(at.1));
        a.swap_rows(k, r);
        det *= a[(k, c)];
        picked[k] = c;
        for i in k + 1..5 {
            let f = a[(i, c)] / a[(k, c)];
            for &j in &free {
                a[(i, j)] -= f * a[(k, j)];
            }
        }
    }
    let frobenius2: f64 = picked.iter().map(|&c| m.column(c).norm_squared()).sum();
    // a margin of 2 for the rounding of det and of the SVD
    det.abs() > 2.0 * tol * frobenius2 * frobenius2
}

/// Every basic feasible solution of the kinematic LP's equality rows `rows` (the
/// independent ones, [`KinematicRows::Independent`]): the rates λ, in the order the bases
/// are enumerated; the vertices among which [`kinematic_best`] picks, the same for every
/// objective. `None` where fewer than five rows are kept and no basis passes the
/// determinant test (nearly dependent rows: no decision here, HiGHS's to make); with five,
/// an empty list as before (infeasible).
pub fn kinematic_vertices(
    columns: &[[f64; 3]],
    power: &[f64],
    rows: u8,
    tol: f64,
) -> Option<Vec<Vec<f64>>> {
    let picked: Vec<usize> = (0..5).filter(|k| rows & 1 << k != 0).collect();
    let (vertices, nonsingular) = match picked.len() {
        5 => return Some(basic_solutions::<5>(columns, power, &picked, tol).0),
        4 => basic_solutions::<4>(columns, power, &picked, tol),
        3 => basic_solutions::<3>(columns, power, &picked, tol),
        2 => basic_solutions::<2>(columns, power, &picked, tol),
        1 => basic_solutions::<1>(columns, power, &picked, tol),
        _ => (Vec::new(), false),
    };
    nonsingular.then_some(vertices)
}

/// The basic feasible solutions of the `R` equality rows `picked` (R × R bases of the
/// columns, the power slack included), and whether any basis passed the determinant test.
fn basic_solutions<const R: usize>(
    columns: &[[f64; 3]],
    power: &[f64],
    picked: &[usize],
    tol: f64,
) -> (Vec<Vec<f64>>, bool)
where
    nalgebra::Const<R>: nalgebra::DimMin<nalgebra::Const<R>, Output = nalgebra::Const<R>>,
{
    use itertools::Itertools;
    use nalgebra::{SMatrix, SVector};
    let n = columns.len();
    // each column's entries in the picked rows
    let cols: Vec<[f64; R]> = (0..=n)
        .map(|j| {
            let c = kinematic_column(columns, power, j);
            std::array::from_fn(|r| c[picked[r]])
        })
        .collect();
    let rhs = SVector::<f64, R>::from_fn(|r, _| if picked[r] == 4 { 1.0 } else { 0.0 });
    let (mut out, mut nonsingular) = (Vec::new(), false);
    for basis in (0..=n).combinations(R) {
        let m = SMatrix::<f64, R, R>::from_fn(|r, c| cols[basis[c]][r]);
        let lu = m.lu();
        if lu.determinant().abs() < BASIS_TOL {
            continue;
        }
        nonsingular = true;
        let Some(x) = lu.solve(&rhs) else { continue };
        if x.iter().any(|&v| v < -tol) {
            continue;
        }
        let mut lambda = vec![0.0; n];
        for (k, &j) in basis.iter().enumerate() {
            if j < n {
                lambda[j] = x[k].max(0.0);
            }
        }
        out.push(lambda);
    }
    (out, nonsingular)
}

/// The vertex of [`kinematic_vertices`] that maximises `objective · λ` (the first of
/// equal ones, to `IMPROVE_TOL`); `Infeasible` when there is none.
pub fn kinematic_best(vertices: &[Vec<f64>], objective: &[f64]) -> Result<Vec<f64>, LpOutcome> {
    let mut best: Option<(f64, &Vec<f64>)> = None;
    for lambda in vertices {
        let value: f64 = lambda.iter().zip(objective).map(|(l, o)| l * o).sum();
        if best.as_ref().is_none_or(|b| value > b.0 + IMPROVE_TOL) {
            best = Some((value, lambda));
        }
    }
    best.map(|b| b.1.clone()).ok_or(LpOutcome::Infeasible)
}

/// Rows 0..[`MULTIPLIER_ROWS`] of the dense multiplier LP are its own: λ ≥ 0, the box
/// |x_k| ≤ `reaction_box` and λ ≤ [`LAMBDA_BOX`]; the caller's rows follow.
pub const MULTIPLIER_ROWS: usize = 8;
/// The bound on λ that, with the box on the reactions, starts the simplex of the
/// largest multiplier (an optimum on it is no optimum of the problem).
pub const LAMBDA_BOX: f64 = 1e15;
/// A warm-start basis is used when its dual values are ≥ −this (rounding of B⁻¹c).
const WARM_DUAL_TOL: f64 = 1e-12;

/// The least or largest multiplier λ ≥ 0 of [`super::highs::multiplier_extreme`] without
/// equality rows: optimise λ, the last of z = (h, v, w, λ), subject to `a · z + c ≤ 0`
/// for every row (scaled to unit gradient norm, as on the HiGHS path). Returns the optimal
/// z and its basis (indices into this LP's rows: [`MULTIPLIER_ROWS`] of its own, then the
/// caller's), which starts the next call through `warm` when the caller only appends
/// rows or changes the box: the basis stays dual feasible (that depends on the rows'
/// gradients only), so the simplex goes on from the previous optimum. `warm` is checked
/// (in range, nonsingular, dual feasible) and ignored otherwise.
///
/// The dense path decides only what it can prove without its artificial bounds: an
/// optimum with the box or λ's bound in the basis, an infeasible boxed LP (primal
/// infeasibility of the problem itself, or a box that cuts every state off) and an
/// unbounded λ all come back as `Failed`, and the caller falls back to HiGHS. `tol` is
/// the feasibility tolerance on normalised rows, relative to 1 + ‖z‖₁.
pub fn multiplier_extreme(
    rows: &[([f64; 4], f64)],
    maximise: bool,
    tol: f64,
    warm: Option<[usize; 4]>,
    reaction_box: f64,
) -> Result<([f64; 4], [usize; 4]), LpOutcome> {
    let m = rows.len() + MULTIPLIER_ROWS;
    let mut a: Vec<[f64; 4]> = Vec::with_capacity(m);
    let mut b: Vec<f64> = Vec::with_capacity(m);
    // 0: −λ ≤ 0; 1..=3: x_k ≤ reaction_box; 4..=6: −x_k ≤ reaction_box; 7: λ ≤ LAMBDA_BOX
    a.push([0.0, 0.0, 0.0, -1.0]);
    b.push(0.0);
    for sign in [1.0, -1.0] {
        for k in 0..3 {
            let mut e = [0.0; 4];
            e[k] = sign;
            a.push(e);
            b.push(reaction_box);
        }
    }
    a.push([0.0, 0.0, 0.0, 1.0]);
    b.push(LAMBDA_BOX);
    for (g, c) in rows {
        let n = g.iter().map(|v| v * v).sum::<f64>().sqrt();
        if n > 0.0 {
            a.push(g.map(|v| v / n));
            b.push(-c / n);
        } else if *c > 0.0 {
            return Err(LpOutcome::Failed("a constant row is violated".into()));
        } else {
            // 0 ≤ −c holds: a row that never binds (kept so that indices stay the caller's)
            a.push([0.0; 4]);
            b.push(0.0);
        }
    }
    let objective = if maximise {
        [0.0, 0.0, 0.0, 1.0]
    } else {
        [0.0, 0.0, 0.0, -1.0]
    };
    // the cold start: λ's own bound in the objective's direction and the upper box
    let cold = [if maximise { 7 } else { 0 }, 1, 2, 3];
    let start = warm
        .filter(|w| dual_feasible(&a, w, objective))
        .unwrap_or(cold);
    match dual_simplex(&a, &b, objective, start, 4, tol)? {
        End::Optimal { z, basis, .. } => {
            if basis.iter().any(|&i| (1..MULTIPLIER_ROWS).contains(&i)) {
                return Err(LpOutcome::Failed(
                    "the optimum touches the starting box".into(),
                ));
            }
            // λ's own bound in the basis: λ = 0 exactly (as a bound on the HiGHS path)
            let lambda = if basis.contains(&0) { 0.0 } else { z[3] };
            Ok(([z[0], z[1], z[2], lambda], basis))
        }
        End::DualUnbounded => Err(LpOutcome::Failed(
            "dual unbounded: the boxed LP is infeasible".into(),
        )),
    }
}

/// Rows a_j · z + c_j ≤ 0 in z ∈ R⁴, scaled to unit gradients once, for many LPs over the
/// same polyhedron ([`NormalisedRows::max_row`]).
pub struct NormalisedRows {
    a: Vec<[f64; 4]>,
    b: Vec<f64>,
}

impl NormalisedRows {
    /// The rows (a, c), each divided by ‖a‖₂ (a zero row kept as it is).
    pub fn new(rows: &[([f64; 4], f64)]) -> NormalisedRows {
        let (mut a, mut b) = (
            Vec::with_capacity(rows.len()),
            Vec::with_capacity(rows.len()),
        );
        for (g, c) in rows {
            let n = g.iter().map(|v| v * v).sum::<f64>().sqrt();
            let n = if n > 0.0 { n } else { 1.0 };
            a.push(g.map(|v| v / n));
            b.push(-c / n);
        }
        NormalisedRows { a, b }
    }

    /// Maximises row `s` over the polyhedron (the caller's rows must bound it, a box among
    /// them) and returns the optimal basis (four row indices); `Ok(None)`: no z satisfies
    /// the rows. From `warm`, an optimal basis of an earlier LP over these rows (a
    /// neighbouring row's; its vertex is feasible), the primal simplex
    /// (`primal_simplex`); without one, or where that fails, the dual simplex from row
    /// `s` itself and three of the
    /// rows `axes` (gradients +e_0 … +e_3): the one along the largest component of row s's
    /// gradient is left out, so the basis is nonsingular, with dual values (1, 0, 0, 0).
    /// `tol`: the feasibility tolerance, relative to 1 + ‖z‖₁.
    pub fn max_row(
        &self,
        s: usize,
        axes: [usize; 4],
        warm: Option<[usize; 4]>,
        tol: f64,
    ) -> Result<Option<[usize; 4]>, LpOutcome> {
        let objective = self.a[s];
        let skip = (0..4)
            .max_by(|&i, &j| objective[i].abs().total_cmp(&objective[j].abs()))
            .unwrap_or(0);
        let mut cold = [s; 4];
        for (slot, k) in (0..4).filter(|&k| k != skip).enumerate() {
            cold[slot + 1] = axes[k];
        }
        if let Some(w) = warm {
            // an optimum of these rows is a feasible vertex: the primal simplex goes on
            // from it (where the objective changed a little, a few steps)
            if let Ok(basis) = primal_simplex(&self.a, &self.b, objective, w, tol) {
                return Ok(Some(basis));
            }
        }
        match dual_simplex(&self.a, &self.b, objective, cold, 4, tol)? {
            End::Optimal { basis, .. } => Ok(Some(basis)),
            End::DualUnbounded => Ok(None),
        }
    }
}

/// The primal simplex method on max cᵀz subject to a_j·z ≤ b_j (z ∈ R⁴), from the
/// vertex of `basis` (feasible to `tol` × (1 + ‖z‖₁)): while a dual value y = B⁻¹c is
/// below −[`WARM_DUAL_TOL`] (the most negative; Bland's rule, the lowest row, after more
/// than 8 degenerate steps), its row leaves along d with a_B·d = −e_k (c·d = −y_k > 0)
/// until the first row it meets (ratio test over every row, ties to the lowest index).
/// `Err` where a basis is singular, no row bounds the step, steps run out, or the optimal
/// basis is nearly singular ([`NEAR_SINGULAR`]) or its vertex not feasible to `tol`: the
/// caller then starts the dual simplex afresh.
fn primal_simplex(
    a: &[[f64; 4]],
    b: &[f64],
    c: [f64; 4],
    mut basis: [usize; 4],
    tol: f64,
) -> Result<[usize; 4], LpOutcome> {
    let m = a.len();
    if basis.iter().any(|&i| i >= m) || (0..4).any(|p| (p + 1..4).any(|q| basis[p] == basis[q])) {
        return Err(LpOutcome::Failed("not a basis".into()));
    }
    let singular = || LpOutcome::Failed("singular basis".into());
    let c = Vector4::from_row_slice(&c);
    let mut degenerate = 0usize;
    for _ in 0..(2 * m + 100) {
        let bmat = Matrix4::from_fn(|r, col| a[basis[col]][r]);
        let bt = bmat.transpose().lu();
        let z = bt
            .solve(&Vector4::from_fn(|i, _| b[basis[i]]))
            .ok_or_else(singular)?;
        let y = bmat.lu().solve(&c).ok_or_else(singular)?;
        let leaving = (0..4).filter(|&k| y[k] < -WARM_DUAL_TOL).min_by(|&p, &q| {
            if degenerate > 8 {
                basis[p].cmp(&basis[q])
            } else {
                y[p].total_cmp(&y[q])
            }
        });
        let Some(k) = leaving else {
            // optimal: the vertex must be feasible and its basis not nearly singular (its
            // dual values then say little); the dual simplex decides such LPs afresh
            if bmat.determinant().abs() < NEAR_SINGULAR {
                return Err(LpOutcome::Failed("a nearly singular optimal basis".into()));
            }
            return feasible(a, b, &z, tol)
                .then_some(basis)
                .ok_or_else(|| LpOutcome::Failed("the optimal vertex is not feasible".into()));
        };
        // the direction, scaled to unit largest component (the pivot tolerance is
        // relative to it)
        let d = bt
            .solve(&Vector4::from_fn(|i, _| if i == k { -1.0 } else { 0.0 }))
            .ok_or_else(singular)?;
        let d = d / d.amax();
        let scale = z.iter().fold(1.0, |s, v| s + v.abs());
        let mut enter: Option<(usize, f64)> = None;
        for (j, (aj, bj)) in a.iter().zip(b).enumerate() {
            let rate = aj[0] * d[0] + aj[1] * d[1] + aj[2] * d[2] + aj[3] * d[3];
            if rate <= PIVOT_TOL || basis.contains(&j) {
                continue;
            }
            let slack = bj - (aj[0] * z[0] + aj[1] * z[1] + aj[2] * z[2] + aj[3] * z[3]);
            if slack < -tol * scale {
                return Err(LpOutcome::Failed("the start is not feasible".into()));
            }
            let step = slack.max(0.0) / rate;
            if enter.is_none_or(|(_, best)| step < best - RATIO_TIE) {
                enter = Some((j, step));
            }
        }
        let Some((j, step)) = enter else {
            return Err(LpOutcome::Failed("unbounded".into()));
        };
        degenerate = if step <= RATIO_TIE { degenerate + 1 } else { 0 };
        basis[k] = j;
    }
    Err(LpOutcome::Failed("iteration limit".into()))
}

/// The least |det B| of an optimal basis the primal simplex returns (rows of unit norm, so
/// |det B| ≤ 1): the least measured on loads of 3 000–4 095 voussoirs was 6·10⁻⁸ (rows
/// of neighbouring joints nearly parallel).
const NEAR_SINGULAR: f64 = 1e-12;

/// Whether z satisfies every row a_j·z ≤ b_j to `tol` × (1 + ‖z‖₁).
fn feasible(a: &[[f64; 4]], b: &[f64], z: &Vector4<f64>, tol: f64) -> bool {
    let scale = z.iter().fold(1.0, |s, v| s + v.abs());
    a.iter().zip(b).all(|(aj, bj)| {
        aj[0] * z[0] + aj[1] * z[1] + aj[2] * z[2] + aj[3] * z[3] - bj <= tol * scale
    })
}

/// Whether `basis` indexes four distinct rows of `a` forming a nonsingular B with
/// B⁻¹c ≥ −[`WARM_DUAL_TOL`].
fn dual_feasible(a: &[[f64; 4]], basis: &[usize; 4], c: [f64; 4]) -> bool {
    if basis.iter().any(|&i| i >= a.len())
        || (0..4).any(|p| (p + 1..4).any(|q| basis[p] == basis[q]))
    {
        return false;
    }
    let bmat = Matrix4::from_fn(|r, col| a[basis[col]][r]);
    bmat.lu()
        .solve(&Vector4::from_row_slice(&c))
        .is_some_and(|y| y.iter().all(|&v| v >= -WARM_DUAL_TOL))
}

#[cfg(test)]
mod tests {
    use super::*;

    fn uniform(seed: &mut u64) -> f64 {
        *seed = seed
            .wrapping_mul(6364136223846793005)
            .wrapping_add(1442695040888963407);
        (*seed >> 11) as f64 / (1u64 << 53) as f64
    }

    /// The value of row s of `rows` at the vertex of `basis`.
    fn value(rows: &NormalisedRows, s: usize, basis: [usize; 4]) -> f64 {
        let bt = Matrix4::from_fn(|r, c| rows.a[basis[r]][c]);
        let z = bt
            .lu()
            .solve(&Vector4::from_fn(|i, _| rows.b[basis[i]]))
            .expect("a nonsingular basis");
        (0..4).map(|k| rows.a[s][k] * z[k]).sum::<f64>() - rows.b[s]
    }

    /// From each row's optimum, the primal simplex (and `max_row` warm-started there)
    /// reaches the next row's optimum (the value of the dual simplex from a cold start)
    /// and the primal simplex does not fail, on 300 random
    /// polytopes in R⁴: a box and random rows, in a third of them each random row twice
    /// (twin rows, as a loaded joint's), in another third six more rows through one vertex
    /// (a degenerate vertex); the objectives are rows that never bind, most of them a
    /// smooth family.
    #[test]
    fn primal_simplex_reaches_the_cold_optimum() {
        let mut seed = 11u64;
        let (mut moved, mut lps) = (0usize, 0usize);
        for case in 0..300 {
            let mut rows: Vec<([f64; 4], f64)> = Vec::new();
            for sign in [1.0, -1.0] {
                for k in 0..4 {
                    let mut e = [0.0; 4];
                    e[k] = sign;
                    rows.push((e, -2.0 - uniform(&mut seed)));
                }
            }
            for _ in 0..(10 + case % 40) {
                let a = [0.0; 4].map(|_: f64| 2.0 * uniform(&mut seed) - 1.0);
                let c = -0.05 - uniform(&mut seed);
                rows.push((a, c));
                if case % 3 == 1 {
                    rows.push((a, c));
                }
            }
            if case % 3 == 2 {
                let apex = [0.0; 4].map(|_: f64| 0.01 * (2.0 * uniform(&mut seed) - 1.0));
                for _ in 0..6 {
                    let a = [0.0; 4].map(|_: f64| 2.0 * uniform(&mut seed) - 1.0);
                    rows.push((a, -(0..4).map(|k| a[k] * apex[k]).sum::<f64>()));
                }
            }
            let first = rows.len();
            let t0 = 6.0 * uniform(&mut seed);
            for i in 0..40 {
                let t = t0 + 0.05 * i as f64;
                let a = if i % 7 == 6 {
                    [0.0; 4].map(|_: f64| 2.0 * uniform(&mut seed) - 1.0)
                } else {
                    [
                        t.cos(),
                        t.sin() * (0.7 * t).cos(),
                        t.sin() * (0.7 * t).sin(),
                        0.3 * t.sin(),
                    ]
                };
                rows.push((a, -100.0));
            }
            let n = NormalisedRows::new(&rows);
            let mut last: Option<[usize; 4]> = None;
            for s in first..rows.len() {
                let cold = n.max_row(s, [0, 1, 2, 3], None, 1e-12).unwrap().unwrap();
                if let Some(from) = last {
                    let primal = primal_simplex(&n.a, &n.b, n.a[s], from, 1e-12)
                        .unwrap_or_else(|e| panic!("case {case} row {s}: {e:?}"));
                    // and `max_row` from that warm basis (the path the face search takes)
                    let warm = n
                        .max_row(s, [0, 1, 2, 3], Some(from), 1e-12)
                        .unwrap()
                        .unwrap();
                    let vc = value(&n, s, cold);
                    for (path, v) in [
                        ("primal", value(&n, s, primal)),
                        ("warm", value(&n, s, warm)),
                    ] {
                        assert!(
                            (vc - v).abs() <= 1e-9 * (1.0 + vc.abs()),
                            "case {case} row {s}: cold {vc} vs {path} {v}"
                        );
                    }
                    moved += usize::from(primal != from);
                    lps += 1;
                }
                last = Some(cold);
            }
        }
        assert!(moved > lps / 4, "{moved} of {lps} moved");
    }
}
