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

mod diagnosis;
mod enumerate;
pub mod solution;

pub use solution::{Candidate, LimitState, Outcome, Solution};

use crate::admissibility::WorkingSet;
use crate::arch::{check_mu, Arch, InputError};
use crate::contact::ContactKind;
use crate::search::{bracket_root, candidates_at, margin_at};
use crate::settings::Settings;
use crate::state::State;
use crate::statics::reaction_scale;
use diagnosis::{no_equilibrium, unresolved};
use enumerate::enumerate;

/// Solves for the least thickness η*(μ) of `arch` at friction `mu` (`f64::INFINITY`:
/// no sliding). Bad input is an `Err`; what the solver found (a limit state, no
/// equilibrium, or an unresolved bracket) is inside the `Solution`.
pub fn solve(arch: &Arch, mu: f64, settings: &Settings) -> Result<Solution, InputError> {
    let mu = check_mu(mu)?;
    settings.validate()?;
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
    let eta_max = crate::arch::ETA_TOP;
    // an LP that fails (not infeasible: a numerical failure of the back end) leaves the
    // question undecided; its text is kept only as the detail of that reason
    let lp_failed = |at: &str, e: String| {
        unresolved(
            0.0,
            2.0,
            format!("the static margin LP could not be solved {at} (LP back end: {e}); no decision at this mu"),
        )
    };
    let top = match margin_at(arch, eta_max, mu, modes, &mut ws, settings) {
        Ok(m) => m,
        Err(e) => return lp_failed("at the thickness limit", e),
    };
    if top.margin < 0.0 {
        return no_equilibrium(arch, mu, settings);
    }
    let bottom = match margin_at(arch, 0.0, mu, modes, &mut ws, settings) {
        Ok(m) => m,
        Err(e) => return lp_failed("at vanishing thickness", e),
    };
    if bottom.margin >= -settings.adm_tol * reaction_scale(&bottom.x) {
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
        Err(e) => return lp_failed("while bracketing eta_s", e),
    };
    let (eta_lo, eta_hi, m_hi) = (lo.0, hi.0, hi.2);

    // Candidate contacts at the upper end of the bracket, then the enumeration.
    let top = State {
        arch,
        eta: eta_hi,
        mu,
        x: m_hi.x,
    };
    let cand = candidates_at(&top, Some(m_hi.margin.max(0.0)), modes, settings);
    let sizes: Vec<usize> = (2..=5).collect();
    let first = enumerate(
        arch,
        mu,
        &cand,
        &sizes,
        m_hi.x,
        eta_hi,
        (eta_lo, eta_hi),
        eta_hi * (1.0 + settings.root_slack),
        settings,
        log,
    );
    let top_slack = eta_hi * (1.0 + settings.root_slack);
    if let Some(ls) = first.limit {
        // η_hi carries a state verified admissible by exact evaluation over the whole
        // arch, so η* ≤ η_hi: a verified pattern above it is not the least. (The lower
        // end comes from the LP's infeasibility decision, accurate only to HiGHS's
        // tolerance, and a verified state below it is simply better.) When the least
        // admissible state was refined inside the bracket, it carries no mechanism: the
        // non-associative gap below, with that state as η_s.
        if ls.eta <= top_slack {
            return Outcome::Limit(ls);
        }
        if !first
            .least_static
            .as_ref()
            .is_some_and(|st| st.eta <= top_slack)
        {
            return unresolved(
                eta_lo,
                eta_hi,
                format!("the least verified pattern gives eta = {} above an admissible state at {eta_hi}", ls.eta),
            );
        }
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
    let least = State {
        arch,
        eta: st.eta,
        mu,
        x: st.x,
    };
    let pool = candidates_at(&least, None, modes, settings);
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
        Some(mut ls) if ls.eta >= st.eta * (1.0 - settings.same_root) => {
            ls.eta_static = st.eta;
            ls.x_static = st.x;
            Outcome::Limit(ls)
        }
        _ => Outcome::Unresolved {
            eta_lo: st.eta,
            eta_hi: f64::INFINITY,
            reason: format!(
                "the least admissible state (eta = {}) has no non-associative mechanism, and no enumerated pattern gave a limit state above it",
                st.eta
            ),
            least_static: Some((st.eta, st.x)),
        },
    }
}
