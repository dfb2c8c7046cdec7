//! The certificate format (version 1): these serde types are the schema.

pub use crate::arch::WeightModel;
pub use crate::contact::{ContactKind, Location};
use serde::{de::Error as _, Deserialize, Deserializer, Serialize};

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
    /// `centreline` or `centroid` (anything else is rejected when read).
    #[serde(deserialize_with = "field_weight")]
    pub weight: WeightModel,
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
    /// `hinge_extrados`, `hinge_intrados`, `slide_plus` or `slide_minus` (anything else
    /// is rejected when read).
    #[serde(deserialize_with = "field_kind")]
    pub kind: ContactKind,
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
    /// Activation function (`hinge_extrados`, `hinge_intrados`, `slide_plus`,
    /// `slide_minus`).
    #[serde(deserialize_with = "field_kind")]
    pub kind: ContactKind,
    /// `springing` or `interior`.
    #[serde(deserialize_with = "field_at")]
    pub at: Location,
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

/// How the limit-state search established its list (a closed set).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum SearchMethod {
    /// A discrete arch: the sweep of the admissible polytope P(η) in η; `no_mechanism`
    /// lists every point it checked without finding a mechanism.
    Sweep,
    /// μ = ∞: every mechanism is made of hinges, and the safe state strictly inside P(η_hi)
    /// rules out every limit state at η ≥ η_hi (virtual work, formulation §6).
    HingesOnly,
    /// A continuous arch: the limit states of two discretisations (J and 2J pieces),
    /// refined on the continuum, agreed (not re-checked by `verify`).
    Refined,
}

/// The Farkas alternative of the kinematic LP on a pattern: with c_j the compatibility
/// column and p_j the external power coefficient of the kept contacts,
/// `c_j · y + z + u p_j ≤ 0` for every kept j, z > 0, u ≥ 0 proves that no rates λ ≥ 0,
/// Σ λ = 1, B λ = 0, L_e ≥ 0 exist on them.
#[derive(Debug, Clone, Serialize, Deserialize)]
pub struct KinematicFarkas {
    /// Indices (into the pattern) of contacts left out: one sliding sense of a joint where
    /// both are active (a joint slides one way only). Empty: the whole pattern.
    pub drop: Vec<usize>,
    /// The multipliers of B λ = 0.
    pub y: [f64; 3],
    /// The multiplier of Σ λ = 1 (> 0).
    pub z: f64,
    /// The multiplier of L_e ≥ 0 (≥ 0).
    pub u: f64,
}

/// A state whose active contacts carry no mechanism, with the proof.
#[derive(Debug, Clone, Serialize, Deserialize)]
pub struct NoMechanism {
    /// Thickness ratio.
    pub eta: f64,
    /// Reactions.
    pub x: [f64; 3],
    /// Every contact active there, strictly increasing in (β, kind).
    pub pattern: Vec<PatternJoint>,
    /// Farkas certificates covering every one-sense choice of the pattern.
    pub farkas: Vec<KinematicFarkas>,
}

/// Evidence for the list of limit states with η in [η_s, 2) (issue 10).
#[derive(Debug, Clone, Serialize, Deserialize)]
pub struct SearchEvidence {
    /// `sweep`, `hinges_only` or `refined` (anything else is rejected when read).
    #[serde(deserialize_with = "field_method")]
    pub method: SearchMethod,
    /// Events of the sweep.
    pub events: usize,
    /// Whether the least admissible state (at η_s) carries a mechanism.
    pub mechanism_at_eta: bool,
    /// Whether exactly one limit state exists with η in [η_s, 2).
    pub unique: bool,
    /// The least admissible state and the proof that its active contacts carry no
    /// mechanism (present when `mechanism_at_eta` is false and η_s is attained).
    pub least_state: Option<NoMechanism>,
    /// Every limit state above η_s, ascending in η.
    pub limit_states_above: Vec<LimitStateCert>,
    /// `sweep` only: every point checked without a mechanism, with its proof.
    pub no_mechanism: Vec<NoMechanism>,
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
    /// Evidence for every limit state with η in [η_s, 2) (absent in older certificates
    /// and where the search could not be completed).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub search: Option<SearchEvidence>,
}

/// Why no certificate could be produced (a result, not bad input).
#[derive(Debug, Clone, PartialEq)]
pub struct NotCertified(pub String);

/// Reads a closed-set field, naming the field in the error: serde's own message names the
/// unknown value and the expected ones, and serde_json appends the line and column.
fn named<'de, D: Deserializer<'de>, T: Deserialize<'de>>(d: D, field: &str) -> Result<T, D::Error> {
    T::deserialize(d).map_err(|e| D::Error::custom(format_args!("field `{field}`: {e}")))
}

fn field_kind<'de, D: Deserializer<'de>>(d: D) -> Result<ContactKind, D::Error> {
    named(d, "kind")
}

fn field_at<'de, D: Deserializer<'de>>(d: D) -> Result<Location, D::Error> {
    named(d, "at")
}

fn field_method<'de, D: Deserializer<'de>>(d: D) -> Result<SearchMethod, D::Error> {
    named(d, "method")
}

fn field_weight<'de, D: Deserializer<'de>>(d: D) -> Result<WeightModel, D::Error> {
    named(d, "weight")
}

impl Certificate {
    /// The claimed bracket (η_lo, η_hi) of a least-thickness claim.
    pub fn bracket(&self) -> Option<(f64, f64)> {
        match self.claim {
            Claim::LeastThickness => Some((self.collapse.as_ref()?.eta?, self.safe.as_ref()?.eta)),
            Claim::NoEquilibrium => None,
        }
    }

    /// Whether the certificate delivers a requested relative gap: a least-thickness claim
    /// when (η_hi − η_lo)/η_hi ≤ `requested` as computed in floating point; a
    /// no-equilibrium claim always (it has no gap).
    pub fn delivers_gap(&self, requested: f64) -> bool {
        match self.claim {
            Claim::NoEquilibrium => true,
            Claim::LeastThickness => self
                .bracket()
                .is_some_and(|(lo, hi)| (hi - lo) / hi <= requested),
        }
    }
}
