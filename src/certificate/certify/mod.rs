//! Building certificates: for η*(μ) around the exact limit state ([`certify()`], see the
//! module documentation of [`crate::certificate`]), and for the largest multiplier of a live
//! load around the solver's answer to the load question ([`certify_load()`],
//! [`crate::multiplier::survey`]); every certificate is verified before it is returned.
//!
//! * `largest_multiplier`: the static maximum (x_s, λ_s) moved into the admissible set at
//!   λ_lo = λ_s (1 − g/2) by a small LP on its active contacts (rows scaled by
//!   1/(λ_s − λ_lo)), and a Farkas certificate at λ_hi = λ_s (1 + g/2) from 4-subsets of
//!   the active contacts (interior tangencies of a continuous arch also as chords β ± δ),
//!   chosen by their float cofactors and proved by the verifier; the gap is widened
//!   tenfold (up to 1e-4) when a side cannot be proved.
//! * `unbounded_multiplier`: a state admissible at λ_min (the unloaded arch's safest
//!   state when λ_min = 0) and the transfer of the point load to a springing that keeps it
//!   admissible as λ grows; where neither transfer is proved, no certificate.
//! * `no_equilibrium`: the multiplier λ* that maximises the x-margin of the rows (a
//!   concave function of λ: doubling, then golden section), and 5-subsets of the rows
//!   nearest to binding there (and −λ ≤ 0), as for the other Farkas certificates.
//! * the limit states: the survey's list with its mechanisms, the state at λ_static
//!   without a mechanism and every point the sweep checked without one, each with the
//!   Farkas alternative of the kinematic LP with the live power. Where the survey leaves
//!   the limit states undecided, the certificate covers the static range alone (no
//!   `load_search`).
//!
//! This file holds the two entry points; each file below it imports only files further
//! down: `filled.rs` (the cells below η_lo of an arch with fill) on `thickness.rs` (with
//! `search.rs`), and the load files `load_bracket.rs`,
//! `load_ends.rs`, `load_search.rs` build on the toolboxes `loaded.rs`, `sides.rs`,
//! `kinematic.rs` and `blank.rs`, and on the verifier.

mod blank;
mod filled;
mod infimum;
mod kinematic;
mod load_bracket;
mod load_ends;
mod load_search;
mod loaded;
mod search;
mod sides;
mod thickness;

use blank::empty;
use infimum::certify_infimum;
use load_bracket::largest;
use load_ends::{no_equilibrium, unbounded};
use load_search::{evidence, found_evidence, unbounded_evidence};
use loaded::load_spec;
use thickness::{
    certify_limit, certify_no_equilibrium, certify_no_equilibrium_at_top, certify_stands,
};

use crate::arch::{Arch, JointLayout};
use crate::certificate::format::{Certificate, Claim, NotCertified};
use crate::limit::Outcome;
use crate::limit_states::ridge::trace;
use crate::limit_states::{survey, LimitState};
use crate::load::LiveLoad;
use crate::multiplier::{self, static_range, LoadOutcome, StaticRange};
use crate::settings::{LimitStateSearch, Settings};
use crate::undecided::Undecided;

/// Builds a certificate for `arch` at friction `mu` with requested relative gap `gap`
/// (e.g. 1e-12). The certificate is verified before it is returned. When the requested
/// gap cannot be proved the gap is widened tenfold (up to 1e-4) and the best certificate
/// found is returned: check [`Certificate::delivers_gap`] to know whether the request
/// was met.
pub fn certify(
    arch: &Arch,
    mu: f64,
    gap: f64,
    settings: &Settings,
) -> Result<Certificate, NotCertified> {
    certify_found(arch, mu, gap, &[], settings)
}

/// [`certify`] with limit states above η_s known at `mu` from elsewhere (`found`: each a
/// limit state of the continuum, e.g. followed from a neighbouring friction by
/// [`crate::limit_states::follow`]) that the search may have missed: where it did, the
/// certificate lists them with method `found` (not claimed complete, `unique = false`);
/// they are re-checked like every listed state.
pub fn certify_found(
    arch: &Arch,
    mu: f64,
    gap: f64,
    found: &[LimitState],
    settings: &Settings,
) -> Result<Certificate, NotCertified> {
    // a discrete arch's certificate carries the ridge's pieces as evidence where the ridge
    // can be traced (a bounded Q, ...), else the sweep's checked points; with fill neither
    // (its certificate lists no search)
    let traced = match arch.layout() {
        JointLayout::Discrete(_) if mu.is_finite() && arch.fill().is_none() => trace(arch, mu).ok(),
        _ => None,
    };
    let settings = &match arch.layout() {
        JointLayout::Discrete(_) if traced.is_none() => Settings {
            limit_state_search: LimitStateSearch::Sweep,
            ..settings.clone()
        },
        _ => settings.clone(),
    };
    let mut survey = survey(arch, mu, settings).map_err(|e| NotCertified(e.to_string()))?;
    let missed = survey.states.as_ref().is_ok_and(|s| {
        found.iter().any(|f| {
            !s.above
                .iter()
                .any(|a| (a.t - f.t).abs() <= settings.same_root * f.t)
        })
    });
    if missed {
        survey.states = Err(Undecided::Discretisation(
            "limit states above eta_s known from elsewhere were missed by the search".into(),
        ));
        survey.found = crate::limit_states::distinct(found);
    }
    let limit = |least| {
        let found = (&survey, traced.as_deref());
        let cert = certify_limit((arch, mu), found, least, gap, settings)?;
        match arch.fill() {
            Some(_) => filled::below_with_fill(cert, (arch, mu), settings),
            None => Ok(cert),
        }
    };
    match survey.solution.outcome.clone() {
        Outcome::Limit(ls) if !ls.attained && arch.fill().is_some() => Err(NotCertified(format!(
            "eta_s = {} of this arch with fill is an infimum (not attained): its certificate \
             is not written with fill",
            ls.eta_static
        ))),
        Outcome::Limit(ls) if !ls.attained => certify_infimum(arch, mu, &ls, gap, settings),
        Outcome::Limit(ls) => {
            let at_eta_s = (ls.eta == ls.eta_static).then_some(&ls);
            limit((ls.eta_static, ls.x_static, at_eta_s))
        }
        Outcome::NoEquilibrium { mu_ms: Some(m), .. } if mu < m => {
            certify_no_equilibrium(arch, mu, settings)
        }
        Outcome::NoEquilibrium { .. } if arch.fill().is_some() => {
            filled::no_equilibrium(arch, mu, settings)
        }
        Outcome::NoEquilibrium { .. } => certify_no_equilibrium_at_top(arch, mu, settings),
        // the least admissible state carries no mechanism and the solve found none above:
        // the bracket of η_s is a claim of the statics alone; where the complete search found
        // limit states above it, the least is its first one, and where it found none the
        // certificate lists none (the solve's answer stays unresolved)
        Outcome::Unresolved {
            least_static: Some((eta_s, x_s)),
            ..
        } => limit((eta_s, x_s, None)),
        Outcome::NoCollapse { reason } => certify_stands(arch, mu, &reason),
        Outcome::Unresolved { reason, .. } => Err(NotCertified(reason)),
    }
}

