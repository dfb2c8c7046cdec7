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
    pub states: Vec<LimitState>,
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

/// A limit state of any question: an admissible state at the parameter t (the thickness
/// ratio η, or a load's multiplier λ) whose active contacts carry a mechanism (under a live
/// load, one with positive live power).
#[derive(Debug, Clone)]
pub struct LimitState {
    /// The parameter: η (thickness) or λ (load multiplier).
    pub t: f64,
    /// Reactions.
    pub x: Reactions,
    /// Every contact active there, by increasing β (at a point load's joint, the side of
    /// the loaded section in `sides`).
    pub pattern: Vec<Contact>,
    /// The collapse mode named from the pattern.
    pub mode: CollapseMode,
    /// A mechanism on them (its `power` is the total external power).
    pub mechanism: Mechanism,
    /// The side of the loaded section of each contact (`After` away from a point load, and
    /// in the thickness question).
    pub sides: Vec<Side>,
    /// The live load's power in the mechanism (> 0 under a load; 0 in the thickness
    /// question).
    pub live_power: f64,
    /// Under a load: `Some(λ_to)` when this state is the least of a continuum of limit
    /// states that reaches up to λ_to (`multiplier::continua`); `None` for an isolated
    /// limit state.
    pub continuum_to: Option<f64>,
}

impl LimitState {
    /// An isolated limit state at (t, x) of `arch`: its active contacts with their sides,
    /// the mode they are named, a mechanism on them and its live power.
    pub(crate) fn new(
        arch: &Arch,
        (t, x): (f64, Reactions),
        (pattern, sides): (Vec<Contact>, Vec<Side>),
        (mechanism, live_power): (Mechanism, f64),
        settings: &Settings,
    ) -> LimitState {
        let mode = classify(
            &pattern,
            0.5 * (arch.beta_right() + arch.beta_left()),
            settings.same_joint,
        );
        LimitState {
            t,
            x,
            pattern,
            mode,
            mechanism,
            sides,
            live_power,
            continuum_to: None,
        }
    }

    /// A limit state of the thickness problem (no live load) at the state (`arch`, η, x).
    pub(crate) fn unloaded(
        arch: &Arch,
        (eta, x): (f64, Reactions),
        pattern: Vec<Contact>,
        mechanism: Mechanism,
        settings: &Settings,
    ) -> LimitState {
        let sides = vec![Side::After; pattern.len()];
        LimitState::new(arch, (eta, x), (pattern, sides), (mechanism, 0.0), settings)
    }
}
