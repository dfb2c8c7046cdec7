//! Statics of the arch (formulation §3): internal actions N, T, M at a radial joint as
//! affine functions of the redundant reactions x = (h, v, w) at the right springing,
//! their exact β-derivatives, and the four activation functions.
//!
//! Forces are divided by γ t d r and moments by γ t d r²; N is positive in compression.

use crate::arch::{Arch, Radians};
use crate::contact::Contact;
use crate::contact::ContactKind;

/// The redundant reactions x = (h, v, w) at the right springing.
pub type Reactions = [f64; 3];

/// An affine function of x: `g · x + c`.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct Affine {
    /// Gradient with respect to (h, v, w).
    pub g: [f64; 3],
    /// Constant term (the value at x = 0).
    pub c: f64,
}

impl Affine {
    /// Evaluates the function at x.
    #[inline]
    pub fn at(&self, x: &Reactions) -> f64 {
        self.g[0] * x[0] + self.g[1] * x[1] + self.g[2] * x[2] + self.c
    }
    /// `a·self + b·other`.
    #[inline]
    pub fn combine(a: f64, p: &Affine, b: f64, q: &Affine) -> Affine {
        Affine {
            g: [
                a * p.g[0] + b * q.g[0],
                a * p.g[1] + b * q.g[1],
                a * p.g[2] + b * q.g[2],
            ],
            c: a * p.c + b * q.c,
        }
    }
    /// Euclidean norm of the gradient, computed without overflow (friction rows carry
    /// μ N, and μ may be as large as the largest finite float).
    pub fn grad_norm(&self) -> f64 {
        let m = self.g[0].abs().max(self.g[1].abs()).max(self.g[2].abs());
        if m == 0.0 || !m.is_finite() {
            return m;
        }
        let (a, b, c) = (self.g[0] / m, self.g[1] / m, self.g[2] / m);
        m * (a * a + b * b + c * c).sqrt()
    }
}

/// N, T or M as the statics combine them: an affine form of x ([`Affine`]), or its value
/// at one x (`f64`). The identities below are written once for both.
pub trait Force: Copy {
    /// `a·p + b·q`.
    fn combine(a: f64, p: &Self, b: f64, q: &Self) -> Self;
    /// `self + k` for a constant k.
    fn shift(self, k: f64) -> Self;
    /// `−self`.
    fn negated(self) -> Self;
}

impl Force for Affine {
    #[inline]
    fn combine(a: f64, p: &Affine, b: f64, q: &Affine) -> Affine {
        Affine::combine(a, p, b, q)
    }
    #[inline]
    fn shift(self, k: f64) -> Affine {
        Affine {
            g: self.g,
            c: self.c + k,
        }
    }
    #[inline]
    fn negated(self) -> Affine {
        Affine {
            g: self.g.map(|v| -v),
            c: -self.c,
        }
    }
}

impl Force for f64 {
    #[inline]
    fn combine(a: f64, p: &f64, b: f64, q: &f64) -> f64 {
        a * p + b * q
    }
    #[inline]
    fn shift(self, k: f64) -> f64 {
        self + k
    }
    #[inline]
    fn negated(self) -> f64 {
        -self
    }
}

/// The first and second β-derivatives of N, T, M under the ring's own weight, from N and T
/// at the angle (sin β, cos β) (formulation §3): dN = T − cos β, dT = −N + sin β,
/// dM = −T + (1 − ρ) cos β; d²N = 2 sin β − N, d²T = 2 cos β − T, d²M = N − (2 − ρ) sin β.
#[inline]
pub fn ring_derivatives<F: Force>(n: F, t: F, (s, c): (f64, f64), rho: f64) -> [[F; 3]; 2] {
    [
        [
            t.shift(-c),
            n.negated().shift(s),
            t.negated().shift((1.0 - rho) * c),
        ],
        [
            n.negated().shift(2.0 * s),
            t.negated().shift(2.0 * c),
            n.shift(-((2.0 - rho) * s)),
        ],
    ]
}

/// The natural magnitude of a state's forces, 1 + |h| + |v| + |w| (units of γ t d r):
/// tolerances on φ and on Newton residuals are relative to it.
pub fn reaction_scale(x: &Reactions) -> f64 {
    1.0 + x.iter().map(|v| v.abs()).sum::<f64>()
}

