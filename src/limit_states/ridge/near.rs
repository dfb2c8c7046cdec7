//! The joints whose rows may be active over a stretch of ∂Q, proved. The walk over a chunk
//! of consecutive edges of Q uses the hinge rows of a subset S of the joints; afterwards
//! every joint outside S is shown inactive, by a margin, at every point of the ridge the
//! walk found there. Then that ridge is the ridge of all the rows: at each of its points
//! (p, η_S, w_S) every row outside S holds strictly, so the band of all the rows at η_S
//! contains w_S (g ≤ η_S), and fewer rows never close the band later (g ≥ η_S); its
//! breakpoints are where a row of S reaches w, since no other row comes near it. The
//! bounds over the chunk ([`Bounds`]): the (h, v) box of its edges, the range of η over its
//! pieces, and the ranges of w less a reference row of each side; each row's difference
//! with its reference is bilinear in (p, η), so its extremes over box × range lie at the
//! eight corners. The proof walks down a tree of groups of joints ([`JointTree`]: a group's
//! rows as the interpolation between its end joints plus the range of the residual), so a
//! chunk costs about |S| log n.
//!
//! The same margins let the candidates' pre-filter and the test for a third sliding line
//! through a vertex of Q look at the joints of S alone: the joints outside are further from
//! active than either test's tolerance.

use super::rows::{ev, HingeRow, JointRows};
use super::walk::Walked;

/// A joint is left out of a chunk when each of its rows is inactive by more than this
/// times the chunk's size (1 + |h| + |v| + |w| over its bounds; times max(1, η) for a hinge
/// row, times 1 + the row's gradient for a sliding one). It is 100 times the walk's own
/// tolerance (`rows::TOL`) and 1000 times the pre-filter's "clearly inactive"
/// (`CLEAR_FACTOR` × `adm_tol`).
const MARGIN_REL: f64 = 1e-7;

/// The joints of a chunk predicted to come near their rows in the next one: a hinge row
/// whose slack is below this many times its own variation over the chunk plus the chunk's
/// range of w.
const PREDICT_FACTOR: f64 = 0.5;

/// What the walk over a chunk found, as bounds: the (h, v) box of its edges, the range of
/// η and of w over its pieces, and the ranges of w − u_r(p, η) and w − l_s(p, η) (the
/// extrados row of a reference joint r and the intrados row of a reference joint s): a
/// row's gap to w is bounded through its difference with the reference row of its side,
/// which varies little over a short stretch for the joints near the reference, where the
/// gaps are small.
pub(super) struct Bounds {
    h: [f64; 2],
    v: [f64; 2],
    eta: [f64; 2],
    w: [f64; 2],
    reference: [usize; 2],
    dw: [[f64; 2]; 2],
    ends: Vec<[f64; 2]>,
}

/// One walked edge as the bounds see it: its ends, its frame p = p0 + t d, its hinge rows
/// and its walk.
pub(super) type EdgeView<'a> = (
    ([f64; 2], [f64; 2]),
    [f64; 2],
    [f64; 2],
    &'a [HingeRow],
    &'a Walked,
);

impl Bounds {
    /// The bounds of the walked edges, relative to the extrados row of the joint
    /// `reference[0]` and the intrados row of the joint `reference[1]`.
    pub(super) fn new(js: &[JointRows], reference: [usize; 2], walks: &[EdgeView]) -> Bounds {
        let empty = [f64::INFINITY, f64::NEG_INFINITY];
        let mut b = Bounds {
            h: empty,
            v: empty,
            eta: empty,
            w: empty,
            reference,
            dw: [empty; 2],
            ends: Vec::with_capacity(2 * walks.len()),
        };
        let (r, s) = (&js[reference[0]], &js[reference[1]]);
        for &((q0, q1), p0, d, hr, walked) in walks {
            for q in [q0, q1] {
                widen(&mut b.h, q[0]);
                widen(&mut b.v, q[1]);
            }
            b.ends.extend([q0, q1]);
            for &(ts, te, e, i) in &walked.pieces {
                // on a piece η(t) = −(d0 + d1 t)/(d2 + d3 t) is monotone (no pole), and
                // w = u_e(t, η(t)) = l_i(t, η(t)); u_e − u_r and l_i − l_s are bilinear in
                // (t, η): their extremes over the piece's box lie at its corners
                let c: [f64; 4] = std::array::from_fn(|k| hr[e].c[k] - hr[i].c[k]);
                let eta_of = |t: f64| -(c[0] + c[1] * t) / (c[2] + c[3] * t);
                let (es, ee) = (eta_of(ts), eta_of(te));
                widen(&mut b.eta, es);
                widen(&mut b.eta, ee);
                for t in [ts, te] {
                    let p = [p0[0] + t * d[0], p0[1] + t * d[1]];
                    for eta in [es, ee] {
                        // on the piece w = u_e = l_i: each bounded on its own side
                        let (u_e, l_i) = (hr[e].at(t, eta), hr[i].at(t, eta));
                        widen(&mut b.w, u_e);
                        let u_r = -ev(&r.m, p) + 0.5 * eta * ev(&r.n, p);
                        let l_s = -ev(&s.m, p) - 0.5 * eta * ev(&s.n, p);
                        widen(&mut b.dw[0], u_e - u_r);
                        widen(&mut b.dw[1], l_i - l_s);
                    }
                }
            }
        }
        b
    }

