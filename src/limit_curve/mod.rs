//! The whole η–μ limit curve of an arch (formulation §5): its branches with their
//! collapse modes and the corners where the active pattern changes, located exactly.
//!
//! 1. μ_ms and its sliding pattern come from the friction-only problem
//!    ([`crate::friction`]); η*(∞) from the thickness problem without sliding.
//! 2. η*(μ) is solved on a geometric grid from just above μ_ms to twice μ_rm, the
//!    friction the infinite-friction state needs (max |T|/N over the arch), or to
//!    10³ μ_ms when that state overturns (N = 0 somewhere: no finite μ_rm).
//! 3. Between two samples whose patterns differ, the corner is the state where both
//!    patterns' contacts are active: Newton on their union with μ as an extra unknown,
//!    accepted when it converges between the samples and is admissible over the arch.
//!    Otherwise the interval is bisected in μ (patterns compared) and Newton retried;
//!    a corner still not converged is reported with `exact: false`.
//! 4. The lowest branch ends at the corner with the vertical purely-sliding branch
//!    (μ = μ_ms, η ≥ η_ms), solved the same way from the friction-limiting pattern.
//!    A top branch whose pattern differs from the infinite-friction one approaches it
//!    asymptotically: its corner is at μ = ∞.

use crate::arch::Arch;
use crate::collapse_mode::CollapseMode;
use crate::contact::Contact;
use crate::friction::{friction_limit, FrictionLimit};
use crate::limit::{solve, Outcome};
use crate::settings::Settings;
use crate::statics::{internal_forces, Reactions};

mod sample;
mod tracer;

pub use sample::{mu_grid, sample, CurvePoint};
use tracer::{Sample, Tracer};

/// A branch of the limit curve: an interval of μ with one active pattern.
#[derive(Debug, Clone)]
pub struct Branch {
    /// Collapse mode of the pattern.
    pub mode: CollapseMode,
    /// Lower end of the μ interval.
    pub mu_min: f64,
    /// Upper end (∞ for a branch that extends to infinite friction).
    pub mu_max: f64,
    /// Least η on the branch (at `mu_max`; approached when `mu_max` is ∞).
    pub eta_min: f64,
    /// Greatest η (at `mu_min`; ∞ for the vertical purely-sliding branch).
    pub eta_max: f64,
    /// A representative pattern (from the middle of the branch).
    pub pattern: Vec<Contact>,
}

/// A corner of the limit curve, where the active pattern changes.
#[derive(Debug, Clone)]
pub struct Corner {
    /// Friction coefficient (∞ for the asymptote of a branch).
    pub mu: f64,
    /// Thickness ratio.
    pub eta: f64,
    /// Reactions of the corner state.
    pub x: Reactions,
    /// Every active contact at the corner, by increasing β.
    pub joints: Vec<Contact>,
    /// The modes of the branches it joins: [higher μ, lower μ].
    pub between: [CollapseMode; 2],
    /// The mode named from the corner's own active pattern (e.g.
    /// `rotational_sliding_shoulders` where a springing hinges and slides at once).
    pub mode: CollapseMode,
    /// True when located by Newton and verified; false when only bracketed in μ.
    pub exact: bool,
    /// Scaled Newton residual (0 for a corner at infinity).
    pub residual: f64,
}

/// When the infinite-friction state overturns (no finite μ_rm), the curve is sampled up to
/// this multiple of its lower end.
const OVERTURNING_SPAN: f64 = 1e3;
/// The lower end used for that span when μ_ms is (nearly) zero.
const MU_FLOOR: f64 = 1e-3;

/// What [`trace`] found, in one word.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum CurveStatus {
    /// At least one branch of the limit curve.
    Traced,
    /// No thickness η < 2 stands at any friction.
    NoEquilibrium,
    /// Every sampled friction admits a state at vanishing thickness: the arch stands at
    /// every η > 0, there is no limit curve (e.g. a discrete arch of at most three joints).
    NoCollapse,
    /// No branch, and some samples could not be resolved.
    Unresolved,
}

