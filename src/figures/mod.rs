//! The data each figure draws, computed from the solver: the sampled limit curves
//! ([`CurveData`]), a state of the arch with its lines and mechanism ([`ArchScene`]) and the
//! margin over the η–μ plane ([`MapData`]). This is numerics; turning these data into
//! pictures is `render::plot_*` (feature `svg`), which calls no solver.
//!
//! Lengths are divided by r and angles are in radians, as everywhere in the crate.

pub mod fill_curve;
pub mod margin_map;
pub mod polylines;
pub mod thrust_line;
mod vertical;

use crate::arch::{Arch, Radians};
use crate::collapse_mode::CollapseMode;
use crate::contact::Contact;
use crate::kinematics::block_motions;
use crate::limit::{solve, LeastLimitState, Outcome};
use crate::limit_curve::{trace, LimitCurve};
use crate::limit_states::{search, survey, Survey};
use crate::load::LiveLoad;
use crate::mechanism::Mechanism;
use crate::settings::Settings;
use crate::state::State;
use crate::statics::Reactions;
use thrust_line::{eccentricities_under, Eccentricity};

/// Why a figure could not be drawn (a result, not bad input).
#[derive(Debug, Clone, PartialEq)]
pub struct NoFigure(pub String);

impl std::fmt::Display for NoFigure {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(&self.0)
    }
}

/// Points per branch when a limit curve is sampled for drawing.
const POINTS_PER_BRANCH: usize = 14;
/// Angles at which the lines of thrust and friction are sampled.
const LINE_SAMPLES: usize = 800;
/// A state at η within this relative distance of η* is drawn as the limit state.
const AT_LIMIT: f64 = 1e-12;

/// One arch's limit curve, sampled for drawing.
#[derive(Debug, Clone)]
pub struct CurveData {
    /// The arch.
    pub arch: Arch,
    /// The branches other than the purely sliding one: mode and points (μ, η) by
    /// decreasing μ.
    pub branches: Vec<(CollapseMode, Vec<(f64, f64)>)>,
    /// Finite corners (μ, η): kinks of the boundary.
    pub corners: Vec<(f64, f64)>,
    /// Finite smooth transitions (μ, η): pattern changes without a kink.
    pub transitions: Vec<(f64, f64)>,
    /// Limit states above the boundary (μ, η), at several μ inside each limit branch.
    pub limit_states: Vec<(f64, f64)>,
    /// η of the asymptote at μ = ∞ when the top branch only approaches it.
    pub asymptote: Option<f64>,
    /// μ_ms: the purely sliding branch is the vertical line μ = μ_ms above the lowest point.
    pub mu_ms: f64,
}

impl CurveData {
    /// The whole curve (all branches) as one polyline by decreasing μ.
    pub fn outline(&self) -> Vec<(f64, f64)> {
        let mut pts: Vec<(f64, f64)> = self
            .branches
            .iter()
            .flat_map(|b| b.1.iter().copied())
            .collect();
        pts.sort_by(|a, b| b.0.total_cmp(&a.0));
        pts
    }
}

/// Samples the branches of a traced `curve` (`n` points per branch, μ up to `mu_cap`).
fn sample(
    arch: &Arch,
    curve: &LimitCurve,
    mu_cap: f64,
    n: usize,
    settings: &Settings,
) -> Option<CurveData> {
    let mu_ms = curve.mu_ms?;
    let mut branches = Vec::new();
    for b in &curve.branches {
        if b.mode == CollapseMode::PurelySliding {
            continue;
        }
        let hi = b.mu_max.min(mu_cap);
        let lo = b.mu_min;
        let mut pts = vec![];
        // the upper end: a corner, or the horizontal branch's constant η at the cap
        // (an asymptotic branch is sampled only, it never reaches its η_min)
        if b.mu_max.is_finite() || b.eta_min == b.eta_max {
            pts.push((hi, b.eta_min));
        }
        for i in 1..n {
            let mu = hi * (lo / hi).powf(i as f64 / n as f64);
            // the static boundary η_s(μ)
            match solve(arch, mu, settings).map(|s| s.outcome) {
                Ok(Outcome::Limit(ls)) => pts.push((mu, ls.eta_static)),
                Ok(Outcome::Unresolved {
                    least_static: Some((eta, _)),
                    ..
                }) => pts.push((mu, eta)),
                _ => {}
            }
        }
        pts.push((lo, b.eta_max));
        branches.push((b.mode, pts));
    }
    let corners = curve
        .corners
        .iter()
        .filter(|c| c.mu.is_finite())
        .map(|c| (c.mu, c.t))
        .collect();
    let asymptote = curve
        .transitions
        .iter()
        .find(|c| c.mu.is_infinite())
        .map(|c| c.t);
    let transitions = curve
        .transitions
        .iter()
        .filter(|c| c.mu.is_finite())
        .map(|c| (c.mu, c.t))
        .collect();
    // limit states above η_s: each limit branch searched again at up to five μ across
    // its sampled range (one where it was seen at one sample only)
    let mut limit_states = Vec::new();
    for lb in &curve.limit_branches {
        let b = &lb.branch;
        let hi = b.mu_max.min(mu_cap);
        let k = if lb.samples > 1 { 5 } else { 1 };
        for i in 0..k {
            let mu = if k == 1 {
                hi
            } else {
                hi * (b.mu_min / hi).powf(i as f64 / (k - 1) as f64)
            };
            if let Ok(Ok(found)) = search(arch, mu, settings) {
                limit_states.extend(found.above.iter().map(|st| (mu, st.t)));
            }
        }
    }
    Some(CurveData {
        arch: arch.clone(),
        branches,
        corners,
        transitions,
        limit_states,
        asymptote,
        mu_ms,
    })
}

