//! The `load --json` document: the question, the admissible range of λ, every limit state
//! with the side of the loaded section each contact is on.

use super::common::{ArchJson, JSON_VERSION};
use super::state::{mechanism_json, reactions, MechanismJson, Reactions};
use crate::contact::Contact;
use crate::limit_states::LimitState;
use crate::load::LiveLoad;
use crate::multiplier::{LoadOutcome, LoadUnsettled};
use crate::render::live_load::{at_joint, force_unit_kn, merged, LoadQuestion};
use schemars::JsonSchema;
use serde::Serialize;

/// The live load: `kind` `horizontal` (towards `right` or `left`) or `point` (at the extrados
/// angle `beta`; `at_joint` on a discrete arch).
#[derive(Debug, Serialize, JsonSchema)]
#[schemars(rename = "LiveLoad")]
pub(super) struct LoadJson {
    /// `horizontal` or `point`.
    kind: &'static str,
    /// Angle of the loaded extrados point (radians); null for the horizontal load.
    beta: Option<f64>,
    /// Horizontal load: `right` (towards +x, the right springing) or `left`.
    #[serde(skip_serializing_if = "Option::is_none")]
    towards: Option<&'static str>,
    /// Point load: whether it sits at a joint (both sides of its section are checked).
    #[serde(skip_serializing_if = "Option::is_none")]
    at_joint: Option<bool>,
}

/// An active contact of a limit state under a live load: a contact, and at the point load's
/// joint the side of the loaded section it is on.
#[derive(Debug, Serialize, JsonSchema)]
#[schemars(rename = "LoadContact")]
pub struct PatternContact {
    #[serde(flatten)]
    contact: Contact,
    /// At the point load's joint: `before` or `after` the loaded section.
    #[serde(skip_serializing_if = "Option::is_none")]
    side: Option<&'static str>,
}

/// A limit state of the live load: its multiplier, mode, pattern, reactions, mechanism and the
/// live load's power; for the least of a continuum of limit states, `continuum_to`.
#[derive(Debug, Serialize, JsonSchema)]
#[schemars(rename = "LoadLimitState")]
struct StateJson {
    /// Its multiplier λ.
    lambda: f64,
    /// Its collapse mode.
    mode: &'static str,
    /// Its active contacts.
    pattern: Vec<PatternContact>,
    /// Its reactions.
    reactions: Reactions,
    /// Its mechanism.
    mechanism: MechanismJson,
    /// The live load's power on the mechanism.
    live_power: f64,
    /// The largest λ of a continuum of limit states this one is the least of.
    continuum_to: Option<f64>,
}

/// The answer in units (given the arch's dimensions).
#[derive(Debug, Serialize, JsonSchema)]
#[schemars(rename = "Units")]
struct UnitsJson {
    /// γ t d r in kN (the unit of a point load, and of the horizontal force per unit λ).
    force_unit_kn: f64,
    /// λ in kN.
    #[serde(skip_serializing_if = "Option::is_none")]
    lambda_kn: Option<f64>,
    /// λ_static in kN.
    #[serde(skip_serializing_if = "Option::is_none")]
    lambda_static_kn: Option<f64>,
    /// λ g in m/s² (a horizontal load).
    #[serde(skip_serializing_if = "Option::is_none")]
    acceleration_ms2: Option<f64>,
    /// λ_static g in m/s².
    #[serde(skip_serializing_if = "Option::is_none")]
    acceleration_static_ms2: Option<f64>,
}

/// The collapse multiplier of a live load at (η, μ) (`load`): `lambda` (the least limit state:
/// the collapse), `lambda_static` (the static maximum), every limit state below it, `unique`
/// and `reduction`. `status` is `ok` or a no-answer status with `message`.
#[derive(Debug, Serialize, JsonSchema)]
#[schemars(rename = "LoadResult")]
pub struct LoadDoc {
    /// The document format's version (2).
    version: u32,
    /// `ok`, or why there is no answer.
    status: &'static str,
    /// The arch.
    arch: ArchJson,
    /// The thickness ratio η.
    eta: f64,
    /// μ (`null` = ∞).
    #[schemars(extend("x-null" = "infinity"))]
    mu: Option<f64>,
    /// The live load.
    load: LoadJson,
    /// The collapse multiplier λ_c: the least limit state's.
    lambda: Option<f64>,
    /// The largest admissible multiplier (the static maximum).
    lambda_static: Option<f64>,
    /// The least admissible multiplier (negative loads allowed).
    lambda_min: Option<f64>,
    /// Whether exactly one limit state lies in [0, λ_static] (`null`: not decided).
    unique: Option<bool>,
    /// Whether the state at λ_static carries a mechanism.
    mechanism_at_static: Option<bool>,
    /// 1 − λ_c / λ_static: how much non-associative friction lowers the collapse load.
    reduction: Option<f64>,
    /// Every limit state with λ in [0, λ_static], ascending (`unresolved`: the ones found,
    /// each verified; others may lie below).
    limit_states: Vec<StateJson>,
    /// `unresolved` with limit states found: the least λ found, which the collapse
    /// multiplier does not exceed.
    #[serde(skip_serializing_if = "Option::is_none")]
    lambda_at_most: Option<f64>,
    /// `unresolved` with a limit state found below λ_static: 1 − `lambda_at_most`/λ_static,
    /// which the reduction is at least.
    #[serde(skip_serializing_if = "Option::is_none")]
    reduction_at_least: Option<f64>,
    /// How the limit states were searched.
    search: Option<SearchJson>,
    /// The answer in units (given the dimensions).
    #[serde(skip_serializing_if = "Option::is_none")]
    units: Option<UnitsJson>,
    /// Why there is no answer.
    #[serde(skip_serializing_if = "Option::is_none")]
    message: Option<String>,
}

