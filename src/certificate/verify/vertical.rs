//! Vertical loads on the extrados, for `verify`, in interval arithmetic (written out again
//! from `../shared/spec/bridge.md` §2–3, not the solver's `fill.rs` and `pressure.rs`): the
//! fill (a dead load) and a pressure's patches and point loads (a live load), each as the
//! resultant F and first moment S = ∫ x dF of its part on the free body [β_R, β], with
//! their first two β-derivatives. They give the internal actions N = −F cos β,
//! T = F sin β, M = F cos β − S, and, as differences between joints, the work of the loads
//! on a block.
//!
//! Fill (r = 1, κ = 1 + η/2, A = g_f κ/η, road y_s = κ max sin β + h): the pressure per unit
//! dθ on the extrados point θ ∈ [θ_a, π], θ_a = max(β_R, 0), is p = A (y_s − κ sin θ) sin θ,
//! F = ∫ p dθ, S = ∫ p κ cos θ dθ over [θ_a, u], u = min(β, π):
//! F = A [y_s (cos θ_a − cos u) − κ ((u − θ_a)/2 − (sin 2u − sin 2θ_a)/4)],
//! S = κ A [y_s (sin²u − sin²θ_a)/2 − κ (sin³u − sin³θ_a)/3];
//! F' = p(β), F'' = A (y_s cos β − 2κ sin β cos β), S' = p κ cos β, S'' = κ (F'' cos β −
//! p sin β) for θ_a < β < π, and zero outside. F' is continuous (p vanishes at 0 and π), so
//! a Taylor enclosure of second order needs no break there: the second derivatives of an
//! interval that holds θ_a or π enclose both sides.
//!
//! Pressure: a patch q on x_lo < x < x_hi, cut to the extrados [κ cos min(β_L, π),
//! κ cos θ_a], carries on the free body its part right of the edge e = κ cos u:
//! F = q (x_hi − from), S = q (x_hi² − from²)/2, from = min(max(e, x_lo), x_hi); where the
//! edge runs through the patch F' = q κ sin β, F'' = q κ cos β, S' = q κ² sin β cos β,
//! S'' = q κ² (cos²β − sin²β), zero elsewhere. F' jumps at a patch's edges: a proof over
//! the continuum breaks there ([`edge_angles`]). A point load q at β_P adds q to F and
//! q κ cos β_P to S on the sections that carry it ([`At`]).

use super::report::{reject, Rejection};
use crate::certificate::interval::Interval as I;
use std::f64::consts::{FRAC_PI_2, PI};

/// A value over an interval of angles with its first two β-derivatives.
pub(super) type Jet = [I; 3];

/// The fill of the certificate's arch: g_f and h.
#[derive(Debug, Clone, Copy)]
pub(super) struct FillModel {
    pub(super) weight_ratio: f64,
    pub(super) depth: f64,
}

/// A pressure's patches (x_lo, x_hi, q) and point loads (β_P, q).
#[derive(Debug, Clone)]
pub(super) struct PressureModel {
    pub(super) patches: Vec<[f64; 3]>,
    pub(super) points: Vec<[f64; 2]>,
}

/// The free body [β_R, `beta`], with a point load at `beta` itself on it when `after`: a
/// section (its side at a point load's angle) or a piece of the arch between point loads.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(super) struct At {
    pub(super) beta: f64,
    pub(super) after: bool,
}

impl At {
    /// Whether the point load at `bp` lies on the free body.
    pub(super) fn carries(&self, bp: f64) -> bool {
        bp < self.beta || (bp == self.beta && self.after)
    }
}

fn zero() -> I {
    I::point(0.0)
}

/// An enclosure of π.
fn pi() -> I {
    I::new(PI, PI.next_up())
}

/// An enclosure of the largest sin β over [β_R, β_L].
fn top(beta_r: f64, beta_l: f64) -> I {
    if beta_r < FRAC_PI_2 && FRAC_PI_2 < beta_l {
        I::point(1.0)
    } else {
        I::point(beta_r).sin().max(I::point(beta_l).sin())
    }
}

