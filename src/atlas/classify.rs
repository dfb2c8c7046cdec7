//! The kind of one (α, μ): what the complete limit-state search says about uniqueness.

use crate::arch::{Arch, InputError};
use crate::limit_states::{survey, LimitState};
use crate::settings::Settings;
use crate::undecided::Undecided;

/// What the search says at one (α, μ).
#[derive(Debug, Clone, Copy, PartialEq, Eq, PartialOrd, Ord)]
pub enum Kind {
    /// η_s carries a limit state and no other exists above it.
    Unique,
    /// η_s carries a limit state and others exist above it (or, at μ_ms, the vertical
    /// branch: every thickness from η_s up).
    NonUnique,
    /// η_s carries no limit state (a non-associative gap, or η_s = 0 an infimum); limit
    /// states may exist above it.
    NoMechanismAtEta,
    /// No thickness stands (μ < μ_ms).
    NoEquilibrium,
}

impl Kind {
    /// The contract's name.
    pub fn name(self) -> &'static str {
        match self {
            Kind::Unique => "unique",
            Kind::NonUnique => "non_unique",
            Kind::NoMechanismAtEta => "no_mechanism_at_eta",
            Kind::NoEquilibrium => "no_equilibrium",
        }
    }
}

/// The classification of one (α, μ): its kind and the η of every limit state, or why the
/// search did not decide.
pub type Classified = Result<(Kind, Vec<f64>), Undecided>;

/// The kind of `arch` at `mu` by the complete search, with the η of its limit states.
pub fn classify(arch: &Arch, mu: f64, settings: &Settings) -> Result<Classified, InputError> {
    Ok(classify_states(arch, mu, settings)?.0)
}

/// [`classify`], with the limit states above η_s the search found (also where it did not
/// settle), for the atlas to follow.
pub(super) fn classify_states(
    arch: &Arch,
    mu: f64,
    settings: &Settings,
) -> Result<(Classified, Vec<LimitState>), InputError> {
    let sv = survey(arch, mu, settings)?;
    if matches!(sv.solution.outcome, crate::Outcome::NoEquilibrium { .. }) {
        return Ok((Ok((Kind::NoEquilibrium, Vec::new())), Vec::new()));
    }
    let states = match &sv.states {
        Ok(s) => s,
        Err(e) => {
            // not searched to the end, but η_s carries a limit state and another was found
            // above it (verified on the continuum): non-unique all the same
            let kind = match sv.limit_at_eta_s() {
                Some(ls) if !sv.found.is_empty() => {
                    let above = sv.found.iter().map(|s| s.t);
                    Ok((
                        Kind::NonUnique,
                        std::iter::once(ls.eta).chain(above).collect(),
                    ))
                }
                _ => Err(e.clone()),
            };
            return Ok((kind, sv.found));
        }
    };
    let mut etas: Vec<f64> = states.above.iter().map(|s| s.t).collect();
    if states.mechanism_at_eta_s {
        etas.insert(0, states.eta_s);
    }
    let kind = if !states.mechanism_at_eta_s || !states.attained {
        Kind::NoMechanismAtEta
    } else if states.vertical.is_some() || !states.above.is_empty() {
        Kind::NonUnique
    } else {
        Kind::Unique
    };
    Ok((Ok((kind, etas)), states.above.clone()))
}