/// The limit curve of `arch` sampled up to three times its largest finite corner (at least
/// twice μ_ms); `None` when the arch stands at no friction.
pub fn curve(arch: &Arch, settings: &Settings) -> Option<CurveData> {
    let c = trace(arch, settings);
    let mu_ms = c.mu_ms?;
    let top = c
        .corners
        .iter()
        .filter(|k| k.mu.is_finite())
        .map(|k| k.mu)
        .fold(mu_ms, f64::max);
    sample(
        arch,
        &c,
        (3.0 * top).max(2.0 * mu_ms),
        POINTS_PER_BRANCH,
        settings,
    )
}

/// The limit curves of several arches (those that can stand at some friction).
pub fn curves(arches: &[Arch], settings: &Settings) -> Result<Vec<CurveData>, NoFigure> {
    let data: Vec<CurveData> = arches.iter().filter_map(|a| curve(a, settings)).collect();
    if data.is_empty() {
        return Err(NoFigure(
            "no arch has a limit curve (none can stand)".into(),
        ));
    }
    Ok(data)
}

/// The rigid motion of one block of a mechanism.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Block {
    /// Joint angle where the block starts.
    pub from: Radians,
    /// Joint angle where it ends.
    pub to: Radians,
    /// (V_x(O), V_y(O), ψ): velocity of the origin and angular velocity (formulation §4).
    pub motion: [f64; 3],
}

/// A state of the arch as the arch and eccentricity figures draw it.
#[derive(Debug, Clone)]
pub struct ArchScene {
    /// The arch.
    pub arch: Arch,
    /// Friction coefficient.
    pub mu: f64,
    /// Thickness ratio drawn.
    pub eta: f64,
    /// The reactions (h, v, w) of the state.
    pub x: Reactions,
    /// Active contacts (limit state) or the least-slack contacts (safe state).
    pub pattern: Vec<Contact>,
    /// The collapse mode at a limit state; `None` for a safe state.
    pub mode: Option<CollapseMode>,
    /// The mechanism at a limit state.
    pub mechanism: Option<Mechanism>,
    /// The moving blocks of the mechanism (empty for a safe state).
    pub blocks: Vec<Block>,
    /// When the mechanism drawn is an extreme ray of its cone: its number (from 1) and the
    /// number of extreme rays ([`extreme_scene`]); `None` for the representative.
    pub ray: Option<(usize, usize)>,
    /// The lines of thrust and friction, sampled along the arch.
    pub lines: Vec<Eccentricity>,
    /// A live load and its multiplier at this state (load figures), drawn as arrows.
    pub load: Option<(LiveLoad, f64)>,
}

