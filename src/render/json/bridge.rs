//! The bridge keys of `load --json` with a vehicle or fill (bridge spec, JSON contract of
//! issue 23): the scope, the fill, the vehicle, and with `--critical` the critical position
//! and the influence line. Added after the load document's own keys, and only when a
//! vehicle or fill was given.

use super::load::{pattern_json, PatternContact};
use crate::bridge::critical::{Collapse, Critical};
use schemars::JsonSchema;
use serde::Serialize;

/// What the results leave out, printed wherever a bridge answer is shown.
pub const SCOPE: &str = "rigid blocks without crushing; one ring, one span; radial joints; \
the fill a vertical dead load on the extrados (no lateral pressure, no strength of its own)";

/// The fill as given.
#[derive(Debug, Clone, Serialize, JsonSchema)]
#[schemars(rename = "Fill")]
pub struct FillJson {
    /// Unit weight of the fill (kN/m³), when given in kN.
    pub weight_kn_m3: Option<f64>,
    /// Depth above the highest extrados point (m), when given in metres.
    pub depth_m: Option<f64>,
    /// g_f = γ_f/γ.
    pub weight_ratio: f64,
    /// h = h_c/r.
    pub depth_ratio: f64,
    /// `solve` with span and rise: the road's depth h r* (m) above the extrados of the
    /// least ring (h held as the ring varies).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub depth_at_least_ring_m: Option<f64>,
}

/// The vehicle as placed.
#[derive(Debug, Clone, Serialize, JsonSchema)]
pub struct VehicleJson {
    /// Axle loads (kN).
    pub axles_kn: Vec<f64>,
    /// A patch load on the road: [q (kN/m²), from (m), to (m)].
    #[serde(skip_serializing_if = "Option::is_none")]
    pub patch: Option<[f64; 3]>,
    /// Gaps between consecutive axles (m).
    pub spacing_m: Vec<f64>,
    /// Road position of the first axle (m from the left intrados springing).
    pub at_m: f64,
    /// Dispersal slope through the fill (0: point loads).
    pub dispersal: f64,
    /// Effective width (m).
    pub effective_width_m: f64,
    /// The vehicle's load at λ = 1 that reaches the ring, and the part the abutments carry
    /// (kN).
    pub carried_kn: f64,
    /// See `carried_kn`.
    pub abutments_kn: f64,
}

#[derive(Debug, Serialize, JsonSchema)]
struct Second {
    at_m: f64,
    lambda: f64,
}

#[derive(Debug, Serialize, JsonSchema)]
struct CriticalJson {
    at_m: f64,
    lambda: f64,
    lambda_kn: Option<f64>,
    mode: Option<&'static str>,
    pattern: Vec<PatternContact>,
    bracket_m: [f64; 2],
    /// The mirror position, which ties (a symmetric arch under a symmetric vehicle).
    mirror_at_m: Option<f64>,
    second: Option<Second>,
    surveys: usize,
    /// Static maxima alone (λ_static, no search below it) evaluated in locating minima.
    static_maxima: usize,
}

#[derive(Debug, Serialize, JsonSchema)]
struct InfluenceJson {
    at_m: f64,
    /// λ_c; null where the vehicle never breaks the arch or nothing was decided (`status`).
    lambda: Option<f64>,
    status: &'static str,
}

/// The bridge keys.
#[derive(Debug, Serialize, JsonSchema)]
pub struct BridgeJson {
    scope: &'static str,
    fill: Option<FillJson>,
    #[serde(skip_serializing_if = "Option::is_none")]
    vehicle: Option<VehicleJson>,
    #[serde(skip_serializing_if = "Option::is_none")]
    critical: Option<CriticalJson>,
    #[serde(skip_serializing_if = "Option::is_none")]
    influence: Option<Vec<InfluenceJson>>,
}

/// The bridge keys of a load answer; `vehicle_kn` the vehicle's total (kN).
pub fn bridge(
    fill: Option<FillJson>,
    vehicle: Option<VehicleJson>,
    critical: Option<&Critical>,
    vehicle_kn: Option<f64>,
) -> BridgeJson {
    BridgeJson {
        scope: SCOPE,
        fill,
        vehicle,
        critical: critical.and_then(|c| critical_json(c, vehicle_kn)),
        influence: critical.map(|c| {
            c.influence
                .iter()
                .map(|p| InfluenceJson {
                    at_m: p.at_m,
                    lambda: p.collapse.value().is_finite().then(|| p.collapse.value()),
                    status: status(&p.collapse),
                })
                .collect()
        }),
    }
}

/// The name of a sample's outcome.
pub fn status(c: &Collapse) -> &'static str {
    match c {
        Collapse::At(_) => "ok",
        Collapse::Never => "no_collapse",
        Collapse::NoEquilibrium => "no_equilibrium",
        Collapse::Undecided(_) => "unresolved",
    }
}

fn critical_json(c: &Critical, vehicle_kn: Option<f64>) -> Option<CriticalJson> {
    let m = c.minima.first()?;
    let least = c.at_critical.as_ref().and_then(|(load, sv)| {
        let s = sv.limit_states.first()?;
        Some((s.mode.name(), pattern_json(load, s)))
    });
    let (mode, pattern) = least.map_or((None, Vec::new()), |(m, p)| (Some(m), p));
    let second = c
        .minima
        .iter()
        .skip(1)
        .find(|o| {
            c.mirror_m.is_none_or(|x| {
                (o.at_m - x).abs() > 2.0 * (m.bracket_m.1 - m.bracket_m.0).max(1e-9)
            })
        })
        .map(|o| Second {
            at_m: o.at_m,
            lambda: o.lambda,
        });
    Some(CriticalJson {
        at_m: m.at_m,
        lambda: m.lambda,
        lambda_kn: vehicle_kn.map(|v| v * m.lambda),
        mode,
        pattern,
        bracket_m: [m.bracket_m.0, m.bracket_m.1],
        mirror_at_m: c.mirror_m,
        second,
        surveys: c.surveys,
        static_maxima: c.statics,
    })
}
