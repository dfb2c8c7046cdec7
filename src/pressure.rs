//! A vertical live pressure on the extrados (bridge spec §3): uniform patches over
//! horizontal intervals of the upward-facing extrados, what a vehicle's axles or a patch
//! load at the road become after spreading through the fill. Non-dimensional as the statics
//! (r = 1; a patch's intensity per unit horizontal length, in γ t d r per unit λ).
//!
//! The extrados point θ ∈ [0, π] lies at x = κ cos θ, κ = 1 + η/2, so the free body
//! [β_R, β] carries the patches' part with x ∈ [κ cos b, κ cos θ_a], b = min(β, π),
//! θ_a = max(β_R, 0): its resultant F(β) and first moment S(β) = ∫ x q dx give the
//! internal actions as for any vertical load ([`crate::fill::vertical_actions`]). F is
//! continuous in β and its β-derivative q κ sin β jumps at a patch's edges: the actions are
//! continuous there with a corner ([`Pressure::breaks`]).

use crate::arch::{fmt_value, Arch, InputError, Radians};
use std::f64::consts::PI;

/// The most patches one pressure carries (a vehicle's axles and a patch load).
pub const MAX_PATCHES: usize = 16;

/// A uniform vertical pressure `q` (per unit horizontal length) over `x_lo < x < x_hi` of
/// the extrados (x from the centre towards the right springing, r = 1).
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct Patch {
    /// Left end (smaller x).
    pub x_lo: f64,
    /// Right end.
    pub x_hi: f64,
    /// Intensity per unit horizontal length, per unit λ.
    pub q: f64,
}

/// A vertical point load `q` (per unit λ) at the extrados point of angle `beta` (loads
/// that do not spread: no fill, or no dispersal).
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct PointLoad {
    /// Angle of the loaded extrados point (in [max(β_R, 0), min(β_L, π)]).
    pub beta: Radians,
    /// The load per unit λ.
    pub q: f64,
}

/// Up to [`MAX_PATCHES`] patches and as many point loads on the extrados (`Copy`, so a live
/// load stays a value).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Pressure {
    patches: [Patch; MAX_PATCHES],
    len: usize,
    points: [PointLoad; MAX_PATCHES],
    n_points: usize,
}

impl Pressure {
    /// The pressure of `patches` (each finite with x_lo < x_hi and q ≥ 0) and `points` (each
    /// finite with q ≥ 0): at most [`MAX_PATCHES`] of each, at least one load.
    pub fn new(patches: &[Patch], points: &[PointLoad]) -> Result<Pressure, InputError> {
        let count = patches.len() + points.len();
        if count == 0 || patches.len() > MAX_PATCHES || points.len() > MAX_PATCHES {
            return Err(InputError::OutOfRange {
                arg: "--axles",
                value: count.to_string(),
                range: format!("1 to {MAX_PATCHES} loads that spread and as many that do not"),
            });
        }
        for p in points {
            if !(p.beta.is_finite() && p.q.is_finite() && p.q >= 0.0) {
                return Err(InputError::OutOfRange {
                    arg: "--axles",
                    value: format!("{} at {}", fmt_value(p.q), p.beta),
                    range: "a finite load >= 0 at a finite angle".into(),
                });
            }
        }
        for p in patches {
            let ok = p.x_lo.is_finite() && p.x_hi.is_finite() && p.x_lo < p.x_hi;
            if !(ok && p.q.is_finite() && p.q >= 0.0) {
                return Err(InputError::OutOfRange {
                    arg: "--axles",
                    value: format!("{} on [{}, {}]", fmt_value(p.q), p.x_lo, p.x_hi),
                    range: "a finite load >= 0 over a non-empty interval".into(),
                });
            }
        }
        let mut out = Pressure {
            patches: [Patch::default(); MAX_PATCHES],
            len: patches.len(),
            points: [PointLoad::default(); MAX_PATCHES],
            n_points: points.len(),
        };
        out.patches[..patches.len()].copy_from_slice(patches);
        out.points[..points.len()].copy_from_slice(points);
        Ok(out)
    }

    /// The patches.
    pub fn patches(&self) -> &[Patch] {
        &self.patches[..self.len]
    }

    /// The point loads.
    pub fn points(&self) -> &[PointLoad] {
        &self.points[..self.n_points]
    }

    /// Whether a point load sits at `beta`: the section there has two sides that differ.
    pub fn splits(&self, beta: Radians) -> bool {
        self.points().iter().any(|p| p.beta == beta)
    }

    /// The loaded extrados of `arch` at thickness `eta`, as x from its left end to its
    /// right end: the upward-facing part θ ∈ [max(β_R, 0), min(β_L, π)].
    pub fn extrados(arch: &Arch, eta: f64) -> (f64, f64) {
        let kappa = 1.0 + 0.5 * eta;
        let (br, bl) = arch.springings();
        (kappa * bl.min(PI).cos(), kappa * br.max(0.0).cos())
    }

    /// The resultant F and first moment S of the pressure on the free body [β_R, `beta`]
    /// with their first two β-derivatives; at a patch's edge the derivatives are those of
    /// the side `after` (larger β) or before, and at a point load's angle the side `after`
    /// carries it (as [`crate::load::LiveLoad::Point`]).
    pub fn resultant(
        &self,
        arch: &Arch,
        eta: f64,
        beta: Radians,
        after: bool,
    ) -> ([f64; 3], [f64; 3]) {
        let kappa = 1.0 + 0.5 * eta;
        let (lo_end, hi_end) = Pressure::extrados(arch, eta);
        let b = beta.min(PI);
        let edge = kappa * b.cos();
        let (s, c) = beta.sin_cos();
        let (mut f, mut m) = ([0.0; 3], [0.0; 3]);
        for p in self.points() {
            if beta > p.beta || (beta == p.beta && after) {
                f[0] += p.q;
                m[0] += p.q * kappa * p.beta.cos();
            }
        }
        if beta <= arch.beta_right().max(0.0) {
            return (f, m);
        }
        for p in self.patches() {
            // the patch's part on the loaded extrados, [lo, hi]
            let (lo, hi) = (p.x_lo.max(lo_end), p.x_hi.min(hi_end));
            if lo >= hi {
                continue;
            }
            let from = lo.max(edge);
            if from < hi {
                f[0] += p.q * (hi - from);
                m[0] += 0.5 * p.q * (hi * hi - from * from);
            }
            // the free body's end x = κ cos β falls through [lo, hi] as β grows: entering
            // at hi, leaving at lo
            let inside = beta < PI
                && ((lo < edge && edge < hi) || (edge == hi && after) || (edge == lo && !after));
            if inside {
                f[1] += p.q * kappa * s;
                f[2] += p.q * kappa * c;
                m[1] += p.q * kappa * kappa * s * c;
                m[2] += p.q * kappa * kappa * (c * c - s * s);
            }
        }
        (f, m)
    }

    /// The angles strictly between the springings where a patch's edge meets the
    /// extrados: the corners of the live actions, sorted.
    pub fn breaks(&self, arch: &Arch, eta: f64) -> Vec<Radians> {
        let kappa = 1.0 + 0.5 * eta;
        let (br, bl) = arch.springings();
        let mut out: Vec<Radians> = self
            .patches()
            .iter()
            .flat_map(|p| [p.x_lo, p.x_hi])
            .filter(|x| x.abs() < kappa)
            .map(|x| (x / kappa).acos())
            .chain(self.points().iter().map(|p| p.beta))
            .filter(|&t| t > br && t < bl)
            .collect();
        out.sort_by(f64::total_cmp);
        out.dedup();
        out
    }
}
