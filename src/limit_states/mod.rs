//! Every limit state at one friction coefficient (formulation §5, paper §2.5).
//!
//! At given (η, μ): no statically admissible state → collapse; admissible states but no
//! limit state → safe; a limit state (an admissible state whose active contacts carry a
//! non-associative mechanism) → limit equilibrium. η_s(μ), the least η with an admissible
//! state, is what [`crate::limit::solve`] computes (`eta_static`); limit states can exist
//! at η_s and above it. This module finds all of them with η in [η_s, 2):
//!
//! * at η_s, the kinematic LP on the least state's active set ([`crate::limit`]);
//! * above η_s, for a discrete arch, a sweep of the admissible polytope P(η) in η
//!   ([`sweep`]): limit states need four contacts at one point, which happens only where P
//!   changes combinatorially, and the sweep visits every such event. A discrete arch that
//!   stands at every η > 0 (`solve` says `NoCollapse`, η_s = 0) is swept from η = 0.

pub mod branch_end;
pub(crate) mod discretised;
mod follow;
pub mod poly;
pub mod ridge;
pub mod sweep;

use crate::admissibility::WorkingSet;
use crate::arch::{Arch, InputError, JointLayout};
use crate::contact::{Contact, ContactKind, Location};
use crate::limit::{bounded, solve, LeastLimitState, Outcome, Solution};
use crate::mechanism;
use crate::search::margin_at;
use crate::settings::{LimitStateSearch, Settings};
use crate::state::State;
use crate::statics::Reactions;
use crate::undecided::Undecided;
pub use branch_end::{branch_end, end_on, BranchEnd, EndCondition};
use discretised::{agreed, Carried, Part, Unsettled};
use follow::refine;
pub use follow::{follow, lost_at};
use ridge::Start;
pub use sweep::{CheckedPoint, LimitState};

/// Every limit state of a discrete arch at friction μ, above the least admissible state.
#[derive(Debug, Clone)]
pub struct LimitStates {
    /// η_s(μ), the least η with a statically admissible state; 0 when the arch stands at
    /// every η > 0 (a state without tension is admissible at vanishing thickness: no arch
    /// has η = 0, so η_s is then an infimum of thicknesses, with no limit state there).
    pub eta_s: f64,
    /// Whether η_s is attained by a bounded state: false when the least state's reactions
    /// exceed `settings.unbounded_reactions` × (1 + span) (η_s is then an infimum
    /// approached as the reactions grow without bound).
    pub attained: bool,
    /// Whether the least admissible state carries a non-associative mechanism.
    pub mechanism_at_eta_s: bool,
    /// Limit states strictly above η_s, ascending in η.
    pub above: Vec<LimitState>,
    /// Events of the sweep (of the finer discretisation for a continuous arch).
    pub events: usize,
    /// The points of a discrete arch's sweep whose active contacts carry no mechanism
    /// (empty for the other methods): the evidence a certificate carries.
    pub no_mechanism: Vec<CheckedPoint>,
    /// How the set was established: `"sweep"` (discrete arch: complete by the sweep's
    /// argument) or `"refined J/2J"` (continuous arch: the refined limit states of the
    /// discretisations of J and 2J pieces agree).
    pub method: String,
    /// At μ = μ_ms: the sliding contacts whose purely sliding mechanism makes every
    /// admissible state at every η ≥ η_s a limit state (the vertical branch; `above` is
    /// then empty: its limit states are not isolated). Checked at the least state.
    pub vertical: Option<Vec<Contact>>,
}

/// Everything `solve` reports at one μ: the thickness solution (η_s, the least limit
/// state found near it) and the search for every limit state above η_s.
#[derive(Debug, Clone)]
pub struct Survey {
    /// The solution of the thickness problem.
    pub solution: Solution,
    /// Every limit state above η_s, or why the search could not be completed.
    pub states: Result<LimitStates, Undecided>,
    /// Where the search is not completed because a continuous arch's discretisations do
    /// not settle: the limit states above η_s that some of them found, each refined and
    /// verified on the continuum (each is a limit state; others may exist), ascending.
    /// Empty otherwise.
    pub found: Vec<LimitState>,
}

impl Survey {
    /// The solve's least state where it is a limit state at η_s (η_s attained, and its
    /// active contacts carry a mechanism), whatever the search above it found.
    pub fn limit_at_eta_s(&self) -> Option<&LeastLimitState> {
        match &self.solution.outcome {
            Outcome::Limit(ls) if ls.eta == ls.eta_static && ls.attained => Some(ls),
            _ => None,
        }
    }

