//! The infeasible side of a certificate: a Farkas certificate over the rows of its joints —
//! at η_lo (thickness), at λ_hi, or over every λ ≥ 0 in (h, v, w, λ) (load) — proved from the
//! signed cofactors of the rows' gradients, in interval arithmetic, with the coordinates that
//! do not enter the rows left out.

use super::joints::check_farkas_joint;
use super::live::{section, side_text, Live};
use super::report::{reject, Rejection};
use super::statics::{affine, affine_times_eta, phi, Model};
use crate::certificate::format::{CertJoint, LoadFarkas};
use crate::certificate::interval::{det2, det3, det4, Interval as I};

/// The row of a Farkas joint at thickness `eta`: its gradient in x = (h, v, w), its constant,
/// and its live part per unit λ (zero without a load, or where the section does not carry
/// the load).
fn joint_row(
    model: &Model,
    live: Option<&Live>,
    j: &CertJoint,
    eta: f64,
    mu: Option<f64>,
) -> ([I; 3], I, I) {
    // `exists` guarantees a finite μ for sliding rows; hinge rows do not use it
    let (g, c) = affine(model, j.kind, j.beta, I::point(eta), mu.unwrap_or(0.0));
    let l = live
        .and_then(|live| live.ntm(model, I::point(j.beta), section(j.beta, j.side)))
        .map_or(I::point(0.0), |l| phi(j.kind, 0, &l, eta, mu));
    (g, c, l)
}

/// The Farkas proof over `rows` (full gradients) with the coordinates `dropped` left out,
/// the joints' multipliers stored in `joints` and, when given, that of the row −λ ≤ 0 (the
/// last row).
fn prove_rows(
    rows: Vec<(Vec<I>, I)>,
    dropped: &[usize],
    joints: &[CertJoint],
    lambda_row: Option<f64>,
) -> Result<f64, Rejection> {
    let rows: Vec<(Vec<I>, I)> = rows
        .into_iter()
        .map(|(g, c)| {
            let g = g
                .into_iter()
                .enumerate()
                .filter(|(k, _)| !dropped.contains(k))
                .map(|(_, v)| v)
                .collect();
            (g, c)
        })
        .collect();
    prove_cofactors(&rows, &stored_of(joints, lambda_row))
}

/// The stored multipliers of the joints (and of the row −λ ≤ 0, when given), each with a
/// label for the messages.
fn stored_of(joints: &[CertJoint], lambda_row: Option<f64>) -> Vec<(f64, String)> {
    let mut stored: Vec<(f64, String)> = joints
        .iter()
        .map(|j| (j.y, format!("beta = {}{}", j.beta, side_text(j.side))))
        .collect();
    if let Some(y) = lambda_row {
        stored.push((y, "the row -lambda <= 0".to_string()));
    }
    stored
}

/// Proves that the Farkas joints rule out every state at every η in `eta` (a point, or a
/// cell; with `friction_only`, every (h, v) for the sliding conditions alone, w left out:
/// without fill T and N do not involve η, and `eta` is any point).
pub(super) fn prove_farkas(
    model: &Model,
    joints: &[CertJoint],
    eta: I,
    mu: Option<f64>,
    friction_only: bool,
) -> Result<f64, Rejection> {
    let d = if friction_only { 2 } else { 3 };
    if joints.len() != d + 1 {
        return reject(format!(
            "collapse side: a Farkas certificate here needs exactly {} joints, found {}",
            d + 1,
            joints.len()
        ));
    }
    for (i, j) in joints.iter().enumerate() {
        check_farkas_joint(model, i, j, mu, &[])?;
        if friction_only && j.kind.is_hinge() {
            return reject(format!(
                "collapse side: joint {i} is {}, but the friction-only certificate may use sliding joints only",
                j.kind.name()
            ));
        }
    }
    let cell = eta.lo < eta.hi;
    // over a cell with fill, the rows times η: the fill's 1/η leaves them, so the
    // enclosures stay tight and a cell may reach η = 0
    let row = match cell && model.fill.is_some() {
        true => affine_times_eta,
        false => affine,
    };
    // `exists` (checked above) guarantees a finite μ for sliding rows
    let at = |e: I| -> Vec<(Vec<I>, I)> {
        joints
            .iter()
            .map(|j| {
                let (g, c) = row(model, j.kind, j.beta, e, mu.unwrap_or(0.0));
                (g.to_vec(), c)
            })
            .collect()
    };
    // the sliding rows' gradients do not depend on η: over a cell, only their constants
    // are enclosed over it
    if cell && !friction_only {
        return prove_over_cell(joints, eta, at);
    }
    prove_rows(
        at(eta),
        if friction_only { &[2] } else { &[] },
        joints,
        None,
    )
}

