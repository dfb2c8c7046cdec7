//! The infeasible side of a certificate: a Farkas certificate over the rows of its joints —
//! at η_lo (thickness), at λ_hi, or over every λ ≥ 0 in (h, v, w, λ) (load) — proved from the
//! signed cofactors of the rows' gradients, in interval arithmetic, with the coordinates that
//! do not enter the rows left out.

use super::joints::check_farkas_joint;
use super::live::{side_text, Live};
use super::report::{reject, Rejection};
use super::statics::{affine, phi, Model};
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
    let (g, c) = affine(model, j.kind, j.beta, eta, mu.unwrap_or(0.0));
    let l = live
        .and_then(|live| live.ntm(model, I::point(j.beta), live.carries(j.beta, j.side)))
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
    let mut stored: Vec<(f64, String)> = joints
        .iter()
        .map(|j| (j.y, format!("beta = {}{}", j.beta, side_text(j.side))))
        .collect();
    if let Some(y) = lambda_row {
        stored.push((y, "the row -lambda <= 0".to_string()));
    }
    prove_cofactors(&rows, &stored)
}

/// Proves that the Farkas joints rule out every state at η (or, with `friction_only`,
/// every (h, v) for the sliding conditions alone, w left out).
pub(super) fn prove_farkas(
    model: &Model,
    joints: &[CertJoint],
    eta: f64,
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
        check_farkas_joint(model, i, j, mu, None)?;
        if friction_only && j.kind.is_hinge() {
            return reject(format!(
                "collapse side: joint {i} is {}, but the friction-only certificate may use sliding joints only",
                j.kind.name()
            ));
        }
    }
    let rows = joints
        .iter()
        .map(|j| {
            let (g, c, _) = joint_row(model, None, j, eta, mu);
            (g.to_vec(), c)
        })
        .collect();
    prove_rows(rows, if friction_only { &[2] } else { &[] }, joints, None)
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
        check_farkas_joint(model, i, j, mu, live.split())?;
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
    let point = live.split().is_some();
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
    let d = rows.len() - 1;
    let y: Vec<I> = (0..=d)
        .map(|i| {
            let cols: Vec<usize> = (0..=d).filter(|&k| k != i).collect();
            let sign = if i % 2 == 0 { 1.0 } else { -1.0 };
            let g = |k: usize, r: usize| rows[cols[k]].0[r];
            let det = match d {
                4 => det4([0, 1, 2, 3].map(|k| [0, 1, 2, 3].map(|r| g(k, r)))),
                3 => det3([0, 1, 2].map(|k| [0, 1, 2].map(|r| g(k, r)))),
                _ => det2([[g(0, 0), g(0, 1)], [g(1, 0), g(1, 1)]]),
            };
            det.scale(sign)
        })
        .collect();
    let positive = y.iter().all(|v| v.lo > 0.0);
    let negative = y.iter().all(|v| v.hi < 0.0);
    if !positive && !negative {
        return reject("collapse side: the exact Farkas multipliers do not share a sign (or are not resolved): no proof");
    }
    let y: Vec<I> = if negative {
        y.iter().map(|v| -*v).collect()
    } else {
        y
    };
    // the stored multipliers must be the recomputed ones (normalised to sum 1), to the
    // width of their enclosure (a few times over: `certify` computes them from its own
    // rounding of the same rows) and a rounding of the normalisation: an edited digit is
    // rejected, though it would prove nothing false
    let total: f64 = y.iter().map(|v| v.mid()).sum();
    let stored_total: f64 = stored.iter().map(|s| s.0).sum();
    for ((sy, label), v) in stored.iter().zip(&y) {
        let (a, b) = (v.mid() / total, sy / stored_total);
        let allowed = MULTIPLIER_WIDTHS * (v.hi - v.lo) / total + MULTIPLIER_REL * (1.0 + a.abs());
        if stored_total.is_nan() || stored_total <= 0.0 || (a - b).abs() > allowed || *sy < 0.0 {
            return reject(format!("collapse side: stored multiplier {sy} at {label} does not match the recomputed {a:.9e} (normalised)"));
        }
    }
    let c = y
        .iter()
        .zip(rows)
        .fold(I::point(0.0), |acc, (yi, (_, ci))| acc + *yi * *ci);
    if c.lo.is_nan() || c.lo <= 0.0 {
        return reject(format!(
            "collapse side: sum y_i phi_i(0) = [{:e}, {:e}] is not proved > 0",
            c.lo, c.hi
        ));
    }
    Ok(c.lo / total)
}
