//! Prototype (issue 12 groundwork): every limit state of a DISCRETE arch (centreline weight,
//! finite μ) above η_s, found on the boundary of the friction polygon Q in the (h, v) plane
//! instead of by the sweep of P(η) in η. Design and proof: docs/design/limit-states-on-boundary.md.
//!
//! For each random arch: `limit_states::survey` (the reference: the sweep), then the
//! candidates on ∂Q. Every mechanism has Σϑ⁺ = Σϑ⁻ (third row of B) so, unless it is pure
//! sliding, an E and an I row are active and the w-band at (h, v) is closed: η = g(h, v).
//! The default search walks this ridge along each edge of the polygon Q (Q ∩ box, by
//! clipping): its ends (vertices of Q, case "V"), its breakpoints where a third hinge row
//! joins ("E1", a quadratic per row, O(n) per breakpoint) and the points of each piece where
//! the sliding column and the piece's E and I columns are dependent ("E2", det B(η) = 0).
//! DQ_BRUTE=1 instead crosses every E/I pair of hinge lines at every vertex of Q and solves
//! every mixed triple of hinge rows on every edge (O(n³) per edge), DQ_ALL_KINDS=1 with it
//! also the E,E / I,I pairs and E,E,E / I,I,I triples. Each candidate is checked with the
//! crate's public API (`State::verdict`; a cofactor sign test when exactly 4 contacts are
//! active, `mechanism::find` otherwise). Prints the agreements, the disagreements (with
//! details), checks of the claims on the sweep's states, the work and the median times.
//! DQ_MODE = random (default) | symmetric | large | p48 selects the arches (see `main`).
//!
//! `cargo run --release --example dq_prototype [CASES]` (default 240).

use arch_enum::contact::{Contact, ContactKind, Location};
use arch_enum::kinematics::column;
use arch_enum::limit_states::survey;
use arch_enum::mechanism;
use arch_enum::state::State;
use arch_enum::statics::actions;
use arch_enum::{least_friction, solve, Arch, Settings, WeightModel};
use std::f64::consts::PI;
use std::time::Instant;

/// Q is clipped by |h|, |v| ≤ BOX (an unbounded Q); points on the box are not candidates.
const BOX: f64 = 1e6;
/// Relative feasibility tolerance of the prototype's own pre-filters (the verdict is the
/// crate's: `Settings::adm_tol`).
const TOL: f64 = 1e-9;
/// DQ_DEBUG=<case>: print that case's polygon and walk.
static DEBUG: std::sync::atomic::AtomicBool = std::sync::atomic::AtomicBool::new(false);

struct Rng(u64);
impl Rng {
    fn next(&mut self) -> f64 {
        // xorshift64* (as tests/it/search_reference.rs)
        self.0 ^= self.0 >> 12;
        self.0 ^= self.0 << 25;
        self.0 ^= self.0 >> 27;
        let v = self.0.wrapping_mul(0x2545_f491_4f6c_dd1d);
        (v >> 11) as f64 / (1u64 << 53) as f64
    }
}

fn random_joints(rng: &mut Rng, br: f64, bl: f64, blocks: usize) -> Vec<f64> {
    let w: Vec<f64> = (0..blocks).map(|_| 0.4 + rng.next()).collect();
    let tot: f64 = w.iter().sum();
    let mut j = vec![br];
    let mut acc = 0.0;
    for wi in &w[..blocks - 1] {
        acc += wi;
        j.push(br + (bl - br) * acc / tot);
    }
    j.push(bl);
    j
}

/// N, T, m (= M − w) at each joint as affine functions of (h, v): [coef h, coef v, const].
struct Joints {
    beta: Vec<f64>,
    n: Vec<[f64; 3]>,
    t: Vec<[f64; 3]>,
    m: Vec<[f64; 3]>,
}

fn ev(a: &[f64; 3], p: [f64; 2]) -> f64 {
    a[0] * p[0] + a[1] * p[1] + a[2]
}

/// A half-plane a·p + b ≤ 0 of the (h, v) plane: a sliding row (joint, kind) or a box side.
#[derive(Clone, Copy)]
struct Row {
    a: [f64; 2],
    b: f64,
    slide: Option<(usize, ContactKind)>,
}

/// A hinge row along a line of the (h, v) plane p = p0 + t d:
/// w = A + B t + η (C + D t) is where it is active (E: upper bound on w, I: lower bound).
#[derive(Clone, Copy)]
struct HRow {
    j: usize,
    upper: bool,
    c: [f64; 4],
}

fn hinge_rows(js: &Joints, p0: [f64; 2], d: [f64; 2]) -> Vec<HRow> {
    let mut out = Vec::with_capacity(2 * js.beta.len());
    for j in 0..js.beta.len() {
        let (m, n) = (&js.m[j], &js.n[j]);
        let m0 = ev(m, p0);
        let m1 = m[0] * d[0] + m[1] * d[1];
        let n0 = ev(n, p0);
        let n1 = n[0] * d[0] + n[1] * d[1];
        out.push(HRow {
            j,
            upper: true,
            c: [-m0, -m1, 0.5 * n0, 0.5 * n1],
        });
        out.push(HRow {
            j,
            upper: false,
            c: [-m0, -m1, -0.5 * n0, -0.5 * n1],
        });
    }
    out
}

fn hkind(r: &HRow) -> (usize, ContactKind) {
    (
        r.j,
        if r.upper {
            ContactKind::HingeExtrados
        } else {
            ContactKind::HingeIntrados
        },
    )
}

fn hval(r: &HRow, t: f64, eta: f64) -> f64 {
    r.c[0] + r.c[1] * t + eta * (r.c[2] + r.c[3] * t)
}

/// Whether w lies in the band [max l, min u] of the hinge rows at (t, η), up to `tol`.
fn in_band(rows: &[HRow], t: f64, eta: f64, w: f64, tol: f64) -> bool {
    rows.iter().all(|r| {
        let v = hval(r, t, eta);
        if r.upper {
            w <= v + tol
        } else {
            w >= v - tol
        }
    })
}