/// The limit curve of an arch.
#[derive(Debug, Clone)]
pub struct LimitCurve {
    /// μ_ms, below which no thickness stands (`None`: no finite μ suffices).
    pub mu_ms: Option<f64>,
    /// Branches, by decreasing μ, the vertical purely-sliding branch last.
    pub branches: Vec<Branch>,
    /// Corners, by decreasing μ.
    pub corners: Vec<Corner>,
    /// Samples that could not be resolved (μ and the reason).
    pub unresolved: Vec<(f64, String)>,
    /// Sampled μ at which the arch stands at every η > 0 (no collapse to find).
    pub no_collapse: Vec<f64>,
    /// Sampled μ at which no thickness stands.
    pub no_equilibrium: Vec<f64>,
    /// Number of η*(μ) solves used.
    pub solves: usize,
}

impl LimitCurve {
    /// The curve's status: traced, or why there is no branch.
    pub fn status(&self) -> CurveStatus {
        if !self.branches.is_empty() {
            CurveStatus::Traced
        } else if !self.unresolved.is_empty() {
            CurveStatus::Unresolved
        } else if !self.no_collapse.is_empty() {
            CurveStatus::NoCollapse
        } else {
            CurveStatus::NoEquilibrium
        }
    }
}

/// The friction an admissible state x at thickness η needs: max |T|/N over the arch
/// (∞ when N vanishes where T does not, or N ≤ 0 somewhere).
fn friction_needed(arch: &Arch, eta: f64, x: &Reactions, samples: usize, detach_rel: f64) -> f64 {
    let (a, b) = (arch.beta_right(), arch.beta_left());
    let joints: Vec<f64> = match arch.layout() {
        crate::arch::JointLayout::Discrete(j) => j.clone(),
        crate::arch::JointLayout::Continuous => (0..=samples)
            .map(|i| a + (b - a) * i as f64 / samples as f64)
            .collect(),
    };
    let scale = 1.0 + x.iter().map(|v| v.abs()).sum::<f64>();
    joints
        .iter()
        .map(|&beta| {
            let (n, t, _) = internal_forces(arch, eta, x, beta);
            if n <= detach_rel * scale {
                f64::INFINITY
            } else {
                t.abs() / n
            }
        })
        .fold(0.0, f64::max)
}

