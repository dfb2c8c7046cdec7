//! The λ–μ curve at fixed η: the answer of [`survey_partial`] at sampled friction coefficients, and
//! its **corners** — the friction coefficients where the collapse pattern changes — located
//! by bisection on the answer itself down to adjacent floating-point numbers in μ (the load
//! problem's part of the [`crate::tracer`]).
//!
//! A *branch* is a range of μ on which the least limit state keeps its pattern (contacts,
//! kinds, sides of a loaded section; the tangency angles of a continuous arch move with μ),
//! and whether it is the static maximum or lies below it. Between two samples on different
//! branches the answer is evaluated at the midpoint (geometric while the ends are more than a
//! factor 2 apart) until the two ends are neighbouring floats; a third branch met on the
//! way is bracketed in turn. The bracket is exact in μ: the answer of the survey at each end
//! is the one reported. Along a branch λ(μ) is smooth; at a corner it is continuous (two
//! limit states cross) or jumps (a limit state appears or vanishes — non-associative
//! friction opens or closes a window below the static maximum; the arch starts or stops
//! standing). A branch shorter than the sampling step between two samples on one branch is
//! not seen: sample densely where that matters.

use super::continuum;
use super::outcome::{LoadAnswer, LoadOutcome};
use super::survey::{below, survey_partial};
use crate::arch::{Arch, InputError, JointLayout};
use crate::contact::{Contact, ContactKind, Location};
use crate::family::{self, Family};
use crate::load::{rows, LiveLoad, LoadRow, Side};
use crate::refine::{self, Objective, Start, Unknowns};
use crate::settings::Settings;
use crate::statics::{magnitude, Reactions};
use crate::tracer::{self, Split};

/// One sample of the λ–μ curve: μ and the answer there (`Err`: no decision, why).
pub type CurveSample = (f64, LoadAnswer);

/// The answer at each friction coefficient of `mus` (any order; μ = ∞ allowed): the λ–μ
/// curve at fixed η, sampled. `progress(done, total)` is called after each sample.
pub fn sample(
    arch: &Arch,
    eta: f64,
    load: &LiveLoad,
    mus: &[f64],
    settings: &Settings,
    progress: &dyn Fn(usize, usize),
) -> Result<Vec<CurveSample>, InputError> {
    let mut out = Vec::with_capacity(mus.len());
    for (i, &mu) in mus.iter().enumerate() {
        out.push((mu, survey_partial(arch, eta, mu, load, settings)?));
        progress(i + 1, mus.len());
    }
    Ok(out)
}

/// One contact of a branch's pattern: its kind, location, side of a loaded section, and
/// its angle where the angle is fixed (a joint of a discrete arch, a springing, a point
/// load's section), `None` for a tangency of a continuous arch (it moves with μ).
pub type BranchContact = (ContactKind, Location, Side, Option<u64>);

/// What stays the same along a branch of the λ–μ curve.
#[derive(Debug, Clone, PartialEq)]
pub enum BranchKey {
    /// No state is admissible at any λ ≥ 0.
    NoEquilibrium,
    /// λ is unbounded and no limit state exists.
    NoCollapse,
    /// No decision at this μ.
    Unresolved,
    /// Admissible states but no limit state at all (the static maximum has no mechanism
    /// with positive live power and none lies below).
    NoLimitState,
    /// The least limit state's pattern, and whether it is the static maximum.
    Collapse {
        /// Contacts of the least limit state, by increasing β.
        pattern: Vec<BranchContact>,
        /// The least limit state is the static maximum (no reduction).
        at_static: bool,
    },
}

/// The branch an answer belongs to.
pub fn branch_key(
    arch: &Arch,
    load: &LiveLoad,
    answer: &LoadAnswer,
    settings: &Settings,
) -> BranchKey {
    let sv = match answer {
        Err(_) => return BranchKey::Unresolved,
        Ok(LoadOutcome::NoEquilibrium) => return BranchKey::NoEquilibrium,
        Ok(LoadOutcome::NoCollapse { .. }) => return BranchKey::NoCollapse,
        Ok(LoadOutcome::Limits(sv)) => sv,
    };
    let Some(least) = sv.limit_states.first() else {
        return BranchKey::NoLimitState;
    };
    let discrete = matches!(arch.layout(), JointLayout::Discrete(_));
    let loaded = match *load {
        LiveLoad::Point { beta } => Some(beta),
        LiveLoad::Horizontal { .. } | LiveLoad::Pressure(_) => None,
    };
    let pattern = least
        .pattern
        .iter()
        .zip(&least.sides)
        .map(|(c, s)| {
            let fixed = discrete || c.at == Location::Springing || Some(c.beta) == loaded;
            (c.kind, c.at, *s, fixed.then_some(c.beta.to_bits()))
        })
        .collect();
    let at_static = sv
        .lambda_static
        .is_some_and(|(top, _)| !below(least.t, top, settings));
    BranchKey::Collapse { pattern, at_static }
}