    fn corners(&self) -> [[f64; 2]; 4] {
        [
            [self.h[0], self.v[0]],
            [self.h[0], self.v[1]],
            [self.h[1], self.v[0]],
            [self.h[1], self.v[1]],
        ]
    }

    /// 1 + |h| + |v| + |w| at most over the bounds.
    fn size(&self) -> f64 {
        let most = |r: [f64; 2]| r[0].abs().max(r[1].abs());
        1.0 + most(self.h) + most(self.v) + most(self.w)
    }

    /// Whether every bound is a finite range (a walk with pieces on every edge).
    fn finite(&self) -> bool {
        [self.h, self.v, self.eta, self.w, self.dw[0], self.dw[1]]
            .iter()
            .all(|r| r[0].is_finite() && r[1].is_finite() && r[0] <= r[1])
    }
}

fn widen(r: &mut [f64; 2], x: f64) {
    r[0] = r[0].min(x);
    r[1] = r[1].max(x);
}

/// A joint's nine coefficients: m, n and t over (h, v) ([∂h, ∂v, constant] each). Every
/// row is a linear form in them.
fn coefficients(jr: &JointRows) -> [f64; 9] {
    [
        jr.m[0], jr.m[1], jr.m[2], jr.n[0], jr.n[1], jr.n[2], jr.t[0], jr.t[1], jr.t[2],
    ]
}

/// The rows of a group of consecutive joints: each joint's coefficients c_j are the
/// interpolation between the group's first and last joints at s_j = (β_j − β_first) /
/// (β_last − β_first), plus a residual whose range over the group is kept. A row's value
/// c_j · φ then lies within min/max(c_first · φ, c_last · φ) plus the residual's range
/// times φ: close to tight, since the residual is of second order in the group's spread
/// (a first-order bound would miss the tangency that makes a row near active).
#[derive(Clone, Copy)]
struct Group {
    first: [f64; 9],
    last: [f64; 9],
    residual: [[f64; 2]; 9],
    /// The largest |∇(±T − μN)|₁ over the group.
    grad: f64,
}

impl Group {
    fn of(js: &[JointRows], mu: f64) -> Group {
        let (first, last) = (coefficients(&js[0]), coefficients(&js[js.len() - 1]));
        let span = js[js.len() - 1].beta - js[0].beta;
        let mut residual = [[0.0f64; 2]; 9];
        let mut grad = 0.0f64;
        for jr in js {
            let s = if span != 0.0 {
                (jr.beta - js[0].beta) / span
            } else {
                0.0
            };
            let c = coefficients(jr);
            for k in 0..9 {
                let r = c[k] - ((1.0 - s) * first[k] + s * last[k]);
                residual[k] = [residual[k][0].min(r), residual[k][1].max(r)];
            }
            grad = grad
                .max((jr.t[0].abs() + mu * jr.n[0].abs()) + (jr.t[1].abs() + mu * jr.n[1].abs()));
        }
        Group {
            first,
            last,
            residual,
            grad,
        }
    }

    /// The group's forms m, n and t at p ([`Forms`]): every row there is a combination of
    /// them. Only the forms marked in `used` are evaluated (the others are left zero: a
    /// hinge row has no t, a sliding row no m).
    #[inline]
    fn forms(&self, p: [f64; 2], used: [bool; 3]) -> Forms {
        let q = [p[0], p[1], 1.0];
        let mut out = Forms {
            first: [0.0; 3],
            last: [0.0; 3],
            residual: [[0.0; 2]; 3],
        };
        for f in 0..3 {
            if !used[f] {
                continue;
            }
            let at = |c: &[f64; 9]| c[3 * f] * q[0] + c[3 * f + 1] * q[1] + c[3 * f + 2] * q[2];
            out.first[f] = at(&self.first);
            out.last[f] = at(&self.last);
            let r = &mut out.residual[f];
            for (res, qk) in self.residual[3 * f..3 * f + 3].iter().zip(q) {
                let (x, y) = (res[0] * qk, res[1] * qk);
                r[0] += x.min(y);
                r[1] += x.max(y);
            }
        }
        out
    }
}

