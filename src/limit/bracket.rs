//! Step 1 of the solve: a bracket [η_lo, η_hi] of η_s, the root of the continuum margin
//! s(η) (increasing in η), with the margin LP's state at its upper end. From a guess when
//! one is given (or from a neighbouring solution's pattern, [`continued`]), else from the
//! whole range (where the answer may instead be "no equilibrium" or "no collapse");
//! narrowed by [`bracket_root`], with two predictions of η_s on the way.

use super::diagnosis::{no_equilibrium, unresolved};
use super::recession::{margin, MARGIN_TOL};
use super::solution::{LeastLimitState, Outcome};
use super::vanishing::{vanishing_thickness_state, NO_COLLAPSE};
use crate::admissibility::{Margin, WorkingSet};
use crate::arch::{Arch, JointLayout, ETA_TOP};
use crate::contact::{Contact, ContactKind};
use crate::refine::{solve_pattern, Refined};
use crate::scan::Verdict;
use crate::search::{bracket_near, bracket_root, candidates_at, margin_at, Bracket, RootGuess};
use crate::settings::Settings;
use crate::state::State;
use crate::statics::{actions, reaction_scale, Affine};
use crate::undecided::Undecided;
use std::ops::ControlFlow::{self, Break, Continue};

/// Each narrowing of the bracket takes at most this many steps of regula falsi or
/// bisection (a safety net: the geometric bisection halves the bracket's logarithm).
const BRACKET_MAX_STEPS: usize = 200;

/// A far state is taken this many times farther along the weightless direction than the
/// distance at which the worst row turns negative, so that every row is clearly so.
const FAR_FACTOR: f64 = 2.0;

/// The bracket of η_s with the margin LP's state at its upper end (and, for a bracket
/// continued from a neighbour's pattern, the active contacts of the refined state at its
/// upper end: [`continued`]); `Break` with the outcome when the solve ends before a
/// bracket: no equilibrium (negative margin at the thickness limit), no collapse (a state
/// without tension at vanishing thickness), or an LP the back end could not solve.
pub(super) fn bracket_eta_s(
    arch: &Arch,
    mu: f64,
    modes: &[ContactKind],
    ws: &mut WorkingSet,
    start: Start,
    settings: &Settings,
) -> ControlFlow<Outcome, (Bracket<Margin>, Option<Vec<Contact>>)> {
    let mut active = None;
    // A bracket found from the guess has a negative margin at a positive η and an
    // admissible state below the thickness limit: neither "no collapse" nor "no
    // equilibrium". Without a guess (or when it brackets nothing) the whole range.
    let (near, from_whole_range) = match start {
        Start::Scanned(b) => (Some(b), true),
        Start::Continued(guess, prior) => {
            let mut eval = |eta: f64| margin_or_far(arch, eta, mu, modes, ws, settings);
            let near = match continued(arch, mu, modes, prior, &mut eval, settings) {
                Ok(Some((b, at_top))) => {
                    active = Some(at_top);
                    Some(b)
                }
                _ => bracket_near(guess, ETA_TOP, eval).ok().flatten(),
            };
            let whole = near.is_none();
            (near, whole)
        }
        Start::Near(guess) => {
            let near = guess.and_then(|g| {
                bracket_near(g, ETA_TOP, |eta| {
                    margin_or_far(arch, eta, mu, modes, ws, settings)
                })
                .ok()
                .flatten()
            });
            let whole = near.is_none();
            (near, whole)
        }
    };
    let start = match near {
        Some(ends) => ends,
        None => whole_range(arch, mu, modes, ws, settings)?,
    };
    let mut eval = |eta: f64| margin_or_far(arch, eta, mu, modes, ws, settings);
    let mut bracket = Ok(start);
    if from_whole_range {
        for level in PREDICT_AT.into_iter().filter(|&l| l > settings.bracket_rel) {
            bracket = bracket.and_then(|(lo, hi)| {
                if hi.0 - lo.0 <= settings.bracket_rel * hi.0 {
                    return Ok((lo, hi)); // an earlier prediction closed it
                }
                let (lo, hi) = bracket_root(lo, hi, level, BRACKET_MAX_STEPS, &mut eval)?;
                predicted(arch, mu, modes, (lo, hi), &mut eval, settings)
            });
        }
    }
    let bracket = bracket.and_then(|(lo, hi)| {
        bracket_root(lo, hi, settings.bracket_rel, BRACKET_MAX_STEPS, &mut eval)
    });
    match bracket {
        Ok(b) => Continue((b, active)),
        Err(e) => Break(lp_failed("while bracketing eta_s", e)),
    }
}

