//! A kind re-proved: the point's certificate ([`crate::certificate::certify`]) checked by
//! the independent verifier ([`crate::certificate::verify`]), and the kind read from what
//! the verified certificate states (its claim and its limit-state search).

use super::classify::Kind;
use crate::arch::Arch;
use crate::certificate::{certify_found, certify_load, verify, Claim};
use crate::limit_states::LimitState;
use crate::load::LiveLoad;
use crate::settings::Settings;

/// The relative gap of the η* brackets the atlas certifies (wide enough to be cheap; the kind
/// does not depend on it).
const ATLAS_GAP: f64 = 1e-9;

/// A reduction of the collapse multiplier re-proved: the load certificate of `load` at
/// (`eta`, `mu`) ([`certify_load`]), checked by the independent verifier, proves λ_static in
/// a bracket [λ_lo, λ_hi] and lists a limit state at λ_c < λ_lo (each listed state checked
/// by the verifier), so λ_c/λ_static ≤ λ_c/λ_lo. Returns that certified least reduction,
/// 1 − λ_c/λ_lo (the least listed state's λ_c), or why there is none.
pub fn certified_reduction(
    arch: &Arch,
    (eta, mu): (f64, f64),
    load: &LiveLoad,
    settings: &Settings,
) -> Result<f64, String> {
    let cert = certify_load(arch, eta, mu, load, ATLAS_GAP, settings).map_err(|e| e.0)?;
    let report =
        verify(&cert).map_err(|r| format!("the verifier rejected the certificate: {}", r.0))?;
    let Some((lo, Some(_))) = report.lambda_bracket else {
        return Err("the certificate proves no finite lambda_static".into());
    };
    let least = cert
        .load_search
        .as_ref()
        .and_then(|s| s.limit_states.first())
        .ok_or("the certificate lists no limit state")?;
    let reduction = 1.0 - least.lambda / lo;
    if reduction > 0.0 {
        Ok(reduction)
    } else {
        Err(format!(
            "its least listed limit state (lambda = {}) is not below the proved lambda_static >= {lo}",
            least.lambda
        ))
    }
}

/// The kind at (arch, μ) as a verified certificate states it, and whether the verifier
/// proved the certificate's list of limit states complete (the ridge evidence of a voussoir
/// arch; a no-equilibrium claim has no list to complete) or only checked each listed state;
/// or why there is no such certificate.
pub fn certified_kind(arch: &Arch, mu: f64, settings: &Settings) -> Result<(Kind, bool), String> {
    certified_kind_with(arch, mu, &[], settings)
}

/// [`certified_kind`] with limit states above η_s known at `mu` from elsewhere (followed
/// from a neighbouring friction: [`crate::certificate::certify_found`]).
pub fn certified_kind_with(
    arch: &Arch,
    mu: f64,
    found: &[LimitState],
    settings: &Settings,
) -> Result<(Kind, bool), String> {
    let cert = certify_found(arch, mu, ATLAS_GAP, found, settings).map_err(|e| e.0)?;
    verify(&cert).map_err(|r| format!("the verifier rejected the certificate: {}", r.0))?;
    match cert.claim {
        Claim::NoEquilibrium => return Ok((Kind::NoEquilibrium, true)),
        Claim::StandsAtEveryThickness => {
            let complete = cert.search.as_ref().is_some_and(|s| s.ridge.is_some());
            return Ok((Kind::NoMechanismAtEta, complete));
        }
        Claim::LeastThickness => {}
        other => return Err(format!("a {} claim", other.name())),
    }
    let search = cert
        .search
        .as_ref()
        .ok_or("the certificate lists no limit states")?;
    let kind = if !search.mechanism_at_eta {
        Kind::NoMechanismAtEta
    } else if search.unique {
        Kind::Unique
    } else {
        Kind::NonUnique
    };
    Ok((kind, search.ridge.is_some()))
}

/// Whether a verified certificate at (arch, μ) states `want` ([`certified_kind_with`], with
/// `found` listed): `Ok` with whether the verifier proved its list complete, else why not.
pub(super) fn states_kind(
    arch: &Arch,
    mu: f64,
    want: Kind,
    found: &[LimitState],
    settings: &Settings,
) -> Result<bool, String> {
    match certified_kind_with(arch, mu, found, settings) {
        Ok((k, complete)) if k == want => Ok(complete),
        Ok((k, _)) => Err(format!("the certificate at mu = {mu} states {}", k.name())),
        Err(e) => Err(format!("at mu = {mu}: {e}")),
    }
}
