//! The polytope P(t) the sweep follows: its planes (one activation function at one joint,
//! or a side of the box) as polynomials in the sweep's parameter t, and its vertices, each
//! the intersection of three planes followed along t by Cramer's rule.

use crate::arch::Arch;
use crate::contact::{Contact, ContactKind, Location};
use crate::limit_states::poly::Poly;
use crate::load::{rows, LiveLoad, Side};
use crate::statics::{actions, Reactions};

/// Half-width of the box on (h, v, w) that bounds the admissible set (units of γ t d r).
pub const BOX: f64 = 1e7;

/// A state lies inside the box, not on it, when every |x_k| < [`BOX`] (1 − this).
pub const BOX_EDGE_REL: f64 = 1e-9;

/// A plane's coefficients, interpolated from three thicknesses, keep no trailing
/// coefficient below this fraction of their largest: it is the rounding residue of a term
/// that cancels (the gradients are affine in η, so their quadratic coefficient is only
/// that).
const COEFF_TRIM_REL: f64 = 1e-15;

/// One activation function at one joint, or a side of the box:
/// φ(x, η) = g(η)·x + c(η), g affine and c at most quadratic in η.
#[derive(Debug, Clone)]
pub(super) struct Plane {
    pub(super) contact: Option<Contact>,
    /// The side of the loaded section (load sweeps; `After` elsewhere).
    pub(super) side: Side,
    pub(super) g: [Poly; 3],
    pub(super) c: Poly,
}

impl Plane {
    pub(super) fn value(&self, x: &Reactions, eta: f64) -> f64 {
        self.g[0].eval(eta) * x[0]
            + self.g[1].eval(eta) * x[1]
            + self.g[2].eval(eta) * x[2]
            + self.c.eval(eta)
    }
    /// ∂φ/∂x (at η) and ∂φ/∂η (at x, η).
    pub(super) fn slopes(&self, x: &Reactions, eta: f64) -> ([f64; 3], f64) {
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
pub(super) fn planes(arch: &Arch, joints: &[f64], mu: f64) -> Vec<Plane> {
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
                Poly::from_coeffs(&[p0, p1 - p0 - c2, c2]).trimmed(COEFF_TRIM_REL)
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
pub(super) fn load_planes(
    arch: &Arch,
    joints: &[f64],
    eta: f64,
    mu: f64,
    load: &LiveLoad,
) -> Vec<Plane> {
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

/// The determinant of a 3 × 3 matrix of polynomials (cofactors along the first row).
pub(super) fn det3(m: [[&Poly; 3]; 3]) -> Poly {
    let minor = |a: &Poly, b: &Poly, c: &Poly, d: &Poly| a.mul(d).sub(&b.mul(c));
    m[0][0]
        .mul(&minor(m[1][1], m[1][2], m[2][1], m[2][2]))
        .sub(&m[0][1].mul(&minor(m[1][0], m[1][2], m[2][0], m[2][2])))
        .add(&m[0][2].mul(&minor(m[1][0], m[1][1], m[2][0], m[2][1])))
}

/// A vertex of P(η): three planes and its path x(η) = num(η)/det(η) (Cramer's rule).
#[derive(Debug, Clone)]
pub(super) struct Vertex {
    pub(super) planes: [usize; 3],
    num: [Poly; 3],
    pub(super) det: Poly,
}

impl Vertex {
    pub(super) fn new(p: &[Plane], t: [usize; 3]) -> Vertex {
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
    pub(super) fn at(&self, eta: f64) -> Reactions {
        let d = self.det.eval(eta);
        [0, 1, 2].map(|k| self.num[k].eval(eta) / d)
    }
    /// φ_l(x(η), η) · det(η), a polynomial.
    pub(super) fn along(&self, l: &Plane) -> Poly {
        (0..3).fold(l.c.mul(&self.det), |acc, k| {
            acc.add(&l.g[k].mul(&self.num[k]))
        })
    }
}
