//! The least thickness η*(μ) of an arch at one friction coefficient (formulation §5).
//!
//! 1. **Bracket.** The continuum margin s(η) of the best state (constraint-generation
//!    LP, [`crate::admissibility`]) is increasing in η; η* is its root, bracketed by
//!    Illinois regula falsi safeguarded by (geometric) bisection.
//! 2. **Candidates.** At the upper end of the bracket, the local maxima of every φ whose
//!    normalised slack is within `candidate_rel` of the LP margin are the candidate
//!    active contacts.
//! 3. **Enumeration.** Every subset of 4 and 5 candidates, and the whole candidate set,
//!    is a pattern; Newton ([`crate::refine`]) solves its system exactly.
//! 4. **Verification.** In increasing η, a refined state must be statically admissible
//!    over the whole arch (scan, `adm_tol`) and its active set must carry a mechanism
//!    (kinematic LP, [`crate::mechanism`]). The first that passes is the limit state.

use crate::admissibility::{grad_norm, max_margin, Goal, Margin, WorkingSet};
use crate::arch::{check_mu, Arch, InputError};
use crate::collapse_mode::{classify, CollapseMode};
use crate::contact::ContactKind;
use crate::contact::{Contact, Peak};
use crate::friction::least_friction;
use crate::lp::LpOutcome;
use crate::mechanism::{self, Mechanism};
use crate::refine::{solve_pattern, NewtonFailure, Refined};
use crate::scan::State;
use crate::settings::Settings;
use crate::statics::Reactions;
use itertools::Itertools;

/// A verified limit state (incipient collapse) at friction μ.
#[derive(Debug, Clone)]
pub struct LimitState {
    /// Friction coefficient μ (∞ allowed).
    pub mu: f64,
    /// The least thickness ratio η*(μ).
    pub eta: f64,
    /// The least η with a statically admissible state. Equal to `eta` unless that
    /// state carries no mechanism without dilatancy (non-associative gap), in which
    /// case the limit state lies above it.
    pub eta_static: f64,
    /// Reactions x = (h, v, w) at the right springing.
    pub x: Reactions,
    /// The active pattern: every contact with φ = 0 at this state, by increasing β.
    pub pattern: Vec<Contact>,
    /// The collapse mode named from the pattern.
    pub mode: CollapseMode,
    /// A mechanism on the pattern.
    pub mechanism: Mechanism,
    /// Newton residual of the pattern's system (scaled).
    pub newton_residual: f64,
    /// Greatest φ over the whole arch relative to its magnitude (≤ `adm_tol`).
    pub max_phi: f64,
    /// The bracket [η_lo, η_hi] found before refinement: at η_hi a state was verified
    /// admissible over the whole arch; η_lo was judged infeasible by the LP (to
    /// HiGHS's tolerance, so for very shallow arches η* may lie slightly below it).
    pub bracket: (f64, f64),
}

/// What the solver found at one μ.
#[derive(Debug, Clone)]
pub enum Outcome {
    /// A verified limit state.
    Limit(LimitState),
    /// No thickness η < 2 admits equilibrium.
    NoEquilibrium {
        /// The least friction coefficient that admits equilibrium at some
        /// (unbounded) thickness, when μ is below it.
        mu_ms: Option<f64>,
        /// Why, in words.
        reason: String,
    },
    /// Every thickness η > 0 admits equilibrium: there is no collapse to find (e.g. a
    /// discrete arch with at most three joints, which is statically determinate).
    NoCollapse {
        /// Why, in words.
        reason: String,
    },
    /// The solver could not verify a limit state; η* lies in the bracket.
    Unresolved {
        /// Lower end of the bracket (no admissible state).
        eta_lo: f64,
        /// Upper end of the bracket (admissible state).
        eta_hi: f64,
        /// What failed.
        reason: String,
    },
}

/// One enumerated pattern and what became of it (for `solve --explain`).
#[derive(Debug, Clone)]
pub struct Candidate {
    /// The contacts of the pattern, as started.
    pub contacts: Vec<Contact>,
    /// Refined η, when Newton converged.
    pub eta: Option<f64>,
    /// Kept or rejected, and why.
    pub verdict: String,
}