/// A corner of the λ–μ curve (`t` is λ): the branch changes between two friction
/// coefficients. Its sides are the samples just below and just above (μ and the answer;
/// μ = ∞ above when the last branch is the associative one itself). It is `exact` where the
/// branches on both sides meet at one degenerate state: five activation functions vanish
/// at one state (x, λ) at one friction coefficient μ (five equations in h, v, w, λ, μ),
/// solved by Newton from the bisection's state and checked admissible at every joint (the
/// survey's active-set tolerance makes such a meeting look like a narrow band of μ,
/// relative width ~1e-8, where all five contacts appear active; this is its exact point).
/// Its pattern is then the five contacts active there (with the side of a loaded section),
/// or the four sliding ones of two faces of states along w at λ_static (w is then the
/// middle of the face at the corner). Where the change is not such a meeting (or not on a
/// discrete arch) the bracket is the answer: μ is its lower end, λ NaN, the pattern empty.
pub type Corner = tracer::Corner<CurveSample, (Contact, Side), Bracket>;

/// How a [`Corner`] of the λ–μ curve was bracketed.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Bracket {
    /// Whether the bisection ended on neighbouring floats (false: it stopped at its
    /// evaluation budget).
    pub bracketed: bool,
    /// How many changes of branch the bisection bracketed here: 1 for a simple corner;
    /// more for a cluster (changes within `CLUSTER_REL` of each other), which is one
    /// exact corner seen through the survey's tolerance, or — when not exact — a stretch
    /// where the answer flickers (near a singularity, e.g. λ growing without bound), whose
    /// ends are the sides.
    pub changes: usize,
    /// At an exact corner, λ is continuous across it: each side's least limit state is on
    /// its five contacts, or its λ is the corner's to `SAME_LAMBDA` (else a limit state
    /// appears or vanishes there and λ jumps).
    pub continuous: bool,
}

impl Corner {
    /// The sample just below the corner.
    pub fn below(&self) -> &CurveSample {
        &self.sides[0]
    }
    /// The sample just above the corner.
    pub fn above(&self) -> &CurveSample {
        &self.sides[1]
    }
    /// The collapse multipliers on both sides, when both exist.
    pub fn lambdas(&self) -> (Option<f64>, Option<f64>) {
        let l = |a: &LoadAnswer| match a {
            Ok(LoadOutcome::Limits(sv)) => sv.lambda(),
            _ => None,
        };
        (l(&self.sides[0].1), l(&self.sides[1].1))
    }
    /// λ is continuous across the corner: at an exact corner, both sides' least limit
    /// states lie on its five contacts; else both sides have a collapse multiplier, equal to
    /// `tol` relative (the bracket is then two neighbouring floats), or to `SAME_LAMBDA` at
    /// least across a cluster.
    pub fn continuous(&self, tol: f64) -> bool {
        if self.exact {
            return self.detail.continuous;
        }
        // a cluster spans the survey's tolerance band (~1e-8 in μ), across which λ moves
        let tol = if self.detail.changes > 1 {
            tol.max(SAME_LAMBDA)
        } else {
            tol
        };
        match self.lambdas() {
            (Some(a), Some(b)) => (a - b).abs() <= tol * a.abs().max(b.abs()).max(1.0),
            _ => false,
        }
    }
}

/// A change known only to lie between the samples `below` and `above`.
fn bracket(below: CurveSample, above: CurveSample, bracketed: bool, changes: usize) -> Corner {
    Corner {
        mu: below.0,
        t: f64::NAN,
        x: [f64::NAN; 3],
        pattern: Vec::new(),
        exact: false,
        residual: f64::NAN,
        sides: [below, above],
        detail: Bracket {
            bracketed,
            changes,
            continuous: false,
        },
    }
}

/// The sampled λ–μ curve and its corners.
#[derive(Debug, Clone)]
pub struct LoadCurve {
    /// The samples, by increasing μ (μ = ∞ last, when sampled).
    pub samples: Vec<CurveSample>,
    /// The corners between them, by increasing μ.
    pub corners: Vec<Corner>,
}

