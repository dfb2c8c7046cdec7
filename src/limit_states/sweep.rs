//! Every limit state of a discrete arch at one friction coefficient, by a sweep in η.
//!
//! At fixed μ and η the admissible states form a convex polytope
//! P(η) = {x : φ_i(x, η) ≤ 0 for every contact i} in x = (h, v, w); it is empty below η_s,
//! a point at η_s, and grows with η (admissibility is monotone). Its vertices are the points
//! where three contacts are active. A limit state needs a mechanism on the active set, and
//! a mechanism needs at least four active contacts unless the pattern is degenerate
//! (formulation §4: B has rank 3, so an extreme mechanism has 4 rates, or 5 when L_e = 0;
//! three suffice only when their columns are dependent, e.g. three collinear hinges).
//! Four contacts meet at one point only at isolated η — exactly where the combinatorial
//! structure of P(η) changes, a plane passing through a vertex. So the sweep follows every
//! vertex of P(η) from η_s to the top, finds when the first other plane crosses it (the
//! roots of a polynomial, [`super::poly`]), and at each such event checks the kinematic LP
//! on the contacts active there; then it replaces the vertices through the event point by
//! the ones that exist just after it (read off the linearisation at the point). Between
//! events no vertex gains a fourth active contact, so no limit state is missed; at every
//! event the whole active set is checked. The vertex set near η_s comes from the same
//! linearisation at the least admissible state.
//!
//! Six box planes |x_k| ≤ [`BOX`] keep P bounded; an event on a box plane is not a limit
//! state. Where η_s is an infimum (the least admissible state unbounded: P(η) recedes to
//! infinity as η ↓ η_s), the sweep starts at the least η at which P(η) meets the box, from
//! the point where it does: below that every admissible state has some |x_k| > BOX.

use super::poly::Poly;
use crate::admissibility::{max_margin, Goal, WorkingSet};
use crate::arch::{Arch, JointLayout, ETA_TOP};
use crate::collapse_mode::{classify, CollapseMode};
use crate::contact::{Contact, ContactKind, Location};
use crate::kinematics::column;
use crate::load::{rows, LiveLoad, Side};
use crate::lp;
use crate::mechanism::{self, Mechanism};
use crate::settings::Settings;
use crate::state::State;
use crate::statics::{actions, magnitude, reaction_scale, Affine, Reactions};
use itertools::Itertools;

/// Half-width of the box on (h, v, w) that bounds the admissible set (units of γ t d r).
pub const BOX: f64 = 1e7;

/// At most this many events are processed (a safety net; never reached in tests).
const MAX_EVENTS: usize = 200_000;

/// One activation function at one joint, or a side of the box:
/// φ(x, η) = g(η)·x + c(η), g affine and c at most quadratic in η.
#[derive(Debug, Clone)]
struct Plane {
    contact: Option<Contact>,
    /// The side of the loaded section (load sweeps; `After` elsewhere).
    side: Side,
    g: [Poly; 3],
    c: Poly,
}

impl Plane {
    fn value(&self, x: &Reactions, eta: f64) -> f64 {
        self.g[0].eval(eta) * x[0]
            + self.g[1].eval(eta) * x[1]
            + self.g[2].eval(eta) * x[2]
            + self.c.eval(eta)
    }
    /// ∂φ/∂x (at η) and ∂φ/∂η (at x, η).
    fn slopes(&self, x: &Reactions, eta: f64) -> ([f64; 3], f64) {
        let g = [
            self.g[0].eval(eta),
            self.g[1].eval(eta),
            self.g[2].eval(eta),
        ];
        let d = self.g[0].derivative().eval(eta) * x[0]
            + self.g[1].derivative().eval(eta) * x[1]
            + self.g[2].derivative().eval(eta) * x[2]
            + self.c.derivative().eval(eta);
        (g, d)
    }
}

/// The planes of a discrete arch at friction μ, then the six box sides.
fn planes(arch: &Arch, joints: &[f64], mu: f64) -> Vec<Plane> {
    let mut out = Vec::new();
    for (j, &beta) in joints.iter().enumerate() {
        let at = Location::of_joint(j, joints.len());
        // coefficients from three thicknesses: exact for g (affine) and c (quadratic)
        let a: Vec<_> = [0.0, 1.0, 2.0]
            .iter()
            .map(|&eta| actions(arch, eta, beta))
            .collect();
        for &kind in ContactKind::active_at(mu) {
            let f: Vec<_> = (0..3)
                .map(|i| a[i].activation(kind, 0, i as f64, mu))
                .collect();
            let quad = |p0: f64, p1: f64, p2: f64| {
                let c2 = 0.5 * (p2 - 2.0 * p1 + p0);
                Poly::from_coeffs(&[p0, p1 - p0 - c2, c2]).trimmed(1e-15)
            };
            out.push(Plane {
                contact: Some(Contact {
                    beta,
                    kind,
                    at,
                    free: false,
                }),
                side: Side::After,
                g: [0, 1, 2].map(|k| quad(f[0].g[k], f[1].g[k], f[2].g[k])),
                c: quad(f[0].c, f[1].c, f[2].c),
            });
        }
    }
    out.extend(box_planes());
    out
}

/// The six sides |x_k| ≤ [`BOX`].
fn box_planes() -> Vec<Plane> {
    let mut out = Vec::new();
    for k in 0..3 {
        for s in [1.0, -1.0] {
            let mut g = [
                Poly::constant(0.0),
                Poly::constant(0.0),
                Poly::constant(0.0),
            ];
            g[k] = Poly::constant(s);
            out.push(Plane {
                contact: None,
                side: Side::After,
                g,
                c: Poly::constant(-BOX),
            });
        }
    }
    out
}

