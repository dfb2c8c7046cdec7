//! The answer of `arch-enum load` as JSON and as text: pure functions of
//! [`crate::multiplier::LoadOutcome`].

use super::json::{mechanism_json, reactions, ArchJson, MechanismJson, Reactions, JSON_VERSION};
use super::table::{describe_arch, fmt_mu, short, sig, Dimensions};
use crate::arch::Arch;
use crate::contact::Contact;
use crate::load::{LiveLoad, Side};
use crate::multiplier::{LoadCurve, LoadLimitState, LoadOutcome};
use serde::Serialize;
use std::fmt::Write;

/// The question asked: arch, η, μ and the load.
pub struct LoadQuestion<'a> {
    /// The arch.
    pub arch: &'a Arch,
    /// Thickness ratio.
    pub eta: f64,
    /// Friction coefficient.
    pub mu: f64,
    /// The live load.
    pub load: LiveLoad,
    /// Physical dimensions, for loads in kN or accelerations in m/s².
    pub dims: Option<Dimensions>,
}

#[derive(Debug, Serialize)]
struct LoadJson {
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

#[derive(Debug, Serialize)]
struct PatternContact {
    #[serde(flatten)]
    contact: Contact,
    /// At the point load's joint: `before` or `after` the loaded section.
    #[serde(skip_serializing_if = "Option::is_none")]
    side: Option<&'static str>,
}

#[derive(Debug, Serialize)]
struct StateJson {
    lambda: f64,
    mode: &'static str,
    pattern: Vec<PatternContact>,
    reactions: Reactions,
    mechanism: MechanismJson,
    live_power: f64,
    /// The largest λ of a continuum of limit states this one is the least of.
    continuum_to: Option<f64>,
}

#[derive(Debug, Serialize)]
struct UnitsJson {
    /// γ t d r in kN (the unit of a point load, and of the horizontal force per unit λ).
    force_unit_kn: f64,
    #[serde(skip_serializing_if = "Option::is_none")]
    lambda_kn: Option<f64>,
    #[serde(skip_serializing_if = "Option::is_none")]
    lambda_static_kn: Option<f64>,
    #[serde(skip_serializing_if = "Option::is_none")]
    acceleration_ms2: Option<f64>,
    #[serde(skip_serializing_if = "Option::is_none")]
    acceleration_static_ms2: Option<f64>,
}

/// The `load --json` document.
#[derive(Debug, Serialize)]
pub struct LoadDoc {
    version: u32,
    status: &'static str,
    arch: ArchJson,
    eta: f64,
    mu: Option<f64>,
    load: LoadJson,
    lambda: Option<f64>,
    lambda_static: Option<f64>,
    lambda_min: Option<f64>,
    unique: Option<bool>,
    mechanism_at_static: Option<bool>,
    reduction: Option<f64>,
    limit_states: Vec<StateJson>,
    search: Option<SearchJson>,
    #[serde(skip_serializing_if = "Option::is_none")]
    units: Option<UnitsJson>,
    #[serde(skip_serializing_if = "Option::is_none")]
    message: Option<String>,
}

#[derive(Debug, Serialize)]
struct SearchJson {
    method: &'static str,
    events: usize,
}

fn load_json(q: &LoadQuestion) -> LoadJson {
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
    }
}

fn at_joint(arch: &Arch, beta: f64) -> bool {
    match arch.layout() {
        crate::arch::JointLayout::Discrete(j) => j.contains(&beta),
        crate::arch::JointLayout::Continuous => false,
    }
}

fn side_name(load: &LiveLoad, c: &Contact, side: Side) -> Option<&'static str> {
    load.splits(c.beta).then_some(match side {
        Side::Before => "before",
        Side::After => "after",
    })
}

