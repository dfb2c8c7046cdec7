//! A kind re-proved: the point's certificate ([`crate::certificate::certify`]) checked by
//! the independent verifier ([`crate::certificate::verify`]), and the kind read from what
//! the verified certificate states (its claim and its limit-state search).

use super::classify::Kind;
use crate::arch::Arch;
use crate::certificate::{certify_found, verify, Claim};
use crate::limit_states::LimitState;
use crate::settings::Settings;

/// The relative gap of the η* brackets the atlas certifies (wide enough to be cheap; the kind
/// does not depend on it).
const ATLAS_GAP: f64 = 1e-9;

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
