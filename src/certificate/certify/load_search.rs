//! The `load_search` section of a load certificate (see
//! [`certify_load()`](super::certify_load)): the survey's limit states with their
//! mechanisms, and the Farkas alternative of the kinematic LP with the live power for every
//! state listed without a mechanism.

use super::kinematic::no_mechanism as unmoved;
use super::loaded::{joint, sorted, Loaded};
use crate::arch::{Arch, JointLayout};
use crate::certificate::format::{
    ContinuumEnd, LoadLimitStateCert, LoadNoMechanism, LoadSearchEvidence, LoadSearchMethod,
    NotCertified,
};
use crate::contact::{Contact, ContactKind};
use crate::limit_states::sweep::{by_faces, sweep_load, CheckedPoint};
use crate::limit_states::LimitState;
use crate::load::LiveLoad;
use crate::multiplier::{LoadSurvey, LoadUnsettled, UNBOUNDED_SEARCH_TOP};
use crate::settings::Settings;
use crate::statics::Reactions;

/// The evidence of the limit states of a survey (`static`: the state at λ_static and its
/// active contacts, when finite).
pub(super) fn evidence(
    arch: &Arch,
    eta: f64,
    load: &LiveLoad,
    sv: &LoadSurvey,
    at_static: Option<(f64, Reactions, &[Loaded])>,
    settings: &Settings,
) -> Result<LoadSearchEvidence, NotCertified> {
    let method = match sv.method {
        "faces" => LoadSearchMethod::Faces,
        "sweep" => LoadSearchMethod::Sweep,
        "associative" => LoadSearchMethod::Associative,
        _ => LoadSearchMethod::Refined,
    };
    let limit_states = sv
        .limit_states
        .iter()
        .map(|s| limit_state_cert(load, s))
        .collect::<Result<Vec<_>, _>>()?;
    let static_state = match at_static {
        Some((lambda, x, pattern)) if !sv.mechanism_at_static => Some(no_mechanism(
            arch,
            eta,
            load,
            (lambda, x, pattern.to_vec()),
            settings,
        )),
        _ => None,
    };
    Ok(LoadSearchEvidence {
        method,
        events: sv.events,
        lambda_min: sv.lambda_min.0,
        mechanism_at_static: sv.mechanism_at_static,
        unique: sv.unique(),
        lambda: sv.lambda(),
        limit_states,
        static_state,
        no_mechanism: checked(arch, eta, load, &sv.no_mechanism, settings),
    })
}

/// The evidence of a survey that did not settle but found limit states (`u.found`, with
/// `u.mechanism_at_static` decided): method `found`, each state listed to be checked, the
/// list not claimed complete (`lambda` null, `unique` false); `at_static` as in
/// [`evidence`]. `None` where nothing was found or the state at λ_static is not decided.
pub(super) fn found_evidence(
    arch: &Arch,
    eta: f64,
    load: &LiveLoad,
    (u, lambda_min): (&LoadUnsettled, f64),
    at_static: (f64, Reactions, &[Loaded]),
    settings: &Settings,
) -> Result<Option<LoadSearchEvidence>, NotCertified> {
    let Some(mechanism_at_static) = u.mechanism_at_static else {
        return Ok(None);
    };
    if u.found.is_empty() {
        return Ok(None);
    }
    let limit_states = u
        .found
        .iter()
        .map(|s| limit_state_cert(load, s))
        .collect::<Result<Vec<_>, _>>()?;
    let (lambda, x, pattern) = at_static;
    Ok(Some(LoadSearchEvidence {
        method: LoadSearchMethod::Found,
        events: 0,
        lambda_min: u.lambda_min.unwrap_or(lambda_min),
        mechanism_at_static,
        unique: false,
        lambda: None,
        limit_states,
        static_state: (!mechanism_at_static)
            .then(|| no_mechanism(arch, eta, load, (lambda, x, pattern.to_vec()), settings)),
        no_mechanism: Vec::new(),
    }))
}

