//! The certificate format (version 1): these serde types are the schema.

pub use crate::arch::WeightModel;
pub use crate::contact::{ContactKind, Location};
pub use crate::load::Side;
use schemars::JsonSchema;
use serde::{de::Error as _, Deserialize, Deserializer, Serialize};

/// The `format` field of every certificate.
pub const FORMAT: &str = "arch-enum-certificate";
/// The current format version.
pub const VERSION: u32 = 1;

/// What the certificate claims.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize, JsonSchema)]
#[serde(rename_all = "snake_case")]
pub enum Claim {
    /// η*(μ) ∈ [η_lo, η_hi].
    LeastThickness,
    /// No thickness stands at this μ (μ < μ_ms); with a `load` section: at the load's η
    /// no state is admissible at any multiplier λ ≥ 0.
    NoEquilibrium,
    /// λ_static ∈ [λ_lo, λ_hi]: the largest admissible multiplier of the live load at
    /// (η, μ) (`load` and `multiplier` sections).
    LargestMultiplier,
    /// λ_static = ∞: admissible states exist at every λ from λ_lo on.
    UnboundedMultiplier,
    /// A state is admissible at every thickness η ∈ (0, 2): η* = 0, not attained (the line
    /// of thrust through the centre of each joint of a three-joint arch; no other section).
    StandsAtEveryThickness,
}

impl Claim {
    /// The claim's name in the certificate and in reports.
    pub fn name(self) -> &'static str {
        match self {
            Claim::LeastThickness => "least_thickness",
            Claim::NoEquilibrium => "no_equilibrium",
            Claim::LargestMultiplier => "largest_multiplier",
            Claim::UnboundedMultiplier => "unbounded_multiplier",
            Claim::StandsAtEveryThickness => "stands_at_every_thickness",
        }
    }
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
    /// Fill above the extrados up to a level road (bridge spec §2), a dead load; absent
    /// without fill.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub fill: Option<FillSpec>,
}

/// The fill of a certificate's arch: unit weight g_f = γ_f/γ and the road's height h = h_c/r
/// above the highest extrados point (non-dimensional, r = 1).
#[derive(Debug, Clone, Copy, Serialize, Deserialize)]
pub struct FillSpec {
    /// g_f ≥ 0.
    pub weight_ratio: f64,
    /// h ≥ 0.
    pub depth: f64,
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
    /// At the point load's own angle: which section, `before` or `after` the loaded
    /// point; absent elsewhere (and in thickness certificates).
    #[serde(
        default,
        skip_serializing_if = "Option::is_none",
        deserialize_with = "field_side"
    )]
    pub side: Option<Side>,
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

/// One cell of a `no_equilibrium` proof over the thickness: a Farkas certificate that no
/// state is admissible at any η in [`eta_lo`, `eta_hi`] (its multipliers, stored at the
/// cell's middle, are the signed cofactors of the rows' gradients, which depend on η).
///
/// [`eta_lo`]: FarkasCell::eta_lo
/// [`eta_hi`]: FarkasCell::eta_hi
#[derive(Debug, Clone, Serialize, Deserialize)]
pub struct FarkasCell {
    /// The cell's least thickness.
    pub eta_lo: f64,
    /// The cell's greatest thickness.
    pub eta_hi: f64,
    /// The contacts and their multipliers (at the cell's middle).
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
    /// At the point load's own angle: which section, `before` or `after` the loaded
    /// point; absent elsewhere (and in thickness certificates).
    #[serde(
        default,
        skip_serializing_if = "Option::is_none",
        deserialize_with = "field_side"
    )]
    pub side: Option<Side>,
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
    /// A discrete arch, centreline weight, finite μ: every limit state above η_s lies on
    /// the ridge over the boundary of the friction polygon Q; `ridge` lists Q's edges and
    /// the ridge's pieces along them, and `verify` re-proves that no limit state lies
    /// between the junctions of the pieces (docs/certificates.md#the-ridge).
    Ridge,
    /// A continuous arch whose discretisations did not settle: the listed limit states were
    /// found (each refined on the continuum) but the list is not claimed complete, so
    /// `unique` is `false`, resting on the listed states alone.
    Found,
}

