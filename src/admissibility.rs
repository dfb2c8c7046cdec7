//! Static admissibility over the continuum by constraint generation (formulation §3, §5).
//!
//! At fixed (η, μ) the margin LP is solved over a small working set of joints; the most
//! violated activation functions over the whole arch are found by the 1-D scan
//! ([`crate::scan`]) and their joints added, until the continuum agrees with the
//! working set. Infeasibility on a subset of joints proves infeasibility for the arch.

use crate::arch::{grid_angle, Arch, JointLayout, Radians};
use crate::contact::{ContactKind, Peak};
use crate::lp::{self, LpOutcome};
use crate::settings::Settings;
use crate::state::State;
use crate::statics::{actions, actions_with, activation_of, forces_with, Reactions};

/// The result of the margin problem at one (η, μ).
#[derive(Debug, Clone)]
pub struct Margin {
    /// The reactions that maximise the margin.
    pub x: Reactions,
    /// The least normalised slack min(−φ / ‖∇ₓφ‖) of x over the whole arch: the
    /// state is admissible iff this is ≥ 0.
    pub margin: f64,
    /// The LP's margin over the working set (an upper bound on the best continuum margin).
    pub lp_margin: f64,
    /// Constraint-generation rounds used.
    pub rounds: usize,
}

/// The initial working set of a continuous arch: the joints that cut it into this many
/// equal pieces (constraint generation adds the rest).
const INITIAL_PIECES: usize = 8;

/// A growing set of joint angles whose activation functions enter the LP, each with its
/// (sin β, cos β) computed once.
#[derive(Debug, Clone)]
pub struct WorkingSet {
    joints: Vec<Radians>,
    trig: Vec<(f64, f64)>,
}

impl WorkingSet {
    /// The springings and a few spread joints of the arch.
    pub fn initial(arch: &Arch) -> WorkingSet {
        let joints: Vec<Radians> = match arch.layout() {
            JointLayout::Continuous => {
                let (a, b) = (arch.beta_right(), arch.beta_left());
                (0..=INITIAL_PIECES)
                    .map(|i| grid_angle(a, b, INITIAL_PIECES + 1, i))
                    .collect()
            }
            JointLayout::Discrete(j) => {
                let stride = (j.len() / 8).max(1);
                let mut v: Vec<Radians> = j.iter().step_by(stride).copied().collect();
                if v.last() != j.last() {
                    v.push(*j.last().unwrap());
                }
                v
            }
        };
        let trig = joints.iter().map(|b| b.sin_cos()).collect();
        WorkingSet { joints, trig }
    }

    /// Adds `beta` unless a joint within `tol` is already present; true when added.
    pub fn add(&mut self, beta: Radians, tol: f64) -> bool {
        if self.joints.iter().any(|b| (b - beta).abs() <= tol) {
            false
        } else {
            self.joints.push(beta);
            self.trig.push(beta.sin_cos());
            true
        }
    }

    /// The joints.
    pub fn joints(&self) -> &[Radians] {
        &self.joints
    }

    /// The joints with their (sin β, cos β).
    fn with_trig(&self) -> impl Iterator<Item = (Radians, (f64, f64))> + '_ {
        self.joints.iter().copied().zip(self.trig.iter().copied())
    }
}

/// ‖∇ₓφ‖ of `mode` at `beta`.
pub fn grad_norm(arch: &Arch, eta: f64, mu: f64, mode: ContactKind, beta: Radians) -> f64 {
    actions(arch, eta, beta)
        .activation(mode, 0, eta, mu)
        .grad_norm()
}

/// [`grad_norm`] at a peak of a scan, from its cached (sin β, cos β) when it has them (the
/// same bits).
pub fn peak_grad_norm(arch: &Arch, eta: f64, mu: f64, p: &Peak) -> f64 {
    match p.sin_cos {
        Some(sc) => activation_of(
            p.contact.kind,
            &forces_with(arch, eta, p.contact.beta, sc),
            eta,
            mu,
        )
        .grad_norm(),
        None => grad_norm(arch, eta, mu, p.contact.kind, p.contact.beta),
    }
}

/// Above √3 with room for the rounding of a norm: ‖g‖ as [`crate::statics::Affine::grad_norm`]
/// computes it is below this times max |gᵢ|.
const SQRT3_ABOVE: f64 = 1.7321;

