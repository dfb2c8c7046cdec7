//! The `modes --json` document (`null` stands for +∞).

use super::common::{ArchJson, JSON_VERSION};
use crate::arch::Arch;
use crate::contact::Contact;
use crate::limit_curve::CurveStatus;
use schemars::JsonSchema;
use serde::Serialize;

/// A branch of the η–μ limit curve: one collapse mode for μ in [mu_min, mu_max] (`null`:
/// unbounded), η between eta_min and eta_max.
#[derive(Debug, Serialize, JsonSchema)]
#[schemars(rename = "Branch")]
struct BranchJson {
    /// The collapse mode.
    mode: &'static str,
    /// Whether the mode's name is one of the contract's list (else a descriptive one).
    mode_standard: bool,
    /// Where the branch starts.
    mu_min: f64,
    /// Where it ends (`null`: ∞).
    mu_max: f64,
    /// Its least η.
    eta_min: f64,
    /// Its largest η.
    eta_max: f64,
    /// The active contacts along it.
    pattern: Vec<Contact>,
}

/// A corner (`kink`) or smooth transition of η_s(μ), located exactly (`mu` `null`: an asymptote
/// at μ = ∞).
#[derive(Debug, Serialize, JsonSchema)]
#[schemars(rename = "Corner")]
struct CornerJson {
    /// Where it is.
    mu: f64,
    /// atan μ in degrees.
    friction_angle_deg: f64,
    /// η_s there.
    eta: f64,
    /// True for a corner (the slopes differ), false for a smooth transition.
    kink: bool,
    /// dη_s/dμ on the side of smaller μ (`null`: the vertical purely-sliding branch at
    /// μ_ms, or undefined at μ = ∞).
    #[schemars(extend("x-null" = "none"))]
    slope_left: f64,
    /// dη_s/dμ on the side of larger μ (`null` at μ = ∞).
    #[schemars(extend("x-null" = "none"))]
    slope_right: f64,
    /// The active contacts there (both branches' together).
    pattern: Vec<Contact>,
    /// The modes on the side of smaller and of larger μ.
    between: [&'static str; 2],
    /// The mode of the state at the corner.
    mode: &'static str,
    /// Whether Newton located it to rounding (else a bracket's midpoint).
    exact: bool,
    /// Newton's residual there (`null`: not located by Newton).
    #[schemars(extend("x-null" = "none"))]
    residual: f64,
}

/// A branch of limit states above the boundary η_s(μ), traced by samples.
#[derive(Debug, Serialize, JsonSchema)]
#[schemars(rename = "LimitBranch")]
struct LimitBranchJson {
    #[serde(flatten)]
    branch: BranchJson,
    /// The samples that trace it.
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

/// Where the boundary reaches the thickness limit η → 2 above μ_ms.
#[derive(Debug, Serialize, JsonSchema)]
#[schemars(rename = "ThicknessLimit")]
struct ThicknessLimitJson {
    /// Where.
    mu: f64,
    /// η there.
    eta: f64,
    /// The active contacts there.
    pattern: Vec<Contact>,
    /// Whether located by Newton.
    exact: bool,
}

/// A friction coefficient at which the curve is not decided, and why.
#[derive(Debug, Serialize, JsonSchema)]
#[schemars(rename = "Unresolved")]
struct UnresolvedJson {
    /// Where.
    mu: f64,
    /// Why.
    message: String,
}

/// The whole η–μ limit curve (`modes`): branches with their collapse modes, exact corners,
/// smooth transitions and the limit states above the boundary. `status` is `ok`,
/// `no_equilibrium`, `no_collapse` or `unresolved`.
#[derive(Debug, Serialize, JsonSchema)]
#[schemars(rename = "ModesResult")]
pub struct ModesJson {
    /// The document format's version (2).
    version: u32,
    /// `ok`, `no_equilibrium`, `no_collapse` or `unresolved`.
    status: &'static str,
    /// The arch.
    arch: ArchJson,
    /// The branches of η_s(μ), in order of μ.
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
    /// Where the curve is not decided.
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