/// A group's forms m, n and t (each c · (h, v, 1) for its joint's part c of the nine
/// coefficients) at one point (h, v): their values at the group's first and last joints,
/// and the range of each form's residual over the group.
struct Forms {
    first: [f64; 3],
    last: [f64; 3],
    residual: [[f64; 2]; 3],
}

impl Forms {
    /// The range over the group of the row a m + b n + c t (`coef` = [a, b, c]): between
    /// its values at the first and last joints, plus the residual's range of each form
    /// scaled by its coefficient.
    fn range(&self, coef: [f64; 3]) -> [f64; 2] {
        // (a form with coefficient zero adds nothing: it is skipped, and need not have been
        // evaluated)
        let (mut a, mut b) = (0.0, 0.0);
        for ((&c, first), last) in coef.iter().zip(&self.first).zip(&self.last) {
            if c != 0.0 {
                a += c * first;
                b += c * last;
            }
        }
        let mut r = [a.min(b), a.max(b)];
        for (&c, res) in coef.iter().zip(&self.residual) {
            if c == 0.0 {
                continue;
            }
            let (x, y) = (res[0] * c, res[1] * c);
            r[0] += x.min(y);
            r[1] += x.max(y);
        }
        r
    }
}

/// The forms a hinge row combines (m, n) and those a sliding row combines (n, t).
const HINGE_FORMS: [bool; 3] = [true, true, false];
const SLIDE_FORMS: [bool; 3] = [false, true, true];

/// The extrados row u = −m + η n / 2 and the intrados row l = −m − η n / 2 as
/// combinations of the forms m, n, t.
fn hinge_rows(eta: f64) -> [[f64; 3]; 2] {
    [[-1.0, 0.5 * eta, 0.0], [-1.0, -0.5 * eta, 0.0]]
}

/// The sliding rows ±T − μN as combinations of the forms m, n, t.
fn slide_rows(mu: f64) -> [[f64; 3]; 2] {
    [[0.0, -mu, 1.0], [0.0, -mu, -1.0]]
}

/// The joints of an arch in a binary tree of consecutive groups (leaves of
/// [`LEAF_JOINTS`]): a group whose rows are shown inactive is passed over whole, so a
/// chunk's verdict costs about |S| log n, not n.
pub(super) struct JointTree {
    /// (first joint, end, group, children) in depth-first order; the root first.
    nodes: Vec<(usize, usize, Group, Option<[usize; 2]>)>,
}

/// Joints per leaf of the tree.
const LEAF_JOINTS: usize = 8;

impl JointTree {
    /// The tree of the joints (empty unless `wanted`).
    pub(super) fn new(js: &[JointRows], mu: f64, wanted: bool) -> JointTree {
        let mut t = JointTree { nodes: Vec::new() };
        if wanted {
            t.build(js, mu, 0, js.len());
        }
        t
    }

    fn build(&mut self, js: &[JointRows], mu: f64, lo: usize, hi: usize) -> usize {
        let k = self.nodes.len();
        self.nodes.push((lo, hi, Group::of(&js[lo..hi], mu), None));
        if hi - lo > LEAF_JOINTS {
            let mid = lo + (hi - lo) / 2;
            let a = self.build(js, mu, lo, mid);
            let b = self.build(js, mu, mid, hi);
            self.nodes[k].3 = Some([a, b]);
        }
        k
    }
}

/// The verdict over a chunk: the joints outside the walk's set whose hinge rows are not
/// shown inactive (the walk must take them and run again), the joints with a row not shown
/// inactive (ascending: the pre-filter and the G1 test must look at them), and the joints
/// predicted near in the next chunk.
pub(super) struct Verdict {
    pub(super) failing: Vec<usize>,
    pub(super) on: Vec<usize>,
    pub(super) next: Vec<usize>,
}

/// Every joint's rows over the chunk's bounds, through the tree. `in_walk[j]`: the walk
/// used joint j's hinge rows.
pub(super) fn verify(
    js: &[JointRows],
    tree: &JointTree,
    mu: f64,
    b: &Bounds,
    in_walk: &[bool],
) -> Verdict {
    let mut out = Verdict {
        failing: Vec::new(),
        on: Vec::new(),
        next: Vec::new(),
    };
    if !b.finite() {
        out.failing = (0..js.len()).filter(|&j| !in_walk[j]).collect();
        out.on = (0..js.len()).collect();
        out.next = (0..js.len()).collect();
        return out;
    }
    let refs = References::new(js, b);
    let mut stack = vec![0];
    while let Some(k) = stack.pop() {
        let (lo, hi, g, children) = &tree.nodes[k];
        let (h_off, h_near) = hinges(g, b, &refs, true);
        if h_off && !h_near && slides(g, mu, b) {
            continue;
        }
        if let Some([a, c]) = children {
            stack.extend([*c, *a]);
            continue;
        }
        for j in *lo..*hi {
            let g = Group::of(std::slice::from_ref(&js[j]), mu);
            let (h_off, h_near) = hinges(&g, b, &refs, false);
            if !h_off && !in_walk[j] {
                out.failing.push(j);
            }
            if !h_off || !slides(&g, mu, b) {
                out.on.push(j);
            }
            if h_near {
                out.next.push(j);
            }
        }
    }
    out
}

