//! The `search` section of a thickness certificate: the survey's limit states with their
//! mechanisms, and the Farkas alternative of the kinematic LP for the least admissible state
//! and every point the sweep checked without a mechanism.

use super::kinematic::no_mechanism as unmoved;
use super::loaded::joint;
use crate::arch::Arch;
use crate::certificate::format::{
    LimitStateCert, NoMechanism, PatternJoint, RidgeEdge, RidgeEvidence, RidgePiece,
    SearchEvidence, SearchMethod, Side,
};
use crate::contact::Contact;
use crate::limit_states::ridge::TracedEdge;
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

/// A Farkas certificate for the junction `nm`'s pattern without `row` (its `drop`), where
/// one exists.
fn without(
    arch: &Arch,
    nm: &NoMechanism,
    row: Contact,
    settings: &Settings,
) -> Option<crate::certificate::format::KinematicFarkas> {
    let at = nm
        .pattern
        .iter()
        .position(|j| j.beta == row.beta && j.kind == row.kind)?;
    let rest: Vec<(Contact, Side)> = nm
        .pattern
        .iter()
        .enumerate()
        .filter(|&(k, _)| k != at)
        .map(|(_, j)| {
            let c = Contact {
                beta: j.beta,
                kind: j.kind,
                at: j.at,
                free: false,
            };
            (c, Side::After)
        })
        .collect();
    let (_, farkas) = unmoved(arch, nm.eta, None, rest, settings);
    let mut f = farkas.into_iter().find(|f| f.drop.is_empty())?;
    f.drop = vec![at];
    Some(f)
}

/// The method of a list that is not claimed complete ([`crate::limit_states::Survey::found`]).
pub(super) const FOUND: &str = "found";

/// The evidence of the limit-state search, for the certificate.
pub(super) fn evidence(
    (arch, traced): (&Arch, Option<&[TracedEdge]>),
    found: &LimitStates,
    least: (f64, Reactions, &[Contact]),
    unique: bool,
    settings: &Settings,
) -> SearchEvidence {
    let ridge = traced
        .filter(|_| found.method == "ridge")
        .map(|edges| ridge_evidence(arch, edges, settings));
    let method = if ridge.is_some() {
        SearchMethod::Ridge
    } else if found.method.starts_with("sweep") {
        SearchMethod::Sweep
    } else if found.method.starts_with("hinges only") {
        SearchMethod::HingesOnly
    } else if found.method == FOUND {
        SearchMethod::Found
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
        ridge,
    }
}

/// The ridge's evidence: Q's edges, the pieces along each, and at each junction the
/// contacts that may be active around it (the edge's sliding row, the previous edge's at a
/// vertex, the hinge rows of the pieces on both sides) with the Farkas proof that they
/// carry no mechanism there (none where the junction is a limit state).
fn ridge_evidence(arch: &Arch, edges: &[TracedEdge], settings: &Settings) -> RidgeEvidence {
    let m = edges.len();
    let mut inside = [0.0; 2];
    for e in edges {
        inside[0] += e.junctions[0].x[0] / m as f64;
        inside[1] += e.junctions[0].x[1] / m as f64;
    }
    let edges = (0..m)
        .map(|k| {
            let (edge, prev) = (&edges[k], &edges[(k + m - 1) % m]);
            let junctions = edge
                .junctions
                .iter()
                .enumerate()
                .map(|(i, jn)| {
                    let (before_row, before) = match i {
                        0 => (
                            Some(prev.row),
                            prev.pieces.last().expect("a piece per edge"),
                        ),
                        _ => (None, &edge.pieces[i - 1]),
                    };
                    let mut pattern: Vec<Contact> = [edge.row, before.1, before.2]
                        .into_iter()
                        .chain(before_row)
                        .chain([edge.pieces[i].1, edge.pieces[i].2])
                        .collect();
                    pattern.sort_by(|a, b| a.beta.total_cmp(&b.beta).then(a.kind.cmp(&b.kind)));
                    pattern.dedup_by(|a, b| a.beta == b.beta && a.kind == b.kind);
                    let mut nm = no_mechanism(arch, jn.eta, jn.x, &pattern, settings);
                    if i == 0 && nm.farkas.is_empty() {
                        // a limit state at a vertex: away from it, on either edge, the
                        // other edge's row is inactive; a proof without it for each side
                        for row in [prev.row, edge.row] {
                            nm.farkas.extend(without(arch, &nm, row, settings));
                        }
                    }
                    nm
                })
                .collect();
            RidgeEdge {
                row: joint(None, (edge.row, Side::After)),
                pieces: edge
                    .pieces
                    .iter()
                    .map(|&(end, e, i)| RidgePiece {
                        end,
                        extrados: e.beta,
                        intrados: i.beta,
                    })
                    .collect(),
                junctions,
            }
        })
        .collect();
    RidgeEvidence { inside, edges }
}
