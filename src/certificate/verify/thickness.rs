//! Re-checking a thickness certificate (`least_thickness` or `no_equilibrium`): the safe
//! state proved admissible at η_hi over the whole arch, the Farkas certificate proved at
//! η_lo, the limit state checked, and the `search` section re-checked ([`super::search`]).

use super::enclosure::prove_state;
use super::farkas::prove_farkas;
use super::input::check_gap;
use super::joints::check_pattern;
use super::limit_state::check_limit_state;
use super::live::StateAt;
use super::report::{mu_text, reject, Rejection, Report};
use super::search::verify_search;
use super::statics::{Model, LIMIT_STATE_TOL};
use crate::certificate::format::{CertJoint, Certificate, Claim};

/// Re-checks a certificate of the thickness problem (`least_thickness` or
/// `no_equilibrium`, no load section) on its checked arch `model`.
pub(super) fn verify_thickness(cert: &Certificate, model: &Model) -> Result<Report, Rejection> {
    let mut checks = Vec::new();
    let mut limit_states = None;
    let bracket = match cert.claim {
        Claim::LargestMultiplier | Claim::UnboundedMultiplier => {
            unreachable!("load claims are verified by verify_load")
        }
        Claim::NoEquilibrium => {
            checks.push(no_equilibrium(cert, model)?);
            None
        }
        Claim::LeastThickness => {
            let (bracket, verdict) = least_thickness(cert, model, &mut checks)?;
            limit_states = verdict;
            Some(bracket)
        }
    };
    Ok(Report {
        claim: cert.claim,
        mu: cert.mu,
        bracket,
        arch: cert.arch.clone(),
        checks,
        limit_states,
        load: None,
        lambda_bracket: None,
    })
}

/// The thickness limit: every arch has η < 2 (t < 2r).
const ETA_LIMIT: f64 = 2.0;

/// `no_equilibrium`: the friction-only Farkas certificate (`eta` null), or the Farkas
/// certificate at the thickness limit η = 2 (centreline weight); proved; returns the
/// report's line.
fn no_equilibrium(cert: &Certificate, model: &Model) -> Result<String, Rejection> {
    let Some(f) = &cert.collapse else {
        return reject("no_equilibrium claim without a Farkas certificate");
    };
    if cert.safe.is_some() || cert.limit_state.is_some() || cert.search.is_some() {
        return reject("a no_equilibrium claim cannot carry a safe state or a limit state");
    }
    if let Some(eta) = f.eta {
        return no_equilibrium_at_limit(cert, model, &f.joints, eta);
    }
    if cert.mu.is_none() {
        return reject("no_equilibrium claim at infinite friction (mu = null): the friction-only problem has no sliding rows there");
    }
    let margin = prove_farkas(model, &f.joints, 1.0, cert.mu, true)?;
    Ok(format!(
        "proved (interval arithmetic): no (h, v) satisfies |T| <= mu N at the {} listed joints (Farkas, margin {margin:.3e}), so no thickness can stand at mu = {}",
        f.joints.len(),
        mu_text(cert.mu)
    ))
}

/// `no_equilibrium` by a Farkas certificate at η = 2: no state is admissible at the
/// thickness limit. With the weight along the centreline N, T and M do not involve η; a
/// state admissible at some η < 2 has N ≥ 0 (the sum of its two hinge rows is −ηN ≤ 0),
/// so its hinge rows ±M − ηN/2 only decrease as η grows to 2: it would be admissible
/// at η = 2. So no thickness stands.
fn no_equilibrium_at_limit(
    cert: &Certificate,
    model: &Model,
    joints: &[CertJoint],
    eta: f64,
) -> Result<String, Rejection> {
    if eta != ETA_LIMIT {
        return reject(format!(
            "collapse side: a no_equilibrium certificate with a thickness has eta = 2 (the thickness limit), found {eta}"
        ));
    }
    if model.centroid {
        return reject("a no_equilibrium certificate at eta = 2 needs the centreline weight (with the true-centroid weight the admissible set is not monotone in eta)");
    }
    let margin = prove_farkas(model, joints, eta, cert.mu, false)?;
    Ok(format!(
        "proved (interval arithmetic): no state is admissible at the thickness limit eta = 2 (Farkas on 4 joints, margin {margin:.3e}); with the weight along the centreline a state admissible at any eta < 2 (N >= 0 there) would be admissible at eta = 2, so no thickness stands at mu = {}",
        mu_text(cert.mu)
    ))
}

/// `least_thickness`: the safe state proved admissible at η_hi, the Farkas certificate
/// proved at η_lo, the stated gaps, the limit state checked and the `search` section
/// re-checked; pushes the report's lines and returns (η_lo, η_hi) and the verdict on the
/// limit states (with a `search` section).
fn least_thickness(
    cert: &Certificate,
    model: &Model,
    checks: &mut Vec<String>,
) -> Result<((f64, f64), Option<String>), Rejection> {
    let (Some(safe), Some(col)) = (&cert.safe, &cert.collapse) else {
        return reject("least_thickness claim needs both a safe state and a Farkas certificate");
    };
    let Some(eta_lo) = col.eta else {
        return reject("collapse side: missing eta");
    };
    if !(eta_lo > 0.0 && safe.eta < 2.0 && eta_lo <= safe.eta) {
        return reject(format!(
            "need 0 < eta_lo <= eta_hi < 2, found eta_lo = {eta_lo}, eta_hi = {}",
            safe.eta
        ));
    }
    if let Some(ls) = &cert.limit_state {
        check_pattern(model, &ls.pattern, cert.mu, None, "limit state")?;
    }
    let pieces = prove_state(
        model,
        StateAt::bare(safe.x, safe.eta),
        cert.mu,
        false,
        "safe side",
    )?;
    checks.push(format!(
        "proved (interval arithmetic): the state x = [{}, {}, {}] is admissible at eta_hi = {} over the whole arch ({pieces} enclosures)",
        safe.x[0], safe.x[1], safe.x[2], safe.eta
    ));
    let margin = prove_farkas(model, &col.joints, eta_lo, cert.mu, false)?;
    checks.push(format!(
        "proved (interval arithmetic): no state is admissible at eta_lo = {eta_lo} (Farkas on {} joints, margin {margin:.3e})",
        col.joints.len()
    ));
    check_gap(cert, eta_lo, safe.eta, "eta")?;
    if let Some(ls) = &cert.limit_state {
        // the least limit state lies above η_s where η_s carries no mechanism
        let above = cert.search.as_ref().is_some_and(|s| !s.mechanism_at_eta);
        check_limit_state(
            model,
            cert.mu,
            ls,
            eta_lo,
            if above { 2.0 } else { safe.eta },
        )?;
        checks.push(format!(
            "checked (floating point, tolerance {LIMIT_STATE_TOL:e}; evidence, not proof): the limit state at eta = {} is consistent (pattern active, B lambda = 0, lambda >= 0, sum 1, L_e >= 0)",
            ls.eta
        ));
    }
    let mut verdict = None;
    if let Some(search) = &cert.search {
        let (lines, v) = verify_search(model, cert, search, eta_lo, safe)?;
        checks.extend(lines);
        verdict = Some(v);
    }
    Ok(((eta_lo, safe.eta), verdict))
}
