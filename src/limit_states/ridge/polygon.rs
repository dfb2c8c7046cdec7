//! The friction polygon Q: the (h, v) points where every sliding row holds (N_j and T_j
//! are affine in (h, v) alone for the centreline weight), clipped by a box.

use super::rows::JointRows;
use crate::contact::ContactKind;

/// |h|, |v| ≤ BOX clip an unbounded Q; points on the box are not states of the arch (the
/// sweep's box, |x_k| ≤ 1e7, is larger).
pub(super) const BOX: f64 = 1e6;

/// Two lines of consecutive angles that meet beyond this many times [`BOX`] are taken as
/// parallel (their meeting point is rounding, and the box cuts it off).
const FAR: f64 = 4.0;

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
/// angular gap below π, so consecutive lines meet unless parallel (angles equal to
/// rounding, or meeting far beyond the box), and of two parallel ones the more restrictive
/// stays.
fn intersect(lines: &[Line]) -> Vec<([f64; 2], usize)> {
    let outside = |l: usize, p: [f64; 2]| {
        let l = &lines[l];
        l.a[0] * p[0] + l.a[1] * p[1] + l.b > 0.0
    };
    // by angle; of parallel lines the most restrictive (the largest b / |a|) first
    let offset = |l: usize| lines[l].b / lines[l].a[0].hypot(lines[l].a[1]);
    let mut order: Vec<(f64, f64, usize)> = (0..lines.len())
        .map(|k| (angle(&lines[k]), offset(k), k))
        .collect();
    order.sort_by(|x, y| x.0.total_cmp(&y.0).then(y.1.total_cmp(&x.1)));
    let mut dq: std::collections::VecDeque<usize> = std::collections::VecDeque::new();
    // pts[k]: where dq[k] and dq[k + 1] meet
    let mut pts: std::collections::VecDeque<[f64; 2]> = std::collections::VecDeque::new();
    for &(_, _, l) in &order {
        // a line parallel to the last one (their angles equal to rounding, or meeting far
        // beyond the box): the more restrictive stays
        if let Some(&last) = dq.back() {
            let far = |p: [f64; 2]| !(p[0].abs() <= FAR * BOX && p[1].abs() <= FAR * BOX);
            if meet(&lines[last], &lines[l]).is_none_or(far) {
                if offset(l) <= offset(last) {
                    continue;
                }
                dq.pop_back();
                pts.pop_back();
            }
        }
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

#[cfg(test)]
mod tests {
    use super::*;

    fn slide(a: [f64; 2], b: f64) -> Line {
        Line {
            a,
            b,
            slide: Some((0, ContactKind::SlidePlus)),
        }
    }

    /// The square |h|, |v| ≤ 1 cut by parallel copies of its sides (one of them with its
    /// normal scaled, so that its angle differs in the last bit): the most restrictive of
    /// each pair stays, and the vertices are the square's corners, counter-clockwise from
    /// the edge of least angle.
    #[test]
    fn parallel_half_planes_keep_the_most_restrictive() {
        let s = 1.0 + 3.0 * f64::EPSILON;
        let mut ls = vec![
            slide([1.0, 0.0], -1.0),
            slide([0.0, 1.0], -1.0),
            slide([-1.0, 0.0], -1.0),
            slide([0.0, -1.0], -1.0),
            // h ≤ 2, meeting h ≤ 1 at v = 10³⁰⁰: parallel to rounding
            slide([1.0, 1e-300], -2.0),
            slide([0.0 * s, s], -1.5 * s),
            slide([-s, 0.0], -0.5 * s),
        ];
        ls.extend(lines(&[], 1.0));
        let poly = q_polygon(&ls);
        let corners: Vec<[f64; 2]> = poly.iter().map(|v| v.0).collect();
        assert_eq!(
            corners,
            vec![[-0.5, 1.0], [-0.5, -1.0], [1.0, -1.0], [1.0, 1.0]],
            "{poly:?}"
        );
        // the edge of least angle first: h ≥ −0.5 (line 6), going down
        assert_eq!(
            poly.iter().map(|v| v.1).collect::<Vec<_>>(),
            vec![6, 3, 0, 1]
        );
    }
}