/// The Farkas proof over a cell of η, the multipliers in centred form about the cell's
/// middle m (|η − m| ≤ `half`, rounded up): the hinge rows' gradients ±∇M − (η/2)∇N have
/// the slope −∇N/2 in η, the sliding rows' none.
fn prove_over_cell(
    joints: &[CertJoint],
    eta: I,
    at: impl Fn(I) -> Vec<(Vec<I>, I)>,
) -> Result<f64, Rejection> {
    let m = 0.5 * (eta.lo + eta.hi);
    let half = (eta.hi - m).max(m - eta.lo).next_up();
    let grads =
        |rows: &[(Vec<I>, I)]| -> Vec<Vec<I>> { rows.iter().map(|r| r.0.clone()).collect() };
    let (mid, over) = (at(I::point(m)), at(eta));
    let slopes: Vec<Vec<I>> = joints
        .iter()
        .map(|j| {
            let b = I::point(j.beta);
            match j.kind.is_hinge() {
                true => vec![b.sin().scale(-0.5), b.cos().scale(-0.5), I::point(0.0)],
                false => vec![I::point(0.0); 3],
            }
        })
        .collect();
    let y = cofactors_over(&grads(&mid), &grads(&over), &slopes, half);
    let consts: Vec<I> = over.iter().map(|r| r.1).collect();
    let at_mid = cofactors(&grads(&mid));
    prove_multipliers(y, Some(at_mid), &consts, &stored_of(joints, None))
}

/// The Farkas proof for rows over the unknowns (h, v, w) — and λ when `with_lambda` — after
/// leaving out the coordinates that do not enter them: w when every joint slides (T and N
/// do not involve w); λ, when the row −λ ≤ 0 is not used, if no joint's section carries
/// the point load (their λ-coefficients are zero) or if every one does (a point load enters
/// the sections that carry it only through x − λ d, d = (0, 1, (1 + η/2) cos β_P − cos β_R):
/// the live actions there are minus the weightless actions of d — an identity of the
/// statics — so a certificate in x covers every (x, λ)). The certificate must have one row
/// more than the coordinates kept; `rows` are (gradient, constant) with the full gradient.
fn prove_reduced(
    model: &Model,
    live: &Live,
    f: &LoadFarkas,
    mu: Option<f64>,
    rows: Vec<(Vec<I>, I)>,
    with_lambda: bool,
) -> Result<f64, Rejection> {
    for (i, j) in f.joints.iter().enumerate() {
        check_farkas_joint(model, i, j, mu, live.splits())?;
    }
    let mut dropped = Vec::new();
    if f.joints.iter().all(|j| !j.kind.is_hinge()) {
        dropped.push(2); // w
    }
    let carried: Vec<bool> = f
        .joints
        .iter()
        .map(|j| live.carries(j.beta, j.side))
        .collect();
    let point = live.point().is_some();
    if with_lambda
        && f.lambda_row.is_none()
        && (carried.iter().all(|c| !c) || (point && carried.iter().all(|&c| c)))
    {
        dropped.push(3); // λ
    }
    let unknowns = if with_lambda { 4 } else { 3 } - dropped.len();
    if rows.len() != unknowns + 1 {
        return reject(format!(
            "collapse side: a Farkas certificate here needs exactly {} rows ({} unknowns{}), found {}",
            unknowns + 1,
            unknowns,
            if dropped.is_empty() {
                String::new()
            } else {
                format!(
                    " once {} left out: they do not enter these rows",
                    dropped
                        .iter()
                        .map(|&k| if k == 2 { "w" } else { "lambda" })
                        .collect::<Vec<_>>()
                        .join(" and ")
                )
            },
            rows.len()
        ));
    }
    prove_rows(rows, &dropped, &f.joints, f.lambda_row)
}