/// The ridge over the friction polygon Q = {(h, v) : |T_j| ≤ μ N_j at every joint}: its
/// edges, each with the pieces of the ridge along it and the junctions between them.
#[derive(Debug, Clone, Serialize, Deserialize)]
pub struct RidgeEvidence {
    /// A point (h, v) strictly inside Q.
    pub inside: [f64; 2],
    /// The edges of Q, counter-clockwise: edge k runs from the meeting of the lines of
    /// edges k − 1 and k to the meeting of the lines of k and k + 1.
    pub edges: Vec<RidgeEdge>,
}

/// One edge of Q: the sliding row whose line carries it, the pieces of the ridge along it
/// (s from 0 at its first vertex to 1 at its last), and one junction per piece: the state
/// at the piece's start, with its contacts and the Farkas proof that they carry no
/// mechanism (no proof where the junction is a limit state).
#[derive(Debug, Clone, Serialize, Deserialize)]
pub struct RidgeEdge {
    /// The sliding row (`slide_plus` or `slide_minus`) active along the edge.
    pub row: PatternJoint,
    /// The pieces along the edge, in order of s.
    pub pieces: Vec<RidgePiece>,
    /// The state where each piece starts (at s = 0, then at each piece's end but the
    /// last), with the contacts that may be active around it.
    pub junctions: Vec<NoMechanism>,
}

/// A piece of the ridge: one extrados and one intrados hinge row close the band of the
/// moment's constant w, η = 2 (m_E − m_I)/(N_E + N_I).
#[derive(Debug, Clone, Serialize, Deserialize)]
pub struct RidgePiece {
    /// Where the piece ends along the edge, s in (0, 1]; the last piece ends at 1.
    pub end: f64,
    /// The joint of the extrados hinge row.
    pub extrados: f64,
    /// The joint of the intrados hinge row.
    pub intrados: f64,
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
    /// The multiplier of L_e ≥ 0 (≥ 0); under a live load, of the total power
    /// L_dead + λ L_live ≥ 0.
    pub u: f64,
    /// Under a live load: the multiplier of L_live ≥ 0 (≥ 0), so that
    /// `c_j · y + z + u P_j + v q_j ≤ 0` (P_j total and q_j live power coefficients)
    /// rules out every rate vector with B λ = 0, Σ λ = 1, total power ≥ 0 and live power
    /// ≥ 0. Absent (zero) in thickness certificates.
    #[serde(default, skip_serializing_if = "is_zero")]
    pub v: f64,
}

fn is_zero(v: &f64) -> bool {
    *v == 0.0
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

/// Evidence for the list of limit states with η in [η_s, 2).
#[derive(Debug, Clone, Serialize, Deserialize)]
pub struct SearchEvidence {
    /// `sweep`, `hinges_only`, `refined`, `ridge` or `found` (anything else is rejected
    /// when read).
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
    /// `ridge` only: the friction polygon and the ridge's pieces.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub ridge: Option<RidgeEvidence>,
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
    /// `no_equilibrium` over every thickness where the weight moves with η (true
    /// centroid): Farkas cells covering [0, 2], in order, each ending where the next begins.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub collapse_cells: Option<Vec<FarkasCell>>,
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
    /// Load claims: the thickness and the live load (absent in thickness certificates).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub load: Option<LoadSpec>,
    /// Load claims: the sides of the multiplier claim.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub multiplier: Option<MultiplierSides>,
    /// Load claims: evidence for every limit state under the load (absent where the
    /// search could not be completed).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub load_search: Option<LoadSearchEvidence>,
}

/// The kind of a live load (a closed set).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum LoadKind {
    /// A uniform horizontal body force λ·(self-weight), applied where the weight is.
    Horizontal,
    /// A vertical (downward) point load λ (units of γ t d r) at an extrados point.
    Point,
    /// A vertical pressure λ·q on the extrados: uniform patches over horizontal intervals
    /// and point loads (a vehicle spread through the fill, bridge spec §3).
    Pressure,
}

