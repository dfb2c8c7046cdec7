//! What every JSON document shares: the version, the arch, the status word, the error
//! document.

use crate::arch::{Arch, JointLayout};
use crate::limit::Outcome;
use schemars::JsonSchema;
use serde::Serialize;

/// The `version` of every JSON document the command line prints: bumped on a breaking
/// change of any shape (2: `version`/`status` everywhere, `pattern` for every joint list).
pub const JSON_VERSION: u32 = 2;

/// The arch as described in every JSON document.
#[derive(Debug, Serialize, JsonSchema)]
#[schemars(rename = "ArchInfo")]
pub struct ArchJson {
    beta_right: f64,
    beta_left: f64,
    weight: &'static str,
    joints: &'static str,
    #[serde(skip_serializing_if = "Option::is_none")]
    joint_angles: Option<Vec<f64>>,
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
