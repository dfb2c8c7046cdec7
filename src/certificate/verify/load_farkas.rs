//! The Farkas certificates of a load certificate: at λ_hi in x = (h, v, w), or over every
//! λ ≥ 0 in (h, v, w, λ), with the coordinates that do not enter the rows left out; proved
//! by the signed cofactors of [`super::farkas`].

use super::farkas::prove_cofactors;
use super::joints::check_farkas_joint;
use super::live::{side_text, Live};
use super::report::{reject, Rejection};
use super::statics::{affine, phi, Model};
use crate::certificate::format::{CertJoint, LoadFarkas};
use crate::certificate::interval::Interval as I;

/// The live part per unit λ of the activation function `kind` at the joint β on `side`
/// (zero where the section does not carry the load).
fn live_row(model: &Model, live: &Live, j: &CertJoint, mu: Option<f64>) -> I {
    match live.ntm(model, I::point(j.beta), live.carries(j.beta, j.side)) {
        Some(l) => phi(j.kind, 0, &l, live.eta, mu),
        None => I::point(0.0),
    }
}

fn labels(joints: &[CertJoint]) -> Vec<(f64, String)> {
    joints
        .iter()
        .map(|j| (j.y, format!("beta = {}{}", j.beta, side_text(j.side))))
        .collect()
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
    let mut stored = labels(&f.joints);
    if let Some(y) = f.lambda_row {
        stored.push((y, "the row -lambda <= 0".to_string()));
    }
    prove_cofactors(&rows, &stored)
}

/// The Farkas certificate at λ_hi: four rows in x = (h, v, w) (three sliding rows in
/// (h, v)), constants with the live terms at λ_hi.
pub(super) fn prove_farkas_at(
    model: &Model,
    live: &Live,
    f: &LoadFarkas,
    lambda: f64,
    mu: Option<f64>,
) -> Result<f64, Rejection> {
    if f.lambda_row.is_some() {
        return reject(
            "collapse side: the row -lambda <= 0 belongs to a no_equilibrium certificate only",
        );
    }
    let rows: Vec<(Vec<I>, I)> = f
        .joints
        .iter()
        .map(|j| {
            let (g, c) = affine(model, j.kind, j.beta, live.eta, mu.unwrap_or(0.0));
            (
                g.to_vec(),
                c + I::point(lambda) * live_row(model, live, j, mu),
            )
        })
        .collect();
    prove_reduced(model, live, f, mu, rows, false)
}

/// The Farkas certificate over every λ ≥ 0: five rows in (h, v, w, λ) — the joints', and
/// −λ ≤ 0 when `lambda_row` is given — or fewer where w or λ does not enter them.
pub(super) fn prove_farkas_any(
    model: &Model,
    live: &Live,
    f: &LoadFarkas,
    mu: Option<f64>,
) -> Result<f64, Rejection> {
    let mut rows: Vec<(Vec<I>, I)> = f
        .joints
        .iter()
        .map(|j| {
            let (g, c) = affine(model, j.kind, j.beta, live.eta, mu.unwrap_or(0.0));
            (vec![g[0], g[1], g[2], live_row(model, live, j, mu)], c)
        })
        .collect();
    if let Some(y) = f.lambda_row {
        if !y.is_finite() {
            return reject("collapse side: the multiplier of -lambda <= 0 is not a finite number");
        }
        let z = I::point(0.0);
        rows.push((vec![z, z, z, I::point(-1.0)], z));
    }
    prove_reduced(model, live, f, mu, rows, true)
}
