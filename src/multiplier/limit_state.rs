//! The test that makes a limit state under the live load: an admissible state whose
//! active contacts carry a mechanism with positive live power.

use crate::arch::Arch;
use crate::family::Tagged;
use crate::limit_states::LimitState;
use crate::load::{LiveLoad, Side};
use crate::lp::LpOutcome;
use crate::mechanism;
use crate::settings::Settings;
use crate::state::State;
use crate::statics::Reactions;
use crate::undecided::Undecided;

/// The limit state at (λ, x) on the active contacts `pattern`, if they carry a mechanism
/// with positive live power.
pub(super) fn limit_state_on(
    arch: &Arch,
    eta: f64,
    mu: f64,
    load: &LiveLoad,
    (lambda, x): (f64, Reactions),
    pairs: &[Tagged<Side>],
    settings: &Settings,
) -> Result<Option<LimitState>, Undecided> {
    let st = State { arch, eta, mu, x };
    let found = match mechanism::find_under_load(&st, lambda, load, pairs, settings) {
        Ok(m) => m,
        Err(LpOutcome::Failed(e)) => return Err(Undecided::back_end(e)),
        Err(LpOutcome::Infeasible) => None,
    };
    Ok(found.map(|m| {
        let contacts = pairs.iter().copied().unzip();
        LimitState::new(arch, (lambda, x), contacts, m, settings)
    }))
}

/// The limit state `from` (of a continuous or discrete arch under `load`) followed to the
/// thickness and friction (η, μ): Newton on its pattern with λ unknown from its (λ, x), the
/// state verified over the whole arch, its active contacts checked for a mechanism with
/// positive live power; or why the pattern carries no limit state there.
pub fn follow(
    arch: &Arch,
    (eta, mu): (f64, f64),
    load: &LiveLoad,
    from: &LimitState,
    settings: &Settings,
) -> Result<LimitState, String> {
    let pattern: Vec<Tagged<Side>> = from
        .pattern
        .iter()
        .copied()
        .zip(from.sides.iter().copied())
        .collect();
    let (lambda, x, active) =
        super::continuum::followed(arch, (eta, mu), load, (from.t, from.x), &pattern, settings)
            .ok_or("Newton on the pattern finds no admissible state")?;
    match limit_state_on(arch, eta, mu, load, (lambda, x), &active, settings) {
        Ok(Some(s)) => Ok(s),
        Ok(None) => Err(format!(
            "the pattern's state (lambda = {lambda}) carries no mechanism with positive live power"
        )),
        Err(e) => Err(e.to_string()),
    }
}