/// The answer of [`solve`]: the outcome and the enumeration log.
#[derive(Debug, Clone)]
pub struct Solution {
    /// The arch solved.
    pub arch: Arch,
    /// Friction coefficient μ.
    pub mu: f64,
    /// The outcome.
    pub outcome: Outcome,
    /// Every pattern tried, in the order verified.
    pub candidates: Vec<Candidate>,
}

pub(crate) fn scale_of(x: &Reactions) -> f64 {
    1.0 + x.iter().map(|v| v.abs()).sum::<f64>()
}

pub(crate) fn margin_at(
    arch: &Arch,
    eta: f64,
    mu: f64,
    modes: &[ContactKind],
    ws: &mut WorkingSet,
    settings: &Settings,
) -> Result<Margin, String> {
    max_margin(arch, eta, mu, modes, ws, Goal::Decide, settings).map_err(|e| match e {
        LpOutcome::Infeasible => "margin LP infeasible".to_string(),
        LpOutcome::Failed(m) => m,
    })
}

/// The ends of a bracket: (η, f) below the root, (η, f, payload) at or above it.
type Bracket<T> = ((f64, f64), (f64, f64, T));

/// Root of an increasing function f on [lo, hi] with f(lo) < 0 ≤ f(hi): Illinois
/// regula falsi with geometric bisection as a safeguard. `eval` returns f and the
/// payload kept for the upper end. Stops when hi − lo ≤ rel · hi.
pub(crate) fn bracket_root<T: Clone>(
    mut lo: (f64, f64),
    mut hi: (f64, f64, T),
    rel: f64,
    max_iter: usize,
    mut eval: impl FnMut(f64) -> Result<(f64, T), String>,
) -> Result<Bracket<T>, String> {
    let mut side = 0i32;
    let (mut flo, mut fhi) = (lo.1, hi.1);
    let mut widths = [f64::INFINITY; 3];
    for _ in 0..max_iter {
        if hi.0 - lo.0 <= rel * hi.0 {
            break;
        }
        let width = hi.0 - lo.0;
        let secant = hi.0 - fhi * (hi.0 - lo.0) / (fhi - flo);
        let bisect = if lo.0 > 0.0 && hi.0 / lo.0 > 4.0 {
            (lo.0 * hi.0).sqrt()
        } else if lo.0 <= 0.0 {
            hi.0 / 8.0
        } else {
            0.5 * (lo.0 + hi.0)
        };
        widths = [widths[1], widths[2], width];
        let stalled = widths[2] > 0.5 * widths[0];
        let t = if stalled || !(secant > lo.0 && secant < hi.0) {
            bisect
        } else {
            // keep the secant point away from the ends
            secant.clamp(lo.0 + 1e-3 * width, hi.0 - 1e-3 * width)
        };
        let (f, payload) = eval(t)?;
        if stalled {
            widths = [f64::INFINITY; 3];
        }
        if f >= 0.0 {
            hi = (t, f, payload);
            fhi = f;
            if side == 1 {
                flo *= 0.5;
            }
            side = 1;
        } else {
            lo = (t, f);
            flo = f;
            if side == -1 {
                fhi *= 0.5;
            }
            side = -1;
        }
    }
    Ok((lo, hi))
}

/// Solves for the least thickness η*(μ) of `arch` at friction `mu` (`f64::INFINITY`:
/// no sliding). Bad input is an `Err`; what the solver found (a limit state, no
/// equilibrium, or an unresolved bracket) is inside the `Solution`.
pub fn solve(arch: &Arch, mu: f64, settings: &Settings) -> Result<Solution, InputError> {
    let mu = check_mu(mu)?;
    let mut candidates = Vec::new();
    let outcome = solve_inner(arch, mu, settings, &mut candidates);
    Ok(Solution {
        arch: arch.clone(),
        mu,
        outcome,
        candidates,
    })
}