/// The sense of a horizontal body force (a closed set).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum Towards {
    /// Towards +x, the right springing.
    Right,
    /// Towards −x, the left springing.
    Left,
}

/// The load problem of a load certificate: thickness and live load (docs/loads.md).
/// Conventions: forces in γ t d r; the horizontal multiplier in units of the
/// self-weight, applied where the weight is (centreline or true centroid, `arch.weight`);
/// the point load vertical and downward at the extrados point (1 + η/2)(cos β, sin β).
/// At the point load's own angle a section has two sides: `before` (free body [β_R, β]
/// without the load) and `after` (with it); joints and contacts there carry `side`.
#[derive(Debug, Clone, Serialize, Deserialize)]
pub struct LoadSpec {
    /// Thickness ratio η at which the multiplier is sought.
    pub eta: f64,
    /// `horizontal` or `point` (anything else is rejected when read).
    #[serde(deserialize_with = "field_load_kind")]
    pub kind: LoadKind,
    /// Horizontal: `right` or `left`; absent for a point load.
    #[serde(
        default,
        skip_serializing_if = "Option::is_none",
        deserialize_with = "field_towards"
    )]
    pub towards: Option<Towards>,
    /// Point load: the angle β_P of the loaded extrados point (radians); absent for a
    /// horizontal load.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub beta: Option<f64>,
    /// Pressure: its uniform patches; absent for the other loads.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub patches: Option<Vec<PatchSpec>>,
    /// Pressure: its point loads; absent for the other loads.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub points: Option<Vec<PointSpec>>,
}

/// A patch of a pressure: q per unit horizontal length (per unit λ, in γ t d r) over
/// x_lo < x < x_hi of the extrados (x from the centre towards the right springing, r = 1).
#[derive(Debug, Clone, Copy, Serialize, Deserialize)]
pub struct PatchSpec {
    /// Left end.
    pub x_lo: f64,
    /// Right end.
    pub x_hi: f64,
    /// Intensity (≥ 0).
    pub q: f64,
}

/// A point load of a pressure: q (per unit λ) at the extrados point of angle `beta`.
#[derive(Debug, Clone, Copy, Serialize, Deserialize)]
pub struct PointSpec {
    /// Angle of the loaded extrados point (radians).
    pub beta: f64,
    /// The load (≥ 0).
    pub q: f64,
}

/// A state (x, λ) of the load problem, or a direction (d_x, d_λ).
#[derive(Debug, Clone, Serialize, Deserialize)]
pub struct LoadState {
    /// Multiplier λ (or d_λ).
    pub lambda: f64,
    /// Reactions (h, v, w) (or d_x).
    pub x: [f64; 3],
}

/// A Farkas certificate of the load problem: d + 1 contacts whose non-negative
/// combination of activation functions is independent of the unknowns and positive.
#[derive(Debug, Clone, Serialize, Deserialize)]
pub struct LoadFarkas {
    /// λ_hi (unknowns x = (h, v, w), d = 3, four joints); `null` for `no_equilibrium`
    /// (unknowns (h, v, w, λ) with λ ≥ 0, d = 4: five rows, the joints and, when used,
    /// the row −λ ≤ 0 with multiplier `lambda_row`).
    pub lambda: Option<f64>,
    /// The contacts and their multipliers.
    pub joints: Vec<CertJoint>,
    /// The multiplier of −λ ≤ 0 (`no_equilibrium` only; absent when not used).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub lambda_row: Option<f64>,
}

