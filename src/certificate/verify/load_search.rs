//! Re-checking the evidence of the limit states under a live load (the `load_search`
//! section of a load certificate).
//!
//! * **No mechanism** at a listed state (the state at λ_static, or a point of the sweep):
//!   *proved* in interval arithmetic by the Farkas alternative of the kinematic LP with the
//!   live power — `c_j · y + z + u P_j + v q_j ≤ 0` for every kept contact, z > 0,
//!   u, v ≥ 0, with P_j = p_j + λ q_j the total and q_j the live power of a unit rate — so no
//!   rates λ̇ ≥ 0, Σ λ̇ = 1, B λ̇ = 0 have total power ≥ 0 and live power ≥ 0, for every
//!   choice of one sliding sense per section. That the listed contacts are the state's
//!   whole active set is *checked* in floating point (discrete arches).
//! * **Limit states**: admissibility (every joint, or 2000 samples per piece of a
//!   continuous arch), the pattern active, B λ̇ = 0, λ̇ ≥ 0, Σ λ̇ = 1, one sliding sense per
//!   section, total power ≥ 0 and live power > 0 — *checked* in floating point.
//! * **μ = ∞** (`associative`): every mechanism is made of hinges and dissipates nothing,
//!   so for compatible rates Σ φ λ̇ = L_dead + λ L_live (virtual work, docs/loads.md); a
//!   limit state at λ* has L_dead + λ* L_live = 0 with L_live > 0, and a state admissible
//!   at λ' > λ* would give (λ' − λ*) L_live ≤ 0. With the state *proved* admissible at
//!   λ_lo, no limit state lies below λ_lo (none at all when λ is unbounded).
//!
//! Not re-proved: that the sweep met every event, that two discretisations agreed
//! (`refined`), and λ_min.

use super::limit_state::LIMIT_STATE_TOL;
use super::live::Live;
use super::load_limit_state::{check_limit_state, state_at};
use super::mechanism::no_mechanism;
use super::report::{reject, Rejection};
use super::statics::Model;
use crate::certificate::format::{LoadSearchEvidence, LoadSearchMethod};

/// Re-checks `search` against the claim: λ_static in [λ_lo, λ_hi] (`hi` `None`: unbounded,
/// admissible states from λ_lo on). Returns the report's lines and the verdict.
pub(super) fn verify_load_search(
    model: &Model,
    live: &Live,
    mu: Option<f64>,
    search: &LoadSearchEvidence,
    lo: f64,
    hi: Option<f64>,
) -> Result<(Vec<String>, String), Rejection> {
    let mut checks = Vec::new();
    let unique = check_listing(search, lo)?;
    limit_states(model, live, mu, search, hi, &mut checks)?;
    check_mechanism_at_static(search, lo, hi)?;
    static_state(model, live, mu, search, (lo, hi), &mut checks)?;
    method_evidence(model, live, mu, search, (lo, hi), &mut checks)?;
    if search.lambda_min > 0.0 {
        checks.push(format!(
            "not proved: lambda_min = {} (below it the arch does not stand; the state there is an unloading limit, never a collapse)",
            search.lambda_min
        ));
    }
    Ok((checks, verdict(search, unique)))
}

/// The listing agrees with itself: `unique` (returned) with the limit states listed, the
/// collapse multiplier with the least of them, λ_min in [0, λ_lo].
fn check_listing(search: &LoadSearchEvidence, lo: f64) -> Result<bool, Rejection> {
    let states = &search.limit_states;
    let unique = states.len() == 1
        && states[0]
            .continuum
            .as_ref()
            .is_none_or(|c| c.to.is_some_and(|to| to <= states[0].lambda));
    if search.unique != unique {
        return reject(format!(
            "load_search: unique = {} but {} limit state(s) are listed{}",
            search.unique,
            states.len(),
            if states.iter().any(|s| s.continuum.is_some()) {
                " (with a continuum)"
            } else {
                ""
            }
        ));
    }
    if search.lambda != states.first().map(|s| s.lambda) {
        return reject(format!(
            "load_search: the collapse multiplier lambda = {:?} is not the least listed limit state's ({:?})",
            search.lambda,
            states.first().map(|s| s.lambda)
        ));
    }
    if !(search.lambda_min.is_finite() && search.lambda_min >= 0.0 && search.lambda_min <= lo) {
        return reject(format!(
            "load_search: lambda_min = {} must lie in [0, lambda_lo = {lo}]",
            search.lambda_min
        ));
    }
    Ok(unique)
}

