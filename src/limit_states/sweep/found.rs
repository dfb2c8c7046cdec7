//! What the sweep reports: the limit states it met, the points it checked that carry no
//! mechanism, and why it stopped if it could not finish.

use crate::arch::Arch;
use crate::collapse_mode::{classify, CollapseMode};
use crate::contact::Contact;
use crate::load::Side;
use crate::mechanism::Mechanism;
use crate::settings::Settings;
use crate::statics::Reactions;
use crate::undecided::Undecided;

/// What the sweep found.
#[derive(Debug, Clone)]
pub struct Sweep {
    /// Limit states above η_s (η_s itself excluded), ascending in η.
    pub states: Vec<SweptState>,
    /// Events processed.
    pub events: usize,
    /// Every point checked whose active contacts carry no mechanism (events, and the
    /// roots at which three contacts' columns become dependent), in the order checked:
    /// the evidence behind "no limit state there" that a certificate can carry.
    pub no_mechanism: Vec<CheckedPoint>,
    /// Why the sweep could not finish, if it could not.
    pub failure: Option<Undecided>,
}

impl Sweep {
    /// A sweep that found nothing and finished: no admissible state to follow.
    pub(super) fn nothing() -> Sweep {
        Sweep {
            states: vec![],
            events: 0,
            no_mechanism: vec![],
            failure: None,
        }
    }

    /// A sweep that could not start, and why.
    pub(super) fn failed(why: Undecided) -> Sweep {
        Sweep {
            failure: Some(why),
            ..Sweep::nothing()
        }
    }
}

/// A point of the sweep whose active contacts were checked and carry no mechanism.
#[derive(Debug, Clone)]
pub struct CheckedPoint {
    /// Thickness ratio.
    pub eta: f64,
    /// Reactions.
    pub x: Reactions,
    /// Every contact active there, by increasing (β, side, kind).
    pub pattern: Vec<Contact>,
    /// The side of the loaded section of each contact (load sweeps; `After` elsewhere).
    pub sides: Vec<Side>,
}

/// A limit state found by the sweep.
#[derive(Debug, Clone)]
pub struct SweptState {
    /// Thickness ratio.
    pub eta: f64,
    /// Reactions.
    pub x: Reactions,
    /// Every contact active there, by increasing β.
    pub pattern: Vec<Contact>,
    /// The collapse mode named from the pattern.
    pub mode: CollapseMode,
    /// A mechanism on them.
    pub mechanism: Mechanism,
    /// The side of the loaded section of each contact (load sweeps; `After` elsewhere).
    pub sides: Vec<Side>,
    /// The live-load power of the mechanism (load sweeps; 0 elsewhere).
    pub live_power: f64,
}

impl SweptState {
    /// A limit state of the thickness problem (no live load) at the state (`arch`, η, x):
    /// its active contacts, the mode they are named, and a mechanism on them.
    pub(crate) fn unloaded(
        arch: &Arch,
        (eta, x): (f64, Reactions),
        pattern: Vec<Contact>,
        mechanism: Mechanism,
        settings: &Settings,
    ) -> SweptState {
        let mode = classify(
            &pattern,
            0.5 * (arch.beta_right() + arch.beta_left()),
            settings.same_joint,
        );
        SweptState {
            eta,
            x,
            sides: vec![Side::After; pattern.len()],
            pattern,
            mode,
            mechanism,
            live_power: 0.0,
        }
    }
}