/// Traces the limit curve of `arch`.
pub fn trace(arch: &Arch, settings: &Settings) -> LimitCurve {
    let mut tr = Tracer {
        arch,
        settings,
        solves: 0,
        unresolved: Vec::new(),
        no_collapse: Vec::new(),
        no_equilibrium: Vec::new(),
    };
    let fl: Option<FrictionLimit> = friction_limit(arch, settings).ok().flatten();
    let Some(fl) = fl else {
        return LimitCurve {
            mu_ms: None,
            branches: vec![],
            corners: vec![],
            unresolved: tr.unresolved,
            no_collapse: tr.no_collapse,
            no_equilibrium: tr.no_equilibrium,
            solves: 0,
        };
    };
    let inf = tr.sample(f64::INFINITY);
    if inf.is_none() && tr.no_equilibrium.len() == 1 {
        // Admissibility is monotone in μ: if nothing stands at μ = ∞, nothing stands.
        if let Ok(Outcome::NoEquilibrium { .. }) =
            solve(arch, f64::INFINITY, settings).map(|s| s.outcome)
        {
            return LimitCurve {
                mu_ms: Some(fl.mu),
                branches: vec![],
                corners: vec![],
                unresolved: tr.unresolved,
                no_collapse: tr.no_collapse,
                no_equilibrium: tr.no_equilibrium,
                solves: tr.solves + 1,
            };
        }
    }
    let mu_lo = fl.mu * (1.0 + settings.curve_start_rel);
    let mu_rm = inf.as_ref().map_or(f64::INFINITY, |s| {
        friction_needed(arch, s.ls.eta, &s.ls.x, 2000, settings.detach_rel)
    });
    let mu_hi = if mu_rm.is_finite() {
        (2.0 * mu_rm).max(1.5 * mu_lo)
    } else {
        OVERTURNING_SPAN * mu_lo.max(MU_FLOOR)
    };
    let n = settings.curve_samples.max(2);
    let mut samples: Vec<Sample> = Vec::new();
    for i in (0..n).rev() {
        let mu = mu_lo * (mu_hi / mu_lo).powf(i as f64 / (n - 1) as f64);
        if let Some(s) = tr.sample(mu) {
            samples.push(s);
        }
    }
    let mut corners = Vec::new();
    // the top: a finite pattern different from the infinite-friction one is asymptotic
    if let (Some(top), Some(inf)) = (samples.first(), inf.as_ref()) {
        if top.sig != inf.sig {
            corners.push(Corner {
                mu: f64::INFINITY,
                eta: inf.ls.eta,
                x: inf.ls.x,
                joints: inf.ls.pattern.clone(),
                between: [tr.mode_of(&top.ls.pattern), tr.mode_of(&inf.ls.pattern)],
                mode: tr.mode_of(&inf.ls.pattern),
                exact: true,
                residual: 0.0,
            });
        }
    }
    for w in 0..samples.len().saturating_sub(1) {
        let (a, b) = (samples[w].clone(), samples[w + 1].clone());
        if a.sig != b.sig {
            corners.extend(tr.locate(&a, &b, 24));
        }
    }
    // the corner with the vertical purely-sliding branch
    if let Some(low) = samples.last() {
        let between = [tr.mode_of(&low.ls.pattern), CollapseMode::PurelySliding];
        let start = (low.ls.x, low.ls.eta, low.ls.mu);
        let c = tr
            .corner_newton(
                &low.ls.pattern,
                &fl.pattern,
                start,
                (fl.mu * (1.0 - settings.root_slack), low.ls.mu),
                between,
            )
            .unwrap_or(Corner {
                mu: fl.mu,
                eta: low.ls.eta,
                x: low.ls.x,
                joints: fl.pattern.clone(),
                between,
                mode: CollapseMode::PurelySliding,
                exact: false,
                residual: f64::NAN,
            });
        corners.push(c);
    }
    corners.sort_by(|a, b| b.mu.total_cmp(&a.mu));

    // branches between consecutive corners (by decreasing μ)
    let mut branches = Vec::new();
    let top_mu = f64::INFINITY;
    let mut upper = (top_mu, inf.as_ref().map_or(f64::NAN, |s| s.ls.eta));
    let mut finite_corners: Vec<&Corner> = corners.iter().filter(|c| c.mu.is_finite()).collect();
    finite_corners.sort_by(|a, b| b.mu.total_cmp(&a.mu));
    for c in &finite_corners {
        let members: Vec<Sample> = samples
            .iter()
            .filter(|s| s.ls.mu < upper.0 && s.ls.mu > c.mu)
            .cloned()
            .collect();
        // two corners between neighbouring samples: solve once inside the branch
        let rep = match members.get(members.len() / 2) {
            Some(r) => Some(r.clone()),
            None if upper.0.is_finite() => tr.sample((upper.0 * c.mu).sqrt()),
            None => None,
        };
        if let Some(rep) = rep {
            branches.push(Branch {
                mode: tr.mode_of(&rep.ls.pattern),
                mu_min: c.mu,
                mu_max: upper.0,
                eta_min: upper.1,
                eta_max: c.eta,
                pattern: rep.ls.pattern.clone(),
            });
        }
        upper = (c.mu, c.eta);
    }
    if let Some(last) = finite_corners.last() {
        branches.push(Branch {
            mode: CollapseMode::PurelySliding,
            mu_min: fl.mu,
            mu_max: fl.mu,
            eta_min: last.eta,
            eta_max: f64::INFINITY,
            pattern: fl.pattern.clone(),
        });
    }
    LimitCurve {
        mu_ms: Some(fl.mu),
        branches,
        corners,
        unresolved: tr.unresolved,
        no_collapse: tr.no_collapse,
        no_equilibrium: tr.no_equilibrium,
        solves: tr.solves,
    }
}
