//! The walk along one edge of Q: the ridge over it, η = g(h, v), the least η whose band of
//! admissible w is not empty, is piecewise a closed form; the walk goes from piece to piece
//! and returns the points where a limit state may be (the edge's ends, the breakpoints, the
//! points of a piece with dependent columns).

use super::rows::{det3, HingeRow, JointRows, TOL};
use crate::kinematics::column;
use crate::undecided::Undecided;

/// The band of w is closed (empty or a point) where max l − min u is at most this times
/// the size of the rows.
const BAND_CLOSED_REL: f64 = 1e-14;

/// Along an edge, a breakpoint is a next one when it lies beyond the current point by more
/// than this times 1 + |t| + the edge's length (and the edge's end is reached within it).
const STEP_REL: f64 = 1e-12;

/// The quadratic whose roots are where a third row reaches w vanishes when its
/// coefficients are below this times the square of the rows' largest coefficient.
const ROW_ZERO_REL: f64 = 1e-13;

/// The quadratic in η of three columns' determinant vanishes when its coefficients are
/// below this times the sum of its values at η = 0, 1, 2.
const DET_ZERO_REL: f64 = 1e-14;

/// Pairs of hinge rows whose η at a point agree to this (relative) both reach the ridge
/// there (rounding of η = −(d0 + d1 t)/(d2 + d3 t)).
const PAIR_TIE_REL: f64 = 1e-13;

/// A quadratic has no real root when its discriminant is below −this times q1² (a double
/// root within rounding otherwise).
const NEGATIVE_DISC_REL: f64 = 1e-12;