/// How an unbounded multiplier is carried (a closed set): the direction along which
/// every state stays admissible as λ grows.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum Transfer {
    /// The point load goes into the right springing: the reactions change by
    /// d_x = (0, 1, (1 + η/2) cos β_P − cos β_R) per unit λ, which leaves N, T, M of every
    /// section that carries the load unchanged (an identity of the statics); the sections
    /// that do not carry it (β < β_P, and β_P's `before` side) take an upward unit force
    /// at the loaded point.
    Right,
    /// The point load goes into the left springing: the reactions do not change, and only
    /// the sections that carry the load (β > β_P, and β_P's `after` side) take it.
    Left,
}

/// The sides of a load claim.
#[derive(Debug, Clone, Serialize, Deserialize)]
pub struct MultiplierSides {
    /// A state admissible at λ_lo (`largest_multiplier`: λ_static ≥ λ_lo; `unbounded_multiplier`:
    /// the start of the ray); absent for `no_equilibrium`.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub admissible: Option<LoadState>,
    /// `largest_multiplier`: no state is admissible at λ_hi; `no_equilibrium`: none at any
    /// λ ≥ 0.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub infeasible: Option<LoadFarkas>,
    /// `unbounded_multiplier`: the transfer that keeps the state admissible as λ grows
    /// (exactly one of `transfer` and `recession`).
    #[serde(
        default,
        skip_serializing_if = "Option::is_none",
        deserialize_with = "field_transfer"
    )]
    pub transfer: Option<Transfer>,
    /// `unbounded_multiplier`: a direction (d_x, d_λ), d_λ > 0, along which no activation
    /// function grows (its linear part g · d_x + a_λ d_λ ≤ 0 at every section).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub recession: Option<LoadState>,
}

/// How the list of limit states under the load was established (a closed set).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum LoadSearchMethod {
    /// A discrete arch: the sweep of P(λ) from λ_min to λ_static; `no_mechanism` lists
    /// every point it checked without a mechanism with positive live power.
    Sweep,
    /// A discrete arch beyond the sweep's budget: the face search, every vertex of the
    /// admissible (x, λ) on which a sliding row is active (docs/loads.md); `no_mechanism`
    /// lists every point it checked without a mechanism with positive live power.
    Faces,
    /// μ = ∞: the static maximum is the only limit state (virtual work: a hinge-only
    /// mechanism dissipates nothing, so a limit state at λ* admits no state at λ > λ*).
    Associative,
    /// A continuous arch at finite μ: two discretisations, refined on the continuum,
    /// agreed (not re-checked by `verify`).
    Refined,
    /// The search did not settle (a continuous arch's discretisations disagree, a discrete
    /// arch lies beyond the sweep's budget): the listed limit states were found, each is
    /// checked, but the list is not claimed complete. So `lambda` (the collapse multiplier)
    /// is `null`, λ_c is at most the least listed λ, and `unique` is `false` (not claimed).
    Found,
}

/// The end of a continuum of limit states (two contacts whose columns cancel, carrying
/// one mechanism wherever both are active).
#[derive(Debug, Clone, Serialize, Deserialize)]
pub struct ContinuumEnd {
    /// The largest λ of the continuum (`null`: unbounded).
    pub to: Option<f64>,
}

/// A limit state under the load (consistency-checked, not proved).
#[derive(Debug, Clone, Serialize, Deserialize)]
pub struct LoadLimitStateCert {
    /// The multiplier.
    pub lambda: f64,
    /// Reactions.
    pub x: [f64; 3],
    /// Every contact active there, strictly increasing in (β, side, kind).
    pub pattern: Vec<PatternJoint>,
    /// Mechanism rates, one per pattern joint (zero for a sliding sense left out).
    pub rates: Vec<f64>,
    /// The live load's power in the mechanism (> 0).
    pub live_power: f64,
    /// Present when this is the least state of a continuum of limit states.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub continuum: Option<ContinuumEnd>,
}

/// A state under the load whose active contacts carry no mechanism with positive live
/// power, with the proof.
#[derive(Debug, Clone, Serialize, Deserialize)]
pub struct LoadNoMechanism {
    /// The multiplier.
    pub lambda: f64,
    /// Reactions.
    pub x: [f64; 3],
    /// Every contact active there, strictly increasing in (β, side, kind).
    pub pattern: Vec<PatternJoint>,
    /// Farkas certificates covering every one-sense choice of the pattern.
    pub farkas: Vec<KinematicFarkas>,
}