/// The state drawn by the arch and eccentricity figures: the limit state at η*(μ) when
/// `eta` is `None`, else the state of greatest margin at `eta` (which must be ≥ η*).
pub fn scene(
    arch: &Arch,
    mu: f64,
    eta: Option<f64>,
    settings: &Settings,
) -> Result<ArchScene, NoFigure> {
    let sol = solve(arch, mu, settings).map_err(|e| NoFigure(e.to_string()))?;
    let ls = match sol.outcome {
        Outcome::Limit(ls) => ls,
        Outcome::NoEquilibrium { reason, .. }
        | Outcome::Unresolved { reason, .. }
        | Outcome::NoCollapse { reason } => return Err(NoFigure(reason)),
    };
    let (eta, x, pattern) = match eta {
        Some(e) if e < ls.eta * (1.0 - AT_LIMIT) => {
            return Err(NoFigure(format!(
            "no admissible state at eta = {e}: the least thickness at this friction is eta* = {}",
            ls.eta
        )))
        }
        Some(e) if e > ls.eta * (1.0 + AT_LIMIT) && sol.vertical.is_some() => {
            let sliding = sol.vertical.as_deref().unwrap_or_default();
            let (x, pattern, mech) =
                vertical::vertical_state(arch, e, mu, ls.x_static, sliding, settings).ok_or_else(
                    || {
                        NoFigure(format!(
                    "no purely sliding limit state found at eta = {e} on the vertical branch"
                ))
                    },
                )?;
            let limit = Some((CollapseMode::PurelySliding, mech));
            return Ok(build_scene(
                arch,
                mu,
                (e, x),
                pattern,
                limit,
                None,
                settings,
            ));
        }
        Some(e) if e > ls.eta * (1.0 + AT_LIMIT) => {
            let (x, pattern) = safe_state(arch, e, mu, settings)?;
            (e, x, pattern)
        }
        _ => return Ok(limit_scene(arch, mu, &ls, settings)),
    };
    Ok(build_scene(
        arch,
        mu,
        (eta, x),
        pattern,
        None,
        None,
        settings,
    ))
}

/// The least limit state of a survey, as `solve` reports it at the top level: the state at
/// η_s when it carries a mechanism (or when the search above it could not be completed),
/// else the least limit state above η_s.
pub fn survey_scene(survey: &Survey, settings: &Settings) -> Result<ArchScene, NoFigure> {
    let sol = &survey.solution;
    let (arch, mu) = (&sol.arch, sol.mu);
    if let Ok(found) = &survey.states {
        if !found.mechanism_at_eta_s {
            let st = found.above.first().ok_or_else(|| {
                NoFigure(format!(
                    "no limit state with eta in [eta_s, 2) at mu = {mu}: the arch is safe from eta_s = {} on",
                    found.eta_s
                ))
            })?;
            return Ok(swept_scene(arch, mu, st, settings));
        }
    }
    match &sol.outcome {
        Outcome::Limit(ls) => Ok(limit_scene(arch, mu, ls, settings)),
        Outcome::NoEquilibrium { reason, .. }
        | Outcome::Unresolved { reason, .. }
        | Outcome::NoCollapse { reason } => Err(NoFigure(reason.clone())),
    }
}

/// The scene of a limit state `ls` found at friction `mu` (what [`scene`] draws at η*).
pub fn limit_scene(arch: &Arch, mu: f64, ls: &LeastLimitState, settings: &Settings) -> ArchScene {
    build_scene(
        arch,
        mu,
        (ls.eta, ls.x),
        ls.pattern.clone(),
        Some((ls.mode, ls.mechanism.clone())),
        None,
        settings,
    )
}

/// The scene of a limit state found by the search above η_s.
fn swept_scene(
    arch: &Arch,
    mu: f64,
    st: &crate::limit_states::LimitState,
    settings: &Settings,
) -> ArchScene {
    build_scene(
        arch,
        mu,
        (st.t, st.x),
        st.pattern.clone(),
        Some((st.mode, st.mechanism.clone())),
        None,
        settings,
    )
}

/// The moving blocks of mechanism `m` at thickness `eta`.
fn blocks_of(eta: f64, m: &Mechanism, settings: &Settings) -> Vec<Block> {
    block_motions(eta, &m.contacts, &m.rates, settings.same_joint)
        .into_iter()
        .map(|(from, to, motion)| Block { from, to, motion })
        .collect()
}

/// The scene of a state (η, x) with its contacts, and the mode and mechanism when it is
/// a limit state.
fn build_scene(
    arch: &Arch,
    mu: f64,
    (eta, x): (f64, Reactions),
    pattern: Vec<Contact>,
    limit: Option<(CollapseMode, Mechanism)>,
    load: Option<(LiveLoad, f64)>,
    settings: &Settings,
) -> ArchScene {
    let blocks = limit
        .as_ref()
        .map_or_else(Vec::new, |(_, m)| blocks_of(eta, m, settings));
    ArchScene {
        arch: arch.clone(),
        mu,
        eta,
        x,
        pattern,
        mode: limit.as_ref().map(|l| l.0),
        mechanism: limit.map(|l| l.1),
        blocks,
        ray: None,
        lines: eccentricities_under(
            &State { arch, eta, mu, x },
            load.as_ref().map(|(l, lambda)| (l, *lambda)),
            LINE_SAMPLES,
        ),
        load,
    }
}

