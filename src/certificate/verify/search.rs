//! Re-checking the evidence of the limit-state search (the `search` section of a
//! certificate): which limit states exist with η in [η_s, 2).
//!
//! * **No mechanism** at a listed state (the least admissible state, or a point of the
//!   sweep): *proved* in interval arithmetic by the Farkas alternative of the kinematic LP
//!   on the listed contacts — `c_j · y + z + u p_j ≤ 0` for every contact kept, z > 0,
//!   u ≥ 0, so no rates λ ≥ 0, Σ λ = 1, B λ = 0, L_e = p · λ ≥ 0 exist — for every choice
//!   of one sliding sense at a joint where both are listed. That the listed contacts are
//!   the state's whole active set is *checked* in floating point (for a discrete arch,
//!   every other contact at every joint at least
//!   [`INACTIVE_REL`](super::mechanism::INACTIVE_REL) below zero).
//! * **Limit states above η_s**: admissibility at the joints (floating point) and the
//!   consistency of the mechanism, as for the certificate's limit state.
//! * **μ = ∞** (`hinges_only`): the safe state is *proved* to lie strictly inside P(η_hi)
//!   (every φ < 0 over the whole arch); a hinge-only mechanism λ has λᵀφ(x) = L_e(λ) for
//!   every x (formulation §6), so a limit state needs P(η) without interior, and P(η) grows
//!   with η: no limit state has η ≥ η_hi.
//!
//! What is *not* re-proved: that the sweep met every event (its completeness argument,
//! docs/limit-states.md), or that two discretisations agreed (`refined`).

use super::enclosure::prove_admissible;
use super::joints::check_pattern;
use super::limit_state::{check_limit_state, LIMIT_STATE_TOL};
use super::mechanism::{no_mechanism, StateAt};
use super::report::{reject, Rejection};
use super::statics::{kinds, phi, Model};
use crate::certificate::format::{
    Certificate, LimitStateCert, NoMechanism, SafeSide, SearchEvidence, SearchMethod,
};
use crate::certificate::interval::Interval as I;

/// Samples of a continuous arch for the floating-point admissibility check of a limit
/// state above η_s.
const SAMPLES: usize = 2000;

/// Re-checks `search` against the bracket [η_lo, safe.eta]; returns the lines of the
/// report (each saying proved or checked) and the one-line verdict on the limit states.
pub(super) fn verify_search(
    model: &Model,
    cert: &Certificate,
    search: &SearchEvidence,
    eta_lo: f64,
    safe: &SafeSide,
) -> Result<(Vec<String>, String), Rejection> {
    let mut checks = Vec::new();
    let count = check_listing(cert, search)?;
    least_state(model, cert.mu, search, eta_lo, safe, &mut checks)?;
    limit_states_above(model, cert.mu, search, eta_lo, safe, &mut checks)?;
    method_evidence(model, cert.mu, search, safe, &mut checks)?;
    Ok((checks, verdict(search, count)))
}

/// The listing agrees with itself and with the certificate: `unique` with the number of
/// limit states listed (returned), the certificate's limit state the least one.
fn check_listing(cert: &Certificate, search: &SearchEvidence) -> Result<usize, Rejection> {
    let count = usize::from(search.mechanism_at_eta) + search.limit_states_above.len();
    if search.unique != (count == 1) {
        return reject(format!(
            "search: unique = {} but {count} limit states are listed (mechanism at eta_s: {}, {} above)",
            search.unique,
            search.mechanism_at_eta,
            search.limit_states_above.len()
        ));
    }
    // the certificate's limit state is the least one
    let least = if search.mechanism_at_eta {
        cert.limit_state.as_ref()
    } else {
        search.limit_states_above.first()
    };
    match (least, &cert.limit_state) {
        (Some(a), Some(b)) if a.eta == b.eta && a.x == b.x => {}
        (None, None) => {}
        _ => return reject(
            "search: the certificate's limit_state is not the least limit state the search lists",
        ),
    }
    if search.mechanism_at_eta && cert.limit_state.is_none() {
        return reject("search: mechanism_at_eta is true but no limit_state is given");
    }
    Ok(count)
}

