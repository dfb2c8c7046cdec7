//! The states at the static maximum of a discrete arch, whatever state the LP returned.
//!
//! At λ_static the admissible states form the optimal face F = P(λ_static) of the
//! polyhedron of admissible (x, λ): a point, or a polytope of dimension up to 3 (an edge
//! when λ_static is set by sliding rows, which do not involve w, and w is free between two
//! hinge rows). The LP returns one vertex of F, its back end's choice; the answer must
//! not depend on it. So F is determined whole, from its vertices (the points where the
//! sweep's vertices of P(λ) end, [`crate::limit_states::sweep::sweep_load_with_top`]),
//! and decided on it:
//!
//! * every face G of F (a vertex, an edge, ...) has one active set A_G — the rows active
//!   at all of G's vertices — on its relative interior, and the active set only grows
//!   towards G's own faces; a mechanism with positive live power on a set of contacts is
//!   one on every larger set (the other rates zero). So the limit states at λ_static are
//!   the union of the faces G whose A_G carries such a mechanism, and checking the faces
//!   spanned by the vertices (their active sets and the intersections of those) decides it;
//! * each maximal such face is reported once: a vertex as an isolated limit state; a face
//!   of dimension ≥ 1 as a continuum of limit states at λ_static (`continuum_to` =
//!   λ_static), by the centroid of its vertices with the contacts A_G;
//! * λ_static and the vertices are recomputed from the rows active at them (least squares,
//!   rows normalised; λ_static at the first vertex in the canonical order), so their last
//!   bits depend on the arch and not on the LP's pivoting either;
//! * the canonical order of the vertices: by their active rows, lexicographically in the
//!   order of [`crate::load::rows`] (joint by joint from the right springing). The first
//!   is the state reported with λ_static.

use super::limit_state::limit_state_on;
use crate::arch::Arch;
use crate::contact::Contact;
use crate::family::Tagged;
use crate::limit_states::sweep::{CheckedPoint, BOX, BOX_EDGE_REL};
use crate::limit_states::LimitState;
use crate::load::{LiveLoad, LoadRow, Side};
use crate::settings::Settings;
use crate::statics::{magnitude, Reactions};
use crate::undecided::Undecided;
use nalgebra::{DMatrix, DVector};

/// The optimal face at λ_static: λ_static and the distinct vertices of F in the canonical
/// order, each with the indices of its active rows.
#[derive(Debug, Clone)]
pub(super) struct Face {
    pub lambda: f64,
    pub vertices: Vec<(Reactions, Vec<usize>)>,
}

/// What holds at λ_static.
#[derive(Debug, Clone)]
pub(super) struct AtStatic {
    /// λ_static and the first vertex of F (the state reported there).
    pub state: (f64, Reactions),
    /// The maximal faces of F made of limit states, in the canonical order.
    pub limit_states: Vec<LimitState>,
    /// The vertices of F without a mechanism with positive live power (evidence), the
    /// first vertex excluded (a certificate describes it as the state at λ_static).
    pub without: Vec<CheckedPoint>,
}

/// The rows active at (x, λ): |φ| within `event_tol` of the row's magnitude (the sweep's
/// and the survey's test).
fn active(
    rows: &[LoadRow],
    eta: f64,
    mu: f64,
    x: &Reactions,
    lambda: f64,
    s: &Settings,
) -> Vec<usize> {
    (0..rows.len())
        .filter(|&i| {
            let r = &rows[i];
            let size = magnitude(r.contact.kind, eta, mu, x, s.magnitude_floor);
            r.at(x, lambda).abs() <= s.event_tol * size
        })
        .collect()
}

/// Least squares on the rows `which`, each scaled to a unit gradient in the unknowns:
/// (x, λ) when `lambda` is `None`, else x at that λ. `None` when the rows do not determine
/// the unknowns or do not meet at one point (a row active only to the tolerance).
fn solve(
    rows: &[LoadRow],
    which: &[usize],
    lambda: Option<f64>,
    settings: &Settings,
) -> Option<[f64; 4]> {
    let n = if lambda.is_some() { 3 } else { 4 };
    if which.len() < n {
        return None;
    }
    let mut m = DMatrix::zeros(which.len(), n);
    let mut b = DVector::zeros(which.len());
    for (r, &i) in which.iter().enumerate() {
        let row = &rows[i];
        let rhs = -row.c - lambda.map_or(0.0, |l| row.a[3] * l);
        let norm = row.a[..n].iter().map(|v| v * v).sum::<f64>().sqrt();
        if norm == 0.0 {
            return None;
        }
        for k in 0..n {
            m[(r, k)] = row.a[k] / norm;
        }
        b[r] = rhs / norm;
    }
    let svd = m.clone().svd(true, true);
    let (smax, smin) = (svd.singular_values.max(), svd.singular_values.min());
    if smin.is_nan() || smin <= settings.rank_tol * smax {
        return None;
    }
    let z = svd.solve(&b, 0.0).ok()?;
    let scale = 1.0 + z.iter().map(|v| v.abs()).sum::<f64>();
    let residual = (&m * &z - &b).amax();
    if residual.is_nan() || residual > settings.same_root * scale {
        return None;
    }
    Some([z[0], z[1], z[2], lambda.unwrap_or_else(|| z[3])])
}

