//! The limit states of a continuous arch from two discretisations, for any question (the
//! thickness η, a load multiplier λ): each discretisation's limit states are carried over
//! to the continuum (adjacent contacts merged into tangencies, Newton, verified over the
//! whole arch), and the list stands when the discretisations of J and 2J pieces give the
//! same set.

use crate::contact::Contact;
use crate::load::Side;
use crate::settings::Settings;
use crate::undecided::Undecided;

/// What one discretisation gave: its limit states carried over to the continuum, in the
/// order found (repeats allowed), and the events of its search (`None`: it ran none).
pub(crate) struct Carried<S> {
    pub(crate) states: Vec<S>,
    pub(crate) events: Option<usize>,
}

/// How two carried states are told apart and ordered, and the parameter t (η or λ) each
/// is at.
pub(crate) struct Compare<Same, Sort, T> {
    pub(crate) same: Same,
    pub(crate) sort: Sort,
    pub(crate) t: T,
}

/// Runs `carry` on `settings.sweep_pieces` and twice as many pieces, removes repeats from
/// each list (`same`) and sorts it (`sort`); the finer list is the answer when both agree
/// (the events of the finer search, or the coarser's where the finer ran none). `Err` says
/// why not: a discretisation failed, or the lists differ.
pub(crate) fn agreed<S, Same, Sort, T>(
    settings: &Settings,
    mut carry: impl FnMut(usize) -> Result<Carried<S>, Undecided>,
    cmp: Compare<Same, Sort, T>,
) -> Result<(Vec<S>, Option<usize>), Undecided>
where
    Same: Fn(&S, &S) -> bool,
    Sort: Fn(&mut Vec<S>),
    T: Fn(&S) -> f64,
{
    let (coarse_pieces, fine_pieces) = (settings.sweep_pieces, 2 * settings.sweep_pieces);
    let mut lists: Vec<Vec<S>> = Vec::new();
    let mut events = None;
    for pieces in [coarse_pieces, fine_pieces] {
        let c = carry(pieces)?;
        events = c.events.or(events);
        let mut found: Vec<S> = Vec::new();
        for s in c.states {
            if !found.iter().any(|f| (cmp.same)(f, &s)) {
                found.push(s);
            }
        }
        (cmp.sort)(&mut found);
        lists.push(found);
    }
    let fine = lists.pop().expect("two discretisations");
    let coarse = lists.pop().expect("two discretisations");
    let same =
        fine.len() == coarse.len() && fine.iter().all(|p| coarse.iter().any(|q| (cmp.same)(p, q)));
    if !same {
        let ts = |l: &[S]| l.iter().map(&cmp.t).collect::<Vec<f64>>();
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
pub(crate) fn same_state(
    (tp, cp, sp): (f64, &[Contact], &[Side]),
    (tq, cq, sq): (f64, &[Contact], &[Side]),
    t_tol: f64,
    settings: &Settings,
) -> bool {
    (tp - tq).abs() <= t_tol
        && cp.len() == cq.len()
        && sp == sq
        && cp
            .iter()
            .zip(cq)
            .all(|(a, b)| a.kind == b.kind && (a.beta - b.beta).abs() <= settings.same_state_angle)
}