/// The listed limit states, each checked in floating point (ascending, below λ_hi,
/// admissible, with a mechanism); pushes the report's lines.
fn limit_states(
    model: &Model,
    live: &Live,
    mu: Option<f64>,
    search: &LoadSearchEvidence,
    hi: Option<f64>,
    checks: &mut Vec<String>,
) -> Result<(), Rejection> {
    let states = &search.limit_states;
    let mut last = f64::NEG_INFINITY;
    for (i, ls) in states.iter().enumerate() {
        let whose = format!("load_search: limit state {i}");
        if ls.lambda.is_nan() || ls.lambda < last {
            return reject(format!("{whose}: lambda = {} is not ascending", ls.lambda));
        }
        last = ls.lambda;
        if hi.is_some_and(|h| ls.lambda >= h) {
            return reject(format!(
                "{whose}: lambda = {} is not below lambda_hi = {} (no state is admissible there)",
                ls.lambda,
                hi.unwrap_or(f64::INFINITY)
            ));
        }
        check_limit_state(model, live, mu, ls, &whose)?;
    }
    if !states.is_empty() {
        checks.push(format!(
            "checked (floating point, tolerance {LIMIT_STATE_TOL:e}; evidence, not proof): {} limit state(s), admissible, each with a mechanism without dilatancy of positive live power (lambda = {})",
            states.len(),
            states.iter().map(|s| s.lambda.to_string()).collect::<Vec<_>>().join(", ")
        ));
    }
    if let Some(c) = states.iter().find(|s| s.continuum.is_some()) {
        checks.push(format!(
            "not re-checked: the continuum of limit states from lambda = {} (only its least state is checked)",
            c.lambda
        ));
    }
    Ok(())
}

/// `mechanism_at_static` agrees with the limit states listed in [λ_lo, λ_hi].
fn check_mechanism_at_static(
    search: &LoadSearchEvidence,
    lo: f64,
    hi: Option<f64>,
) -> Result<(), Rejection> {
    let states = &search.limit_states;
    // a state at λ_static: an isolated one in the bracket, or a continuum reaching it
    let isolated_at_static = states
        .iter()
        .any(|s| s.continuum.is_none() && s.lambda >= lo);
    let at_static = isolated_at_static
        || states.iter().any(|s| {
            s.continuum
                .as_ref()
                .is_some_and(|c| c.to.is_none_or(|to| to >= lo))
        });
    match (search.mechanism_at_static, hi) {
        (true, None) => {
            return reject("load_search: mechanism_at_static is true, but lambda_static is unbounded")
        }
        (true, Some(_)) if !at_static => {
            return reject(format!(
                "load_search: mechanism_at_static is true, but no listed limit state (or continuum of them) reaches [lambda_lo, lambda_hi] (from {lo})"
            ))
        }
        (false, Some(_)) if isolated_at_static => {
            return reject(format!(
                "load_search: mechanism_at_static is false, but a listed limit state lies in [lambda_lo, lambda_hi] (from {lo})"
            ))
        }
        _ => {}
    }
    Ok(())
}

/// The state at λ_static listed without a mechanism, proved to carry none; pushes the
/// report's line.
fn static_state(
    model: &Model,
    live: &Live,
    mu: Option<f64>,
    search: &LoadSearchEvidence,
    (lo, hi): (f64, Option<f64>),
    checks: &mut Vec<String>,
) -> Result<(), Rejection> {
    match (&search.static_state, hi) {
        (Some(_), _) if search.mechanism_at_static => {
            return reject("load_search: a static_state without mechanism is listed, but mechanism_at_static is true")
        }
        (Some(_), None) => {
            return reject("load_search: a static_state is listed, but lambda_static is unbounded")
        }
        (Some(p), Some(h)) => {
            if !(p.lambda >= lo && p.lambda <= h) {
                return reject(format!(
                    "load_search: static_state lambda = {} lies outside [lambda_lo, lambda_hi]",
                    p.lambda
                ));
            }
            let proved = no_mechanism(
                model,
                mu,
                state_at(live, p.lambda, p.x),
                &p.pattern,
                &p.farkas,
                "load_search: static_state",
            )?;
            checks.push(if proved {
                format!(
                    "proved (interval arithmetic): the {} contacts active at the state at lambda_static (lambda = {}) carry no mechanism with non-negative total and live power (Farkas); checked (floating point): they are its whole active set{}",
                    p.pattern.len(),
                    p.lambda,
                    if model.joints.is_some() { "" } else { " (at the listed contacts; a continuous arch's other angles are not enumerated)" }
                )
            } else {
                format!(
                    "not proved: the state at lambda_static (lambda = {}) carries no mechanism (no Farkas certificate covers every sliding sense)",
                    p.lambda
                )
            });
        }
        (None, Some(_)) if !search.mechanism_at_static => checks.push(
            "not proved: that the state at lambda_static carries no mechanism (no evidence listed)"
                .into(),
        ),
        _ => {}
    }
    Ok(())
}

