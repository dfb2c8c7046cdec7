//! The ridge traced for a certificate: the edges of a bounded Q from vertex to vertex, the
//! junctions along each (its first vertex, the breakpoints, the points of dependent
//! columns) and the pair of hinge rows that closes the band of w on each piece between
//! them. `certificate::verify` re-proves from this that no limit state lies between the
//! junctions.

use super::candidates::{edge_frame, no_third_line};
use super::polygon::{lines, on_box, q_polygon, Line};
use super::rows::{applies, hinge_rows, JointRows};
use super::walk::walk_edge;
use crate::arch::{Arch, JointLayout};
use crate::contact::{Contact, ContactKind, Location};
use crate::kinematics::column;
use crate::statics::Reactions;
use crate::undecided::Undecided;

/// Junctions closer than this (in s, the edge's own parameter in [0, 1]) are one.
const SAME_JUNCTION: f64 = 1e-14;

/// A point of the ridge where the pieces meet: s along the edge, the state (h, v, w) at η.
#[derive(Debug, Clone, Copy)]
pub struct Junction {
    /// Position along the edge, 0 at its first vertex, 1 at its last.
    pub s: f64,
    /// The state on the ridge there.
    pub x: Reactions,
    /// Its η.
    pub eta: f64,
}

/// One edge of Q as traced.
#[derive(Debug, Clone)]
pub struct TracedEdge {
    /// The sliding row whose line carries the edge.
    pub row: Contact,
    /// Where each piece starts (the first at s = 0).
    pub junctions: Vec<Junction>,
    /// Each piece: where it ends (the last at s = 1) and its extrados and intrados rows.
    pub pieces: Vec<(f64, Contact, Contact)>,
}

/// The ridge over a bounded Q, edge by edge (counter-clockwise), for a discrete arch with
/// the centreline weight at finite μ. `Err` where Q is unbounded, has no interior, an apex
/// (both lines of one joint) or more than two lines through a vertex that break G1 (the
/// search's test, `candidates::no_third_line`), or where the walk fails.
pub fn trace(arch: &Arch, mu: f64) -> Result<Vec<TracedEdge>, Undecided> {
    let not = |why: &str| Err(Undecided::NotCovered(format!("no ridge evidence: {why}")));
    if !applies(arch, mu) {
        return not("the ridge needs a discrete arch, the centreline weight and finite mu");
    }
    let JointLayout::Discrete(joints) = arch.layout() else {
        unreachable!("checked by applies")
    };
    let js: Vec<JointRows> = joints.iter().map(|&b| JointRows::at(arch, b)).collect();
    let lines = lines(&js, mu);
    let poly = q_polygon(&lines);
    if poly.len() < 3 {
        return not("Q has no interior");
    }
    if poly
        .iter()
        .any(|&(q, e)| on_box(q) || lines[e].slide.is_none())
    {
        return not("Q is unbounded");
    }
    no_third_line(&js, &lines, &poly)?;
    let m = poly.len();
    let contact = |j: usize, kind: ContactKind| Contact {
        beta: js[j].beta,
        kind,
        at: Location::of_joint(j, js.len()),
        free: false,
    };
    let mut edges = Vec::with_capacity(m);
    for k in 0..m {
        let (q0, li) = poly[k];
        let q1 = poly[(k + 1) % m].0;
        let (j, kind) = lines[li].slide.expect("checked: every edge slides");
        let prev = lines[poly[(k + m - 1) % m].1].slide.expect("checked");
        if prev.0 == j {
            return not("Q has an apex (both sliding lines of one joint meet at a vertex)");
        }
        edges.push(trace_edge(&js, &lines[li], (q0, q1), (j, kind), &contact)?);
    }
    Ok(edges)
}

/// One edge from q0 to q1 on `line` (the sliding row `slide`).
fn trace_edge(
    js: &[JointRows],
    line: &Line,
    (q0, q1): ([f64; 2], [f64; 2]),
    slide: (usize, ContactKind),
    contact: &impl Fn(usize, ContactKind) -> Contact,
) -> Result<TracedEdge, Undecided> {
    let (p0, d) = edge_frame(line);
    let tof = |q: [f64; 2]| (q[0] - p0[0]) * d[0] + (q[1] - p0[1]) * d[1];
    let (t0, t1) = (tof(q0), tof(q1));
    let hr = hinge_rows(js, p0, d);
    let cs = column(slide.1, js[slide.0].beta, 0.0);
    let walked = walk_edge(&hr, (t0, t1), (None, usize::MAX), cs, js)?;
    let s_of = |t: f64| (t - t0) / (t1 - t0);
    let mut points: Vec<(f64, f64, f64)> = walked
        .points
        .iter()
        .map(|&(t, eta, w)| (s_of(t), eta, w))
        .filter(|p| p.0 < 1.0 - SAME_JUNCTION)
        .collect();
    points.sort_by(|a, b| a.0.total_cmp(&b.0));
    points.dedup_by(|b, a| b.0 - a.0 <= SAME_JUNCTION);
    let Some(first) = points.first_mut() else {
        return Err(Undecided::Resolution(
            "the walk gave no point on an edge of Q".into(),
        ));
    };
    first.0 = first.0.max(0.0);
    if first.0 > SAME_JUNCTION {
        return Err(Undecided::Resolution(
            "the walk did not start at a vertex of Q".into(),
        ));
    }
    first.0 = 0.0;
    let junctions: Vec<Junction> = points
        .iter()
        .map(|&(s, eta, w)| Junction {
            s,
            x: [
                p0[0] + (t0 + s * (t1 - t0)) * d[0],
                p0[1] + (t0 + s * (t1 - t0)) * d[1],
                w,
            ],
            eta,
        })
        .collect();
    // each piece between junctions: the walk's pair over its middle
    let ends: Vec<f64> = junctions.iter().skip(1).map(|j| j.s).chain([1.0]).collect();
    let mut pieces = Vec::with_capacity(ends.len());
    for (k, &end) in ends.iter().enumerate() {
        let mid = t0 + 0.5 * (junctions[k].s + end) * (t1 - t0);
        let (lo, hi) = (t0.min(t1), t0.max(t1));
        let (_, _, e, i) = walked
            .pieces
            .iter()
            .copied()
            .find(|p| mid.clamp(lo, hi) >= p.0.min(p.1) && mid.clamp(lo, hi) <= p.0.max(p.1))
            .ok_or_else(|| Undecided::Resolution("a piece of the ridge has no pair".into()))?;
        pieces.push((
            end,
            contact(hr[e].j, hr[e].kind()),
            contact(hr[i].j, hr[i].kind()),
        ));
    }
    Ok(TracedEdge {
        row: contact(slide.0, slide.1),
        junctions,
        pieces,
    })
}
