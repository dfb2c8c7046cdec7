//! The arch being analysed: springings, joint layout and weight model, validated once.
//!
//! Lengths are divided by the mean radius r; angles are in radians, measured
//! counter-clockwise from the horizontal through the centre of the circle
//! (formulation §2). The right springing is at `beta_right`, the left at
//! `beta_left > beta_right`; a symmetric arch of opening α has β_R = −α, β_L = π + α.

use crate::fill::Fill;
use crate::input::check_finite;
pub use crate::input::{check_non_negative, check_positive, fmt_value, InputError};
use schemars::JsonSchema;
use serde::{Deserialize, Serialize};
use std::f64::consts::PI;

/// An angle in radians, counter-clockwise from the horizontal through the centre.
pub type Radians = f64;

/// How the self-weight of a piece of arch is applied (formulation §3).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize, JsonSchema)]
#[serde(rename_all = "lowercase")]
pub enum WeightModel {
    /// Uniformly along the centreline (Heyman's assumption; the default).
    Centreline,
    /// At the true centroid of each annular sector (Milankovitch): the weight
    /// moment arm is scaled by ρ = 1 + η²/12.
    Centroid,
}

impl WeightModel {
    /// The centroid factor ρ(η): 1 for the centreline model, 1 + η²/12 for the true centroid.
    pub fn rho(self, eta: f64) -> f64 {
        match self {
            WeightModel::Centreline => 1.0,
            WeightModel::Centroid => 1.0 + eta * eta / 12.0,
        }
    }

    /// dρ/dη.
    pub fn drho_deta(self, eta: f64) -> f64 {
        match self {
            WeightModel::Centreline => 0.0,
            WeightModel::Centroid => eta / 6.0,
        }
    }

    /// d²ρ/dη².
    pub fn d2rho_deta2(self, _eta: f64) -> f64 {
        match self {
            WeightModel::Centreline => 0.0,
            WeightModel::Centroid => 1.0 / 6.0,
        }
    }

    /// The name used on the command line and in JSON.
    pub fn name(self) -> &'static str {
        match self {
            WeightModel::Centreline => "centreline",
            WeightModel::Centroid => "centroid",
        }
    }
}

/// Where joints may open.
#[derive(Debug, Clone, PartialEq)]
pub enum JointLayout {
    /// Any angle in [β_R, β_L] (continuous arch).
    Continuous,
    /// Only at these angles, strictly increasing, first β_R and last β_L (given stereotomy).
    Discrete(Vec<Radians>),
}

/// A validated circular arch. Build it with [`Arch::new`] (or the helpers), which
/// rejects anything that does not describe a real arch.
#[derive(Debug, Clone, PartialEq)]
pub struct Arch {
    beta_right: Radians,
    beta_left: Radians,
    layout: JointLayout,
    weight: WeightModel,
    /// Fill above the extrados (a dead load, bridge spec §2); `None` without fill.
    fill: Option<Fill>,
    /// (sin β_R, cos β_R), computed once: every internal action needs them.
    right_trig: (f64, f64),
    /// (sin β_j, cos β_j) of each joint of a discrete arch (empty for a continuous one),
    /// computed once: every scan over the joints needs them.
    joint_trig: Vec<(f64, f64)>,
    /// (sin β, cos β) on a continuous arch's scan grid, computed at the first scan.
    scan_trig: ScanTrig,
}

/// (sin β, cos β) at the angles of the scan grid of a continuous arch ([`crate::scan`]:
/// `n` equally spaced angles from β_R to β_L), for the one `n` first asked for: filled once,
/// shared by every scan of the arch (the same bits as computing them again). A cache, not
/// part of the arch's identity: two arches are equal whatever their caches hold.
#[derive(Debug, Clone, Default)]
struct ScanTrig(std::sync::OnceLock<(usize, Vec<(f64, f64)>)>);

impl PartialEq for ScanTrig {
    fn eq(&self, _: &ScanTrig) -> bool {
        true
    }
}

/// The `i`-th of `n` equally spaced angles from `a` to `b` (the last one `b` itself): the
/// one grid every scan of a smooth piece lays out.
#[inline]
pub fn grid_angle(a: Radians, b: Radians, n: usize, i: usize) -> Radians {
    if i + 1 == n {
        b
    } else {
        a + (b - a) * i as f64 / (n - 1) as f64
    }
}

