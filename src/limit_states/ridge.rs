//! Limit states of a discrete arch above η_s, found on the ridge over the friction polygon
//! (issue 12; the theorem, its proof and the cases are in
//! `docs/design/limit-states-on-boundary.md`).
//!
//! For the centreline weight and finite μ, N_j and T_j are affine in (h, v) alone, so the
//! sliding rows cut a fixed convex polygon Q of the (h, v) plane. Where P(η) has an interior
//! point, every limit state has an active sliding row, so (h, v) ∈ ∂Q; its mechanism has as
//! much extrados as intrados hinge rate (the third row of B), so an E row and an I row are
//! active and η = g(h, v), the least η whose band of admissible w at (h, v) is not empty.
//! The limit states are points of this ridge with four active rows (or three with
//! dependent columns). The search walks the ridge along each edge of Q: the edge's ends
//! (vertices of Q, case V), the apexes where both sliding lines of one joint meet (V2), the
//! breakpoints where a third hinge row reaches w (E1, a quadratic per row) and the points of
//! a piece where the sliding column and the piece's two hinge columns are dependent (E2, a
//! quadratic in η). Every candidate is then checked like a state of the sweep: admissible
//! over every joint (`State::verdict`) and a mechanism on its active contacts
//! (`mechanism::find`).
//!
//! Every event is a closed form of degree ≤ 2. What the walk cannot decide it hands back
//! as an `Err` (the caller then sweeps): three sliding lines through one vertex of Q,
//! families of limit states (a quadratic that vanishes identically), a walk that does not
//! reach the end of its edge, a kinematic LP the back end does not decide.

use crate::arch::{Arch, JointLayout, WeightModel, ETA_TOP};
use crate::contact::ContactKind;
use crate::kinematics::column;
use crate::mechanism;
use crate::settings::Settings;
use crate::state::State;
use crate::statics::{actions, reaction_scale, Reactions};

use super::SweptState;

/// |h|, |v| ≤ BOX clip an unbounded Q; points on the box are not states of the arch (the
/// sweep's box, |x_k| ≤ 1e7, is larger).
const BOX: f64 = 1e6;
/// Relative tolerance of the walk's own tests (band membership, rows through a vertex);
/// the verdict on a candidate is `Settings::adm_tol`'s.
const TOL: f64 = 1e-9;

/// The limit states the ridge search found, and how many candidate points it checked.
#[derive(Debug, Clone)]
pub struct Ridge {
    /// Limit states with η > `eta_lo`, ascending in η.
    pub states: Vec<SweptState>,
    /// Candidate points of the ridge checked (vertices, apexes, breakpoints, dependent
    /// columns) with η > `eta_lo`.
    pub candidates: usize,
}

/// Whether the ridge search applies: a discrete arch with the centreline weight at finite μ
/// (the true centroid puts η² into the hinge rows; μ = ∞ has no sliding rows, and
/// `limit_states` answers it by the interior alone).
pub fn applies(arch: &Arch, mu: f64) -> bool {
    mu.is_finite()
        && matches!(arch.layout(), JointLayout::Discrete(_))
        && matches!(arch.weight(), WeightModel::Centreline)
}

/// N, T and m = M − w at one joint as affine functions of (h, v): [∂/∂h, ∂/∂v, constant].
struct JointRows {
    beta: f64,
    n: [f64; 3],
    t: [f64; 3],
    m: [f64; 3],
}

fn ev(a: &[f64; 3], p: [f64; 2]) -> f64 {
    a[0] * p[0] + a[1] * p[1] + a[2]
}

/// A half-plane a·p + b ≤ 0 of the (h, v) plane: a sliding row (joint, kind) or a side of
/// the box.
#[derive(Clone, Copy)]
struct Line {
    a: [f64; 2],
    b: f64,
    slide: Option<(usize, ContactKind)>,
}

/// A hinge row along the line p = p0 + t d of the (h, v) plane: the row is active where
/// w = c0 + c1 t + η (c2 + c3 t); an upper bound on w (extrados) or a lower one (intrados).
#[derive(Clone, Copy)]
struct HingeRow {
    j: usize,
    upper: bool,
    c: [f64; 4],
}

impl HingeRow {
    fn at(&self, t: f64, eta: f64) -> f64 {
        self.c[0] + self.c[1] * t + eta * (self.c[2] + self.c[3] * t)
    }
    fn kind(&self) -> ContactKind {
        if self.upper {
            ContactKind::HingeExtrados
        } else {
            ContactKind::HingeIntrados
        }
    }
}

