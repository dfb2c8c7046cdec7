//! The friction-only problem (formulation §6): the least friction coefficient μ_ms for
//! which some state satisfies |T| ≤ μN at every joint. Neither T nor N involves w or
//! η, so this is a problem in (h, v) alone; below μ_ms no thickness can stand.
//!
//! The LP bracket (constraint generation over the continuum, Illinois in μ) gives the
//! candidate sliding contacts; the pattern's system with μ unknown (and the KKT
//! conditions of min μ when it has fewer than three contacts) is solved by Newton and
//! verified over the whole arch, as for the thickness problem.

use crate::admissibility::WorkingSet;
use crate::arch::Arch;
use crate::contact::Contact;
use crate::contact::ContactKind;
use crate::refine::{solve_system, Unknowns};
use crate::search::{bracket_root, candidates_at, margin_at};
use crate::settings::Settings;
use crate::state::State;
use crate::statics::Reactions;
use crate::undecided::Undecided;
use itertools::Itertools;

/// The friction-only search gives up above this μ (friction angle 90° − 1e-8 rad): an
/// arch that needs more stands by no finite friction (μ_ms reported as none).
pub const FRICTION_SEARCH_MAX: f64 = 1e8;

/// The sliding activation functions.
pub const SLIDES: [ContactKind; 2] = [ContactKind::SlidePlus, ContactKind::SlideMinus];

/// The friction limit of an arch.
#[derive(Debug, Clone)]
pub struct FrictionLimit {
    /// μ_ms: below it no state satisfies the friction conditions.
    pub mu: f64,
    /// Reactions (h, v) of the limiting state (w is irrelevant here and left as found).
    pub x: Reactions,
    /// The active sliding contacts, by increasing β.
    pub pattern: Vec<Contact>,
    /// True when μ comes from a verified exact pattern; false when only the LP bracket
    /// (relative width `bracket_rel`) is available.
    pub exact: bool,
}

/// Solves the friction-only problem. `Ok(None)` when no finite μ suffices.
pub fn friction_limit(
    arch: &Arch,
    settings: &Settings,
) -> Result<Option<FrictionLimit>, Undecided> {
    let mut ws = WorkingSet::initial(arch);
    let mut f = |mu: f64| -> Result<(f64, Reactions), Undecided> {
        let m = margin_at(arch, 1.0, mu, &SLIDES, &mut ws, settings)?;
        Ok((m.margin, m.x))
    };
    let mut hi = 1.0;
    let (mut fhi, mut xhi) = f(hi)?;
    while fhi < 0.0 {
        hi *= 4.0;
        if hi > FRICTION_SEARCH_MAX {
            return Ok(None);
        }
        (fhi, xhi) = f(hi)?;
    }
    let (f0, x0) = f(0.0)?;
    if f0 >= 0.0 {
        return Ok(Some(FrictionLimit {
            mu: 0.0,
            x: x0,
            pattern: Vec::new(),
            exact: true,
        }));
    }
    let (_, (mu_hi, margin_hi, x_hi)) =
        bracket_root((0.0, f0), (hi, fhi, xhi), settings.bracket_rel, 200, f)?;

    // η does not enter the friction-only problem (T and N involve neither w nor η)
    let top = State {
        arch,
        eta: 1.0,
        mu: mu_hi,
        x: x_hi,
    };
    let cand = candidates_at(&top, Some(margin_hi.max(0.0)), &SLIDES, settings);
    let mut best: Option<FrictionLimit> = None;
    let mut patterns: Vec<Vec<Contact>> = vec![cand.clone()];
    for k in (1..=3).rev() {
        if cand.len() > k {
            patterns.extend(cand.iter().copied().combinations(k));
        }
    }
    for p in patterns {
        let Ok(r) = solve_system(&top, &p, Unknowns::Mu, settings) else {
            continue;
        };
        if best.as_ref().is_some_and(|b| b.mu <= r.mu) {
            continue;
        }
        let st = State {
            arch,
            eta: 1.0,
            mu: r.mu,
            x: r.x,
        };
        let v = st.verdict(&SLIDES, settings);
        if v.worst > settings.adm_tol || r.mu > mu_hi * (1.0 + settings.root_slack) {
            continue;
        }
        let pattern = v.active;
        best = Some(FrictionLimit {
            mu: r.mu,
            x: r.x,
            pattern,
            exact: true,
        });
    }
    Ok(Some(best.unwrap_or(FrictionLimit {
        mu: mu_hi,
        x: x_hi,
        pattern: cand,
        exact: false,
    })))
}

/// μ_ms alone (see [`friction_limit`]).
pub fn least_friction(arch: &Arch, settings: &Settings) -> Result<Option<f64>, Undecided> {
    Ok(friction_limit(arch, settings)?.map(|f| f.mu))
}
