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

use crate::arch::{Arch, ETA_TOP};
use crate::collapse_mode::CollapseMode;
use crate::contact::Contact;
use crate::friction::{friction_limit, FrictionLimit};
use crate::limit::{solve, Outcome};
use crate::limit_states::{search_after, LimitStates};
use crate::settings::Settings;
use crate::statics::{internal_forces, Reactions};
use crate::undecided::Undecided;

mod boundary;
pub mod filled;
mod onset;
mod sample;
mod transition;

use crate::search::RootGuess;
pub use crate::threads::available as available_threads;
use boundary::{corner, Sample, Tracer};
pub use boundary::{Corner, Shape, Side, ThicknessLimit};
pub use sample::{check_mu_range, mu_grid, sample, CurvePoint};
use transition::Located;

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
    /// Corners (kinks of η_s(μ)), by decreasing μ.
    pub corners: Vec<Corner>,
    /// Smooth pattern changes, by decreasing μ (the asymptote at μ = ∞ of a top branch
    /// whose pattern differs from the infinite-friction one is listed here too).
    pub transitions: Vec<Corner>,
    /// Limit states above the boundary, grouped into branches over the samples.
    pub limit_branches: Vec<LimitBranch>,
    /// Samples that could not be resolved (μ and the reason).
    pub unresolved: Vec<(f64, String)>,
    /// Sampled μ at which the arch stands at every η > 0 (no collapse to find).
    pub no_collapse: Vec<f64>,
    /// Sampled μ at which no thickness stands.
    pub no_equilibrium: Vec<f64>,
    /// Number of η*(μ) solves used.
    pub solves: usize,
    /// Number of boundary samples searched for limit states above η_s.
    pub samples: usize,
    /// Where the static boundary reaches the thickness limit η → 2 (`ETA_TOP`) at a
    /// friction above μ_ms: the arch then needs η ≥ 2 at every μ below it, there is no
    /// purely-sliding corner within 0 < η < 2, and this μ is the least friction at which
    /// the arch stands.
    pub thickness_limit: Option<ThicknessLimit>,
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

/// Traces the limit curve of `arch` on one thread.
pub fn trace(arch: &Arch, settings: &Settings) -> LimitCurve {
    trace_parallel(arch, settings, 1)
}

/// Consecutive coarse samples solved in sequence, each bracketing η_s from its
/// neighbours' (a group is what one thread takes; fixed, so that the work, and with it the
/// answer, does not depend on the thread count).
const SAMPLE_GROUP: usize = 8;

