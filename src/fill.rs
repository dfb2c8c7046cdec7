//! Fill above the extrados (bridge spec §2), in closed form: a vertical dead load equal to
//! the weight of the fill column above each extrados point, up to a level road.
//!
//! Non-dimensional as the statics (r = 1, forces / γ t d r): with g_f = γ_f/γ, κ = 1 + η/2
//! and the road at height y_s above the centre, the pressure per unit dθ on the extrados
//! point θ is p(θ) = (g_f/η)(y_s − κ sin θ) κ sin θ, over the loaded part θ ∈ [β_a, π],
//! β_a = max(β_R, 0) (a horseshoe's lower flanks carry none). On the free body [β_R, β]
//! the fill's resultant is F(β) = ∫ p dθ at the horizontal position S/F,
//! S(β) = ∫ p κ cos θ dθ, both over [β_a, min(β, π)], and it adds to the internal actions
//! N_f = −F cos β, T_f = F sin β, M_f = F cos β − S.
//!
//! With A = g_f κ/η:
//! F = A [y_s (cos β_a − cos b) − κ ((b − β_a)/2 − (sin 2b − sin 2β_a)/4)],
//! S = κ A [y_s (sin²b − sin²β_a)/2 − κ (sin³b − sin³β_a)/3], b = min(β, π).
//! The road height y_s = κ max sin β over the arch + h (h = h_c/r, the depth above the
//! highest extrados point, held fixed as η varies), so ∂y_s/∂η = (max sin β)/2, and
//! ∂A/∂η = −g_f/η².
//!

use crate::input::{check_non_negative, InputError};
use std::f64::consts::{FRAC_PI_2, PI};

/// Fill of unit weight g_f γ up to a level road at depth h r above the highest extrados
/// point (non-dimensional).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Fill {
    /// g_f = γ_f/γ, the fill's unit weight over the masonry's.
    pub weight_ratio: f64,
    /// h = h_c/r, the road's height above the highest extrados point over the mean radius.
    pub depth: f64,
}

/// The fill's load on the free body [β_R, β] at one β and η: the resultant, its first
/// moment, the pressure there, and their derivatives.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct FillLoad {
    /// F, dF/dβ = p(β), d²F/dβ² = p'(β).
    pub f: [f64; 3],
    /// S, dS/dβ = p κ cos β, d²S/dβ².
    pub s: [f64; 3],
    /// ∂F/∂η (`[0]`) and ∂²F/∂η² (`[1]`) at fixed β, each with its first two β-derivatives.
    pub f_eta: [[f64; 3]; 2],
    /// ∂S/∂η and ∂²S/∂η², likewise.
    pub s_eta: [[f64; 3]; 2],
}

/// The fill's contribution to the internal actions at β: N_f, T_f, M_f with their first two
/// β-derivatives, and their first and second η-derivatives (added to the constant terms of
/// the statics).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct FillActions {
    /// N_f and its β-derivatives.
    pub n: [f64; 3],
    /// T_f and its β-derivatives.
    pub t: [f64; 3],
    /// M_f and its β-derivatives.
    pub m: [f64; 3],
    /// `eta[k][a][o]`: the (k+1)-th η-derivative of action a (N_f, T_f, M_f) and its
    /// β-derivative of order o.
    pub eta: [[[f64; 3]; 3]; 2],
}

/// A value with its first two derivatives in η: `[v, v', v'']`.
type Jet = [f64; 3];

/// The product of two jets (Leibniz).
fn jet_mul(a: Jet, b: Jet) -> Jet {
    [
        a[0] * b[0],
        a[1] * b[0] + a[0] * b[1],
        a[2] * b[0] + 2.0 * a[1] * b[1] + a[0] * b[2],
    ]
}

impl Fill {
    /// Fill of weight ratio `weight_ratio` (≥ 0) and depth `depth` (≥ 0) above the highest
    /// extrados point; zero weight is no fill.
    pub fn new(weight_ratio: f64, depth: f64) -> Result<Fill, InputError> {
        Ok(Fill {
            weight_ratio: check_non_negative("--fill-weight", weight_ratio)?,
            depth: check_non_negative("--fill-depth", depth)?,
        })
    }

    /// The largest sin β over the arch [β_R, β_L]: where the extrados is highest.
    pub fn top(beta_r: f64, beta_l: f64) -> f64 {
        if beta_r <= FRAC_PI_2 && FRAC_PI_2 <= beta_l {
            1.0
        } else {
            beta_r.sin().max(beta_l.sin())
        }
    }

    /// The road's height y_s above the centre at thickness `eta`.
    pub fn road(&self, (beta_r, beta_l): (f64, f64), eta: f64) -> f64 {
        (1.0 + 0.5 * eta) * Fill::top(beta_r, beta_l) + self.depth
    }

