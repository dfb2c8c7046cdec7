//! The `search` section of a thickness certificate: the survey's limit states with their
//! mechanisms, and the Farkas alternative of the kinematic LP for the least admissible state
//! and every point the sweep checked without a mechanism.

use super::kinematic::no_mechanism as unmoved;
use super::loaded::joint;
use crate::arch::Arch;
use crate::certificate::format::{
    LimitStateCert, NoMechanism, PatternJoint, SearchEvidence, SearchMethod, Side,
};
use crate::contact::Contact;
use crate::limit_states::{LimitState, LimitStates};
use crate::mechanism::Mechanism;
use crate::settings::Settings;
use crate::statics::Reactions;

/// A limit state in the format's order: pattern increasing in (β, kind), rates alongside.
pub(super) fn limit_state_cert(eta: f64, x: Reactions, mechanism: &Mechanism) -> LimitStateCert {
    let mut joints: Vec<(PatternJoint, f64)> = mechanism
        .contacts
        .iter()
        .zip(&mechanism.rates)
        .map(|(c, &r)| (joint(None, (*c, Side::After)), r))
        .collect();
    joints.sort_by(|a, b| a.0.beta.total_cmp(&b.0.beta).then(a.0.kind.cmp(&b.0.kind)));
    LimitStateCert {
        eta,
        x,
        pattern: joints.iter().map(|(j, _)| j.clone()).collect(),
        rates: joints.iter().map(|&(_, r)| r).collect(),
        complementarity_residual: mechanism.complementarity,
    }
}

/// A state without a mechanism of the thickness problem, with the proof.
fn no_mechanism(
    arch: &Arch,
    eta: f64,
    x: Reactions,
    pattern: &[Contact],
    settings: &Settings,
) -> NoMechanism {
    let pattern = pattern.iter().map(|&c| (c, Side::After)).collect();
    let (pattern, farkas) = unmoved(arch, eta, None, pattern, settings);
    NoMechanism {
        eta,
        x,
        pattern,
        farkas,
    }
}

/// The evidence of the limit-state search, for the certificate.
pub(super) fn evidence(
    arch: &Arch,
    found: &LimitStates,
    least: (f64, Reactions, &[Contact]),
    unique: bool,
    settings: &Settings,
) -> SearchEvidence {
    let method = if found.method.starts_with("sweep") {
        SearchMethod::Sweep
    } else if found.method.starts_with("hinges only") {
        SearchMethod::HingesOnly
    } else {
        SearchMethod::Refined
    };
    // ascending in η to the last bit, as the verifier reads them (the search orders a
    // mirror pair equal to rounding by its patterns)
    let mut listed: Vec<&LimitState> = found.above.iter().collect();
    listed.sort_by(|a, b| a.t.total_cmp(&b.t));
    let above = |s: &&LimitState| limit_state_cert(s.t, s.x, &s.mechanism);
    SearchEvidence {
        method,
        events: found.events,
        mechanism_at_eta: found.mechanism_at_eta_s,
        unique,
        least_state: (!found.mechanism_at_eta_s && found.attained)
            .then(|| no_mechanism(arch, least.0, least.1, least.2, settings)),
        limit_states_above: listed.iter().map(above).collect(),
        no_mechanism: found
            .no_mechanism
            .iter()
            .map(|p| no_mechanism(arch, p.eta, p.x, &p.pattern, settings))
            .collect(),
    }
}