/// The load certificate where the survey did not settle (`u`): the static range alone
/// (no equilibrium, λ unbounded, or λ_static bracketed), with the limit states the survey
/// found all the same as evidence of method `found` (each checked; the list not claimed
/// complete) where λ_static is finite.
fn undecided_load(
    arch: &Arch,
    (eta, mu): (f64, f64),
    load: &LiveLoad,
    u: &multiplier::LoadUnsettled,
    base: impl Fn(Claim) -> Certificate,
    gap: f64,
    settings: &Settings,
) -> Result<Certificate, NotCertified> {
    let reason = &u.why;
    let range = static_range(arch, eta, mu, load, settings)
        .map_err(|e| NotCertified(e.to_string()))?
        .map_err(|e| NotCertified(format!("the load question is not decided: {e}")))?;
    match range {
        StaticRange::NoEquilibrium => {
            no_equilibrium(arch, eta, mu, load, base(Claim::NoEquilibrium), settings)
        }
        StaticRange::Interval { min, max: None } => unbounded(
            arch,
            eta,
            mu,
            load,
            min,
            base(Claim::UnboundedMultiplier),
            settings,
        ),
        StaticRange::Interval {
            min,
            max: Some(top),
        } => {
            let with = |found: bool| {
                largest(
                    arch,
                    (eta, mu),
                    load,
                    top,
                    (base(Claim::LargestMultiplier), gap),
                    settings,
                    |at_static| match found {
                        true => found_evidence(arch, eta, load, (u, min.0), at_static, settings),
                        false => Ok(None),
                    },
                )
            };
            // the states found as evidence where the verifier takes them; else the bracket
            // alone (a state the verifier's own check rejects costs the listing, not the
            // bracket)
            with(true).or_else(|_| with(false))
        }
    }
    .map_err(|e| {
        NotCertified(format!(
            "{} (the limit states are not decided: {reason})",
            e.0
        ))
    })
}

/// Builds a certificate for the live `load` on `arch` at thickness `eta` and friction
/// `mu` with requested relative gap `gap` of the multiplier bracket (e.g. 1e-12): the
/// largest admissible multiplier (two-sided), its unboundedness, or no equilibrium at any
/// λ ≥ 0, with the evidence of the limit states where the search is complete. Verified
/// before it is returned; [`Certificate::delivers_gap`] says whether the gap was met.
pub fn certify_load(
    arch: &Arch,
    eta: f64,
    mu: f64,
    load: &LiveLoad,
    gap: f64,
    settings: &Settings,
) -> Result<Certificate, NotCertified> {
    let base = |claim: Claim| {
        let mut c = empty(arch, mu, claim);
        c.load = Some(load_spec(eta, load));
        c
    };
    let outcome = match multiplier::survey_partial(arch, eta, mu, load, settings)
        .map_err(|e| NotCertified(e.to_string()))?
    {
        Ok(o) => o,
        Err(u) => return undecided_load(arch, (eta, mu), load, &u, base, gap, settings),
    };
    match outcome {
        LoadOutcome::NoEquilibrium => {
            no_equilibrium(arch, eta, mu, load, base(Claim::NoEquilibrium), settings)
        }
        LoadOutcome::NoCollapse { lambda_min, .. } => {
            let mut cert = base(Claim::UnboundedMultiplier);
            cert.load_search = unbounded_evidence(arch, eta, mu, load, lambda_min, settings);
            unbounded(arch, eta, mu, load, lambda_min, cert, settings)
        }
        LoadOutcome::Limits(sv) => match sv.lambda_static {
            Some(top) => largest(
                arch,
                (eta, mu),
                load,
                top,
                (base(Claim::LargestMultiplier), gap),
                settings,
                |at_static| evidence(arch, eta, load, &sv, Some(at_static), settings).map(Some),
            ),
            None => {
                let mut cert = base(Claim::UnboundedMultiplier);
                cert.load_search = Some(evidence(arch, eta, load, &sv, None, settings)?);
                unbounded(arch, eta, mu, load, sv.lambda_min, cert, settings)
            }
        },
    }
}