/// The planes of a discrete arch under a live load at fixed η, as functions of the
/// multiplier λ: constant gradients, constant terms affine in λ; a joint carrying the
/// point load has both sides of its section. Then the six box sides.
fn load_planes(arch: &Arch, joints: &[f64], eta: f64, mu: f64, load: &LiveLoad) -> Vec<Plane> {
    let mut out: Vec<Plane> = rows(arch, joints, eta, mu, load)
        .into_iter()
        .map(|r| Plane {
            contact: Some(r.contact),
            side: r.side,
            g: [0, 1, 2].map(|k| Poly::constant(r.a[k])),
            c: Poly::linear(r.c, r.a[3]),
        })
        .collect();
    out.extend(box_planes());
    out
}

fn det3(m: [[&Poly; 3]; 3]) -> Poly {
    let minor = |a: &Poly, b: &Poly, c: &Poly, d: &Poly| a.mul(d).sub(&b.mul(c));
    m[0][0]
        .mul(&minor(m[1][1], m[1][2], m[2][1], m[2][2]))
        .sub(&m[0][1].mul(&minor(m[1][0], m[1][2], m[2][0], m[2][2])))
        .add(&m[0][2].mul(&minor(m[1][0], m[1][1], m[2][0], m[2][1])))
}

/// A vertex of P(η): three planes and its path x(η) = num(η)/det(η) (Cramer's rule).
#[derive(Debug, Clone)]
struct Vertex {
    planes: [usize; 3],
    num: [Poly; 3],
    det: Poly,
}

impl Vertex {
    fn new(p: &[Plane], t: [usize; 3]) -> Vertex {
        let rows = t.map(|i| &p[i]);
        let neg_c: Vec<Poly> = rows.iter().map(|r| r.c.scale(-1.0)).collect();
        let det = det3([0, 1, 2].map(|i| [&rows[i].g[0], &rows[i].g[1], &rows[i].g[2]]));
        let num = [0, 1, 2].map(|k| {
            det3([0, 1, 2].map(|i| {
                let mut row = [&rows[i].g[0], &rows[i].g[1], &rows[i].g[2]];
                row[k] = &neg_c[i];
                row
            }))
        });
        Vertex {
            planes: t,
            num,
            det,
        }
    }
    fn at(&self, eta: f64) -> Reactions {
        let d = self.det.eval(eta);
        [0, 1, 2].map(|k| self.num[k].eval(eta) / d)
    }
    /// φ_l(x(η), η) · det(η), a polynomial.
    fn along(&self, l: &Plane) -> Poly {
        (0..3).fold(l.c.mul(&self.det), |acc, k| {
            acc.add(&l.g[k].mul(&self.num[k]))
        })
    }
}

/// What the sweep found.
#[derive(Debug, Clone)]
pub struct Sweep {
    /// Limit states above η_s (η_s itself excluded), ascending in η.
    pub states: Vec<SweptState>,
    /// Events processed.
    pub events: usize,
    /// Every point checked whose active contacts carry no mechanism (events, and the
    /// roots at which three contacts' columns become dependent), in the order checked:
    /// the evidence behind "no limit state there" that a certificate can carry.
    pub no_mechanism: Vec<CheckedPoint>,
    /// Why the sweep could not finish, if it could not.
    pub failure: Option<String>,
}

/// A point of the sweep whose active contacts were checked and carry no mechanism.
#[derive(Debug, Clone)]
pub struct CheckedPoint {
    /// Thickness ratio.
    pub eta: f64,
    /// Reactions.
    pub x: Reactions,
    /// Every contact active there, by increasing (β, side, kind).
    pub pattern: Vec<Contact>,
    /// The side of the loaded section of each contact (load sweeps; `After` elsewhere).
    pub sides: Vec<Side>,
}

/// A limit state found by the sweep.
#[derive(Debug, Clone)]
pub struct SweptState {
    /// Thickness ratio.
    pub eta: f64,
    /// Reactions.
    pub x: Reactions,
    /// Every contact active there, by increasing β.
    pub pattern: Vec<Contact>,
    /// The collapse mode named from the pattern.
    pub mode: CollapseMode,
    /// A mechanism on them.
    pub mechanism: Mechanism,
    /// The side of the loaded section of each contact (load sweeps; `After` elsewhere).
    pub sides: Vec<Side>,
    /// The live-load power of the mechanism (load sweeps; 0 elsewhere).
    pub live_power: f64,
}

impl SweptState {
    /// A limit state of the thickness problem (no live load) at the state (`arch`, η, x):
    /// its active contacts, the mode they are named, and a mechanism on them.
    pub(crate) fn unloaded(
        arch: &Arch,
        (eta, x): (f64, Reactions),
        pattern: Vec<Contact>,
        mechanism: Mechanism,
        settings: &Settings,
    ) -> SweptState {
        let mode = classify(
            &pattern,
            0.5 * (arch.beta_right() + arch.beta_left()),
            settings.same_joint,
        );
        SweptState {
            eta,
            x,
            sides: vec![Side::After; pattern.len()],
            pattern,
            mode,
            mechanism,
            live_power: 0.0,
        }
    }
}