/// [`trace`] with its independent parts on `threads` threads (0 is taken as 1): the groups
/// of coarse samples, the location of each pattern change between them, and the
/// limit-state search at each sample. The curve is the same for every thread count.
pub fn trace_parallel(arch: &Arch, settings: &Settings, threads: usize) -> LimitCurve {
    let mut tr = Tracer::new(arch, settings);
    if let Err(e) = crate::limit::refuse_fill(arch, "the limit curve") {
        tr.unresolved.push((0.0, e.to_string()));
        return without_branches(tr, None, 0);
    }
    let fl: Option<FrictionLimit> = friction_limit(arch, settings).ok().flatten();
    let Some(fl) = fl else {
        return without_branches(tr, None, 0);
    };
    let inf = tr.sample_near(f64::INFINITY, None);
    if inf.is_none() && tr.no_equilibrium.len() == 1 {
        // Admissibility is monotone in μ: if nothing stands at μ = ∞, nothing stands.
        if let Ok(Outcome::NoEquilibrium { .. }) =
            solve(arch, f64::INFINITY, settings).map(|s| s.outcome)
        {
            let solves = tr.solves + 1;
            return without_branches(tr, Some(fl.mu), solves);
        }
    }
    let mus = sample_frictions(arch, &fl, inf.as_ref(), settings);
    let samples = sample_groups(&mut tr, &mus, inf.as_ref(), threads);
    let mut changes = Vec::new();
    // the top: a finite pattern different from the infinite-friction one is asymptotic
    if let (Some(top), Some(inf)) = (samples.first(), inf.as_ref()) {
        if top.sig != inf.sig {
            let at = Located::at(f64::INFINITY, inf, 0.0);
            let mode = tr.mode_of(&inf.pattern);
            let between = [tr.mode_of(&top.pattern), mode];
            let shape = Shape { kink: false, mode };
            changes.push(corner(at, true, [f64::NAN; 2], between, shape));
        }
    }
    changes.extend(locate_changes(&mut tr, &samples, threads));
    let (thickness_limit, lowest) = lowest_end(&mut tr, &fl, &samples);
    changes.extend(lowest);
    changes.sort_by(|a, b| b.mu.total_cmp(&a.mu));
    let changes = merge_duplicates(changes, settings.same_root);
    let branches = branches_between(
        &mut tr,
        &fl,
        &changes,
        &samples,
        inf.as_ref(),
        &thickness_limit,
    );
    let searched = samples.len() + usize::from(inf.is_some());
    let searched_samples: Vec<&Sample> = inf.iter().chain(&samples).collect();
    let searches = crate::threads::map(&searched_samples, threads, |_, s| {
        search_after(&s.solution, settings)
    });
    let (limit_branches, incomplete) =
        limit_branches(&tr, searched_samples.into_iter().zip(searches));
    let mut unresolved = tr.unresolved.clone();
    unresolved.extend(incomplete);
    let (corners, transitions) = changes.into_iter().partition(|c| c.detail.kink);
    LimitCurve {
        mu_ms: Some(fl.mu),
        branches,
        corners,
        transitions,
        limit_branches,
        unresolved,
        no_collapse: tr.no_collapse,
        no_equilibrium: tr.no_equilibrium,
        solves: tr.solves,
        samples: searched,
        thickness_limit,
    }
}

/// One corner for each place: exact corners located from several pairs of samples (where
/// two patterns of one state alternate from sample to sample, e.g. two intrados hinges of a
/// discrete arch tied) agree in μ and η to `same` (relative) and become one, joining the
/// branch above the first to the branch below the last; the zero-width branches between
/// them go. `changes` by decreasing μ.
fn merge_duplicates(changes: Vec<Corner>, same: f64) -> Vec<Corner> {
    let close = |a: f64, b: f64| (a - b).abs() <= same * a.abs().max(b.abs());
    let mut out: Vec<Corner> = Vec::with_capacity(changes.len());
    for c in changes {
        match out.last_mut() {
            Some(p) if p.exact && c.exact && close(p.mu, c.mu) && close(p.t, c.t) => {
                p.sides[0] = c.sides[0];
                p.detail.kink |= c.detail.kink;
            }
            _ => out.push(c),
        }
    }
    out
}

/// The pattern changes of η_s(μ) (corners and smooth transitions) with μ in
/// [`mu_lo`, `mu_hi`], located as [`trace`] locates them between `n` samples geometric over
/// the range, without the limit-state search and without the lowest end: where a branch of
/// limit states above η_s may be born (the atlas samples both sides of each). One thread.
pub fn pattern_changes(
    arch: &Arch,
    (mu_lo, mu_hi): (f64, f64),
    n: usize,
    settings: &Settings,
) -> Vec<Corner> {
    let mut tr = Tracer::new(arch, settings);
    let samples = sample_groups(&mut tr, &geometric_down(mu_lo, mu_hi, n), None, 1);
    let mut changes = locate_changes(&mut tr, &samples, 1);
    changes.retain(|c| c.mu.is_finite());
    changes.sort_by(|a, b| b.mu.total_cmp(&a.mu));
    merge_duplicates(changes, settings.same_root)
}

