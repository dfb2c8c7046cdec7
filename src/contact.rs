//! A contact: one activation function active at one joint. The vocabulary of patterns.

use crate::arch::Radians;
use crate::statics::JointMode;
use serde::Serialize;

/// Where a joint of a pattern sits.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, PartialOrd, Ord, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum Location {
    /// At the right or left springing (shoulder joint).
    Springing,
    /// Strictly between the springings.
    Interior,
}

/// One active activation function at one joint.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct Contact {
    /// Joint angle (radians from the horizontal).
    pub beta: Radians,
    /// Which activation function is active.
    #[serde(rename = "kind")]
    pub mode: JointMode,
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
}