/// The reference rows' values (u_r and l_s) at the eight corners of box × range of η
/// (for each corner of the box, at each end of the range), and the hinge margin.
struct References {
    at: [([f64; 2], [[f64; 2]; 2]); 4],
    margin: f64,
}

impl References {
    fn new(js: &[JointRows], b: &Bounds) -> References {
        let corners = b.corners();
        let at = std::array::from_fn(|c| {
            let p = corners[c];
            let [r, s] = [0, 1].map(|k| Group::of(std::slice::from_ref(&js[b.reference[k]]), 0.0));
            let (r, s) = (r.forms(p, HINGE_FORMS), s.forms(p, HINGE_FORMS));
            let values = b.eta.map(|eta| {
                let [u, l] = hinge_rows(eta);
                [r.range(u)[0], s.range(l)[0]]
            });
            (p, values)
        });
        References {
            at,
            margin: MARGIN_REL * b.size() * b.eta[0].abs().max(b.eta[1].abs()).max(1.0),
        }
    }
}

/// Whether the group's hinge rows are inactive by the margin over the chunk, and whether
/// they may come near in the next chunk (a slack below [`PREDICT_FACTOR`] times the rows'
/// variation over this one). The gaps are u_j − w = (u_j − u_r) − (w − u_r) and
/// w − l_j = (w − l_s) − (l_j − l_s), with u_j − u_r and l_j − l_s over box × range of η
/// (bilinear: their extremes at the corners). With `stop_near`, it stops at the first
/// corner after which the rows are near (the slack only shrinks and the variation only
/// grows with more corners, so they are near over all of them) and returns (false, true):
/// `false` is then not a verdict on inactivity, only the cautious answer, for a caller
/// that descends into a near group whatever its first answer (a group node in
/// [`verify`]).
fn hinges(g: &Group, b: &Bounds, refs: &References, stop_near: bool) -> (bool, bool) {
    let (mut u, mut l) = (
        [f64::INFINITY, f64::NEG_INFINITY],
        [f64::INFINITY, f64::NEG_INFINITY],
    );
    let margin = refs.margin;
    let verdict = |u: [f64; 2], l: [f64; 2]| {
        let slack = [u[0] - b.dw[0][1], b.dw[1][0] - l[1]];
        let vary = [
            u[1] - u[0] + b.dw[0][1] - b.dw[0][0],
            l[1] - l[0] + b.dw[1][1] - b.dw[1][0],
        ];
        let off = slack[0] > margin && slack[1] > margin;
        // (a NaN slack counts as near)
        let near = (0..2).any(|k| {
            slack[k].partial_cmp(&(PREDICT_FACTOR * vary[k] + margin))
                != Some(std::cmp::Ordering::Greater)
        });
        (off, near)
    };
    for (p, values) in &refs.at {
        let forms = g.forms(*p, HINGE_FORMS);
        for (eta, [ur, ls]) in b.eta.iter().zip(values) {
            let [hu, hl] = hinge_rows(*eta);
            let (gu, gl) = (forms.range(hu), forms.range(hl));
            widen(&mut u, gu[0] - ur);
            widen(&mut u, gu[1] - ur);
            widen(&mut l, gl[0] - ls);
            widen(&mut l, gl[1] - ls);
        }
        if stop_near && verdict(u, l).1 {
            return (false, true);
        }
    }
    verdict(u, l)
}

/// Whether the group's sliding rows are inactive by the margin on the chunk's edges (over
/// the box's corners first; where that fails, at the edges' ends: the corners lie outside
/// Q, and a row is affine along each edge).
fn slides(g: &Group, mu: f64, b: &Bounds) -> bool {
    let margin = MARGIN_REL * b.size() * (1.0 + g.grad);
    let [sp, sm] = slide_rows(mu);
    let most = |p: [f64; 2]| {
        let forms = g.forms(p, SLIDE_FORMS);
        forms.range(sp)[1].max(forms.range(sm)[1])
    };
    b.corners().into_iter().all(|p| most(p) < -margin) || b.ends.iter().all(|&p| most(p) < -margin)
}
