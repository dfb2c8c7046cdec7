//! The friction polygon Q: the (h, v) points where every sliding row holds (N_j and T_j
//! are affine in (h, v) alone for the centreline weight), clipped by a box.

use super::rows::JointRows;
use crate::contact::ContactKind;

/// |h|, |v| ≤ BOX clip an unbounded Q; points on the box are not states of the arch (the
/// sweep's box, |x_k| ≤ 1e7, is larger).
pub(super) const BOX: f64 = 1e6;

/// A point is on the box when |h| or |v| ≥ [`BOX`] (1 − this).
const BOX_EDGE_REL: f64 = 1e-9;

/// The clipping drops an edge shorter (ℓ₁) than this times 1 + the size of its end: a
/// vertex repeated.
const REPEATED_VERTEX_REL: f64 = 1e-13;

/// A half-plane a·p + b ≤ 0 of the (h, v) plane: a sliding row (joint, kind) or a side of
/// the box.
#[derive(Clone, Copy)]
pub(super) struct Line {
    pub(super) a: [f64; 2],
    pub(super) b: f64,
    pub(super) slide: Option<(usize, ContactKind)>,
}

/// The sliding rows of every joint (T ≤ μN and −T ≤ μN), then the four sides of the box.
pub(super) fn lines(js: &[JointRows], mu: f64) -> Vec<Line> {
    let mut lines: Vec<Line> = Vec::with_capacity(2 * js.len() + 4);
    for (j, jr) in js.iter().enumerate() {
        for (sg, kind) in [
            (1.0, ContactKind::SlidePlus),
            (-1.0, ContactKind::SlideMinus),
        ] {
            lines.push(Line {
                a: [sg * jr.t[0] - mu * jr.n[0], sg * jr.t[1] - mu * jr.n[1]],
                b: sg * jr.t[2] - mu * jr.n[2],
                slide: Some((j, kind)),
            });
        }
    }
    for a in [[1.0, 0.0], [-1.0, 0.0], [0.0, 1.0], [0.0, -1.0]] {
        lines.push(Line {
            a,
            b: -BOX,
            slide: None,
        });
    }
    lines
}

/// Whether p lies on the box (not inside it).
pub(super) fn on_box(p: [f64; 2]) -> bool {
    p[0].abs() >= BOX * (1.0 - BOX_EDGE_REL) || p[1].abs() >= BOX * (1.0 - BOX_EDGE_REL)
}

/// Q ∩ box as a convex polygon: its vertices in order, each with the index (in `lines`) of
/// the line that carries the edge from it to the next vertex. Sutherland–Hodgman clipping
/// of the box by each sliding half-plane, then each vertex again from its two lines
/// (clipping from the box's corners leaves absolute errors of order BOX · 1e-16).
pub(super) fn q_polygon(lines: &[Line]) -> Vec<([f64; 2], usize)> {
    let boxes: Vec<usize> = (0..lines.len())
        .filter(|&k| lines[k].slide.is_none())
        .collect();
    // box lines in the order h ≤ B, −h ≤ B, v ≤ B, −v ≤ B; counter-clockwise from (B, −B)
    let (hp, hm, vp, vm) = (boxes[0], boxes[1], boxes[2], boxes[3]);
    let mut poly = vec![
        ([BOX, -BOX], hp),
        ([BOX, BOX], vp),
        ([-BOX, BOX], hm),
        ([-BOX, -BOX], vm),
    ];
    for (li, l) in lines.iter().enumerate().filter(|(_, l)| l.slide.is_some()) {
        if poly.is_empty() {
            break;
        }
        let f = |p: [f64; 2]| l.a[0] * p[0] + l.a[1] * p[1] + l.b;
        let mut next = Vec::with_capacity(poly.len() + 1);
        for k in 0..poly.len() {
            let (p, e) = poly[k];
            let q = poly[(k + 1) % poly.len()].0;
            let (fp, fq) = (f(p), f(q));
            let cut = |s: f64| [p[0] + s * (q[0] - p[0]), p[1] + s * (q[1] - p[1])];
            if fp <= 0.0 {
                next.push((p, e));
                if fq > 0.0 {
                    next.push((cut(fp / (fp - fq)), li));
                }
            } else if fq <= 0.0 {
                next.push((cut(fp / (fp - fq)), e));
            }
        }
        // drop zero-length edges (a vertex repeated)
        let mut clean: Vec<([f64; 2], usize)> = Vec::with_capacity(next.len());
        for k in 0..next.len() {
            let (p, _) = next[k];
            let q = next[(k + 1) % next.len()].0;
            let sc = 1.0 + p[0].abs() + p[1].abs();
            if (p[0] - q[0]).abs() + (p[1] - q[1]).abs() > REPEATED_VERTEX_REL * sc
                || next.len() == 1
            {
                clean.push(next[k]);
            }
        }
        poly = clean;
    }
    let m = poly.len();
    (0..m)
        .map(|k| {
            let (p, e) = poly[k];
            let (r, s) = (&lines[poly[(k + m - 1) % m].1], &lines[e]);
            let det = r.a[0] * s.a[1] - r.a[1] * s.a[0];
            if det == 0.0 {
                return (p, e);
            }
            let q = [
                (-r.b * s.a[1] + s.b * r.a[1]) / det,
                (-r.a[0] * s.b + s.a[0] * r.b) / det,
            ];
            (q, e)
        })
        .collect()
}
