//! The least thickness η*(μ) of an arch at one friction coefficient (formulation §5).
//!
//! 1. **Bracket.** The continuum margin s(η) of the best state (constraint-generation
//!    LP, [`crate::admissibility`]) is increasing in η; η* is its root, bracketed by
//!    inverse quadratic interpolation and regula falsi safeguarded by (geometric)
//!    bisection (`bracket`; the test for an arch that stands at every thickness is
//!    `vanishing`). Along a curve the bracket starts from the previous μ's pattern.
//! 2. **Candidates.** At the upper end of the bracket, the local maxima of every φ whose
//!    normalised slack is within `candidate_rel` of the LP margin are the candidate
//!    active contacts.
//! 3. **Enumeration.** Every subset of 4 and 5 candidates, and the whole candidate set,
//!    is a pattern; Newton ([`crate::refine`]) solves its system exactly (`enumerate`).
//! 4. **Verification.** In increasing η, a refined state must be statically admissible
//!    over the whole arch (scan, `adm_tol`) and its active set must carry a mechanism
//!    (kinematic LP, [`crate::mechanism`]). The first that passes is the limit state.
//!    When the least admissible state carries none (the non-associative gap), a wider
//!    pool of candidates at that state is enumerated again.
//!
//! Where the least admissible state is unbounded, η_s is an infimum, made exact from the
//! weightless directions of [`recession`].

mod bracket;
mod diagnosis;
mod enumerate;
pub mod filled;
pub mod recession;
pub mod solution;
mod vanishing;
mod vertical;

pub use solution::{Candidate, LeastLimitState, Outcome, Solution};
pub(crate) use vanishing::vanishing_thickness_state;
pub use vertical::{mu_ms_of, MU_MS_ROUNDING, MU_MS_ZERO};

use crate::admissibility::{Margin, WorkingSet};
use crate::arch::{check_mu, Arch, InputError, JointLayout};
use crate::contact::{Contact, ContactKind};
use crate::refine::Refined;
use crate::search::{candidates_at, RootGuess};
use crate::settings::Settings;
use crate::state::State;
use crate::statics::Reactions;
use bracket::bracket_eta_s;
use diagnosis::unresolved;
use enumerate::enumerate;
use recession::{continuum_threshold, threshold};
use std::ops::ControlFlow::{self, Break, Continue};

/// Solves for the least thickness η*(μ) of `arch` at friction `mu` (`f64::INFINITY`:
/// no sliding). Bad input is an `Err`; what the solver found (a limit state, no
/// equilibrium, or an unresolved bracket) is inside the `Solution`.
pub fn solve(arch: &Arch, mu: f64, settings: &Settings) -> Result<Solution, InputError> {
    solve_near(arch, mu, continuum_guess(arch, mu, settings), settings)
}

/// [`solve_near`] from a neighbouring solution's least limit state `prior` (the previous
/// μ of a curve): where `prior` carries its limit state at its η_s, the bracket of η_s
/// starts with Newton on its pattern at `mu` (one margin LP when the pattern still holds,
/// instead of a bracket narrowed from `guess`); otherwise, or when the pattern does not
/// hold here, as [`solve_near`] from `guess`. The same algorithm after the bracket.
pub fn solve_continued(
    arch: &Arch,
    mu: f64,
    guess: RootGuess,
    prior: &LeastLimitState,
    settings: &Settings,
) -> Result<Solution, InputError> {
    let usable = prior.eta == prior.eta_static && prior.attained && arch.fill().is_none();
    if !usable {
        return solve_near(arch, mu, Some(guess), settings);
    }
    solve_from(arch, mu, bracket::Start::Continued(guess, prior), settings)
}

