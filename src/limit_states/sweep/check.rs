//! The check at a point of the sweep: the kinematic LP on the contacts active there. A
//! mechanism makes the point a limit state; none makes it evidence of "no limit state
//! here" that a certificate can carry.

use super::found::{CheckedPoint, LimitState};
use super::sweeper::{Param, Sweeper};
use crate::contact::Contact;
use crate::load::Side;
use crate::mechanism;
use crate::state::State;
use crate::statics::Reactions;
use crate::undecided::Undecided;

impl Sweeper<'_> {
    /// Checks the contacts active at (x, t) for a mechanism; records a limit state.
    pub(super) fn check(&mut self, x: Reactions, t: f64, act: &[usize]) {
        let mut pattern: Vec<(Contact, Side)> = act
            .iter()
            .filter_map(|&i| self.planes[i].contact.map(|c| (c, self.planes[i].side)))
            .collect();
        if pattern.len() < 3 || act.len() > pattern.len() {
            return; // too few contacts, or on the box (not a bounded state)
        }
        pattern.sort_by(|a, b| {
            a.0.beta
                .total_cmp(&b.0.beta)
                .then((a.1 == Side::After).cmp(&(b.1 == Side::After)))
                .then(a.0.kind.cmp(&b.0.kind))
        });
        let contacts: Vec<Contact> = pattern.iter().map(|p| p.0).collect();
        let sides: Vec<Side> = pattern.iter().map(|p| p.1).collect();
        let found = match self.param {
            Param::Thickness => {
                let st = State {
                    arch: self.arch,
                    eta: t,
                    mu: self.mu,
                    x,
                };
                match mechanism::find(&st, &contacts, self.settings) {
                    Ok(m) => m.map(|m| (m, 0.0)),
                    Err(e) => {
                        self.lp_failure.get_or_insert(Undecided::Lp(format!(
                            "the kinematic LP at eta = {t} was not decided by the LP back end: {e:?}"
                        )));
                        return;
                    }
                }
            }
            Param::Multiplier { eta, load } => {
                let st = State {
                    arch: self.arch,
                    eta,
                    mu: self.mu,
                    x,
                };
                match mechanism::find_under_load(&st, t, load, &pattern, self.settings) {
                    Ok(m) => m,
                    Err(e) => {
                        self.lp_failure.get_or_insert(Undecided::Lp(format!(
                            "the kinematic LP at lambda = {t} was not decided by the LP back end: {e:?}"
                        )));
                        return;
                    }
                }
            }
        };
        if let Some((mech, live_power)) = found {
            self.states.push(LimitState::new(
                self.arch,
                (t, x),
                (contacts, sides),
                (mech, live_power),
                self.settings,
            ));
        } else {
            self.no_mechanism.push(CheckedPoint {
                eta: t,
                x,
                pattern: contacts,
                sides,
            });
        }
    }
}
