//! A limit state under the live load, and the test that makes one: an admissible state
//! whose active contacts carry a mechanism with positive live power.

use crate::arch::Arch;
use crate::collapse_mode::{classify, CollapseMode};
use crate::contact::Contact;
use crate::family::Tagged;
use crate::load::{LiveLoad, Side};
use crate::lp::LpOutcome;
use crate::mechanism::{self, Mechanism};
use crate::settings::Settings;
use crate::state::State;
use crate::statics::Reactions;
use crate::undecided::Undecided;

/// A limit state under the live load: an admissible state at multiplier λ whose active
/// contacts carry a mechanism with positive live power.
#[derive(Debug, Clone)]
pub struct LoadLimitState {
    /// The multiplier.
    pub lambda: f64,
    /// Reactions.
    pub x: Reactions,
    /// Every contact active there, by increasing β (at the point load's joint, the side
    /// of the loaded section in `sides`).
    pub pattern: Vec<Contact>,
    /// The side of the loaded section of each contact (`After` away from the point load).
    pub sides: Vec<Side>,
    /// The collapse mode named from the pattern.
    pub mode: CollapseMode,
    /// A mechanism on them (its `power` is the total external power).
    pub mechanism: Mechanism,
    /// The live load's power in that mechanism (> 0).
    pub live_power: f64,
    /// `Some(λ_to)` when this state is the least of a continuum of limit states that
    /// reaches up to λ_to (see [`continua`](super::continua)); `None` for an isolated limit state.
    pub continuum_to: Option<f64>,
}

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
) -> Result<Option<LoadLimitState>, Undecided> {
    let st = State { arch, eta, mu, x };
    let found = match mechanism::find_under_load(&st, lambda, load, pairs, settings) {
        Ok(m) => m,
        Err(LpOutcome::Failed(e)) => return Err(Undecided::back_end(e)),
        Err(LpOutcome::Infeasible) => None,
    };
    Ok(found.map(|(mechanism, live_power)| {
        let contacts: Vec<Contact> = pairs.iter().map(|p| p.0).collect();
        LoadLimitState {
            lambda,
            x,
            mode: classify(
                &contacts,
                0.5 * (arch.beta_right() + arch.beta_left()),
                settings.same_joint,
            ),
            sides: pairs.iter().map(|p| p.1).collect(),
            pattern: contacts,
            mechanism,
            live_power,
            continuum_to: None,
        }
    }))
}
