//! Every limit state of a discrete arch at one friction coefficient, by a sweep in η.
//!
//! At fixed μ and η the admissible states form a convex polytope
//! P(η) = {x : φ_i(x, η) ≤ 0 for every contact i} in x = (h, v, w); it is empty below η_s,
//! a point at η_s, and grows with η (admissibility is monotone). Its vertices are the points
//! where three contacts are active. A limit state needs a mechanism on the active set, and
//! a mechanism needs at least four active contacts unless the pattern is degenerate
//! (formulation §4: B has rank 3, so an extreme mechanism has 4 rates, or 5 when L_e = 0;
//! three suffice only when their columns are dependent, e.g. three collinear hinges).
//! Four contacts meet at one point only at isolated η — exactly where the combinatorial
//! structure of P(η) changes, a plane passing through a vertex. So the sweep follows every
//! vertex of P(η) from η_s to the top, finds when the first other plane crosses it (the
//! roots of a polynomial, [`super::poly`]), and at each such event checks the kinematic LP
//! on the contacts active there; then it replaces the vertices through the event point by
//! the ones that exist just after it (read off the linearisation at the point). Between
//! events no vertex gains a fourth active contact, so no limit state is missed; at every
//! event the whole active set is checked. The vertex set near η_s comes from the same
//! linearisation at the least admissible state.
//!
//! Six box planes |x_k| ≤ [`BOX`] keep P bounded; an event on a box plane is not a limit
//! state. Where η_s is an infimum (the least admissible state unbounded: P(η) recedes to
//! infinity as η ↓ η_s), the sweep starts at the least η at which P(η) meets the box, from
//! the point where it does: below that every admissible state has some |x_k| > BOX.
//!
//! The files follow the method, each using only those before it: `found` (what the sweep
//! reports), `geometry` (the planes of P and the paths of its vertices), `sweeper` (the
//! sweep's state and its activity test), `check` (the kinematic LP at a point),
//! `dependent` (three contacts with dependent columns along a vertex's path), `vertices`
//! (a vertex's birth and death), `walk` and `start` (the vertices at the start), `events`
//! (the event loop). This file is the driver: the planes, the start, the event loop.

mod check;
mod dependent;
mod events;
mod facets;
mod found;
mod geometry;
mod start;
mod sweeper;
mod vertices;
mod walk;

pub use found::{CheckedPoint, LimitState, Sweep};
pub use geometry::{BOX, BOX_EDGE_REL};

use crate::arch::{Arch, JointLayout, ETA_TOP};
use crate::load::LiveLoad;
use crate::settings::Settings;
use crate::statics::Reactions;
use crate::undecided::Undecided;
use events::{run, run_to_top};
use geometry::{load_planes, planes};
use sweeper::{Param, Sweeper};

/// Follows P(η) from the least admissible state (η_s, x_s) to the top and returns every
/// limit state met on the way (η > η_s; the caller checks η_s itself). `joints` are the
/// joint angles of a discrete arch.
pub fn sweep(arch: &Arch, mu: f64, eta_s: f64, x_s: Reactions, settings: &Settings) -> Sweep {
    let JointLayout::Discrete(joints) = arch.layout() else {
        return Sweep::failed(not_discrete());
    };
    if let Some(f) = too_many(joints.len(), settings.sweep_max_joints, "sweep_max_joints") {
        return Sweep::failed(f);
    }
    let planes = planes(arch, joints, mu);
    let mut sw = Sweeper::new(arch, mu, Param::Thickness, ETA_TOP, planes, settings);
    match sw.start_at_least(eta_s, x_s) {
        Ok(true) => run(sw),
        Ok(false) => Sweep::nothing(),
        Err(f) => Sweep::failed(f),
    }
}

/// The sweep follows the planes of the joints: a continuous arch has none.
fn not_discrete() -> Undecided {
    Undecided::NotCovered("the sweep needs the joints of a discrete arch".into())
}

/// Why the sweep is not run on `joints` joints, if it is not: its work grows faster than
/// the square of the number of joints (every vertex born is tested against every plane),
/// so beyond its budget `most` (the setting `name`: `sweep_max_joints` in η,
/// `load_sweep_max_joints` in λ) it is not attempted.
fn too_many(joints: usize, most: usize, name: &str) -> Option<Undecided> {
    (joints > most).then(|| {
        Undecided::Budget(format!(
            "the complete search over {joints} joints is beyond this version's budget (settings.{name} = {most}): the limit states were not searched"
        ))
    })
}