/// `n` (at least 2) frictions geometric from `hi` down to `lo`.
fn geometric_down(lo: f64, hi: f64, n: usize) -> Vec<f64> {
    let n = n.max(2);
    (0..n)
        .rev()
        .map(|i| lo * (hi / lo).powf(i as f64 / (n - 1) as f64))
        .collect()
}

/// The curve of an arch without branches: no finite μ suffices (`mu_ms` `None`), or
/// nothing stands at any μ.
fn without_branches(tr: Tracer, mu_ms: Option<f64>, solves: usize) -> LimitCurve {
    LimitCurve {
        mu_ms,
        branches: vec![],
        corners: vec![],
        transitions: vec![],
        limit_branches: vec![],
        unresolved: tr.unresolved,
        no_collapse: tr.no_collapse,
        no_equilibrium: tr.no_equilibrium,
        solves,
        samples: 0,
        thickness_limit: None,
    }
}

/// The sampled frictions, by decreasing μ: a geometric grid from just above μ_ms to twice
/// μ_rm (the friction the infinite-friction state needs), or to [`OVERTURNING_SPAN`] times
/// the lower end when that state overturns.
fn sample_frictions(
    arch: &Arch,
    fl: &FrictionLimit,
    inf: Option<&Sample>,
    settings: &Settings,
) -> Vec<f64> {
    let mu_lo = fl.mu * (1.0 + settings.curve_start_rel);
    let mu_rm = inf.map_or(f64::INFINITY, |s| {
        friction_needed(arch, s.eta, &s.x, 2000, settings.detach_rel)
    });
    let mu_hi = if mu_rm.is_finite() {
        (2.0 * mu_rm).max(1.5 * mu_lo)
    } else {
        OVERTURNING_SPAN * mu_lo.max(MU_FLOOR)
    };
    geometric_down(mu_lo, mu_hi, settings.curve_samples)
}

/// η_s at each of `mus`, in fixed groups of [`SAMPLE_GROUP`] on `threads` threads (each
/// sample bracketed from its neighbour in the group; the first group starts from μ = ∞).
fn sample_groups(
    tr: &mut Tracer,
    mus: &[f64],
    inf: Option<&Sample>,
    threads: usize,
) -> Vec<Sample> {
    let (arch, settings) = (tr.arch, tr.settings);
    let groups: Vec<&[f64]> = mus.chunks(SAMPLE_GROUP).collect();
    let solved = crate::threads::map(&groups, threads, |g, group| {
        let mut t = Tracer::new(arch, settings);
        let mut got: Vec<Sample> = Vec::new();
        for &mu in *group {
            // the first group starts from μ = ∞, the others from the whole range
            let guess = next_guess(&got, inf.filter(|_| g == 0));
            if let Some(s) = t.sample_near(mu, guess) {
                got.push(s);
            }
        }
        (got, t)
    });
    let mut samples: Vec<Sample> = Vec::new();
    for (got, t) in solved {
        samples.extend(got);
        tr.absorb(t);
    }
    samples
}

/// Every pattern change between neighbouring samples, each located on its own thread.
fn locate_changes(tr: &mut Tracer, samples: &[Sample], threads: usize) -> Vec<Corner> {
    let (arch, settings) = (tr.arch, tr.settings);
    let pairs: Vec<(&Sample, &Sample)> = samples
        .windows(2)
        .map(|w| (&w[0], &w[1]))
        .filter(|(a, b)| a.sig != b.sig)
        .collect();
    let located = crate::threads::map(&pairs, threads, |_, (a, b)| {
        let mut t = Tracer::new(arch, settings);
        (t.locate(a, b, 24), t)
    });
    let mut changes = Vec::new();
    for (found, t) in located {
        changes.extend(found);
        tr.absorb(t);
    }
    changes
}