/// What the sweep's parameter t is.
#[derive(Debug, Clone, Copy)]
enum Param<'a> {
    /// t = η: the thickness problem (self-weight only).
    Thickness,
    /// t = λ: the multiplier of a live load at fixed η.
    Multiplier { eta: f64, load: &'a LiveLoad },
}

struct Sweeper<'a> {
    arch: &'a Arch,
    mu: f64,
    param: Param<'a>,
    /// The end of the sweep: η's thickness limit, or λ_static.
    top: f64,
    planes: Vec<Plane>,
    settings: &'a Settings,
    alive: Vec<(Vertex, Option<(f64, usize)>)>,
    states: Vec<SweptState>,
    no_mechanism: Vec<CheckedPoint>,
    /// The first kinematic LP that the back end could not decide: the sweep then decides
    /// nothing (an undecided point is neither a limit state nor "no mechanism").
    lp_failure: Option<String>,
}

impl Sweeper<'_> {
    fn tol(&self, x: &Reactions) -> f64 {
        self.settings.event_tol * reaction_scale(x)
    }

    /// Two planes that are one and the same function of (x, t) (at the point load's joint
    /// the extrados hinge rows of both sides coincide: the load passes through the hinge
    /// point). Their contacts differ (in the kinematics), their plane does not.
    fn twins(&self, i: usize, j: usize) -> bool {
        let (p, q) = (&self.planes[i], &self.planes[j]);
        let same = |a: &Poly, b: &Poly| {
            let (a, b) = (a.coeffs(), b.coeffs());
            (0..a.len().max(b.len())).all(|k| {
                let (x, y) = (
                    a.get(k).copied().unwrap_or(0.0),
                    b.get(k).copied().unwrap_or(0.0),
                );
                (x - y).abs() <= 1e-13 * (1.0 + x.abs().max(y.abs()))
            })
        };
        i != j
            && p.contact.is_some()
            && q.contact.is_some()
            && same(&p.c, &q.c)
            && (0..3).all(|k| same(&p.g[k], &q.g[k]))
    }

    /// Planes active at (x, η): |φ| within `event_tol` of the plane's own magnitude
    /// ([`magnitude`]: shallow arches have φ of order η).
    fn active(&self, x: &Reactions, eta: f64) -> Vec<usize> {
        let thickness = match self.param {
            Param::Thickness => eta,
            Param::Multiplier { eta, .. } => eta,
        };
        (0..self.planes.len())
            .filter(|&i| {
                let p = &self.planes[i];
                let size = match p.contact {
                    Some(c) => {
                        magnitude(c.kind, thickness, self.mu, x, self.settings.magnitude_floor)
                    }
                    None => BOX,
                };
                p.value(x, eta).abs() <= self.settings.event_tol * size
            })
            .collect()
    }

    /// The first η in (η0, top] at which another plane crosses the vertex (it stops being
    /// feasible), or `None` when it survives to the top.
    fn death(&self, v: &Vertex, eta0: f64) -> Option<(f64, usize)> {
        let lo = eta0 + 1e-12 * (1.0 + eta0);
        let top = self.top;
        if lo >= top {
            return None;
        }
        // the vertex exists until its determinant vanishes
        let dscale = v.det.norm().max(f64::MIN_POSITIVE);
        let hi = v
            .det
            .roots_in(lo, top, 1e-14, dscale)
            .and_then(|r| r.first().copied())
            .unwrap_or(top);
        let mut first: Option<(f64, usize)> = None;
        for (l, plane) in self.planes.iter().enumerate() {
            if v.planes.contains(&l) {
                continue;
            }
            let p = v.along(plane);
            // φ_l = p / det stays negative on [lo, bound] when the Bernstein coefficients of
            // p there all have the sign opposite to det's (det keeps its sign before `hi`)
            let bound = first.map_or(hi, |f| f.0);
            let (bmin, bmax) = p.bernstein_bounds(lo, bound);
            let det_sign = v.det.eval(0.5 * (lo + bound)).signum();
            if (det_sign > 0.0 && bmax < 0.0) || (det_sign < 0.0 && bmin > 0.0) {
                continue;
            }
            let scale = p.norm().max(f64::MIN_POSITIVE);
            let Some(roots) = p.roots_in(lo, hi, 1e-13, scale) else {
                continue; // through the vertex for every η: degenerate, never first
            };
            let bound = first.map_or(hi, |f| f.0);
            for r in roots {
                if r >= bound {
                    break;
                }
                // a crossing when the plane is violated just after the root
                let after = (r + 1e-9 * (1.0 + r)).min(hi);
                if plane.value(&v.at(after), after) > 0.0 {
                    first = Some((r, l));
                    break;
                }
            }
        }
        first
    }

    /// Vertices that exist just after η at the point x where the planes `act` are active:
    /// the triples of `act` whose path stays inside the others' half-spaces (first order).
    fn vertices_after(&self, x: &Reactions, eta: f64, act: &[usize]) -> Vec<Vertex> {
        let slopes: Vec<([f64; 3], f64)> =
            act.iter().map(|&i| self.planes[i].slopes(x, eta)).collect();
        let mut out = Vec::new();
        for t in (0..act.len()).combinations(3) {
            let m = nalgebra::Matrix3::from_fn(|r, c| slopes[t[r]].0[c]);
            let scale = m.norm();
            let Some(inv) = m.try_inverse() else { continue };
            // dependent planes (E and I of one joint at η = 0) have a determinant at the
            // rounding level of its terms (~1e-16 scale³); ill-conditioned ones are vertices
            // all the same: where η_s is an infimum, the vertex of the three contacts whose
            // gradients become dependent at η_s enters the box with det ~ 1e-12 scale³
            if m.determinant().abs() <= 1e-14 * scale * scale * scale {
                continue;
            }
            // d/dη of φ_t = 0 along the path: G dx + ∂φ/∂η = 0
            let rhs = nalgebra::Vector3::from_fn(|r, _| -slopes[t[r]].1);
            let dx = inv * rhs;
            // strictly inside the other planes just after η (a tie is not a vertex: the
            // neighbouring triple of the tie carries the path); a plane identical to one
            // of the triple (a twin) is not another plane
            let ok = (0..act.len())
                .filter(|i| !t.contains(i))
                .filter(|&i| !t.iter().any(|&k| self.twins(act[i], act[k])))
                .all(|i| {
                    let (g, d) = slopes[i];
                    let rate = g[0] * dx[0] + g[1] * dx[1] + g[2] * dx[2] + d;
                    let size = g[0].abs() * dx[0].abs()
                        + g[1].abs() * dx[1].abs()
                        + g[2].abs() * dx[2].abs()
                        + d.abs();
                    rate < -1e-12 * size
                });
            if ok {
                out.push(Vertex::new(&self.planes, [act[t[0]], act[t[1]], act[t[2]]]));
            }
        }
        out
    }

    /// The vertices of P(η) by a walk on its vertex graph from `start` (a point of P(η)):
    /// shoot a ray to a facet, slide within it to an edge, along the edge to a vertex; then
    /// from each vertex along each of its three edges to the next plane (a ratio test over
    /// every plane). The vertex graph of a bounded polytope is connected, so the walk visits
    /// every vertex. Used where the least state is degenerate (its active planes' normals
    /// dependent, so that P(η_s) is not a point) and the first-order start does not apply.
    fn vertices_by_walk(&self, eta: f64, start: Reactions) -> Vec<[usize; 3]> {
        let g: Vec<[f64; 3]> = self
            .planes
            .iter()
            .map(|p| [p.g[0].eval(eta), p.g[1].eval(eta), p.g[2].eval(eta)])
            .collect();
        let phi = |x: &Reactions, i: usize| self.planes[i].value(x, eta);
        let dot = |a: &[f64; 3], b: &[f64; 3]| a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
        let cross = |a: &[f64; 3], b: &[f64; 3]| {
            [
                a[1] * b[2] - a[2] * b[1],
                a[2] * b[0] - a[0] * b[2],
                a[0] * b[1] - a[1] * b[0],
            ]
        };
        // the first plane hit from x along d, skipping `skip`
        let shoot = |x: &Reactions, d: &[f64; 3], skip: &[usize]| -> Option<(usize, f64)> {
            let mut best: Option<(usize, f64)> = None;
            for (i, gi) in g.iter().enumerate() {
                if skip.contains(&i) {
                    continue;
                }
                let rate = dot(gi, d);
                if rate <= 1e-14 * (1.0 + d.iter().map(|v| v.abs()).sum::<f64>()) {
                    continue;
                }
                let t = (-phi(x, i)).max(0.0) / rate;
                if best.is_none_or(|(_, bt)| t < bt) {
                    best = Some((i, t));
                }
            }
            best
        };
        let step = |x: &Reactions, d: &[f64; 3], t: f64| {
            [x[0] + t * d[0], x[1] + t * d[1], x[2] + t * d[2]]
        };
        let d1 = [0.6, 0.3, 0.7416];
        let Some((p1, t1)) = shoot(&start, &d1, &[]) else {
            return vec![];
        };
        let x1 = step(&start, &d1, t1);
        let n1 = dot(&g[p1], &g[p1]);
        let u = [0.31, -0.77, 0.55];
        let k = dot(&u, &g[p1]) / n1;
        let d2 = [
            u[0] - k * g[p1][0],
            u[1] - k * g[p1][1],
            u[2] - k * g[p1][2],
        ];
        let Some((p2, t2)) = shoot(&x1, &d2, &[p1]) else {
            return vec![];
        };
        let x2 = step(&x1, &d2, t2);
        let d3 = cross(&g[p1], &g[p2]);
        let Some((p3, _)) =
            shoot(&x2, &d3, &[p1, p2]).or_else(|| shoot(&x2, &[-d3[0], -d3[1], -d3[2]], &[p1, p2]))
        else {
            return vec![];
        };
        let mut seen: Vec<[usize; 3]> = Vec::new();
        let mut queue = vec![[p1, p2, p3]];
        while let Some(mut t) = queue.pop() {
            t.sort_unstable();
            if seen.contains(&t) || seen.len() > 20 * self.planes.len() {
                continue;
            }
            seen.push(t);
            let v = Vertex::new(&self.planes, t);
            let x = v.at(eta);
            let tol = 1e-9 * reaction_scale(&x);
            if !x.iter().all(|c| c.is_finite())
                || (0..self.planes.len()).any(|i| !t.contains(&i) && phi(&x, i) > tol)
            {
                continue; // not a vertex of P(η): do not walk on from it
            }
            for drop in 0..3 {
                let (p, q, k) = (t[(drop + 1) % 3], t[(drop + 2) % 3], t[drop]);
                let mut d = cross(&g[p], &g[q]);
                if dot(&g[k], &d) > 0.0 {
                    d = [-d[0], -d[1], -d[2]];
                }
                if let Some((r, _)) = shoot(&x, &d, &[p, q, k]) {
                    queue.push([p, q, r]);
                }
            }
        }
        seen
    }

    /// Whether P(η) meets the box, and its point of greatest margin there: the margin LP
    /// over every plane (box sides included) in units of the box, x = BOX·u, so that the
    /// rows keep unit gradients and the dense solver's own bounds never bind.
    fn in_box(&self, eta: f64) -> Option<(bool, Reactions)> {
        let rows: Vec<Affine> = self
            .planes
            .iter()
            .map(|p| Affine {
                g: [0, 1, 2].map(|k| p.g[k].eval(eta) * BOX),
                c: p.c.eval(eta),
            })
            .collect();
        let (u, s) = lp::max_margin(&rows, 1.0, self.settings).ok()?;
        Some((s >= 0.0, u.map(|v| v * BOX)))
    }

    /// The least η above `eta_lo` (where P(η) lies outside the box) at which P(η) meets the
    /// box, and a point of P(η) ∩ box there, to the resolution of η (bisection on
    /// [`Self::in_box`] to 1e-15 relative): the sweep's start when the least admissible
    /// state is unbounded. `Ok(None)` when P(η) misses the box up to the thickness limit.
    fn least_in_box(&self, eta_lo: f64) -> Result<Option<(f64, Reactions)>, String> {
        let failed = || format!("the margin LP inside the box failed above eta_s = {eta_lo}");
        let (ok, mut x) = self.in_box(ETA_TOP).ok_or_else(failed)?;
        if !ok {
            return Ok(None);
        }
        let (mut lo, mut hi) = (eta_lo, ETA_TOP);
        while hi - lo > 1e-15 * hi {
            let m = 0.5 * (lo + hi);
            if m <= lo || m >= hi {
                break;
            }
            let (ok, xm) = self.in_box(m).ok_or_else(failed)?;
            if ok {
                (hi, x) = (m, xm);
            } else {
                lo = m;
            }
        }
        Ok(Some((hi, x)))
    }

    /// Checks the contacts active at (x, t) for a mechanism; records a limit state.
    fn check(&mut self, x: Reactions, t: f64, act: &[usize]) {
        let mut pattern: Vec<(Contact, Side)> = act
            .iter()
            .filter_map(|&i| self.planes[i].contact.map(|c| (c, self.planes[i].side)))
            .collect();
        if pattern.len() < 3 || act.len() > pattern.len() {
            return; // too few contacts, or on the box (not a bounded state)
        }
        pattern.sort_by(|a, b| {
            a.0.beta
                .total_cmp(&b.0.beta)
                .then((a.1 == Side::After).cmp(&(b.1 == Side::After)))
                .then(a.0.kind.cmp(&b.0.kind))
        });
        let contacts: Vec<Contact> = pattern.iter().map(|p| p.0).collect();
        let sides: Vec<Side> = pattern.iter().map(|p| p.1).collect();
        let found = match self.param {
            Param::Thickness => {
                let st = State {
                    arch: self.arch,
                    eta: t,
                    mu: self.mu,
                    x,
                };
                match mechanism::find(&st, &contacts, self.settings) {
                    Ok(m) => m.map(|m| (m, 0.0)),
                    Err(e) => {
                        self.lp_failure.get_or_insert(format!(
                            "the kinematic LP at eta = {t} was not decided by the LP back end: {e:?}"
                        ));
                        return;
                    }
                }
            }
            Param::Multiplier { eta, load } => {
                let st = State {
                    arch: self.arch,
                    eta,
                    mu: self.mu,
                    x,
                };
                match mechanism::find_under_load(&st, t, load, &pattern, self.settings) {
                    Ok(m) => m,
                    Err(e) => {
                        self.lp_failure.get_or_insert(format!(
                            "the kinematic LP at lambda = {t} was not decided by the LP back end: {e:?}"
                        ));
                        return;
                    }
                }
            }
        };
        if let Some((mech, live_power)) = found {
            let mode = classify(
                &contacts,
                0.5 * (self.arch.beta_right() + self.arch.beta_left()),
                self.settings.same_joint,
            );
            self.states.push(SweptState {
                eta: t,
                x,
                pattern: contacts,
                mode,
                mechanism: mech,
                sides,
                live_power,
            });
        } else {
            self.no_mechanism.push(CheckedPoint {
                eta: t,
                x,
                pattern: contacts,
                sides,
            });
        }
    }

    /// Starts from every vertex of P(t), found by a walk on its vertex graph from `centre`
    /// (a point inside P(t)).
    fn start_by_walk(&mut self, t: f64, centre: Reactions) {
        for tri in self.vertices_by_walk(t, centre) {
            let v = Vertex::new(&self.planes, tri);
            let x = v.at(t);
            let feasible = self
                .planes
                .iter()
                .enumerate()
                .all(|(i, p)| tri.contains(&i) || p.value(&x, t) <= 1e-9 * reaction_scale(&x));
            if !feasible {
                continue;
            }
            // a degenerate vertex (more planes through it than its three): only the
            // triples whose path stays inside the others just after t continue — e.g. at
            // λ = 0 the two sides of a loaded section are one plane, and the vertex on the
            // side that is violated for λ > 0 ends at once
            let mut act = self.active(&x, t);
            for p in tri {
                if !act.contains(&p) {
                    act.push(p);
                }
            }
            act.sort_unstable();
            if act.len() == 3 {
                self.push(v, t);
            } else {
                for w in self.vertices_after(&x, t, &act) {
                    self.push(w, t);
                }
            }
        }
    }

    /// Adds a vertex born at η unless it is already there, or it would end at once (within
    /// the resolution of η: a tie the first-order test could not break).
    fn push(&mut self, v: Vertex, eta: f64) {
        let mut key = v.planes;
        key.sort_unstable();
        if self.alive.iter().any(|(w, _)| {
            let mut k = w.planes;
            k.sort_unstable();
            k == key
        }) {
            return;
        }
        let d = self.death(&v, eta);
        if d.is_some_and(|(e, _)| e <= eta + 1e-9 * (1.0 + eta)) {
            return;
        }
        self.three_contact_mechanisms(&v, eta, d.map_or(self.top, |d| d.0));
        self.alive.push((v, d));
    }

    /// Three active contacts carry a mechanism only where their compatibility columns are
    /// dependent (e.g. a slide parallel to the line through two hinges): the roots of the
    /// cubic det[c₁(η) c₂(η) c₃(η)] during the vertex's life, each checked.
    fn three_contact_mechanisms(&mut self, v: &Vertex, from: f64, to: f64) {
        if let Param::Multiplier { eta, load } = self.param {
            self.three_contact_under_load(v, from, to, eta, load);
            return;
        }
        let Some(cs) = v
            .planes
            .iter()
            .map(|&i| self.planes[i].contact)
            .collect::<Option<Vec<Contact>>>()
        else {
            return;
        };
        let col = |c: &Contact| {
            let (c0, c1) = (column(c.kind, c.beta, 0.0), column(c.kind, c.beta, 1.0));
            [0, 1, 2].map(|k| Poly::linear(c0[k], c1[k] - c0[k]))
        };
        let cols: Vec<[Poly; 3]> = cs.iter().map(col).collect();
        let det = det3([0, 1, 2].map(|r| [&cols[0][r], &cols[1][r], &cols[2][r]]));
        let scale = det.norm().max(f64::MIN_POSITIVE);
        let roots = match det.roots_in(from, to, 1e-13, scale) {
            Some(r) => r,
            // dependent for every η (e.g. two slides at one joint): the sweep's events and
            // the least state cover such sets
            None => return,
        };
        for r in roots {
            if r <= from * (1.0 + 1e-12) {
                continue;
            }
            let x = v.at(r);
            let act = self.active(&x, r);
            self.check(x, r, &act);
        }
    }
}

