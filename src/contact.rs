//! A contact: one activation function active at one joint. The vocabulary of patterns.

use crate::arch::Radians;
use schemars::JsonSchema;
use serde::{Deserialize, Serialize};

/// Where a joint of a pattern sits.
#[derive(
    Debug, Clone, Copy, PartialEq, Eq, Hash, PartialOrd, Ord, Serialize, Deserialize, JsonSchema,
)]
#[serde(rename_all = "snake_case")]
pub enum Location {
    /// At the right or left springing (shoulder joint).
    Springing,
    /// Strictly between the springings.
    Interior,
}

impl Location {
    /// The location of joint `j` of `count` listed joints (the first and last are the
    /// springings).
    pub fn of_joint(j: usize, count: usize) -> Location {
        if j == 0 || j + 1 == count {
            Location::Springing
        } else {
            Location::Interior
        }
    }
}

/// One active activation function at one joint.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, JsonSchema)]
pub struct Contact {
    /// Joint angle (radians from the horizontal).
    pub beta: Radians,
    /// Which activation function is active.
    pub kind: ContactKind,
    /// Springing or interior joint.
    pub at: Location,
    /// True when the joint angle is an unknown (an interior joint of a continuous
    /// arch, fixed by the tangency condition dφ/dβ = 0); false for springings and
    /// for the given joints of a discrete arch.
    #[serde(skip)]
    pub free: bool,
}

/// A contact found by the scan, with its value φ at the current state.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Peak {
    /// The contact (angle, mode, location).
    pub contact: Contact,
    /// φ at that contact (≤ 0 when admissible).
    pub value: f64,
    /// (sin β, cos β) when the scan had them cached (the joints of a discrete arch), so
    /// that what follows needs no trigonometry.
    pub sin_cos: Option<(f64, f64)>,
}

/// The four activation functions of a joint (formulation §3), each ≤ 0 when admissible.
#[derive(
    Debug, Clone, Copy, PartialEq, Eq, Hash, PartialOrd, Ord, Serialize, Deserialize, JsonSchema,
)]
#[serde(rename_all = "snake_case")]
pub enum ContactKind {
    /// φ_E = M − ηN/2: hinge at the extrados (rate ϑ⁺).
    HingeExtrados,
    /// φ_I = −M − ηN/2: hinge at the intrados (rate ϑ⁻).
    HingeIntrados,
    /// φ_S+ = T − μN: sliding in the positive sense (rate s⁺).
    SlidePlus,
    /// φ_S− = −T − μN: sliding in the negative sense (rate s⁻).
    SlideMinus,
}

impl ContactKind {
    /// All four modes.
    pub const ALL: [ContactKind; 4] = [
        ContactKind::HingeExtrados,
        ContactKind::HingeIntrados,
        ContactKind::SlidePlus,
        ContactKind::SlideMinus,
    ];
    /// The hinge modes only (infinite friction).
    pub const HINGES: [ContactKind; 2] = [ContactKind::HingeExtrados, ContactKind::HingeIntrados];

    /// The modes that can activate at friction μ (no sliding when μ = ∞).
    pub fn active_at(mu: f64) -> &'static [ContactKind] {
        if mu.is_finite() {
            &Self::ALL
        } else {
            &Self::HINGES
        }
    }
    /// The name used in JSON and tables.
    pub fn name(self) -> &'static str {
        match self {
            ContactKind::HingeExtrados => "hinge_extrados",
            ContactKind::HingeIntrados => "hinge_intrados",
            ContactKind::SlidePlus => "slide_plus",
            ContactKind::SlideMinus => "slide_minus",
        }
    }
    /// True for the two hinge modes.
    pub fn is_hinge(self) -> bool {
        matches!(
            self,
            ContactKind::HingeExtrados | ContactKind::HingeIntrados
        )
    }
    /// The mode of the mirror-image contact (β ↦ π − β): hinges keep their side,
    /// sliding changes sense.
    pub fn mirrored(self) -> ContactKind {
        match self {
            ContactKind::SlidePlus => ContactKind::SlideMinus,
            ContactKind::SlideMinus => ContactKind::SlidePlus,
            m => m,
        }
    }
}