/// How the limit states under the load were searched.
#[derive(Debug, Serialize, JsonSchema)]
#[schemars(rename = "LoadSearch")]
struct SearchJson {
    /// The method.
    method: &'static str,
    /// The points it checked.
    events: usize,
}

pub(super) fn load_json(q: &LoadQuestion) -> LoadJson {
    match q.load {
        LiveLoad::Horizontal { towards_right } => LoadJson {
            kind: "horizontal",
            beta: None,
            towards: Some(if towards_right { "right" } else { "left" }),
            at_joint: None,
        },
        LiveLoad::Point { beta } => LoadJson {
            kind: "point",
            beta: Some(beta),
            towards: None,
            at_joint: Some(at_joint(q.arch, beta)),
        },
        LiveLoad::Pressure(_) => LoadJson {
            kind: "pressure",
            beta: None,
            towards: None,
            at_joint: None,
        },
    }
}

/// The pattern of a limit state, each contact with the side of the loaded section it is on.
pub(super) fn pattern_json(load: &LiveLoad, s: &LimitState) -> Vec<PatternContact> {
    merged(load, s.pattern.iter().zip(s.sides.iter().copied()))
        .into_iter()
        .map(|(contact, side)| PatternContact { contact, side })
        .collect()
}

fn state_json(load: &LiveLoad, s: &LimitState) -> StateJson {
    StateJson {
        lambda: s.t,
        mode: s.mode.name(),
        pattern: pattern_json(load, s),
        reactions: reactions(&s.x),
        mechanism: mechanism_json(&s.mechanism),
        live_power: s.live_power,
        continuum_to: s.continuum_to,
    }
}

fn units(q: &LoadQuestion, lambda: Option<f64>, lambda_static: Option<f64>) -> Option<UnitsJson> {
    let d = q.dims.as_ref()?;
    let unit = force_unit_kn(q, d);
    // the load at λ = 1 in kN: γ t d r for a point load, the vehicle's for a pressure
    let horizontal = matches!(q.load, LiveLoad::Horizontal { .. });
    let at_one = match q.load {
        LiveLoad::Point { .. } => Some(unit),
        LiveLoad::Pressure(_) => q.vehicle_kn,
        LiveLoad::Horizontal { .. } => None,
    };
    Some(UnitsJson {
        force_unit_kn: unit,
        lambda_kn: lambda.zip(at_one).map(|(l, u)| l * u),
        lambda_static_kn: lambda_static.zip(at_one).map(|(l, u)| l * u),
        acceleration_ms2: lambda.filter(|_| horizontal).map(|l| l * d.g),
        acceleration_static_ms2: lambda_static.filter(|_| horizontal).map(|l| l * d.g),
    })
}

/// The `load --json` document; the `Err` of the outcome is the reason no decision was
/// reached (status `unresolved`), with what was decided all the same.
pub fn load(q: &LoadQuestion, outcome: &Result<LoadOutcome, LoadUnsettled>) -> LoadDoc {
    let mut doc = LoadDoc {
        version: JSON_VERSION,
        status: "ok",
        arch: ArchJson::new(q.arch),
        eta: q.eta,
        mu: q.mu.is_finite().then_some(q.mu),
        load: load_json(q),
        lambda: None,
        lambda_static: None,
        lambda_min: None,
        unique: None,
        mechanism_at_static: None,
        reduction: None,
        limit_states: Vec::new(),
        lambda_at_most: None,
        reduction_at_least: None,
        search: None,
        units: None,
        message: None,
    };
    match outcome {
        Err(u) => {
            doc.status = "unresolved";
            doc.message = Some(u.why.to_string());
            doc.lambda_static = u.lambda_static;
            doc.lambda_min = u.lambda_min;
            doc.unique = u.unique();
            doc.mechanism_at_static = u.mechanism_at_static;
            doc.limit_states = u.found.iter().map(|l| state_json(&q.load, l)).collect();
            doc.lambda_at_most = u.lambda_at_most();
            doc.reduction_at_least = u.reduction_at_least();
            doc.units = units(q, None, doc.lambda_static);
        }
        Ok(LoadOutcome::NoEquilibrium) => {
            doc.status = "no_equilibrium";
            doc.message = Some("no statically admissible state at any lambda >= 0".into());
        }
        Ok(LoadOutcome::NoCollapse { lambda_min, events }) => {
            doc.status = "no_collapse";
            doc.lambda_min = Some(lambda_min.0);
            doc.search = Some(SearchJson {
                method: "sweep",
                events: *events,
            });
            doc.message = Some(format!(
                "admissible states exist at every lambda >= {} and no limit state was found up to lambda = {:e}: the load does not break the arch",
                lambda_min.0,
                crate::multiplier::UNBOUNDED_SEARCH_TOP
            ));
        }
        Ok(LoadOutcome::Limits(s)) => {
            doc.lambda = s.lambda();
            doc.lambda_static = s.lambda_static.map(|m| m.0);
            doc.lambda_min = Some(s.lambda_min.0);
            doc.unique = Some(s.unique());
            doc.mechanism_at_static = Some(s.mechanism_at_static);
            doc.reduction = s.reduction();
            doc.limit_states = s
                .limit_states
                .iter()
                .map(|l| state_json(&q.load, l))
                .collect();
            doc.search = Some(SearchJson {
                method: s.method,
                events: s.events,
            });
            doc.units = units(q, doc.lambda, doc.lambda_static);
            if s.limit_states.is_empty() {
                doc.message = Some("no limit state: the static maximum carries no mechanism with positive live power, and none lies below it".into());
            }
        }
    }
    doc
}
