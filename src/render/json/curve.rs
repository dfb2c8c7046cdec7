//! The `curve --json` document.

use super::bridge::FillJson;
use super::common::{status, ArchJson, JSON_VERSION};
use crate::arch::Arch;
use crate::contact::Contact;
use crate::limit::Outcome;
use crate::limit_curve::CurvePoint;
use schemars::JsonSchema;
use serde::Serialize;

/// η*(μ) at one friction coefficient.
#[derive(Debug, Serialize, JsonSchema)]
#[schemars(rename = "CurvePoint")]
struct CurveRow {
    /// The friction coefficient (`null`: ∞).
    mu: f64,
    /// atan μ in degrees.
    friction_angle_deg: f64,
    /// `ok`, `no_equilibrium`, `unresolved` or `no_collapse`.
    status: &'static str,
    /// η*(μ) (absent unless `ok`).
    eta: Option<f64>,
    /// The collapse mode.
    mode: Option<&'static str>,
    /// The active contacts of the least limit state.
    pattern: Option<Vec<Contact>>,
    /// Why there is no answer.
    #[serde(skip_serializing_if = "Option::is_none")]
    message: Option<String>,
}

/// η*(μ) sampled at the given friction coefficients (`curve`): one point per μ, in the order
/// given.
#[derive(Debug, Serialize, JsonSchema)]
#[schemars(rename = "CurveResult")]
pub struct CurveJson {
    /// The document format's version (2).
    version: u32,
    /// `ok`.
    status: &'static str,
    /// The arch.
    arch: ArchJson,
    /// μ_ms, the least friction at which some thickness stands.
    mu_ms: Option<f64>,
    /// The fill, as given (absent without fill).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub fill: Option<FillJson>,
    /// One point per μ, in the order given.
    points: Vec<CurveRow>,
}

/// Builds the `curve --json` document. `mu_ms` is the least friction admitting
/// equilibrium (`None` when no finite μ does).
pub fn curve(arch: &Arch, mu_ms: Option<f64>, points: &[CurvePoint]) -> CurveJson {
    CurveJson {
        version: JSON_VERSION,
        status: "ok",
        arch: ArchJson::new(arch),
        mu_ms,
        fill: None,
        points: points
            .iter()
            .map(|p| {
                let (eta, mode, pattern, message) = match &p.outcome {
                    Outcome::Limit(ls) => (
                        Some(ls.eta),
                        Some(ls.mode.name()),
                        Some(ls.pattern.clone()),
                        None,
                    ),
                    Outcome::NoEquilibrium { reason, .. }
                    | Outcome::Unresolved { reason, .. }
                    | Outcome::NoCollapse { reason } => (None, None, None, Some(reason.clone())),
                };
                CurveRow {
                    mu: p.mu,
                    friction_angle_deg: p.mu.atan().to_degrees(),
                    status: status(&p.outcome),
                    eta,
                    mode,
                    pattern,
                    message,
                }
            })
            .collect(),
    }
}