fn hinge_rows(js: &[JointRows], p0: [f64; 2], d: [f64; 2]) -> Vec<HingeRow> {
    let mut out = Vec::with_capacity(2 * js.len());
    for (j, jr) in js.iter().enumerate() {
        let (m0, m1) = (ev(&jr.m, p0), jr.m[0] * d[0] + jr.m[1] * d[1]);
        let (n0, n1) = (ev(&jr.n, p0), jr.n[0] * d[0] + jr.n[1] * d[1]);
        for (upper, sg) in [(true, 0.5), (false, -0.5)] {
            out.push(HingeRow {
                j,
                upper,
                c: [-m0, -m1, sg * n0, sg * n1],
            });
        }
    }
    out
}

/// Whether w lies in the band [max l, min u] of the hinge rows at (t, η), up to `tol`.
fn in_band(rows: &[HingeRow], t: f64, eta: f64, w: f64, tol: f64) -> bool {
    rows.iter().all(|r| {
        let v = r.at(t, eta);
        if r.upper {
            w <= v + tol
        } else {
            w >= v - tol
        }
    })
}

/// A point of the ridge to check: (h, v, w) and η.
#[derive(Clone, Copy, Debug)]
struct Candidate {
    x: Reactions,
    eta: f64,
}

/// Every limit state of a discrete arch (centreline weight, finite μ) with η in
/// (`eta_lo`, 2) that lies on the ridge over ∂Q. The caller owns the claim that these are
/// *all* limit states there: it holds wherever P(η) has an interior point (checked by the
/// caller with one margin LP). `Err` says why the walk could not decide (the caller then
/// sweeps).
pub fn search(arch: &Arch, mu: f64, eta_lo: f64, settings: &Settings) -> Result<Ridge, String> {
    if !applies(arch, mu) {
        return Err(
            "the ridge search needs a discrete arch, the centreline weight and finite mu".into(),
        );
    }
    let JointLayout::Discrete(joints) = arch.layout() else {
        unreachable!("checked by applies")
    };
    if joints.len() > settings.ridge_max_joints {
        return Err(format!(
            "the ridge walk over {} joints is beyond settings.ridge_max_joints = {}",
            joints.len(),
            settings.ridge_max_joints
        ));
    }
    let js: Vec<JointRows> = joints
        .iter()
        .map(|&b| {
            let a = actions(arch, 1.0, b);
            JointRows {
                beta: b,
                n: [a.n[0].g[0], a.n[0].g[1], a.n[0].c],
                t: [a.t[0].g[0], a.t[0].g[1], a.t[0].c],
                m: [a.m[0].g[0], a.m[0].g[1], a.m[0].c],
            }
        })
        .collect();
    let cands = candidates(&js, mu, eta_lo)?;
    let mut states: Vec<SweptState> = Vec::new();
    for c in &cands {
        if !may_carry_mechanism(&js, mu, c, settings) {
            continue;
        }
        if let Some(s) = check(arch, mu, c, settings)? {
            let dup = states.iter().any(|p| {
                (p.eta - s.eta).abs() <= 1e-9 * s.eta
                    && (0..3).all(|k| (p.x[k] - s.x[k]).abs() <= 1e-7 * reaction_scale(&s.x))
            });
            if !dup {
                states.push(s);
            }
        }
    }
    sort_states(&mut states);
    Ok(Ridge {
        states,
        candidates: cands.len(),
    })
}

/// Ascending in η; states whose η agree to 1e-12 (mirror images) by their patterns
/// (angles, then kinds), so that the order does not depend on the order of the walk.
pub(crate) fn sort_states(states: &mut [SweptState]) {
    states.sort_by(|p, q| p.eta.total_cmp(&q.eta));
    let mut k = 0;
    while k < states.len() {
        let mut end = k + 1;
        while end < states.len() && states[end].eta - states[k].eta <= 1e-12 * states[k].eta {
            end += 1;
        }
        states[k..end].sort_by(|p, q| {
            let key = |s: &SweptState| {
                s.pattern
                    .iter()
                    .map(|c| (c.beta, c.kind))
                    .collect::<Vec<_>>()
            };
            key(p)
                .partial_cmp(&key(q))
                .unwrap_or(std::cmp::Ordering::Equal)
        });
        k = end;
    }
}

