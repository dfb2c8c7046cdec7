//! The event loop: the next event is the earliest death among the vertices alive; there the
//! contacts active are checked for a mechanism, the vertices through the event point end,
//! and the ones that exist just after it are born.

use super::found::Sweep;
use super::sweeper::{Param, Sweeper};
use crate::statics::Reactions;
use crate::undecided::Undecided;

/// At most this many events are processed (a safety net; never reached in tests).
const MAX_EVENTS: usize = 200_000;

/// The event loop: from the vertices alive at the start to the top.
pub(super) fn run(sw: Sweeper) -> Sweep {
    run_to_top(sw).0
}

/// [`run`], and, for a load sweep, the points of P(top) it reached (see
/// [`super::sweep_load_with_top`]): every event within `settings.same_root` × (1 + top) of
/// the top — neither counted nor checked there, the caller decides at the top — and every
/// vertex alive at the end, evaluated at the top. Empty for the thickness sweep.
pub(super) fn run_to_top(mut sw: Sweeper) -> (Sweep, Vec<Reactions>) {
    let mut events = 0;
    let mut at_top = Vec::new();
    let top_band = match sw.param {
        // the resolution of the sweep's roots (see `death`): relative, and absolute near 0
        Param::Multiplier { .. } => sw.top - sw.settings.same_root * (1.0 + sw.top.abs()),
        Param::Thickness => f64::INFINITY,
    };
    while let Some((i, (eta_e, killer))) = sw.next_death() {
        let at_the_top = eta_e >= top_band;
        if !at_the_top {
            events += 1;
        }
        if events > MAX_EVENTS {
            let sweep = Sweep {
                states: sw.states,
                events,
                no_mechanism: sw.no_mechanism,
                failure: Some(Undecided::Budget(format!("more than {MAX_EVENTS} events"))),
            };
            return (sweep, at_top);
        }
        let x_e = sw.alive[i].0.at(eta_e);
        let act = sw.active_at_event(i, killer, &x_e, eta_e);
        if at_the_top {
            at_top.push(x_e);
        } else {
            sw.check(x_e, eta_e, &act);
        }
        sw.end_through(i, &x_e, eta_e, &act);
        for v in sw.vertices_after(&x_e, eta_e, &act) {
            sw.push(v, eta_e);
        }
    }
    if top_band.is_finite() {
        at_top.extend(sw.alive.iter().map(|(v, _)| v.at(sw.top)));
    }
    (sw.found(events), at_top)
}

impl Sweeper<'_> {
    /// The vertex alive that dies first (its index) and its death.
    fn next_death(&self) -> Option<(usize, (f64, usize))> {
        self.alive
            .iter()
            .enumerate()
            .filter_map(|(i, (_, d))| d.map(|d| (i, d)))
            .min_by(|a, b| a.1 .0.total_cmp(&b.1 .0))
    }

    /// The planes active at the event where vertex `i` meets plane `killer`, at the point
    /// `x_e`: those within `event_tol`, and the four that define the event in any case;
    /// ascending.
    fn active_at_event(&self, i: usize, killer: usize, x_e: &Reactions, eta_e: f64) -> Vec<usize> {
        let mut act = self.active(x_e, eta_e);
        for p in self.alive[i].0.planes.into_iter().chain([killer]) {
            if !act.contains(&p) {
                act.push(p);
            }
        }
        act.sort_unstable();
        act
    }

    /// Ends vertex `i` and every other vertex through the event point: its three planes
    /// active there, and at the point to `event_tol` (relative to the state's size, and to
    /// each coordinate's).
    fn end_through(&mut self, i: usize, x_e: &Reactions, eta_e: f64, act: &[usize]) {
        let tol = self.tol(x_e);
        let rel = self.settings.event_tol;
        self.alive.swap_remove(i);
        self.alive.retain(|(v, _)| {
            let through = v.planes.iter().all(|p| act.contains(p));
            let at = v.at(eta_e);
            !(through
                && (0..3).all(|k| (at[k] - x_e[k]).abs() <= tol.max(rel * (1.0 + x_e[k].abs()))))
        });
    }

    /// What the sweep found after `events` events: its limit states ascending in t, each
    /// once (states at the same root with the same contacts, met from several vertices,
    /// are one).
    pub(super) fn found(mut self, events: usize) -> Sweep {
        let same_root = self.settings.same_root;
        self.states.sort_by(|a, b| a.t.total_cmp(&b.t));
        self.states.dedup_by(|a, b| {
            (a.t - b.t).abs() <= same_root * (1.0 + b.t)
                && a.pattern.len() == b.pattern.len()
                && a.pattern
                    .iter()
                    .zip(&b.pattern)
                    .all(|(p, q)| p.kind == q.kind && p.beta == q.beta)
        });
        Sweep {
            states: self.states,
            events,
            no_mechanism: self.no_mechanism,
            failure: self.lp_failure,
        }
    }
}