/// The questions whose method still assumes that the sliding rows do not depend on η (the
/// friction limit μ_ms and the vertical branch of the limit curve) refuse an arch with fill
/// by name: with fill every row depends on η, and μ_ms becomes a curve; the limit curve is
/// then traced in η ([`crate::limit_curve::filled`]).
pub(crate) fn refuse_fill(arch: &Arch, what: &str) -> Result<(), InputError> {
    match arch.fill() {
        Some(_) => Err(InputError::Inconsistent {
            arg: "--fill-weight",
            reason: format!(
                "{what} of an arch with fill is not traced in mu (with fill the friction \
                 limit depends on eta): it is traced in eta, as mu_min(eta) \
                 (limit_curve::filled::trace, `modes` with the fill flags)"
            ),
        }),
        None => Ok(()),
    }
}

/// The width of a bracket guessed from the continuous arch (relative) is at least this
/// (the resolution of η_s) ...
const GUESS_REL_MIN: f64 = 1e-12;

/// ... and at most this (a guess any wider brackets little).
const GUESS_REL_MAX: f64 = 1e-2;

/// From this many joints on, a discrete arch brackets η_s from the η_s of the continuous
/// arch between its springings: each margin LP of the discrete arch costs a pass over
/// every joint, and the continuous one costs about as much as a few hundred joints.
const GUESS_FROM_CONTINUUM_JOINTS: usize = 1000;

/// Where η_s of a discrete arch with many joints is expected: at the continuous arch's,
/// within the square of the widest spacing of its joints (fine joints change η_s by about
/// a tenth of that: 10⁻⁶ at 1 000 equal voussoirs of a semicircle, 5·10⁻⁹ at 10 000; the
/// bracket widens where it misses). `None` for fewer joints, or when the continuous arch
/// has no least thickness.
fn continuum_guess(arch: &Arch, mu: f64, settings: &Settings) -> Option<RootGuess> {
    let JointLayout::Discrete(joints) = arch.layout() else {
        return None;
    };
    if joints.len() < GUESS_FROM_CONTINUUM_JOINTS || arch.fill().is_some() {
        return None;
    }
    let continuum = Arch::new(arch.beta_right(), arch.beta_left(), arch.weight()).ok()?;
    let eta = match solve_near(&continuum, mu, None, settings).ok()?.outcome {
        Outcome::Limit(ls) => ls.eta_static,
        Outcome::Unresolved {
            least_static: Some((eta, _)),
            ..
        } => eta,
        _ => return None,
    };
    let gap = joints.windows(2).map(|w| w[1] - w[0]).fold(0.0, f64::max);
    Some(RootGuess {
        eta,
        rel: (gap * gap).clamp(GUESS_REL_MIN, GUESS_REL_MAX),
    })
}

/// [`solve`] with the bracket of η_s started from a guess (a neighbouring solution, as
/// along a limit curve): the same algorithm and answer, with fewer margin LPs when the
/// guess is good. A guess that brackets nothing within a few widenings costs those LPs and
/// the bracket starts from the whole range, as without one.
pub fn solve_near(
    arch: &Arch,
    mu: f64,
    guess: Option<RootGuess>,
    settings: &Settings,
) -> Result<Solution, InputError> {
    solve_from(arch, mu, bracket::Start::Near(guess), settings)
}

/// The solve with the bracket of η_s started from `start` (the input checks first).
fn solve_from(
    arch: &Arch,
    mu: f64,
    start: bracket::Start,
    settings: &Settings,
) -> Result<Solution, InputError> {
    let mu = check_mu(mu)?;
    settings.validate()?;
    let mut candidates = Vec::new();
    if arch.fill().is_some() {
        let (outcome, scan) = solve_filled(arch, mu, settings, &mut candidates);
        return Ok(Solution {
            arch: arch.clone(),
            mu,
            outcome,
            candidates,
            vertical: None,
            scan,
        });
    }
    // a neighbour's limit state at μ_p ≥ μ_ms with μ ≥ μ_p (1 + resolution) is clearly
    // above the band: no friction-only LP needed
    let band = match &start {
        bracket::Start::Continued(_, p) if p.mu * (1.0 + settings.mu_ms_resolution) <= mu => {
            vertical::Band::Above
        }
        _ => vertical::band(arch, mu, settings),
    };
    let (outcome, vertical) = match band {
        vertical::Band::Near(fl) => {
            let above = |mu1: f64| solve_at(arch, mu1, settings, &mut Vec::new());
            let outcome = vertical::near_mu_ms(arch, mu, &fl, settings, &mut candidates, above);
            let sliding = vertical::vertical_branch(mu, &fl, &outcome);
            (outcome, sliding)
        }
        vertical::Band::Above => (
            exact_infimum(
                arch,
                mu,
                solve_inner(arch, mu, settings, &mut candidates, start),
                settings,
            ),
            None,
        ),
    };
    Ok(Solution {
        arch: arch.clone(),
        mu,
        outcome,
        candidates,
        vertical,
        scan: None,
    })
}