/// The method's own evidence: the sweep's points without a mechanism, virtual work at
/// μ = ∞, or the refinement (not re-checked); pushes the report's lines.
fn method_evidence(
    model: &Model,
    live: &Live,
    mu: Option<f64>,
    search: &LoadSearchEvidence,
    (lo, hi): (f64, Option<f64>),
    checks: &mut Vec<String>,
) -> Result<(), Rejection> {
    let states = &search.limit_states;
    match search.method {
        LoadSearchMethod::Sweep => {
            if model.joints.is_none() {
                return reject("load_search: method sweep needs a discrete arch");
            }
            if mu.is_none() {
                return reject(
                    "load_search: method sweep is for finite friction (mu = inf is associative)",
                );
            }
            let mut proved = 0;
            for (i, p) in search.no_mechanism.iter().enumerate() {
                let top = hi.unwrap_or(f64::INFINITY);
                if !(p.lambda >= search.lambda_min && p.lambda <= top) {
                    return reject(format!(
                        "load_search: no_mechanism {i}: lambda = {} lies outside [lambda_min, lambda_hi]",
                        p.lambda
                    ));
                }
                if no_mechanism(
                    model,
                    mu,
                    state_at(live, p.lambda, p.x),
                    &p.pattern,
                    &p.farkas,
                    &format!("load_search: no_mechanism {i}"),
                )? {
                    proved += 1;
                }
            }
            let n = search.no_mechanism.len();
            checks.push(format!(
                "proved (interval arithmetic) at {proved} of the {n} points the sweep checked without finding a mechanism ({} events): their active contacts carry no mechanism with non-negative total and live power (Farkas); not re-proved: that the sweep met every event of P(lambda) (docs/loads.md), so that no limit state lies between them",
                search.events
            ));
            if proved < n {
                checks.push(format!(
                    "not proved: {} points of the sweep have no Farkas certificate covering every sliding sense",
                    n - proved
                ));
            }
        }
        LoadSearchMethod::Associative => {
            if mu.is_some() {
                return reject(
                    "load_search: method associative needs infinite friction (mu = null)",
                );
            }
            if !search.no_mechanism.is_empty() {
                return reject("load_search: method associative lists no sweep points");
            }
            if states.iter().any(|s| s.lambda < lo) {
                return reject(format!(
                    "load_search (associative): a limit state below lambda_lo = {lo} is listed, which virtual work rules out"
                ));
            }
            checks.push(match hi {
                Some(_) => format!(
                    "proved (virtual work, mu = inf): no limit state lies below lambda_lo = {lo}: a hinge-only mechanism dissipates nothing, so a limit state at lambda* admits no state at any lambda > lambda*, and one is proved admissible at lambda_lo; with lambda_hi, every limit state lies in [lambda_lo, lambda_hi)"
                ),
                None => "proved (virtual work, mu = inf): no limit state exists: a hinge-only mechanism dissipates nothing, so a limit state at lambda* admits no state at any lambda > lambda*, and states are proved admissible at every lambda from lambda_lo on".to_string(),
            });
        }
        LoadSearchMethod::Refined => {
            if model.joints.is_some() {
                return reject("load_search: method refined is for a continuous arch");
            }
            if !search.no_mechanism.is_empty() {
                return reject("load_search: method refined lists no sweep points");
            }
            checks.push("not re-checked: that the refined limit states of two discretisations agreed (method refined); the listed states are checked above".into());
        }
    }
    Ok(())
}

/// The one-line verdict on the limit states listed.
fn verdict(search: &LoadSearchEvidence, unique: bool) -> String {
    let states = &search.limit_states;
    let verdict = match (states.len(), unique) {
        (0, _) => "no limit state: the load never drives a mechanism".to_string(),
        (1, true) => format!(
            "one limit state, lambda = {} (unique{})",
            states[0].lambda,
            if search.mechanism_at_static {
                ", at lambda_static"
            } else {
                ""
            }
        ),
        (n, _) => format!(
            "{n} limit states, the least at lambda = {} (not unique{})",
            states[0].lambda,
            if states.iter().any(|s| s.continuum.is_some()) {
                "; with a continuum"
            } else {
                ""
            }
        ),
    };
    format!(
        "the search ({}) lists {verdict}",
        match search.method {
            LoadSearchMethod::Sweep => "sweep",
            LoadSearchMethod::Associative => "associative",
            LoadSearchMethod::Refined => "refined",
        }
    )
}