impl Sweeper<'_> {
    /// Under a live load at fixed η the columns do not depend on λ: three contacts with
    /// dependent columns stay dependent along the whole vertex path, and their one rate
    /// vector r (B r = 0) has total power L_dead·r + λ L_live·r, linear in λ. It is a
    /// limit state from the least λ of the path at which that power is ≥ 0, if L_live·r > 0
    /// (checked there by the kinematic LP like any event).
    fn three_contact_under_load(
        &mut self,
        v: &Vertex,
        from: f64,
        to: f64,
        eta: f64,
        load: &LiveLoad,
    ) {
        let Some(cs) = v
            .planes
            .iter()
            .map(|&i| self.planes[i].contact.map(|c| (c, self.planes[i].side)))
            .collect::<Option<Vec<(Contact, Side)>>>()
        else {
            return;
        };
        let cols: Vec<[f64; 3]> = cs
            .iter()
            .map(|(c, _)| column(c.kind, c.beta, eta))
            .collect();
        let m = nalgebra::Matrix3::from_fn(|r, c| cols[c][r]);
        let scale = m.norm();
        if m.determinant().abs() > 1e-12 * scale * scale * scale {
            return;
        }
        // the rate vector: a null vector of the column matrix (cross product of two rows)
        let rows = [m.row(0), m.row(1), m.row(2)];
        let mut r = nalgebra::Vector3::zeros();
        for (a, b) in [(0, 1), (0, 2), (1, 2)] {
            let c = rows[a].transpose().cross(&rows[b].transpose());
            if c.norm() > r.norm() {
                r = c;
            }
        }
        if r.norm() == 0.0 {
            return;
        }
        let plain: Vec<Contact> = cs.iter().map(|p| p.0).collect();
        let dead = crate::kinematics::power(self.arch, eta, &plain);
        let live = load.power(self.arch, eta, &cs);
        let (d, l): (f64, f64) = (0..3).fold((0.0, 0.0), |(d, l), k| {
            (d + dead[k] * r[k], l + live[k] * r[k])
        });
        let sign = if r.iter().all(|v| *v >= 0.0) {
            1.0
        } else if r.iter().all(|v| *v <= 0.0) {
            -1.0
        } else {
            return;
        };
        let (d, l) = (sign * d, sign * l);
        if l <= 0.0 {
            return;
        }
        let t = from.max(-d / l);
        if t >= to {
            return;
        }
        let t = if t > from {
            t * (1.0 + 1e-12) + 1e-15
        } else {
            t
        };
        let x = v.at(t);
        let act = self.active(&x, t);
        self.check(x, t, &act);
    }
}