    /// Whether exactly one limit state exists with η in [η_s, 2) (`None`: the search was
    /// not completed, and the limit states it found are not two: a least state carrying a
    /// mechanism and one found above it, or two above, decide `false` all the same).
    pub fn unique(&self) -> Option<bool> {
        let s = match &self.states {
            Ok(s) => s,
            Err(_) => {
                let at_eta_s = usize::from(self.limit_at_eta_s().is_some());
                return (at_eta_s + distinct(&self.found).len() >= 2).then_some(false);
            }
        };
        if s.vertical.is_some() {
            return Some(false);
        }
        Some(usize::from(s.mechanism_at_eta_s) + s.above.len() == 1)
    }
}

/// Two limit states found are one where their η and reactions agree to this (relative):
/// the list found is kept apart by patterns, and near where a branch ends a contact at the
/// edge of being active could list one state twice.
const DISTINCT_REL: f64 = 1e-9;

/// The distinct states of `states` (η and reactions to [`DISTINCT_REL`]), the first of each.
pub(crate) fn distinct(states: &[LimitState]) -> Vec<LimitState> {
    let same = |p: &LimitState, q: &LimitState| {
        let scale = 1.0 + crate::statics::reaction_scale(&q.x);
        (p.t - q.t).abs() <= DISTINCT_REL * q.t
            && (0..3).all(|k| (p.x[k] - q.x[k]).abs() <= DISTINCT_REL * scale)
    };
    let mut out: Vec<LimitState> = Vec::new();
    for p in states {
        if !out.iter().any(|q| same(p, q)) {
            out.push(p.clone());
        }
    }
    out
}

/// The extreme rays of the mechanism cones of a survey's limit states, each a list of
/// rates on the mechanism's contacts summing to 1
/// ([`crate::mechanism::extreme_mechanisms`]): one ray where the cone has dimension 1.
#[derive(Debug, Clone, Default)]
pub struct Rays {
    /// The least limit state's (`Outcome::Limit`), when there is one.
    pub least: Option<Vec<Vec<f64>>>,
    /// Each limit state's above η_s, in the order of [`LimitStates::above`] (or of
    /// [`Survey::found`] where the search is not complete).
    pub above: Vec<Vec<Vec<f64>>>,
}

impl Survey {
    /// The extreme rays of every limit state's mechanism cone (for reports: not computed by
    /// the solve itself, which needs one representative only).
    pub fn rays(&self, settings: &Settings) -> Rays {
        let arch = &self.solution.arch;
        let least = match &self.solution.outcome {
            Outcome::Limit(ls) => Some(mechanism::extreme_mechanisms(
                arch,
                ls.eta,
                &ls.mechanism,
                settings,
            )),
            _ => None,
        };
        let above = self
            .states
            .as_ref()
            .map_or(&self.found, |s| &s.above)
            .iter()
            .map(|a| mechanism::extreme_mechanisms(arch, a.t, &a.mechanism, settings))
            .collect();
        Rays { least, above }
    }
}

/// [`solve`] and [`search`] together.
pub fn survey(arch: &Arch, mu: f64, settings: &Settings) -> Result<Survey, InputError> {
    let solution = solve(arch, mu, settings)?;
    let (states, found) = match search_found(&solution, settings) {
        Ok(s) => (Ok(s), Vec::new()),
        Err(u) => (Err(u.why), u.found),
    };
    Ok(Survey {
        solution,
        states,
        found,
    })
}

/// Searches every limit state of `arch` at friction `mu` with η above the least admissible
/// thickness η_s. The inner `Err` says why the search could not be completed (no least
/// state to start from, a failed sweep, discretisations that disagree).
pub fn search(
    arch: &Arch,
    mu: f64,
    settings: &Settings,
) -> Result<Result<LimitStates, Undecided>, InputError> {
    Ok(search_from(&solve(arch, mu, settings)?, settings))
}

/// [`search`] from a solution already computed (η_s and its least state): the inner
/// `Err` says why the search could not be completed.
pub fn search_after(sol: &Solution, settings: &Settings) -> Result<LimitStates, Undecided> {
    search_from(sol, settings)
}

/// With fill the sweep's rows are η φ, whose terms span 1/η in magnitude: below this η_s
/// the limit-state search is declined (a shallow segment of 0.07 rad under fill, η_s =
/// 1.8e-6, ran for minutes in the sweep).
const FILL_SWEEP_MIN_ETA: f64 = 1e-4;

