//! The question an engineer brings: an arch of given thickness η at friction μ — does it
//! stand, and with what margins?
//!
//! * the least thickness η*(μ) ([`crate::limit::solve`]) and the geometric factor of
//!   safety η / η*(μ);
//! * the least friction at which this thickness stands, μ_min(η) — the inverse of the limit
//!   curve — and the friction factor μ / μ_min. Admissibility is monotone in μ, so μ_min is
//!   the root of the continuum margin s(η, μ) in μ: bracketed by the LP, then solved exactly
//!   by Newton on the active pattern with μ unknown (η fixed) and verified over the arch.
//!   When η ≥ η_ms the arch stands as soon as any state does, and μ_min = μ_ms (the
//!   friction-only problem, [`crate::friction`]);
//! * the collapse mode of η*(μ) (the mode this arch is closest to at this friction);
//! * the admissible state of largest margin at (η, μ): the "safest" line of thrust.

use crate::admissibility::{margin_over_arch, Goal, WorkingSet};
use crate::arch::{check_eta, check_mu, Arch, InputError};
use crate::collapse_mode::CollapseMode;
use crate::contact::{Contact, ContactKind};
use crate::friction::friction_limit;
use crate::limit::{solve, Outcome};
use crate::refine::{solve_system, Unknowns};
use crate::search::{bracket_root, candidates_at, margin_at};
use crate::settings::Settings;
use crate::state::State;
use crate::statics::Reactions;
use crate::undecided::Undecided;
use itertools::Itertools;

/// The smallest friction at which the upward search for a standing state starts.
const FIRST_TRIAL_MU: f64 = 1e-3;

/// With fill, the friction at which the search for μ_min starts (μ_ms moves with η there):
/// a thickness standing at it is reported as μ_min ≤ it.
const FILL_FIRST_MU: f64 = 1e-6;

/// The least friction at which a given thickness stands.
#[derive(Debug, Clone, PartialEq)]
pub enum LeastFriction {
    /// μ_min, with the active pattern of the state that reaches it. `exact` is true when
    /// Newton on that pattern converged and the state was verified over the arch (or
    /// μ_min = μ_ms from the exact friction-only problem); false when only the LP bracket
    /// (relative width `bracket_rel`) is known, and then `mu` is its upper end.
    Finite {
        /// μ_min.
        mu: f64,
        /// Active contacts of the limiting state.
        pattern: Vec<Contact>,
        /// Whether `mu` is exact (see above).
        exact: bool,
    },
    /// No friction makes this thickness stand (η < η*(∞), or nothing stands at all).
    Never,
}

/// The admissible state of largest margin.
#[derive(Debug, Clone, PartialEq)]
pub struct SafestState {
    /// Reactions x = (h, v, w) at the right springing.
    pub x: Reactions,
    /// Its margin: the least normalised slack min(−φ/‖∇ₓφ‖) over the arch (≥ 0).
    pub margin: f64,
}

/// The answer of [`assess`].
#[derive(Debug, Clone)]
pub struct Assessment {
    /// The thickness ratio assessed.
    pub eta: f64,
    /// The friction coefficient assessed (∞ allowed).
    pub mu: f64,
    /// What the solver found at μ: η*(μ) and its mode, or why there is none.
    pub limit: Outcome,
    /// Whether the arch stands: η ≥ η*(μ) (every η > 0 when there is no collapse).
    pub stands: bool,
    /// η / η*(μ) (∞ when the arch stands at every thickness; `None` when nothing stands
    /// or η*(μ) is unresolved).
    pub geometric_factor: Option<f64>,
    /// μ_min(η).
    pub least_friction: LeastFriction,
    /// μ / μ_min(η) (`None` when μ_min does not exist; ∞ when μ = ∞).
    pub friction_factor: Option<f64>,
    /// The collapse mode of η*(μ).
    pub mode: Option<CollapseMode>,
    /// The admissible state of largest margin at (η, μ), when the arch stands.
    pub safest: Option<SafestState>,
}