/// One candidate point (h, v, w, η) and the case that produced it.
#[derive(Clone, Copy, Debug)]
struct Cand {
    x: [f64; 3],
    eta: f64,
    case: &'static str,
    /// The rows that define the point: (joint, kind); 3 (E2) or 4.
    support: [(usize, ContactKind); 4],
    size: usize,
}

#[derive(Default, Debug)]
struct Counts {
    vertices: usize,
    edges: usize,
    candidates: usize,
    checked: usize,
    families: usize,
    pieces: usize,
    walk_failures: usize,
}

/// Every candidate on ∂Q with η in (eta_lo, eta_hi).
fn candidates(
    js: &Joints,
    mu: f64,
    (eta_lo, eta_hi): (f64, f64),
    all_kinds: bool,
    walk: bool,
    cnt: &mut Counts,
) -> Vec<Cand> {
    let nj = js.beta.len();
    let mut rows: Vec<Row> = Vec::new();
    for j in 0..nj {
        for (sg, kind) in [
            (1.0, ContactKind::SlidePlus),
            (-1.0, ContactKind::SlideMinus),
        ] {
            let (t, n) = (&js.t[j], &js.n[j]);
            rows.push(Row {
                a: [sg * t[0] - mu * n[0], sg * t[1] - mu * n[1]],
                b: sg * t[2] - mu * n[2],
                slide: Some((j, kind)),
            });
        }
    }
    for (a, b) in [
        ([1.0, 0.0], 1.0),
        ([-1.0, 0.0], 1.0),
        ([0.0, 1.0], 1.0),
        ([0.0, -1.0], 1.0),
    ] {
        rows.push(Row {
            a,
            b: -b * BOX,
            slide: None,
        });
    }
    let scale = |p: [f64; 2]| 1.0 + p[0].abs() + p[1].abs();
    let feasible = |p: [f64; 2]| {
        rows.iter()
            .all(|r| r.a[0] * p[0] + r.a[1] * p[1] + r.b <= TOL * scale(p))
    };
    let mut out = Vec::new();

    if walk {
        // Q as a polygon (the box clipped by every sliding half-plane), then the walk of the
        // ridge along each of its sliding edges
        let poly = q_polygon(&rows);
        if DEBUG.load(std::sync::atomic::Ordering::Relaxed) {
            for (q, e) in &poly {
                eprintln!("vertex {q:?} edge row {e} {:?}", rows[*e].slide);
            }
        }
        cnt.vertices += poly.len();
        // V2: an apex of joint k (both its sliding lines meet: N_k = T_k = 0) has M_k = 0,
        // so w = −m_k(q) for every η, and E_k, I_k are always active: the ridge is the
        // vertical segment over q; its events are where another hinge row reaches w
        for k in 0..poly.len() {
            let (q, e1) = poly[k];
            let e0 = poly[(k + poly.len() - 1) % poly.len()].1;
            let (Some((j0, _)), Some((j1, _))) = (rows[e0].slide, rows[e1].slide) else {
                continue;
            };
            if j0 != j1 {
                continue;
            }
            let hr = hinge_rows(js, q, [0.0, 0.0]);
            let w = -ev(&js.m[j0], q);
            for r in hr.iter().filter(|r| r.j != j0) {
                if r.c[2] == 0.0 {
                    continue;
                }
                let eta = (w - r.c[0]) / r.c[2];
                if eta > eta_lo && eta < eta_hi && in_band(&hr, 0.0, eta, w, TOL * scale(q)) {
                    out.push(Cand {
                        x: [q[0], q[1], w],
                        eta,
                        case: "V2",
                        support: [
                            rows[e0].slide.unwrap(),
                            rows[e1].slide.unwrap(),
                            hkind(r),
                            hkind(r),
                        ],
                        size: 3,
                    });
                }
            }
        }
        for k in 0..poly.len() {
            let (q0, ri) = poly[k];
            let q1 = poly[(k + 1) % poly.len()].0;
            let Some(sl) = rows[ri].slide else {
                continue; // a side of the box
            };
            let len = ((q1[0] - q0[0]).powi(2) + (q1[1] - q0[1]).powi(2)).sqrt();
            if len <= 1e-12 * scale(q0) {
                continue;
            }
            cnt.edges += 1;
            // parametrised from the foot of the perpendicular from the origin (not from a
            // vertex, which may be on the box, 10⁶ away: t would lose ~10 digits)
            let (a, b) = (rows[ri].a, rows[ri].b);
            let na2 = a[0] * a[0] + a[1] * a[1];
            let p0 = [-b * a[0] / na2, -b * a[1] / na2];
            let d = [-a[1] / na2.sqrt(), a[0] / na2.sqrt()];
            let tof = |q: [f64; 2]| (q[0] - p0[0]) * d[0] + (q[1] - p0[1]) * d[1];
            let (t0, t1) = (tof(q0), tof(q1));
            let q0 = p0;
            let hr = hinge_rows(js, q0, d);
            let cs = column(sl.1, js.beta[sl.0], 0.0);
            for (t, eta, w, case, e, i, r) in walk_edge(&hr, (t0, t1), cs, js, cnt) {
                if DEBUG.load(std::sync::atomic::Ordering::Relaxed) {
                    eprintln!("  edge {k}: t = {t} in [{t0}, {t1}], eta = {eta}, w = {w}, {case}, rows {:?} {:?} {:?}", hkind(&hr[e]), hkind(&hr[i]), r.map(|r| hkind(&hr[r])));
                }
                let p = [q0[0] + t * d[0], q0[1] + t * d[1]];
                let on_box = p[0].abs() >= BOX * (1.0 - 1e-9) || p[1].abs() >= BOX * (1.0 - 1e-9);
                if !(eta > eta_lo && eta < eta_hi) || on_box {
                    continue;
                }
                let mut support = [sl, hkind(&hr[e]), hkind(&hr[i]), sl];
                let mut size = 3;
                if let Some(r) = r {
                    support[3] = hkind(&hr[r]);
                    size = 4;
                }
                out.push(Cand {
                    x: [p[0], p[1], w],
                    eta,
                    case,
                    support,
                    size,
                });
            }
        }
        cnt.candidates += out.len();
        return out;
    }
    // V: vertices of Q (pairs of rows), then crossings of two hinge lines in (η, w)
    let mut verts: Vec<[f64; 2]> = Vec::new();
    for i in 0..rows.len() {
        for k in i + 1..rows.len() {
            let (r, s) = (&rows[i], &rows[k]);
            let det = r.a[0] * s.a[1] - r.a[1] * s.a[0];
            if det.abs() <= 1e-14 * (r.a[0].abs() + r.a[1].abs()) * (s.a[0].abs() + s.a[1].abs()) {
                continue;
            }
            let p = [
                (-r.b * s.a[1] + s.b * r.a[1]) / det,
                (-r.a[0] * s.b + s.a[0] * r.b) / det,
            ];
            if !feasible(p)
                || verts
                    .iter()
                    .any(|q| (q[0] - p[0]).abs() + (q[1] - p[1]).abs() <= 1e-9 * scale(p))
            {
                continue;
            }
            verts.push(p);
            // a point on the box is not a state of the arch
            if p[0].abs() >= BOX * (1.0 - 1e-9) || p[1].abs() >= BOX * (1.0 - 1e-9) {
                continue;
            }
            cnt.vertices += 1;
            if walk {
                continue; // the walk of each edge starts and ends at the vertices
            }
            let hr = hinge_rows(js, p, [0.0, 0.0]);
            let tol = TOL * scale(p);
            for a in 0..hr.len() {
                for b in a + 1..hr.len() {
                    let (ra, rb) = (&hr[a], &hr[b]);
                    if !all_kinds && ra.upper == rb.upper {
                        continue; // two E (or two I) rows: no mechanism (third components)
                    }
                    let ds = ra.c[2] - rb.c[2];
                    if ds.abs() <= 1e-14 * (ra.c[2].abs() + rb.c[2].abs()) {
                        continue; // parallel lines (equal N, or the flat pair of an apex)
                    }
                    let eta = (rb.c[0] - ra.c[0]) / ds;
                    if !(eta > eta_lo && eta < eta_hi) {
                        continue;
                    }
                    let w = ra.c[0] + ra.c[2] * eta;
                    if in_band(&hr, 0.0, eta, w, tol) {
                        let (Some(s1), Some(s2)) = (r.slide, s.slide) else {
                            continue;
                        };
                        out.push(Cand {
                            x: [p[0], p[1], w],
                            eta,
                            case: "V",
                            support: [s1, s2, hkind(ra), hkind(rb)],
                            size: 4,
                        });
                    }
                }
            }
        }
    }

    // E1, E2: the open edges of Q (one sliding row active)
    for r in rows.iter().filter(|r| r.slide.is_some()) {
        let na = (r.a[0] * r.a[0] + r.a[1] * r.a[1]).sqrt();
        let p0 = [-r.b * r.a[0] / (na * na), -r.b * r.a[1] / (na * na)];
        let d = [-r.a[1] / na, r.a[0] / na];
        let (mut t0, mut t1) = (f64::NEG_INFINITY, f64::INFINITY);
        let mut empty = false;
        for s in &rows {
            let sd = s.a[0] * d[0] + s.a[1] * d[1];
            let sp = s.a[0] * p0[0] + s.a[1] * p0[1] + s.b;
            if std::ptr::eq(s, r) {
                continue;
            }
            if sd.abs() <= 1e-14 * (s.a[0].abs() + s.a[1].abs()) {
                if sp > TOL * scale(p0) {
                    empty = true;
                }
                continue;
            }
            let tb = -sp / sd;
            if sd > 0.0 {
                t1 = t1.min(tb);
            } else {
                t0 = t0.max(tb);
            }
        }
        if empty || t0 >= t1 {
            continue;
        }
        cnt.edges += 1;
        let hr = hinge_rows(js, p0, d);
        let pt = |t: f64| [p0[0] + t * d[0], p0[1] + t * d[1]];
        let span = 1e-12 * (1.0 + t0.abs() + t1.abs());
        let sl = r.slide.expect("sliding row");
        let push =
            |t: f64, eta: f64, w: f64, case: &'static str, hs: &[&HRow], out: &mut Vec<Cand>| {
                if !(t >= t0 - span && t <= t1 + span && eta > eta_lo && eta < eta_hi) {
                    return;
                }
                let p = pt(t);
                if p[0].abs() >= BOX * (1.0 - 1e-9) || p[1].abs() >= BOX * (1.0 - 1e-9) {
                    return;
                }
                if in_band(&hr, t, eta, w, TOL * scale(p)) {
                    let mut support = [sl; 4];
                    for (k, h) in hs.iter().enumerate() {
                        support[k + 1] = hkind(h);
                    }
                    out.push(Cand {
                        x: [p[0], p[1], w],
                        eta,
                        case,
                        support,
                        size: 1 + hs.len(),
                    });
                }
            };
        if walk {
            let cs = column(sl.1, js.beta[sl.0], 0.0);
            for (t, eta, w, case, e, i, r) in walk_edge(&hr, (t0, t1), cs, js, cnt) {
                let mut rows = vec![&hr[e], &hr[i]];
                if let Some(r) = r {
                    rows.push(&hr[r]);
                }
                push(t, eta, w, case, &rows, &mut out);
            }
            continue;
        }
        // E1: three concurrent hinge rows at three distinct joints
        for a in 0..hr.len() {
            for b in a + 1..hr.len() {
                if hr[a].j == hr[b].j {
                    continue;
                }
                let d1: [f64; 4] = std::array::from_fn(|i| hr[a].c[i] - hr[b].c[i]);
                for c in b + 1..hr.len() {
                    if hr[c].j == hr[a].j || hr[c].j == hr[b].j {
                        continue;
                    }
                    if !all_kinds && hr[a].upper == hr[b].upper && hr[b].upper == hr[c].upper {
                        continue; // three E (or three I) rows: no mechanism
                    }
                    let d2: [f64; 4] = std::array::from_fn(|i| hr[a].c[i] - hr[c].c[i]);
                    // (d1[0] + d1[1] t)(d2[2] + d2[3] t) − (d2[0] + d2[1] t)(d1[2] + d1[3] t) = 0
                    let q2 = d1[1] * d2[3] - d2[1] * d1[3];
                    let q1 = d1[0] * d2[3] + d1[1] * d2[2] - d2[0] * d1[3] - d2[1] * d1[2];
                    let q0 = d1[0] * d2[2] - d2[0] * d1[2];
                    let mag = d1.iter().chain(&d2).fold(0.0f64, |m, v| m.max(v.abs()));
                    let small = 1e-13 * mag * mag;
                    if q2.abs() <= small && q1.abs() <= small {
                        if q0.abs() <= small {
                            cnt.families += 1;
                        }
                        continue;
                    }
                    for t in quadratic_roots(q2, q1, q0, small) {
                        let Some((t, eta, w)) = polish3([&hr[a], &hr[b], &hr[c]], t) else {
                            continue;
                        };
                        push(t, eta, w, "E1", &[&hr[a], &hr[b], &hr[c]], &mut out);
                    }
                }
            }
        }
        // E2: the sliding row and two hinges at distinct joints with dependent columns
        let (ja, ka) = r.slide.expect("sliding row");
        let cs = column(ka, js.beta[ja], 0.0);
        for a in 0..hr.len() {
            for b in a + 1..hr.len() {
                if hr[a].j == hr[b].j || (!all_kinds && hr[a].upper == hr[b].upper) {
                    continue;
                }
                let kind = |h: &HRow| {
                    if h.upper {
                        ContactKind::HingeExtrados
                    } else {
                        ContactKind::HingeIntrados
                    }
                };
                let det = |eta: f64| {
                    let c1 = column(kind(&hr[a]), js.beta[hr[a].j], eta);
                    let c2 = column(kind(&hr[b]), js.beta[hr[b].j], eta);
                    det3(cs, c1, c2)
                };
                // det is a quadratic in η: interpolate at 0, 1, 2
                let (f0, f1, f2) = (det(0.0), det(1.0), det(2.0));
                let q2 = 0.5 * (f2 - 2.0 * f1 + f0);
                let q1 = f1 - f0 - q2;
                let small = 1e-14 * (f0.abs() + f1.abs() + f2.abs());
                if q2.abs() <= small && q1.abs() <= small {
                    if f0.abs() <= small {
                        cnt.families += 1;
                    }
                    continue;
                }
                for eta in quadratic_roots(q2, q1, f0, small) {
                    let dd: [f64; 4] = std::array::from_fn(|i| hr[a].c[i] - hr[b].c[i]);
                    let den = dd[1] + eta * dd[3];
                    if den.abs() <= 1e-14 * (dd[1].abs() + eta * dd[3].abs()) {
                        continue;
                    }
                    let t = -(dd[0] + eta * dd[2]) / den;
                    push(
                        t,
                        eta,
                        hval(&hr[a], t, eta),
                        "E2",
                        &[&hr[a], &hr[b]],
                        &mut out,
                    );
                }
            }
        }
    }
    cnt.candidates += out.len();
    out
}