/// Follows P(η) from the least admissible state (η_s, x_s) to the top and returns every
/// limit state met on the way (η > η_s; the caller checks η_s itself). `joints` are the
/// joint angles of a discrete arch.
pub fn sweep(arch: &Arch, mu: f64, eta_s: f64, x_s: Reactions, settings: &Settings) -> Sweep {
    let JointLayout::Discrete(joints) = arch.layout() else {
        return Sweep {
            states: vec![],
            events: 0,
            no_mechanism: vec![],
            failure: Some("the sweep needs the joints of a discrete arch".into()),
        };
    };
    if let Some(f) = too_many(joints.len(), settings) {
        return Sweep {
            states: vec![],
            events: 0,
            no_mechanism: vec![],
            failure: Some(f),
        };
    }
    let mut sw = Sweeper {
        arch,
        mu,
        param: Param::Thickness,
        top: ETA_TOP,
        planes: planes(arch, joints, mu),
        settings,
        alive: Vec::new(),
        states: Vec::new(),
        no_mechanism: Vec::new(),
        lp_failure: None,
    };
    // the start: the least admissible state, or, where that state is unbounded (η_s an
    // infimum, approached only as the reactions grow without bound), the least point of
    // P(η) inside the box — below it P(η) lies wholly outside the box, where no state is
    // a limit state, and from it on every vertex of P(η) ∩ box is followed
    // (a bounded least state on or outside the box — possible only with
    // `unbounded_reactions` raised beyond 1e7 / (1 + span) — starts the same way)
    let bounded_start = x_s.iter().all(|v| {
        v.abs() <= settings.unbounded_reactions * (1.0 + arch.span())
            && v.abs() < BOX * (1.0 - 1e-9)
    });
    let (eta_s, x_s) = if bounded_start {
        (eta_s, x_s)
    } else {
        match sw.least_in_box(eta_s) {
            Ok(Some(start)) => start,
            Ok(None) => {
                // no state inside the box below the thickness limit: no limit state
                return Sweep {
                    states: vec![],
                    events: 0,
                    no_mechanism: vec![],
                    failure: None,
                };
            }
            Err(f) => {
                return Sweep {
                    states: vec![],
                    events: 0,
                    no_mechanism: vec![],
                    failure: Some(f),
                }
            }
        }
    };
    let act = sw.active(&x_s, eta_s);
    for v in sw.vertices_after(&x_s, eta_s, &act) {
        sw.push(v, eta_s);
    }
    if sw.alive.is_empty() {
        // a degenerate least state: walk the vertex graph just above η_s instead (limit
        // states in (η_s, η₀] would be missed)
        let eta0 = if eta_s > 0.0 {
            eta_s * (1.0 + 1e-6)
        } else {
            settings.sweep_min_eta
        };
        // start from the state of largest margin at η₀ (inside P(η₀))
        let centre = if bounded_start {
            let mut ws = WorkingSet::initial(arch);
            max_margin(
                arch,
                eta0,
                mu,
                ContactKind::active_at(mu),
                &mut ws,
                Goal::Optimise,
                settings,
            )
            .map_or(x_s, |m| m.x)
        } else {
            sw.in_box(eta0).map_or(x_s, |(_, x)| x)
        };
        sw.start_by_walk(eta0, centre);
    }
    if sw.alive.is_empty() {
        return Sweep {
            states: vec![],
            events: 0,
            no_mechanism: vec![],
            failure: Some(format!(
                "no vertex of the admissible set found just above eta_s = {eta_s} ({} contacts active there)",
                act.len()
            )),
        };
    }
    run(sw)
}

