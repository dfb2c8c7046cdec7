//! The `modes --json` document (`null` stands for +∞).

use super::common::{ArchJson, JSON_VERSION};
use crate::arch::Arch;
use crate::contact::Contact;
use crate::limit_curve::CurveStatus;
use schemars::JsonSchema;
use serde::Serialize;

#[derive(Debug, Serialize, JsonSchema)]
#[schemars(rename = "Branch")]
struct BranchJson {
    mode: &'static str,
    mode_standard: bool,
    mu_min: f64,
    mu_max: f64,
    eta_min: f64,
    eta_max: f64,
    pattern: Vec<Contact>,
}

#[derive(Debug, Serialize, JsonSchema)]
#[schemars(rename = "Corner")]
struct CornerJson {
    mu: f64,
    friction_angle_deg: f64,
    eta: f64,
    /// True for a corner (the slopes differ), false for a smooth transition.
    kink: bool,
    /// dη_s/dμ on the side of smaller μ (`null`: the vertical purely-sliding branch at
    /// μ_ms, or undefined at μ = ∞).
    slope_left: f64,
    /// dη_s/dμ on the side of larger μ (`null` at μ = ∞).
    slope_right: f64,
    pattern: Vec<Contact>,
    between: [&'static str; 2],
    mode: &'static str,
    exact: bool,
    residual: f64,
}

#[derive(Debug, Serialize, JsonSchema)]
#[schemars(rename = "LimitBranch")]
struct LimitBranchJson {
    #[serde(flatten)]
    branch: BranchJson,
    samples: usize,
}

fn branch(b: &crate::limit_curve::Branch) -> BranchJson {
    BranchJson {
        mode: b.mode.name(),
        mode_standard: b.mode.is_standard(),
        mu_min: b.mu_min,
        mu_max: b.mu_max,
        eta_min: b.eta_min,
        eta_max: b.eta_max,
        pattern: b.pattern.clone(),
    }
}

#[derive(Debug, Serialize, JsonSchema)]
#[schemars(rename = "ThicknessLimit")]
struct ThicknessLimitJson {
    mu: f64,
    eta: f64,
    pattern: Vec<Contact>,
    exact: bool,
}

#[derive(Debug, Serialize, JsonSchema)]
#[schemars(rename = "Unresolved")]
struct UnresolvedJson {
    mu: f64,
    message: String,
}

/// The `modes --json` document (`null` stands for +∞).
#[derive(Debug, Serialize, JsonSchema)]
#[schemars(rename = "ModesResult")]
pub struct ModesJson {
    version: u32,
    status: &'static str,
    arch: ArchJson,
    branches: Vec<BranchJson>,
    /// Kinks of η_s(μ).
    corners: Vec<CornerJson>,
    /// Smooth pattern changes of η_s(μ).
    transitions: Vec<CornerJson>,
    /// Limit states above the boundary, by samples.
    limit_branches: Vec<LimitBranchJson>,
    /// Where the boundary reaches the thickness limit η → 2 above μ_ms (then no
    /// purely-sliding corner, and `mu_min` is this μ), else `null`.
    thickness_limit: Option<ThicknessLimitJson>,
    /// The least friction at which the arch stands at some thickness (μ_ms); the same
    /// value as `mu_ms`, under the name the contract gives it.
    mu_min: Option<f64>,
    /// μ_ms.
    mu_ms: Option<f64>,
    unresolved: Vec<UnresolvedJson>,
    /// Sampled μ at which the arch stands at every thickness (no collapse).
    no_collapse: Vec<f64>,
    /// Sampled μ at which no thickness stands.
    no_equilibrium: Vec<f64>,
}

fn corner(c: &crate::limit_curve::Corner) -> CornerJson {
    CornerJson {
        mu: c.mu,
        friction_angle_deg: c.mu.atan().to_degrees(),
        eta: c.t,
        kink: c.detail.kink,
        slope_left: c.sides[0].slope,
        slope_right: c.sides[1].slope,
        pattern: c.pattern.clone(),
        between: c.between().map(|m| m.name()),
        mode: c.detail.mode.name(),
        exact: c.exact,
        residual: c.residual,
    }
}

/// Builds the `modes --json` document.
pub fn modes(arch: &Arch, curve: &crate::limit_curve::LimitCurve) -> ModesJson {
    ModesJson {
        version: JSON_VERSION,
        status: match curve.status() {
            CurveStatus::Traced => "ok",
            CurveStatus::NoEquilibrium => "no_equilibrium",
            CurveStatus::NoCollapse => "no_collapse",
            CurveStatus::Unresolved => "unresolved",
        },
        arch: ArchJson::new(arch),
        branches: curve.branches.iter().map(branch).collect(),
        corners: curve.corners.iter().map(corner).collect(),
        transitions: curve.transitions.iter().map(corner).collect(),
        limit_branches: curve
            .limit_branches
            .iter()
            .map(|b| LimitBranchJson {
                branch: branch(&b.branch),
                samples: b.samples,
            })
            .collect(),
        thickness_limit: curve.thickness_limit.as_ref().map(|t| ThicknessLimitJson {
            mu: t.mu,
            eta: t.eta,
            pattern: t.pattern.clone(),
            exact: t.exact,
        }),
        mu_min: curve.thickness_limit.as_ref().map(|t| t.mu).or(curve.mu_ms),
        mu_ms: curve.mu_ms,
        no_collapse: curve.no_collapse.clone(),
        no_equilibrium: curve.no_equilibrium.clone(),
        unresolved: curve
            .unresolved
            .iter()
            .map(|(mu, m)| UnresolvedJson {
                mu: *mu,
                message: m.clone(),
            })
            .collect(),
    }
}