/// Every candidate on the ridge with η in (eta_lo, ETA_TOP).
fn candidates(js: &[JointRows], mu: f64, eta_lo: f64) -> Result<Vec<Candidate>, String> {
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
    let scale = |p: [f64; 2]| 1.0 + p[0].abs() + p[1].abs();
    let on_box = |p: [f64; 2]| p[0].abs() >= BOX * (1.0 - 1e-9) || p[1].abs() >= BOX * (1.0 - 1e-9);
    let in_range = |eta: f64| eta > eta_lo && eta < ETA_TOP;
    let poly = q_polygon(&lines);
    if poly.len() < 3 {
        return Err("the friction polygon Q has no interior".into());
    }
    // G1: no third sliding line through a vertex of Q (a pure-sliding mechanism may then
    // hold over an interval of η, and the pair of lines would not define the vertex)
    for &(q, _) in &poly {
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
            return Err(format!(
                "{through} sliding lines meet at the vertex ({}, {}) of Q",
                q[0], q[1]
            ));
        }
    }
    let mut out = Vec::new();
    // V2: an apex of joint k (both its sliding lines meet: N_k = T_k = 0) has M_k = 0, so
    // w = −m_k(q) at every η and E_k, I_k are always active: the ridge is the vertical
    // segment over q; its events are where another hinge row reaches w
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
    // the walk along each sliding edge of Q
    for k in 0..poly.len() {
        let (q0, ri) = poly[k];
        let q1 = poly[(k + 1) % poly.len()].0;
        let Some(sl) = lines[ri].slide else {
            continue; // a side of the box
        };
        let len = (q1[0] - q0[0]).abs() + (q1[1] - q0[1]).abs();
        if len <= 1e-12 * scale(q0) {
            continue;
        }
        // parametrised from the foot of the perpendicular from the origin (not from a
        // vertex, which may be on the box, 10⁶ away: t would lose ~10 digits)
        let (a, b) = (lines[ri].a, lines[ri].b);
        let na2 = a[0] * a[0] + a[1] * a[1];
        let p0 = [-b * a[0] / na2, -b * a[1] / na2];
        let d = [-a[1] / na2.sqrt(), a[0] / na2.sqrt()];
        let tof = |q: [f64; 2]| (q[0] - p0[0]) * d[0] + (q[1] - p0[1]) * d[1];
        let hr = hinge_rows(js, p0, d);
        let cs = column(sl.1, js[sl.0].beta, 0.0);
        for (t, eta, w) in walk_edge(&hr, (tof(q0), tof(q1)), cs, js)? {
            let p = [p0[0] + t * d[0], p0[1] + t * d[1]];
            if in_range(eta) && !on_box(p) {
                out.push(Candidate {
                    x: [p[0], p[1], w],
                    eta,
                });
            }
        }
    }
    Ok(out)
}

/// The least η at which the band of w is not empty at t (the ridge's height g), with the
/// E and I rows that close it there (distinct joints), the pair that dominates just after
/// t (the largest dη/dt). Newton on the convex, decreasing, piecewise-linear
/// f(η) = max_I l(η) − min_E u(η) from η = 0: every step lands on or below the root, and
/// the pieces are finitely many.
fn ridge_pair(hr: &[HingeRow], t: f64) -> Option<(usize, usize)> {
    let mut eta = 0.0;
    let scale = 1.0 + hr.iter().fold(0.0f64, |m, r| m.max(r.at(t, 0.0).abs()));
    let mut closed = false;
    for _ in 0..2 * hr.len() + 8 {
        let (mut lo, mut up) = ((f64::NEG_INFINITY, 0), (f64::INFINITY, 0));
        for (k, r) in hr.iter().enumerate() {
            let v = r.at(t, eta);
            if r.upper && v < up.0 {
                up = (v, k);
            } else if !r.upper && v > lo.0 {
                lo = (v, k);
            }
        }
        let f = lo.0 - up.0;
        if f <= 1e-14 * scale {
            closed = true;
            break;
        }
        let slope = (hr[lo.1].c[2] + hr[lo.1].c[3] * t) - (hr[up.1].c[2] + hr[up.1].c[3] * t);
        if slope >= 0.0 {
            return None; // the band never opens along this line (N ≤ 0 somewhere)
        }
        eta -= f / slope;
    }
    if !closed {
        return None;
    }
    let w = hr
        .iter()
        .filter(|r| r.upper)
        .map(|r| r.at(t, eta))
        .fold(f64::INFINITY, f64::min);
    let tol = TOL * (scale + w.abs());
    let near = |r: &HingeRow| (r.at(t, eta) - w).abs() <= tol;
    let mut best: Option<(usize, usize, f64)> = None;
    for e in (0..hr.len()).filter(|&e| hr[e].upper && near(&hr[e])) {
        for i in (0..hr.len()).filter(|&i| !hr[i].upper && hr[i].j != hr[e].j && near(&hr[i])) {
            let d = diff(hr, e, i);
            let q = d[2] + d[3] * t;
            if q <= 0.0 {
                continue;
            }
            let slope = (d[0] * d[3] - d[1] * d[2]) / (q * q);
            if best.is_none_or(|b| slope > b.2) {
                best = Some((e, i, slope));
            }
        }
    }
    best.map(|b| (b.0, b.1))
}