impl Arch {
    /// A continuous arch between the springings `beta_right < beta_left`, with
    /// `beta_left − beta_right ≤ 2π` (an arch cannot overlap itself).
    pub fn new(
        beta_right: Radians,
        beta_left: Radians,
        weight: WeightModel,
    ) -> Result<Arch, InputError> {
        check_finite("--beta-right", beta_right, "a finite angle in radians")?;
        check_finite("--beta-left", beta_left, "a finite angle in radians")?;
        if beta_left <= beta_right {
            return Err(InputError::Inconsistent {
                arg: "--beta-right/--beta-left",
                reason: format!(
                    "the right springing must come first: need beta_right < beta_left, got {beta_right} >= {beta_left}"
                ),
            });
        }
        if beta_left - beta_right > 2.0 * PI {
            return Err(InputError::Inconsistent {
                arg: "--beta-right/--beta-left",
                reason: format!(
                    "the arch would overlap itself: need beta_left - beta_right <= 2*pi, got {}",
                    beta_left - beta_right
                ),
            });
        }
        // + 0.0 turns a negative zero (alpha = 0) into +0.
        let beta_right = beta_right + 0.0;
        Ok(Arch {
            beta_right,
            beta_left: beta_left + 0.0,
            layout: JointLayout::Continuous,
            weight,
            fill: None,
            right_trig: beta_right.sin_cos(),
            joint_trig: Vec::new(),
            scan_trig: ScanTrig::default(),
        })
    }

    /// A continuous symmetric arch of opening `alpha` (β_R = −α, β_L = π + α),
    /// with −π/2 < α < π/2. α = 0 is the semicircle.
    pub fn symmetric(alpha: Radians, weight: WeightModel) -> Result<Arch, InputError> {
        if !(alpha.is_finite() && alpha > -PI / 2.0 && alpha < PI / 2.0) {
            return Err(InputError::OutOfRange {
                arg: "--alpha",
                value: fmt_value(alpha),
                range: "(-pi/2, pi/2) radians, i.e. (-90, 90) degrees".to_string(),
            });
        }
        Arch::new(-alpha, PI + alpha, weight)
    }

    /// The same arch under `fill` (a dead load on the extrados, held at a depth ratio
    /// h = h_c/r above its highest point); fill of zero weight is no fill, the same arch bit
    /// for bit.
    pub fn with_fill(self, fill: Fill) -> Arch {
        Arch {
            fill: (fill.weight_ratio > 0.0).then_some(fill),
            ..self
        }
    }

    /// (β_R, β_L).
    pub fn springings(&self) -> (Radians, Radians) {
        (self.beta_right, self.beta_left)
    }

    /// The fill on the extrados, if any.
    pub fn fill(&self) -> Option<&Fill> {
        self.fill.as_ref()
    }

    /// The same springings with `blocks` equal voussoirs (joints at the `blocks + 1`
    /// equally spaced angles), 1 ≤ blocks ≤ 100 000.
    pub fn with_blocks(self, blocks: usize) -> Result<Arch, InputError> {
        if !(1..=100_000).contains(&blocks) {
            return Err(InputError::OutOfRange {
                arg: "--blocks",
                value: blocks.to_string(),
                range: "whole numbers 1 to 100000".to_string(),
            });
        }
        let (a, b) = (self.beta_right, self.beta_left);
        let joints: Vec<Radians> = (0..=blocks)
            .map(|i| grid_angle(a, b, blocks + 1, i))
            .collect();
        Ok(Arch {
            joint_trig: trig_of(&joints),
            layout: JointLayout::Discrete(joints),
            ..self
        })
    }