/// The least admissible state without a mechanism, proved to carry none (or said not to
/// be attained); pushes the report's line.
fn least_state(
    model: &Model,
    mu: Option<f64>,
    search: &SearchEvidence,
    eta_lo: f64,
    safe: &SafeSide,
    checks: &mut Vec<String>,
) -> Result<(), Rejection> {
    if let Some(ls) = &search.least_state {
        if search.mechanism_at_eta {
            return reject(
                "search: a least_state without mechanism is listed, but mechanism_at_eta is true",
            );
        }
        if !(ls.eta >= eta_lo && ls.eta <= safe.eta) {
            return reject(format!(
                "search: least_state eta = {} lies outside [eta_lo, eta_hi]",
                ls.eta
            ));
        }
        let proved = thickness_no_mechanism(model, mu, ls, "search: least_state")?;
        checks.push(if proved {
            format!(
                "proved (interval arithmetic): the {} contacts active at the least admissible state (eta = {}) carry no mechanism without dilatancy (Farkas); checked (floating point): they are its whole active set{}",
                ls.pattern.len(),
                ls.eta,
                if model.joints.is_some() { "" } else { " (at the listed contacts; a continuous arch's other angles are not enumerated)" }
            )
        } else {
            format!(
                "not proved: the least admissible state (eta = {}) carries no mechanism (no Farkas certificate covers every sliding sense)",
                ls.eta
            )
        });
    } else if !search.mechanism_at_eta {
        checks.push("no least admissible state is listed: eta_s is not attained by a bounded state (an infimum), so no limit state exists there".into());
    }
    Ok(())
}

/// The limit states listed above η_s, each checked in floating point (ascending, finite,
/// admissible, with a mechanism); pushes the report's line.
fn limit_states_above(
    model: &Model,
    mu: Option<f64>,
    search: &SearchEvidence,
    eta_lo: f64,
    safe: &SafeSide,
    checks: &mut Vec<String>,
) -> Result<(), Rejection> {
    let mut last = safe.eta;
    for (i, ls) in search.limit_states_above.iter().enumerate() {
        let whose = format!("search: limit state above eta_s {i}");
        finite(ls, &whose)?;
        check_pattern(model, &ls.pattern, mu, None, &whose)?;
        if ls.eta < last {
            return reject(format!(
                "{whose}: eta = {} is not above eta_hi and the previous listed state (not ascending)",
                ls.eta
            ));
        }
        last = ls.eta;
        check_limit_state(model, mu, ls, eta_lo, 2.0)?;
        admissible_at_samples(model, mu, ls, &whose)?;
    }
    if !search.limit_states_above.is_empty() {
        checks.push(format!(
            "checked (floating point, tolerance {LIMIT_STATE_TOL:e}; evidence, not proof): {} limit state(s) above eta_s, admissible, each with a mechanism without dilatancy (eta = {})",
            search.limit_states_above.len(),
            search
                .limit_states_above
                .iter()
                .map(|s| s.eta.to_string())
                .collect::<Vec<_>>()
                .join(", ")
        ));
    }
    Ok(())
}