/// row_e − row_i: on the piece of the pair (e, i), η(t) = −(d0 + d1 t)/(d2 + d3 t).
fn diff(hr: &[HingeRow], e: usize, i: usize) -> [f64; 4] {
    std::array::from_fn(|k| hr[e].c[k] - hr[i].c[k])
}

/// The ridge over one edge of Q, followed from t0 to t1. On each piece one E row and one I
/// row close the band: η(t) = −(d0 + d1 t)/(d2 + d3 t) with d = row_E − row_I. The piece
/// ends where a third row reaches w (a quadratic per row); there the pair changes to the one
/// with the larger dη/dt. Returns the points (t, η, w): the two ends of the edge (V), the
/// breakpoints (E1) and the points of each piece where the sliding column `cs` and the
/// pair's columns are dependent (E2, det = 0, a quadratic in η).
fn walk_edge(
    hr: &[HingeRow],
    (t0, t1): (f64, f64),
    cs: [f64; 3],
    js: &[JointRows],
) -> Result<Vec<(f64, f64, f64)>, String> {
    let eta_of = |d: &[f64; 4], t: f64| -(d[0] + d[1] * t) / (d[2] + d[3] * t);
    let slope = |d: &[f64; 4], t: f64| {
        let q = d[2] + d[3] * t;
        (d[0] * d[3] - d[1] * d[2]) / (q * q)
    };
    let mut out = Vec::new();
    let Some((mut e, mut i)) = ridge_pair(hr, t0) else {
        return Err(format!("no ridge over the edge of Q at t = {t0}"));
    };
    let w_at = |e: usize, d: &[f64; 4], t: f64| hr[e].at(t, eta_of(d, t));
    let d = diff(hr, e, i);
    out.push((t0, eta_of(&d, t0), w_at(e, &d, t0)));
    let mut t = t0;
    for _ in 0..4 * hr.len() + 4 {
        let d = diff(hr, e, i);
        let q = |t: f64| d[2] + d[3] * t;
        // the next row to reach w along the pair's curve
        let eps = 1e-12 * (1.0 + t.abs() + (t1 - t0).abs());
        let mut next: Option<(f64, usize)> = None;
        for r in (0..hr.len()).filter(|&r| r != e && r != i) {
            // (row_r − row_e)(t, η(t)) · q(t) = 0
            let g = diff(hr, r, e);
            let q2 = g[1] * d[3] - g[3] * d[1];
            let q1 = g[0] * d[3] + g[1] * d[2] - g[2] * d[1] - g[3] * d[0];
            let q0 = g[0] * d[2] - g[2] * d[0];
            // no sign change on (lo, hi] and no extremum of the other sign inside: no root
            // there (most rows, most pieces; a row that vanishes identically goes on)
            let (lo, hi) = (t + eps, next.map_or(t1, |n| n.0.min(t1)) + eps);
            let f = |x: f64| (q2 * x + q1) * x + q0;
            let (flo, fhi) = (f(lo), f(hi));
            if flo * fhi > 0.0 {
                let v = -0.5 * q1 / q2;
                if !(v > lo && v < hi) || f(v) * flo > 0.0 {
                    continue;
                }
            }
            let mag = g.iter().chain(&d).fold(0.0f64, |m, v| m.max(v.abs()));
            let small = 1e-13 * mag * mag;
            if q2.abs() <= small && q1.abs() <= small {
                if q0.abs() <= small {
                    return Err(format!(
                        "a family of ridge points: the rows of joints {}, {} and {} meet along an edge of Q",
                        hr[e].j, hr[i].j, hr[r].j
                    ));
                }
                continue;
            }
            let (nr, roots) = quadratic_roots(q2, q1, q0, small);
            for &tr in &roots[..nr] {
                if tr > t + eps && tr <= t1 + eps && q(tr) > 0.0 && next.is_none_or(|n| tr < n.0) {
                    next = Some((tr, r));
                }
            }
        }
        let t_end = next.map_or(t1, |n| n.0.min(t1));
        // E2 on the piece (t, t_end)
        let (ke, be) = (hr[e].kind(), js[hr[e].j].beta);
        let (ki, bi) = (hr[i].kind(), js[hr[i].j].beta);
        let det = |eta: f64| det3(cs, column(ke, be, eta), column(ki, bi, eta));
        let (f0, f1, f2) = (det(0.0), det(1.0), det(2.0));
        let k2 = 0.5 * (f2 - 2.0 * f1 + f0);
        let k1 = f1 - f0 - k2;
        let small = 1e-14 * (f0.abs() + f1.abs() + f2.abs());
        if k2.abs() > small || k1.abs() > small {
            let (nr, roots) = quadratic_roots(k2, k1, f0, small);
            for &eta in &roots[..nr] {
                let den = d[1] + eta * d[3];
                if den == 0.0 {
                    continue;
                }
                let te = -(d[0] + eta * d[2]) / den;
                if te > t - eps && te < t_end + eps {
                    out.push((te, eta, w_at(e, &d, te)));
                }
            }
        } else if f0.abs() <= small {
            return Err(format!(
                "a family of ridge points: the sliding column and the hinges at joints {} and {} are dependent at every eta",
                hr[e].j, hr[i].j
            ));
        }
        let Some((tn, r)) = next.filter(|n| n.0 < t1 - eps) else {
            out.push((t1, eta_of(&d, t1), w_at(e, &d, t1)));
            return Ok(out);
        };
        out.push((tn, eta_of(&d, tn), w_at(e, &d, tn)));
        // the pair after the breakpoint: the one with the larger dη/dt
        let (ne, ni) = if hr[r].upper { (r, i) } else { (e, r) };
        if hr[ne].j != hr[ni].j {
            let dn = diff(hr, ne, ni);
            if q(tn) > 0.0 && dn[2] + dn[3] * tn > 0.0 && slope(&dn, tn) >= slope(&d, tn) {
                e = ne;
                i = ni;
            }
        }
        t = tn;
    }
    Err("the walk along an edge of Q did not reach its end".into())
}