/// At most this many survey evaluations per bracket of two samples.
const MAX_EVALUATIONS: usize = 4000;
/// At most this many corners between two samples.
const MAX_CORNERS: usize = 64;
/// The search for the last corner below μ = ∞ stops at this friction coefficient.
const LARGE_MU: f64 = 1e12;

/// The load problem's part of the tracer: the answer of [`survey_partial`] at one (η, load),
/// keyed by [`branch_key`], bisected on the key to neighbouring floats within a budget of
/// evaluations; the exact corner is solved afterwards, per cluster of changes.
struct Bisection<'a> {
    arch: &'a Arch,
    eta: f64,
    load: &'a LiveLoad,
    settings: &'a Settings,
    /// Survey evaluations left for the current bracket of two samples.
    budget: usize,
    /// Corners bracketed so far in the current list.
    found: usize,
}

impl Bisection<'_> {
    fn at(&self, mu: f64) -> Result<CurveSample, InputError> {
        Ok((
            mu,
            survey_partial(self.arch, self.eta, mu, self.load, self.settings)?,
        ))
    }

    /// A finite μ on the associative branch of `inf` above `lo`: μ_lo × 10^k up to
    /// `LARGE_MU`, else (`Err`) the last sample tried.
    fn associative(
        &self,
        lo: &CurveSample,
        inf: &CurveSample,
    ) -> Result<Result<CurveSample, CurveSample>, InputError> {
        use tracer::Problem;
        let mut last = lo.clone();
        while last.0 < LARGE_MU {
            let s = self.at((last.0 * 10.0).min(LARGE_MU))?;
            if self.key(&s) == self.key(inf) {
                return Ok(Ok(s));
            }
            last = s;
        }
        Ok(Err(last))
    }
}

/// On a continuous arch (where each survey is costly) a bracket this narrow (relative) is
/// not bisected further when its two ends already solve the corner exactly.
const EARLY_REL: f64 = 1e-9;

impl Bisection<'_> {
    /// Whether the bracket (`lo`, `hi`) of a continuous arch is narrow and its ends give an
    /// exact corner (which the clustering then solves again, with every change found).
    fn solved_early(&self, lo: &CurveSample, hi: &CurveSample) -> bool {
        matches!(self.arch.layout(), JointLayout::Continuous)
            && hi.0 - lo.0 <= EARLY_REL * hi.0
            && exact_corner(self, &[lo, hi], &bracket(lo.clone(), hi.clone(), false, 1)).is_some()
    }
}

impl tracer::Problem for Bisection<'_> {
    type Sample = CurveSample;
    type Key = BranchKey;
    type Corner = Corner;
    type Error = InputError;

    fn key(&self, s: &CurveSample) -> BranchKey {
        branch_key(self.arch, self.load, &s.1, self.settings)
    }

    /// The midpoint (geometric while the ends are more than a factor 2 apart), until the
    /// ends are neighbouring floats, the budget is spent or `MAX_CORNERS` are found.
    fn split(&mut self, lo: &CurveSample, hi: &CurveSample, _: usize) -> Split {
        let mid = if hi.0 > 2.0 * lo.0 && lo.0 > 0.0 {
            (lo.0 * hi.0).sqrt()
        } else {
            lo.0 + 0.5 * (hi.0 - lo.0)
        };
        let tight = mid <= lo.0 || mid >= hi.0;
        if tight || self.budget == 0 || self.found >= MAX_CORNERS {
            return Split::Stop { tight };
        }
        if self.solved_early(lo, hi) {
            return Split::Stop { tight: false };
        }
        self.budget -= 1;
        Split::At(mid)
    }

    fn sample(
        &mut self,
        mu: f64,
        _: &CurveSample,
        _: &CurveSample,
    ) -> Result<Option<CurveSample>, InputError> {
        self.at(mu).map(Some)
    }

    fn exact(&mut self, _: &CurveSample, _: &CurveSample) -> Option<Corner> {
        None
    }

    fn bracketed(&mut self, lo: &CurveSample, hi: &CurveSample, tight: bool) -> Corner {
        self.found += 1;
        bracket(lo.clone(), hi.clone(), tight, 1)
    }
}

