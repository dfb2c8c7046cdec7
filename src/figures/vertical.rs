//! A state on the vertical branch μ = μ_ms above η_ms, for the paper's purely sliding
//! figures: the friction conditions pin (h, v) to the least state's, and w is the middle
//! of the interval the hinge conditions leave at η (every such state is a limit state,
//! with the purely sliding mechanism of the friction limit's contacts).

use crate::arch::Arch;
use crate::contact::{Contact, ContactKind};
use crate::mechanism::{self, Mechanism};
use crate::settings::Settings;
use crate::state::State;
use crate::statics::{actions, Reactions};

/// The hinge conditions of a continuous arch are sampled at this many joints for the
/// interval of w (the state is then checked over the whole arch).
const SAMPLES: usize = 4097;

/// The state at η with (h, v) of `pinned` and w in the middle of its admissible interval,
/// its active contacts, and the purely sliding mechanism on `sliding`. `None` when that
/// state is not admissible over the whole arch or carries no such mechanism.
pub(super) fn vertical_state(
    arch: &Arch,
    eta: f64,
    mu: f64,
    pinned: Reactions,
    sliding: &[Contact],
    settings: &Settings,
) -> Option<(Reactions, Vec<Contact>, Mechanism)> {
    let joints = arch.angles(SAMPLES);
    // each hinge row g·x + c ≤ 0 with (h, v) fixed bounds w on one side
    let (mut lo, mut hi) = (f64::NEG_INFINITY, f64::INFINITY);
    for &beta in &joints {
        let a = actions(arch, eta, beta);
        for kind in ContactKind::HINGES {
            let row = a.activation(kind, 0, eta, mu);
            let rest = row.g[0] * pinned[0] + row.g[1] * pinned[1] + row.c;
            match row.g[2] {
                g if g > 0.0 => hi = hi.min(-rest / g),
                g if g < 0.0 => lo = lo.max(-rest / g),
                _ => {}
            }
        }
    }
    if !(lo <= hi && lo.is_finite() && hi.is_finite()) {
        return None;
    }
    let x = [pinned[0], pinned[1], 0.5 * (lo + hi)];
    let st = State { arch, eta, mu, x };
    let verdict = st
        .admissible_verdict(ContactKind::active_at(mu), settings)
        .ok()?;
    let mech = mechanism::find(&st, sliding, settings).ok()??;
    Some((x, verdict.active, mech))
}