    /// The same springings with joints at the given angles (radians). Angles must be
    /// finite, strictly increasing and inside [β_R, β_L]; the springings are added
    /// when they are not listed.
    pub fn with_joints(self, angles: &[Radians]) -> Result<Arch, InputError> {
        let (a, b) = (self.beta_right, self.beta_left);
        let mut joints = Vec::with_capacity(angles.len() + 2);
        for &beta in angles {
            if !(beta.is_finite() && beta >= a && beta <= b) {
                return Err(InputError::OutOfRange {
                    arg: "--joints",
                    value: fmt_value(beta),
                    range: format!("angles in [beta_right, beta_left] = [{a}, {b}] radians"),
                });
            }
        }
        if angles.windows(2).any(|w| w[1] <= w[0]) {
            return Err(InputError::Inconsistent {
                arg: "--joints",
                reason: "joint angles must be strictly increasing".to_string(),
            });
        }
        if angles.first() != Some(&a) {
            joints.push(a);
        }
        joints.extend_from_slice(angles);
        if angles.last() != Some(&b) {
            joints.push(b);
        }
        Ok(Arch {
            joint_trig: trig_of(&joints),
            layout: JointLayout::Discrete(joints),
            ..self
        })
    }

    /// The joint within 1e-9 rad of `beta` on a discrete arch, else `beta`: an angle given
    /// in decimal (degrees, say) that is meant as a joint rarely lands on it exactly.
    pub fn snap_to_joint(&self, beta: Radians) -> Radians {
        match &self.layout {
            JointLayout::Discrete(j) => j
                .iter()
                .copied()
                .find(|j| (j - beta).abs() <= 1e-9)
                .unwrap_or(beta),
            JointLayout::Continuous => beta,
        }
    }
    /// (sin β_j, cos β_j) of the joints of a discrete arch, in the order of its joints
    /// (empty for a continuous arch), computed once with the arch.
    #[inline]
    pub fn joint_sin_cos(&self) -> &[(f64, f64)] {
        &self.joint_trig
    }
    /// (sin β, cos β): from [`Arch::joint_sin_cos`] where `beta` is one of a discrete arch's
    /// joints (the same bits: the cache holds `sin_cos` of the same angle), else computed.
    #[inline]
    pub fn sin_cos(&self, beta: Radians) -> (f64, f64) {
        if let JointLayout::Discrete(joints) = &self.layout {
            // equal voussoirs: the index from the angle; other joints: bisection
            let (first, last, n) = (joints[0], joints[joints.len() - 1], joints.len() - 1);
            let t = (beta - first) / (last - first) * n as f64;
            if t >= 0.0 && t <= n as f64 {
                let k = (t + 0.5) as usize;
                let k = if joints[k] == beta {
                    k
                } else {
                    joints.partition_point(|&j| j < beta)
                };
                if joints.get(k) == Some(&beta) {
                    return self.joint_trig[k];
                }
            }
        }
        beta.sin_cos()
    }
    /// (sin β, cos β) at `beta` when it is an angle of the `n`-point scan grid from β_R to
    /// β_L ([`grid_angle`]), from the arch's cache (filled at the first call, for the first
    /// `n` asked for); `None` for any other angle or `n`.
    #[inline]
    pub fn scan_sin_cos(&self, n: usize, beta: Radians) -> Option<(f64, f64)> {
        let (a, b) = (self.beta_right, self.beta_left);
        let trig = self.scan_trig(n)?;
        let t = (beta - a) / (b - a) * (n - 1) as f64;
        if !(t >= 0.0 && t <= (n - 1) as f64) {
            return None;
        }
        // the nearest index (t ≥ 0: truncation of t + ½; no call to round)
        let i = ((t + 0.5) as usize).min(n - 1);
        (grid_angle(a, b, n, i) == beta).then(|| trig[i])
    }
    /// (sin β, cos β) at the `n` angles of the scan grid from β_R to β_L ([`grid_angle`]),
    /// from the arch's cache (filled at the first call, for the first `n` asked for); `None`
    /// for any other `n`.
    #[inline]
    pub fn scan_trig(&self, n: usize) -> Option<&[(f64, f64)]> {
        let (a, b) = (self.beta_right, self.beta_left);
        let (m, trig) = self.scan_trig.0.get_or_init(|| {
            (
                n,
                (0..n).map(|i| grid_angle(a, b, n, i).sin_cos()).collect(),
            )
        });
        (*m == n).then_some(&trig[..])
    }
    /// (sin β_R, cos β_R) of the right springing, computed once with the arch.
    #[inline]
    pub fn right_sin_cos(&self) -> (f64, f64) {
        self.right_trig
    }
    /// Right springing β_R.
    pub fn beta_right(&self) -> Radians {
        self.beta_right
    }
    /// Left springing β_L.
    pub fn beta_left(&self) -> Radians {
        self.beta_left
    }
    /// Angular span β_L − β_R (also the total weight in units of γ t d r).
    pub fn span(&self) -> Radians {
        self.beta_left - self.beta_right
    }
    /// Joint layout.
    pub fn layout(&self) -> &JointLayout {
        &self.layout
    }
    /// Angles at which to evaluate the arch: every joint of a discrete arch, or `n` equally
    /// spaced angles from springing to springing of a continuous one.
    pub fn angles(&self, n: usize) -> Vec<Radians> {
        match &self.layout {
            JointLayout::Discrete(j) => j.clone(),
            JointLayout::Continuous => (0..n)
                .map(|i| grid_angle(self.beta_right, self.beta_left, n, i))
                .collect(),
        }
    }
    /// Weight model.
    pub fn weight(&self) -> WeightModel {
        self.weight
    }
    /// True when the springings are mirror images about the vertical axis
    /// (β_R + β_L = π) and the joint layout is mirror-symmetric too.
    pub fn is_symmetric(&self) -> bool {
        let tol = SYMMETRY_TOL * (1.0 + self.span());
        let springs = (self.beta_right + self.beta_left - PI).abs() <= tol;
        springs
            && match &self.layout {
                JointLayout::Continuous => true,
                JointLayout::Discrete(j) => j
                    .iter()
                    .zip(j.iter().rev())
                    .all(|(a, b)| (a + b - PI).abs() <= tol),
            }
    }
    /// The mirror image about the vertical axis (β ↦ π − β).
    pub fn mirrored(&self) -> Arch {
        let layout = match &self.layout {
            JointLayout::Continuous => JointLayout::Continuous,
            JointLayout::Discrete(j) => {
                JointLayout::Discrete(j.iter().rev().map(|b| PI - b).collect())
            }
        };
        let beta_right = PI - self.beta_left;
        let joint_trig = match &layout {
            JointLayout::Continuous => Vec::new(),
            JointLayout::Discrete(j) => trig_of(j),
        };
        Arch {
            beta_right,
            beta_left: PI - self.beta_right,
            layout,
            weight: self.weight,
            fill: self.fill,
            right_trig: beta_right.sin_cos(),
            joint_trig,
            scan_trig: ScanTrig::default(),
        }
    }
}