/// The λ–μ curve: the samples at `mus` (sorted by increasing μ, μ = ∞ allowed) and every
/// corner between two samples on different branches, bisected to neighbouring floats. When
/// the last finite sample and μ = ∞ differ, the μ above which the answer is the associative
/// one is looked for up to μ = 1e12. `progress(done, total)` counts the samples, then the
/// brackets bisected.
pub fn trace(
    arch: &Arch,
    eta: f64,
    load: &LiveLoad,
    mus: &[f64],
    settings: &Settings,
    progress: &dyn Fn(usize, usize),
) -> Result<LoadCurve, InputError> {
    use tracer::Problem;
    let mut mus = mus.to_vec();
    mus.sort_by(f64::total_cmp);
    mus.dedup();
    // the samples count against at most as many brackets as gaps between them; the total
    // shrinks to the brackets there are once the samples are in
    let most = 2 * mus.len().max(1) - 1;
    let samples = sample(arch, eta, load, &mus, settings, &|d, _| progress(d, most))?;
    let mut p = Bisection {
        arch,
        eta,
        load,
        settings,
        budget: 0,
        found: 0,
    };
    let mut corners = Vec::new();
    // progress goes on over the brackets to bisect: each is one more unit of work
    let changes: Vec<bool> = samples
        .windows(2)
        .map(|w| p.key(&w[0]) != p.key(&w[1]))
        .collect();
    let total = samples.len() + changes.iter().filter(|&&c| c).count();
    if total == samples.len() {
        progress(total, total);
    }
    let brackets = samples.windows(2).zip(&changes).filter(|(_, &c)| c);
    for (k, (w, _)) in brackets.enumerate() {
        let (lo, hi) = (&w[0], &w[1]);
        let at = samples.len() + k + 1;
        let report = move || progress(at, total);
        let _finished = Finished(&report);
        let hi = if hi.0.is_finite() {
            hi.clone()
        } else {
            match p.associative(lo, hi)? {
                Ok(s) => s,
                Err(last) => {
                    corners.push(bracket(last, hi.clone(), false, 1));
                    continue;
                }
            }
        };
        (p.budget, p.found) = (MAX_EVALUATIONS, 0);
        let mut found = tracer::locate(&mut p, lo, &hi, usize::MAX)?;
        // a short branch beside a corner (between the bisection's points) shows 1e-6 away:
        // bracket it too
        p.found = 0;
        let mut extra = Vec::new();
        for c in &found {
            for (probe, side) in [
                (c.below().0 * (1.0 - PROBE_REL), c.below()),
                (c.above().0 * (1.0 + PROBE_REL), c.above()),
            ] {
                if probe <= lo.0 || probe >= hi.0 {
                    continue;
                }
                let q = p.at(probe)?;
                if p.key(&q) != p.key(side) {
                    let (a, b) = if probe < side.0 {
                        (&q, side)
                    } else {
                        (side, &q)
                    };
                    extra.extend(tracer::locate(&mut p, a, b, usize::MAX)?);
                }
            }
        }
        found.extend(extra);
        found.sort_by(|a, b| a.below().0.total_cmp(&b.below().0));
        found.dedup_by(|a, b| a.below().0 == b.below().0 && a.above().0 == b.above().0);
        corners.extend(clusters(&p, found));
    }
    corners.sort_by(|a, b| a.below().0.total_cmp(&b.below().0));
    Ok(LoadCurve { samples, corners })
}

/// Calls its function when dropped: a bracket's progress is reported however it ends.
struct Finished<'a>(&'a dyn Fn());

impl Drop for Finished<'_> {
    fn drop(&mut self) {
        (self.0)();
    }
}

/// Across an exact corner the two sides' λ (at the ends of the survey's tolerance band,
/// ~1e-8 wide in μ) are the corner's own to this relative tolerance when λ is continuous
/// (a limit state on a contact outside the five met there).
const SAME_LAMBDA: f64 = 1e-6;

/// Two rows that agree to this relative tolerance in every coefficient are one function
/// (the extrados hinge rows on both sides of a loaded section differ in the last bits only).
const TWIN_REL: f64 = 1e-13;

/// Each corner's neighbourhood is probed this far away (relative in μ) for a short branch.
const PROBE_REL: f64 = 1e-6;

/// Changes of branch closer than this (relative in μ) are one corner seen through the
/// survey's active-set tolerance.
const CLUSTER_REL: f64 = 1e-6;