/// Assesses `arch` at thickness `eta` and friction `mu`. Bad input is an `Err`; what was
/// found is inside the [`Assessment`].
pub fn assess(
    arch: &Arch,
    eta: f64,
    mu: f64,
    settings: &Settings,
) -> Result<Assessment, InputError> {
    let eta = check_eta(eta)?;
    let mu = check_mu(mu)?;
    let solution = solve(arch, mu, settings)?;
    // with fill the admissible thicknesses need not form an interval (the scan says)
    let gaps = solution.scan.as_ref().is_some_and(|s| !s.gaps().is_empty());
    let limit = solution.outcome;
    let (stands, geometric_factor, mode) = match &limit {
        // statics decide whether it stands: η at least the least admissible thickness
        Outcome::Limit(ls) => (eta >= ls.eta_static, Some(eta / ls.eta), Some(ls.mode)),
        Outcome::NoCollapse { .. } => (true, Some(f64::INFINITY), None),
        Outcome::NoEquilibrium { .. } => (false, None, None),
        // η_hi carries a verified admissible state
        Outcome::Unresolved { eta_hi, .. } => (eta >= *eta_hi, None, None),
    };
    // with fill, whether this thickness stands is its own question (admissibility need not
    // grow with η): the safest state decides it, found once; and η/η* is a factor of
    // safety only where every thicker ring stands
    let (stands, geometric_factor, safest) = match arch.fill() {
        Some(_) => {
            let safest = safest_state(arch, eta, mu, settings);
            (safest.is_some(), geometric_factor.filter(|_| !gaps), safest)
        }
        None => {
            let safest = stands.then(|| safest_state(arch, eta, mu, settings));
            (stands, geometric_factor, safest.flatten())
        }
    };
    let least_friction = least_friction_for(arch, eta, settings);
    let friction_factor = match &least_friction {
        LeastFriction::Finite { mu: m, .. } if *m > 0.0 => Some(mu / m),
        LeastFriction::Finite { .. } => Some(f64::INFINITY),
        LeastFriction::Never => None,
    };
    Ok(Assessment {
        eta,
        mu,
        limit,
        stands,
        geometric_factor,
        least_friction,
        friction_factor,
        mode,
        safest,
    })
}

/// The admissible state of largest margin at (η, μ) (constraint generation to optimality).
pub fn safest_state(arch: &Arch, eta: f64, mu: f64, settings: &Settings) -> Option<SafestState> {
    let mut ws = WorkingSet::initial(arch);
    let m = margin_over_arch(
        arch,
        eta,
        mu,
        ContactKind::active_at(mu),
        &mut ws,
        Goal::Optimise,
        settings,
    )
    .ok()?;
    (m.margin >= 0.0).then_some(SafestState {
        x: m.x,
        margin: m.margin,
    })
}

/// Where the upward search for μ_min starts: just above μ_ms, and its margin there (the
/// answer itself, `Err`, where η already stands at μ_ms: the vertical branch). With fill
/// μ_ms moves with η (the friction-only problem is the ring's), so the search starts at
/// [`FILL_FIRST_MU`] instead, and stands there only as "μ_min ≤ it" (not exact).
fn lowest_trial(
    arch: &Arch,
    settings: &Settings,
    f: &mut impl FnMut(f64) -> Result<(f64, Reactions), Undecided>,
) -> Result<(f64, f64), LeastFriction> {
    if arch.fill().is_some() {
        let Ok((f_lo, _)) = f(FILL_FIRST_MU) else {
            return Err(LeastFriction::Never);
        };
        if f_lo >= 0.0 {
            return Err(LeastFriction::Finite {
                mu: FILL_FIRST_MU,
                pattern: Vec::new(),
                exact: false,
            });
        }
        return Ok((FILL_FIRST_MU, f_lo));
    }
    let Ok(Some(fl)) = friction_limit(arch, settings) else {
        return Err(LeastFriction::Never);
    };
    // Just above μ_ms: if η already stands there, μ_min = μ_ms (vertical branch).
    let mu_lo = fl.mu * (1.0 + settings.bracket_rel);
    let Ok((f_lo, _)) = f(mu_lo.max(f64::MIN_POSITIVE)) else {
        return Err(LeastFriction::Never);
    };
    if f_lo >= 0.0 {
        return Err(LeastFriction::Finite {
            mu: fl.mu,
            pattern: fl.pattern,
            exact: fl.exact,
        });
    }
    Ok((mu_lo, f_lo))
}

