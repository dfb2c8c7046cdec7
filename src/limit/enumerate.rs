//! Enumeration and verification of patterns: every subset of the candidate contacts is
//! refined by Newton ([`crate::refine`]), then checked in increasing η for static
//! admissibility over the whole arch and a non-associative mechanism on its active set.

use super::solution::{Candidate, LeastLimitState};
use crate::arch::Arch;
use crate::collapse_mode::classify;
use crate::contact::{Contact, ContactKind};
use crate::mechanism;
use crate::refine::{solve_pattern, NewtonFailure, Refined};
use crate::settings::Settings;
use crate::state::State;
use crate::statics::Reactions;
use itertools::Itertools;

/// What one enumeration found.
pub(crate) struct Enumeration {
    /// The verified limit state of least η.
    pub limit: Option<LeastLimitState>,
    /// The least-η statically admissible refined state (with or without mechanism).
    pub least_static: Option<Refined>,
}

/// Refines every subset of `cand` of the given sizes (and the whole set), then
/// verifies: static admissibility over the whole arch, then a mechanism on the
/// active set. Groups go largest first (the whole set, then subsets by decreasing
/// size); every admissible state has η at least the static least thickness, so once
/// a limit state at most `stop_at` is verified, later groups are not tried.
#[allow(clippy::too_many_arguments)]
pub(crate) fn enumerate(
    arch: &Arch,
    mu: f64,
    cand: &[Contact],
    sizes: &[usize],
    x0: Reactions,
    eta0: f64,
    bracket: (f64, f64),
    stop_at: f64,
    settings: &Settings,
    log: &mut Vec<Candidate>,
) -> Enumeration {
    let mut groups: Vec<Vec<Vec<Contact>>> = vec![vec![cand.to_vec()]];
    let mut sizes = sizes.to_vec();
    sizes.sort_unstable_by(|a, b| b.cmp(a));
    for k in sizes {
        if cand.len() > k {
            groups.push(cand.iter().copied().combinations(k).collect());
        }
    }
    let mut out = Enumeration {
        limit: None,
        least_static: None,
    };
    for group in groups {
        if out.limit.as_ref().is_some_and(|l| l.eta <= stop_at) {
            for s in group {
                log.push(Candidate {
                    contacts: s,
                    eta: None,
                    tried: false,
                    verdict: "not tried: a limit state at the static least thickness is verified"
                        .into(),
                });
            }
            continue;
        }
        verify_group(arch, mu, group, x0, eta0, bracket, settings, log, &mut out);
    }
    out
}

/// Newton from `start` on each pattern of `group`: the refined ones in increasing η, the
/// others logged with why Newton rejected them.
fn refine_group(
    start: &State,
    group: Vec<Vec<Contact>>,
    settings: &Settings,
    log: &mut Vec<Candidate>,
) -> Vec<(Vec<Contact>, Refined)> {
    let mut refined = Vec::new();
    for s in group {
        match solve_pattern(start, &s, settings) {
            Ok(r) => refined.push((s, r)),
            Err(f) => log.push(Candidate {
                contacts: s,
                eta: None,
                tried: true,
                verdict: match f {
                    NewtonFailure::Empty => "rejected: empty pattern".into(),
                    NewtonFailure::NegativeMultiplier => {
                        "rejected: a KKT multiplier is negative (not a least thickness)".into()
                    }
                    NewtonFailure::LeftDomain => "rejected: Newton left the domain".into(),
                    NewtonFailure::NoConvergence(r) => {
                        format!("rejected: Newton did not converge (residual {r:.2e})")
                    }
                },
            }),
        }
    }
    refined.sort_by(|a, b| a.1.t.total_cmp(&b.1.t));
    refined
}

/// Refines each pattern of `group`, then verifies them in increasing η, keeping the
/// least verified limit state and the least admissible state in `out`.
#[allow(clippy::too_many_arguments)]
fn verify_group(
    arch: &Arch,
    mu: f64,
    group: Vec<Vec<Contact>>,
    x0: Reactions,
    eta0: f64,
    bracket: (f64, f64),
    settings: &Settings,
    log: &mut Vec<Candidate>,
    out: &mut Enumeration,
) {
    let start = State {
        arch,
        eta: eta0,
        mu,
        x: x0,
    };
    let refined = refine_group(&start, group, settings, log);
    let mut last_eta = f64::NAN;
    for (s, r) in refined {
        let push = |log: &mut Vec<Candidate>, verdict: String| {
            log.push(Candidate {
                contacts: s.clone(),
                eta: Some(r.t),
                tried: true,
                verdict,
            })
        };
        if out.limit.as_ref().is_some_and(|l| l.eta <= r.t) {
            push(
                log,
                "not needed: a limit state of lower or equal eta was verified".into(),
            );
            continue;
        }
        let st = State {
            arch,
            eta: r.t,
            mu,
            x: r.x,
        };
        let verdict = match st.admissible_verdict(ContactKind::active_at(mu), settings) {
            Ok(v) => v,
            Err(phi) => {
                push(
                    log,
                    format!(
                        "rejected: not admissible over the arch (phi = {phi:.2e} of its magnitude at a contact)"
                    ),
                );
                continue;
            }
        };
        let worst = verdict.worst;
        if out.least_static.as_ref().is_none_or(|l| r.t < l.t) {
            out.least_static = Some(r.clone());
        }
        if r.t == last_eta {
            push(log, "same state as a pattern already checked".into());
            continue;
        }
        last_eta = r.t;
        let pattern = verdict.active;
        match mechanism::find(&st, &pattern, settings) {
            Ok(Some(mech)) => {
                push(
                    log,
                    format!(
                        "kept: admissible (max phi = {worst:.2e}), mechanism with {} dof",
                        mech.dof
                    ),
                );
                let mode = classify(
                    &pattern,
                    0.5 * (arch.beta_right() + arch.beta_left()),
                    settings.same_joint,
                );
                out.limit = Some(LeastLimitState {
                    eta_rounding: crate::statics::eta_rounding(arch, r.t, &r.x, &pattern),
                    mu,
                    eta: r.t,
                    eta_static: r.t,
                    x_static: r.x,
                    x: r.x,
                    pattern,
                    mode,
                    mechanism: mech,
                    newton_residual: r.residual,
                    max_phi: worst,
                    attained: true,
                    bracket,
                });
            }
            Ok(None) => push(
                log,
                "rejected: admissible, but no non-associative mechanism on its active set".into(),
            ),
            Err(e) => push(log, format!("rejected: kinematic LP failed ({e:?})")),
        }
    }
}