/// The ridge of P over one edge of Q: G(t) = least η with a non-empty w-band at p(t),
/// followed from t0 to t1. On each piece one E row (index `e` of `hr`) and one I row (`i`)
/// close the band: η(t) = −(a + b t)/(c + d t) with (a, b, c, d) = row_e − row_i. The piece
/// ends where a third row reaches w (a quadratic per row, O(n)); there the pair changes to
/// the one that dominates after (the larger dη/dt). Returns the points (t, η, w, case, e, i,
/// third row): the two ends of the edge (vertices of Q, case "V"), the breakpoints ("E1"),
/// and the points of each piece where the sliding column and the pair's columns are
/// dependent ("E2", det B(η) = 0, a quadratic in η).
#[allow(clippy::type_complexity)]
fn walk_edge(
    hr: &[HRow],
    (t0, t1): (f64, f64),
    cs: [f64; 3],
    js: &Joints,
    cnt: &mut Counts,
) -> Vec<(f64, f64, f64, &'static str, usize, usize, Option<usize>)> {
    let mut out = Vec::new();
    let diff =
        |e: usize, i: usize| -> [f64; 4] { std::array::from_fn(|k| hr[e].c[k] - hr[i].c[k]) };
    let eta_of = |d: &[f64; 4], t: f64| -(d[0] + d[1] * t) / (d[2] + d[3] * t);
    let slope = |d: &[f64; 4], t: f64| {
        let q = d[2] + d[3] * t;
        (d[0] * d[3] - d[1] * d[2]) / (q * q)
    };
    // the pair at t0: the largest η over (E, I) pairs at distinct joints, ties by slope
    let mut best: Option<(usize, usize, f64, f64)> = None;
    for e in (0..hr.len()).filter(|&e| hr[e].upper) {
        for i in (0..hr.len()).filter(|&i| !hr[i].upper && hr[i].j != hr[e].j) {
            let d = diff(e, i);
            if d[2] + d[3] * t0 <= 1e-14 * (d[2].abs() + d[3].abs() * t0.abs()) {
                continue;
            }
            let (eta, sl) = (eta_of(&d, t0), slope(&d, t0));
            let tol = 1e-12 * (1.0 + eta.abs());
            let better = match best {
                None => true,
                Some((_, _, be, bs)) => eta > be + tol || (eta >= be - tol && sl > bs),
            };
            if better {
                best = Some((e, i, eta, sl));
            }
        }
    }
    let Some((mut e, mut i, _, _)) = best else {
        return out;
    };
    let w_at = |e: usize, d: &[f64; 4], t: f64| hval(&hr[e], t, eta_of(d, t));
    let d = diff(e, i);
    out.push((t0, eta_of(&d, t0), w_at(e, &d, t0), "V", e, i, None));
    let mut t = t0;
    let kind = |h: &HRow| {
        if h.upper {
            ContactKind::HingeExtrados
        } else {
            ContactKind::HingeIntrados
        }
    };
    for _ in 0..4 * hr.len() + 4 {
        cnt.pieces += 1;
        let d = diff(e, i);
        let q = |t: f64| d[2] + d[3] * t;
        // the next row to reach w along the pair's curve
        let eps = 1e-12 * (1.0 + t.abs() + (t1 - t0).abs());
        let mut next: Option<(f64, usize)> = None;
        for r in (0..hr.len()).filter(|&r| r != e && r != i) {
            // (row_r − row_e)(t, η(t)) · q(t) = 0: (A + B t) q(t) − (C + D t)(a + b t)
            let g = diff(r, e);
            let q2 = g[1] * d[3] - g[3] * d[1];
            let q1 = g[0] * d[3] + g[1] * d[2] - g[2] * d[1] - g[3] * d[0];
            let q0 = g[0] * d[2] - g[2] * d[0];
            let mag = g.iter().chain(&d).fold(0.0f64, |m, v| m.max(v.abs()));
            let small = 1e-13 * mag * mag;
            if q2.abs() <= small && q1.abs() <= small {
                if q0.abs() <= small {
                    cnt.families += 1;
                }
                continue;
            }
            for tr in quadratic_roots(q2, q1, q0, small) {
                if tr > t + eps
                    && tr <= t1 + eps
                    && q(tr) > 0.0
                    && next.is_none_or(|(tn, _)| tr < tn)
                {
                    next = Some((tr, r));
                }
            }
        }
        let t_end = next.map_or(t1, |(tn, _)| tn.min(t1));
        // E2 on the piece (t, t_end)
        let (ce, ci) = (
            (kind(&hr[e]), js.beta[hr[e].j]),
            (kind(&hr[i]), js.beta[hr[i].j]),
        );
        let det = |eta: f64| det3(cs, column(ce.0, ce.1, eta), column(ci.0, ci.1, eta));
        let (f0, f1, f2) = (det(0.0), det(1.0), det(2.0));
        let k2 = 0.5 * (f2 - 2.0 * f1 + f0);
        let k1 = f1 - f0 - k2;
        let small = 1e-14 * (f0.abs() + f1.abs() + f2.abs());
        if k2.abs() > small || k1.abs() > small {
            for eta in quadratic_roots(k2, k1, f0, small) {
                let den = d[1] + eta * d[3];
                if den == 0.0 {
                    continue;
                }
                let te = -(d[0] + eta * d[2]) / den;
                if te > t - eps && te < t_end + eps {
                    out.push((te, eta, w_at(e, &d, te), "E2", e, i, None));
                }
            }
        } else if f0.abs() <= small {
            cnt.families += 1;
        }
        let Some((tn, r)) = next.filter(|(tn, _)| *tn < t1 - eps) else {
            out.push((t1, eta_of(&d, t1), w_at(e, &d, t1), "V", e, i, None));
            return out;
        };
        let w = w_at(e, &d, tn);
        out.push((tn, eta_of(&d, tn), w, "E1", e, i, Some(r)));
        // the pair after the breakpoint: the one with the larger dη/dt
        let (ne, ni) = if hr[r].upper { (r, i) } else { (e, r) };
        if hr[ne].j != hr[ni].j {
            let dn = diff(ne, ni);
            if q(tn) > 0.0 && dn[2] + dn[3] * tn > 0.0 && slope(&dn, tn) >= slope(&d, tn) {
                e = ne;
                i = ni;
            }
        }
        t = tn;
    }
    cnt.walk_failures += 1;
    out
}