fn solve_inner(arch: &Arch, mu: f64, settings: &Settings, log: &mut Vec<Candidate>) -> Outcome {
    let modes = ContactKind::active_at(mu);
    let mut ws = WorkingSet::initial(arch);
    let eta_max = 2.0 * (1.0 - 1e-9);
    let top = match margin_at(arch, eta_max, mu, modes, &mut ws, settings) {
        Ok(m) => m,
        Err(e) => return unresolved(0.0, 2.0, e),
    };
    if top.margin < 0.0 {
        return no_equilibrium(arch, mu, settings);
    }
    let bottom = match margin_at(arch, 0.0, mu, modes, &mut ws, settings) {
        Ok(m) => m,
        Err(e) => return unresolved(0.0, 2.0, e),
    };
    if bottom.margin >= -settings.adm_tol * scale_of(&bottom.x) {
        return Outcome::NoCollapse {
            reason:
                "a state is admissible at vanishing thickness, so the arch stands at every eta > 0"
                    .into(),
        };
    }
    let bracket = bracket_root(
        (0.0, bottom.margin.min(-f64::MIN_POSITIVE)),
        (eta_max, top.margin, top),
        settings.bracket_rel,
        200,
        |eta| {
            let m = margin_at(arch, eta, mu, modes, &mut ws, settings)?;
            Ok((m.margin, m))
        },
    );
    let (lo, hi) = match bracket {
        Ok(b) => b,
        Err(e) => return unresolved(0.0, 2.0, e),
    };
    let (eta_lo, eta_hi, m_hi) = (lo.0, hi.0, hi.2);

    // Candidate contacts at the upper end of the bracket, then the enumeration.
    let cand = candidates_at(
        arch,
        mu,
        eta_hi,
        &m_hi.x,
        Some(m_hi.margin.max(0.0)),
        modes,
        settings,
    );
    let sizes: Vec<usize> = (2..=5).collect();
    let first = enumerate(
        arch,
        mu,
        &cand,
        &sizes,
        m_hi.x,
        eta_hi,
        (eta_lo, eta_hi),
        eta_hi * (1.0 + 1e-9),
        settings,
        log,
    );
    if let Some(ls) = first.limit {
        // η_hi carries a state verified admissible by exact evaluation over the whole
        // arch, so η* ≤ η_hi: a verified pattern above it is not the least. (The lower
        // end comes from the LP's infeasibility decision, accurate only to HiGHS's
        // tolerance, and a verified state below it is simply better.)
        return if ls.eta > eta_hi * (1.0 + 1e-9) {
            unresolved(
                eta_lo,
                eta_hi,
                format!("the least verified pattern gives eta = {} above an admissible state at {eta_hi}", ls.eta),
            )
        } else {
            Outcome::Limit(ls)
        };
    }
    let Some(st) = first.least_static else {
        return unresolved(
            eta_lo,
            eta_hi,
            "no enumerated pattern gave a verified limit state".into(),
        );
    };
    // Non-associative gap: the least admissible state carries no mechanism without
    // dilatancy. A limit state then needs a larger η and another active set: widen the
    // pool to the best local maxima at that state, whatever their slack, and enumerate
    // determined patterns (four or five contacts).
    let pool = candidates_at(arch, mu, st.eta, &st.x, None, modes, settings);
    let second = enumerate(
        arch,
        mu,
        &pool,
        &[4, 5],
        st.x,
        st.eta,
        (eta_lo, eta_hi),
        0.0,
        settings,
        log,
    );
    match second.limit {
        Some(mut ls) if ls.eta >= st.eta * (1.0 - 1e-12) => {
            ls.eta_static = st.eta;
            Outcome::Limit(ls)
        }
        _ => unresolved(
            st.eta,
            f64::INFINITY,
            format!(
                "the least admissible state (eta = {}) has no non-associative mechanism, and no enumerated pattern gave a limit state above it",
                st.eta
            ),
        ),
    }
}

/// Local maxima of φ at the state (η, x) that may be active contacts, best first: with
/// `margin` given, those whose normalised slack is within `candidate_rel` of it; with
/// `None`, simply the best ones. At most `max_candidates`.
pub(crate) fn candidates_at(
    arch: &Arch,
    mu: f64,
    eta: f64,
    x: &Reactions,
    margin: Option<f64>,
    modes: &[ContactKind],
    settings: &Settings,
) -> Vec<Contact> {
    let state = State {
        arch,
        eta,
        mu,
        x: *x,
    };
    let limit = margin.map_or(f64::INFINITY, |m| m + settings.candidate_rel * scale_of(x));
    let mut peaks: Vec<(f64, Peak)> = state
        .near_active(settings, f64::NEG_INFINITY)
        .into_iter()
        .filter(|p| modes.contains(&p.contact.kind))
        .map(|p| {
            (
                -p.value / grad_norm(arch, eta, mu, p.contact.kind, p.contact.beta),
                p,
            )
        })
        .filter(|(slack, _)| *slack <= limit)
        .collect();
    peaks.sort_by(|a, b| a.0.total_cmp(&b.0));
    peaks.truncate(settings.max_candidates);
    peaks.into_iter().map(|(_, p)| p.contact).collect()
}

