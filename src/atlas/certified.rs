//! A kind re-proved: the point's certificate ([`crate::certificate::certify`]) checked by
//! the independent verifier ([`crate::certificate::verify`]), and the kind read from what
//! the verified certificate states (its claim and its limit-state search).

use super::classify::Kind;
use crate::arch::Arch;
use crate::certificate::{certify, verify, Claim};
use crate::settings::Settings;

/// The relative gap of the η* brackets the atlas certifies (wide enough to be cheap; the kind
/// does not depend on it).
const ATLAS_GAP: f64 = 1e-9;

/// The kind at (arch, μ) as a verified certificate states it, or why there is none.
pub fn certified_kind(arch: &Arch, mu: f64, settings: &Settings) -> Result<Kind, String> {
    let cert = certify(arch, mu, ATLAS_GAP, settings).map_err(|e| e.0)?;
    verify(&cert).map_err(|r| format!("the verifier rejected the certificate: {}", r.0))?;
    match cert.claim {
        Claim::NoEquilibrium => return Ok(Kind::NoEquilibrium),
        Claim::StandsAtEveryThickness => return Ok(Kind::NoMechanismAtEta),
        Claim::LeastThickness => {}
        other => return Err(format!("a {} claim", other.name())),
    }
    let search = cert
        .search
        .as_ref()
        .ok_or("the certificate lists no limit states")?;
    Ok(if !search.mechanism_at_eta {
        Kind::NoMechanismAtEta
    } else if search.unique {
        Kind::Unique
    } else {
        Kind::NonUnique
    })
}