/// Q ∩ box as a convex polygon: its vertices in order, each with the index (in `rows`) of
/// the row whose line carries the edge from it to the next vertex. Sutherland–Hodgman
/// clipping of the box by each sliding half-plane: O(rows · vertices).
fn q_polygon(rows: &[Row]) -> Vec<([f64; 2], usize)> {
    let boxes: Vec<usize> = (0..rows.len())
        .filter(|&k| rows[k].slide.is_none())
        .collect();
    // box rows in the order h ≤ B, −h ≤ B, v ≤ B, −v ≤ B; counter-clockwise from (B, −B)
    let (hp, hm, vp, vm) = (boxes[0], boxes[1], boxes[2], boxes[3]);
    let mut poly = vec![
        ([BOX, -BOX], hp),
        ([BOX, BOX], vp),
        ([-BOX, BOX], hm),
        ([-BOX, -BOX], vm),
    ];
    for (ri, r) in rows.iter().enumerate().filter(|(_, r)| r.slide.is_some()) {
        if poly.is_empty() {
            break;
        }
        let f = |p: [f64; 2]| r.a[0] * p[0] + r.a[1] * p[1] + r.b;
        let mut next = Vec::with_capacity(poly.len() + 1);
        for k in 0..poly.len() {
            let (p, e) = poly[k];
            let q = poly[(k + 1) % poly.len()].0;
            let (fp, fq) = (f(p), f(q));
            if fp <= 0.0 {
                next.push((p, e));
                if fq > 0.0 {
                    let s = fp / (fp - fq);
                    next.push(([p[0] + s * (q[0] - p[0]), p[1] + s * (q[1] - p[1])], ri));
                }
            } else if fq <= 0.0 {
                let s = fp / (fp - fq);
                next.push(([p[0] + s * (q[0] - p[0]), p[1] + s * (q[1] - p[1])], e));
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
    // each vertex again from its two lines (clipping from the box's corners leaves absolute
    // errors of order BOX · 1e-16)
    let m = poly.len();
    (0..m)
        .map(|k| {
            let (p, e) = poly[k];
            let (r, s) = (&rows[poly[(k + m - 1) % m].1], &rows[e]);
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

/// Real roots of q2 t² + q1 t + q0 (a linear equation when |q2| ≤ small).
fn quadratic_roots(q2: f64, q1: f64, q0: f64, small: f64) -> Vec<f64> {
    if q2.abs() <= small {
        return vec![-q0 / q1];
    }
    let disc = q1 * q1 - 4.0 * q2 * q0;
    if disc < -1e-12 * q1 * q1 {
        return Vec::new();
    }
    let sq = disc.max(0.0).sqrt();
    let qq = -0.5 * (q1 + q1.signum() * sq);
    if qq == 0.0 {
        return vec![0.0];
    }
    vec![qq / q2, q0 / qq]
}

/// Newton on the three equations w = row_i(t, η) from t (η, w from the first two rows).
fn polish3(r: [&HRow; 3], t: f64) -> Option<(f64, f64, f64)> {
    let d1: [f64; 4] = std::array::from_fn(|i| r[0].c[i] - r[1].c[i]);
    let den = d1[2] + d1[3] * t;
    let (mut t, mut eta) = if den.abs() > 1e-14 * (d1[2].abs() + d1[3].abs() * t.abs()) {
        (t, -(d1[0] + d1[1] * t) / den)
    } else {
        let d2: [f64; 4] = std::array::from_fn(|i| r[0].c[i] - r[2].c[i]);
        let den2 = d2[2] + d2[3] * t;
        if den2 == 0.0 {
            return None;
        }
        (t, -(d2[0] + d2[1] * t) / den2)
    };
    if !t.is_finite() || !eta.is_finite() {
        return None;
    }
    let mut w = hval(r[0], t, eta);
    for _ in 0..3 {
        // F_k = row_k(t, η) − w; J_k = [B + η D, C + D t, −1]
        let f: [f64; 3] = std::array::from_fn(|k| hval(r[k], t, eta) - w);
        let jm: [[f64; 3]; 3] =
            std::array::from_fn(|k| [r[k].c[1] + eta * r[k].c[3], r[k].c[2] + r[k].c[3] * t, -1.0]);
        let cols = |k: usize| [jm[0][k], jm[1][k], jm[2][k]];
        let det = det3(cols(0), cols(1), cols(2));
        if det == 0.0 || !det.is_finite() {
            break;
        }
        let dt = det3(f, cols(1), cols(2)) / det;
        let de = det3(cols(0), f, cols(2)) / det;
        let dw = det3(cols(0), cols(1), f) / det;
        t -= dt;
        eta -= de;
        w -= dw;
    }
    Some((t, eta, w))
}

/// A limit state found by the prototype: η, x, the case, the active set, sliding rate.
#[derive(Clone, Debug)]
struct Found {
    /// The rows that produced the candidate (joint, kind), the first `size` of them.
    support: [(usize, ContactKind); 4],
    size: usize,
    eta: f64,
    x: [f64; 3],
    case: &'static str,
    active: Vec<Contact>,
}

fn check(arch: &Arch, mu: f64, c: &Cand, settings: &Settings) -> Option<Found> {
    let st = State {
        arch,
        eta: c.eta,
        mu,
        x: c.x,
    };
    let v = st.verdict(ContactKind::active_at(mu), settings);
    if v.worst > settings.adm_tol {
        return None;
    }
    // the O(1) test: exactly 4 contacts active, one sliding sense per joint ⇒ a mechanism
    // iff the cofactor null vector of their columns (3 × 4) has one strict sign. Otherwise
    // (3 or ≥ 5 active, both senses at a joint, a zero cofactor) the LP decides.
    let a = &v.active;
    let two_senses = a.iter().any(|p| {
        p.kind == ContactKind::SlidePlus
            && a.iter().any(|q| {
                q.kind == ContactKind::SlideMinus && (q.beta - p.beta).abs() <= settings.same_joint
            })
    });
    let mut decided = false;
    if a.len() == 4 && !two_senses {
        let cols: Vec<[f64; 3]> = a.iter().map(|p| column(p.kind, p.beta, c.eta)).collect();
        let lam = [
            det3(cols[1], cols[2], cols[3]),
            -det3(cols[0], cols[2], cols[3]),
            det3(cols[0], cols[1], cols[3]),
            -det3(cols[0], cols[1], cols[2]),
        ];
        let big = lam.iter().fold(0.0f64, |m, v| m.max(v.abs()));
        if lam.iter().all(|v| v.abs() > 1e-9 * big) {
            if !(lam.iter().all(|&v| v > 0.0) || lam.iter().all(|&v| v < 0.0)) {
                return None;
            }
            decided = true;
        }
    }
    if !decided {
        mechanism::find(&st, &v.active, settings).ok()??;
    }
    Some(Found {
        support: c.support,
        size: c.size,
        eta: c.eta,
        x: c.x,
        case: c.case,
        active: v.active,
    })
}

fn same(a: (f64, [f64; 3]), b: (f64, [f64; 3])) -> bool {
    let sc = 1.0 + a.1.iter().map(|v| v.abs()).sum::<f64>();
    (a.0 - b.0).abs() <= 1e-8 * a.0.max(1e-3)
        && (0..3).all(|k| (a.1[k] - b.1[k]).abs() <= 1e-6 * sc)
}

fn joints_of(arch: &Arch, joints: &[f64]) -> Joints {
    let mut js = Joints {
        beta: joints.to_vec(),
        n: Vec::new(),
        t: Vec::new(),
        m: Vec::new(),
    };
    for &b in joints {
        let a = actions(arch, 1.0, b);
        js.n.push([a.n[0].g[0], a.n[0].g[1], a.n[0].c]);
        js.t.push([a.t[0].g[0], a.t[0].g[1], a.t[0].c]);
        js.m.push([a.m[0].g[0], a.m[0].g[1], a.m[0].c]);
    }
    js
}

fn median(v: &mut [f64]) -> f64 {
    v.sort_by(f64::total_cmp);
    if v.is_empty() {
        f64::NAN
    } else {
        v[v.len() / 2]
    }
}

fn main() {
    let cases: usize = std::env::args()
        .nth(1)
        .map(|s| s.parse().expect("CASES: a positive integer"))
        .unwrap_or(240);
    let settings = Settings::default();
    // DQ_ALL_KINDS=1: also the E,E / I,I crossings and E,E,E / I,I,I triples (which carry no
    // mechanism generically: the third components of the hinge columns are -1 and +1)
    let all_kinds = std::env::var("DQ_ALL_KINDS").is_ok_and(|v| v == "1");
    // DQ_BRUTE=1: every pair/triple of hinge rows (O(n^3) per edge) instead of the walk of
    // the ridge along each edge (O(n) per breakpoint)
    let walk = !std::env::var("DQ_BRUTE").is_ok_and(|v| v == "1");
    // DQ_MODE: "random" (default: arch-like and arbitrary springings, 3-8 voussoirs),
    // "symmetric" (equal voussoirs, 3-12: mirror pairs, where families may appear) or
    // "large" (arch-like, 12-24 voussoirs: how the times scale) or "p48" (48 equal
    // voussoirs, symmetric: the coarse discretisation `survey` uses for a continuous arch)
    // or "p96" (96: the fine one)
    let mode_s = std::env::var("DQ_MODE").unwrap_or_else(|_| "random".into());
    let mode = mode_s.as_str();
    let skip: Vec<String> = std::env::var("DQ_SKIP")
        .map(|v| v.split(',').map(str::to_string).collect())
        .unwrap_or_default();
    assert!(
        ["random", "symmetric", "large", "p48", "p96"].contains(&mode),
        "DQ_MODE must be random, symmetric, large, p48 or p96, not {mode}"
    );
    let mut rng = Rng(0x1234_5678_9abc_def1);
    let (mut agree, mut agree_nonempty, mut differ, mut skipped) = (0usize, 0usize, 0usize, 0usize);
    let (mut states_ref, mut states_dq) = (0usize, 0usize);
    let (mut hinge_only, mut off_boundary, mut band_open) = (0usize, 0usize, 0usize);
    let mut by_case = std::collections::BTreeMap::<&str, usize>::new();
    let (mut t_survey, mut t_solve, mut t_dq) = (Vec::new(), Vec::new(), Vec::new());
    let mut t_gen = Vec::new();
    let mut cnt = Counts::default();
    let mut reports = Vec::new();
    let mut sizes = Vec::new();
    let mut case = 0;
    let mut wild_count = 0;
    while sizes.len() < cases {
        case += 1;
        // three quarters arch-like (springings within 0.6 rad of a semicircle's, 3-8
        // voussoirs), one quarter arbitrary (spans 0.3-3.8 rad anywhere, 3-4 voussoirs), as
        // tests/it/search_reference.rs; μ within 2 % of μ_ms, within 30 %, or up to 3
        let wild = mode == "random" && case % 4 == 3;
        let (n, br, bl) = if wild {
            let n = 3 + (rng.next() * 2.0) as usize;
            let br = -1.2 + 2.6 * rng.next();
            (n, br, br + 0.3 + 3.5 * rng.next())
        } else {
            let n = match mode {
                "large" => 12 + (rng.next() * 13.0) as usize, // 12..=24 voussoirs
                "symmetric" => 3 + (rng.next() * 10.0) as usize, // 3..=12
                "p48" => 48,
                "p96" => 96,
                _ => 3 + (rng.next() * 6.0) as usize, // 3..=8
            };
            let br = -0.6 + 1.2 * rng.next();
            let bl = if mode == "symmetric" || mode == "p48" || mode == "p96" {
                PI - br
            } else {
                PI - 0.6 + 1.2 * rng.next()
            };
            (n, br, bl)
        };
        let joints = if mode == "symmetric" || mode == "p48" || mode == "p96" {
            // equal voussoirs, exactly mirror-symmetric angles
            let mut j: Vec<f64> = (0..=n)
                .map(|k| br + (bl - br) * k as f64 / n as f64)
                .collect();
            for k in 0..=n / 2 {
                j[n - k] = PI - j[k];
            }
            if n % 2 == 0 {
                j[n / 2] = 0.5 * PI;
            }
            j
        } else {
            random_joints(&mut rng, br, bl, n)
        };
        let u = rng.next();
        let arch = Arch::new(br, bl, WeightModel::Centreline)
            .and_then(|a| a.with_joints(&joints))
            .expect("valid arch");
        let Ok(Some(ms)) = least_friction(&arch, &settings) else {
            continue;
        };
        let mu = match case % 3 {
            0 => ms * (1.0 + 0.02 * u) + 1e-6 * ms,
            1 => ms * (1.0 + 0.3 * u * u) + 1e-3 * ms,
            _ if ms < 3.0 => ms + (3.0 - ms) * u * u + 1e-3 * ms,
            _ => ms * (1.0 + u),
        };
        if wild {
            wild_count += 1;
        }
        sizes.push(n);
        let t = Instant::now();
        let sv = survey(&arch, mu, &settings).expect("valid input");
        t_survey.push(t.elapsed().as_secs_f64());
        let t = Instant::now();
        let sol = solve(&arch, mu, &settings).expect("valid input");
        t_solve.push(t.elapsed().as_secs_f64());
        let _ = sol;
        let Ok(reference) = &sv.states else {
            skipped += 1;
            reports.push(format!(
                "case {case}: survey incomplete: {:?}",
                sv.states.as_ref().err()
            ));
            continue;
        };
        let eta_lo = reference.eta_s * (1.0 + settings.root_slack);
        let js = joints_of(&arch, &joints);
        DEBUG.store(
            std::env::var("DQ_DEBUG").is_ok_and(|v| v == case.to_string()),
            std::sync::atomic::Ordering::Relaxed,
        );
        let t = Instant::now();
        let mut cands = candidates(
            &js,
            mu,
            (eta_lo, 2.0 * (1.0 - 1e-9)),
            all_kinds,
            walk,
            &mut cnt,
        );
        // DQ_SKIP=V,E1,...: drop those cases (shows that each case is needed)
        cands.retain(|c| !skip.iter().any(|k| k == c.case));
        t_gen.push(t.elapsed().as_secs_f64());
        let mut found: Vec<Found> = Vec::new();
        for c in &cands {
            if found.iter().any(|f| same((f.eta, f.x), (c.eta, c.x))) {
                continue;
            }
            cnt.checked += 1;
            if let Some(f) = check(&arch, mu, c, &settings) {
                found.push(f);
            }
        }
        found.sort_by(|a, b| a.eta.total_cmp(&b.eta));
        t_dq.push(t.elapsed().as_secs_f64());

        // the theorem on the sweep's states: no hinge-only mechanism, (h, v) on ∂Q
        for s in &reference.above {
            let hinges: Vec<Contact> = s
                .pattern
                .iter()
                .copied()
                .filter(|c| c.kind.is_hinge())
                .collect();
            let st = State {
                arch: &arch,
                eta: s.eta,
                mu,
                x: s.x,
            };
            if !hinges.is_empty() && matches!(mechanism::find(&st, &hinges, &settings), Ok(Some(_)))
            {
                hinge_only += 1;
            }
            if !s.pattern.iter().any(|c| !c.kind.is_hinge()) {
                off_boundary += 1;
            }
            // the band of w at (h, v) is closed there: η = g(h, v)
            let hr = hinge_rows(&js, [s.x[0], s.x[1]], [0.0, 0.0]);
            let (mut lo, mut hi) = (f64::NEG_INFINITY, f64::INFINITY);
            for r in &hr {
                let v = hval(r, 0.0, s.eta);
                if r.upper {
                    hi = hi.min(v);
                } else {
                    lo = lo.max(v);
                }
            }
            let sc = 1.0 + s.x.iter().map(|v| v.abs()).sum::<f64>();
            if hi - lo > 1e-9 * sc * s.eta.max(1e-3) {
                band_open += 1;
            }
        }
        states_ref += reference.above.len();
        states_dq += found.len();
        for f in &found {
            *by_case.entry(f.case).or_default() += 1;
        }
        let missing: Vec<_> = reference
            .above
            .iter()
            .filter(|s| !found.iter().any(|f| same((f.eta, f.x), (s.eta, s.x))))
            .collect();
        let extra: Vec<_> = found
            .iter()
            .filter(|f| {
                !reference
                    .above
                    .iter()
                    .any(|s| same((f.eta, f.x), (s.eta, s.x)))
            })
            .collect();
        if missing.is_empty() && extra.is_empty() {
            agree += 1;
            if !found.is_empty() {
                agree_nonempty += 1;
            }
        } else {
            differ += 1;
            let mut r = format!(
                "case {case}: beta_r = {br:?}, beta_l = {bl:?}, joints = {joints:?}, mu = {mu:?} (mu_ms = {ms:?}), eta_s = {:?}",
                reference.eta_s
            );
            for s in &missing {
                let pat: Vec<String> = s
                    .pattern
                    .iter()
                    .map(|c| format!("{}@{:.6}", c.kind.name(), c.beta))
                    .collect();
                r += &format!(
                    "\n  missed (sweep only): eta = {:.15}, x = {:?}, pattern {}",
                    s.eta,
                    s.x,
                    pat.join(" ")
                );
            }
            for f in &extra {
                let pat: Vec<String> = f
                    .active
                    .iter()
                    .map(|c| format!("{}@{:.6}", c.kind.name(), c.beta))
                    .collect();
                r += &format!(
                    "\n  extra (prototype only, case {} from rows {:?}): eta = {:.15}, x = {:?}, pattern {}",
                    f.case,
                    &f.support[..f.size],
                    f.eta,
                    f.x,
                    pat.join(" ")
                );
            }
            reports.push(r);
        }
    }
    let _ = Location::Interior;
    let ms = |v: &mut Vec<f64>| median(v) * 1e6;
    println!("=== dq_prototype: {cases} random discrete arches, DQ_MODE={mode} (centreline weight; {wild_count} with arbitrary springings; mu in (mu_ms, max(3, 2 mu_ms)]; median voussoirs {}) ===", median(&mut sizes.iter().map(|&v| v as f64).collect::<Vec<_>>()));
    println!(
        "candidates: {}",
        if walk {
            "walk of the ridge G along each edge of Q"
        } else if all_kinds {
            "brute force, all hinge kinds (DQ_BRUTE=1 DQ_ALL_KINDS=1)"
        } else {
            "brute force, E and I mixed (DQ_BRUTE=1)"
        }
    );
    println!("survey incomplete (not compared): {skipped}");
    println!(
        "agree: {agree} (of which with limit states above eta_s: {agree_nonempty}), disagree: {differ}"
    );
    println!("limit states above eta_s: sweep {states_ref}, prototype {states_dq}; prototype by case: {by_case:?}");
    println!(
        "theorem on the sweep's states: hinge-only mechanism on the active set: {hinge_only}, no active sliding row: {off_boundary}, w-band not closed (eta > g(h, v)): {band_open}"
    );
    println!(
        "prototype work: Q vertices {} edges {} ridge pieces {} candidates {} checked (distinct) {} degenerate supports (families) {} walks cut off {}",
        cnt.vertices, cnt.edges, cnt.pieces, cnt.candidates, cnt.checked, cnt.families, cnt.walk_failures
    );
    println!(
        "median time per arch: survey (solve + sweep) {:.1} us, solve alone {:.1} us, prototype (given eta_s) {:.1} us, of which candidates {:.1} us",
        ms(&mut t_survey),
        ms(&mut t_solve),
        ms(&mut t_dq),
        ms(&mut t_gen)
    );
    for r in reports.iter().take(12) {
        println!("{r}");
    }
}