/// At most this many vertices of F are visited by [`walk`] (a safety net).
const MAX_FACE_VERTICES: usize = 256;

/// The vertices of P(λ) = F at λ = `lambda`, by a walk on its vertex graph from `start` (a
/// vertex, the LP's state): at each vertex, every direction along two of its active rows'
/// planes that keeps every active row ≤ 0 (within `event_tol` of its gradient) is an
/// edge of F, followed to the first other row (a ratio test); an edge that meets none is a
/// ray (F unbounded: its vertices are still returned). F may be lower-dimensional (rows
/// that are equalities on it are active at every vertex, and the test keeps the walk
/// inside them), which the sweep's full-dimensional walk does not allow.
pub(super) fn walk(
    rows: &[LoadRow],
    eta: f64,
    mu: f64,
    lambda: f64,
    start: Reactions,
    settings: &Settings,
) -> Vec<Reactions> {
    let g: Vec<[f64; 3]> = rows.iter().map(|r| [r.a[0], r.a[1], r.a[2]]).collect();
    let dot = |a: &[f64; 3], b: &[f64; 3]| a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
    let norm = |a: &[f64; 3]| dot(a, a).sqrt();
    let mut seen: Vec<Vec<usize>> = Vec::new();
    let mut out = Vec::new();
    let mut queue = vec![start];
    while let Some(x) = queue.pop() {
        let act = active(rows, eta, mu, &x, lambda, settings);
        if seen.contains(&act) || seen.len() >= MAX_FACE_VERTICES {
            continue;
        }
        seen.push(act.clone());
        out.push(x);
        for (ip, &p) in act.iter().enumerate() {
            for &q in &act[ip + 1..] {
                let (a, b) = (g[p], g[q]);
                let d0 = [
                    a[1] * b[2] - a[2] * b[1],
                    a[2] * b[0] - a[0] * b[2],
                    a[0] * b[1] - a[1] * b[0],
                ];
                let dn = norm(&d0);
                if dn <= settings.rank_tol * norm(&a) * norm(&b) {
                    continue; // parallel planes (twins, or one joint's two slides)
                }
                for sign in [1.0, -1.0] {
                    let d = d0.map(|v| sign * v / dn);
                    // inside every active row, and leaving at least one
                    let rate = |i: usize| dot(&g[i], &d);
                    let tol = |i: usize| settings.event_tol * norm(&g[i]);
                    if act.iter().any(|&i| rate(i) > tol(i))
                        || act.iter().all(|&i| rate(i) >= -tol(i))
                    {
                        continue;
                    }
                    let mut step: Option<f64> = None;
                    for i in (0..rows.len()).filter(|i| !act.contains(i)) {
                        if rate(i) <= tol(i) {
                            continue;
                        }
                        let t = (-rows[i].at(&x, lambda)).max(0.0) / rate(i);
                        if step.is_none_or(|s| t < s) {
                            step = Some(t);
                        }
                    }
                    if let Some(t) = step {
                        queue.push([0, 1, 2].map(|k| x[k] + t * d[k]));
                    }
                }
            }
        }
    }
    out
}

/// The vertices of F from `points` (the sweep's points at the top, or the LP's state):
/// those inside the box and admissible at `lambda_lp`, one per active set, recomputed on
/// their active rows, in the canonical order. λ_static is recomputed at the first; where a
/// recomputation does not meet the rows (a row active only to the tolerance) or moves
/// λ_static by more than `root_slack`, the LP's λ_static and the sweep's points stand.
pub(super) fn face(
    rows: &[LoadRow],
    eta: f64,
    mu: f64,
    lambda_lp: f64,
    points: &[Reactions],
    settings: &Settings,
) -> Face {
    let mut vertices: Vec<(Reactions, Vec<usize>)> = Vec::new();
    for x in points {
        if x.iter()
            .any(|v| !v.is_finite() || v.abs() >= BOX * (1.0 - BOX_EDGE_REL))
        {
            continue;
        }
        let inside = rows.iter().all(|r| {
            let size = magnitude(r.contact.kind, eta, mu, x, settings.magnitude_floor);
            r.at(x, lambda_lp) <= settings.event_tol * size
        });
        let act = active(rows, eta, mu, x, lambda_lp, settings);
        if inside && !vertices.iter().any(|(_, a)| *a == act) {
            vertices.push((*x, act));
        }
    }
    vertices.sort_by(|p, q| p.1.cmp(&q.1));
    let lambda = vertices
        .first()
        .and_then(|(_, act)| solve(rows, act, None, settings))
        .map(|z| z[3])
        .filter(|l| (l - lambda_lp).abs() <= settings.root_slack * lambda_lp.abs().max(1.0))
        .unwrap_or(lambda_lp);
    for (x, act) in vertices.iter_mut() {
        if let Some(z) = solve(rows, act, Some(lambda), settings) {
            let tol = settings.event_tol * (1.0 + x.iter().map(|v| v.abs()).sum::<f64>());
            if (0..3).all(|k| (z[k] - x[k]).abs() <= tol) {
                *x = [z[0], z[1], z[2]];
            }
        }
    }
    Face { lambda, vertices }
}

