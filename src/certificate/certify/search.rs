//! The `search` section of a thickness certificate: the survey's limit states with their
//! mechanisms, and the Farkas alternative of the kinematic LP for the least admissible state
//! and every point the sweep checked without a mechanism.

use super::kinematic::farkas_cover;
use crate::arch::Arch;
use crate::certificate::format::{
    KinematicFarkas, LimitStateCert, NoMechanism, PatternJoint, SearchEvidence, SearchMethod,
};
use crate::contact::{Contact, ContactKind};
use crate::kinematics::{column, power};
use crate::limit_states::{LimitStates, SweptState};
use crate::lp;
use crate::mechanism::Mechanism;
use crate::settings::Settings;
use crate::statics::Reactions;

/// A limit state in the format's order: pattern increasing in (β, kind), rates alongside.
pub(super) fn limit_state_cert(eta: f64, x: Reactions, mechanism: &Mechanism) -> LimitStateCert {
    let mut joints: Vec<(PatternJoint, f64)> = mechanism
        .contacts
        .iter()
        .zip(&mechanism.rates)
        .map(|(c, &r)| (pattern_joint(c), r))
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

pub(super) fn pattern_joint(c: &Contact) -> PatternJoint {
    PatternJoint {
        beta: c.beta,
        kind: c.kind,
        at: c.at,
        side: None,
    }
}

/// Farkas certificates that the kinematic LP on `pattern` at η is infeasible for every
/// one-sense choice (a joint where both sliding senses are active slides one way only):
/// first for the whole pattern, else one per choice. z is halved so that every inequality
/// holds with room for the verifier's rounding. Those that cannot be found are left out
/// (the verifier then reports the state as not proved).
fn kinematic_farkas(
    arch: &Arch,
    eta: f64,
    pattern: &[Contact],
    settings: &Settings,
) -> Vec<KinematicFarkas> {
    let keys: Vec<(f64, ContactKind, bool)> =
        pattern.iter().map(|c| (c.beta, c.kind, false)).collect();
    farkas_cover(&keys, |drop: Vec<usize>| {
        let kept: Vec<Contact> = (0..pattern.len())
            .filter(|i| !drop.contains(i))
            .map(|i| pattern[i])
            .collect();
        let cols: Vec<[f64; 3]> = kept.iter().map(|c| column(c.kind, c.beta, eta)).collect();
        let p = power(arch, eta, &kept);
        let (y, z, u) = lp::kinematic_farkas(&cols, &p, settings).ok()?;
        (z > 0.0).then_some(KinematicFarkas {
            drop,
            y,
            z: 0.5 * z,
            u: u.max(0.0),
            v: 0.0,
        })
    })
}

fn no_mechanism(
    arch: &Arch,
    eta: f64,
    x: Reactions,
    pattern: &[Contact],
    settings: &Settings,
) -> NoMechanism {
    let mut pattern = pattern.to_vec();
    pattern.sort_by(|a, b| a.beta.total_cmp(&b.beta).then(a.kind.cmp(&b.kind)));
    NoMechanism {
        eta,
        x,
        pattern: pattern.iter().map(pattern_joint).collect(),
        farkas: kinematic_farkas(arch, eta, &pattern, settings),
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
    let above = |s: &SweptState| limit_state_cert(s.eta, s.x, &s.mechanism);
    SearchEvidence {
        method,
        events: found.events,
        mechanism_at_eta: found.mechanism_at_eta_s,
        unique,
        least_state: (!found.mechanism_at_eta_s && found.attained)
            .then(|| no_mechanism(arch, least.0, least.1, least.2, settings)),
        limit_states_above: found.above.iter().map(above).collect(),
        no_mechanism: found
            .no_mechanism
            .iter()
            .map(|p| no_mechanism(arch, p.eta, p.x, &p.pattern, settings))
            .collect(),
    }
}
