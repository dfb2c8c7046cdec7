//! The test that makes a limit state under the live load: an admissible state whose
//! active contacts carry a mechanism with positive live power.

use crate::arch::Arch;
use crate::collapse_mode::classify;
use crate::contact::Contact;
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
    Ok(found.map(|(mechanism, live_power)| {
        let contacts: Vec<Contact> = pairs.iter().map(|p| p.0).collect();
        LimitState {
            t: lambda,
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