/// Why [`extreme_scene`] drew nothing.
#[derive(Debug, Clone, PartialEq, Eq)]
pub enum ExtremeChoice {
    /// The scene is not a limit state: it has no mechanism.
    NoMechanism,
    /// The cone has this many extreme rays, and the one asked for is not among them.
    OutOfRange(usize),
}

/// `scene` with extreme mechanism `k` (from 1) of its mechanism cone in place of the
/// representative ([`crate::mechanism::extreme_mechanisms`]): the same limit state, other
/// rates, other moving blocks.
pub fn extreme_scene(
    mut scene: ArchScene,
    k: usize,
    settings: &Settings,
) -> Result<ArchScene, ExtremeChoice> {
    let m = scene.mechanism.as_mut().ok_or(ExtremeChoice::NoMechanism)?;
    let rays = crate::mechanism::extreme_mechanisms(&scene.arch, scene.eta, m, settings);
    let rates = k
        .checked_sub(1)
        .and_then(|i| rays.get(i))
        .ok_or(ExtremeChoice::OutOfRange(rays.len()))?;
    m.rates.clone_from(rates);
    m.symmetric = false;
    scene.blocks = blocks_of(scene.eta, m, settings);
    scene.ray = Some((k, rays.len()));
    Ok(scene)
}

/// Every limit state of a live load at (η, μ) (the least, the collapse, first), each as a
/// scene with its load, lines of thrust and friction under the load, and mechanism.
pub fn load_scenes(
    arch: &Arch,
    eta: f64,
    mu: f64,
    load: &LiveLoad,
    settings: &Settings,
) -> Result<Vec<(String, ArchScene)>, NoFigure> {
    let outcome = crate::multiplier::survey(arch, eta, mu, load, settings)
        .map_err(|e| NoFigure(e.to_string()))?
        .map_err(|e| NoFigure(format!("no decision: {e}")))?;
    let sv = match outcome {
        crate::multiplier::LoadOutcome::Limits(sv) => sv,
        crate::multiplier::LoadOutcome::NoEquilibrium => {
            return Err(NoFigure("no admissible state at any lambda >= 0".into()))
        }
        crate::multiplier::LoadOutcome::NoCollapse { .. } => {
            return Err(NoFigure(
                "the load never breaks the arch (no collapse)".into(),
            ))
        }
    };
    let stat = sv.lambda_static.map(|m| m.0);
    let n = sv.limit_states.len();
    if n == 0 {
        return Err(NoFigure(
            "no limit state: the static maximum carries no mechanism with positive live power"
                .into(),
        ));
    }
    Ok(sv
        .limit_states
        .iter()
        .enumerate()
        .map(|(k, st)| {
            let label = format!(
                "{} {} of {n}: lambda = {:.9}{}{}",
                if k == 0 {
                    "collapse: limit state"
                } else {
                    "limit state"
                },
                k + 1,
                st.t,
                stat.map_or(String::new(), |s| format!(" (lambda_static = {s:.9})")),
                st.continuum_to.map_or(String::new(), |to| format!(
                    ", least of a continuum up to {to:.6}"
                ))
            );
            (
                label,
                build_scene(
                    arch,
                    mu,
                    (eta, st.x),
                    st.pattern.clone(),
                    Some((st.mode, st.mechanism.clone())),
                    Some((*load, st.t)),
                    settings,
                ),
            )
        })
        .collect())
}

/// Every limit state at μ with η in [η_s, 2) (the one at η_s when it carries a
/// mechanism, then each above it), each as a scene with a one-line label.
pub fn limit_scenes(
    arch: &Arch,
    mu: f64,
    settings: &Settings,
) -> Result<Vec<(String, ArchScene)>, NoFigure> {
    let sv = survey(arch, mu, settings).map_err(|e| NoFigure(e.to_string()))?;
    let found = sv.states.map_err(|e| {
        NoFigure(format!(
            "the search for every limit state could not be completed: {e}"
        ))
    })?;
    let mut out = Vec::new();
    if let (true, Outcome::Limit(ls)) = (found.mechanism_at_eta_s, &sv.solution.outcome) {
        out.push((
            format!("at eta_s: eta = {:.9}", ls.eta),
            limit_scene(arch, mu, ls, settings),
        ));
    }
    for st in &found.above {
        out.push((
            format!(
                "above eta_s = {:.9} by {:.3e}: eta = {:.9}",
                found.eta_s,
                st.t - found.eta_s,
                st.t
            ),
            swept_scene(arch, mu, st, settings),
        ));
    }
    let n = out.len();
    if n == 0 {
        return Err(NoFigure(format!(
            "no limit state with eta in [eta_s, 2) at mu = {mu}: the arch is safe from eta_s = {} on",
            found.eta_s
        )));
    }
    for (k, (label, _)) in out.iter_mut().enumerate() {
        *label = format!("limit state {} of {n}, {label}", k + 1);
    }
    Ok(out)
}