/// The integration limit u = min(max(β, θ_a), π) over β ∈ `b`, and where `b` lies: inside
/// [θ_a, π] (`Some(true)`), beyond π (`Some(false)`), or across an end (`None`).
fn limit(b: I, start: f64) -> (I, Option<bool>) {
    let u = I::new(b.lo.max(start).min(PI), b.hi.min(pi().hi).max(start));
    let place = if b.lo >= start && b.hi <= PI {
        Some(true)
    } else if b.lo > PI {
        Some(false)
    } else {
        None
    };
    (u, place)
}

/// The derivatives of `jet` where `b` lies: kept inside, zero beyond, either across an end.
fn placed(mut jet: Jet, place: Option<bool>) -> Jet {
    for d in &mut jet[1..] {
        *d = match place {
            Some(true) => *d,
            Some(false) => zero(),
            None => d.hull(zero()),
        };
    }
    jet
}

/// F and S of the fill over the angles `b` at the thicknesses `eta` (η > 0; zero where
/// the cell reaches η ≤ 0, so callers keep η > 0).
pub(super) fn fill_jets(fill: &FillModel, ends: (f64, f64), b: I, eta: I) -> (Jet, Jet) {
    match eta.recip() {
        Some(per) if eta.lo > 0.0 => fill_jets_per(fill, ends, b, eta, per),
        _ => ([zero(); 3], [zero(); 3]),
    }
}

/// η F and η S of the fill: in units of γ r² d rather than of the ring's weight γ t d r,
/// so bounded as η → 0 (η ≥ 0).
pub(super) fn fill_jets_times_eta(fill: &FillModel, ends: (f64, f64), b: I, eta: I) -> (Jet, Jet) {
    fill_jets_per(fill, ends, b, eta, I::point(1.0))
}

/// F and S of the fill times η `per` (`per` = 1/η gives F and S themselves).
fn fill_jets_per(
    fill: &FillModel,
    (beta_r, beta_l): (f64, f64),
    b: I,
    eta: I,
    per: I,
) -> (Jet, Jet) {
    let start = beta_r.max(0.0);
    if fill.weight_ratio == 0.0 || start >= PI || b.hi < start {
        return ([zero(); 3], [zero(); 3]);
    }
    let (half, two) = (I::point(0.5), I::point(2.0));
    let kappa = I::point(1.0) + half * eta;
    let a = I::point(fill.weight_ratio) * kappa * per;
    let ys = kappa * top(beta_r, beta_l) + I::point(fill.depth);
    let (u, place) = limit(b, start);
    let (su, cu) = (u.sin(), u.cos());
    let a0 = I::point(start);
    let (sa, ca) = (a0.sin(), a0.cos());
    let third = I::new((1.0f64 / 3.0).next_down(), (1.0f64 / 3.0).next_up());
    let c1 = ca - cu;
    let c2 = half * (u - a0) - I::point(0.25) * ((two * u).sin() - (two * a0).sin());
    let d1 = half * (su * su - sa * sa);
    let d2 = third * (su * su * su - sa * sa * sa);
    let p = a * (ys - kappa * su) * su;
    let dp = a * (ys * cu - two * kappa * su * cu);
    let mut f = placed([a * (ys * c1 - kappa * c2), p, dp], place);
    let mut s = placed(
        [
            kappa * a * (ys * d1 - kappa * d2),
            p * kappa * cu,
            kappa * (dp * cu - p * su),
        ],
        place,
    );
    if b.lo < start {
        f[0] = f[0].hull(zero());
        s[0] = s[0].hull(zero());
    }
    (f, s)
}