/// Q ∩ box as a convex polygon: its vertices in order, each with the index (in `lines`) of
/// the line that carries the edge from it to the next vertex. Sutherland–Hodgman clipping
/// of the box by each sliding half-plane, then each vertex again from its two lines
/// (clipping from the box's corners leaves absolute errors of order BOX · 1e-16).
fn q_polygon(lines: &[Line]) -> Vec<([f64; 2], usize)> {
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
            if (p[0] - q[0]).abs() + (p[1] - q[1]).abs() > 1e-13 * sc || next.len() == 1 {
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

fn det3(a: [f64; 3], b: [f64; 3], c: [f64; 3]) -> f64 {
    a[0] * (b[1] * c[2] - b[2] * c[1]) - a[1] * (b[0] * c[2] - b[2] * c[0])
        + a[2] * (b[0] * c[1] - b[1] * c[0])
}

/// Real roots of q2 t² + q1 t + q0 (a linear equation when |q2| ≤ small; the caller has
/// excluded q2 = q1 = 0): up to two, the count first.
fn quadratic_roots(q2: f64, q1: f64, q0: f64, small: f64) -> (usize, [f64; 2]) {
    if q2.abs() <= small {
        return (1, [-q0 / q1, 0.0]);
    }
    let disc = q1 * q1 - 4.0 * q2 * q0;
    if disc < -1e-12 * q1 * q1 {
        return (0, [0.0; 2]);
    }
    let sq = disc.max(0.0).sqrt();
    let qq = -0.5 * (q1 + q1.signum() * sq);
    if qq == 0.0 {
        return (1, [0.0; 2]);
    }
    (2, [qq / q2, q0 / qq])
}

/// A pre-filter on the joints' rows (no trigonometry): `false` only where the answer of
/// [`check`] is sure to be "no limit state" — the candidate is clearly not admissible
/// (some φ above 100 `adm_tol` times its magnitude), or every contact is clearly active or
/// clearly not (|φ| below `adm_tol`, or φ below −100 `adm_tol`, in units of its magnitude),
/// exactly four are active, one sliding sense per joint, and the cofactors of their columns
/// have mixed signs. Everything in between is left to `check`.
fn may_carry_mechanism(js: &[JointRows], mu: f64, c: &Candidate, settings: &Settings) -> bool {
    let p = [c.x[0], c.x[1]];
    let tol = settings.adm_tol;
    let mut active: [(usize, ContactKind); 4] = [(0, ContactKind::HingeExtrados); 4];
    let mut count = 0;
    for (j, jr) in js.iter().enumerate() {
        let (n, t, m) = (ev(&jr.n, p), ev(&jr.t, p), ev(&jr.m, p) + c.x[2]);
        for (kind, phi) in [
            (ContactKind::HingeExtrados, m - 0.5 * c.eta * n),
            (ContactKind::HingeIntrados, -m - 0.5 * c.eta * n),
            (ContactKind::SlidePlus, t - mu * n),
            (ContactKind::SlideMinus, -t - mu * n),
        ] {
            let mag = crate::statics::magnitude(kind, c.eta, mu, &c.x, settings.magnitude_floor);
            let r = phi / mag;
            if r > 100.0 * tol {
                return false;
            }
            if r < -100.0 * tol {
                continue;
            }
            if r.abs() > tol || count == 4 {
                return true; // near the tolerance, or more than four active: let `check` decide
            }
            active[count] = (j, kind);
            count += 1;
        }
    }
    if count != 4 {
        return true;
    }
    let slides = |k: ContactKind| matches!(k, ContactKind::SlidePlus | ContactKind::SlideMinus);
    for a in 0..4 {
        for b in a + 1..4 {
            if active[a].0 == active[b].0 && slides(active[a].1) && slides(active[b].1) {
                return true; // both senses at one joint
            }
        }
    }
    let cols: [[f64; 3]; 4] =
        std::array::from_fn(|k| column(active[k].1, js[active[k].0].beta, c.eta));
    null_vector_signs(&cols, 1e-6) != NullSigns::Mixed
}

/// The signs of the null vector of four compatibility columns (3 × 4), its cofactors.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum NullSigns {
    /// Every cofactor strictly of one sign: the rates of a mechanism.
    OneSign,
    /// Cofactors of both signs, none near zero: no mechanism on these four.
    Mixed,
    /// A cofactor within `zero_rel` of the largest: the null space may be larger (an LP
    /// decides).
    NearZero,
}

fn null_vector_signs(cols: &[[f64; 3]; 4], zero_rel: f64) -> NullSigns {
    let lam = [
        det3(cols[1], cols[2], cols[3]),
        -det3(cols[0], cols[2], cols[3]),
        det3(cols[0], cols[1], cols[3]),
        -det3(cols[0], cols[1], cols[2]),
    ];
    let big = lam.iter().fold(0.0f64, |m, v| m.max(v.abs()));
    if lam.iter().any(|v| v.abs() <= zero_rel * big) {
        NullSigns::NearZero
    } else if lam.iter().all(|&v| v > 0.0) || lam.iter().all(|&v| v < 0.0) {
        NullSigns::OneSign
    } else {
        NullSigns::Mixed
    }
}

/// A candidate checked like a point of the sweep: admissible at every joint, and a
/// mechanism on its active contacts. When exactly four contacts are active, one sliding
/// sense per joint, with no zero cofactor, the mechanism exists iff the null vector of
/// their 3 × 4 columns has one strict sign (O(1)); the LP then only builds it. `Err`: the
/// LP back end did not decide.
fn check(
    arch: &Arch,
    mu: f64,
    c: &Candidate,
    settings: &Settings,
) -> Result<Option<SweptState>, String> {
    let st = State {
        arch,
        eta: c.eta,
        mu,
        x: c.x,
    };
    let v = st.verdict(ContactKind::active_at(mu), settings);
    if v.worst > settings.adm_tol {
        return Ok(None);
    }
    let a = &v.active;
    let two_senses = a.iter().any(|p| {
        p.kind == ContactKind::SlidePlus
            && a.iter().any(|q| {
                q.kind == ContactKind::SlideMinus && (q.beta - p.beta).abs() <= settings.same_joint
            })
    });
    if a.len() == 4 && !two_senses {
        let cols: [[f64; 3]; 4] = std::array::from_fn(|k| column(a[k].kind, a[k].beta, c.eta));
        if null_vector_signs(&cols, 1e-9) == NullSigns::Mixed {
            return Ok(None);
        }
    }
    let mech = mechanism::find(&st, a, settings).map_err(|e| {
        format!(
            "the kinematic LP at eta = {} was not decided by the LP back end: {e:?}",
            c.eta
        )
    })?;
    Ok(mech.map(|m| SweptState::unloaded(arch, (c.eta, c.x), v.active, m, settings)))
}