/// The limit states of a discrete arch under a live load at fixed η strictly between
/// `lambda_min` and `lambda_static`, as [`sweep_load`] finds them, by the vertices of the
/// admissible (x, λ) on which a sliding row is active (docs/design/load-limit-states-on-the-seam.md
/// §5; the events counted are
/// those vertices). It needs the admissible (x, λ) to have an interior point (one margin
/// LP at the middle of the range; the theorem behind it holds only then): without one,
/// or where the search meets what it does not handle (a vertex with many rows active), it
/// says so and finds nothing.
pub fn faces_load(
    arch: &Arch,
    (eta, mu): (f64, f64),
    load: &LiveLoad,
    (lambda_min, lambda_static): (f64, f64),
    settings: &Settings,
) -> Sweep {
    let JointLayout::Discrete(joints) = arch.layout() else {
        return Sweep::failed(not_discrete());
    };
    let planes = load_planes(arch, joints, eta, mu, load);
    let middle = 0.5 * (lambda_min + lambda_static);
    let rows: Vec<crate::statics::Affine> = planes
        .iter()
        .filter(|p| p.contact.is_some())
        .map(|p| p.affine(middle))
        .collect();
    match crate::lp::max_margin(&rows, 1.0, settings) {
        Ok((_, margin)) if margin > settings.lp_tol => {}
        Ok(_) => {
            return Sweep::failed(Undecided::NotCovered(
                "the admissible (x, lambda) has no interior point: the face search does not apply"
                    .into(),
            ))
        }
        Err(e) => {
            return Sweep::failed(Undecided::Lp(format!("the face search's margin LP: {e:?}")))
        }
    }
    let param = Param::Multiplier { eta, load };
    let mut sw = Sweeper::new(arch, mu, param, lambda_static, planes, settings);
    match facets::search(&mut sw, lambda_min, lambda_static) {
        Ok(vertices) => sw.found(vertices),
        Err(e) => Sweep::failed(e),
    }
}

/// Whether a load's limit states on a discrete arch of `joints` joints are searched by the
/// face search ([`faces_load`], beyond the sweep's budget `settings.load_sweep_max_joints`)
/// rather than by the sweep: the one rule that the survey, its method's name and the
/// certificate follow.
pub fn by_faces(joints: usize, settings: &Settings) -> bool {
    joints > settings.load_sweep_max_joints
}

/// Follows P(λ) = {x : φ_i(x, λ) ≤ 0} of a discrete arch under a live load at fixed η,
/// from the least admissible multiplier λ_min (a state `x_min` there) to λ_static, and
/// returns every limit state met on the way whose mechanism has positive live power (the
/// caller checks λ_static itself). The same argument as in η applies: a limit state needs
/// four active contacts at one point (or three with dependent columns, which stay
/// dependent along a vertex path: checked where its total power turns ≥ 0), which happens
/// only where P(λ) changes
/// combinatorially, at the events the sweep visits. Where P(λ_min) has an interior (the
/// arch stands unloaded, λ_min = 0) the sweep starts from all its vertices, found by a
/// walk on its vertex graph.
#[allow(clippy::too_many_arguments)]
pub fn sweep_load(
    arch: &Arch,
    eta: f64,
    mu: f64,
    load: &LiveLoad,
    min: (f64, Reactions),
    lambda_static: f64,
    settings: &Settings,
) -> Sweep {
    sweep_load_with_top(arch, eta, mu, load, min, lambda_static, settings).0
}

/// [`sweep_load`], and the points of P(λ_static) the sweep reached: every vertex alive at
/// the top, evaluated there, and every event within `settings.same_root` × (1 + λ_static)
/// of the top (the resolution of its roots), which the sweep neither counts nor checks (the
/// caller decides at λ_static). As λ rises to λ_static the vertices of P(λ) run into the
/// vertices of the optimal face P(λ_static), so these points are those vertices (each
/// possibly several times, and points on the box included), whichever state the LP returned
/// there. Empty after a failure before the event loop.
#[allow(clippy::too_many_arguments)]
pub fn sweep_load_with_top(
    arch: &Arch,
    eta: f64,
    mu: f64,
    load: &LiveLoad,
    (lambda_min, x_min): (f64, Reactions),
    lambda_static: f64,
    settings: &Settings,
) -> (Sweep, Vec<Reactions>) {
    let failure = |f: Undecided| (Sweep::failed(f), Vec::new());
    let JointLayout::Discrete(joints) = arch.layout() else {
        return failure(not_discrete());
    };
    if by_faces(joints.len(), settings) {
        // beyond the sweep's budget, the face search (no points at the top: the caller's
        // walk on the optimal face finds them)
        let most = settings.load_face_max_joints;
        if let Some(f) = too_many(joints.len(), most, "load_face_max_joints") {
            return failure(f);
        }
        let range = (lambda_min, lambda_static);
        return (
            faces_load(arch, (eta, mu), load, range, settings),
            Vec::new(),
        );
    }
    let planes = load_planes(arch, joints, eta, mu, load);
    let param = Param::Multiplier { eta, load };
    let mut sw = Sweeper::new(arch, mu, param, lambda_static, planes, settings);
    match sw.start_at_least_load((lambda_min, x_min)) {
        Ok(()) => run_to_top(sw),
        Err(f) => failure(f),
    }
}
