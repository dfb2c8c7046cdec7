//! The polytope P(t) the sweep follows: its planes (one activation function at one joint,
//! or a side of the box) as polynomials in the sweep's parameter t, and its vertices, each
//! the intersection of three planes followed along t by Cramer's rule.

use crate::arch::Arch;
use crate::contact::{Contact, ContactKind, Location};
use crate::limit_states::poly::{Poly, MAX_COEFFS};
use crate::load::{rows, LiveLoad, Side};
use crate::statics::{actions, Affine, Reactions};

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
/// φ(x, η) = g(η)·x + c(η), g affine and c at most quadratic in η (with fill, the row times
/// η, `scaled`: g = η × affine, with its constant coefficient exactly zero, and c cubic).
#[derive(Debug, Clone)]
pub(super) struct Plane {
    pub(super) contact: Option<Contact>,
    /// The side of the loaded section (load sweeps; `After` elsewhere).
    pub(super) side: Side,
    pub(super) g: [Poly; 3],
    pub(super) c: Poly,
    /// Whether the row is η φ (an arch with fill).
    pub(super) scaled: bool,
}

impl Plane {
    /// φ at (x, η) (of a scaled row, η φ / η: tolerances stay those of φ).
    #[inline]
    pub(super) fn value(&self, x: &Reactions, eta: f64) -> f64 {
        self.at(eta).value(x)
    }
    /// The plane at η, for its values at many x ([`PlaneAt::value`]).
    #[inline]
    pub(super) fn at(&self, eta: f64) -> PlaneAt {
        PlaneAt {
            g: [
                self.g[0].eval(eta),
                self.g[1].eval(eta),
                self.g[2].eval(eta),
            ],
            c: self.c.eval(eta),
            scaled: self.scaled.then_some(eta),
        }
    }
    /// φ at η as an affine function of x (of a scaled row, divided by η).
    pub(super) fn affine(&self, eta: f64) -> Affine {
        let k = if self.scaled { 1.0 / eta } else { 1.0 };
        let g = [0, 1, 2].map(|i| self.g[i].eval(eta));
        let c = self.c.eval(eta);
        if self.scaled {
            Affine {
                g: g.map(|v| k * v),
                c: k * c,
            }
        } else {
            Affine { g, c }
        }
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
        if self.scaled {
            // φ = ψ/η: ∂φ/∂η = (ψ' − ψ/η)/η
            let psi = g[0] * x[0] + g[1] * x[1] + g[2] * x[2] + self.c.eval(eta);
            return (g.map(|v| v / eta), (d - psi / eta) / eta);
        }
        (g, d)
    }
}

/// With fill the rows carry the fill's 1/η: η φ is then a polynomial in η with the sign
/// and the zeros of φ for η > 0 — its gradient η × (affine), from these two thicknesses,
/// and its constant term a cubic, from all four.
const FILLED_NODES: [f64; 4] = [1.0, 2.0, 0.5, 1.5];

/// The cubic through (`FILLED_NODES`[i], `v[i]`) (Newton's divided differences, expanded).
fn cubic(v: [f64; 4]) -> Poly {
    let t = FILLED_NODES;
    let mut d = v;
    for level in 1..4 {
        for i in (level..4).rev() {
            d[i] = (d[i] - d[i - 1]) / (t[i] - t[i - level]);
        }
    }
    // d0 + d1 (η − t0) + d2 (η − t0)(η − t1) + d3 (η − t0)(η − t1)(η − t2), by Horner
    let mut p = Poly::constant(d[3]);
    for k in (0..3).rev() {
        p = p.mul(&Poly::linear(-t[k], 1.0)).add(&Poly::constant(d[k]));
    }
    p.trimmed(COEFF_TRIM_REL)
}

/// The rows of one joint with fill as polynomials in η: each row times η, its gradient's
/// constant coefficient exactly zero, so that every vertex's determinant and numerators
/// carry their common power of η exactly, and [`Vertex::new`] divides it out (a multiple
/// root at η = 0 would blur the roots just above it).
fn filled_rows(arch: &Arch, beta: f64, kinds: &[ContactKind], mu: f64) -> Vec<([Poly; 3], Poly)> {
    let a = FILLED_NODES.map(|eta| actions(arch, eta, beta));
    kinds
        .iter()
        .map(|&kind| {
            let rows = [0, 1, 2, 3].map(|i| a[i].activation(kind, 0, FILLED_NODES[i], mu));
            // g(η) affine through η = 1 and 2: η g(η) = (2 g₁ − g₂) η + (g₂ − g₁) η²
            let g = [0, 1, 2].map(|k| {
                let (g1, g2) = (rows[0].g[k], rows[1].g[k]);
                Poly::from_coeffs(&[0.0, 2.0 * g1 - g2, g2 - g1]).trimmed(COEFF_TRIM_REL)
            });
            (g, cubic([0, 1, 2, 3].map(|i| FILLED_NODES[i] * rows[i].c)))
        })
        .collect()
}