/// Groups the bisected changes of branch into corners: consecutive changes within
/// `CLUSTER_REL` are one corner, solved exactly where their patterns meet at one degenerate
/// state (see [`Corner`]).
fn clusters(p: &Bisection, found: Vec<Corner>) -> Vec<Corner> {
    let mut out: Vec<Corner> = Vec::new();
    let mut group: Vec<Corner> = Vec::new();
    let flush = |group: &mut Vec<Corner>, out: &mut Vec<Corner>| {
        let (Some(first), Some(last)) = (group.first(), group.last()) else {
            return;
        };
        let mut inner: Vec<&CurveSample> = vec![first.below()];
        inner.extend(group.iter().map(|c| c.above()));
        let bracketed = group.iter().all(|c| c.detail.bracketed);
        let c = bracket(
            first.below().clone(),
            last.above().clone(),
            bracketed,
            group.len(),
        );
        out.push(exact_corner(p, &inner, &c).unwrap_or(c));
        group.clear();
    };
    for c in found {
        if let Some(prev) = group.last() {
            if c.below().0 > prev.above().0 + CLUSTER_REL * prev.above().0.abs() {
                flush(&mut group, &mut out);
            }
        }
        group.push(c);
    }
    flush(&mut group, &mut out);
    out
}

/// Contacts with the side of a loaded section.
type Pattern = Vec<(Contact, Side)>;

/// A least limit state: (λ, x, pattern).
type LeastState = (f64, Reactions, Vec<(Contact, Side)>);

fn least(answer: &LoadAnswer) -> Option<LeastState> {
    let Ok(LoadOutcome::Limits(sv)) = answer else {
        return None;
    };
    let l = sv.limit_states.first()?;
    Some((
        l.t,
        l.x,
        l.pattern
            .iter()
            .copied()
            .zip(l.sides.iter().copied())
            .collect(),
    ))
}

/// The corner `bracket` made exact: Newton on five activation functions in (h, v, w, λ, μ)
/// — the union of the least limit states' patterns of `answers` (samples across one corner,
/// by increasing μ) — from the state of the answer with the most contacts; kept when it
/// converges inside the answers' μ-range (widened by `CLUSTER_REL`), to a state admissible
/// at every joint.
fn exact_corner(p: &Bisection, answers: &[&CurveSample], bracket: &Corner) -> Option<Corner> {
    let (arch, eta, load, settings) = (p.arch, p.eta, p.load, p.settings);
    let joints = match arch.layout() {
        JointLayout::Discrete(joints) => Some(joints),
        JointLayout::Continuous => None,
    };
    let (mu_lo, mu_hi) = (answers.first()?.0, answers.last()?.0);
    if !mu_hi.is_finite() {
        return None;
    }
    let states: Vec<(f64, f64, Reactions, Pattern)> = answers
        .iter()
        .filter_map(|(mu, a)| least(a).map(|(l, x, p)| (*mu, l, x, p)))
        .collect();
    let start = states.iter().max_by_key(|s| s.3.len())?;
    let family = family::Load { arch, eta, load };
    // a contact's row in a list of the arch's rows at one μ
    let row_in = |list: &[LoadRow], c: &Contact, side: Side| -> Option<LoadRow> {
        list.iter()
            .copied()
            .find(|r| r.contact.beta == c.beta && r.contact.kind == c.kind && r.side == side)
    };
    let at_start = joints.map(|js| rows(arch, js, eta, start.0, load));
    // a contact's activation function at the start's μ, as (h, v, w, λ) coefficients and a
    // constant: a joint's row, or on the continuous arch the function at its angle
    let row_of = |c: &Contact, side: Side| -> Option<([f64; 4], f64)> {
        match &at_start {
            Some(list) => row_in(list, c, side).map(|r| (r.a, r.c)),
            None => Some(
                family
                    .local(c.kind, c.beta, side, start.1, start.0)
                    .coefficients(0),
            ),
        }
    };
    // distinct activation functions (the extrados hinge on both sides of a loaded
    // section is one)
    let distinct = |pats: &[&Vec<(Contact, Side)>]| -> Option<Vec<(Contact, Side)>> {
        let mut union: Vec<(Contact, Side)> = Vec::new();
        for p in pats {
            for &(c, side) in p.iter() {
                let (ra, rc) = row_of(&c, side)?;
                // one function to rounding (the extrados hinge rows on both sides of a
                // loaded section differ in the last bits only)
                let close =
                    |p: f64, q: f64| (p - q).abs() <= TWIN_REL * (1.0 + p.abs().max(q.abs()));
                let same = union.iter().any(|&(d, t)| {
                    d.kind == c.kind
                        && row_of(&d, t).is_some_and(|(qa, qc)| {
                            (0..4).all(|k| close(qa[k], ra[k])) && close(qc, rc)
                        })
                });
                if !same {
                    union.push((c, side));
                }
            }
        }
        Some(union)
    };
    // the pattern of five: the largest single pattern, or the union of the two ends, or of all
    let ends = [&states.first()?.3, &states.last()?.3];
    let all: Vec<&Vec<(Contact, Side)>> = states.iter().map(|s| &s.3).collect();
    let candidates = [distinct(&[&start.3])?, distinct(&ends)?, distinct(&all)?];
    // four sliding rows (w enters none of them): the least states are faces of states along
    // w at λ_static, and the corner is where the two faces' rows meet, four equations in
    // (h, v, λ, μ); w is held at the start's (inside the face) and then centred in the band
    // the other rows leave it
    let w_free = |u: &[(Contact, Side)]| {
        joints.is_some()
            && u.iter()
                .all(|(c, side)| row_of(c, *side).is_some_and(|r| r.0[2] == 0.0))
    };
    let union = candidates
        .into_iter()
        .find(|u| u.len() == 5 || (u.len() == 4 && w_free(u)))?;
    let size = union.len();
    let on_union =
        |p: &Vec<(Contact, Side)>| distinct(&[&union, p]).is_some_and(|u| u.len() == size);
    let continuous_at = |s: &(f64, f64, Reactions, Pattern), lambda: f64| {
        on_union(&s.3) || (s.1 - lambda).abs() <= SAME_LAMBDA * (1.0 + lambda.abs())
    };
    // the one Newton in (h, v, w, λ, μ) and the free angles of a continuous arch's
    // tangencies; with four sliding rows (no w in any) its minimum-norm steps leave w at
    // the start's
    let from = Start {
        x: start.2,
        t: start.1,
        mu: start.0,
    };
    let r = refine::solve(
        &family,
        &union,
        from,
        Unknowns::TMu,
        Objective::Least,
        settings,
    )
    .ok()?;
    let (mu, lambda, mut x) = (r.mu, r.t, r.x);
    let widen = CLUSTER_REL * mu_hi;
    if mu < mu_lo - widen || mu > mu_hi + widen {
        return None;
    }
    let admissible = corner_admissible(p, joints, size == 4, (mu, lambda), &mut x);
    let continuous =
        continuous_at(states.first()?, lambda) && continuous_at(states.last()?, lambda);
    admissible.then(|| Corner {
        mu,
        t: lambda,
        x,
        pattern: union,
        exact: true,
        residual: r.residual,
        sides: bracket.sides.clone(),
        detail: Bracket {
            continuous,
            ..bracket.detail
        },
    })
}