/// μ_min(η): the least friction coefficient at which thickness `eta` admits a statically
/// admissible state (the inverse of the limit curve η_s(μ)).
pub fn least_friction_for(arch: &Arch, eta: f64, settings: &Settings) -> LeastFriction {
    let kinds = &ContactKind::ALL;
    let mut ws = WorkingSet::initial(arch);
    let mut f = |mu: f64| -> Result<(f64, Reactions), Undecided> {
        let m = margin_at(arch, eta, mu, kinds, &mut ws, settings)?;
        Ok((m.margin, m.x))
    };
    // Without sliding the question is the thickness problem at μ = ∞.
    let stands_at_inf = margin_at(
        arch,
        eta,
        f64::INFINITY,
        &ContactKind::HINGES,
        &mut WorkingSet::initial(arch),
        settings,
    )
    .is_ok_and(|m| m.margin >= 0.0);
    if !stands_at_inf {
        return LeastFriction::Never;
    }
    let (mu_lo, f_lo) = match lowest_trial(arch, settings, &mut f) {
        Ok(lo) => lo,
        Err(answer) => return answer,
    };
    // A finite friction at which η stands: double until the margin is non-negative.
    let mut hi = mu_lo.max(FIRST_TRIAL_MU) * 2.0;
    let (mut f_hi, mut x_hi) = match f(hi) {
        Ok(v) => v,
        Err(_) => return LeastFriction::Never,
    };
    while f_hi < 0.0 {
        hi *= 4.0;
        if hi > crate::arch::MU_MAX_FINITE {
            // stands at μ = ∞ only: the limit curve approaches η asymptotically
            return LeastFriction::Finite {
                mu: f64::INFINITY,
                pattern: Vec::new(),
                exact: false,
            };
        }
        (f_hi, x_hi) = match f(hi) {
            Ok(v) => v,
            Err(_) => return LeastFriction::Never,
        };
    }
    let Ok((_, (mu_hi, margin_hi, x_hi))) = bracket_root(
        (mu_lo, f_lo),
        (hi, f_hi, x_hi),
        settings.bracket_rel,
        200,
        f,
    ) else {
        return LeastFriction::Never;
    };
    let top = State {
        arch,
        eta,
        mu: mu_hi,
        x: x_hi,
    };
    let cand = candidates_at(&top, Some(margin_hi.max(0.0)), kinds, settings);
    // Newton with μ unknown (η fixed) on the whole candidate set and its determined
    // subsets; the least μ verified admissible over the arch wins.
    let mut patterns: Vec<Vec<Contact>> = vec![cand.clone()];
    if cand.len() > 4 {
        patterns.extend(cand.iter().copied().combinations(4));
    }
    let mut best: Option<(f64, Vec<Contact>)> = None;
    for p in patterns {
        let Ok(r) = solve_system(&top, &p, Unknowns::Mu, settings) else {
            continue;
        };
        if r.mu.is_nan() || r.mu <= 0.0 || r.mu > mu_hi * (1.0 + settings.candidate_rel) {
            continue;
        }
        if best.as_ref().is_some_and(|b| b.0 <= r.mu) {
            continue;
        }
        let st = State {
            arch,
            eta,
            mu: r.mu,
            x: r.x,
        };
        let v = st.verdict(kinds, settings);
        if v.worst <= settings.adm_tol {
            best = Some((r.mu, v.active));
        }
    }
    match best {
        Some((mu, pattern)) => LeastFriction::Finite {
            mu,
            pattern,
            exact: true,
        },
        None => LeastFriction::Finite {
            mu: mu_hi,
            pattern: cand,
            exact: false,
        },
    }
}
