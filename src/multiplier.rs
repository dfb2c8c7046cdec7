//! The load-multiplier problem at fixed η and μ (issue 11, first piece): the range of
//! multipliers λ ≥ 0 of a [`LiveLoad`] at which a statically admissible state exists.
//!
//! Every activation function is affine in (x, λ) ([`crate::load`]), so the admissible
//! (x, λ) form a convex polyhedron and its λ-range [λ_min, λ_static] is two LPs. For a
//! discrete arch the rows are the four activation functions at every joint — at the
//! point load's own joint on both sides of the loaded section. λ_min > 0 means the arch
//! does not stand without the load (the load stabilises it up to λ_min); λ_static is the
//! largest statically admissible multiplier (unbounded: the load never breaks the arch).

use crate::arch::{check_eta, Arch, InputError, JointLayout, Radians};
use crate::contact::ContactKind;
use crate::load::{live_activation, LiveLoad, Side};
use crate::lp::{self, LpOutcome};
use crate::settings::Settings;
use crate::statics::{actions, Reactions};

/// The admissible multipliers λ ≥ 0 at (η, μ).
#[derive(Debug, Clone, PartialEq)]
pub enum StaticRange {
    /// No state is admissible at any λ ≥ 0.
    NoEquilibrium,
    /// Admissible states exist for λ in [`min`, `max`] (`max` `None`: unbounded), each end
    /// with a state that attains it.
    Interval {
        /// The least admissible λ (0 when the arch stands unloaded) and a state there.
        min: (f64, Reactions),
        /// The largest admissible λ, λ_static, and a state there; `None` when unbounded.
        max: Option<(f64, Reactions)>,
    },
}

/// The rows `a · (h, v, w, λ) + c ≤ 0` of a discrete arch: every activation function
/// that exists at μ, at every joint, on both sides of a joint carrying the point load.
pub fn rows(
    arch: &Arch,
    joints: &[Radians],
    eta: f64,
    mu: f64,
    load: &LiveLoad,
) -> Vec<([f64; 4], f64)> {
    let mut out = Vec::with_capacity(4 * joints.len() + 4);
    for &beta in joints {
        let sides: &[Side] = if load.splits(beta) {
            &[Side::Before, Side::After]
        } else {
            &[Side::After]
        };
        let dead = actions(arch, eta, beta);
        for &side in sides {
            let live = load.actions(arch, eta, beta, side);
            for &kind in ContactKind::active_at(mu) {
                let a = dead.activation(kind, 0, eta, mu);
                let l = live_activation(kind, eta, mu, live);
                out.push(([a.g[0], a.g[1], a.g[2], l], a.c));
            }
        }
    }
    out
}

/// Checks the load against the arch: a point load must lie on it (β_R ≤ β_P ≤ β_L).
pub fn check_load(arch: &Arch, load: &LiveLoad) -> Result<(), InputError> {
    if let LiveLoad::Point { beta } = *load {
        let (a, b) = (arch.beta_right(), arch.beta_left());
        if !(beta.is_finite() && beta >= a && beta <= b) {
            return Err(InputError::OutOfRange {
                arg: "--point-load",
                value: crate::arch::fmt_value(beta),
                range: format!("beta_right = {a} <= B <= beta_left = {b} (radians)"),
            });
        }
    }
    Ok(())
}

/// The range of admissible multipliers λ ≥ 0 of `load` on a discrete arch at thickness
/// `eta` and friction `mu` (two LPs). The inner `Err` is the LP back end's failure text
/// (no decision), never an answer.
pub fn static_range(
    arch: &Arch,
    eta: f64,
    mu: f64,
    load: &LiveLoad,
    settings: &Settings,
) -> Result<Result<StaticRange, String>, InputError> {
    check_eta(eta)?;
    crate::arch::check_mu(mu)?;
    check_load(arch, load)?;
    let JointLayout::Discrete(joints) = arch.layout() else {
        return Ok(Err(
            "the static multiplier range is computed for discrete arches (given joints) only, so far"
                .into(),
        ));
    };
    let rows = rows(arch, joints, eta, mu, load);
    let split = |z: [f64; 4]| (z[3], [z[0], z[1], z[2]]);
    let min = match lp::multiplier_extreme(&rows, false, settings) {
        Ok(Some(z)) => split(z),
        Ok(None) => return Ok(Err("the least multiplier came out unbounded below 0".into())),
        Err(LpOutcome::Infeasible) => return Ok(Ok(StaticRange::NoEquilibrium)),
        Err(LpOutcome::Failed(e)) => return Ok(Err(format!("LP back end: {e}"))),
    };
    let max = match lp::multiplier_extreme(&rows, true, settings) {
        Ok(z) => z.map(split),
        Err(LpOutcome::Infeasible) => return Ok(Ok(StaticRange::NoEquilibrium)),
        Err(LpOutcome::Failed(e)) => return Ok(Err(format!("LP back end: {e}"))),
    };
    Ok(Ok(StaticRange::Interval { min, max }))
}