/// F and S of the pressure per unit λ over the angles `b` at thickness `eta`, with the
/// point loads of the free body `at`.
pub(super) fn pressure_jets(
    p: &PressureModel,
    (beta_r, beta_l): (f64, f64),
    b: I,
    eta: f64,
    at: At,
) -> (Jet, Jet) {
    let kappa = I::point(1.0) + I::point(0.5) * I::point(eta);
    let (mut f, mut s) = ([zero(); 3], [zero(); 3]);
    for &[bp, q] in &p.points {
        if at.carries(bp) {
            f[0] = f[0] + I::point(q);
            s[0] = s[0] + I::point(q) * kappa * I::point(bp).cos();
        }
    }
    let start = beta_r.max(0.0);
    if start >= PI {
        return (f, s);
    }
    let lo_end = kappa
        * if beta_l > PI {
            I::point(-1.0)
        } else {
            I::point(beta_l).cos()
        };
    let hi_end = kappa
        * if beta_r < 0.0 {
            I::point(1.0)
        } else {
            I::point(beta_r).cos()
        };
    let (u, place) = limit(b, start);
    let (su, cu) = (u.sin(), u.cos());
    let e = kappa * cu;
    for &[x_lo, x_hi, q] in &p.patches {
        let (lo, hi) = (I::point(x_lo).max(lo_end), I::point(x_hi).min(hi_end));
        if lo.lo >= hi.hi {
            continue; // off the loaded extrados
        }
        let q = I::point(q);
        let from = e.max(lo).min(hi);
        let w = hi - from;
        f[0] = f[0] + q * w;
        s[0] = s[0] + I::point(0.5) * q * w * (hi + from);
        let through = match place {
            Some(false) => Some(false),
            _ if e.hi < lo.lo || e.lo > hi.hi => Some(false),
            Some(true) if e.lo > lo.hi && e.hi < hi.lo => Some(true),
            _ => None,
        };
        let k2 = q * kappa * kappa;
        let d = [
            q * kappa * su,
            q * kappa * cu,
            k2 * su * cu,
            k2 * (cu * cu - su * su),
        ];
        let d = d.map(|v| match through {
            Some(true) => v,
            Some(false) => zero(),
            None => v.hull(zero()),
        });
        f[1] = f[1] + d[0];
        f[2] = f[2] + d[1];
        s[1] = s[1] + d[2];
        s[2] = s[2] + d[3];
    }
    (f, s)
}

/// N, T, M (each with two β-derivatives) of a vertical load with resultant `f` and first
/// moment `s` over the angles `b`: N = −F cos β, T = F sin β, M = F cos β − S.
pub(super) fn actions(f: Jet, s: Jet, b: I) -> [Jet; 3] {
    let (sn, c) = (b.sin(), b.cos());
    let two = I::point(2.0);
    let [f0, f1, f2] = f;
    [
        [-(f0 * c), f0 * sn - f1 * c, f0 * c + two * f1 * sn - f2 * c],
        [
            f0 * sn,
            f0 * c + f1 * sn,
            -(f0 * sn) + two * f1 * c + f2 * sn,
        ],
        [
            f0 * c - s[0],
            -(f0 * sn) + f1 * c - s[1],
            -(f0 * c) - two * f1 * sn + f2 * c - s[2],
        ],
    ]
}

/// Where each patch edge inside the loaded extrados meets it, at thickness `eta`:
/// an interval of angles [θ_lo, θ_hi] proved to hold the edge's angle (κ cos θ_lo > x >
/// κ cos θ_hi in intervals), sorted by θ_lo.
pub(super) fn edge_angles(
    p: &PressureModel,
    (beta_r, beta_l): (f64, f64),
    eta: f64,
) -> Result<Vec<(f64, f64)>, Rejection> {
    let kappa = I::point(1.0) + I::point(0.5) * I::point(eta);
    let k = 1.0 + 0.5 * eta;
    let mut out = Vec::new();
    let (start, end) = (beta_r.max(0.0), beta_l.min(PI));
    for x in p.patches.iter().flat_map(|q| [q[0], q[1]]) {
        if x >= kappa.hi || x <= -kappa.hi {
            continue; // beyond the extrados: no edge on it
        }
        let guess = (x / k).clamp(-1.0, 1.0).acos();
        let proved = (0..50)
            .map(|i| 8.0 * f64::EPSILON * 2f64.powi(i))
            .find_map(|d| {
                let (lo, hi) = ((guess - d).max(0.0), (guess + d).min(PI));
                let right = (kappa * I::point(lo).cos()).lo > x;
                let left = (kappa * I::point(hi).cos()).hi < x;
                (right && left).then_some((lo, hi))
            });
        match proved {
            // an edge off the loaded extrados (θ_a, min(β_L, π)) breaks nothing there
            Some((lo, hi)) if hi <= start || lo >= end => {}
            Some(e) => out.push(e),
            None => {
                return reject(format!(
                    "load.patches: the edge x = {x} of a patch could not be located on the extrados"
                ))
            }
        }
    }
    out.sort_by(|a, b| a.0.total_cmp(&b.0));
    Ok(out)
}