/// The Farkas certificate of a load certificate: at λ_hi (`lambda`), four rows in
/// x = (h, v, w) (three sliding rows in (h, v)), constants with the live terms at λ_hi; or,
/// without `lambda`, over every λ ≥ 0: five rows in (h, v, w, λ) — the joints', and −λ ≤ 0
/// when `lambda_row` is given — or fewer where w or λ does not enter them.
pub(super) fn prove_infeasible(
    model: &Model,
    live: &Live,
    f: &LoadFarkas,
    lambda: Option<f64>,
    mu: Option<f64>,
) -> Result<f64, Rejection> {
    let row = |j: &CertJoint| joint_row(model, Some(live), j, live.eta, mu);
    let Some(lambda) = lambda else {
        let mut rows: Vec<(Vec<I>, I)> = f
            .joints
            .iter()
            .map(|j| {
                let (g, c, l) = row(j);
                (vec![g[0], g[1], g[2], l], c)
            })
            .collect();
        if let Some(y) = f.lambda_row {
            if !y.is_finite() {
                return reject(
                    "collapse side: the multiplier of -lambda <= 0 is not a finite number",
                );
            }
            let z = I::point(0.0);
            rows.push((vec![z, z, z, I::point(-1.0)], z));
        }
        return prove_reduced(model, live, f, mu, rows, true);
    };
    if f.lambda_row.is_some() {
        return reject(
            "collapse side: the row -lambda <= 0 belongs to a no_equilibrium certificate only",
        );
    }
    let rows = f
        .joints
        .iter()
        .map(|j| {
            let (g, c, l) = row(j);
            (g.to_vec(), c + I::point(lambda) * l)
        })
        .collect();
    prove_reduced(model, live, f, mu, rows, false)
}

/// The Farkas proof for d + 1 affine rows `g · u + c ≤ 0` in d unknowns (d = 2, 3 or 4):
/// the exact multipliers are the signed cofactors of the gradients, enclosed in
/// intervals; they must share a sign, match the `stored` ones (normalised to sum 1; each
/// with a label for the messages), and give Σ yᵢ cᵢ > 0 rigorously, so that
/// Σ yᵢ rowᵢ(u) = Σ yᵢ cᵢ > 0 for every u: no u satisfies all rows. Returns the margin
/// Σ yᵢ cᵢ / Σ yᵢ (lower bound).
/// A stored Farkas multiplier may differ from the recomputed one by this many widths of
/// its interval enclosure ...
const MULTIPLIER_WIDTHS: f64 = 16.0;

/// ... plus this much relative to it.
const MULTIPLIER_REL: f64 = 1e-12;

pub(super) fn prove_cofactors(
    rows: &[(Vec<I>, I)],
    stored: &[(f64, String)],
) -> Result<f64, Rejection> {
    let grads: Vec<Vec<I>> = rows.iter().map(|r| r.0.clone()).collect();
    let consts: Vec<I> = rows.iter().map(|r| r.1).collect();
    prove_multipliers(cofactors(&grads), None, &consts, stored)
}

/// The signed cofactors of d + 1 gradients in d unknowns (d = 2, 3 or 4): the exact
/// multipliers of their Farkas combination, up to a common factor.
fn cofactors(grads: &[Vec<I>]) -> Vec<I> {
    let d = grads.len() - 1;
    (0..=d)
        .map(|i| {
            let cols: Vec<usize> = (0..=d).filter(|&k| k != i).collect();
            let sign = if i % 2 == 0 { 1.0 } else { -1.0 };
            let g = |k: usize, r: usize| grads[cols[k]][r];
            let det = match d {
                4 => det4([0, 1, 2, 3].map(|k| [0, 1, 2, 3].map(|r| g(k, r)))),
                3 => det3([0, 1, 2].map(|k| [0, 1, 2].map(|r| g(k, r)))),
                _ => det2([[g(0, 0), g(0, 1)], [g(1, 0), g(1, 1)]]),
            };
            det.scale(sign)
        })
        .collect()
}