fn search_from(sol: &Solution, settings: &Settings) -> Result<LimitStates, Undecided> {
    search_found(sol, settings).map_err(|u| u.why)
}

/// [`search_from`], with the limit states found where a continuous arch's discretisations
/// do not settle.
fn search_found(sol: &Solution, settings: &Settings) -> Result<LimitStates, Unsettled> {
    let (arch, mu) = (&sol.arch, sol.mu);
    if let (Some(sliding), Outcome::Limit(ls)) = (&sol.vertical, &sol.outcome) {
        return Ok(vertical_branch(sol, ls, sliding, settings)?);
    }
    // whether η_s is attained: the solve's word for a limit state (a large finite state
    // below every weightless direction is attained), else by the size of the reactions
    let (eta_s, x_s, mechanism_at_eta_s, attained) = match &sol.outcome {
        Outcome::Limit(ls) => (
            ls.eta_static,
            ls.x_static,
            ls.eta == ls.eta_static,
            ls.attained,
        ),
        Outcome::Unresolved {
            least_static: Some((eta, x)),
            ..
        } => (*eta, *x, false, bounded(arch, x, settings)),
        Outcome::NoCollapse { .. } if matches!(arch.layout(), JointLayout::Discrete(_)) => {
            return Ok(from_vanishing_thickness(arch, mu, settings)?);
        }
        _ => {
            return Err(
                Undecided::Resolution("no least admissible state to start from".into()).into(),
            )
        }
    };
    // an infimum approached only with reactions growing without bound is not a state: no
    // limit state exists at η_s itself (its "mechanism" would balance no finite thrust;
    // the virtual-work identity fails there)
    let mechanism_at_eta_s = mechanism_at_eta_s && attained;
    if arch.fill().is_some() && !attained {
        // the sweep on the rows times η starts inside the box there, where its vertices'
        // paths grow like 1/η; one such arch of 234 compared lost two limit states
        return Err(Undecided::NotCovered(
            "with fill, eta_s is an infimum (the least states' reactions grow without bound): the limit-state search above it is not covered yet".into(),
        ).into());
    }
    if arch.fill().is_some() && eta_s < FILL_SWEEP_MIN_ETA {
        return Err(Undecided::Resolution(format!(
            "with fill, eta_s = {eta_s:e} is below {FILL_SWEEP_MIN_ETA:e}: there the fill's 1/eta spreads the sweep's polynomials over that many orders of magnitude, and their roots are not resolved"
        )).into());
    }
    if eta_s < settings.sweep_min_eta {
        return Err(Undecided::Resolution(format!(
            "eta_s = {eta_s:e} is below {:e}, where the sweep's polynomial roots are not resolved",
            settings.sweep_min_eta
        ))
        .into());
    }
    // P(η) with an interior point just above η_s: at μ = ∞ no limit state lies above
    // (`hinges_only`), at finite μ every one lies on the ridge over ∂Q (`ridge`)
    // (the margin LP only where its answer is used: μ = ∞, or a search the ridge may do)
    // (with fill neither shortcut holds: the friction polygon moves with η, and P(η) need
    // not grow with η, so the sweep follows P(η) all the way up)
    let ridge_may_apply = mu.is_finite()
        && settings.limit_state_search == LimitStateSearch::Ridge
        && matches!(arch.weight(), crate::arch::WeightModel::Centreline)
        && arch.fill().is_none();
    let interior = (mu.is_infinite() || ridge_may_apply)
        && arch.fill().is_none()
        && interior_above(sol, eta_s, settings);
    if interior && mu.is_infinite() {
        return Ok(hinges_only(arch, eta_s, &x_s, mechanism_at_eta_s, settings));
    }
    let ridge = interior && ridge_may_apply;
    if !matches!(arch.layout(), JointLayout::Discrete(_)) {
        return continuous(
            arch,
            mu,
            eta_s,
            attained,
            mechanism_at_eta_s,
            ridge,
            settings,
        );
    }
    let lo = eta_s * (1.0 + settings.root_slack);
    let mut walk_failure = None;
    if ridge {
        match ridge::search(arch, mu, lo, 0.0, settings) {
            Err(e) => walk_failure = Some(e),
            Ok(r) => {
                return Ok(LimitStates {
                    eta_s,
                    attained,
                    mechanism_at_eta_s,
                    above: r.states,
                    events: r.candidates,
                    no_mechanism: Vec::new(),
                    method: "ridge".into(),
                    vertical: None,
                })
            }
        }
    }
    let sw = sweep::sweep(arch, mu, eta_s, x_s, settings);
    if let Some(f) = sw.failure {
        return Err(match walk_failure {
            Some(w) => f.map_text(|f| format!("{f}; {w}")),
            None => f,
        }
        .into());
    }
    let mut above: Vec<LimitState> = sw.states.into_iter().filter(|s| s.t > lo).collect();
    ridge::sort_states(&mut above, settings);
    Ok(LimitStates {
        eta_s,
        attained,
        mechanism_at_eta_s,
        above,
        events: sw.events,
        no_mechanism: sw.no_mechanism,
        method: "sweep".into(),
        vertical: None,
    })
}

