//! What every JSON document shares: the version, the arch, the status word, the error
//! document.

use crate::arch::{Arch, JointLayout};
use crate::limit::Outcome;
use schemars::JsonSchema;
use serde::Serialize;

/// The `version` of every JSON document the command line prints: bumped on a breaking
/// change of any shape (2: `version`/`status` everywhere, `pattern` for every joint list).
pub const JSON_VERSION: u32 = 2;

/// The arch a document answers for.
#[derive(Debug, Serialize, JsonSchema)]
#[schemars(rename = "ArchInfo")]
pub struct ArchJson {
    /// The right springing β_R (radians).
    beta_right: f64,
    /// The left springing β_L (radians).
    beta_left: f64,
    /// `centreline` (Heyman's weight) or `centroid` (the true centroid).
    weight: &'static str,
    /// `continuous` (a joint at every section) or `discrete` (voussoirs).
    joints: &'static str,
    /// The joint angles of a discrete arch, springings included (absent when continuous).
    #[serde(skip_serializing_if = "Option::is_none")]
    joint_angles: Option<Vec<f64>>,
    /// Whether the arch (springings and joints) is mirror-symmetric.
    symmetric: bool,
}

impl ArchJson {
    /// Describes `arch`.
    pub fn new(arch: &Arch) -> ArchJson {
        let (joints, joint_angles) = match arch.layout() {
            JointLayout::Continuous => ("continuous", None),
            JointLayout::Discrete(j) => ("discrete", Some(j.clone())),
        };
        ArchJson {
            beta_right: arch.beta_right(),
            beta_left: arch.beta_left(),
            weight: arch.weight().name(),
            joints,
            joint_angles,
            symmetric: arch.is_symmetric(),
        }
    }
}

/// The document printed for bad input under `--json`.
#[derive(Debug, Serialize, JsonSchema)]
#[schemars(rename = "ErrorDocument")]
pub struct ErrorJson {
    version: u32,
    /// Always `"error"`.
    status: &'static str,
    /// The message naming the argument and its valid range.
    message: String,
}

impl ErrorJson {
    /// The error document for `message`.
    pub fn new(message: String) -> ErrorJson {
        ErrorJson {
            version: JSON_VERSION,
            status: "error",
            message,
        }
    }
}

/// The status word of an outcome.
pub fn status(outcome: &Outcome) -> &'static str {
    match outcome {
        Outcome::Limit(_) => "ok",
        Outcome::NoEquilibrium { .. } => "no_equilibrium",
        Outcome::Unresolved { .. } => "unresolved",
        Outcome::NoCollapse { .. } => "no_collapse",
    }
}
