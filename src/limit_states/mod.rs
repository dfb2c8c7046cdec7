//! Every limit state at one friction coefficient (formulation §5, paper §2.5).
//!
//! At given (η, μ): no statically admissible state → collapse; admissible states but no
//! limit state → safe; a limit state (an admissible state whose active contacts carry a
//! non-associative mechanism) → limit equilibrium. η_s(μ), the least η with an admissible
//! state, is what [`crate::limit::solve`] computes (`eta_static`); limit states can exist
//! at η_s and above it. This module finds all of them with η in [η_s, 2):
//!
//! * at η_s, the kinematic LP on the least state's active set ([`crate::limit`]);
//! * above η_s, for a discrete arch, a sweep of the admissible polytope P(η) in η
//!   ([`sweep`]): limit states need four contacts at one point, which happens only where P
//!   changes combinatorially, and the sweep visits every such event.

pub mod poly;
pub mod sweep;

use crate::arch::{Arch, InputError, JointLayout};
use crate::limit::{solve, Outcome};
use crate::settings::Settings;
pub use sweep::SweptState;

/// Every limit state of a discrete arch at friction μ, above the least admissible state.
#[derive(Debug, Clone)]
pub struct LimitStates {
    /// η_s(μ), the least η with a statically admissible state.
    pub eta_s: f64,
    /// Whether the least admissible state carries a non-associative mechanism.
    pub mechanism_at_eta_s: bool,
    /// Limit states strictly above η_s, ascending in η.
    pub above: Vec<SweptState>,
    /// Events of the sweep.
    pub events: usize,
}

/// Searches every limit state of `arch` (discrete) at friction `mu`. `Ok(None)` when the
/// search does not apply (continuous arch, or no limit state at η_s to start from).
pub fn search(
    arch: &Arch,
    mu: f64,
    settings: &Settings,
) -> Result<Result<LimitStates, String>, InputError> {
    let sol = solve(arch, mu, settings)?;
    if !matches!(arch.layout(), JointLayout::Discrete(_)) {
        return Ok(Err(
            "the complete search is implemented for discrete arches".into(),
        ));
    }
    let (eta_s, x_s, mechanism_at_eta_s) = match sol.outcome {
        Outcome::Limit(ls) => (ls.eta_static, ls.x_static, ls.eta == ls.eta_static),
        Outcome::Unresolved {
            least_static: Some((eta, x)),
            ..
        } => (eta, x, false),
        _ => return Ok(Err("no least admissible state to start from".into())),
    };
    let sw = sweep::sweep(arch, mu, eta_s, x_s, settings);
    if let Some(f) = sw.failure {
        return Ok(Err(f));
    }
    let above = sw
        .states
        .into_iter()
        .filter(|s| s.eta > eta_s * (1.0 + settings.root_slack))
        .collect();
    Ok(Ok(LimitStates {
        eta_s,
        mechanism_at_eta_s,
        above,
        events: sw.events,
    }))
}