    /// The load on the free body [β_R, `beta`] of the arch with springings `springings`
    /// at thickness `eta` (> 0).
    pub fn load(&self, springings: (f64, f64), eta: f64, beta: f64) -> FillLoad {
        let a_start = springings.0.max(0.0);
        let b = beta.min(PI);
        if self.weight_ratio == 0.0 || b <= a_start {
            return FillLoad {
                f: [0.0; 3],
                s: [0.0; 3],
                f_eta: [[0.0; 3]; 2],
                s_eta: [[0.0; 3]; 2],
            };
        }
        let gf = self.weight_ratio;
        let kappa = 1.0 + 0.5 * eta;
        let a = gf * kappa / eta;
        let top = Fill::top(springings.0, springings.1);
        let ys = self.road(springings, eta);
        let (sa, ca) = a_start.sin_cos();
        let (sb, cb) = b.sin_cos();
        // the integrals of sin θ, sin²θ, sin θ cos θ and sin²θ cos θ over [β_a, b]
        let c1 = ca - cb;
        let c2 = 0.5 * (b - a_start) - 0.25 * ((2.0 * b).sin() - (2.0 * a_start).sin());
        let d1 = 0.5 * (sb * sb - sa * sa);
        let d2 = (sb * sb * sb - sa * sa * sa) / 3.0;
        let f = a * (ys * c1 - kappa * c2);
        let s = kappa * a * (ys * d1 - kappa * d2);
        // the pressure where the free body ends (zero beyond π) and its β-derivative
        let inside = beta < PI;
        let (sbeta, cbeta) = beta.sin_cos();
        let p = if inside {
            a * (ys - kappa * sbeta) * sbeta
        } else {
            0.0
        };
        let dp = if inside {
            a * (ys * cbeta - 2.0 * kappa * sbeta * cbeta)
        } else {
            0.0
        };
        let ds2 = kappa * (dp * cbeta - p * sbeta);
        // the η-jets of the coefficients: A = g_f (1/η + 1/2), κ = 1 + η/2, y_s = κ top + h
        let jet_a = [a, -gf / (eta * eta), 2.0 * gf / (eta * eta * eta)];
        let jet_k = [kappa, 0.5, 0.0];
        let jet_y = [ys, 0.5 * top, 0.0];
        let ay = jet_mul(jet_a, jet_y);
        let ak = jet_mul(jet_a, jet_k);
        let aky = jet_mul(ak, jet_y);
        let akk = jet_mul(ak, jet_k);
        // the β-jets of the four integrals (constant beyond π)
        let [c1j, c2j, d1j, d2j] = if inside {
            [
                [c1, sbeta, cbeta],
                [c2, sbeta * sbeta, 2.0 * sbeta * cbeta],
                [d1, sbeta * cbeta, cbeta * cbeta - sbeta * sbeta],
                [
                    d2,
                    sbeta * sbeta * cbeta,
                    sbeta * (2.0 * cbeta * cbeta - sbeta * sbeta),
                ],
            ]
        } else {
            [
                [c1, 0.0, 0.0],
                [c2, 0.0, 0.0],
                [d1, 0.0, 0.0],
                [d2, 0.0, 0.0],
            ]
        };
        let along = |k: usize, p: Jet, u: Jet, q: Jet, v: Jet| -> [f64; 3] {
            [0, 1, 2].map(|o| p[k] * u[o] - q[k] * v[o])
        };
        FillLoad {
            f: [f, p, dp],
            s: [s, p * kappa * cbeta, ds2],
            f_eta: [1, 2].map(|k| along(k, ay, c1j, ak, c2j)),
            s_eta: [1, 2].map(|k| along(k, aky, d1j, akk, d2j)),
        }
    }

    /// The fill's internal actions at `beta` (N_f = −F cos β, T_f = F sin β,
    /// M_f = F cos β − S) with their β- and η-derivatives.
    pub fn actions(&self, springings: (f64, f64), eta: f64, beta: f64) -> FillActions {
        let l = self.load(springings, eta, beta);
        let [n, t, m] = vertical_actions(l.f, l.s, beta);
        FillActions {
            n,
            t,
            m,
            eta: [0, 1].map(|k| vertical_actions(l.f_eta[k], l.s_eta[k], beta)),
        }
    }
}

/// The internal actions at `beta` of any vertical load on the free body [β_R, β] with
/// resultant `f` = F and first moment `s` = S (each with its first two β-derivatives):
/// `[N, T, M][derivative order]`, N = −F cos β, T = F sin β, M = F cos β − S.
pub fn vertical_actions(f: [f64; 3], s: [f64; 3], beta: f64) -> [[f64; 3]; 3] {
    let (sn, c) = beta.sin_cos();
    let [f0, f1, f2] = f;
    let [s0, s1, s2] = s;
    [
        [-f0 * c, f0 * sn - f1 * c, f0 * c + 2.0 * f1 * sn - f2 * c],
        [f0 * sn, f0 * c + f1 * sn, -f0 * sn + 2.0 * f1 * c + f2 * sn],
        [
            f0 * c - s0,
            -f0 * sn + f1 * c - s1,
            -f0 * c - 2.0 * f1 * sn + f2 * c - s2,
        ],
    ]
}
