//! The certificate format (version 1): these serde types are the schema.

use serde::{Deserialize, Serialize};

/// The `format` field of every certificate.
pub const FORMAT: &str = "arch-enum-certificate";
/// The current format version.
pub const VERSION: u32 = 1;

/// What the certificate claims.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum Claim {
    /// η*(μ) ∈ [η_lo, η_hi].
    LeastThickness,
    /// No thickness stands at this μ (μ < μ_ms).
    NoEquilibrium,
}

/// The arch of a certificate.
#[derive(Debug, Clone, Serialize, Deserialize)]
pub struct ArchSpec {
    /// Right springing (radians).
    pub beta_right: f64,
    /// Left springing (radians).
    pub beta_left: f64,
    /// `centreline` or `centroid`.
    pub weight: String,
    /// The joints of a discrete arch; `null` for a continuous one.
    pub joint_angles: Option<Vec<f64>>,
}

/// The upper-bound side: an admissible state at η_hi.
#[derive(Debug, Clone, Serialize, Deserialize)]
pub struct SafeSide {
    /// η_hi.
    pub eta: f64,
    /// Reactions (h, v, w).
    pub x: [f64; 3],
}

/// One contact of a Farkas certificate.
#[derive(Debug, Clone, Serialize, Deserialize)]
pub struct CertJoint {
    /// Joint angle (radians).
    pub beta: f64,
    /// `hinge_extrados`, `hinge_intrados`, `slide_plus` or `slide_minus`.
    pub kind: String,
    /// Non-negative multiplier (normalised to sum 1).
    pub y: f64,
}

/// The lower-bound side: a Farkas certificate of infeasibility.
#[derive(Debug, Clone, Serialize, Deserialize)]
pub struct Farkas {
    /// η_lo (`null` for the friction-only problem, where η does not enter).
    pub eta: Option<f64>,
    /// The contacts and their multipliers.
    pub joints: Vec<CertJoint>,
}

/// A joint of the limit state's pattern.
#[derive(Debug, Clone, Serialize, Deserialize)]
pub struct PatternJoint {
    /// Joint angle.
    pub beta: f64,
    /// Activation function.
    pub kind: String,
    /// `springing` or `interior`.
    pub at: String,
}

/// The limit state (consistency-checked, not proved).
#[derive(Debug, Clone, Serialize, Deserialize)]
pub struct LimitStateCert {
    /// η*.
    pub eta: f64,
    /// Reactions.
    pub x: [f64; 3],
    /// Active pattern.
    pub pattern: Vec<PatternJoint>,
    /// Mechanism rates, one per pattern joint.
    pub rates: Vec<f64>,
    /// Σ |φ_i| λ_i at the limit state.
    pub complementarity_residual: f64,
}

/// A certificate (format version 1).
#[derive(Debug, Clone, Serialize, Deserialize)]
pub struct Certificate {
    /// Always [`FORMAT`].
    pub format: String,
    /// Always [`VERSION`] for this format.
    pub version: u32,
    /// Producer.
    pub tool: String,
    /// The arch.
    pub arch: ArchSpec,
    /// μ (`null` = ∞).
    pub mu: Option<f64>,
    /// The claim.
    pub claim: Claim,
    /// Upper-bound side (least-thickness claims).
    pub safe: Option<SafeSide>,
    /// Lower-bound side.
    pub collapse: Option<Farkas>,
    /// The limit state.
    pub limit_state: Option<LimitStateCert>,
    /// η_hi − η_lo.
    pub gap: Option<f64>,
    /// (η_hi − η_lo)/η_hi.
    pub gap_relative: Option<f64>,
}

/// Why no certificate could be produced (a result, not bad input).
#[derive(Debug, Clone, PartialEq)]
pub struct NotCertified(pub String);