/// The method's own evidence: the sweep's points without a mechanism, the safe state
/// strictly inside at μ = ∞, or the refinement (not re-checked); pushes the report's lines.
fn method_evidence(
    model: &Model,
    mu: Option<f64>,
    search: &SearchEvidence,
    safe: &SafeSide,
    checks: &mut Vec<String>,
) -> Result<(), Rejection> {
    match search.method {
        SearchMethod::Sweep => {
            if model.joints.is_none() {
                return reject("search: method sweep needs a discrete arch");
            }
            let mut proved = 0;
            for (i, p) in search.no_mechanism.iter().enumerate() {
                if thickness_no_mechanism(model, mu, p, &format!("search: no_mechanism {i}"))? {
                    proved += 1;
                }
            }
            let n = search.no_mechanism.len();
            checks.push(format!(
                "proved (interval arithmetic) at {proved} of the {n} points the sweep checked without finding a mechanism ({} events): their active contacts carry no mechanism (Farkas); not re-proved: that the sweep met every event (docs/limit-states.md)",
                search.events
            ));
            if proved < n {
                checks.push(format!(
                    "not proved: {} points of the sweep have no Farkas certificate covering every sliding sense",
                    n - proved
                ));
            }
        }
        SearchMethod::HingesOnly => {
            if mu.is_some() {
                return reject("search: method hinges_only needs infinite friction (mu = null)");
            }
            if !search.limit_states_above.is_empty() || !search.no_mechanism.is_empty() {
                return reject("search: method hinges_only lists nothing above eta_s");
            }
            prove_admissible(model, safe.x, safe.eta, mu, true).map_err(|e| {
                Rejection(format!("search (hinges_only): the safe state is not proved strictly inside P(eta_hi): {}", e.0))
            })?;
            checks.push(format!(
                "proved (interval arithmetic): the safe state lies strictly inside P(eta_hi) (every phi < 0 over the whole arch), so at mu = inf no limit state has eta >= {} (a hinge-only mechanism needs P(eta) without interior, formulation §6)",
                safe.eta
            ));
        }
        SearchMethod::Refined => {
            if model.joints.is_some() {
                return reject("search: method refined is for a continuous arch");
            }
            checks.push("not re-checked: that the refined limit states of two discretisations agreed (method refined); the listed states are checked above".into());
        }
    }
    Ok(())
}

/// The one-line verdict on the `count` limit states listed.
fn verdict(search: &SearchEvidence, count: usize) -> String {
    let verdict = match (count, search.mechanism_at_eta) {
        (0, _) => {
            "no limit state with eta in [eta_s, 2): the arch is safe from eta_s on".to_string()
        }
        (1, true) => "one limit state with eta in [eta_s, 2), at eta_s (unique)".to_string(),
        (1, false) => "one limit state with eta in [eta_s, 2), above eta_s (unique; none at eta_s)"
            .to_string(),
        (n, _) => format!("{n} limit states with eta in [eta_s, 2) (not unique)"),
    };
    format!(
        "the search ({}) lists {verdict}",
        method_name(search.method)
    )
}

/// [`no_mechanism`] for a state of the thickness problem.
fn thickness_no_mechanism(
    model: &Model,
    mu: Option<f64>,
    p: &NoMechanism,
    whose: &str,
) -> Result<bool, Rejection> {
    let state = StateAt {
        x: p.x,
        eta: p.eta,
        load: None,
    };
    no_mechanism(model, mu, state, &p.pattern, &p.farkas, whose)
}

fn method_name(m: SearchMethod) -> &'static str {
    match m {
        SearchMethod::Sweep => "sweep",
        SearchMethod::HingesOnly => "hinges only",
        SearchMethod::Refined => "refined",
    }
}

fn finite(ls: &LimitStateCert, whose: &str) -> Result<(), Rejection> {
    let ok = ls.eta.is_finite()
        && ls.x.iter().all(|v| v.is_finite())
        && ls.rates.iter().all(|v| v.is_finite())
        && ls.pattern.iter().all(|j| j.beta.is_finite());
    if ok {
        Ok(())
    } else {
        reject(format!("{whose}: every number must be finite"))
    }
}

/// φ ≤ tol·(1 + ‖x‖₁) at every joint (discrete) or at [`SAMPLES`] angles (continuous):
/// a floating-point check.
fn admissible_at_samples(
    model: &Model,
    mu: Option<f64>,
    ls: &LimitStateCert,
    whose: &str,
) -> Result<(), Rejection> {
    let scale = 1.0 + ls.x.iter().map(|v| v.abs()).sum::<f64>();
    let angles: Vec<f64> = match &model.joints {
        Some(j) => j.clone(),
        None => (0..=SAMPLES)
            .map(|i| model.beta_r + (model.beta_l - model.beta_r) * i as f64 / SAMPLES as f64)
            .collect(),
    };
    for &b in &angles {
        let a = model.ntm(I::point(b), ls.x, ls.eta);
        for &k in kinds(mu) {
            let v = phi(k, 0, &a, ls.eta, mu).mid();
            if v.is_nan() || v > LIMIT_STATE_TOL * scale {
                return reject(format!(
                    "{whose}: not admissible, {} = {v:e} > 0 at beta = {b}",
                    k.name()
                ));
            }
        }
    }
    Ok(())
}
