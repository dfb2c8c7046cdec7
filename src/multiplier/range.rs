//! The range of admissible multipliers, two LPs (exchange and Newton on a continuous
//! arch), and the check of a load against its arch.

use super::continuum::{self, NoExtreme};
use super::outcome::StaticRange;
use crate::arch::{check_eta, Arch, InputError, JointLayout};
use crate::load::{rows, LiveLoad, LoadRow};
use crate::lp::{self, LpOutcome};
use crate::settings::Settings;
use crate::undecided::Undecided;

/// The least multiplier of a continuous arch came out unbounded (the LP's cap on λ is only
/// above).
pub(super) const UNBOUNDED_BELOW: &str = "the least multiplier came out unbounded";

/// Checks the load against the arch: a point load must lie on it (β_R ≤ β_P ≤ β_L), and a
/// horizontal acceleration has no fill to act on.
pub fn check_load(arch: &Arch, load: &LiveLoad) -> Result<(), InputError> {
    if arch.fill().is_some() && matches!(load, LiveLoad::Horizontal { .. }) {
        return Err(InputError::Inconsistent {
            arg: "--fill-weight",
            reason: "a horizontal acceleration acts on the ring's weight alone, and the \
                     fill's inertia is not modelled: no fill with --horizontal"
                .into(),
        });
    }
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
) -> Result<Result<StaticRange, Undecided>, InputError> {
    check_eta(eta)?;
    crate::arch::check_mu(mu)?;
    check_load(arch, load)?;
    let JointLayout::Discrete(joints) = arch.layout() else {
        let ext = |maximise| continuum::extreme(arch, eta, mu, load, maximise, settings);
        let min = match ext(false) {
            Ok(Some((l, x, _))) => (l, x),
            Ok(None) => return Ok(Err(Undecided::Lp(UNBOUNDED_BELOW.into()))),
            Err(NoExtreme::NoState) => return Ok(Ok(StaticRange::NoEquilibrium)),
            Err(NoExtreme::Undecided(e)) => return Ok(Err(e)),
        };
        let max = match ext(true) {
            Ok(m) => m.map(|(l, x, _)| (l, x)),
            Err(NoExtreme::NoState) => return Ok(Ok(StaticRange::NoEquilibrium)),
            Err(NoExtreme::Undecided(e)) => return Ok(Err(e)),
        };
        return Ok(Ok(StaticRange::Interval { min, max }));
    };
    let rows: Vec<([f64; 4], f64)> = rows(arch, joints, eta, mu, load)
        .iter()
        .map(LoadRow::pair)
        .collect();
    let split = |z: [f64; 4]| (z[3], [z[0], z[1], z[2]]);
    let min = match lp::multiplier_extreme(&rows, &[], false, settings) {
        Ok(Some(z)) => split(z),
        Ok(None) => {
            return Ok(Err(Undecided::Lp(
                "the least multiplier came out unbounded below 0".into(),
            )))
        }
        Err(LpOutcome::Infeasible) => return Ok(Ok(StaticRange::NoEquilibrium)),
        Err(LpOutcome::Failed(e)) => return Ok(Err(Undecided::back_end(e))),
    };
    let max = match lp::multiplier_extreme(&rows, &[], true, settings) {
        Ok(z) => z.filter(|z| !lp::on_box(z)).map(split),
        Err(LpOutcome::Infeasible) => return Ok(Ok(StaticRange::NoEquilibrium)),
        Err(LpOutcome::Failed(e)) => return Ok(Err(Undecided::back_end(e))),
    };
    Ok(Ok(StaticRange::Interval { min, max }))
}
