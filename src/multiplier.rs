//! The load-multiplier problem at fixed η and μ (issue 11): the range of multipliers
//! λ ≥ 0 of a [`LiveLoad`] at which a statically admissible state exists, and every limit
//! state in it (a state whose active contacts carry a mechanism with positive live power).
//!
//! Every activation function is affine in (x, λ) ([`crate::load`]), so the admissible
//! (x, λ) form a convex polyhedron and its λ-range [λ_min, λ_static] is two LPs. For a
//! discrete arch the rows are the four activation functions at every joint — at the
//! point load's own joint on both sides of the loaded section. λ_min > 0 means the arch
//! does not stand without the load (the load stabilises it up to λ_min); λ_static is the
//! largest statically admissible multiplier (unbounded: the load never breaks the arch).

use crate::arch::{check_eta, Arch, InputError, JointLayout, Radians};
use crate::collapse_mode::{classify, CollapseMode};
use crate::contact::{Contact, ContactKind, Location};
use crate::limit_states::sweep::sweep_load;
use crate::load::{live_activation, LiveLoad, Side};
use crate::lp::{self, LpOutcome};
use crate::mechanism::{self, Mechanism};
use crate::settings::Settings;
use crate::state::State;
use crate::statics::{actions, magnitude, Reactions};

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

/// A limit state under the live load: an admissible state at multiplier λ whose active
/// contacts carry a mechanism with positive live power.
#[derive(Debug, Clone)]
pub struct LoadLimitState {
    /// The multiplier.
    pub lambda: f64,
    /// Reactions.
    pub x: Reactions,
    /// Every contact active there, by increasing β (at the point load's joint, the side
    /// of the loaded section in `sides`).
    pub pattern: Vec<Contact>,
    /// The side of the loaded section of each contact (`After` away from the point load).
    pub sides: Vec<Side>,
    /// The collapse mode named from the pattern.
    pub mode: CollapseMode,
    /// A mechanism on them (its `power` is the total external power).
    pub mechanism: Mechanism,
    /// The live load's power in that mechanism (> 0).
    pub live_power: f64,
}

/// Every limit state of a loaded discrete arch at (η, μ) with λ in [λ_min, λ_static].
#[derive(Debug, Clone)]
pub struct LoadSurvey {
    /// The least admissible multiplier (0 when the arch stands unloaded) and a state.
    pub lambda_min: (f64, Reactions),
    /// The largest admissible multiplier and a state there.
    pub lambda_static: (f64, Reactions),
    /// Whether the state at λ_static carries a mechanism with positive live power.
    pub mechanism_at_static: bool,
    /// Every limit state, ascending in λ (the one at λ_static included when it exists).
    pub limit_states: Vec<LoadLimitState>,
    /// Events of the sweep.
    pub events: usize,
}

impl LoadSurvey {
    /// The collapse multiplier: the least limit state's λ (`None`: no limit state at all,
    /// which the static maximum without a mechanism can leave).
    pub fn lambda(&self) -> Option<f64> {
        self.limit_states.first().map(|s| s.lambda)
    }
    /// Whether exactly one limit state exists.
    pub fn unique(&self) -> bool {
        self.limit_states.len() == 1
    }
    /// 1 − λ/λ_static: how far non-associative friction lowers the collapse multiplier.
    pub fn reduction(&self) -> Option<f64> {
        self.lambda().map(|l| 1.0 - l / self.lambda_static.0)
    }
}

/// The answer to the load question at (η, μ).
#[derive(Debug, Clone)]
pub enum LoadOutcome {
    /// No state is admissible at any λ ≥ 0.
    NoEquilibrium,
    /// λ is unbounded: the load never breaks the arch (the least admissible multiplier
    /// and a state there are given; limit states are not searched).
    NoCollapse {
        /// λ_min and a state there.
        lambda_min: (f64, Reactions),
    },
    /// The static range and every limit state in it.
    Limits(LoadSurvey),
}