/// N, T, M at one angle as affine functions of x, with their first and second
/// β-derivatives (index = order of the derivative). Their η-derivatives, which only the
/// thickness family needs, are [`eta_terms`].
#[derive(Debug, Clone, Copy)]
pub struct Actions {
    /// N, dN/dβ, d²N/dβ².
    pub n: [Affine; 3],
    /// T, dT/dβ, d²T/dβ².
    pub t: [Affine; 3],
    /// M, dM/dβ, d²M/dβ².
    pub m: [Affine; 3],
}

/// The first and second η-derivatives of the constant terms of N, T, M at one angle (each
/// with its β-derivatives of order 0 to 2): the true centroid's ρ(η) in M, and with fill the
/// fill's 1/η in all three. Apart from [`Actions`], so that a scan of the ring pays nothing
/// for them.
#[derive(Debug, Clone, Copy)]
pub struct EtaTerms {
    /// ∂M/∂η of the ring's weight (zero for the centreline model), by β-order.
    ring: [f64; 3],
    /// ∂²M/∂η² of the ring's weight, by β-order.
    ring2: [f64; 3],
    /// With fill, `[k][action][order]`: the (k+1)-th η-derivative of the fill's N, T, M
    /// ([`crate::fill::FillActions::eta`]).
    fill: Option<[[[f64; 3]; 3]; 2]>,
}

/// The η-derivatives of the internal actions of `arch` at thickness `eta` and angle `beta`.
pub fn eta_terms(arch: &Arch, eta: f64, beta: Radians) -> EtaTerms {
    eta_terms_with(arch, eta, beta, arch.sin_cos(beta))
}

/// [`eta_terms`] with (sin β, cos β) given.
#[inline]
pub fn eta_terms_with(arch: &Arch, eta: f64, beta: Radians, (s, c): (f64, f64)) -> EtaTerms {
    let sr = arch.right_sin_cos().0;
    let drho = arch.weight().drho_deta(eta);
    let d2rho = arch.weight().d2rho_deta2(eta);
    EtaTerms {
        ring: [-drho * (s - sr), -drho * c, drho * s],
        ring2: [-d2rho * (s - sr), -d2rho * c, d2rho * s],
        fill: arch
            .fill()
            .map(|f| f.actions(arch.springings(), eta, beta).eta),
    }
}

impl EtaTerms {
    /// Whether the sliding rows depend on η (only through a fill).
    pub fn moves_sliding(&self) -> bool {
        self.fill.is_some()
    }

    /// ∂/∂η of the activation function of `mode` (β-derivative `order`) at thickness `eta`,
    /// friction `mu`, where N (of that order) is `n`: ±∂M/∂η − N/2 − (η/2) ∂N/∂η for a hinge,
    /// ±∂T/∂η − μ ∂N/∂η for sliding (the η-terms of N and T come from the fill alone).
    #[inline]
    pub fn activation_d_eta(
        &self,
        mode: ContactKind,
        order: usize,
        (eta, mu): (f64, f64),
        n: f64,
    ) -> f64 {
        let dm = self.ring[order];
        let ring = match mode {
            ContactKind::HingeExtrados => -0.5 * n + dm,
            ContactKind::HingeIntrados => -0.5 * n - dm,
            _ => 0.0,
        };
        let Some(f) = &self.fill else {
            return ring;
        };
        let [dn, dt, dm] = f[0].map(|a| a[order]);
        ring + match mode {
            ContactKind::HingeExtrados => dm - 0.5 * eta * dn,
            ContactKind::HingeIntrados => -dm - 0.5 * eta * dn,
            ContactKind::SlidePlus => dt - mu * dn,
            ContactKind::SlideMinus => -dt - mu * dn,
        }
    }

    /// ∂²/∂η² of the activation function of `mode` (β-derivative `order`) at (η, μ):
    /// ±∂²M/∂η² − ∂N/∂η − (η/2) ∂²N/∂η² for a hinge, ±∂²T/∂η² − μ ∂²N/∂η² for sliding
    /// (independent of x: η enters the gradient linearly).
    #[inline]
    pub fn activation_d2_eta(&self, mode: ContactKind, order: usize, (eta, mu): (f64, f64)) -> f64 {
        let d2m = self.ring2[order];
        let ring = match mode {
            ContactKind::HingeExtrados => d2m,
            ContactKind::HingeIntrados => -d2m,
            _ => 0.0,
        };
        let Some(f) = &self.fill else {
            return ring;
        };
        let dn = f[0][0][order];
        let [d2n, d2t, d2m] = f[1].map(|a| a[order]);
        ring + match mode {
            ContactKind::HingeExtrados => d2m - dn - 0.5 * eta * d2n,
            ContactKind::HingeIntrados => -d2m - dn - 0.5 * eta * d2n,
            ContactKind::SlidePlus => d2t - mu * d2n,
            ContactKind::SlideMinus => -d2t - mu * d2n,
        }
    }
}

