//! Re-checking a load certificate: the claims about the largest admissible
//! multiplier λ_static of a live load at fixed (η, μ), with the live actions of
//! [`super::live`] (docs/loads.md, written out again) and the same interval arithmetic
//! as the thickness certificates.
//!
//! * `largest_multiplier`: the state (x_lo, λ_lo) is *proved* admissible — at every joint
//!   of a discrete arch, or over the whole continuum by Taylor enclosures, on both sides of
//!   a loaded section — and the Farkas certificate at λ_hi is *proved* (four contacts, the
//!   signed cofactors of their x-gradients; the live terms enter the constants). The
//!   admissible (x, λ) form a convex set: a state at some λ ≥ λ_hi would put one at λ_hi on
//!   the segment from (x_lo, λ_lo). So λ_lo ≤ λ_static < λ_hi.
//! * `unbounded_multiplier`: (x_0, λ_0) is *proved* admissible and the stated transfer is
//!   *proved* to keep it admissible as λ grows: along (x_0 + t d, λ_0 + t) every activation
//!   function is φ(x_0, λ_0) + t ψ, with ψ ≤ 0 proved at every section (ψ = 0 identically
//!   where the transfer cancels the load, by an identity of the statics).
//! * `no_equilibrium` under a load: five rows in (h, v, w, λ) (with, possibly, −λ ≤ 0),
//!   the cofactors of their 4-gradients: no state at any λ ≥ 0.

use super::enclosure::prove_state;
use super::farkas::prove_infeasible;
use super::input::check_gap;
use super::live::{everywhere, Live, StateAt};
use super::load_unbounded::{prove_recession, prove_transfer};
use super::report::{reject, Rejection, Report};
use super::search::verify_load_search;
use super::statics::Model;
use crate::certificate::format::{Certificate, Claim, LoadState, MultiplierSides};

/// Verifies a certificate with a `load` section (`cert.load` must be present).
pub(super) fn verify_load(cert: &Certificate, model: &Model) -> Result<Report, Rejection> {
    let Some(spec) = &cert.load else {
        return reject(format!(
            "a {} claim needs a load section",
            cert.claim.name()
        ));
    };
    if matches!(
        cert.claim,
        Claim::LeastThickness | Claim::StandsAtEveryThickness
    ) {
        return reject(format!(
            "a {} claim carries no load section",
            cert.claim.name()
        ));
    }
    if cert.safe.is_some()
        || cert.collapse.is_some()
        || cert.collapse_cells.is_some()
        || cert.limit_state.is_some()
        || cert.search.is_some()
    {
        return reject("a load certificate carries none of the thickness sections (safe, collapse, collapse_cells, limit_state, search)");
    }
    let live = Live::of(spec, model)?;
    let Some(sides) = &cert.multiplier else {
        return reject("a load certificate needs a multiplier section");
    };
    let mu = cert.mu;
    let mut checks = Vec::new();
    let lambda_bracket = match cert.claim {
        Claim::LargestMultiplier => {
            Some(largest_multiplier(cert, model, &live, sides, &mut checks)?)
        }
        Claim::UnboundedMultiplier => Some(unbounded_multiplier(
            cert,
            model,
            &live,
            sides,
            &mut checks,
        )?),
        Claim::NoEquilibrium => {
            no_equilibrium(cert, model, &live, sides, &mut checks)?;
            None
        }
        Claim::LeastThickness | Claim::StandsAtEveryThickness => unreachable!("checked above"),
    };
    let limit_states = match &cert.load_search {
        Some(search) => {
            let Some((lo, hi)) = lambda_bracket else {
                return reject("load_search: the limit states need a multiplier claim with an admissible state");
            };
            let (lines, verdict) = verify_load_search(model, &live, mu, search, lo, hi)?;
            checks.extend(lines);
            Some(verdict)
        }
        None => None,
    };
    Ok(Report {
        claim: cert.claim,
        mu,
        bracket: None,
        arch: cert.arch.clone(),
        checks,
        limit_states,
        load: Some(live.text()),
        lambda_bracket,
    })
}