fn trig_of(joints: &[Radians]) -> Vec<(f64, f64)> {
    joints.iter().map(|b| b.sin_cos()).collect()
}

/// Springings (and joints) mirror each other when β_R + β_L = π to within this, relative
/// to 1 + span: the opening given in degrees or as −β_R round-trips to this accuracy.
pub const SYMMETRY_TOL: f64 = 1e-12;

/// The largest thickness the solver tries: just below η = 2, where the intrados radius
/// 1 − η/2 vanishes.
pub const ETA_TOP: f64 = 2.0 * (1.0 - 1e-9);

/// Validates a thickness ratio η = t/r: finite, 0 < η < 2.
pub fn check_eta(eta: f64) -> Result<f64, InputError> {
    if eta.is_finite() && eta > 0.0 && eta < 2.0 {
        Ok(eta)
    } else {
        Err(InputError::OutOfRange {
            arg: "--eta",
            value: fmt_value(eta),
            range: "0 < eta < 2 (thickness / mean radius)".to_string(),
        })
    }
}

/// The largest finite friction coefficient accepted. Friction rows carry μ N with N up
/// to the size of the reactions, so μ must stay far from the float range's end; at this
/// friction angle (90° − 1e-200 rad) no joint can slide and the answer is that of
/// μ = ∞ (tested).
pub const MU_MAX_FINITE: f64 = 1e200;

/// Validates a friction coefficient μ: 0 < μ ≤ [`MU_MAX_FINITE`], or `f64::INFINITY`
/// (no sliding).
pub fn check_mu(mu: f64) -> Result<f64, InputError> {
    if !mu.is_nan() && mu > 0.0 && (mu <= MU_MAX_FINITE || mu == f64::INFINITY) {
        Ok(mu)
    } else {
        Err(InputError::OutOfRange {
            arg: "--mu",
            value: fmt_value(mu),
            range: "0 < mu <= 1e200, or inf (no sliding)".to_string(),
        })
    }
}