/// N, T, M alone (no β-derivatives) at angle `beta` with (sin β, cos β) given: what a scan
/// of the joints needs, the same arithmetic as [`actions_with`]'s order 0 (the ring's
/// weight, then the fill's actions added to the constant terms).
#[inline]
pub fn forces_with(arch: &Arch, eta: f64, beta: Radians, sc: (f64, f64)) -> [Affine; 3] {
    let mut f = ring_forces(arch, eta, beta, sc);
    if let Some(fill) = arch.fill() {
        let a = fill.actions(arch.springings(), eta, beta);
        for (k, v) in [a.n[0], a.t[0], a.m[0]].into_iter().enumerate() {
            f[k].c += v;
        }
    }
    f
}

/// N, T, M of the ring's own weight alone (no fill).
#[inline]
fn ring_forces(arch: &Arch, eta: f64, beta: Radians, (s, c): (f64, f64)) -> [Affine; 3] {
    let (sr, cr) = arch.right_sin_cos();
    let d = beta - arch.beta_right();
    let rho = arch.weight().rho(eta);
    [
        Affine {
            g: [s, c, 0.0],
            c: -d * c,
        },
        Affine {
            g: [c, -s, 0.0],
            c: d * s,
        },
        Affine {
            g: [-(s - sr), cr - c, 1.0],
            c: d * c - rho * (s - sr),
        },
    ]
}

/// dφ/dβ of each of `modes` (in their order; the rest zero) at reactions `x`, from the
/// ring's own weight alone (the caller leaves out arches with fill), at angle `beta` with
/// (sin β, cos β) given: N and T are evaluated at x first and [`ring_derivatives`] combines
/// their values, a few flops in all. The values of
/// `actions_with(..).activation(mode, 1, ..).at(x)` to rounding (another order of the same
/// terms, so not bit for bit): a scan's sign tests on its grid use them.
#[inline]
pub fn ring_slopes(
    arch: &Arch,
    (eta, mu): (f64, f64),
    beta: Radians,
    sc: (f64, f64),
    x: &Reactions,
    modes: &[ContactKind],
) -> [f64; 4] {
    debug_assert!(arch.fill().is_none(), "ring_slopes on an arch with fill");
    let [n, t, _] = ring_forces(arch, eta, beta, sc);
    let [first, _] = ring_derivatives(n.at(x), t.at(x), sc, arch.weight().rho(eta));
    let mut out = [0.0; 4];
    for (slot, &mode) in out.iter_mut().zip(modes) {
        *slot = activation_of(mode, &first, eta, mu);
    }
    out
}

/// The activation function of `mode` from N, T, M (any one β-derivative order) at
/// thickness `eta` and friction `mu`: an affine function of x from their affine forms, or
/// its value from their values ([`Force`]).
#[inline]
pub fn activation_of<F: Force>(mode: ContactKind, [n, t, m]: &[F; 3], eta: f64, mu: f64) -> F {
    match mode {
        ContactKind::HingeExtrados => F::combine(1.0, m, -0.5 * eta, n),
        ContactKind::HingeIntrados => F::combine(-1.0, m, -0.5 * eta, n),
        ContactKind::SlidePlus => F::combine(1.0, t, -mu, n),
        ContactKind::SlideMinus => F::combine(-1.0, t, -mu, n),
    }
}

/// Internal actions at angle `beta` of `arch` at thickness `eta` (formulation §3):
///
/// N = h sin β + v cos β − (β − β_R) cos β,
/// T = h cos β − v sin β + (β − β_R) sin β,
/// M = −h (sin β − sin β_R) + v (cos β_R − cos β) + w + (β − β_R) cos β − ρ (sin β − sin β_R),
///
/// with ρ = 1 (centreline weight) or 1 + η²/12 (true centroid).
pub fn actions(arch: &Arch, eta: f64, beta: Radians) -> Actions {
    actions_with(arch, eta, beta, arch.sin_cos(beta))
}

