//! The `modes --json` document of an arch with fill: the boundary μ_min(η) of the region
//! where it stands, traced in η (`null` stands for +∞).

use super::bridge::FillJson;
use super::common::{ArchJson, JSON_VERSION};
use crate::arch::Arch;
use crate::bridge::Intrados;
use crate::contact::Contact;
use crate::limit_curve::filled::{FillCurve, FrictionPoint};
use schemars::JsonSchema;
use serde::Serialize;

#[derive(Debug, Serialize, JsonSchema)]
struct PointJson {
    eta: f64,
    mu: f64,
    friction_angle_deg: f64,
    mode: &'static str,
    exact: bool,
    pattern: Vec<Contact>,
    /// The ring's thickness in metres with the span and rise held (given `--span --rise`).
    #[serde(skip_serializing_if = "Option::is_none")]
    ring_m: Option<f64>,
}

fn point(p: &FrictionPoint, intrados: Option<&Intrados>) -> PointJson {
    PointJson {
        ring_m: intrados.map(|i| i.ring_of(p.eta).thickness),
        eta: p.eta,
        mu: p.mu,
        friction_angle_deg: p.mu.atan().to_degrees(),
        mode: p.mode.name(),
        exact: p.exact,
        pattern: p.pattern.clone(),
    }
}

#[derive(Debug, Serialize, JsonSchema)]
struct BranchJson {
    mode: &'static str,
    /// The thinnest and the thickest point of the branch.
    ends: [PointJson; 2],
}

#[derive(Debug, Serialize, JsonSchema)]
struct ChangeJson {
    /// The bracket's thinner and thicker end.
    ends: [PointJson; 2],
    /// Bisected to neighbouring floats in η (both changes, where two across a sliver of
    /// the union pattern were merged into one).
    tight: bool,
}

#[derive(Debug, Serialize, JsonSchema)]
struct UnresolvedJson {
    eta: f64,
    message: String,
}

/// The `modes --json` document with fill.
#[derive(Debug, Serialize, JsonSchema)]
pub struct FillModesJson {
    version: u32,
    status: &'static str,
    arch: ArchJson,
    fill: Option<FillJson>,
    /// "eta": the curve is μ_min(η), traced in η.
    traced_in: &'static str,
    /// η*(∞): no thinner ring stands at any friction.
    eta_inf: Option<f64>,
    /// The least friction at which the arch stands at all, at the thickness that needs
    /// no more.
    least_friction: Option<PointJson>,
    branches: Vec<BranchJson>,
    changes: Vec<ChangeJson>,
    samples: Vec<PointJson>,
    unresolved: Vec<UnresolvedJson>,
}

/// Builds the `modes --json` document of an arch with fill.
pub fn modes_fill(
    arch: &Arch,
    fill: Option<FillJson>,
    intrados: Option<&Intrados>,
    curve: &FillCurve,
) -> FillModesJson {
    let point = |p: &FrictionPoint| point(p, intrados);
    FillModesJson {
        version: JSON_VERSION,
        status: match (curve.least.is_some(), curve.eta_inf.is_some()) {
            (true, _) => "ok",
            (false, true) => "unresolved",
            (false, false) => "no_equilibrium",
        },
        arch: ArchJson::new(arch),
        fill,
        traced_in: "eta",
        eta_inf: curve.eta_inf,
        least_friction: curve.least.as_ref().map(&point),
        branches: curve
            .branches
            .iter()
            .map(|b| BranchJson {
                mode: b.mode.name(),
                ends: [point(&b.ends[0]), point(&b.ends[1])],
            })
            .collect(),
        changes: curve
            .changes
            .iter()
            .map(|c| ChangeJson {
                ends: [point(&c.ends[0]), point(&c.ends[1])],
                tight: c.tight,
            })
            .collect(),
        samples: curve.samples.iter().map(&point).collect(),
        unresolved: curve
            .unresolved
            .iter()
            .map(|(eta, m)| UnresolvedJson {
                eta: *eta,
                message: m.clone(),
            })
            .collect(),
    }
}