/// Where the lowest branch ends: at the corner with the vertical purely-sliding branch
/// (slope −∞ on its left), or — when samples above μ_ms have no equilibrium at any
/// η < 2 (η_ms would be ≥ 2) — where η_s reaches the thickness limit.
fn lowest_end(
    tr: &mut Tracer,
    fl: &FrictionLimit,
    samples: &[Sample],
) -> (Option<ThicknessLimit>, Option<Corner>) {
    let (arch, settings) = (tr.arch, tr.settings);
    let Some(low) = samples.last() else {
        return (None, None);
    };
    let no_eq_above = tr
        .no_equilibrium
        .iter()
        .copied()
        .filter(|&m| m > fl.mu && m < low.mu)
        .reduce(f64::max);
    if let Some(ne) = no_eq_above {
        let start = (low.x, low.eta, low.mu);
        let limit = match onset::reach_eta(arch, &low.pattern, start, ne, ETA_TOP, settings) {
            Some(o) => ThicknessLimit {
                mu: o.mu,
                eta: o.eta,
                pattern: o.pattern,
                exact: true,
            },
            None => tr.thickness_limit_by_bisection(ne, low),
        };
        return (Some(limit), None);
    }
    let between = [tr.mode_of(&low.pattern), CollapseMode::PurelySliding];
    let start = (low.x, low.eta, low.mu);
    let range = (fl.mu * (1.0 - settings.root_slack), low.mu);
    let c = tr
        .union_newton(&low.pattern, &fl.pattern, start, range, between, true)
        .or_else(|| tr.follow_to_mu_ms(low, fl.mu, between))
        .map(|mut c| {
            c.detail.kink = true;
            c
        })
        .unwrap_or_else(|| {
            let slopes = [f64::NEG_INFINITY, tr.slope(low.mu, low.eta, 1.0).0];
            let at = Located {
                pattern: fl.pattern.clone(),
                ..Located::at(fl.mu, low, f64::NAN)
            };
            let mode = CollapseMode::PurelySliding;
            corner(at, false, slopes, between, Shape { kink: true, mode })
        });
    (None, Some(c))
}

/// The branches between consecutive pattern changes (`changes` by decreasing μ), each
/// named from a sample inside it (solved once inside where two changes fall between
/// neighbouring samples), then the lowest: to the thickness limit, or the vertical
/// purely-sliding branch.
fn branches_between(
    tr: &mut Tracer,
    fl: &FrictionLimit,
    changes: &[Corner],
    samples: &[Sample],
    inf: Option<&Sample>,
    thickness_limit: &Option<ThicknessLimit>,
) -> Vec<Branch> {
    let mut branches = Vec::new();
    let mut upper = (f64::INFINITY, inf.map_or(f64::NAN, |s| s.eta));
    let finite: Vec<&Corner> = changes.iter().filter(|c| c.mu.is_finite()).collect();
    for c in &finite {
        let members: Vec<Sample> = samples
            .iter()
            .filter(|s| s.mu < upper.0 && s.mu > c.mu)
            .cloned()
            .collect();
        // two changes between neighbouring samples: solve once inside the branch
        let rep = match members.get(members.len() / 2) {
            Some(r) => Some(r.clone()),
            None if upper.0.is_finite() => tr.sample_near(
                (upper.0 * c.mu).sqrt(),
                Some(boundary::between(upper.1, c.t)),
            ),
            None => None,
        };
        if let Some(rep) = rep {
            branches.push(Branch {
                mode: tr.mode_of(&rep.pattern),
                mu_min: c.mu,
                mu_max: upper.0,
                eta_min: upper.1,
                eta_max: c.t,
                pattern: rep.pattern.clone(),
            });
        }
        upper = (c.mu, c.t);
    }
    if let (Some(t), Some(low)) = (thickness_limit, samples.last()) {
        branches.push(Branch {
            mode: tr.mode_of(&low.pattern),
            mu_min: t.mu,
            mu_max: upper.0,
            eta_min: upper.1,
            eta_max: t.eta,
            pattern: low.pattern.clone(),
        });
    } else if let Some(last) = finite.last() {
        branches.push(Branch {
            mode: CollapseMode::PurelySliding,
            mu_min: fl.mu,
            mu_max: fl.mu,
            eta_min: last.t,
            eta_max: f64::INFINITY,
            pattern: fl.pattern.clone(),
        });
    }
    branches
}

