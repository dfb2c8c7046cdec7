//! The limit states of a continuous arch from two discretisations, for any question (the
//! thickness η, a load multiplier λ): each discretisation's limit states are carried over
//! to the continuum (adjacent contacts merged into tangencies, Newton, verified over the
//! whole arch), and the list stands when the discretisations of J and 2J pieces give the
//! same set (where they differ, 2J and 4J, and so on up to a limit).

use super::sweep::LimitState;
use crate::settings::Settings;
use crate::undecided::Undecided;

/// What one discretisation gave: its limit states carried over to the continuum, in the
/// order found (repeats allowed), the events of its search (`None`: it ran none), and for
/// [`Part::Shifted`] whether a shifted search was narrowed or failed ([`shifted`]).
pub(crate) struct Carried {
    pub(crate) states: Vec<LimitState>,
    pub(crate) events: Option<usize>,
    pub(crate) narrowed: bool,
}

/// A continuous arch's search that did not settle: why, and the limit states its
/// discretisations found (each carried over to the continuum, refined and verified there,
/// so each is a limit state; the list may miss others).
#[derive(Debug, Clone)]
pub struct Unsettled {
    /// Why the list is not complete.
    pub why: Undecided,
    /// The limit states found all the same, ascending.
    pub found: Vec<LimitState>,
}

impl From<Undecided> for Unsettled {
    fn from(why: Undecided) -> Unsettled {
        Unsettled {
            why,
            found: Vec::new(),
        }
    }
}

/// Which searches of a discretisation `carry` runs: the one at μ itself, or the ones at
/// the shifted friction coefficients ([`shifted`]).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) enum Part {
    AtMu,
    Shifted,
}

/// Runs `carry` on `settings.sweep_pieces` pieces and on twice as many, removes repeats
/// from each list (`same`) and sorts it (`sort`); the finer list is the answer when both
/// agree. Where they differ, the pieces are doubled again (at most
/// `settings.sweep_doublings` doublings in all) until two consecutive lists agree and
/// hold every state any list held (each carried state is a limit state of the continuum,
/// so a list without one of them is incomplete, whatever its neighbour says).
///
/// The coarsest discretisation is searched at μ and at the shifted friction coefficients
/// ([`Part`]); a finer one at μ, and at the shifted ones where its list without them would
/// not settle, or where the last shifted searches were narrowed or failed (near μ_ms). A
/// branch that the discretisations miss at μ near its end is found by the coarsest one's
/// shifted searches (they reach furthest), and a finer one that misses it then searches
/// its own.
///
/// Returns the answer, the events of the finer search (or of the coarser where the finer
/// ran none) and the finer discretisation's pieces. `Err` says why not (a discretisation
/// failed, or no two consecutive lists agree on every state found) with every state found.
pub(crate) fn agreed(
    settings: &Settings,
    mut carry: impl FnMut(usize, Part) -> Result<Carried, Undecided>,
    same: impl Fn(&LimitState, &LimitState) -> bool,
    sort: impl Fn(&mut Vec<LimitState>),
) -> Result<(Vec<LimitState>, Option<usize>, usize), Unsettled> {
    let holds = |l: &[LimitState], p: &LimitState| l.iter().any(|q| same(p, q));
    // adds `part` of the `pieces`-piece discretisation's states to `found` (no repeats);
    // its events and whether a shifted search was narrowed or failed
    let mut add = |pieces: usize, part: Part, found: &mut Vec<LimitState>| {
        let c = carry(pieces, part)?;
        for s in c.states {
            if !holds(found, &s) {
                found.push(s);
            }
        }
        sort(found);
        Ok::<_, Undecided>((c.events, c.narrowed))
    };
    let ts = |l: &[LimitState]| l.iter().map(|s| s.t).collect::<Vec<f64>>();
    let mut pieces = settings.sweep_pieces;
    let mut coarse = Vec::new();
    let (mut events, _) = add(pieces, Part::AtMu, &mut coarse)?;
    // whether the last shifted searches were narrowed or failed
    let (_, mut narrowed) = add(pieces, Part::Shifted, &mut coarse)?;
    let mut seen = coarse.clone();
    // each discretisation's pieces and the η (or λ) of its states, for the message
    let mut tried = vec![(pieces, ts(&coarse))];
    let unsettled = |tried: &[(usize, Vec<f64>)]| {
        let (mut ps, ls): (Vec<String>, Vec<String>) = tried
            .iter()
            .map(|(p, l)| (p.to_string(), format!("{l:?}")))
            .unzip();
        let last = ps.pop().unwrap_or_default();
        format!(
            "the refined limit states of {} and {last} pieces do not settle: {}",
            ps.join(", "),
            ls.join(" vs ")
        )
    };
    let settles = |fine: &[LimitState], coarse: &[LimitState], seen: &[LimitState]| {
        fine.len() == coarse.len()
            && fine.iter().all(|p| holds(coarse, p))
            && seen.iter().all(|p| holds(fine, p))
    };
    for _ in 0..settings.sweep_doublings {
        let mut fine = Vec::new();
        let mut searched = add(2 * pieces, Part::AtMu, &mut fine).map(|r| r.0);
        if searched.is_ok() && (narrowed || !settles(&fine, &coarse, &seen)) {
            match add(2 * pieces, Part::Shifted, &mut fine) {
                Ok((_, n)) => narrowed = n,
                Err(e) => searched = Err(e),
            }
        }
        let fine_events = match searched {
            Ok(e) => e,
            Err(e) if tried.len() == 1 => return Err(e.into()),
            Err(e) => {
                sort(&mut seen);
                return Err(Unsettled {
                    why: e.map_text(|e| format!("{}; then {e}", unsettled(&tried))),
                    found: seen,
                });
            }
        };
        events = fine_events.or(events);
        pieces *= 2;
        tried.push((pieces, ts(&fine)));
        for s in &fine {
            if !holds(&seen, s) {
                seen.push(s.clone());
            }
        }
        if settles(&fine, &coarse, &seen) {
            return Ok((fine, events, pieces));
        }
        coarse = fine;
    }
    sort(&mut seen);
    Err(Unsettled {
        why: Undecided::Discretisation(unsettled(&tried)),
        found: seen,
    })
}