/// The bracket of the whole range [0, thickness limit], or the outcome that ends the
/// solve there (see [`bracket_eta_s`]).
fn whole_range(
    arch: &Arch,
    mu: f64,
    modes: &[ContactKind],
    ws: &mut WorkingSet,
    settings: &Settings,
) -> ControlFlow<Outcome, Bracket<Margin>> {
    let top = match margin_at(arch, ETA_TOP, mu, modes, ws, settings) {
        Ok(m) => m,
        Err(e) => return Break(lp_failed("at the thickness limit", e)),
    };
    if top.margin < 0.0 {
        return Break(no_equilibrium(arch, mu, settings));
    }
    let bottom = match margin_at(arch, 0.0, mu, modes, ws, settings) {
        Ok(m) => m,
        Err(e) => return Break(lp_failed("at vanishing thickness", e)),
    };
    if bottom.margin >= -settings.adm_tol * reaction_scale(&bottom.x) {
        match vanishing_thickness_state(arch, mu, settings) {
            Ok(Some(_)) => {
                return Break(Outcome::NoCollapse {
                    reason: NO_COLLAPSE.into(),
                })
            }
            Ok(None) => {}
            Err(e) => return Break(lp_failed("at vanishing thickness", e)),
        }
    }
    Continue((
        (0.0, bottom.margin.min(-f64::MIN_POSITIVE)),
        (ETA_TOP, top.margin, top),
    ))
}

/// Where the bracket of η_s starts.
pub(super) enum Start<'a> {
    /// Near a guess (a neighbouring solution), or the whole range without one.
    Near(Option<RootGuess>),
    /// From a neighbouring solution's least state ([`continued`]), else near the guess.
    Continued(RootGuess, &'a LeastLimitState),
    /// The bracket of a scan of the whole range (an arch with fill, [`super::filled`]):
    /// narrowed as a bracket of the whole range is.
    Scanned(Bracket<Margin>),
}

/// An LP that fails (not infeasible: a numerical failure of the back end) leaves the
/// question undecided; its text is kept only as the detail of that reason.
pub(super) fn lp_failed(at: &str, e: Undecided) -> Outcome {
    unresolved(
        0.0,
        2.0,
        format!("the static margin LP could not be solved {at} (LP back end: {e}); no decision at this mu"),
    )
}

/// An admissible state of a discrete arch at η found without the margin LP, where a
/// weightless admissible direction d exists with room (the cone's margin r > 0,
/// [`recession::margin`]): far enough along d every activation
/// function is negative, whatever the weight (φ_i(t d) = c_i + t g_i·d ≤ c_i − t r |g_i|).
/// Near an infimum the margin LP's best states are that far out, and the LP back end can
/// fail there ("Unbounded" even with the reactions boxed); the bracket of η_s only needs
/// to know that P(η) is not empty. `None` for a continuous arch or when r ≤ 0.
fn far_state(arch: &Arch, eta: f64, mu: f64, settings: &Settings) -> Option<Margin> {
    let JointLayout::Discrete(joints) = arch.layout() else {
        return None;
    };
    let (r, d) = margin(arch, mu, eta, settings)?;
    if r <= MARGIN_TOL {
        return None;
    }
    let rows: Vec<Affine> = joints
        .iter()
        .flat_map(|&b| {
            let a = actions(arch, eta, b);
            ContactKind::active_at(mu)
                .iter()
                .map(move |&k| a.activation(k, 0, eta, mu))
        })
        .collect();
    let t = 1.0
        + FAR_FACTOR
            * rows
                .iter()
                .map(|row| row.c.max(0.0) / (r * row.grad_norm()))
                .fold(0.0, f64::max);
    let x = d.map(|v| t * v);
    let slack = rows
        .iter()
        .map(|row| -row.at(&x) / row.grad_norm())
        .fold(f64::INFINITY, f64::min);
    (slack >= 0.0).then_some(Margin {
        x,
        margin: slack,
        lp_margin: slack,
        rounds: 0,
    })
}

/// The continuum margin at η decided by the LP, or, where the LP back end fails near an
/// infimum, a far admissible state along a weightless direction ([`far_state`]).
fn margin_or_far(
    arch: &Arch,
    eta: f64,
    mu: f64,
    modes: &[ContactKind],
    ws: &mut WorkingSet,
    settings: &Settings,
) -> Result<(f64, Margin), Undecided> {
    match margin_at(arch, eta, mu, modes, ws, settings) {
        Ok(m) => Ok((m.margin, m)),
        // near an infimum the best states are huge and the LP back end can fail
        Err(e) => far_state(arch, eta, mu, settings)
            .map(|m| (m.margin, m))
            .ok_or(e),
    }
}

/// The bracket of η_s from the whole range is narrowed to each of these widths (relative)
/// in turn, and η_s predicted there from the LP's state ([`predicted`]): at 10 % the least
/// state's pattern is often the LP's already; a wrong first prediction gets a second
/// chance at 10⁻³ before the bisection goes on to `bracket_rel`.
const PREDICT_AT: [f64; 2] = [1e-1, 1e-3];

