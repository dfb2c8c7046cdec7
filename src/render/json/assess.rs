//! The `assess --json` document (`null` stands for +∞ where noted).

use super::common::{ArchJson, JSON_VERSION};
use crate::arch::Arch;
use crate::contact::Contact;
use crate::limit::Outcome;
use schemars::JsonSchema;
use serde::Serialize;

/// The admissible state of largest margin: the reactions h, v, w and the margin.
#[derive(Debug, Serialize, JsonSchema)]
#[schemars(rename = "SafestState")]
struct SafestJson {
    /// Horizontal reaction.
    h: f64,
    /// Vertical reaction.
    v: f64,
    /// Moment reaction.
    w: f64,
    /// Its margin: the least distance of any contact from activation, relative.
    margin: f64,
}

/// A given thickness η at a given friction μ (`assess`): whether it stands, η*(μ) (`eta_min`),
/// the geometric factor η / η*, the least friction μ_min(η) at which it stands and the friction
/// factor μ / μ_min, the collapse mode of η*(μ) and the safest state. Factors are `null` when
/// they do not exist or are infinite.
#[derive(Debug, Serialize, JsonSchema)]
#[schemars(rename = "AssessResult")]
pub struct AssessJson {
    /// The document format's version (2).
    version: u32,
    /// `ok`, or why η*(μ) is missing (`no_equilibrium`, `unresolved`, ...).
    status: &'static str,
    /// The arch.
    arch: ArchJson,
    /// The thickness ratio assessed.
    eta: f64,
    /// η*(μ) (`null` when nothing stands at μ or η* is unresolved; 0 when every η stands).
    eta_min: Option<f64>,
    /// Whether the arch stands at (η, μ).
    stands: bool,
    /// η / η*(μ) (`null`: none, or infinite when every η stands).
    geometric_factor: Option<f64>,
    /// μ (`null` = ∞).
    #[schemars(extend("x-null" = "infinity"))]
    mu: Option<f64>,
    /// μ_min(η), the least friction at which η stands (`null` when none does).
    mu_min: Option<f64>,
    /// Whether `mu_min` is exact (Newton on the active pattern, verified) or an LP bound.
    mu_min_exact: Option<bool>,
    /// The active pattern of the state at μ_min.
    mu_min_pattern: Vec<Contact>,
    /// μ / μ_min (`null` when μ_min does not exist or the factor is infinite).
    friction_factor: Option<f64>,
    /// The collapse mode of η*(μ).
    mode: Option<&'static str>,
    /// The admissible state of largest margin, when the arch stands.
    safest_state: Option<SafestJson>,
    /// Why η*(μ) is missing, when it is.
    #[serde(skip_serializing_if = "Option::is_none")]
    message: Option<String>,
    /// The fill (absent without fill).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub fill: Option<super::bridge::FillJson>,
}

fn finite(v: f64) -> Option<f64> {
    v.is_finite().then_some(v)
}

/// Builds the `assess --json` document.
pub fn assess(arch: &Arch, a: &crate::assess::Assessment) -> AssessJson {
    use crate::assess::LeastFriction;
    let (mu_min, mu_min_exact, mu_min_pattern) = match &a.least_friction {
        LeastFriction::Finite { mu, pattern, exact } => {
            (finite(*mu), Some(*exact), pattern.clone())
        }
        LeastFriction::Never => (None, None, Vec::new()),
    };
    let (eta_min, message) = match &a.limit {
        Outcome::Limit(ls) => (Some(ls.eta), None),
        Outcome::NoCollapse { reason } => (Some(0.0), Some(reason.clone())),
        Outcome::NoEquilibrium { reason, .. } | Outcome::Unresolved { reason, .. } => {
            (None, Some(reason.clone()))
        }
    };
    AssessJson {
        version: JSON_VERSION,
        status: match &a.limit {
            Outcome::Unresolved { .. } => "unresolved",
            _ => "ok",
        },
        arch: ArchJson::new(arch),
        eta: a.eta,
        eta_min,
        stands: a.stands,
        geometric_factor: a.geometric_factor.and_then(finite),
        mu: finite(a.mu),
        mu_min,
        mu_min_exact,
        mu_min_pattern,
        friction_factor: a.friction_factor.and_then(finite),
        mode: a.mode.map(|m| m.name()),
        safest_state: a.safest.as_ref().map(|s| SafestJson {
            h: s.x[0],
            v: s.x[1],
            w: s.x[2],
            margin: s.margin,
        }),
        message,
        fill: None,
    }
}