/// The least thickness of an arch with fill ([`filled`]): the scan of the whole range,
/// then the solve from the bracket of its lowest admissible node.
fn solve_filled(
    arch: &Arch,
    mu: f64,
    settings: &Settings,
    log: &mut Vec<Candidate>,
) -> (Outcome, Option<filled::ThicknessScan>) {
    let modes = ContactKind::active_at(mu);
    let mut ws = WorkingSet::initial(arch);
    let (scan, start) = match filled::scan(arch, mu, modes, &mut ws, settings) {
        Ok(s) => s,
        Err(e) => {
            return (
                bracket::lp_failed("while scanning the thickness range", e),
                None,
            )
        }
    };
    let outcome = match (scan.lowest(), start) {
        (_, Some(b)) => exact_infimum(
            arch,
            mu,
            solve_inner(arch, mu, settings, log, bracket::Start::Scanned(b)),
            settings,
        ),
        (None, _) => Outcome::NoEquilibrium {
            mu_ms: None,
            reason: format!(
                "with fill, no state is admissible at any of the {} thicknesses scanned from eta = {} to {} at mu = {} (between them the margin is taken as monotone, and its maximum near the best one is negative)",
                scan.etas.len(),
                filled::SCAN_FLOOR,
                crate::arch::ETA_TOP,
                crate::arch::fmt_value(mu)
            ),
        },
        (Some(_), None) => unresolved(
            0.0,
            filled::SCAN_FLOOR,
            format!(
                "with fill, a state is admissible at eta = {}, the thinnest ring scanned: whether the arch stands at every thickness is not decided",
                filled::SCAN_FLOOR
            ),
        ),
    };
    (outcome, Some(scan))
}

/// The outcome at a μ clearly above μ_ms, from the whole range (no guess).
fn solve_at(arch: &Arch, mu: f64, settings: &Settings, log: &mut Vec<Candidate>) -> Outcome {
    exact_infimum(
        arch,
        mu,
        solve_inner(arch, mu, settings, log, bracket::Start::Near(None)),
        settings,
    )
}

/// An arch whose least admissible state is unbounded (its reactions beyond
/// `settings.unbounded_reactions`): η_s is then an infimum, the least η with a weightless
/// admissible direction ([`recession`]), and the Newton state found near it only
/// approximates that η (its equations hold relative to reactions of 1e9 or more). η_s
/// becomes the exact root of the direction's three contacts (a discrete arch: a cubic; a
/// continuous one: Newton on the weightless system, free contacts tangent) when it verifies
/// within `settings.infimum_rel` of the approximation; anything found at η_s itself moves
/// with it (no finite state carries it: the search reports no limit state there).
fn exact_infimum(arch: &Arch, mu: f64, outcome: Outcome, settings: &Settings) -> Outcome {
    let exact = |eta: f64, x: &Reactions| {
        let hi = (eta * (1.0 + settings.infimum_rel)).min(crate::arch::ETA_TOP);
        let r = match arch.layout() {
            JointLayout::Discrete(_) => {
                threshold(arch, mu, eta * (1.0 - settings.infimum_rel), hi, settings)
            }
            JointLayout::Continuous => continuum_threshold(arch, mu, eta, x, settings),
        };
        r.filter(|r| r.exact && r.eta >= eta * (1.0 - settings.infimum_rel) && r.eta <= hi)
            .map(|r| r.eta)
    };
    // η_rec above the state found (beyond the rounding of its η): that admissible state is a
    // finite one below every weightless direction, and η_s is attained there however large
    // its reactions; η_rec is kept only at or below it
    let at_or_below = |rec: f64, eta: f64| rec <= eta * (1.0 + settings.root_slack);
    match outcome {
        Outcome::Limit(mut ls) if !bounded(arch, &ls.x_static, settings) => {
            match exact(ls.eta_static, &ls.x_static) {
                Some(eta) if at_or_below(eta, ls.eta_static) => {
                    if ls.eta <= ls.eta_static * (1.0 + settings.root_slack) {
                        ls.eta = eta;
                    }
                    ls.eta_static = eta;
                    ls.attained = false;
                }
                Some(_) => {}
                None => ls.attained = false,
            }
            Outcome::Limit(ls)
        }
        Outcome::Unresolved {
            eta_lo,
            eta_hi,
            reason,
            least_static: Some((eta, x)),
        } if !bounded(arch, &x, settings) => {
            let eta = exact(eta, &x)
                .filter(|&rec| at_or_below(rec, eta))
                .unwrap_or(eta);
            Outcome::Unresolved {
                eta_lo: eta_lo.min(eta),
                eta_hi,
                reason,
                least_static: Some((eta, x)),
            }
        }
        other => other,
    }
}

