//! The least thickness η*(μ) of an arch at one friction coefficient (formulation §5).
//!
//! 1. **Bracket.** The continuum margin s(η) of the best state (constraint-generation
//!    LP, [`crate::admissibility`]) is increasing in η; η* is its root, bracketed by
//!    Illinois regula falsi safeguarded by (geometric) bisection.
//! 2. **Candidates.** At the upper end of the bracket, the local maxima of every φ whose
//!    normalised slack is within `candidate_rel` of the LP margin are the candidate
//!    active contacts.
//! 3. **Enumeration.** Every subset of 4 and 5 candidates, and the whole candidate set,
//!    is a pattern; Newton ([`crate::refine`]) solves its system exactly.
//! 4. **Verification.** In increasing η, a refined state must be statically admissible
//!    over the whole arch (scan, `adm_tol`) and its active set must carry a mechanism
//!    (kinematic LP, [`crate::mechanism`]). The first that passes is the limit state.

mod diagnosis;
mod enumerate;
pub mod recession;
pub mod solution;

pub use solution::{Candidate, LimitState, Outcome, Solution};

use crate::admissibility::{Margin, WorkingSet};
use crate::arch::{check_mu, Arch, InputError, JointLayout};
use crate::contact::ContactKind;
use crate::lp::{self, LpOutcome};
use crate::refine::solve_pattern;
use crate::search::{bracket_near, bracket_root, candidates_at, margin_at, Bracket, RootGuess};
use crate::settings::Settings;
use crate::state::State;
use crate::statics::{actions, reaction_scale, Affine, Reactions};
use diagnosis::{no_equilibrium, unresolved};
use enumerate::enumerate;
use recession::{continuum_threshold, margin, threshold};

/// Solves for the least thickness η*(μ) of `arch` at friction `mu` (`f64::INFINITY`:
/// no sliding). Bad input is an `Err`; what the solver found (a limit state, no
/// equilibrium, or an unresolved bracket) is inside the `Solution`.
pub fn solve(arch: &Arch, mu: f64, settings: &Settings) -> Result<Solution, InputError> {
    solve_near(arch, mu, continuum_guess(arch, mu, settings), settings)
}

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
    if joints.len() < GUESS_FROM_CONTINUUM_JOINTS {
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
        rel: (gap * gap).clamp(1e-12, 1e-2),
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
    let mu = check_mu(mu)?;
    settings.validate()?;
    let mut candidates = Vec::new();
    let outcome = exact_infimum(
        arch,
        mu,
        solve_inner(arch, mu, settings, &mut candidates, guess),
        settings,
    );
    Ok(Solution {
        arch: arch.clone(),
        mu,
        outcome,
        candidates,
    })
}