/// The cofactors over a cell of η in centred (mean-value) form, y(E) ⊂ y(m) + y'(E)(E − m):
/// each gradient is affine in η (`over` the cell, at its middle `at_mid`, slope `slopes`),
/// so y' is the sum over the rows of the cofactors with that row's gradient replaced by its
/// slope. The naive enclosure over the cell loses a small multiplier in the dependency of
/// the entries on η; this one keeps it to the width of its true variation.
fn cofactors_over(at_mid: &[Vec<I>], over: &[Vec<I>], slopes: &[Vec<I>], half: f64) -> Vec<I> {
    let mut dy = vec![I::point(0.0); over.len()];
    for (k, slope) in slopes.iter().enumerate() {
        if slope.iter().all(|v| v.lo == 0.0 && v.hi == 0.0) {
            continue;
        }
        let mut g = over.to_vec();
        g[k].clone_from(slope);
        for (i, c) in cofactors(&g).into_iter().enumerate() {
            // the cofactor of row k itself does not contain row k
            if i != k {
                dy[i] = dy[i] + c;
            }
        }
    }
    let spread = I::new(-half, half);
    cofactors(at_mid)
        .into_iter()
        .zip(dy)
        .map(|(y, dy)| y + dy * spread)
        .collect()
}

/// The Farkas proof from the multipliers `y` (exact, enclosed) and the rows' constants: the
/// multipliers must share a sign, the `stored` ones must match `matched` (the multipliers
/// at one point: `y` itself, or at a cell's middle), and Σ yᵢ cᵢ > 0.
fn prove_multipliers(
    y: Vec<I>,
    matched: Option<Vec<I>>,
    consts: &[I],
    stored: &[(f64, String)],
) -> Result<f64, Rejection> {
    let positive = y.iter().all(|v| v.lo > 0.0);
    let negative = y.iter().all(|v| v.hi < 0.0);
    if !positive && !negative {
        return reject("collapse side: the exact Farkas multipliers do not share a sign (or are not resolved): no proof");
    }
    let flip = |y: Vec<I>| -> Vec<I> {
        match negative {
            true => y.iter().map(|v| -*v).collect(),
            false => y,
        }
    };
    let matched = flip(matched.unwrap_or_else(|| y.clone()));
    let y = flip(y);
    // the stored multipliers must be the recomputed ones (normalised to sum 1), to the
    // width of their enclosure (a few times over: `certify` computes them from its own
    // rounding of the same rows) and a rounding of the normalisation: an edited digit is
    // rejected, though it would prove nothing false
    let total: f64 = matched.iter().map(|v| v.mid()).sum();
    let stored_total: f64 = stored.iter().map(|s| s.0).sum();
    for ((sy, label), v) in stored.iter().zip(&matched) {
        let (a, b) = (v.mid() / total, sy / stored_total);
        let allowed = MULTIPLIER_WIDTHS * (v.hi - v.lo) / total + MULTIPLIER_REL * (1.0 + a.abs());
        if stored_total.is_nan() || stored_total <= 0.0 || (a - b).abs() > allowed || *sy < 0.0 {
            return reject(format!("collapse side: stored multiplier {sy} at {label} does not match the recomputed {a:.9e} (normalised)"));
        }
    }
    let c = y
        .iter()
        .zip(consts)
        .fold(I::point(0.0), |acc, (yi, ci)| acc + *yi * *ci);
    if c.lo.is_nan() || c.lo <= 0.0 {
        return reject(format!(
            "collapse side: sum y_i phi_i(0) = [{:e}, {:e}] is not proved > 0",
            c.lo, c.hi
        ));
    }
    Ok(c.lo / y.iter().map(|v| v.mid()).sum::<f64>())
}
