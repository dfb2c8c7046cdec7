//! The limit states of a continuous arch from two discretisations, for any question (the
//! thickness η, a load multiplier λ): each discretisation's limit states are carried over
//! to the continuum (adjacent contacts merged into tangencies, Newton, verified over the
//! whole arch), and the list stands when the discretisations of J and 2J pieces give the
//! same set.

use super::sweep::LimitState;
use crate::settings::Settings;
use crate::undecided::Undecided;

/// What one discretisation gave: its limit states carried over to the continuum, in the
/// order found (repeats allowed), and the events of its search (`None`: it ran none).
pub(crate) struct Carried {
    pub(crate) states: Vec<LimitState>,
    pub(crate) events: Option<usize>,
}

/// Runs `carry` on `settings.sweep_pieces` and twice as many pieces, removes repeats from
/// each list (`same`) and sorts it (`sort`); the finer list is the answer when both agree
/// (the events of the finer search, or the coarser's where the finer ran none). `Err` says
/// why not: a discretisation failed, or the lists differ.
pub(crate) fn agreed(
    settings: &Settings,
    mut carry: impl FnMut(usize) -> Result<Carried, Undecided>,
    same: impl Fn(&LimitState, &LimitState) -> bool,
    sort: impl Fn(&mut Vec<LimitState>),
) -> Result<(Vec<LimitState>, Option<usize>), Undecided> {
    let (coarse_pieces, fine_pieces) = (settings.sweep_pieces, 2 * settings.sweep_pieces);
    let mut lists: Vec<Vec<LimitState>> = Vec::new();
    let mut events = None;
    for pieces in [coarse_pieces, fine_pieces] {
        let c = carry(pieces)?;
        events = c.events.or(events);
        let mut found: Vec<LimitState> = Vec::new();
        for s in c.states {
            if !found.iter().any(|f| same(f, &s)) {
                found.push(s);
            }
        }
        sort(&mut found);
        lists.push(found);
    }
    let fine = lists.pop().expect("two discretisations");
    let coarse = lists.pop().expect("two discretisations");
    let agree =
        fine.len() == coarse.len() && fine.iter().all(|p| coarse.iter().any(|q| same(p, q)));
    if !agree {
        let ts = |l: &[LimitState]| l.iter().map(|s| s.t).collect::<Vec<f64>>();
        return Err(Undecided::Discretisation(format!(
            "the refined limit states of {coarse_pieces} and {fine_pieces} pieces differ: {:?} vs {:?}",
            ts(&coarse),
            ts(&fine)
        )));
    }
    Ok((fine, events))
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
