//! Limit states of a discrete arch above η_s, found on the ridge over the friction polygon
//! (the theorem, its proof and the cases are in
//! `docs/design/limit-states-on-boundary.md`).
//!
//! For the centreline weight and finite μ, N_j and T_j are affine in (h, v) alone, so the
//! sliding rows cut a fixed convex polygon Q of the (h, v) plane. Where P(η) has an interior
//! point, every limit state has an active sliding row, so (h, v) ∈ ∂Q; its mechanism has as
//! much extrados as intrados hinge rate (the third row of B), so an E row and an I row are
//! active and η = g(h, v), the least η whose band of admissible w at (h, v) is not empty.
//! The limit states are points of this ridge with four active rows (or three with
//! dependent columns). The search walks the ridge along each edge of Q: the edge's ends
//! (vertices of Q, case V), the apexes where both sliding lines of one joint meet (V2), the
//! breakpoints where a third hinge row reaches w (E1, a quadratic per row) and the points of
//! a piece where the sliding column and the piece's two hinge columns are dependent (E2, a
//! quadratic in η). Every candidate is then checked like a state of the sweep: admissible
//! over every joint (`State::verdict`) and a mechanism on its active contacts
//! (`mechanism::find`).
//!
//! Every event is a closed form of degree ≤ 2. What the walk cannot decide it hands back
//! as an `Err` (the caller then sweeps): three sliding lines through one vertex of Q whose
//! columns could balance without hinge rates, or one running along an edge there (G1),
//! families of limit states (a quadratic that vanishes identically), a walk that does not
//! reach the end of its edge, a kinematic LP the back end does not decide.
//!
//! The files, each using only those before it: `rows` (the joints' rows over (h, v) and
//! the hinge rows along a line), `polygon` (Q), `walk` (the ridge over one edge of Q),
//! `candidates` (every point to check), `check` (a candidate checked like a point of the
//! sweep). This file is the driver.

mod candidates;
mod check;
mod near;
mod polygon;
mod rows;
mod trace;
mod walk;

use crate::arch::{Arch, JointLayout};
use crate::contact::Contact;
use crate::settings::Settings;
use crate::statics::reaction_scale;
use crate::statics::Reactions;
use crate::undecided::Undecided;
use candidates::candidates;
use check::{check, may_carry_mechanism, Checked};
pub use rows::applies;
use rows::JointRows;
pub use trace::{trace, Junction, TracedEdge};

use super::sweep::LimitState;

/// The limit states the ridge search found, and how many candidate points it checked.
#[derive(Debug, Clone)]
pub struct Ridge {
    /// Limit states with η > `eta_lo`, ascending in η.
    pub states: Vec<LimitState>,
    /// Candidate points of the ridge checked (vertices, apexes, breakpoints, dependent
    /// columns) with η > `eta_lo`.
    pub candidates: usize,
    /// Admissible points with four active contacts whose mechanism only just fails (one
    /// rate of the other sign, of at most `almost_rate` of the largest; none where that is
    /// 0). Not limit states of this arch; a continuous arch's discretisation hands them to
    /// the continuum, whose branch may end a little later.
    pub almost: Vec<Start>,
}

/// Where Newton on the continuum starts from: a discrete state (η, reactions) and its
/// contacts.
pub type Start = (f64, Reactions, Vec<Contact>);

/// Every limit state of a discrete arch (centreline weight, finite μ) with η in
/// (`eta_lo`, 2) that lies on the ridge over ∂Q. The caller owns the claim that these are
/// *all* limit states there: it holds wherever P(η) has an interior point (checked by the
/// caller with one margin LP). `Err` says why the walk could not decide (the caller then
/// sweeps). With `almost_rate` > 0 it also lists the points whose mechanism only just fails
/// ([`Ridge::almost`]).
pub fn search(
    arch: &Arch,
    mu: f64,
    eta_lo: f64,
    almost_rate: f64,
    settings: &Settings,
) -> Result<Ridge, Undecided> {
    if !applies(arch, mu) {
        return Err(Undecided::NotCovered(
            "the ridge search needs a discrete arch, the centreline weight and finite mu".into(),
        ));
    }
    let JointLayout::Discrete(joints) = arch.layout() else {
        unreachable!("checked by applies")
    };
    if joints.len() > settings.ridge_max_joints {
        return Err(Undecided::Budget(format!(
            "the ridge walk over {} joints is beyond settings.ridge_max_joints = {}",
            joints.len(),
            settings.ridge_max_joints
        )));
    }
    let js: Vec<JointRows> = joints.iter().map(|&b| JointRows::at(arch, b)).collect();
    let (cands, subsets) = candidates(&js, mu, eta_lo)?;
    let mut states: Vec<LimitState> = Vec::new();
    let mut almost = Vec::new();
    for c in &cands {
        if !may_carry_mechanism(&js, (mu, almost_rate), c, &subsets, settings) {
            continue;
        }
        let s = match check(arch, (mu, almost_rate), c, settings)? {
            Checked::Limit(s) => s,
            Checked::Almost(contacts) => {
                almost.push((c.eta, c.x, contacts));
                continue;
            }
            Checked::No => continue,
        };
        // a state found twice (an end of two edges of Q, say) is kept as the least of its
        // finds, so that the answer does not depend on the order of the walk
        let dup = states.iter_mut().find(|p| {
            (p.t - s.t).abs() <= settings.same_state_eta * s.t
                && (0..3).all(|k| {
                    (p.x[k] - s.x[k]).abs() <= settings.same_state_x * reaction_scale(&s.x)
                })
        });
        let key = |s: &LimitState| [s.t, s.x[0], s.x[1], s.x[2]];
        match dup {
            None => states.push(s),
            Some(p) => {
                let (a, b) = (key(&s), key(p));
                if (0..4).map(|k| a[k].total_cmp(&b[k])).find(|o| o.is_ne())
                    == Some(std::cmp::Ordering::Less)
                {
                    *p = s;
                }
            }
        }
    }
    sort_states(&mut states, settings);
    Ok(Ridge {
        states,
        candidates: cands.len(),
        almost,
    })
}

/// Ascending in η; states whose η agree to `settings.same_root` (relative: mirror images)
/// by their patterns (angles, then kinds), so that the order does not depend on the order
/// of the walk.
pub(crate) fn sort_states(states: &mut [LimitState], settings: &Settings) {
    states.sort_by(|p, q| p.t.total_cmp(&q.t));
    let mut k = 0;
    while k < states.len() {
        let mut end = k + 1;
        while end < states.len() && states[end].t - states[k].t <= settings.same_root * states[k].t
        {
            end += 1;
        }
        states[k..end].sort_by(|p, q| {
            let key = |s: &LimitState| {
                s.pattern
                    .iter()
                    .map(|c| (c.beta, c.kind))
                    .collect::<Vec<_>>()
            };
            key(p)
                .partial_cmp(&key(q))
                .unwrap_or(std::cmp::Ordering::Equal)
        });
        k = end;
    }
}
