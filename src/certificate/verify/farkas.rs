//! The collapse side of a thickness certificate: a Farkas certificate proved from the
//! signed cofactors of its rows' gradients, in interval arithmetic (shared with the load
//! certificates, [`super::load_farkas`]).

use super::joints::check_farkas_joint;
use super::report::{reject, Rejection};
use super::statics::{affine, Model};
use crate::certificate::format::CertJoint;
use crate::certificate::interval::{det2, det3, det4, Interval as I};

/// Proves that the Farkas joints rule out every state at η (or, with `friction_only`,
/// every (h, v) for the sliding conditions alone).
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
    let mut aff: Vec<([I; 3], I)> = Vec::with_capacity(joints.len());
    for (i, j) in joints.iter().enumerate() {
        check_farkas_joint(model, i, j, mu, None)?;
        if friction_only && j.kind.is_hinge() {
            return reject(format!(
                "collapse side: joint {i} is {}, but the friction-only certificate may use sliding joints only",
                j.kind.name()
            ));
        }
        // `exists` guarantees a finite μ for sliding rows; hinge rows do not use it
        aff.push(affine(model, j.kind, j.beta, eta, mu.unwrap_or(0.0)));
    }
    let rows: Vec<(Vec<I>, I)> = aff.iter().map(|(g, c)| (g[..d].to_vec(), *c)).collect();
    let stored: Vec<(f64, String)> = joints
        .iter()
        .map(|j| (j.y, format!("beta = {}", j.beta)))
        .collect();
    prove_cofactors(&rows, &stored)
}

/// The Farkas proof for d + 1 affine rows `g · u + c ≤ 0` in d unknowns (d = 2, 3 or 4):
/// the exact multipliers are the signed cofactors of the gradients, enclosed in
/// intervals; they must share a sign, match the `stored` ones (normalised to sum 1; each
/// with a label for the messages), and give Σ yᵢ cᵢ > 0 rigorously, so that
/// Σ yᵢ rowᵢ(u) = Σ yᵢ cᵢ > 0 for every u: no u satisfies all rows. Returns the margin
/// Σ yᵢ cᵢ / Σ yᵢ (lower bound).
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
    // the stored multipliers must be the recomputed ones (normalised to sum 1)
    let total: f64 = y.iter().map(|v| v.mid()).sum();
    let stored_total: f64 = stored.iter().map(|s| s.0).sum();
    for ((sy, label), v) in stored.iter().zip(&y) {
        let (a, b) = (v.mid() / total, sy / stored_total);
        if stored_total.is_nan()
            || stored_total <= 0.0
            || (a - b).abs() > 1e-6 * (1.0 + a.abs())
            || *sy < 0.0
        {
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
