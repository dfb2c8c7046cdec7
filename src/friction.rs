//! The friction-only problem (formulation §6): the least friction coefficient μ_ms for
//! which some state satisfies |T| ≤ μN at every joint. Neither T nor N involves w or
//! η, so this is a problem in (h, v) alone; below μ_ms no thickness can stand.
//!
//! The LP bracket (constraint generation over the continuum, [`crate::search::bracket_root`] in μ) gives the
//! candidate sliding contacts; the pattern's system with μ unknown (and the KKT
//! conditions of min μ when it has fewer than three contacts) is solved by Newton and
//! verified over the whole arch, as for the thickness problem.

use crate::admissibility::WorkingSet;
use crate::arch::Arch;
use crate::contact::{Contact, ContactKind, Location};
use crate::refine::{solve_system, Unknowns};
use crate::search::{bracket_root, candidates_at, margin_at};
use crate::settings::Settings;
use crate::state::State;
use crate::statics::actions;
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
    /// True when μ comes from a verified exact pattern (or is the exact chord value
    /// tan(Δ/2) of an infimum); false when only the LP bracket (relative width
    /// `bracket_rel`) is available.
    pub exact: bool,
    /// False when μ_ms is an infimum approached only as the reactions grow without bound:
    /// a weightless line of thrust along the chord, at T/N = tan(Δ/2) at both springings
    /// ([`chord_limit`]); `x` is then that line's direction (|x|∞ = 1), not a state.
    pub attained: bool,
}

/// Solves the friction-only problem. `Ok(None)` when no finite μ suffices.
pub fn friction_limit(
    arch: &Arch,
    settings: &Settings,
) -> Result<Option<FrictionLimit>, Undecided> {
    if arch.fill().is_some() {
        return Err(Undecided::NotCovered(
            "with fill the sliding rows depend on eta: the friction limit is a curve mu_ms(eta), not computed yet".into(),
        ));
    }
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
            attained: true,
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
            attained: true,
        });
    }
    // the weightless line along the chord, where the bracket reaches it and no bounded
    // state does better
    if let Some(chord) = chord_limit(arch) {
        let reached = chord.mu <= mu_hi * (1.0 + settings.bracket_rel);
        if reached && best.as_ref().is_none_or(|b| chord.mu < b.mu) {
            return Ok(Some(chord));
        }
    }
    Ok(Some(best.unwrap_or(FrictionLimit {
        mu: mu_hi,
        x: x_hi,
        pattern: cand,
        exact: false,
        attained: true,
    })))
}

/// The friction of a weightless line of thrust along the chord of an arch of opening
/// Δ = β_L − β_R < π: a constant force (h, v) = (sin m, cos m), m the middle angle, has
/// N = cos(β − m) > 0 and |T|/N = |tan(β − m)| at every joint, the most, tan(Δ/2), at
/// both springings, and no constant force does better (its worst joint is a springing).
/// Far along it the weight no longer counts: μ_ms ≤ tan(Δ/2), with equality only as an
/// infimum. `None` for Δ ≥ π (no such line keeps N > 0).
pub fn chord_limit(arch: &Arch) -> Option<FrictionLimit> {
    let (br, bl) = (arch.beta_right(), arch.beta_left());
    let half = 0.5 * (bl - br);
    if half >= 0.5 * std::f64::consts::PI {
        return None;
    }
    let m = 0.5 * (br + bl);
    let x = [m.sin(), m.cos(), 0.0];
    let mu = half.tan();
    let at_springings = [(br, Location::Springing), (bl, Location::Springing)];
    let pattern = at_springings
        .iter()
        .filter_map(|&(beta, at)| {
            let a = actions(arch, 1.0, beta);
            let phi = |k: ContactKind| {
                let g = a.activation(k, 0, 1.0, mu).g;
                g[0] * x[0] + g[1] * x[1] + g[2] * x[2]
            };
            SLIDES
                .into_iter()
                .max_by(|p, q| phi(*p).total_cmp(&phi(*q)))
                .map(|kind| Contact {
                    beta,
                    kind,
                    at,
                    free: false,
                })
        })
        .collect();
    Some(FrictionLimit {
        mu,
        x,
        pattern,
        exact: true,
        attained: false,
    })
}

/// μ_ms alone (see [`friction_limit`]).
pub fn least_friction(arch: &Arch, settings: &Settings) -> Result<Option<f64>, Undecided> {
    Ok(friction_limit(arch, settings)?.map(|f| f.mu))
}