/// Evidence for the list of limit states under the load.
#[derive(Debug, Clone, Serialize, Deserialize)]
pub struct LoadSearchEvidence {
    /// `sweep`, `associative`, `refined` or `found` (anything else is rejected when read).
    #[serde(deserialize_with = "field_load_method")]
    pub method: LoadSearchMethod,
    /// Events of the sweep.
    pub events: usize,
    /// The least admissible multiplier (reported, not proved; where it is positive the
    /// state there is the unloading end, never a collapse).
    pub lambda_min: f64,
    /// Whether the state at λ_static carries a mechanism with positive live power.
    pub mechanism_at_static: bool,
    /// Whether exactly one limit state exists (a continuum is not unique).
    pub unique: bool,
    /// The collapse multiplier: the least listed limit state's λ (`null`: none).
    pub lambda: Option<f64>,
    /// Every limit state, ascending in λ (the one at λ_static included).
    pub limit_states: Vec<LoadLimitStateCert>,
    /// The state at λ_static and the proof that its active contacts carry no mechanism
    /// (present when `mechanism_at_static` is false and λ_static is finite).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub static_state: Option<LoadNoMechanism>,
    /// `sweep` only: every point checked without a mechanism, with its proof.
    pub no_mechanism: Vec<LoadNoMechanism>,
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

fn field_side<'de, D: Deserializer<'de>>(d: D) -> Result<Option<Side>, D::Error> {
    named(d, "side")
}

fn field_load_kind<'de, D: Deserializer<'de>>(d: D) -> Result<LoadKind, D::Error> {
    named(d, "load.kind")
}

fn field_towards<'de, D: Deserializer<'de>>(d: D) -> Result<Option<Towards>, D::Error> {
    named(d, "load.towards")
}

fn field_transfer<'de, D: Deserializer<'de>>(d: D) -> Result<Option<Transfer>, D::Error> {
    named(d, "multiplier.transfer")
}

fn field_load_method<'de, D: Deserializer<'de>>(d: D) -> Result<LoadSearchMethod, D::Error> {
    named(d, "load_search.method")
}

impl Certificate {
    /// The claimed bracket (η_lo, η_hi) of a least-thickness claim.
    pub fn bracket(&self) -> Option<(f64, f64)> {
        match self.claim {
            Claim::LeastThickness => Some((self.collapse.as_ref()?.eta?, self.safe.as_ref()?.eta)),
            _ => None,
        }
    }

    /// The claimed bracket (λ_lo, λ_hi) of a largest-multiplier claim.
    pub fn lambda_bracket(&self) -> Option<(f64, f64)> {
        let m = self.multiplier.as_ref()?;
        match self.claim {
            Claim::LargestMultiplier => Some((
                m.admissible.as_ref()?.lambda,
                m.infeasible.as_ref()?.lambda?,
            )),
            _ => None,
        }
    }

    /// Whether the certificate delivers a requested relative gap: a least-thickness claim
    /// when (η_hi − η_lo)/η_hi ≤ `requested` as computed in floating point, a
    /// largest-multiplier claim when λ_hi − λ_lo ≤ `requested` λ_hi; a no-equilibrium,
    /// unbounded-multiplier or stands-at-every-thickness claim always (it has no gap).
    pub fn delivers_gap(&self, requested: f64) -> bool {
        match self.claim {
            Claim::NoEquilibrium | Claim::UnboundedMultiplier | Claim::StandsAtEveryThickness => {
                true
            }
            Claim::LeastThickness => self
                .bracket()
                .is_some_and(|(lo, hi)| (hi - lo) / hi <= requested),
            Claim::LargestMultiplier => self
                .lambda_bracket()
                .is_some_and(|(lo, hi)| hi - lo <= requested * hi),
        }
    }
}