/// The state of greatest margin at (η, μ) and its contacts of least slack (within 1 % of
/// the least, at most six).
fn safe_state(
    arch: &Arch,
    eta: f64,
    mu: f64,
    settings: &Settings,
) -> Result<(Reactions, Vec<Contact>), NoFigure> {
    let m = crate::assess::safest_state(arch, eta, mu, settings)
        .ok_or_else(|| NoFigure(format!("no admissible state at eta = {eta}")))?;
    let st = State {
        arch,
        eta,
        mu,
        x: m.x,
    };
    let mut peaks = st.peaks(settings);
    peaks.sort_by(|a, b| b.value.total_cmp(&a.value));
    let best = peaks.first().map_or(0.0, |p| p.value);
    let pattern = peaks
        .iter()
        .filter(|p| p.value >= best * 1.01 - 1e-15)
        .take(6)
        .map(|p| p.contact)
        .collect();
    Ok((m.x, pattern))
}

/// The grid of a margin map.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct MapGrid {
    /// Cells along η.
    pub n_eta: usize,
    /// Cells along μ (always spaced geometrically).
    pub n_mu: usize,
    /// Space the η cells geometrically (for a log-scale η axis) instead of evenly from 0.
    pub log_eta: bool,
}

/// The margin over the η–μ plane and the limit curve it is drawn with.
#[derive(Debug, Clone)]
pub struct MapData {
    /// The limit curve of the arch.
    pub curve: CurveData,
    /// Cell centres along η (increasing).
    pub etas: Vec<f64>,
    /// Cell centres along μ (increasing).
    pub mus: Vec<f64>,
    /// `values[i][j]`: the margin at (`etas[i]`, `mus[j]`), NaN where the LP failed
    /// (see [`margin_map::margin_map`]).
    pub values: Vec<Vec<f64>>,
    /// Whether the η cells are spaced geometrically.
    pub log_eta: bool,
}

/// The margin map of `arch` on `grid`, computed on `threads` threads; `progress(done,
/// total)` after each cell. The window spans μ from 0.7 μ_ms to the end of the sampled
/// curve, η up to 1.6 × the curve's highest point.
pub fn map(
    arch: &Arch,
    grid: MapGrid,
    threads: usize,
    settings: &Settings,
    progress: &(dyn Fn(usize, usize) + Sync),
) -> Result<MapData, NoFigure> {
    let curve = curve(arch, settings)
        .ok_or_else(|| NoFigure("the arch cannot stand at any friction".into()))?;
    let pts = curve.outline();
    let mu_lo = 0.7 * curve.mu_ms;
    let mu_hi = pts.iter().map(|p| p.0).fold(curve.mu_ms, f64::max);
    let eta_max = pts.iter().map(|p| p.1).fold(0.0, f64::max);
    let eta_min = pts.iter().map(|p| p.1).fold(f64::INFINITY, f64::min);
    let eta_top = (1.6 * eta_max).min(1.999);
    let (n_eta, n_mu) = (grid.n_eta, grid.n_mu);
    let mus: Vec<f64> = (0..n_mu)
        .map(|j| mu_lo * (mu_hi / mu_lo).powf((j as f64 + 0.5) / n_mu as f64))
        .collect();
    let etas: Vec<f64> = if grid.log_eta {
        let eta_lo = 0.4 * eta_min;
        (0..n_eta)
            .map(|i| eta_lo * (eta_top / eta_lo).powf((i as f64 + 0.5) / n_eta as f64))
            .collect()
    } else {
        (0..n_eta)
            .map(|i| eta_top * (i as f64 + 0.5) / n_eta as f64)
            .collect()
    };
    let values = margin_map::margin_map(arch, &etas, &mus, settings, threads, progress);
    Ok(MapData {
        curve,
        etas,
        mus,
        values,
        log_eta: grid.log_eta,
    })
}