/// Whether a least state is a bounded one: its reactions within
/// `settings.unbounded_reactions` × (1 + span) (the arch's weight). Beyond, η_s is taken
/// as an infimum approached as the reactions grow without bound.
pub(crate) fn bounded(arch: &Arch, x: &Reactions, settings: &Settings) -> bool {
    x.iter()
        .all(|v| v.abs() <= settings.unbounded_reactions * (1.0 + arch.span()))
}

/// The solve after the input checks: the bracket (step 1), the enumeration at its upper
/// end (steps 2–4), and, across a non-associative gap, the enumeration above the least
/// admissible state. Every pattern tried goes to `log`.
fn solve_inner(
    arch: &Arch,
    mu: f64,
    settings: &Settings,
    log: &mut Vec<Candidate>,
    start: bracket::Start,
) -> Outcome {
    let modes = ContactKind::active_at(mu);
    let mut ws = WorkingSet::initial(arch);
    let ((lo, hi), active) = match bracket_eta_s(arch, mu, modes, &mut ws, start, settings) {
        Continue(b) => b,
        Break(outcome) => return outcome,
    };
    let (eta_lo, eta_hi, m_hi) = (lo.0, hi.0, hi.2);
    if let Some(ls) =
        active.and_then(|a| at_top(arch, mu, &a, (eta_lo, eta_hi, m_hi.x), settings, log))
    {
        return Outcome::Limit(ls);
    }
    match at_bracket(arch, mu, modes, (eta_lo, eta_hi, m_hi), settings, log) {
        Continue(least) => across_gap(arch, mu, modes, least, (eta_lo, eta_hi), settings, log),
        Break(outcome) => outcome,
    }
}

/// The limit state at the upper end of a continued bracket, where the state there is the
/// refined one of a neighbour's pattern and `active` its active contacts: the enumeration's
/// whole-set step on them alone (Newton from that state, admissibility, a mechanism). `None`
/// when they carry no mechanism: the caller then enumerates the candidates as usual.
fn at_top(
    arch: &Arch,
    mu: f64,
    active: &[Contact],
    (eta_lo, eta_hi, x): (f64, f64, Reactions),
    settings: &Settings,
    log: &mut Vec<Candidate>,
) -> Option<LeastLimitState> {
    let top_slack = eta_hi * (1.0 + settings.root_slack);
    let found = enumerate(
        arch,
        mu,
        active,
        &[],
        x,
        eta_hi,
        (eta_lo, eta_hi),
        top_slack,
        settings,
        log,
    );
    found.limit.filter(|ls| ls.eta <= top_slack)
}