/// The least η at which the band of w is not empty at t (the ridge's height g), with the
/// E and I rows that close it there (distinct joints), the pair that dominates just after
/// t (the largest dη/dt). Newton on the convex, decreasing, piecewise-linear
/// f(η) = max_I l(η) − min_E u(η) from η = 0: every step lands on or below the root, and
/// the pieces are finitely many.
fn ridge_pair(hr: &[HingeRow], t: f64) -> Option<(usize, usize)> {
    let mut eta = 0.0;
    // 1 + the largest |row| at η = 0 (found by Newton's first pass, which starts there)
    let mut scale = 1.0;
    let mut closed = false;
    for step in 0..2 * hr.len() + 8 {
        let (mut lo, mut up) = ((f64::NEG_INFINITY, 0), (f64::INFINITY, 0));
        for (k, r) in hr.iter().enumerate() {
            let v = r.at(t, eta);
            if step == 0 {
                scale = f64::max(scale, 1.0 + v.abs());
            }
            if r.upper && v < up.0 {
                up = (v, k);
            } else if !r.upper && v > lo.0 {
                lo = (v, k);
            }
        }
        let f = lo.0 - up.0;
        if f <= BAND_CLOSED_REL * scale {
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
    // the rows near w (E and I, each ascending), in one pass
    let (mut es, mut is) = (Vec::new(), Vec::new());
    for (k, r) in hr.iter().enumerate() {
        if (r.at(t, eta) - w).abs() <= tol {
            if r.upper {
                es.push(k);
            } else {
                is.push(k);
            }
        }
    }
    // the pairs of rows near w: their η at t, and dη/dt
    let mut pairs: Vec<(usize, usize, f64, f64)> = Vec::new();
    for &e in &es {
        for &i in is.iter().filter(|&&i| hr[i].j != hr[e].j) {
            let d = diff(hr, e, i);
            let q = d[2] + d[3] * t;
            if q <= 0.0 {
                continue;
            }
            let slope = (d[0] * d[3] - d[1] * d[2]) / (q * q);
            pairs.push((e, i, -(d[0] + d[1] * t) / q, slope));
        }
    }
    // the ridge is the largest pair's η: of the pairs that reach it (to rounding), the one
    // with the largest dη/dt dominates just after t (a pair near w by `TOL` but below the
    // ridge by more than rounding does not close the band there: at 1 000 voussoirs the
    // rows of neighbouring joints differ by 10⁻⁹ and cross a little way along the edge)
    let top = pairs.iter().fold(f64::NEG_INFINITY, |m, p| m.max(p.2));
    let tie = PAIR_TIE_REL * (1.0 + top.abs());
    pairs
        .iter()
        .filter(|p| p.2 >= top - tie)
        .fold(None, |b: Option<&(usize, usize, f64, f64)>, p| match b {
            Some(b) if b.3 >= p.3 => Some(b),
            _ => Some(p),
        })
        .map(|b| (b.0, b.1))
}

/// row_e − row_i: on the piece of the pair (e, i), η(t) = −(d0 + d1 t)/(d2 + d3 t).
fn diff(hr: &[HingeRow], e: usize, i: usize) -> [f64; 4] {
    std::array::from_fn(|k| hr[e].c[k] - hr[i].c[k])
}

/// The ridge over one edge of Q as walked: the points to check (t, η, w) and the pieces
/// (t_start, t_end, E row, I row), in order; where the walk stopped before the edge's end
/// (after its most pieces), the point and the pair of rows the next piece starts with.
pub(super) struct Walked {
    pub(super) points: Vec<(f64, f64, f64)>,
    pub(super) pieces: Vec<(f64, f64, usize, usize)>,
    pub(super) stopped: Option<(f64, usize, usize)>,
}

/// The ridge over one edge of Q, followed from t0 to t1. On each piece one E row and one I
/// row close the band: η(t) = −(d0 + d1 t)/(d2 + d3 t) with d = row_E − row_I. The piece
/// ends where a third row reaches w (a quadratic per row); there the pair changes to the one
/// with the larger dη/dt. Returns the points (t, η, w): the two ends of the edge (V), the
/// breakpoints (E1) and the points of each piece where the sliding column `cs` and the
/// pair's columns are dependent (E2, det = 0, a quadratic in η). `from`: the walk goes on
/// from a point where an earlier walk stopped, with its pair of rows (that point is not
/// returned again); it stops after `most_pieces` pieces.
pub(super) fn walk_edge(
    hr: &[HingeRow],
    (t0, t1): (f64, f64),
    (from, most_pieces): (Option<(f64, usize, usize)>, usize),
    cs: [f64; 3],
    js: &[JointRows],
) -> Result<Walked, Undecided> {
    let eta_of = |d: &[f64; 4], t: f64| -(d[0] + d[1] * t) / (d[2] + d[3] * t);
    let slope = |d: &[f64; 4], t: f64| {
        let q = d[2] + d[3] * t;
        (d[0] * d[3] - d[1] * d[2]) / (q * q)
    };
    let mut out = Vec::new();
    let mut pieces = Vec::new();
    let w_at = |e: usize, d: &[f64; 4], t: f64| hr[e].at(t, eta_of(d, t));
    let (mut t, mut e, mut i) = match from {
        Some(f) => f,
        None => {
            let Some((e, i)) = ridge_pair(hr, t0) else {
                return Err(Undecided::Resolution(format!(
                    "no ridge over the edge of Q at t = {t0}"
                )));
            };
            let d = diff(hr, e, i);
            out.push((t0, eta_of(&d, t0), w_at(e, &d, t0)));
            (t0, e, i)
        }
    };
    for _ in 0..4 * hr.len() + 4 {
        let d = diff(hr, e, i);
        let q = |t: f64| d[2] + d[3] * t;
        // the next row to reach w along the pair's curve
        let eps = STEP_REL * (1.0 + t.abs() + (t1 - t0).abs());
        let mut next: Option<(f64, usize)> = None;
        let ce = hr[e].c;
        for (r, row) in hr.iter().enumerate().filter(|&(r, _)| r != e && r != i) {
            // (row_r − row_e)(t, η(t)) · q(t) = 0
            let g: [f64; 4] = std::array::from_fn(|k| row.c[k] - ce[k]);
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
            let small = ROW_ZERO_REL * mag * mag;
            if q2.abs() <= small && q1.abs() <= small {
                if q0.abs() <= small {
                    return Err(Undecided::NotCovered(format!(
                        "a family of ridge points: the rows of joints {}, {} and {} meet along an edge of Q",
                        hr[e].j, hr[i].j, hr[r].j
                    )));
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
        pieces.push((t, t_end, e, i));
        // E2 on the piece (t, t_end)
        let (ke, be) = (hr[e].kind(), js[hr[e].j].beta);
        let (ki, bi) = (hr[i].kind(), js[hr[i].j].beta);
        let det = |eta: f64| det3(cs, column(ke, be, eta), column(ki, bi, eta));
        let (f0, f1, f2) = (det(0.0), det(1.0), det(2.0));
        let k2 = 0.5 * (f2 - 2.0 * f1 + f0);
        let k1 = f1 - f0 - k2;
        let small = DET_ZERO_REL * (f0.abs() + f1.abs() + f2.abs());
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
            return Err(Undecided::NotCovered(format!(
                "a family of ridge points: the sliding column and the hinges at joints {} and {} are dependent at every eta",
                hr[e].j, hr[i].j
            )));
        }
        let Some((tn, r)) = next.filter(|n| n.0 < t1 - eps) else {
            out.push((t1, eta_of(&d, t1), w_at(e, &d, t1)));
            if let Some(last) = pieces.last_mut() {
                last.1 = t1;
            }
            return Ok(Walked {
                points: out,
                pieces,
                stopped: None,
            });
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
        if pieces.len() >= most_pieces {
            return Ok(Walked {
                points: out,
                pieces,
                stopped: Some((t, e, i)),
            });
        }
    }
    Err(Undecided::Resolution(
        "the walk along an edge of Q did not reach its end".into(),
    ))
}

/// Real roots of q2 t² + q1 t + q0 (a linear equation when |q2| ≤ small; the caller has
/// excluded q2 = q1 = 0): up to two, the count first.
fn quadratic_roots(q2: f64, q1: f64, q0: f64, small: f64) -> (usize, [f64; 2]) {
    if q2.abs() <= small {
        return (1, [-q0 / q1, 0.0]);
    }
    let disc = q1 * q1 - 4.0 * q2 * q0;
    if disc < -NEGATIVE_DISC_REL * q1 * q1 {
        return (0, [0.0; 2]);
    }
    let sq = disc.max(0.0).sqrt();
    let qq = -0.5 * (q1 + q1.signum() * sq);
    if qq == 0.0 {
        return (1, [0.0; 2]);
    }
    (2, [qq / q2, q0 / qq])
}