/// A discrete arch that stands at every η > 0 (η_s = 0: a state without tension is
/// admissible at vanishing thickness, [`crate::limit::vanishing_thickness_state`]) can
/// still have limit states above: four contacts meeting where P(η) changes, with a
/// sliding mechanism (e.g. two voussoirs, two hinges and two slides at η ≈ 1.54).
/// The sweep starts at η = 0 from that state: P(0) is the set where M = 0 at every joint
/// (the hinge planes E and I of a joint coincide there), and the vertices just above it
/// come from the same first-order test as at any least state. No limit state is at η = 0
/// itself (no arch has zero thickness).
fn from_vanishing_thickness(
    arch: &Arch,
    mu: f64,
    settings: &Settings,
) -> Result<LimitStates, Undecided> {
    let x0 = crate::limit::vanishing_thickness_state(arch, mu, settings)?.ok_or_else(|| {
        Undecided::Resolution(
            "no state without tension at vanishing thickness to start from".into(),
        )
    })?;
    let sw = sweep::sweep(arch, mu, 0.0, x0, settings);
    if let Some(f) = sw.failure {
        return Err(f);
    }
    let mut above: Vec<LimitState> = sw.states.into_iter().filter(|s| s.t > 0.0).collect();
    ridge::sort_states(&mut above, settings);
    Ok(LimitStates {
        eta_s: 0.0,
        attained: bounded(arch, &x0, settings),
        mechanism_at_eta_s: false,
        above,
        events: sw.events,
        no_mechanism: sw.no_mechanism,
        method: "sweep from eta = 0 (the arch stands at every eta > 0)".into(),
        vertical: None,
    })
}

/// Whether P(η) has an interior point at η_s(1 + `root_slack`), the resolution at which η_s
/// itself is decided: a positive continuum margin of the margin LP (verified by the scan at
/// its state). P(η) grows with η, so it then has one at every larger η. The LP's working
/// set starts with the joints of the solution's limit state (where the least states are
/// tight), so that it needs few rounds of constraint generation.
fn interior_above(sol: &Solution, eta_s: f64, settings: &Settings) -> bool {
    let (arch, mu) = (&sol.arch, sol.mu);
    let eta1 = eta_s * (1.0 + settings.root_slack);
    let mut ws = WorkingSet::initial(arch);
    if let Outcome::Limit(ls) = &sol.outcome {
        for c in &ls.pattern {
            ws.add(c.beta, settings.working_set_gap);
        }
    }
    margin_at(
        arch,
        eta1,
        mu,
        ContactKind::active_at(mu),
        &mut ws,
        settings,
    )
    .is_ok_and(|m| m.margin > 0.0)
}

/// At μ = ∞ every mechanism is made of hinges, and a hinge-only λ has λᵀφ(x) = L_e(λ)
/// for every x (virtual work, formulation §6). At a limit state λᵀφ = 0, so L_e = 0 and
/// every contact that moves is active at *every* admissible state: the admissible set
/// P(η) has no interior. So once P(η) has an interior point ([`interior_above`]) there is
/// no limit state at any larger η: the search is complete without a sweep.
fn hinges_only(
    arch: &Arch,
    eta_s: f64,
    x_s: &Reactions,
    mechanism_at_eta_s: bool,
    settings: &Settings,
) -> LimitStates {
    LimitStates {
        eta_s,
        attained: bounded(arch, x_s, settings),
        mechanism_at_eta_s,
        above: Vec::new(),
        events: 0,
        no_mechanism: Vec::new(),
        method: "hinges only (mu = inf): P(eta) has an interior just above eta_s".into(),
        vertical: None,
    }
}