/// Where λ_static is unbounded and no limit state exists (`NoCollapse`): at μ = ∞ the
/// associative argument; at finite μ on a discrete arch the sweep again (or the face
/// search, beyond its budget; the survey keeps no list there), its points without a
/// mechanism as evidence.
pub(super) fn unbounded_evidence(
    arch: &Arch,
    eta: f64,
    mu: f64,
    load: &LiveLoad,
    (lambda_min, x_min): (f64, Reactions),
    settings: &Settings,
) -> Option<LoadSearchEvidence> {
    let empty = |method, events, no_mechanism| LoadSearchEvidence {
        method,
        events,
        lambda_min,
        mechanism_at_static: false,
        unique: false,
        lambda: None,
        limit_states: Vec::new(),
        static_state: None,
        no_mechanism,
    };
    if mu.is_infinite() {
        return Some(empty(LoadSearchMethod::Associative, 0, Vec::new()));
    }
    let JointLayout::Discrete(joints) = arch.layout() else {
        return None;
    };
    // beyond the sweep's budget `sweep_load` runs the face search
    let method = if by_faces(joints.len(), settings) {
        LoadSearchMethod::Faces
    } else {
        LoadSearchMethod::Sweep
    };
    let sw = sweep_load(
        arch,
        eta,
        mu,
        load,
        (lambda_min, x_min),
        UNBOUNDED_SEARCH_TOP,
        settings,
    );
    if sw.failure.is_some() || !sw.states.is_empty() {
        return None;
    }
    Some(empty(
        method,
        sw.events,
        checked(arch, eta, load, &sw.no_mechanism, settings),
    ))
}

/// The sweep's points without a mechanism, each with its proof.
fn checked(
    arch: &Arch,
    eta: f64,
    load: &LiveLoad,
    points: &[CheckedPoint],
    settings: &Settings,
) -> Vec<LoadNoMechanism> {
    points
        .iter()
        .map(|p| {
            let pattern: Vec<Loaded> = p
                .pattern
                .iter()
                .copied()
                .zip(p.sides.iter().copied())
                .collect();
            no_mechanism(arch, eta, load, (p.eta, p.x, sorted(pattern)), settings)
        })
        .collect()
}

/// A limit state under the load in the certificate's order, its rates on its pattern.
fn limit_state_cert(load: &LiveLoad, s: &LimitState) -> Result<LoadLimitStateCert, NotCertified> {
    let pattern = sorted(
        s.pattern
            .iter()
            .copied()
            .zip(s.sides.iter().copied())
            .collect(),
    );
    let rates = rates_on(&pattern, &s.mechanism.contacts, &s.mechanism.rates).ok_or_else(|| {
        NotCertified(format!(
            "the mechanism of the limit state at lambda = {} does not match its pattern",
            s.t
        ))
    })?;
    Ok(LoadLimitStateCert {
        lambda: s.t,
        x: s.x,
        pattern: pattern.iter().map(|&l| joint(Some(load), l)).collect(),
        rates,
        live_power: s.live_power,
        continuum: s.continuum_to.map(|to| ContinuumEnd {
            to: to.is_finite().then_some(to),
        }),
    })
}

/// The rates of a mechanism (on the kept contacts of one sliding sense per section, in
/// the pattern's (β, side, kind) order but without sides) on the whole `pattern`: at each
/// angle the kept contacts of the `before` side come first, one fewer than listed where a
/// section has both sliding senses; a contact left out gets rate 0.
fn rates_on(pattern: &[Loaded], kept: &[Contact], rates: &[f64]) -> Option<Vec<f64>> {
    let mut out = vec![0.0; pattern.len()];
    let mut next = 0;
    let mut i = 0;
    while i < pattern.len() {
        // the section (β, side) from i
        let (beta, side) = (pattern[i].0.beta, pattern[i].1);
        let end = (i..pattern.len())
            .find(|&k| pattern[k].0.beta != beta || pattern[k].1 != side)
            .unwrap_or(pattern.len());
        let has = |kind| (i..end).any(|k| pattern[k].0.kind == kind);
        let n = end - i - usize::from(has(ContactKind::SlidePlus) && has(ContactKind::SlideMinus));
        for _ in 0..n {
            let c = kept.get(next)?;
            let k =
                (i..end).find(|&k| pattern[k].0.kind == c.kind && pattern[k].0.beta == c.beta)?;
            out[k] = *rates.get(next)?;
            next += 1;
        }
        i = end;
    }
    (next == kept.len()).then_some(out)
}

/// A state without a mechanism with positive live power, with the proof.
fn no_mechanism(
    arch: &Arch,
    eta: f64,
    load: &LiveLoad,
    (lambda, x, pattern): (f64, Reactions, Vec<Loaded>),
    settings: &Settings,
) -> LoadNoMechanism {
    let (pattern, farkas) = unmoved(arch, eta, Some((load, lambda)), pattern, settings);
    LoadNoMechanism {
        lambda,
        x,
        pattern,
        farkas,
    }
}