/// The least normalised slack −φ/‖∇φ‖ over every contact of `modes` at every joint of a
/// discrete arch at x, and the (at most) four smallest below `below`, ascending (ties in
/// the order kind by kind, then joint by joint): one pass, no list of every contact.
fn discrete_slacks(
    arch: &Arch,
    joints: &[Radians],
    eta: f64,
    mu: f64,
    modes: &[ContactKind],
    x: &Reactions,
    below: f64,
) -> (f64, Vec<(f64, Radians)>) {
    let kinds: Vec<(usize, ContactKind)> = ContactKind::active_at(mu)
        .iter()
        .enumerate()
        .filter(|(_, k)| modes.contains(k))
        .map(|(i, &k)| (i, k))
        .collect();
    let trig = arch.joint_sin_cos();
    let cached = trig.len() == joints.len();
    let n = joints.len();
    let mut margin = f64::INFINITY;
    // (slack, order in the kind-major listing, β), the four smallest so far, ascending
    let mut worst: Vec<(f64, usize, Radians)> = Vec::with_capacity(5);
    for (j, &beta) in joints.iter().enumerate() {
        let sc = if cached { trig[j] } else { beta.sin_cos() };
        let f = forces_with(arch, eta, beta, sc);
        for &(k, kind) in &kinds {
            let a = activation_of(kind, &f, eta, mu);
            let phi = a.at(x);
            // a contact that can change neither the least slack nor the four smallest is
            // skipped before its norm: ‖∇φ‖ ≤ √3 max|∂φ/∂xᵢ| (with room for rounding)
            // bounds its slack from below
            let keep = if worst.len() == 4 {
                worst[3].0.min(below)
            } else {
                below
            };
            let floor = margin.max(keep);
            if phi < 0.0 && floor.is_finite() {
                let m = a.g[0].abs().max(a.g[1].abs()).max(a.g[2].abs());
                if -phi > floor.max(0.0) * m * SQRT3_ABOVE {
                    continue;
                }
            }
            let slack = -phi / a.grad_norm();
            margin = margin.min(slack);
            if slack < below {
                let key = (slack, k * n + j);
                let at = worst
                    .iter()
                    .position(|w| key.0.total_cmp(&w.0).then(key.1.cmp(&w.1)).is_lt())
                    .unwrap_or(worst.len());
                if at < 4 {
                    worst.insert(at, (slack, k * n + j, beta));
                    worst.truncate(4);
                }
            }
        }
    }
    (margin, worst.into_iter().map(|w| (w.0, w.2)).collect())
}

/// How far constraint generation goes.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Goal {
    /// Only decide feasibility: stop as soon as the LP margin is negative (no state is
    /// admissible: a subset of joints already rules it out) or the LP state is
    /// admissible over the whole arch.
    Decide,
    /// Find the best continuum margin to `sep_tol`.
    Optimise,
}

/// Maximises the admissibility margin over the continuum at (η, μ) restricted to
/// the activation functions `modes`, growing `ws` as needed.
pub fn margin_over_arch(
    arch: &Arch,
    eta: f64,
    mu: f64,
    modes: &[ContactKind],
    ws: &mut WorkingSet,
    goal: Goal,
    settings: &Settings,
) -> Result<Margin, LpOutcome> {
    let cap = arch.span();
    let mut rounds = 0;
    loop {
        rounds += 1;
        let rows: Vec<_> = ws
            .with_trig()
            .flat_map(|(beta, sc)| {
                let a = actions_with(arch, eta, beta, sc);
                modes.iter().map(move |&m| a.activation(m, 0, eta, mu))
            })
            .collect();
        let (x, s) = lp::max_margin(&rows, cap, settings)?;
        let tol = settings.sep_tol * crate::statics::reaction_scale(&x);
        let (margin, worst) = match arch.layout() {
            JointLayout::Discrete(joints) => {
                discrete_slacks(arch, joints, eta, mu, modes, &x, s - tol)
            }
            JointLayout::Continuous => {
                let peaks = State { arch, eta, mu, x }.peaks(settings);
                let mut margin = f64::INFINITY;
                let mut worst: Vec<(f64, Radians)> = Vec::new();
                for p in peaks.iter().filter(|p| modes.contains(&p.contact.kind)) {
                    let slack = -p.value / peak_grad_norm(arch, eta, mu, p);
                    margin = margin.min(slack);
                    if slack < s - tol {
                        worst.push((slack, p.contact.beta));
                    }
                }
                worst.sort_by(|a, b| a.0.total_cmp(&b.0));
                worst.truncate(4);
                (margin, worst)
            }
        };
        let mut added = false;
        let decided = goal == Goal::Decide && (s < 0.0 || margin >= 0.0);
        for &(_, beta) in &worst {
            added |= ws.add(beta, settings.working_set_gap);
        }
        if decided || !added || rounds >= settings.max_rounds {
            return Ok(Margin {
                x,
                margin: margin.min(s),
                lp_margin: s,
                rounds,
            });
        }
    }
}