/// Every limit state of `load` on a discrete arch at thickness `eta` and friction `mu`:
/// the static range (two LPs), the state at λ_static checked for a mechanism with positive
/// live power, and the sweep of P(λ) from λ_min to λ_static for the limit states below it.
/// The inner `Err` says why no decision was reached.
pub fn survey(
    arch: &Arch,
    eta: f64,
    mu: f64,
    load: &LiveLoad,
    settings: &Settings,
) -> Result<Result<LoadOutcome, String>, InputError> {
    let range = match static_range(arch, eta, mu, load, settings)? {
        Ok(r) => r,
        Err(e) => return Ok(Err(e)),
    };
    let (min, max) = match range {
        StaticRange::NoEquilibrium => return Ok(Ok(LoadOutcome::NoEquilibrium)),
        StaticRange::Interval { min, max: None } => {
            return Ok(Ok(LoadOutcome::NoCollapse { lambda_min: min }))
        }
        StaticRange::Interval {
            min,
            max: Some(max),
        } => (min, max),
    };
    let at_static = limit_state_at(arch, eta, mu, load, max, settings);
    let sw = sweep_load(arch, eta, mu, load, min, max.0, settings);
    if let Some(f) = sw.failure {
        return Ok(Err(f));
    }
    let mut limit_states: Vec<LoadLimitState> = sw
        .states
        .into_iter()
        .filter(|s| s.eta < max.0 * (1.0 - settings.root_slack))
        .map(|s| LoadLimitState {
            lambda: s.eta,
            x: s.x,
            pattern: s.pattern,
            sides: s.sides,
            mode: s.mode,
            mechanism: s.mechanism,
            live_power: s.live_power,
        })
        .collect();
    let mechanism_at_static = at_static.is_some();
    limit_states.extend(at_static);
    Ok(Ok(LoadOutcome::Limits(LoadSurvey {
        lambda_min: min,
        lambda_static: max,
        mechanism_at_static,
        limit_states,
        events: sw.events,
    })))
}

/// The limit state at the static maximum, if its active contacts carry a mechanism with
/// positive live power.
fn limit_state_at(
    arch: &Arch,
    eta: f64,
    mu: f64,
    load: &LiveLoad,
    (lambda, x): (f64, Reactions),
    settings: &Settings,
) -> Option<LoadLimitState> {
    let JointLayout::Discrete(joints) = arch.layout() else {
        return None;
    };
    let last = joints.len() - 1;
    let mut pattern: Vec<(Contact, Side)> = Vec::new();
    for (j, &beta) in joints.iter().enumerate() {
        let at = if j == 0 || j == last {
            Location::Springing
        } else {
            Location::Interior
        };
        let dead = actions(arch, eta, beta);
        let sides: &[Side] = if load.splits(beta) {
            &[Side::Before, Side::After]
        } else {
            &[Side::After]
        };
        for &side in sides {
            let live = load.actions(arch, eta, beta, side);
            for &kind in ContactKind::active_at(mu) {
                let phi = dead.activation(kind, 0, eta, mu).at(&x)
                    + lambda * live_activation(kind, eta, mu, live);
                let size = magnitude(kind, eta, mu, &x, settings.magnitude_floor);
                if phi.abs() <= settings.event_tol * size {
                    let c = Contact {
                        beta,
                        kind,
                        at,
                        free: false,
                    };
                    pattern.push((c, side));
                }
            }
        }
    }
    let st = State { arch, eta, mu, x };
    let (mechanism, live_power) =
        mechanism::find_under_load(&st, lambda, load, &pattern, settings).ok()??;
    let contacts: Vec<Contact> = pattern.iter().map(|p| p.0).collect();
    let mode = classify(
        &contacts,
        0.5 * (arch.beta_right() + arch.beta_left()),
        settings.same_joint,
    );
    Some(LoadLimitState {
        lambda,
        x,
        sides: pattern.iter().map(|p| p.1).collect(),
        pattern: contacts,
        mode,
        mechanism,
        live_power,
    })
}