/// Why the sweep is not run on `joints` joints, if it is not: its work grows faster than
/// the square of the number of joints (every vertex born is tested against every plane),
/// so beyond `settings.sweep_max_joints` it is not attempted.
fn too_many(joints: usize, settings: &Settings) -> Option<String> {
    (joints > settings.sweep_max_joints).then(|| {
        format!(
            "the complete search over {joints} joints is beyond this version's budget (settings.sweep_max_joints = {}): the limit states were not searched",
            settings.sweep_max_joints
        )
    })
}

/// The event loop: from the vertices alive at the start to the top.
fn run(sw: Sweeper) -> Sweep {
    run_to_top(sw).0
}

/// [`run`], and, for a load sweep, the points of P(top) it reached (see
/// [`sweep_load_with_top`]): every event within `settings.same_root` × (1 + top) of the top
/// — neither counted nor checked there, the caller decides at the top — and every vertex
/// alive at the end, evaluated at the top. Empty for the thickness sweep.
fn run_to_top(mut sw: Sweeper) -> (Sweep, Vec<Reactions>) {
    let mut events = 0;
    let mut at_top = Vec::new();
    let top_band = match sw.param {
        // the resolution of the sweep's roots (see `death`): relative, and absolute near 0
        Param::Multiplier { .. } => sw.top - sw.settings.same_root * (1.0 + sw.top.abs()),
        Param::Thickness => f64::INFINITY,
    };
    loop {
        let next = sw
            .alive
            .iter()
            .enumerate()
            .filter_map(|(i, (_, d))| d.map(|d| (i, d)))
            .min_by(|a, b| a.1 .0.total_cmp(&b.1 .0));
        let Some((i, (eta_e, killer))) = next else {
            break;
        };
        let at_the_top = eta_e >= top_band;
        if !at_the_top {
            events += 1;
        }
        if events > MAX_EVENTS {
            let sweep = Sweep {
                states: sw.states,
                events,
                no_mechanism: sw.no_mechanism,
                failure: Some(format!("more than {MAX_EVENTS} events")),
            };
            return (sweep, at_top);
        }
        let x_e = sw.alive[i].0.at(eta_e);

        let mut act = sw.active(&x_e, eta_e);
        for p in sw.alive[i].0.planes.into_iter().chain([killer]) {
            if !act.contains(&p) {
                act.push(p);
            }
        }
        act.sort_unstable();
        if at_the_top {
            at_top.push(x_e);
        } else {
            sw.check(x_e, eta_e, &act);
        }
        // the vertices through the event point end here
        let tol = sw.tol(&x_e);
        sw.alive.swap_remove(i);
        sw.alive.retain(|(v, _)| {
            let through = v.planes.iter().all(|p| act.contains(p));
            let at = v.at(eta_e);
            !(through
                && (0..3).all(|k| (at[k] - x_e[k]).abs() <= tol.max(1e-9 * (1.0 + x_e[k].abs()))))
        });
        for v in sw.vertices_after(&x_e, eta_e, &act) {
            sw.push(v, eta_e);
        }
    }
    if top_band.is_finite() {
        at_top.extend(sw.alive.iter().map(|(v, _)| v.at(sw.top)));
    }
    sw.states.sort_by(|a, b| a.eta.total_cmp(&b.eta));
    sw.states.dedup_by(|a, b| {
        (a.eta - b.eta).abs() <= 1e-12 * (1.0 + b.eta)
            && a.pattern.len() == b.pattern.len()
            && a.pattern
                .iter()
                .zip(&b.pattern)
                .all(|(p, q)| p.kind == q.kind && p.beta == q.beta)
    });
    let sweep = Sweep {
        states: sw.states,
        events,
        no_mechanism: sw.no_mechanism,
        failure: sw.lp_failure,
    };
    (sweep, at_top)
}