/// An arch whose least admissible state is unbounded (its reactions beyond
/// `settings.unbounded_reactions`): η_s is then an infimum, the least η with a weightless
/// admissible direction ([`recession`]), and the Newton state found
/// near it only approximates that η (its equations hold relative to reactions of 1e9 or
/// more). η_s becomes the exact root of the direction's three contacts (a discrete arch:
/// a cubic; a continuous one: Newton on the weightless system, free contacts tangent) when
/// it verifies within 1e-6 (relative) of the approximation; anything found at η_s itself moves with it
/// (no finite state carries it: the search reports no limit state there).
fn exact_infimum(arch: &Arch, mu: f64, outcome: Outcome, settings: &Settings) -> Outcome {
    let exact = |eta: f64, x: &Reactions| {
        let hi = (eta * (1.0 + 1e-6)).min(crate::arch::ETA_TOP);
        let r = match arch.layout() {
            JointLayout::Discrete(_) => threshold(arch, mu, eta * (1.0 - 1e-6), hi, settings),
            JointLayout::Continuous => continuum_threshold(arch, mu, eta, x, settings),
        };
        r.filter(|r| r.exact && r.eta >= eta * (1.0 - 1e-6) && r.eta <= hi)
            .map(|r| r.eta)
    };
    match outcome {
        Outcome::Limit(mut ls) if !bounded(arch, &ls.x_static, settings) => {
            if let Some(eta) = exact(ls.eta_static, &ls.x_static) {
                if ls.eta <= ls.eta_static * (1.0 + settings.root_slack) {
                    ls.eta = eta;
                }
                ls.eta_static = eta;
            }
            Outcome::Limit(ls)
        }
        Outcome::Unresolved {
            eta_lo,
            eta_hi,
            reason,
            least_static: Some((eta, x)),
        } if !bounded(arch, &x, settings) => {
            let eta = exact(eta, &x).unwrap_or(eta);
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
    if r <= 1e-12 {
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
        + 2.0
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

/// Whether a least state is a bounded one: its reactions within
/// `settings.unbounded_reactions` × (1 + span) (the arch's weight). Beyond, η_s is taken
/// as an infimum approached as the reactions grow without bound.
pub(crate) fn bounded(arch: &Arch, x: &Reactions, settings: &Settings) -> bool {
    x.iter()
        .all(|v| v.abs() <= settings.unbounded_reactions * (1.0 + arch.span()))
}

/// Why [`Outcome::NoCollapse`].
const NO_COLLAPSE: &str = "a state without tension is admissible at vanishing thickness, so the arch stands at every eta > 0 (eta_s = 0); limit states above it can still exist (non-associative friction): the limit-state search lists them";

/// A state admissible as η → 0⁺, if there is one: φ(x, 0) ≤ 0 for every activation
/// function **and** N ≥ 0 at every joint. At η = 0 the hinge conditions |M| ≤ ηN/2 reduce
/// to M = 0 and no longer imply N ≥ 0 (at finite μ the friction conditions |T| ≤ μN still
/// do; at μ = ∞ nothing does): a two-voussoir arch at μ = ∞ always has M = 0 at its three
/// joints for one x, in tension or not, and only without tension does that x stand at
/// every η > 0. Such a state is admissible at every η > 0 (admissibility is monotone once
/// N ≥ 0). A discrete arch is checked at every joint (margin LP with the rows −N ≤ 0, then
/// every row evaluated at its state); a continuous one by the continuum margin LP at η = 0
/// and N ≥ 0 sampled over the arch at its state (M ≡ 0 on an interval is impossible, so
/// this is never met in practice). Tolerances are distances to the planes, relative to the
/// state's size, as the margin LP's own decision.
pub(crate) fn vanishing_thickness_state(
    arch: &Arch,
    mu: f64,
    settings: &Settings,
) -> Result<Option<Reactions>, String> {
    let modes = ContactKind::active_at(mu);
    let lp_err = |e: LpOutcome| match e {
        LpOutcome::Infeasible => "margin LP infeasible".to_string(),
        LpOutcome::Failed(m) => m,
    };
    // distances to the planes (rows normalised to unit gradient), as the margin LP's own
    // decision at η = 0 (the hinge slabs |M| ≤ ηN/2 have no width there, so a relative
    // test on φ alone would judge the LP's rounding)
    let distance = |r: &Affine, x: &Reactions| r.at(x) / r.grad_norm().max(f64::MIN_POSITIVE);
    match arch.layout() {
        JointLayout::Discrete(joints) => {
            let mut rows: Vec<Affine> = Vec::new();
            for &beta in joints {
                let a = actions(arch, 0.0, beta);
                rows.extend(modes.iter().map(|&k| a.activation(k, 0, 0.0, mu)));
                rows.push(Affine::combine(-1.0, &a.n[0], 0.0, &a.n[0]));
            }
            let (x, _) = lp::max_margin(&rows, arch.span(), settings).map_err(lp_err)?;
            // exact evaluation of every row at the LP's state
            let worst = rows
                .iter()
                .map(|r| distance(r, &x))
                .fold(f64::NEG_INFINITY, f64::max);
            Ok((worst <= settings.adm_tol * reaction_scale(&x)).then_some(x))
        }
        JointLayout::Continuous => {
            let mut ws = WorkingSet::initial(arch);
            let m = margin_at(arch, 0.0, mu, modes, &mut ws, settings)?;
            let tol = settings.adm_tol * reaction_scale(&m.x);
            if m.margin < -tol {
                return Ok(None);
            }
            let (a, b) = (arch.beta_right(), arch.beta_left());
            let tension = (0..=4096)
                .map(|i| {
                    let n = actions(arch, 0.0, a + (b - a) * i as f64 / 4096.0).n[0];
                    -distance(&n, &m.x)
                })
                .fold(f64::NEG_INFINITY, f64::max);
            Ok((tension <= tol).then_some(m.x))
        }
    }
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
) -> Result<(f64, Margin), String> {
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

/// A narrowed bracket of η_s from a prediction: Newton on the candidates at the upper end of
/// a coarse bracket (the whole set, as the solve's enumeration starts) gives an admissible
/// refined state, η_p; the margin at η_p (1 ∓ [`PREDICT_STEP`] `bracket_rel`) then brackets η_s
/// to a tenth of `bracket_rel` when the prediction is right. Each margin evaluated narrows the bracket
/// whatever its sign (the margin is increasing in η), so a wrong prediction costs two LPs
/// and the bracketing goes on from there.
fn predicted(
    arch: &Arch,
    mu: f64,
    modes: &[ContactKind],
    (mut lo, mut hi): Bracket<Margin>,
    eval: &mut impl FnMut(f64) -> Result<(f64, Margin), String>,
    settings: &Settings,
) -> Result<Bracket<Margin>, String> {
    let top = State {
        arch,
        eta: hi.0,
        mu,
        x: hi.2.x,
    };
    let cand = candidates_at(&top, Some(hi.2.margin.max(0.0)), modes, settings);
    // Newton on the whole candidate set, and its state admissible over the arch (the least
    // admissible state the enumeration's first group would give; no mechanism needed here)
    let Ok(r) = solve_pattern(&top, &cand, settings) else {
        return Ok((lo, hi));
    };
    let refined = State {
        arch,
        eta: r.t,
        mu,
        x: r.x,
    };
    if refined.admissible_verdict(modes, settings).is_err() {
        return Ok((lo, hi));
    }
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

fn solve_inner(
    arch: &Arch,
    mu: f64,
    settings: &Settings,
    log: &mut Vec<Candidate>,
    guess: Option<RootGuess>,
) -> Outcome {
    let modes = ContactKind::active_at(mu);
    let mut ws = WorkingSet::initial(arch);
    let eta_max = crate::arch::ETA_TOP;
    // an LP that fails (not infeasible: a numerical failure of the back end) leaves the
    // question undecided; its text is kept only as the detail of that reason
    let lp_failed = |at: &str, e: String| {
        unresolved(
            0.0,
            2.0,
            format!("the static margin LP could not be solved {at} (LP back end: {e}); no decision at this mu"),
        )
    };
    // A bracket found from the guess has a negative margin at a positive η and an
    // admissible state below the thickness limit: neither "no collapse" nor "no
    // equilibrium". Without a guess (or when it brackets nothing) the whole range.
    let near = guess.and_then(|g| {
        bracket_near(g, eta_max, |eta| {
            margin_or_far(arch, eta, mu, modes, &mut ws, settings)
        })
        .ok()
        .flatten()
    });
    let from_whole_range = near.is_none();
    let start = match near {
        Some(ends) => ends,
        None => {
            let top = match margin_at(arch, eta_max, mu, modes, &mut ws, settings) {
                Ok(m) => m,
                Err(e) => return lp_failed("at the thickness limit", e),
            };
            if top.margin < 0.0 {
                return no_equilibrium(arch, mu, settings);
            }
            let bottom = match margin_at(arch, 0.0, mu, modes, &mut ws, settings) {
                Ok(m) => m,
                Err(e) => return lp_failed("at vanishing thickness", e),
            };
            if bottom.margin >= -settings.adm_tol * reaction_scale(&bottom.x) {
                match vanishing_thickness_state(arch, mu, settings) {
                    Ok(Some(_)) => {
                        return Outcome::NoCollapse {
                            reason: NO_COLLAPSE.into(),
                        }
                    }
                    Ok(None) => {}
                    Err(e) => return lp_failed("at vanishing thickness", e),
                }
            }
            (
                (0.0, bottom.margin.min(-f64::MIN_POSITIVE)),
                (eta_max, top.margin, top),
            )
        }
    };
    let mut eval = |eta: f64| margin_or_far(arch, eta, mu, modes, &mut ws, settings);
    let mut bracket = Ok(start);
    if from_whole_range {
        for level in PREDICT_AT.into_iter().filter(|&l| l > settings.bracket_rel) {
            bracket = bracket.and_then(|(lo, hi)| {
                if hi.0 - lo.0 <= settings.bracket_rel * hi.0 {
                    return Ok((lo, hi)); // an earlier prediction closed it
                }
                let (lo, hi) = bracket_root(lo, hi, level, 200, &mut eval)?;
                predicted(arch, mu, modes, (lo, hi), &mut eval, settings)
            });
        }
    }
    let bracket =
        bracket.and_then(|(lo, hi)| bracket_root(lo, hi, settings.bracket_rel, 200, &mut eval));
    let (lo, hi) = match bracket {
        Ok(b) => b,
        Err(e) => return lp_failed("while bracketing eta_s", e),
    };
    let (eta_lo, eta_hi, m_hi) = (lo.0, hi.0, hi.2);

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
            return Outcome::Limit(ls);
        }
        if !first
            .least_static
            .as_ref()
            .is_some_and(|st| st.t <= top_slack)
        {
            return unresolved(
                eta_lo,
                eta_hi,
                format!("the least verified pattern gives eta = {} above an admissible state at {eta_hi}", ls.eta),
            );
        }
    }
    let Some(st) = first.least_static else {
        return unresolved(
            eta_lo,
            eta_hi,
            "no enumerated pattern gave a verified limit state".into(),
        );
    };
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
