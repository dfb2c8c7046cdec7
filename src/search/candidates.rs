//! Candidate active contacts: the local maxima of φ at a state whose normalised slack is
//! within `candidate_rel` of the LP margin (formulation §5, pattern enumeration).

use crate::admissibility::peak_grad_norm;
use crate::contact::{Contact, ContactKind, Peak};
use crate::settings::Settings;
use crate::state::State;
use crate::statics::reaction_scale;

/// Local maxima of φ at the state (η, x) that may be active contacts, best first: with
/// `margin` given, those whose normalised slack is within `candidate_rel` of it; with
/// `None`, simply the best ones. At most `max_candidates`.
pub fn candidates_at(
    state: &State,
    margin: Option<f64>,
    modes: &[ContactKind],
    settings: &Settings,
) -> Vec<Contact> {
    let (arch, eta, mu, x) = (state.arch, state.eta, state.mu, &state.x);
    let limit = margin.map_or(f64::INFINITY, |m| {
        m + settings.candidate_rel * reaction_scale(x)
    });
    let mut peaks: Vec<(f64, Peak)> = state
        .peaks(settings)
        .into_iter()
        .filter(|p| modes.contains(&p.contact.kind))
        .map(|p| (-p.value / peak_grad_norm(arch, eta, mu, &p), p))
        .filter(|(slack, _)| *slack <= limit)
        .collect();
    // by slack, equal slacks by decreasing φ, then in the scan's order
    peaks.sort_by(|a, b| a.0.total_cmp(&b.0).then(b.1.value.total_cmp(&a.1.value)));
    peaks.truncate(settings.max_candidates);
    peaks.into_iter().map(|(_, p)| p.contact).collect()
}
