//! Every point of the ridge over ∂Q where a limit state may be: the apexes of Q (V2) and
//! the points the walk along each sliding edge returns (V, E1, E2), once Q is known to
//! have no three sliding lines through a vertex (G1).

use super::polygon::{lines, on_box, q_polygon, Line};
use super::rows::{ev, hinge_rows, in_band, Candidate, JointRows, TOL};
use super::walk::walk_edge;
use crate::arch::ETA_TOP;
use crate::kinematics::column;
use crate::undecided::Undecided;

/// An edge of Q shorter (ℓ₁) than this times 1 + the size of its start is not walked.
const SHORT_EDGE_REL: f64 = 1e-12;

/// A vertex of Q with the index (in the lines) of the edge that leaves it.
type QVertex = ([f64; 2], usize);

/// 1 + |h| + |v|: the size the walk's tests at p are relative to.
fn scale(p: [f64; 2]) -> f64 {
    1.0 + p[0].abs() + p[1].abs()
}

/// Every candidate on the ridge with η in (eta_lo, ETA_TOP).
pub(super) fn candidates(
    js: &[JointRows],
    mu: f64,
    eta_lo: f64,
) -> Result<Vec<Candidate>, Undecided> {
    let lines = lines(js, mu);
    let poly = q_polygon(&lines);
    if poly.len() < 3 {
        return Err(Undecided::Resolution(
            "the friction polygon Q has no interior".into(),
        ));
    }
    no_third_line(&lines, &poly)?;
    let in_range = |eta: f64| eta > eta_lo && eta < ETA_TOP;
    let mut out = apexes(js, &lines, &poly, &in_range);
    along_edges(js, &lines, &poly, &in_range, &mut out)?;
    Ok(out)
}

/// G1: no third sliding line through a vertex of Q (a pure-sliding mechanism may then
/// hold over an interval of η, and the pair of lines would not define the vertex).
pub(super) fn no_third_line(lines: &[Line], poly: &[QVertex]) -> Result<(), Undecided> {
    for &(q, _) in poly {
        if on_box(q) {
            continue;
        }
        let through = lines
            .iter()
            .filter(|l| l.slide.is_some())
            .filter(|l| {
                let na = l.a[0].abs() + l.a[1].abs();
                (l.a[0] * q[0] + l.a[1] * q[1] + l.b).abs() <= TOL * na * scale(q)
            })
            .count();
        if through > 2 {
            return Err(Undecided::NotCovered(format!(
                "{through} sliding lines meet at the vertex ({}, {}) of Q",
                q[0], q[1]
            )));
        }
    }
    Ok(())
}

/// V2: an apex of joint k (both its sliding lines meet: N_k = T_k = 0) has M_k = 0, so
/// w = −m_k(q) at every η and E_k, I_k are always active: the ridge is the vertical
/// segment over q; its events are where another hinge row reaches w.
fn apexes(
    js: &[JointRows],
    lines: &[Line],
    poly: &[QVertex],
    in_range: &impl Fn(f64) -> bool,
) -> Vec<Candidate> {
    let mut out = Vec::new();
    for k in 0..poly.len() {
        let (q, e1) = poly[k];
        let e0 = poly[(k + poly.len() - 1) % poly.len()].1;
        let (Some((j0, _)), Some((j1, _))) = (lines[e0].slide, lines[e1].slide) else {
            continue;
        };
        if j0 != j1 {
            continue;
        }
        let hr = hinge_rows(js, q, [0.0, 0.0]);
        let w = -ev(&js[j0].m, q);
        for r in hr.iter().filter(|r| r.j != j0 && r.c[2] != 0.0) {
            let eta = (w - r.c[0]) / r.c[2];
            if in_range(eta) && in_band(&hr, 0.0, eta, w, TOL * scale(q)) {
                out.push(Candidate {
                    x: [q[0], q[1], w],
                    eta,
                });
            }
        }
    }
    out
}

/// The frame p = p0 + t d of a line of Q: parametrised from the foot of the perpendicular
/// from the origin (not from a vertex, which may be on the box, 10⁶ away: t would lose ~10
/// digits), d of unit length.
pub(super) fn edge_frame(line: &Line) -> ([f64; 2], [f64; 2]) {
    let (a, b) = (line.a, line.b);
    let na2 = a[0] * a[0] + a[1] * a[1];
    let p0 = [-b * a[0] / na2, -b * a[1] / na2];
    let d = [-a[1] / na2.sqrt(), a[0] / na2.sqrt()];
    (p0, d)
}

/// The walk along each sliding edge of Q: the points it returns inside the box, added to
/// `out`.
fn along_edges(
    js: &[JointRows],
    lines: &[Line],
    poly: &[QVertex],
    in_range: &impl Fn(f64) -> bool,
    out: &mut Vec<Candidate>,
) -> Result<(), Undecided> {
    for k in 0..poly.len() {
        let (q0, ri) = poly[k];
        let q1 = poly[(k + 1) % poly.len()].0;
        let Some(sl) = lines[ri].slide else {
            continue; // a side of the box
        };
        let len = (q1[0] - q0[0]).abs() + (q1[1] - q0[1]).abs();
        if len <= SHORT_EDGE_REL * scale(q0) {
            continue;
        }
        let (p0, d) = edge_frame(&lines[ri]);
        let tof = |q: [f64; 2]| (q[0] - p0[0]) * d[0] + (q[1] - p0[1]) * d[1];
        let hr = hinge_rows(js, p0, d);
        let cs = column(sl.1, js[sl.0].beta, 0.0);
        for (t, eta, w) in walk_edge(&hr, (tof(q0), tof(q1)), cs, js)?.points {
            let p = [p0[0] + t * d[0], p0[1] + t * d[1]];
            if in_range(eta) && !on_box(p) {
                out.push(Candidate {
                    x: [p[0], p[1], w],
                    eta,
                });
            }
        }
    }
    Ok(())
}