/// Steps 2–4 at the upper end of the bracket [η_lo, η_hi] (the margin LP's state `m_hi`
/// there): candidate contacts, then the enumeration of patterns of 2 to 5 of them and the
/// whole set. `Break` with the limit state when it is the least admissible one (or with
/// why the bracket is unresolved); `Continue` with the least admissible state when that
/// state carries no mechanism (the non-associative gap).
fn at_bracket(
    arch: &Arch,
    mu: f64,
    modes: &[ContactKind],
    (eta_lo, eta_hi, m_hi): (f64, f64, Margin),
    settings: &Settings,
    log: &mut Vec<Candidate>,
) -> ControlFlow<Outcome, Refined> {
    // Candidate contacts at the upper end of the bracket, then the enumeration.
    let top = State {
        arch,
        eta: eta_hi,
        mu,
        x: m_hi.x,
    };
    let cand = candidates_at(&top, Some(m_hi.margin.max(0.0)), modes, settings);
    let sizes: Vec<usize> = (2..=5).collect();
    let first = enumerate(
        arch,
        mu,
        &cand,
        &sizes,
        m_hi.x,
        eta_hi,
        (eta_lo, eta_hi),
        eta_hi * (1.0 + settings.root_slack),
        settings,
        log,
    );
    let top_slack = eta_hi * (1.0 + settings.root_slack);
    if let Some(ls) = first.limit {
        // η_hi carries a state verified admissible by exact evaluation over the whole
        // arch, so η* ≤ η_hi: a verified pattern above it is not the least. (The lower
        // end comes from the LP's infeasibility decision, accurate only to HiGHS's
        // tolerance, and a verified state below it is simply better.) When the least
        // admissible state was refined inside the bracket, it carries no mechanism: the
        // non-associative gap below, with that state as η_s.
        if ls.eta <= top_slack {
            return Break(Outcome::Limit(ls));
        }
        if !first
            .least_static
            .as_ref()
            .is_some_and(|st| st.t <= top_slack)
        {
            return Break(unresolved(
                eta_lo,
                eta_hi,
                format!("the least verified pattern gives eta = {} above an admissible state at {eta_hi}", ls.eta),
            ));
        }
    }
    match first.least_static {
        Some(st) => Continue(st),
        None => Break(unresolved(
            eta_lo,
            eta_hi,
            "no enumerated pattern gave a verified limit state".into(),
        )),
    }
}

/// Across a non-associative gap: above the least admissible state `st` (refined inside the
/// bracket [η_lo, η_hi], with no mechanism), the enumeration again on a wider pool of
/// candidates at that state.
fn across_gap(
    arch: &Arch,
    mu: f64,
    modes: &[ContactKind],
    st: Refined,
    (eta_lo, eta_hi): (f64, f64),
    settings: &Settings,
    log: &mut Vec<Candidate>,
) -> Outcome {
    // Non-associative gap: the least admissible state carries no mechanism without
    // dilatancy. A limit state then needs a larger η and another active set: widen the
    // pool to the best local maxima at that state, whatever their slack, and enumerate
    // determined patterns (four or five contacts).
    let least = State {
        arch,
        eta: st.t,
        mu,
        x: st.x,
    };
    let pool = candidates_at(&least, None, modes, settings);
    let second = enumerate(
        arch,
        mu,
        &pool,
        &[4, 5],
        st.x,
        st.t,
        (eta_lo, eta_hi),
        0.0,
        settings,
        log,
    );
    match second.limit {
        Some(mut ls) if ls.eta >= st.t * (1.0 - settings.same_root) => {
            ls.eta_static = st.t;
            ls.x_static = st.x;
            ls.eta_rounding = ls.eta_rounding.max(crate::statics::eta_rounding(
                arch,
                st.t,
                &st.x,
                &st.contacts,
            ));
            Outcome::Limit(ls)
        }
        _ => Outcome::Unresolved {
            eta_lo: st.t,
            eta_hi: f64::INFINITY,
            reason: format!(
                "the least admissible state (eta = {}) has no non-associative mechanism, and no enumerated pattern gave a limit state above it",
                st.t
            ),
            least_static: Some((st.t, st.x)),
        },
    }
}