/// What one enumeration found.
struct Enumeration {
    /// The verified limit state of least η.
    limit: Option<LimitState>,
    /// The least-η statically admissible refined state (with or without mechanism).
    least_static: Option<Refined>,
}

/// Refines every subset of `cand` of the given sizes (and the whole set), then
/// verifies: static admissibility over the whole arch, then a mechanism on the
/// active set. Groups go largest first (the whole set, then subsets by decreasing
/// size); every admissible state has η at least the static least thickness, so once
/// a limit state at most `stop_at` is verified, later groups are not tried.
#[allow(clippy::too_many_arguments)]
fn enumerate(
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
    let mut refined = Vec::new();
    for s in group {
        match solve_pattern(arch, mu, &s, x0, eta0, settings) {
            Ok(r) => refined.push((s, r)),
            Err(f) => log.push(Candidate {
                contacts: s,
                eta: None,
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
    refined.sort_by(|a, b| a.1.eta.total_cmp(&b.1.eta));
    let mut last_eta = f64::NAN;
    for (s, r) in refined {
        let push = |log: &mut Vec<Candidate>, verdict: String| {
            log.push(Candidate {
                contacts: s.clone(),
                eta: Some(r.eta),
                verdict,
            })
        };
        if out.limit.as_ref().is_some_and(|l| l.eta <= r.eta) {
            push(
                log,
                "not needed: a limit state of lower or equal eta was verified".into(),
            );
            continue;
        }
        let st = State {
            arch,
            eta: r.eta,
            mu,
            x: r.x,
        };
        let verdict = st.verdict(ContactKind::active_at(mu), settings);
        let worst = verdict.worst;
        if worst > settings.adm_tol {
            push(
                log,
                format!("rejected: not admissible over the arch (max phi = {worst:.2e})"),
            );
            continue;
        }
        if out.least_static.as_ref().is_none_or(|l| r.eta < l.eta) {
            out.least_static = Some(r.clone());
        }
        if r.eta == last_eta {
            push(log, "same state as a pattern already checked".into());
            continue;
        }
        last_eta = r.eta;
        let pattern = verdict.active;
        match mechanism::find(arch, r.eta, mu, &r.x, &pattern, settings) {
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
                out.limit = Some(LimitState {
                    mu,
                    eta: r.eta,
                    eta_static: r.eta,
                    x: r.x,
                    pattern,
                    mode,
                    mechanism: mech,
                    newton_residual: r.residual,
                    max_phi: worst,
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

fn unresolved(eta_lo: f64, eta_hi: f64, reason: String) -> Outcome {
    Outcome::Unresolved {
        eta_lo,
        eta_hi,
        reason,
    }
}

fn no_equilibrium(arch: &Arch, mu: f64, settings: &Settings) -> Outcome {
    match least_friction(arch, settings) {
        Ok(Some(mu_ms)) if mu < mu_ms => Outcome::NoEquilibrium {
            mu_ms: Some(mu_ms),
            reason: format!(
                "mu = {} is below mu_ms = {mu_ms:.10}: no thickness can stand (purely sliding collapse)", crate::arch::fmt_value(mu)
            ),
        },
        Ok(Some(mu_ms)) if mu < mu_ms * (1.0 + 1e-6) => Outcome::Unresolved {
            eta_lo: 0.0,
            eta_hi: 2.0,
            reason: format!(
                "mu = {} is within 1e-6 (relative) of mu_ms = {mu_ms:.10}, closer than the LP resolves admissibility",
                crate::arch::fmt_value(mu)
            ),
        },
        Ok(Some(mu_ms)) => Outcome::NoEquilibrium {
            mu_ms: Some(mu_ms),
            reason: format!(
                "mu = {} is above mu_ms = {mu_ms:.10}, but no thickness eta < 2 admits equilibrium at this friction",
                crate::arch::fmt_value(mu)
            ),
        },
        Ok(None) => Outcome::NoEquilibrium {
            mu_ms: None,
            reason: "no friction coefficient admits equilibrium for this opening".into(),
        },
        Err(e) => Outcome::NoEquilibrium {
            mu_ms: None,
            reason: format!("no thickness eta < 2 admits equilibrium (mu_ms not computed: {e})"),
        },
    }
}