/// `largest_multiplier`: the state at λ_lo proved admissible and the Farkas certificate
/// at λ_hi proved; pushes the report's lines and returns (λ_lo, λ_hi).
fn largest_multiplier(
    cert: &Certificate,
    model: &Model,
    live: &Live,
    sides: &MultiplierSides,
    checks: &mut Vec<String>,
) -> Result<(f64, Option<f64>), Rejection> {
    let mu = cert.mu;
    let (Some(adm), Some(inf), None, None) = (
        &sides.admissible,
        &sides.infeasible,
        sides.transfer,
        &sides.recession,
    ) else {
        return reject("largest_multiplier: needs multiplier.admissible and multiplier.infeasible (and no transfer or recession)");
    };
    let Some(lambda_hi) = inf.lambda else {
        return reject("largest_multiplier: multiplier.infeasible.lambda (lambda_hi) is missing");
    };
    check_state(adm, "multiplier.admissible")?;
    if !(lambda_hi.is_finite() && adm.lambda <= lambda_hi) {
        return reject(format!(
            "need 0 <= lambda_lo <= lambda_hi, found lambda_lo = {}, lambda_hi = {lambda_hi}",
            adm.lambda
        ));
    }
    checks.push(admissible_line(model, live, adm, mu, "lambda_lo")?);
    let margin = prove_infeasible(model, live, inf, Some(lambda_hi), mu)?;
    checks.push(format!(
        "proved (interval arithmetic): no state is admissible at lambda_hi = {lambda_hi} (Farkas on {} joints{}, margin {margin:.3e}); the admissible (x, lambda) are convex, so none at any lambda >= lambda_hi",
        inf.joints.len(),
        if inf.joints.len() == 3 { ", sliding rows in (h, v): w does not enter them" } else { "" }
    ));
    check_gap(cert, adm.lambda, lambda_hi, "lambda")?;
    Ok((adm.lambda, Some(lambda_hi)))
}

/// The state `adm` proved admissible at its λ (named `at` in the report), and the report's
/// line.
fn admissible_line(
    model: &Model,
    live: &Live,
    adm: &LoadState,
    mu: Option<f64>,
    at: &str,
) -> Result<String, Rejection> {
    let state = StateAt::loaded(live, adm.lambda, adm.x);
    let pieces = prove_state(model, state, mu, false, "admissible side")?;
    Ok(format!(
        "proved (interval arithmetic): the state x = [{}, {}, {}] is admissible at {at} = {} {} ({pieces} enclosures)",
        adm.x[0], adm.x[1], adm.x[2], adm.lambda, everywhere(model, live)
    ))
}

/// `unbounded_multiplier`: the state proved admissible and the transfer or the recession
/// direction proved to keep it so; pushes the report's lines and returns (λ, `None`).
fn unbounded_multiplier(
    cert: &Certificate,
    model: &Model,
    live: &Live,
    sides: &MultiplierSides,
    checks: &mut Vec<String>,
) -> Result<(f64, Option<f64>), Rejection> {
    let mu = cert.mu;
    let (Some(adm), None) = (&sides.admissible, &sides.infeasible) else {
        return reject("unbounded_multiplier: needs multiplier.admissible and a transfer or a recession direction (and no infeasible side)");
    };
    check_state(adm, "multiplier.admissible")?;
    if cert.gap.is_some() || cert.gap_relative.is_some() {
        return reject("unbounded_multiplier: a gap is stated, but there is no bracket");
    }
    checks.push(admissible_line(model, live, adm, mu, "lambda")?);
    checks.push(match (sides.transfer, &sides.recession) {
        (Some(transfer), None) => prove_transfer(model, live, transfer, mu)?,
        (None, Some(d)) => prove_recession(model, live, d, mu)?,
        _ => return reject("unbounded_multiplier: needs exactly one of multiplier.transfer and multiplier.recession"),
    });
    Ok((adm.lambda, None))
}

/// `no_equilibrium` under a load: the Farkas certificate over every λ ≥ 0 proved; pushes
/// the report's line.
fn no_equilibrium(
    cert: &Certificate,
    model: &Model,
    live: &Live,
    sides: &MultiplierSides,
    checks: &mut Vec<String>,
) -> Result<(), Rejection> {
    let mu = cert.mu;
    let (None, Some(inf), None, None) = (
        &sides.admissible,
        &sides.infeasible,
        sides.transfer,
        &sides.recession,
    ) else {
        return reject("no_equilibrium under a load: needs multiplier.infeasible only");
    };
    if inf.lambda.is_some() {
        return reject("no_equilibrium under a load: multiplier.infeasible.lambda must be null (the certificate covers every lambda >= 0)");
    }
    if cert.gap.is_some() || cert.gap_relative.is_some() {
        return reject("no_equilibrium: a gap is stated, but there is no bracket");
    }
    let margin = prove_infeasible(model, live, inf, None, mu)?;
    checks.push(format!(
        "proved (interval arithmetic): no state (h, v, w, lambda) with lambda >= 0 is admissible (Farkas on {} joints{}, margin {margin:.3e})",
        inf.joints.len(),
        if inf.lambda_row.is_some() { " and the row -lambda <= 0" } else { "" }
    ));
    Ok(())
}

/// A state (x, λ) as read: λ finite and ≥ 0, x finite.
pub(super) fn check_state(s: &LoadState, what: &str) -> Result<(), Rejection> {
    if !(s.lambda.is_finite() && s.lambda >= 0.0 && s.x.iter().all(|v| v.is_finite())) {
        return reject(format!(
            "{what}: lambda must be finite and >= 0 and x finite, found lambda = {}",
            s.lambda
        ));
    }
    Ok(())
}