/// A continuous arch: sweep two discretisations (J and 2J equal pieces), carry each discrete
/// limit state over to the continuum (adjacent contacts of one kind merged into one
/// tangency contact), refine it by Newton, verify it over the whole arch, and accept the set
/// when both discretisations give the same one (where they differ, finer ones:
/// [`discretised::agreed`]). Each discretisation also hands over its ridge points whose
/// mechanism just fails, and the coarsest one (a finer one where needed) its states at
/// shifted μ ([`carried`]), so that a branch of the continuum is found up to its end.
fn continuous(
    arch: &Arch,
    mu: f64,
    eta_s: f64,
    attained: bool,
    mechanism_at_eta_s: bool,
    ridge: bool,
    settings: &Settings,
) -> Result<LimitStates, Unsettled> {
    let (mut walked, mut tried) = (0, 0);
    // each discretisation's shifted searches use the method its search at μ used
    let mut by_ridge_of: Vec<(usize, bool)> = Vec::new();
    let carry = |pieces: usize, part: Part| -> Result<Carried, Undecided> {
        let discrete = arch
            .clone()
            .with_blocks(pieces)
            .map_err(|e| Undecided::Discretisation(e.to_string()))?;
        let ridge = match part {
            Part::AtMu => ridge,
            Part::Shifted => by_ridge_of.iter().any(|&(p, r)| p == pieces && r),
        };
        let (carried, by_ridge) = carried(
            arch,
            &discrete,
            (mu, pieces),
            (eta_s, ridge),
            part,
            settings,
        )?;
        if part == Part::AtMu {
            tried += 1;
            walked += usize::from(by_ridge);
            by_ridge_of.push((pieces, by_ridge));
        }
        Ok(carried)
    };
    let same = |p: &LimitState, q: &LimitState| {
        discretised::same_state(p, q, settings.same_state_eta * p.t, settings)
    };
    let sort = |l: &mut Vec<LimitState>| ridge::sort_states(l, settings);
    let (fine, events, fine_pieces) = agreed(settings, carry, same, sort)?;
    Ok(LimitStates {
        eta_s,
        attained,
        mechanism_at_eta_s,
        above: fine,
        events: events.unwrap_or(0),
        no_mechanism: Vec::new(),
        method: format!(
            "refined {}/{}{}",
            fine_pieces / 2,
            fine_pieces,
            match walked {
                0 => "",
                w if w == tried => " (ridge)",
                _ => " (ridge and sweep)",
            }
        ),
        vertical: None,
    })
}

/// The limit states of `discrete`, the `pieces`-piece discretisation of `arch`, carried
/// over to the continuum at `mu` (adjacent contacts merged, Newton, checked there) and
/// kept above η_s (1 + `root_slack`); with the events of its search and whether the ridge
/// walked it (else the sweep; `ridge`: try the ridge first). `part` says which searches:
/// the one at `mu`, whose ridge points whose mechanism only just fails
/// (`Settings::carry_almost_rate`) are carried too, or the ones at μ (1 ∓ `carry_shift` /
/// pieces²) ([`discretised::shifted`]: a branch of the continuum that ends, or begins,
/// within the discretisation's error of `mu` is found by it on one side), which have no
/// events; a shifted search that fails adds nothing.
fn carried(
    arch: &Arch,
    discrete: &Arch,
    (mu, pieces): (f64, usize),
    (eta_s, ridge): (f64, bool),
    part: Part,
    settings: &Settings,
) -> Result<(Carried, bool), Undecided> {
    // the ridge of the discretisation, from η = 0: every point it gives is checked, and
    // the list is complete wherever P(η) of the continuum (hence of the discretisation,
    // which has fewer joints) has an interior point, i.e. above η_s(1 + root_slack)
    let walk = |m: f64| {
        ridge::search(discrete, m, 0.0, settings.carry_almost_rate, settings).map(|r| {
            let mut seeds: Vec<Start> = r.states.iter().map(start_of).collect();
            seeds.extend(r.almost);
            (seeds, r.candidates)
        })
    };
    let sweep = |m: f64| {
        discrete_sweep(discrete, m, pieces, settings)
            .map(|(s, e)| (s.iter().map(start_of).collect::<Vec<_>>(), e))
    };
    let (seeds, events, by_ridge, narrowed) = match part {
        Part::AtMu => {
            let at_mu = if ridge { walk(mu).ok() } else { None };
            let by_ridge = at_mu.is_some();
            let (seeds, events) = match at_mu {
                Some(w) => w,
                None => sweep(mu)?,
            };
            (seeds, Some(events), by_ridge, false)
        }
        Part::Shifted => {
            let search = |m: f64| if ridge { walk(m) } else { sweep(m) };
            let (found, narrowed) = discretised::shifted(mu, pieces, settings, search);
            let seeds = found.into_iter().flat_map(|(s, _)| s).collect();
            (seeds, None, ridge, narrowed)
        }
    };
    let h = arch.span() / pieces as f64;
    let states = seeds
        .iter()
        .filter_map(|(t, x, pattern)| refine(arch, mu, *t, *x, &merge(pattern, h), settings))
        .filter(|r| r.t > eta_s * (1.0 + settings.root_slack))
        .collect();
    let carried = Carried {
        states,
        events,
        narrowed,
    };
    Ok((carried, by_ridge))
}