/// The contacts of a pattern with the side of a loaded section each is on (`None`: no
/// section split there; `Some("both")`: one hinge seen from both sides). The extrados hinge
/// rows on the two sides of a point load's section are one function — the load acts at the
/// extrados point, so its moment about it is nil — and appear once, as `both`.
fn merged<'a>(
    load: &LiveLoad,
    pattern: impl Iterator<Item = (&'a Contact, Side)>,
) -> Vec<(Contact, Option<&'static str>)> {
    let mut out: Vec<(Contact, Option<&'static str>)> = Vec::new();
    for (c, side) in pattern {
        let name = side_name(load, c, side);
        if let Some(twin) = out.iter_mut().find(|(d, side)| {
            name.is_some()
                && side.is_some()
                && d.beta == c.beta
                && d.kind == c.kind
                && c.kind == crate::contact::ContactKind::HingeExtrados
        }) {
            twin.1 = Some("both");
            continue;
        }
        out.push((*c, name));
    }
    out
}

fn state_json(load: &LiveLoad, s: &LoadLimitState) -> StateJson {
    StateJson {
        lambda: s.lambda,
        mode: s.mode.name(),
        pattern: merged(load, s.pattern.iter().zip(s.sides.iter().copied()))
            .into_iter()
            .map(|(contact, side)| PatternContact { contact, side })
            .collect(),
        reactions: reactions(&s.x),
        mechanism: mechanism_json(&s.mechanism),
        live_power: s.live_power,
        continuum_to: s.continuum_to,
    }
}

/// γ t d r in kN, and g in m/s², for the question's dimensions.
fn force_unit_kn(q: &LoadQuestion, d: &Dimensions) -> f64 {
    d.density * d.g * q.eta * d.radius * d.depth * d.radius / 1000.0
}

fn units(q: &LoadQuestion, lambda: Option<f64>, lambda_static: Option<f64>) -> Option<UnitsJson> {
    let d = q.dims.as_ref()?;
    let unit = force_unit_kn(q, d);
    let point = matches!(q.load, LiveLoad::Point { .. });
    Some(UnitsJson {
        force_unit_kn: unit,
        lambda_kn: lambda.filter(|_| point).map(|l| l * unit),
        lambda_static_kn: lambda_static.filter(|_| point).map(|l| l * unit),
        acceleration_ms2: lambda.filter(|_| !point).map(|l| l * d.g),
        acceleration_static_ms2: lambda_static.filter(|_| !point).map(|l| l * d.g),
    })
}

/// The `load --json` document; the `Err` of the outcome is the reason no decision was
/// reached (status `unresolved`).
pub fn json(q: &LoadQuestion, outcome: &Result<LoadOutcome, String>) -> LoadDoc {
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
        search: None,
        units: None,
        message: None,
    };
    match outcome {
        Err(reason) => {
            doc.status = "unresolved";
            doc.message = Some(reason.clone());
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

fn pattern_text(load: &LiveLoad, s: &LoadLimitState) -> String {
    merged(load, s.pattern.iter().zip(s.sides.iter().copied()))
        .iter()
        .map(|(c, side)| {
            let tag = match side {
                Some("before") => "<",
                Some("after") => ">",
                _ => "",
            };
            format!("{}@{:.4}{tag}", short(c), c.beta)
        })
        .collect::<Vec<_>>()
        .join(" ")
}

/// The human-readable answer of `load`.
pub fn table(q: &LoadQuestion, outcome: &Result<LoadOutcome, String>) -> String {
    let mut s = String::new();
    let _ = writeln!(s, "{}", describe_arch(q.arch));
    let _ = writeln!(
        s,
        "thickness           eta = t/r = {}; friction mu = {}",
        sig(q.eta, 12),
        fmt_mu(q.mu)
    );
    let load_text = match q.load {
        LiveLoad::Horizontal { towards_right } => format!(
            "horizontal body force lambda x self-weight, towards the {} springing",
            if towards_right { "right" } else { "left" }
        ),
        LiveLoad::Point { beta } => format!(
            "vertical point load lambda (units of gamma t d r) at the extrados point beta = {beta:.10} rad ({:.4} deg){}",
            beta.to_degrees(),
            match q.arch.layout() {
                crate::arch::JointLayout::Continuous => ", on the continuum (both sides of the loaded section checked)",
                _ if at_joint(q.arch, beta) => ", at a joint (both sides of its section checked)",
                _ => ", inside a voussoir",
            }
        ),
    };
    let _ = writeln!(s, "load                {load_text}");
    let unit = q.dims.as_ref().map(|d| (force_unit_kn(q, d), d.g));
    let physical = |l: f64| match (unit, q.load) {
        (Some((u, _)), LiveLoad::Point { .. }) => format!("  ({} kN)", sig(l * u, 6)),
        (Some((_, g)), LiveLoad::Horizontal { .. }) => {
            format!("  ({} m/s^2 = {} g)", sig(l * g, 6), sig(l, 6))
        }
        _ => String::new(),
    };
    match outcome {
        Err(reason) => {
            let _ = writeln!(s, "unresolved: {reason}");
        }
        Ok(LoadOutcome::NoEquilibrium) => {
            let _ = writeln!(
                s,
                "no equilibrium: no statically admissible state at any lambda >= 0"
            );
        }
        Ok(LoadOutcome::NoCollapse { lambda_min, .. }) => {
            let _ = writeln!(
                s,
                "no collapse: admissible states at every lambda >= {} and no limit state up to lambda = {:e}",
                sig(lambda_min.0, 12),
                crate::multiplier::UNBOUNDED_SEARCH_TOP
            );
        }
        Ok(LoadOutcome::Limits(sv)) => {
            let stat = sv
                .lambda_static
                .map_or("unbounded".to_string(), |m| sig(m.0, 12));
            let _ = writeln!(
                s,
                "admissible          lambda in [{}, {}]{}",
                sig(sv.lambda_min.0, 12),
                stat,
                if sv.lambda_min.0 > 0.0 {
                    "  (the arch needs the load to stand: the lower end is an unloading limit, never a collapse)"
                } else {
                    ""
                }
            );
            if let Some(m) = sv.lambda_static {
                let _ = writeln!(
                    s,
                    "static maximum      lambda_static = {}{}; {}",
                    sig(m.0, 12),
                    physical(m.0),
                    if sv.mechanism_at_static {
                        "carries a mechanism with positive live power"
                    } else {
                        "carries NO mechanism with positive live power"
                    }
                );
            }
            match sv.lambda() {
                Some(l) => {
                    let _ = writeln!(
                        s,
                        "collapse multiplier lambda = {}{}{}",
                        sig(l, 12),
                        physical(l),
                        sv.reduction()
                            .filter(|r| *r > 0.0)
                            .map_or(String::new(), |r| format!(
                                "; {} below the static maximum (reduction 1 - lambda/lambda_static = {})",
                                if r >= 1.0 { "infinitely" } else { "non-associative friction brings it" },
                                sig(r, 6)
                            ))
                    );
                }
                None => {
                    let _ = writeln!(s, "collapse multiplier none: no limit state with lambda in the admissible range");
                }
            }
            let how = match sv.method {
                "sweep" => format!("{} events of the sweep", sv.events),
                "refined" => format!(
                    "two discretisations swept ({} events in the finer) and refined on the continuum",
                    sv.events
                ),
                _ => "mu = inf: associative, the static maximum is the only limit state".to_string(),
            };
            let _ = writeln!(
                s,
                "limit states ({how}; E/I hinge at extrados/intrados, S+/S- sliding, < > before/after the loaded section):"
            );
            for l in &sv.limit_states {
                let _ = writeln!(
                    s,
                    "  lambda = {}  {}  {}{}",
                    sig(l.lambda, 12),
                    l.mode.name(),
                    pattern_text(&q.load, l),
                    l.continuum_to.map_or(String::new(), |to| if to > l.lambda {
                        format!(
                            "  (least of a continuum of limit states up to lambda = {})",
                            sig(to, 12)
                        )
                    } else {
                        "  (a continuum of limit states at this lambda: every state of a face of the admissible set)".to_string()
                    })
                );
            }
            let _ = writeln!(
                s,
                "verdict             {}",
                if sv.limit_states.is_empty() {
                    "no limit state"
                } else if sv.unique() {
                    "unique limit state"
                } else {
                    "not unique"
                }
            );
        }
    }
    s.lines().map(|l| l.trim_end().to_string() + "\n").collect()
}

/// One sample of the λ–μ curve at fixed η.
#[derive(Debug, Serialize)]
pub struct LoadCurveRow {
    mu: Option<f64>,
    status: &'static str,
    lambda: Option<f64>,
    lambda_static: Option<f64>,
    reduction: Option<f64>,
    unique: Option<bool>,
    mode: Option<&'static str>,
    limit_states: usize,
    #[serde(skip_serializing_if = "Option::is_none")]
    message: Option<String>,
}

/// The `load-curve --json` document.
#[derive(Debug, Serialize)]
pub struct LoadCurveDoc {
    version: u32,
    status: &'static str,
    arch: ArchJson,
    eta: f64,
    load: LoadJson,
    points: Vec<LoadCurveRow>,
    corners: Vec<CornerJson>,
}

fn curve_row(mu: f64, outcome: &Result<LoadOutcome, String>) -> LoadCurveRow {
    let mut row = LoadCurveRow {
        mu: mu.is_finite().then_some(mu),
        status: "ok",
        lambda: None,
        lambda_static: None,
        reduction: None,
        unique: None,
        mode: None,
        limit_states: 0,
        message: None,
    };
    match outcome {
        Err(e) => {
            row.status = "unresolved";
            row.message = Some(e.clone());
        }
        Ok(LoadOutcome::NoEquilibrium) => row.status = "no_equilibrium",
        Ok(LoadOutcome::NoCollapse { .. }) => row.status = "no_collapse",
        Ok(LoadOutcome::Limits(s)) => {
            row.lambda = s.lambda();
            row.lambda_static = s.lambda_static.map(|m| m.0);
            row.reduction = s.reduction();
            row.unique = Some(s.unique());
            row.mode = s.limit_states.first().map(|l| l.mode.name());
            row.limit_states = s.limit_states.len();
        }
    }
    row
}

/// One side of a corner of the λ–μ curve: the sample's row, and the least limit state's
/// pattern.
#[derive(Debug, Serialize)]
struct CornerSide {
    #[serde(flatten)]
    row: LoadCurveRow,
    pattern: Vec<PatternContact>,
}

/// A corner of the λ–μ curve in `load-curve --json`.
#[derive(Debug, Serialize)]
struct CornerJson {
    /// The corner's friction coefficient: exact (five activation functions vanish at one
    /// state, Newton in (h, v, w, λ, μ)) when `exact`, else null (see the bracket).
    mu: Option<f64>,
    /// λ at the exact corner.
    lambda: Option<f64>,
    exact: bool,
    /// The bisection's bracket: answers at μ just below and just above (neighbouring floats
    /// when `bracketed`; around an exact corner, the survey's active-set tolerance widens it).
    mu_below: f64,
    mu_above: Option<f64>,
    bracketed: bool,
    /// Changes of branch bracketed here (more than 1 without `exact`: the answer flickers
    /// in this stretch).
    changes: usize,
    /// λ continuous across the corner (two limit states cross) or not (a jump).
    continuous: bool,
    below: CornerSide,
    above: CornerSide,
}

fn corner_side(load: &LiveLoad, (mu, o): &(f64, Result<LoadOutcome, String>)) -> CornerSide {
    let pattern = match o {
        Ok(LoadOutcome::Limits(sv)) => sv.limit_states.first().map_or(Vec::new(), |l| {
            merged(load, l.pattern.iter().zip(l.sides.iter().copied()))
                .into_iter()
                .map(|(contact, side)| PatternContact { contact, side })
                .collect()
        }),
        _ => Vec::new(),
    };
    CornerSide {
        row: curve_row(*mu, o),
        pattern,
    }
}

/// λ equal on both sides of a corner to this relative tolerance: continuous.
const CONTINUOUS_TOL: f64 = 1e-9;

/// The `load-curve --json` document: the samples and the corners.
pub fn curve_json(q: &LoadQuestion, curve: &LoadCurve) -> LoadCurveDoc {
    LoadCurveDoc {
        version: JSON_VERSION,
        status: "ok",
        arch: ArchJson::new(q.arch),
        eta: q.eta,
        load: load_json(q),
        points: curve
            .samples
            .iter()
            .map(|(mu, o)| curve_row(*mu, o))
            .collect(),
        corners: curve
            .corners
            .iter()
            .map(|c| CornerJson {
                mu: c.exact.as_ref().map(|e| e.mu),
                lambda: c.exact.as_ref().map(|e| e.lambda),
                exact: c.exact.is_some(),
                mu_below: c.below.0,
                mu_above: c.above.0.is_finite().then_some(c.above.0),
                bracketed: c.bracketed,
                changes: c.changes,
                continuous: c.continuous(CONTINUOUS_TOL),
                below: corner_side(&q.load, &c.below),
                above: corner_side(&q.load, &c.above),
            })
            .collect(),
    }
}

/// The least limit state of an answer in words: mode and pattern (or the status).
fn least_text(load: &LiveLoad, o: &Result<LoadOutcome, String>) -> String {
    match o {
        Err(_) => "unresolved".into(),
        Ok(LoadOutcome::NoEquilibrium) => "no equilibrium".into(),
        Ok(LoadOutcome::NoCollapse { .. }) => "no collapse".into(),
        Ok(LoadOutcome::Limits(sv)) => match sv.limit_states.first() {
            None => "no limit state".into(),
            Some(l) => format!(
                "lambda = {}  {}  {}{}",
                sig(l.lambda, 12),
                l.mode.name(),
                pattern_text(load, l),
                if sv.reduction().is_some_and(|r| r > 0.0) {
                    "  (below lambda_static)"
                } else {
                    ""
                }
            ),
        },
    }
}

/// The human-readable λ–μ table.
pub fn curve_table(q: &LoadQuestion, curve: &LoadCurve) -> String {
    let samples = &curve.samples;
    let mut s = String::new();
    let _ = writeln!(s, "{}", describe_arch(q.arch));
    let _ = writeln!(s, "thickness           eta = t/r = {}", sig(q.eta, 12));
    let _ = writeln!(
        s,
        "load                {}",
        match q.load {
            LiveLoad::Horizontal { towards_right } => format!(
                "horizontal body force lambda x self-weight, towards the {} springing",
                if towards_right { "right" } else { "left" }
            ),
            LiveLoad::Point { beta } => format!(
                "vertical point load at the extrados point beta = {beta:.10} rad ({:.4} deg)",
                beta.to_degrees()
            ),
        }
    );
    let _ = writeln!(
        s,
        "{:>16}  {:>16}  {:>16}  {:>11}  {:>6}  mode of the least limit state",
        "mu", "lambda_static", "lambda", "reduction", "states"
    );
    for (mu, o) in samples {
        let r = curve_row(*mu, o);
        let num = |v: Option<f64>| v.map_or("-".to_string(), |v| sig(v, 12));
        if r.status == "ok" {
            let _ = writeln!(
                s,
                "{:>16}  {:>16}  {:>16}  {:>11}  {:>6}  {}",
                fmt_mu(*mu),
                num(r.lambda_static),
                num(r.lambda),
                r.reduction.map_or("-".to_string(), |v| sig(v, 4)),
                r.limit_states,
                r.mode.unwrap_or("-")
            );
        } else {
            let _ = writeln!(
                s,
                "{:>16}  {}{}",
                fmt_mu(*mu),
                r.status,
                r.message.map_or(String::new(), |m| format!(": {m}"))
            );
        }
    }
    if curve.corners.is_empty() {
        let _ = writeln!(s, "corners             none between the samples");
    } else {
        let _ = writeln!(
            s,
            "corners             where the least limit state changes (exact: five contacts active at one state, or four sliding ones where the least states are faces along w, Newton in h, v, w, lambda, mu; else the bisection's neighbouring floats in mu):"
        );
    }
    for c in &curve.corners {
        let (below, above) = c.lambdas();
        let change = match (below, above) {
            _ if c.exact.is_none() && c.changes > 1 => format!(
                "the answer changes {} times in this stretch (no single corner: near a singularity the survey's answer flickers)",
                c.changes
            ),
            (Some(_), Some(_)) if c.continuous(CONTINUOUS_TOL) => "continuous".into(),
            (Some(a), Some(b)) => format!("lambda jumps {} -> {}", sig(a, 12), sig(b, 12)),
            _ => "a change of status".into(),
        };
        let at = match &c.exact {
            Some(e) => format!("mu = {}  lambda = {} (exact)", e.mu, sig(e.lambda, 15)),
            None => format!(
                "mu in [{}, {}]{}",
                c.below.0,
                if c.above.0.is_finite() {
                    c.above.0.to_string()
                } else {
                    "inf".into()
                },
                if c.bracketed || c.changes > 1 {
                    ""
                } else {
                    " (not bisected to the end)"
                }
            ),
        };
        let _ = writeln!(s, "  {at}  {change}");
        let _ = writeln!(s, "      below: {}", least_text(&q.load, &c.below.1));
        let _ = writeln!(s, "      above: {}", least_text(&q.load, &c.above.1));
    }
    s.lines().map(|l| l.trim_end().to_string() + "\n").collect()
}