/// [`actions`] with (sin β, cos β) given (a discrete arch's cached
/// [`Arch::joint_sin_cos`]): the same arithmetic, the same bits.
#[inline]
pub fn actions_with(arch: &Arch, eta: f64, beta: Radians, (s, c): (f64, f64)) -> Actions {
    let rho = arch.weight().rho(eta);
    let [n0, t0, m0] = ring_forces(arch, eta, beta, (s, c));
    let [[n1, t1, m1], [n2, t2, m2]] = ring_derivatives(n0, t0, (s, c), rho);
    let mut a = Actions {
        n: [n0, n1, n2],
        t: [t0, t1, t2],
        m: [m0, m1, m2],
    };
    if let Some(fill) = arch.fill() {
        // the identities above hold for the ring's weight alone: the fill adds its own
        let f = fill.actions(arch.springings(), eta, beta);
        for order in 0..3 {
            a.n[order].c += f.n[order];
            a.t[order].c += f.t[order];
            a.m[order].c += f.m[order];
        }
    }
    a
}

impl Actions {
    /// The activation function of `mode` (derivative `order` 0, 1 or 2 in β) as an
    /// affine function of x at thickness `eta` and friction `mu`.
    #[inline]
    pub fn activation(&self, mode: ContactKind, order: usize, eta: f64, mu: f64) -> Affine {
        activation_of(
            mode,
            &[self.n[order], self.t[order], self.m[order]],
            eta,
            mu,
        )
    }

    /// ∂/∂μ of the activation function of `mode` (β-derivative `order`) at x.
    #[inline]
    pub fn activation_d_mu(&self, mode: ContactKind, order: usize, x: &Reactions) -> f64 {
        match mode {
            ContactKind::SlidePlus | ContactKind::SlideMinus => -self.n[order].at(x),
            _ => 0.0,
        }
    }
}

/// The values (N, T, M) at angle `beta` for reactions x.
pub fn internal_forces(arch: &Arch, eta: f64, x: &Reactions, beta: Radians) -> (f64, f64, f64) {
    let a = actions(arch, eta, beta);
    (a.n[0].at(x), a.t[0].at(x), a.m[0].at(x))
}

/// The natural magnitude of the activation function of `mode` at reactions x, used
/// to make tolerances relative (formulation §6): (1 + ‖x‖₁) times η for hinges and
/// min(μ, 1) for sliding, neither below `floor` (which keeps tolerances above the
/// rounding error of M, T, N, whose terms are of size ‖x‖).
pub fn magnitude(mode: ContactKind, eta: f64, mu: f64, x: &Reactions, floor: f64) -> f64 {
    let base = 1.0 + x.iter().map(|v| v.abs()).sum::<f64>();
    let factor = if mode.is_hinge() { eta } else { mu.min(1.0) };
    base * factor.max(floor)
}

/// The relative rounding error to expect in η refined on the hinge contacts of `contacts` at
/// the state (η, x), in double precision: at a hinge η is where M = ±ηN/2, and M is a sum of
/// terms much larger than ηN/2 on a shallow segment (sin β − sin β_R of two sines near 1,
/// times h), so their rounding fixes η only to about u Σ|terms of M| / (η N / 2) (u the unit
/// roundoff). The largest over the hinges; 0 when no hinge carries compression. A
/// first-order bound of the evaluation's error, not of Newton's: tables print η to the
/// digits it leaves.
pub fn eta_rounding(arch: &Arch, eta: f64, x: &Reactions, contacts: &[Contact]) -> f64 {
    let u = 0.5 * f64::EPSILON;
    let (sr, cr) = arch.right_sin_cos();
    let rho = arch.weight().rho(eta);
    let [h, v, w] = x.map(f64::abs);
    contacts
        .iter()
        .filter(|c| c.kind.is_hinge())
        .map(|c| {
            let (s, co) = c.beta.sin_cos();
            let d = (c.beta - arch.beta_right()).abs();
            let (n, _, _) = internal_forces(arch, eta, x, c.beta);
            let terms_m =
                (h + rho) * (s.abs() + sr.abs()) + v * (co.abs() + cr.abs()) + w + d * co.abs();
            let terms_n = h * s.abs() + v * co.abs() + d * co.abs();
            let err = u * (terms_m + 0.5 * eta * terms_n);
            if n > 0.0 && eta > 0.0 {
                err / (0.5 * n * eta)
            } else {
                0.0
            }
        })
        .fold(0.0, f64::max)
}