/// The prediction is tested this fraction of `bracket_rel` (relative) on either side: a
/// bracket 10 times narrower than the bisection's, still wide enough for the LP to decide
/// the margin's sign on ordinary arches (the margin changes by about η N/2 per unit of
/// relative η).
const PREDICT_STEP: f64 = 0.05;

/// Newton on `pattern` from `from` (η unknown), and the refined state's verdict when it
/// lies inside (0, thickness limit) and is admissible over the whole arch.
fn admissible_refined(
    from: &State,
    pattern: &[Contact],
    modes: &[ContactKind],
    settings: &Settings,
) -> Option<(Refined, Verdict)> {
    let r = solve_pattern(from, pattern, settings).ok()?;
    let refined = State {
        eta: r.t,
        x: r.x,
        ..*from
    };
    if !(r.t > 0.0 && r.t < ETA_TOP) {
        return None;
    }
    let verdict = refined.admissible_verdict(modes, settings).ok()?;
    Some((r, verdict))
}

/// A bracket of η_s with the active contacts of the state at its upper end.
type AtTop = (Bracket<Margin>, Vec<Contact>);

/// A bracket of η_s a twentieth of `bracket_rel` wide from a neighbouring solution's least
/// state `prior` (the previous μ of a curve, where that state carries the limit state):
/// Newton on its pattern at this μ, from its state, gives a state admissible over the arch
/// at η_p when the pattern still holds here, so η_s ≤ η_p; a negative margin at η_p (1 −
/// [`PREDICT_STEP`] `bracket_rel`) then brackets η_s. `None` when the pattern does not
/// hold (Newton fails, its state is not admissible, or the margin below is not negative):
/// the caller then brackets from its guess, having spent at most one LP. With the bracket,
/// the active contacts of the refined state (the scan's).
fn continued(
    arch: &Arch,
    mu: f64,
    modes: &[ContactKind],
    prior: &LeastLimitState,
    eval: &mut impl FnMut(f64) -> Result<(f64, Margin), Undecided>,
    settings: &Settings,
) -> Result<Option<AtTop>, Undecided> {
    let from = State {
        arch,
        eta: prior.eta_static,
        mu,
        x: prior.x_static,
    };
    let Some((r, verdict)) = admissible_refined(&from, &prior.pattern, modes, settings) else {
        return Ok(None);
    };
    // the upper end is η_p itself, its state the refined one (admissible over the arch by
    // the scan, as a limit state is verified); the lower end needs the margin LP
    let t_lo = r.t * (1.0 - PREDICT_STEP * settings.bracket_rel);
    let (f_lo, _) = eval(t_lo)?;
    let top = Margin {
        x: r.x,
        margin: 0.0,
        lp_margin: 0.0,
        rounds: 0,
    };
    Ok((f_lo < 0.0).then_some((((t_lo, f_lo), (r.t, 0.0, top)), verdict.active)))
}

/// A narrowed bracket of η_s from a prediction: Newton on the candidates at the upper end
/// of a coarse bracket (the whole set, as the solve's enumeration starts) gives an
/// admissible refined state, η_p; the margin at η_p (1 ∓ [`PREDICT_STEP`] `bracket_rel`)
/// then brackets η_s to a tenth of `bracket_rel` when the prediction is right. Each margin
/// evaluated narrows the bracket whatever its sign (the margin is increasing in η), so a
/// wrong prediction costs two LPs and the bracketing goes on from there.
fn predicted(
    arch: &Arch,
    mu: f64,
    modes: &[ContactKind],
    (mut lo, mut hi): Bracket<Margin>,
    eval: &mut impl FnMut(f64) -> Result<(f64, Margin), Undecided>,
    settings: &Settings,
) -> Result<Bracket<Margin>, Undecided> {
    let top = State {
        arch,
        eta: hi.0,
        mu,
        x: hi.2.x,
    };
    let cand = candidates_at(&top, Some(hi.2.margin.max(0.0)), modes, settings);
    // Newton on the whole candidate set, and its state admissible over the arch (the least
    // admissible state the enumeration's first group would give; no mechanism needed here)
    let Some((r, _)) = admissible_refined(&top, &cand, modes, settings) else {
        return Ok((lo, hi));
    };
    let eta_p = r.t;
    let k = PREDICT_STEP * settings.bracket_rel;
    for t in [eta_p * (1.0 + k), eta_p * (1.0 - k)] {
        if !(t > lo.0 && t < hi.0) {
            continue;
        }
        let (f, m) = eval(t)?;
        if f >= 0.0 {
            hi = (t, f, m);
        } else {
            lo = (t, f);
        }
    }
    Ok((lo, hi))
}