/// Whether a corner's state (x at (μ, λ)) is admissible: at every joint to the survey's
/// event tolerance (w first centred in its band when `w_free`: four sliding rows), or over
/// the whole continuous arch, as its refined states are checked.
fn corner_admissible(
    p: &Bisection,
    joints: Option<&Vec<f64>>,
    w_free: bool,
    (mu, lambda): (f64, f64),
    x: &mut Reactions,
) -> bool {
    let (arch, eta, load, settings) = (p.arch, p.eta, p.load, p.settings);
    let Some(js) = joints else {
        return continuum::admissible((arch, eta, load), mu, x, lambda, settings);
    };
    let at_mu = rows(arch, js, eta, mu, load);
    if w_free {
        centre_w(&at_mu, x, lambda);
    }
    at_mu.iter().all(|r| {
        let size =
            magnitude(r.contact.kind, eta, mu, x, settings.magnitude_floor) * (1.0 + lambda.abs());
        r.at(x, lambda) <= settings.event_tol * size
    })
}

/// w in the middle of the band that the rows containing it leave at (x, λ), where the
/// corner's rows (four sliding ones) do not fix it.
fn centre_w(rows: &[LoadRow], x: &mut Reactions, lambda: f64) {
    let (mut lo, mut hi) = (f64::NEG_INFINITY, f64::INFINITY);
    for r in rows.iter().filter(|r| r.a[2] != 0.0) {
        let bound = -(r.a[0] * x[0] + r.a[1] * x[1] + r.a[3] * lambda + r.c) / r.a[2];
        if r.a[2] > 0.0 {
            hi = hi.min(bound);
        } else {
            lo = lo.max(bound);
        }
    }
    if lo.is_finite() && hi.is_finite() && lo <= hi {
        x[2] = 0.5 * (lo + hi);
    }
}