/// The rows of one joint of the ring alone as polynomials in η, from three thicknesses:
/// exact for g (affine) and c (quadratic).
fn ring_rows(arch: &Arch, beta: f64, kinds: &[ContactKind], mu: f64) -> Vec<([Poly; 3], Poly)> {
    let a: Vec<_> = [0.0, 1.0, 2.0]
        .iter()
        .map(|&eta| actions(arch, eta, beta))
        .collect();
    let quad = |p0: f64, p1: f64, p2: f64| {
        let c2 = 0.5 * (p2 - 2.0 * p1 + p0);
        Poly::from_coeffs(&[p0, p1 - p0 - c2, c2]).trimmed(COEFF_TRIM_REL)
    };
    kinds
        .iter()
        .map(|&kind| {
            let f: Vec<_> = (0..3)
                .map(|i| a[i].activation(kind, 0, i as f64, mu))
                .collect();
            (
                [0, 1, 2].map(|k| quad(f[0].g[k], f[1].g[k], f[2].g[k])),
                quad(f[0].c, f[1].c, f[2].c),
            )
        })
        .collect()
}

/// The planes of a discrete arch at friction μ (with fill, each row times η:
/// [`FILLED_NODES`]), then the six box sides.
pub(super) fn planes(arch: &Arch, joints: &[f64], mu: f64) -> Vec<Plane> {
    let scaled = arch.fill().is_some();
    let kinds = ContactKind::active_at(mu);
    let mut out = Vec::new();
    for (j, &beta) in joints.iter().enumerate() {
        let at = Location::of_joint(j, joints.len());
        let rows = if scaled {
            filled_rows(arch, beta, kinds, mu)
        } else {
            ring_rows(arch, beta, kinds, mu)
        };
        for (&kind, (g, c)) in kinds.iter().zip(rows) {
            out.push(Plane {
                contact: Some(Contact {
                    beta,
                    kind,
                    at,
                    free: false,
                }),
                side: Side::After,
                g,
                c,
                scaled,
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
                scaled: false,
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
            scaled: false,
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

/// A crossing polynomial of a scaled row with its power of η divided out (same sign for
/// η > 0); out of line, so that the ring's hot path `along` stays as it was.
#[inline(never)]
fn deflated(p: Poly) -> Poly {
    p.shifted_down(p.zero_order())
}

/// A screen of the planes along a vertex's path over an interval where det keeps its sign:
/// the crossing polynomial φ_l·det ([`Vertex::along`]) is linear in the plane's
/// coefficients, and so are its Bernstein coefficients there. A plane's coefficients fill
/// slots (its constant term's powers of η, then each gradient component's); each slot
/// multiplies a polynomial (η^i det, η^i num_k) whose Bernstein coefficients, all of one
/// degree, are held by coefficient, then slot.
pub(super) struct Screen {
    /// For each Bernstein coefficient in turn, its value for each slot.
    by_degree: Vec<f64>,
    /// Slots a plane fills (`c_len + 3 g_len`).
    slots: usize,
    det_sign: f64,
}

/// A Bernstein coefficient clears the screen when its sign is det's opposite by more than
/// this fraction of the sum of its terms' sizes (their rounding is far below).
const SCREEN_REL: f64 = 1e-12;

impl Screen {
    /// Whether the plane stays strictly inside along the path over the whole interval:
    /// every Bernstein coefficient of φ_l·det has det's opposite sign (beyond rounding), so
    /// φ_l < 0 there and the plane crosses nowhere in it: plane `l`, its coefficients in
    /// `layout` ([`slot_layout`]).
    pub(super) fn inside(&self, layout: &[f64], l: usize) -> bool {
        let coeffs = &layout[l * self.slots..(l + 1) * self.slots];
        self.by_degree.chunks_exact(self.slots).all(|row| {
            let (mut b, mut size) = (0.0, 0.0);
            for (x, y) in row.iter().zip(coeffs) {
                let t = x * y;
                b += t;
                size += t.abs();
            }
            self.det_sign * b < -SCREEN_REL * size
        })
    }
}

/// The planes' coefficients in the screen's slots, `c_len + 3 g_len` a plane (its constant
/// term's, then each gradient component's, zero where it has fewer): the `l`-th plane's are
/// `[l * slots, (l + 1) * slots)`. A product with such a zero adds zero to both sums of
/// [`Screen::inside`] (its rows are finite), so every sum is the one without that slot.
pub(super) fn slot_layout(planes: &[Plane], c_len: usize, g_len: usize) -> Vec<f64> {
    let slots = c_len + 3 * g_len;
    let mut out = vec![0.0; planes.len() * slots];
    for (l, p) in planes.iter().enumerate() {
        let w = &mut out[l * slots..(l + 1) * slots];
        let c = p.c.coeffs();
        w[..c.len()].copy_from_slice(c);
        for (k, q) in p.g.iter().enumerate() {
            let at = c_len + k * g_len;
            w[at..at + q.coeffs().len()].copy_from_slice(q.coeffs());
        }
    }
    out
}

/// A plane's polynomials evaluated at one η ([`Plane::at`]).
#[derive(Debug, Clone, Copy)]
pub(super) struct PlaneAt {
    g: [f64; 3],
    c: f64,
    /// η, where the row is η φ.
    scaled: Option<f64>,
}

impl PlaneAt {
    /// φ at x ([`Plane::value`]).
    #[inline]
    pub(super) fn value(&self, x: &Reactions) -> f64 {
        let v = self.g[0] * x[0] + self.g[1] * x[1] + self.g[2] * x[2] + self.c;
        match self.scaled {
            Some(eta) => v / eta,
            None => v,
        }
    }
}

/// A vertex of P(η): three planes and its path x(η) = num(η)/det(η) (Cramer's rule).
#[derive(Debug, Clone)]
pub(super) struct Vertex {
    pub(super) planes: [usize; 3],
    num: [Poly; 3],
    pub(super) det: Poly,
    /// Whether a plane of the vertex is η φ ([`Plane::scaled`]).
    scaled: bool,
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
        let scaled = rows.iter().any(|r| r.scaled);
        if scaled {
            // η^k divides det and every numerator exactly (the scaled gradients' zero
            // constant coefficients): divide it out, x(η) unchanged
            let k = num
                .iter()
                .filter(|p| p.norm() > 0.0)
                .map(Poly::zero_order)
                .fold(det.zero_order(), usize::min);
            return Vertex {
                planes: t,
                num: num.map(|p| p.shifted_down(k)),
                det: det.shifted_down(k),
                scaled,
            };
        }
        Vertex {
            planes: t,
            num,
            det,
            scaled,
        }
    }
    pub(super) fn at(&self, eta: f64) -> Reactions {
        let d = self.det.eval(eta);
        [0, 1, 2].map(|k| self.num[k].eval(eta) / d)
    }
    /// The screen of [`Screen`] over [lo, hi] for planes of at most `c_len` constant and
    /// `g_len` gradient coefficients (`None` where their crossing polynomials would have
    /// too high a degree, or det vanishes inside).
    pub(super) fn screen(&self, c_len: usize, g_len: usize, lo: f64, hi: f64) -> Option<Screen> {
        let degree = |p: &Poly| p.coeffs().len().saturating_sub(1);
        let top_num = self.num.iter().map(degree).max().unwrap_or(0);
        let n = (c_len.saturating_sub(1) + degree(&self.det))
            .max(g_len.saturating_sub(1) + top_num)
            + 1;
        let det_sign = self.det.eval(0.5 * (lo + hi)).signum();
        if n > MAX_COEFFS || det_sign == 0.0 {
            return None;
        }
        let slots = c_len + 3 * g_len;
        let mut by_degree = vec![0.0; n * slots];
        let polys = (0..c_len).map(|i| (&self.det, i)).chain(
            self.num
                .iter()
                .flat_map(|num| (0..g_len).map(move |i| (num, i))),
        );
        for (s, (p, i)) in polys.enumerate() {
            let b = p.shifted_up(i).bernstein(lo, hi, n - 1);
            for j in 0..n {
                by_degree[j * slots + s] = b[j];
            }
        }
        Some(Screen {
            by_degree,
            slots,
            det_sign,
        })
    }

    /// φ_l(x(η), η) · det(η), a polynomial.
    #[inline]
    pub(super) fn along(&self, l: &Plane) -> Poly {
        let p = Poly::sum_of_products([
            (&l.c, &self.det),
            (&l.g[0], &self.num[0]),
            (&l.g[1], &self.num[1]),
            (&l.g[2], &self.num[2]),
        ]);
        if self.scaled || l.scaled {
            return deflated(p);
        }
        p
    }
}
