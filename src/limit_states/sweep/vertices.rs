//! The life of a vertex of P(t): the vertices born at a point (the triples of its active
//! planes whose path stays inside the others just after it, read off the linearisation
//! there), and the first plane to cross a vertex's path after its birth (its death: the
//! next event it takes part in).

use super::geometry::Vertex;
use super::sweeper::Sweeper;
use crate::limit_states::poly::Poly;
use crate::statics::Reactions;
use itertools::Itertools;

/// "Just after" t in the sweep is t + `JUST_AFTER_REL` (1 + |t|): a root of a plane along
/// a vertex's path is a crossing when the plane is violated there, and a vertex that would
/// die no later than that after its birth is a tie the first-order test could not break
/// (it is not followed: the neighbouring triple of the tie carries the path).
const JUST_AFTER_REL: f64 = 1e-9;

/// A vertex's determinant vanishes identically (planes dependent for every t) when its
/// coefficients are all below this fraction of their largest.
const DET_ZERO_REL: f64 = 1e-14;

/// A plane passes through a vertex for every t (degenerate, never its first crossing) when
/// the coefficients of φ·det along the path are all below this fraction of their largest.
const THROUGH_ZERO_REL: f64 = 1e-13;

/// Three planes are dependent at a point when the determinant of their gradients is below
/// this times the cube of the matrix's norm (the rounding level of its terms is ~1e-16;
/// ill-conditioned triples, with det ~1e-12, are vertices all the same).
const DEPENDENT_PLANES_REL: f64 = 1e-14;

/// A plane's rate along a vertex's first-order path is strictly negative (the path stays
/// inside it) when below −this times the sum of the rate's terms' sizes.
const STRICTLY_INSIDE_REL: f64 = 1e-12;

/// Two planes are twins when every coefficient agrees to this, relative to 1 + its size.
const TWIN_REL: f64 = 1e-13;

impl Sweeper<'_> {
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
                (x - y).abs() <= TWIN_REL * (1.0 + x.abs().max(y.abs()))
            })
        };
        i != j
            && p.contact.is_some()
            && q.contact.is_some()
            && same(&p.c, &q.c)
            && (0..3).all(|k| same(&p.g[k], &q.g[k]))
    }

    /// The first η in (η0, top] at which another plane crosses the vertex (it stops being
    /// feasible), or `None` when it survives to the top.
    pub(super) fn death(&self, v: &Vertex, eta0: f64) -> Option<(f64, usize)> {
        let lo = eta0 + self.settings.same_root * (1.0 + eta0);
        let top = self.top;
        if lo >= top {
            return None;
        }
        // the vertex exists until its determinant vanishes
        let dscale = v.det.norm().max(f64::MIN_POSITIVE);
        let hi = v
            .det
            .roots_in(lo, top, DET_ZERO_REL, dscale)
            .and_then(|r| r.first().copied())
            .unwrap_or(top);
        let mut first: Option<(f64, usize)> = None;
        // the screen clears most planes at once; what it cannot clear is tested as before
        let build = |bound: f64| {
            self.screen_slots
                .and_then(|(c_len, g_len)| v.screen(c_len, g_len, lo, bound))
        };
        let mut screen = build(hi);
        for (l, plane) in self.planes.iter().enumerate() {
            if v.planes.contains(&l)
                || (screen.as_ref()).is_some_and(|s| s.inside(&self.screen_coeffs, l))
            {
                continue;
            }
            let before = first;
            let p = v.along(plane);
            // φ_l = p / det stays negative on [lo, bound] when the Bernstein coefficients of
            // p there all have the sign opposite to det's (det keeps its sign before `hi`)
            let bound = first.map_or(hi, |f| f.0);
            let det_sign = v.det.eval(0.5 * (lo + bound)).signum();
            if p.bernstein_sign(lo, bound, -det_sign) {
                continue;
            }
            let scale = p.norm().max(f64::MIN_POSITIVE);
            let Some(roots) = p.roots_in(lo, hi, THROUGH_ZERO_REL, scale) else {
                continue; // through the vertex for every η: degenerate, never first
            };
            let bound = first.map_or(hi, |f| f.0);
            for r in roots {
                if r >= bound {
                    break;
                }
                // a crossing when the plane is violated just after the root
                let after = (r + JUST_AFTER_REL * (1.0 + r)).min(hi);
                if plane.value(&v.at(after), after) > 0.0 {
                    first = Some((r, l));
                    break;
                }
            }
            if first != before {
                screen = build(first.map_or(hi, |f| f.0));
            }
        }
        first
    }

    /// Vertices that exist just after η at the point x where the planes `act` are active:
    /// the triples of `act` whose path stays inside the others' half-spaces (first order).
    pub(super) fn vertices_after(&self, x: &Reactions, eta: f64, act: &[usize]) -> Vec<Vertex> {
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
            if m.determinant().abs() <= DEPENDENT_PLANES_REL * scale * scale * scale {
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
                    rate < -STRICTLY_INSIDE_REL * size
                });
            if ok {
                out.push(Vertex::new(&self.planes, [act[t[0]], act[t[1]], act[t[2]]]));
            }
        }
        out
    }

    /// Adds a vertex born at η unless it is already there, or it would end at once (within
    /// the resolution of η: a tie the first-order test could not break).
    pub(super) fn push(&mut self, v: Vertex, eta: f64) {
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
        if d.is_some_and(|(e, _)| e <= eta + JUST_AFTER_REL * (1.0 + eta)) {
            return;
        }
        self.three_contact_mechanisms(&v, eta, d.map_or(self.top, |d| d.0));
        self.alive.push((v, d));
    }
}