/// Decides F: every maximal face of F whose active set carries a mechanism with positive
/// live power (see the module's notes), and the vertices that carry none. No vertex (none
/// inside the box) is no decision.
pub(super) fn decide(
    arch: &Arch,
    eta: f64,
    mu: f64,
    load: &LiveLoad,
    rows: &[LoadRow],
    face: &Face,
    settings: &Settings,
) -> Result<AtStatic, Undecided> {
    let lambda = face.lambda;
    let verts = &face.vertices;
    let Some(first) = verts.first() else {
        return Err(Undecided::Resolution(
            "no vertex of the admissible states at lambda_static".into(),
        ));
    };
    // the faces spanned by the vertices: their active sets, closed under intersection
    let mut faces: Vec<Vec<usize>> = verts.iter().map(|v| v.1.clone()).collect();
    let mut i = 0;
    while i < faces.len() {
        for j in 0..i {
            let common: Vec<usize> = faces[i]
                .iter()
                .copied()
                .filter(|r| faces[j].contains(r))
                .collect();
            if !faces.contains(&common) {
                faces.push(common);
            }
        }
        i += 1;
    }
    let pattern_of = |act: &[usize]| -> Vec<Tagged<Side>> {
        act.iter()
            .map(|&r| (rows[r].contact, rows[r].side))
            .collect()
    };
    let vertices_of = |act: &[usize]| -> Vec<usize> {
        (0..verts.len())
            .filter(|&v| act.iter().all(|r| verts[v].1.contains(r)))
            .collect()
    };
    let mut limit: Vec<(Vec<usize>, LimitState)> = Vec::new();
    let mut carries = vec![false; verts.len()];
    for act in &faces {
        let on = vertices_of(act);
        let n = on.len() as f64;
        let centroid: Reactions =
            [0, 1, 2].map(|k| on.iter().map(|&v| verts[v].0[k]).sum::<f64>() / n);
        let found = limit_state_on(
            arch,
            eta,
            mu,
            load,
            (lambda, centroid),
            &pattern_of(act),
            settings,
        )?;
        if let Some(mut s) = found {
            if on.len() > 1 {
                s.continuum_to = Some(lambda);
            }
            for &v in &on {
                carries[v] = true;
            }
            limit.push((act.clone(), s));
        }
    }
    // maximal: no other limit face whose active set is a proper subset
    let maximal: Vec<LimitState> = limit
        .iter()
        .filter(|(a, _)| {
            !limit
                .iter()
                .any(|(b, _)| b.len() < a.len() && b.iter().all(|r| a.contains(r)))
        })
        .map(|(_, s)| s.clone())
        .collect();
    let without = (1..verts.len())
        .filter(|&v| !carries[v])
        .map(|v| checked_point(rows, lambda, &verts[v]))
        .collect();
    Ok(AtStatic {
        state: (lambda, first.0),
        limit_states: maximal,
        without,
    })
}

/// A vertex without a mechanism, as the sweep records one: its contacts by increasing
/// (β, side, kind).
fn checked_point(
    rows: &[LoadRow],
    lambda: f64,
    (x, act): &(Reactions, Vec<usize>),
) -> CheckedPoint {
    let mut pattern: Vec<(Contact, Side)> = act
        .iter()
        .map(|&r| (rows[r].contact, rows[r].side))
        .collect();
    pattern.sort_by(|a, b| {
        a.0.beta
            .total_cmp(&b.0.beta)
            .then((a.1 == Side::After).cmp(&(b.1 == Side::After)))
            .then(a.0.kind.cmp(&b.0.kind))
    });
    CheckedPoint {
        eta: lambda,
        x: *x,
        pattern: pattern.iter().map(|p| p.0).collect(),
        sides: pattern.iter().map(|p| p.1).collect(),
    }
}
