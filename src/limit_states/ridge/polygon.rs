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

/// The angle of a half-plane's boundary direction, its interior on the left: d = (−a₁, a₀).
fn angle(l: &Line) -> f64 {
    l.a[0].atan2(-l.a[1])
}

/// Whether p lies on the box (not inside it).
pub(super) fn on_box(p: [f64; 2]) -> bool {
    p[0].abs() >= BOX * (1.0 - BOX_EDGE_REL) || p[1].abs() >= BOX * (1.0 - BOX_EDGE_REL)
}

/// Q ∩ box as a convex polygon: its vertices counter-clockwise from the edge whose boundary
/// direction has the least angle, each with the index (in `lines`) of the line that carries
/// the edge from it to the next vertex. The half-planes in order of angle, kept on a deque
/// (each new one drops from either end the lines whose corner it cuts off: O(n log n));
/// then vertices repeated within rounding dropped, and each vertex computed again from
/// its two lines.
pub(super) fn q_polygon(lines: &[Line]) -> Vec<([f64; 2], usize)> {
    let mut poly = intersect(lines);
    poly = drop_repeated(poly);
    if let Some(k) = (0..poly.len())
        .min_by(|&x, &y| angle(&lines[poly[x].1]).total_cmp(&angle(&lines[poly[y].1])))
    {
        poly.rotate_left(k);
    }
    let m = poly.len();
    (0..m)
        .map(|k| {
            let (p, e) = poly[k];
            match meet(&lines[poly[(k + m - 1) % m].1], &lines[e]) {
                Some(q) => (q, e),
                None => (p, e),
            }
        })
        .collect()
}

/// The point where two lines meet (None: parallel).
fn meet(r: &Line, s: &Line) -> Option<[f64; 2]> {
    let det = r.a[0] * s.a[1] - r.a[1] * s.a[0];
    (det != 0.0).then(|| {
        [
            (-r.b * s.a[1] + s.b * r.a[1]) / det,
            (-r.a[0] * s.b + s.a[0] * r.b) / det,
        ]
    })
}

/// The intersection of the half-planes: its vertices in order, each with the line of the
/// edge that leaves it (empty where it has no interior). The box's four sides keep every
/// angular gap below π, so consecutive lines always meet.
fn intersect(lines: &[Line]) -> Vec<([f64; 2], usize)> {
    let outside = |l: usize, p: [f64; 2]| {
        let l = &lines[l];
        l.a[0] * p[0] + l.a[1] * p[1] + l.b > 0.0
    };
    // by angle; of parallel lines the most restrictive (the largest b / |a|) first
    let mut order: Vec<(f64, f64, usize)> = lines
        .iter()
        .enumerate()
        .map(|(k, l)| (angle(l), l.b / l.a[0].hypot(l.a[1]), k))
        .collect();
    order.sort_by(|x, y| x.0.total_cmp(&y.0).then(y.1.total_cmp(&x.1)));
    order.dedup_by(|y, x| y.0 == x.0);
    let order: Vec<usize> = order.into_iter().map(|o| o.2).collect();
    let mut dq: std::collections::VecDeque<usize> = std::collections::VecDeque::new();
    // pts[k]: where dq[k] and dq[k + 1] meet
    let mut pts: std::collections::VecDeque<[f64; 2]> = std::collections::VecDeque::new();
    for &l in &order {
        while pts.back().is_some_and(|&p| outside(l, p)) {
            dq.pop_back();
            pts.pop_back();
        }
        while pts.front().is_some_and(|&p| outside(l, p)) {
            dq.pop_front();
            pts.pop_front();
        }
        if let Some(&last) = dq.back() {
            let Some(p) = meet(&lines[last], &lines[l]) else {
                return Vec::new();
            };
            pts.push_back(p);
        }
        dq.push_back(l);
    }
    while dq.len() >= 3 && pts.back().is_some_and(|&p| outside(dq[0], p)) {
        dq.pop_back();
        pts.pop_back();
    }
    while dq.len() >= 3 && pts.front().is_some_and(|&p| outside(dq[dq.len() - 1], p)) {
        dq.pop_front();
        pts.pop_front();
    }
    if dq.len() < 3 {
        return Vec::new();
    }
    let Some(close) = meet(&lines[dq[dq.len() - 1]], &lines[dq[0]]) else {
        return Vec::new();
    };
    // vertex k starts the edge on dq[k]: it is where dq[k − 1] and dq[k] meet
    (0..dq.len())
        .map(|k| (if k == 0 { close } else { pts[k - 1] }, dq[k]))
        .collect()
}

/// The polygon without its zero-length edges (a vertex repeated within rounding).
fn drop_repeated(poly: Vec<([f64; 2], usize)>) -> Vec<([f64; 2], usize)> {
    let n = poly.len();
    (0..n)
        .filter(|&k| {
            let (p, q) = (poly[k].0, poly[(k + 1) % n].0);
            let sc = 1.0 + p[0].abs() + p[1].abs();
            (p[0] - q[0]).abs() + (p[1] - q[1]).abs() > REPEATED_VERTEX_REL * sc || n == 1
        })
        .map(|k| poly[k])
        .collect()
}