/// The results of `search` at the friction coefficients a `pieces`-piece discretisation is
/// searched at besides `mu` (`Settings::carry_shift`): μ (1 − d) and μ (1 + d),
/// d = `carry_shift` / pieces², the lower d quartered, at most twice, where the search
/// fails there (just above μ_ms the discretisation has no equilibrium; any failure counts)
/// or where μ (1 − d) would not be positive. A search that fails adds nothing. Returns the
/// results and whether a search was narrowed or failed.
pub(crate) fn shifted<T, E>(
    mu: f64,
    pieces: usize,
    settings: &Settings,
    mut search: impl FnMut(f64) -> Result<T, E>,
) -> (Vec<T>, bool) {
    let shift = settings.carry_shift / (pieces * pieces) as f64;
    let mut out = Vec::new();
    if shift <= 0.0 || !mu.is_finite() {
        return (out, false);
    }
    let mut narrowed = false;
    for (sign, tries) in [(-1.0, 3), (1.0, 1)] {
        let mut d = shift;
        let mut found = false;
        for k in 0..tries {
            let m = mu * (1.0 + sign * d);
            if m > 0.0 {
                if let Ok(r) = search(m) {
                    out.push(r);
                    found = true;
                    narrowed |= k > 0;
                    break;
                }
            }
            d /= 4.0;
        }
        narrowed |= !found;
    }
    (out, narrowed)
}

/// Two carried states are the same: their parameters within `t_tol` and the same contacts
/// (kinds and sides, angles to `settings.same_state_angle`). Mirror images share t but not
/// contacts.
pub(crate) fn same_state(p: &LimitState, q: &LimitState, t_tol: f64, settings: &Settings) -> bool {
    (p.t - q.t).abs() <= t_tol
        && p.pattern.len() == q.pattern.len()
        && p.sides == q.sides
        && p.pattern
            .iter()
            .zip(&q.pattern)
            .all(|(a, b)| a.kind == b.kind && (a.beta - b.beta).abs() <= settings.same_state_angle)
}
