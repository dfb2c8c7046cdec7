//! Collapse-mode names, derived from the active pattern alone by documented rules
//! (never from the opening or μ).
//!
//! Let the *middle* of the arch be β_m = (β_R + β_L)/2 and call a joint *detached*
//! when both hinge functions are active there (N = 0, formulation §3). Then, in order:
//! 1. no sliding contact: `overturning` if some joint is detached, else `purely_rotational`;
//! 2. no hinge contact: `purely_sliding`;
//! 3. a springing carries a hinge and a sliding contact: `rotational_sliding_shoulders`;
//! 4. the contact farthest from β_m is a sliding joint (sliding at the shoulders, every
//!    hinge nearer the crown): `mixed_sliding_rotational`;
//! 5. the contact farthest from β_m is a hinge (rotation at the shoulders, every sliding
//!    joint nearer the crown, whether or not a hinge also lies inside them):
//!    `mixed_rotational_sliding`;
//! 6. when a hinge and a sliding contact are equally far out (e.g. one springing hinges,
//!    the other slides), the innermost contact decides: a hinge (rotation at the crown)
//!    gives `mixed_sliding_rotational`, a sliding joint `mixed_rotational_sliding`;
//! 7. otherwise (a hinge and a sliding contact share the innermost joint as well)
//!    `mixed_interleaved`, a descriptive name outside the contract's list.
//!
//! Rules 4 and 5 read a mixed mode from the shoulders inwards, as the founding paper
//! names its branches: the upper branch of α_s = 1.15, with hinges at the springings, a
//! hinge at the crown and sliding joints just beside it, is rotational–sliding there.

use crate::contact::{Contact, Location};
use schemars::JsonSchema;
use serde::Serialize;

/// The collapse mode of a pattern.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Serialize, JsonSchema)]
#[serde(rename_all = "snake_case")]
pub enum CollapseMode {
    /// Hinges only (Couplet–Heyman).
    PurelyRotational,
    /// Hinges and sliding, with sliding at the shoulders and rotation nearer the crown.
    MixedSlidingRotational,
    /// Hinges and sliding, with rotation at the shoulders and sliding nearer the crown.
    MixedRotationalSliding,
    /// Rotation and sliding together at a springing.
    RotationalSlidingShoulders,
    /// Sliding only.
    PurelySliding,
    /// Hinges only, with complete separation (N = 0) at some joint.
    Overturning,
    /// Hinges and sliding interleaved in a way none of the names above fits.
    MixedInterleaved,
}

impl CollapseMode {
    /// Every mode, in the order of the declaration.
    pub const ALL: [CollapseMode; 7] = [
        CollapseMode::PurelyRotational,
        CollapseMode::MixedSlidingRotational,
        CollapseMode::MixedRotationalSliding,
        CollapseMode::RotationalSlidingShoulders,
        CollapseMode::PurelySliding,
        CollapseMode::Overturning,
        CollapseMode::MixedInterleaved,
    ];

    /// The name used in JSON and tables.
    pub fn name(self) -> &'static str {
        match self {
            CollapseMode::PurelyRotational => "purely_rotational",
            CollapseMode::MixedSlidingRotational => "mixed_sliding_rotational",
            CollapseMode::MixedRotationalSliding => "mixed_rotational_sliding",
            CollapseMode::RotationalSlidingShoulders => "rotational_sliding_shoulders",
            CollapseMode::PurelySliding => "purely_sliding",
            CollapseMode::Overturning => "overturning",
            CollapseMode::MixedInterleaved => "mixed_interleaved",
        }
    }
    /// True for the names fixed by the command-line contract.
    pub fn is_standard(self) -> bool {
        self != CollapseMode::MixedInterleaved
    }
}

/// Names the mode of `pattern` (see the module documentation for the rules).
/// `same_joint` is the angle tolerance under which two contacts share a joint.
pub fn classify(pattern: &[Contact], beta_mid: f64, same_joint: f64) -> CollapseMode {
    let hinges: Vec<&Contact> = pattern.iter().filter(|c| c.kind.is_hinge()).collect();
    let slides: Vec<&Contact> = pattern.iter().filter(|c| !c.kind.is_hinge()).collect();
    let detached = hinges.iter().any(|a| {
        hinges
            .iter()
            .any(|b| a.kind != b.kind && (a.beta - b.beta).abs() <= same_joint)
    });
    if slides.is_empty() {
        return if detached {
            CollapseMode::Overturning
        } else {
            CollapseMode::PurelyRotational
        };
    }
    if hinges.is_empty() {
        return CollapseMode::PurelySliding;
    }
    let shoulder_both = hinges.iter().any(|h| {
        h.at == Location::Springing
            && slides
                .iter()
                .any(|s| s.at == Location::Springing && (s.beta - h.beta).abs() <= same_joint)
    });
    if shoulder_both {
        return CollapseMode::RotationalSlidingShoulders;
    }
    let dist = |c: &&Contact| (c.beta - beta_mid).abs();
    let hinge_out = hinges.iter().map(dist).fold(0.0, f64::max);
    let slide_out = slides.iter().map(dist).fold(0.0, f64::max);
    let hinge_in = hinges.iter().map(dist).fold(f64::INFINITY, f64::min);
    let slide_in = slides.iter().map(dist).fold(f64::INFINITY, f64::min);
    if slide_out > hinge_out + same_joint {
        CollapseMode::MixedSlidingRotational
    } else if hinge_out > slide_out + same_joint {
        CollapseMode::MixedRotationalSliding
    } else if hinge_in < slide_in - same_joint {
        CollapseMode::MixedSlidingRotational
    } else if slide_in < hinge_in - same_joint {
        CollapseMode::MixedRotationalSliding
    } else {
        CollapseMode::MixedInterleaved
    }
}