/// Follows P(λ) = {x : φ_i(x, λ) ≤ 0} of a discrete arch under a live load at fixed η,
/// from the least admissible multiplier λ_min (a state `x_min` there) to λ_static, and
/// returns every limit state met on the way whose mechanism has positive live power (the
/// caller checks λ_static itself). The same argument as in η applies: a limit state needs
/// four active contacts at one point (or three with dependent columns, which stay
/// dependent along a vertex path: checked where its total power turns ≥ 0), which happens
/// only where P(λ) changes
/// combinatorially, at the events the sweep visits. Where P(λ_min) has an interior (the
/// arch stands unloaded, λ_min = 0) the sweep starts from all its vertices, found by a
/// walk on its vertex graph.
#[allow(clippy::too_many_arguments)]
pub fn sweep_load(
    arch: &Arch,
    eta: f64,
    mu: f64,
    load: &LiveLoad,
    min: (f64, Reactions),
    lambda_static: f64,
    settings: &Settings,
) -> Sweep {
    sweep_load_with_top(arch, eta, mu, load, min, lambda_static, settings).0
}

/// [`sweep_load`], and the points of P(λ_static) the sweep reached: every vertex alive at
/// the top, evaluated there, and every event within `settings.same_root` × (1 + λ_static)
/// of the top (the resolution of its roots), which the sweep neither counts nor checks (the caller decides at λ_static). As λ
/// rises to λ_static the vertices of P(λ) run into the vertices of the optimal face
/// P(λ_static), so these points are those vertices (each possibly several times, and
/// points on the box included), whichever state the LP returned there. Empty after a
/// failure before the event loop.
#[allow(clippy::too_many_arguments)]
pub fn sweep_load_with_top(
    arch: &Arch,
    eta: f64,
    mu: f64,
    load: &LiveLoad,
    (lambda_min, x_min): (f64, Reactions),
    lambda_static: f64,
    settings: &Settings,
) -> (Sweep, Vec<Reactions>) {
    let failure = |f: String| {
        let sweep = Sweep {
            states: vec![],
            events: 0,
            no_mechanism: vec![],
            failure: Some(f),
        };
        (sweep, Vec::new())
    };
    let JointLayout::Discrete(joints) = arch.layout() else {
        return failure("the sweep needs the joints of a discrete arch".into());
    };
    if let Some(f) = too_many(joints.len(), settings) {
        return failure(f);
    }
    if x_min.iter().any(|v| v.abs() >= BOX * (1.0 - 1e-9)) {
        return failure(format!(
            "the least admissible state at lambda = {lambda_min} lies outside the box |x| <= {BOX:e}"
        ));
    }
    let mut sw = Sweeper {
        arch,
        mu,
        param: Param::Multiplier { eta, load },
        top: lambda_static,
        planes: load_planes(arch, joints, eta, mu, load),
        settings,
        alive: Vec::new(),
        states: Vec::new(),
        no_mechanism: Vec::new(),
        lp_failure: None,
    };
    // λ_min > 0: P(λ_min) is (generically) the point x_min, and the vertices just after
    // it come from the linearisation there; λ_min = 0: P(0) is the admissible set of the
    // unloaded arch, in general with an interior, and every one of its vertices starts
    if lambda_min > 0.0 {
        let act = sw.active(&x_min, lambda_min);
        for v in sw.vertices_after(&x_min, lambda_min, &act) {
            sw.push(v, lambda_min);
        }
    }
    if sw.alive.is_empty() {
        // an interior (or a degenerate least state): every vertex, by a walk from the
        // most interior point
        let t0 = if lambda_min == 0.0 {
            0.0
        } else {
            lambda_min + 1e-6 * (lambda_static - lambda_min).min(1.0 + lambda_min)
        };
        let rows: Vec<Affine> = sw
            .planes
            .iter()
            .map(|p| Affine {
                g: [0, 1, 2].map(|k| p.g[k].eval(t0)),
                c: p.c.eval(t0),
            })
            .collect();
        let centre = lp::max_margin(&rows, 1.0, settings).map_or(x_min, |m| m.0);
        sw.start_by_walk(t0, centre);
    }
    if sw.alive.is_empty() {
        return failure(format!(
            "no vertex of the admissible set found at lambda = {lambda_min}"
        ));
    }
    run_to_top(sw)
}