/// A branch of limit states above the static boundary: consecutive samples (by
/// decreasing μ) each with a limit state above η_s of one pattern signature and mode.
/// Its ends are those of the samples, not located exactly.
#[derive(Debug, Clone)]
pub struct LimitBranch {
    /// Mode, the sampled μ range (`mu_max` ∞ when found at μ = ∞), the least and
    /// greatest η over the samples, and the pattern at the sample of greatest μ.
    pub branch: Branch,
    /// Samples on the branch.
    pub samples: usize,
}

/// The limit states above η_s at each sample, grouped into branches, and the samples
/// whose search could not be completed (μ and why: listed as unresolved).
fn limit_branches<'a>(
    tr: &Tracer,
    samples: impl Iterator<Item = (&'a Sample, Result<LimitStates, Undecided>)>,
) -> (Vec<LimitBranch>, Vec<(f64, String)>) {
    let mut open: Vec<(boundary::Signature, LimitBranch, bool)> = Vec::new();
    let mut done: Vec<LimitBranch> = Vec::new();
    let mut incomplete = Vec::new();
    for (s, search) in samples {
        let above = match search {
            Ok(ls) => ls.above,
            Err(e) => {
                incomplete.push((
                    s.mu,
                    format!("the search for limit states above eta_s is incomplete: {e}"),
                ));
                Vec::new()
            }
        };
        for o in open.iter_mut() {
            o.2 = false;
        }
        for st in above {
            let sig = boundary::signature(tr.arch, &st.pattern);
            let mode = tr.mode_of(&st.pattern);
            match open
                .iter_mut()
                .find(|o| o.0 == sig && o.1.branch.mode == mode && !o.2)
            {
                Some(o) => {
                    let b = &mut o.1.branch;
                    b.mu_min = s.mu;
                    b.eta_min = b.eta_min.min(st.t);
                    b.eta_max = b.eta_max.max(st.t);
                    o.1.samples += 1;
                    o.2 = true;
                }
                None => open.push((
                    sig,
                    LimitBranch {
                        branch: Branch {
                            mode,
                            mu_min: s.mu,
                            mu_max: s.mu,
                            eta_min: st.t,
                            eta_max: st.t,
                            pattern: st.pattern.clone(),
                        },
                        samples: 1,
                    },
                    true,
                )),
            }
        }
        // branches not continued at this sample end
        let (cont, ended): (Vec<_>, Vec<_>) = open.into_iter().partition(|o| o.2);
        done.extend(ended.into_iter().map(|o| o.1));
        open = cont;
    }
    done.extend(open.into_iter().map(|o| o.1));
    done.sort_by(|a, b| b.branch.mu_max.total_cmp(&a.branch.mu_max));
    (done, incomplete)
}

/// Where η_s is expected at the next (smaller) μ of the coarse sampling: the last sample's
/// η extrapolated linearly from the two before it, within the last step's change (at least
/// 10⁻³ of η); from the sample at μ = ∞ (equal to it above the friction a pattern needs)
/// for the first.
fn next_guess(samples: &[Sample], inf: Option<&Sample>) -> Option<RootGuess> {
    match samples {
        [.., p, q] => {
            let step = q.eta - p.eta;
            let eta = q.eta + step;
            Some(RootGuess {
                eta,
                rel: (2.0 * step.abs() / eta).max(1e-3),
            })
        }
        [q] => Some(RootGuess {
            eta: q.eta,
            rel: 1e-2,
        }),
        [] => inf.map(|s| RootGuess {
            eta: s.eta,
            rel: 1e-3,
        }),
    }
}