/// A discrete limit state as a start for Newton on the continuum.
fn start_of(s: &LimitState) -> Start {
    (s.t, s.x, s.pattern.clone())
}

/// The sweep of a `pieces`-piece discretisation from its least admissible state: its
/// limit states and events.
fn discrete_sweep(
    discrete: &Arch,
    mu: f64,
    pieces: usize,
    settings: &Settings,
) -> Result<(Vec<LimitState>, usize), Undecided> {
    let start = match solve(discrete, mu, settings)
        .map_err(|e| Undecided::Discretisation(e.to_string()))?
        .outcome
    {
        Outcome::Limit(ls) => (ls.eta_static, ls.x_static),
        Outcome::Unresolved {
            least_static: Some(s),
            ..
        } => s,
        _ => {
            return Err(Undecided::Discretisation(format!(
                "the {pieces}-piece discretisation has no least state"
            )))
        }
    };
    let sw = sweep::sweep(discrete, mu, start.0, start.1, settings);
    match sw.failure {
        Some(f) => Err(f.map_text(|f| format!("{pieces} pieces: {f}"))),
        None => Ok((sw.states, sw.events)),
    }
}

/// A discrete pattern carried over to the continuum ([`crate::family::merge_adjacent`]; a
/// springing stays where it is), by increasing β.
fn merge(pattern: &[Contact], h: f64) -> Vec<Contact> {
    let tagged: Vec<(Contact, ())> = pattern.iter().map(|&c| (c, ())).collect();
    let mut out: Vec<Contact> =
        crate::family::merge_adjacent(&tagged, h, |c| c.0.at == Location::Springing)
            .into_iter()
            .map(|c| c.0)
            .collect();
    out.sort_by(|p, q| p.beta.total_cmp(&q.beta).then(p.kind.cmp(&q.kind)));
    out
}

/// At μ = μ_ms: the vertical branch, when the sliding contacts carry a mechanism at the
/// least state by themselves (the purely sliding one). Why that makes every admissible
/// state at every η ≥ η_s a limit state: the mechanism's rates λ are compatible,
/// Σ λ_i ∇ₓφ_i = 0, so Σ λ_i φ_i(x) is the same at every x, and it is 0 at the least
/// state, where these contacts are active. At any admissible state every φ_i ≤ 0, so each
/// contact the mechanism moves is active there too. Its power equals its dissipation
/// μ Σ N s ≥ 0 at any admissible state (virtual work), so it is a mechanism there as well.
fn vertical_branch(
    sol: &Solution,
    ls: &LeastLimitState,
    sliding: &[Contact],
    settings: &Settings,
) -> Result<LimitStates, Undecided> {
    let st = State {
        arch: &sol.arch,
        eta: ls.eta_static,
        mu: sol.mu,
        x: ls.x_static,
    };
    match crate::mechanism::find(&st, sliding, settings) {
        Ok(Some(_)) => Ok(LimitStates {
            eta_s: ls.eta_static,
            attained: true,
            mechanism_at_eta_s: ls.eta == ls.eta_static,
            above: Vec::new(),
            events: 0,
            no_mechanism: Vec::new(),
            method: "vertical branch".into(),
            vertical: Some(sliding.to_vec()),
        }),
        Ok(None) => Err(Undecided::Resolution(
            "at mu_ms the sliding contacts of the friction limit carry no mechanism at the least state".into(),
        )),
        Err(e) => Err(Undecided::Lp(format!("the kinematic LP of the vertical branch: {e:?}"))),
    }
}
