//! One column of the atlas: an opening α, its μ_ms, the samples in μ classified, the changes
//! of kind located by bisection, and the runs of one kind they bound.

use super::certified::states_kind;
use super::classify::{classify, classify_states, Classified, Kind};
use crate::arch::{Arch, InputError, JointLayout, WeightModel};
use crate::friction::friction_limit;
use crate::limit_curve::pattern_changes;
use crate::limit_states::{branch_end, follow, lost_at, BranchEnd, LimitState};
use crate::settings::Settings;

/// What the atlas covers.
#[derive(Debug, Clone, Copy)]
pub struct Rectangle {
    /// The least opening (radians).
    pub alpha_min: f64,
    /// The largest opening.
    pub alpha_max: f64,
    /// μ runs from μ_ms(α) to this times μ_ms(α).
    pub mu_max_factor: f64,
    /// Where the weight acts.
    pub weight: WeightModel,
    /// Equal voussoirs, or a continuous arch.
    pub blocks: Option<usize>,
    /// Columns (openings), evenly spaced, ≥ 2.
    pub columns: usize,
    /// Samples of μ per column, ≥ 2.
    pub samples: usize,
    /// Certify (and verify) the ends of every located bracket and one sample per run.
    pub certify: bool,
}

impl Rectangle {
    /// The arch of opening `alpha`.
    pub fn arch(&self, alpha: f64) -> Result<Arch, InputError> {
        let a = Arch::symmetric(alpha, self.weight)?;
        match self.blocks {
            Some(n) => a.with_blocks(n),
            None => Ok(a),
        }
    }

    /// The openings of the columns.
    pub fn alphas(&self) -> Vec<f64> {
        let n = self.columns.max(2);
        (0..n)
            .map(|k| self.alpha_min + (self.alpha_max - self.alpha_min) * k as f64 / (n - 1) as f64)
            .collect()
    }

    /// The μ samples of a column whose μ_ms is `mu_ms`: μ_ms (1 + d), d geometric from
    /// [`FIRST_OFFSET`] to K − 1.
    pub fn mus(&self, mu_ms: f64) -> Vec<f64> {
        let n = self.samples.max(2);
        let top = self.mu_max_factor - 1.0;
        (0..n)
            .map(|j| {
                let d = FIRST_OFFSET * (top / FIRST_OFFSET).powf(j as f64 / (n - 1) as f64);
                mu_ms * (1.0 + d)
            })
            .collect()
    }

    /// Checks the ranges, naming the argument.
    pub fn check(&self) -> Result<(), InputError> {
        let bad = |arg: &'static str, value: f64, range: &str| InputError::OutOfRange {
            arg,
            value: crate::arch::fmt_value(value),
            range: range.into(),
        };
        for (arg, a) in [
            ("--alpha-min", self.alpha_min),
            ("--alpha-max", self.alpha_max),
        ] {
            if a.is_nan() || a.abs() >= std::f64::consts::FRAC_PI_2 {
                return Err(bad(arg, a, "(-pi/2, pi/2) radians"));
            }
        }
        if self.alpha_max.is_nan() || self.alpha_max <= self.alpha_min {
            return Err(bad("--alpha-max", self.alpha_max, "above --alpha-min"));
        }
        if !(self.mu_max_factor > 1.0 + 10.0 * FIRST_OFFSET && self.mu_max_factor <= 1e6) {
            return Err(bad("--mu-max-factor", self.mu_max_factor, "(1.00001, 1e6]"));
        }
        if !(2..=2000).contains(&self.columns) {
            return Err(bad(
                "--columns",
                self.columns as f64,
                "whole numbers 2 to 2000",
            ));
        }
        if !(2..=2000).contains(&self.samples) {
            return Err(bad(
                "--samples",
                self.samples as f64,
                "whole numbers 2 to 2000",
            ));
        }
        Ok(())
    }
}

/// The first sample of a column lies this far above μ_ms (relative): at μ_ms itself every
/// thickness from η_s up is a limit state (the vertical branch).
pub const FIRST_OFFSET: f64 = 1e-6;

/// A column samples both sides of each pattern change of η_s(μ) this far from it
/// (relative): beyond the change's own rounding, close enough that a branch born there is
/// met (docs/uniqueness.md, the notch of uniqueness).
pub const CORNER_OFFSET: f64 = 1e-5;

/// μ_ms bracketed by two verified certificates (see [`Column::mu_ms_certified`]).
#[derive(Debug, Clone, Copy)]
pub struct MuMsCertified {
    /// μ_ms (1 − δ) and μ_ms (1 + δ).
    pub bracket: (f64, f64),
    /// Whether the verifier proved the list of limit states at the upper end complete.
    pub complete: bool,
}

/// The relative half-width of the certified bracket of μ_ms (the sample just above μ_ms
/// lies at [`FIRST_OFFSET`]).
pub const MU_MS_BRACKET: f64 = 1e-6;

/// Bisections of one bracket stop after this many steps (neighbouring floats come first:
/// about 50 from the samples' spacing).
const MAX_BISECTIONS: usize = 80;

/// A change of kind located between two floats of μ at one α.
#[derive(Debug, Clone)]
pub struct BoundaryPoint {
    /// The opening.
    pub alpha: f64,
    /// The kinds below and above.
    pub between: [Kind; 2],
    /// The last μ of the lower kind and the first of the upper one.
    pub bracket: (f64, f64),
    /// Whether the bracket's ends are neighbouring floats (else the bisection stopped at a
    /// sample the search did not decide, or at its step limit).
    pub tight: bool,
    /// Why the bisection stopped short of neighbouring floats, if it did.
    pub stopped: Option<String>,
    /// Between `non_unique` and `unique`: what becomes of the limit states above η_s at the
    /// non-unique end when each is followed on its own pattern (Newton) to the other end:
    /// why each is not a limit state there, or that one still is (then the unique side
    /// missed it). `None` for other pairs of kinds.
    pub why: Option<String>,
    /// The limit states above η_s followed to the non-unique end (between `non_unique` and
    /// `unique`; what the end's certificate lists where the search there missed them).
    pub followed: Vec<LimitState>,
    /// Between `non_unique` and `unique`: where the last of the followed branches ends,
    /// solved from the condition that ends it ([`branch_end()`]), or why not. `None` for
    /// other pairs of kinds.
    pub end: Option<Result<BranchEnd, String>>,
    /// With [`Rectangle::certify`]: verified certificates at the bracket's two ends state the
    /// two kinds (`Ok`, true where the verifier proved both lists of limit states complete,
    /// false where it only checked the listed states), or why not (`Err`).
    pub certified: Option<Result<bool, String>>,
}

impl BoundaryPoint {
    /// The point's μ: where its branch ends, solved from the defining condition, or
    /// else the middle of its bracket.
    pub fn mu(&self) -> f64 {
        match &self.end {
            Some(Ok(e)) => e.mu,
            _ => 0.5 * (self.bracket.0 + self.bracket.1),
        }
    }

    /// The two μ that `--certify` certifies as the two kinds: the bracket, or where the
    /// point is solved from its defining condition, the branch's end (its last limit state,
    /// at the non-unique side) and the bracket's other end.
    pub fn certified_bracket(&self) -> (f64, f64) {
        match (&self.end, self.between[0]) {
            (Some(Ok(e)), Kind::NonUnique) => (e.mu, self.bracket.1),
            (Some(Ok(e)), _) => (self.bracket.0, e.mu),
            _ => self.bracket,
        }
    }

    /// Whether the point is solved from its defining condition.
    pub fn exact(&self) -> bool {
        matches!(self.end, Some(Ok(_)))
    }
}

/// One sample of a column.
#[derive(Debug, Clone)]
pub struct Sample {
    /// Friction coefficient.
    pub mu: f64,
    /// Its classification.
    pub kind: Classified,
}

/// One opening: μ_ms, the samples, the changes of kind and the runs they bound.
#[derive(Debug, Clone)]
pub struct Column {
    /// The opening.
    pub alpha: f64,
    /// μ_ms(α) (`None`: no finite μ gives equilibrium; the column is left out).
    pub mu_ms: Option<f64>,
    /// Whether μ_ms is exact (a verified pattern).
    pub mu_ms_exact: bool,
    /// The samples, ascending in μ.
    pub samples: Vec<Sample>,
    /// The changes of kind, ascending in μ.
    pub boundaries: Vec<BoundaryPoint>,
    /// Maximal runs of one kind: (kind, μ from, μ to), from μ_ms to K μ_ms; `None` for a
    /// stretch the search did not decide.
    pub runs: Vec<(Option<Kind>, f64, f64)>,
    /// With [`Rectangle::certify`], one per run: a sample inside it and whether a verified
    /// certificate there states the run's kind (`Ok(complete)` as for a bracket; `Err`: why
    /// not).
    pub runs_certified: Vec<(f64, Result<bool, String>)>,
    /// With [`Rectangle::certify`]: μ_ms in a bracket [μ_ms (1 − δ), μ_ms (1 + δ)] (δ =
    /// [`MU_MS_BRACKET`]) whose ends verified certificates state as no equilibrium and as the
    /// first run's kind, with whether both lists were proved complete (`Err`: why not).
    pub mu_ms_certified: Option<Result<MuMsCertified, String>>,
    /// (α, μ_ms(α)) at [`CURVE_STEPS`] − 1 openings between this column and the next (none
    /// after the last): the μ_ms curve between columns, which the regions follow.
    pub mu_ms_between: Vec<[f64; 2]>,
}

/// The μ_ms curve is evaluated at this many steps per strip between columns: at the default
/// spacing (0.05 rad) its chords then lie within ~5e-6 of it, relative (the other boundaries
/// are joined by straight segments). Even, so that a strip's middle is one of the points.
pub const CURVE_STEPS: usize = 16;

/// One column at `alpha` (`next`: the following column's opening): μ_ms, the samples, the
/// located changes, the runs, and the μ_ms curve up to the next column.
pub(super) fn column(
    rect: &Rectangle,
    (alpha, next): (f64, Option<f64>),
    settings: &Settings,
) -> Result<Column, InputError> {
    let arch = rect.arch(alpha)?;
    let limit = friction_limit(&arch, settings).ok().flatten();
    let mut col = Column {
        alpha,
        mu_ms: limit.as_ref().map(|l| l.mu),
        mu_ms_exact: limit.as_ref().is_some_and(|l| l.exact),
        samples: Vec::new(),
        boundaries: Vec::new(),
        runs: Vec::new(),
        runs_certified: Vec::new(),
        mu_ms_certified: None,
        mu_ms_between: Vec::new(),
    };
    if let Some(next) = next {
        for i in 1..CURVE_STEPS {
            let a = alpha + (next - alpha) * i as f64 / CURVE_STEPS as f64;
            if let Some(l) = friction_limit(&rect.arch(a)?, settings).ok().flatten() {
                col.mu_ms_between.push([a, l.mu]);
            }
        }
    }
    let Some(mu_ms) = col.mu_ms else {
        return Ok(col);
    };
    for mu in sample_mus(rect, &arch, mu_ms, settings) {
        let kind = classify(&arch, mu, settings)?;
        col.samples.push(Sample { mu, kind });
    }
    let kind_of = |s: &Sample| s.kind.as_ref().ok().map(|k| k.0);
    for w in 0..col.samples.len() - 1 {
        let (a, b) = (&col.samples[w], &col.samples[w + 1]);
        if let (Some(ka), Some(kb)) = (kind_of(a), kind_of(b)) {
            if ka != kb {
                locate(
                    &arch,
                    alpha,
                    (a.mu, ka),
                    (b.mu, kb),
                    settings,
                    &mut col.boundaries,
                    0,
                )?;
            }
        }
    }
    col.runs = runs(&col, rect.mu_max_factor);
    if rect.certify {
        certify_column(&arch, &mut col, settings);
    }
    Ok(col)
}

/// A column's μ samples, ascending: [`Rectangle::mus`], and both sides of every pattern
/// change of η_s(μ) in their range (at μ (1 ± [`CORNER_OFFSET`]), located by
/// [`pattern_changes`]): a branch of limit states born at a corner of η*(μ) can be narrower
/// than the samples' spacing (the upper branch of a notch of uniqueness), and starts there.
fn sample_mus(rect: &Rectangle, arch: &Arch, mu_ms: f64, settings: &Settings) -> Vec<f64> {
    let mut mus = rect.mus(mu_ms);
    let (lo, hi) = (mus[0], mus[mus.len() - 1]);
    let n = settings.curve_samples;
    for c in pattern_changes(arch, (lo, hi), n, settings) {
        mus.extend(
            [c.mu * (1.0 - CORNER_OFFSET), c.mu * (1.0 + CORNER_OFFSET)]
                .into_iter()
                .filter(|m| *m > lo && *m < hi),
        );
    }
    mus.sort_by(f64::total_cmp);
    mus.dedup();
    mus
}

/// The certificates of a column: both ends of every located bracket, and the middle sample
/// of every decided run.
fn certify_column(arch: &Arch, col: &mut Column, settings: &Settings) {
    let holds_with =
        |mu: f64, want: Kind, found: &[LimitState]| states_kind(arch, mu, want, found, settings);
    let holds = |mu: f64, want: Kind| holds_with(mu, want, &[]);
    let both = |a: Result<bool, String>, b: Result<bool, String>| Ok(a? && b?);
    if let (Some(ms), Some((Some(first), _, _))) = (col.mu_ms, col.runs.first()) {
        let (lo, hi) = (ms * (1.0 - MU_MS_BRACKET), ms * (1.0 + MU_MS_BRACKET));
        col.mu_ms_certified = Some(both(holds(lo, Kind::NoEquilibrium), holds(hi, *first)).map(
            |complete| MuMsCertified {
                bracket: (lo, hi),
                complete,
            },
        ));
    }
    for p in &mut col.boundaries {
        p.certified = Some(certify_point(arch, p, settings));
    }
    for &(kind, from, to) in &col.runs {
        let Some(kind) = kind else { continue };
        let inside: Vec<f64> = col
            .samples
            .iter()
            .filter(|s| s.mu > from && s.mu < to && s.kind.is_ok())
            .map(|s| s.mu)
            .collect();
        if let Some(&mu) = inside.get(inside.len() / 2) {
            col.runs_certified.push((mu, holds(mu, kind)));
        }
    }
}

/// Verified certificates at the two μ of `p`'s certified bracket state its two kinds (`Ok`,
/// true where the verifier proved both lists complete), or why not.
pub(super) fn certify_point(
    arch: &Arch,
    p: &BoundaryPoint,
    settings: &Settings,
) -> Result<bool, String> {
    let (lo, hi) = p.certified_bracket();
    // the followed states (or the branch's last one, at its end) belong to the non-unique end
    let last: Vec<LimitState> = match &p.end {
        Some(Ok(e)) => vec![e.state.clone()],
        _ => p.followed.clone(),
    };
    let (f_lo, f_hi): (&[LimitState], &[LimitState]) = match p.between[0] {
        Kind::NonUnique => (&last, &[]),
        _ => (&[], &last),
    };
    let a = states_kind(arch, lo, p.between[0], f_lo, settings)?;
    let b = states_kind(arch, hi, p.between[1], f_hi, settings)?;
    Ok(a && b)
}

/// Bisects [lo, hi] between kinds `ka` (at lo) and `kb` (at hi) down to neighbouring floats;
/// a third kind met in between splits the bracket in two. Between `non_unique` and `unique`
/// on a continuous arch the non-unique end's limit states above η_s are followed along (Newton on each one's
/// pattern, [`follow`]): a midpoint the search calls unique where one of them still is a
/// limit state above η_s is non-unique (the discretised search lost the branch before its
/// end), so the point is where the branches end, not where the search loses them.
pub(super) fn locate(
    arch: &Arch,
    alpha: f64,
    (mut lo, ka): (f64, Kind),
    (mut hi, kb): (f64, Kind),
    settings: &Settings,
    out: &mut Vec<BoundaryPoint>,
    depth: usize,
) -> Result<(), InputError> {
    let mut tight = false;
    let mut stopped = Some(format!("{MAX_BISECTIONS} bisections"));
    // the non-unique end (true: lo) and its limit states above η_s
    // (a voussoir arch's search is complete by itself: only a continuous arch's, which rests
    // on discretisations agreeing, is helped along)
    let continuous = !matches!(arch.layout(), JointLayout::Discrete(_));
    let mut tracked = match (ka, kb) {
        _ if !continuous => None,
        (Kind::NonUnique, Kind::Unique) => Some((true, lo, states_above(arch, lo, settings)?)),
        (Kind::Unique, Kind::NonUnique) => Some((false, hi, states_above(arch, hi, settings)?)),
        _ => None,
    };
    for _ in 0..MAX_BISECTIONS {
        let m = 0.5 * (lo + hi);
        if m <= lo || m >= hi {
            (tight, stopped) = (true, None);
            break;
        }
        let (mut kind, found) = classify_states(arch, m, settings)?;
        if let (Ok((k, etas)), Some((_, at, states))) = (&mut kind, &mut tracked) {
            let followed: Vec<LimitState> = states
                .iter()
                .filter_map(|s| follow_to(arch, s, (*at, m), settings, FOLLOW_HALVINGS))
                .filter(|f| f.t > etas[0] * (1.0 + settings.root_slack))
                .collect();
            if *k == Kind::Unique && !followed.is_empty() {
                *k = Kind::NonUnique;
            }
            if *k == Kind::NonUnique {
                // the search's own states where the tracked ones changed pattern on the way
                let now = if followed.is_empty() { found } else { followed };
                (*at, *states) = (m, now);
            }
        }
        match kind {
            Ok((k, _)) if k == ka => lo = m,
            Ok((k, _)) if k == kb => hi = m,
            Ok((k, _)) if depth < 4 => {
                locate(arch, alpha, (lo, ka), (m, k), settings, out, depth + 1)?;
                return locate(arch, alpha, (m, k), (hi, kb), settings, out, depth + 1);
            }
            Ok((k, _)) => {
                stopped = Some(format!("a fourth kind ({}) inside the bracket", k.name()));
                break;
            }
            Err(e) => {
                stopped = Some(format!("undecided at mu = {m}: {e}"));
                break;
            }
        }
    }
    let (mut why, mut followed, mut end) = (None, Vec::new(), None);
    if let Some((at_lo, at, states)) = tracked {
        let (from, to) = if at_lo { (lo, hi) } else { (hi, lo) };
        followed = states
            .iter()
            .filter_map(|s| follow_to(arch, s, (at, from), settings, FOLLOW_HALVINGS))
            .collect();
        why = Some(why_lost(arch, &followed, (from, to), settings)).filter(|w| !w.is_empty());
        end = last_end(arch, &followed, (from, to), settings);
    }
    out.push(BoundaryPoint {
        alpha,
        between: [ka, kb],
        bracket: (lo, hi),
        tight,
        stopped,
        why,
        followed,
        end,
        certified: None,
    });
    Ok(())
}

/// A limit state is followed over a step of μ in up to this many halvings where one step
/// fails (near a branch's end its states move fast, and Newton from too far lands on
/// another state or none).
const FOLLOW_HALVINGS: usize = 12;

/// `s`, a limit state at `from`, followed to `to` on its pattern ([`follow`]), through
/// midpoints where one step fails; `None` where it ends on the way.
fn follow_to(
    arch: &Arch,
    s: &LimitState,
    (from, to): (f64, f64),
    settings: &Settings,
    halvings: usize,
) -> Option<LimitState> {
    if from == to {
        return Some(s.clone()); // a limit state there already (found by the search there)
    }
    if let Ok(f) = follow(arch, to, s, settings) {
        return Some(f);
    }
    if halvings == 0 {
        return None;
    }
    let mid = 0.5 * (from + to);
    let half = follow_to(arch, s, (from, mid), settings, halvings - 1)?;
    follow_to(arch, &half, (mid, to), settings, halvings - 1)
}

/// Where the last of the branches of `states` (limit states at `from`, none of them one at
/// `to`) ends between the two, each solved from its defining condition ([`branch_end()`]):
/// `Err` where one of them could not be (why); `None` without states.
fn last_end(
    arch: &Arch,
    states: &[LimitState],
    (from, to): (f64, f64),
    settings: &Settings,
) -> Option<Result<BranchEnd, String>> {
    let mut last: Option<BranchEnd> = None;
    for s in states {
        match branch_end(arch, s, (from, to), settings) {
            Ok(e) => {
                let later = |l: &BranchEnd| (e.mu - l.mu) * (to - from) > 0.0;
                if last.as_ref().is_none_or(later) {
                    last = Some(e);
                }
            }
            Err(why) => return Some(Err(format!("the limit state at eta = {:.10}: {why}", s.t))),
        }
    }
    last.map(Ok)
}

/// The limit states above η_s at `mu` (those found where the search did not settle).
fn states_above(arch: &Arch, mu: f64, settings: &Settings) -> Result<Vec<LimitState>, InputError> {
    Ok(classify_states(arch, mu, settings)?.1)
}

/// The limit states `states` (above η_s at `from`), each followed to `to` ([`lost_at`]):
/// why none is a limit state there, one line per distinct η (mirror images share theirs),
/// or which one still is.
fn why_lost(
    arch: &Arch,
    states: &[LimitState],
    (from, to): (f64, f64),
    settings: &Settings,
) -> String {
    let mut lines: Vec<String> = Vec::new();
    let mut last = f64::NAN;
    for s in states {
        if (s.t - last).abs() <= settings.same_root * s.t {
            continue;
        }
        last = s.t;
        lines.push(match lost_at(arch, to, s, settings) {
            Some(why) => format!("the limit state at eta = {:.10} (mu = {from}): {why}", s.t),
            None => format!(
                "the limit state at eta = {:.10} (mu = {from}) is still one at mu = {to}",
                s.t
            ),
        });
    }
    lines.join("; ")
}

/// The runs of a column from μ_ms to K μ_ms: each sample's kind (an undecided sample is a
/// run of its own, `None`), cut at the located boundaries.
fn runs(col: &Column, factor: f64) -> Vec<(Option<Kind>, f64, f64)> {
    let Some(mu_ms) = col.mu_ms else {
        return Vec::new();
    };
    let mut out: Vec<(Option<Kind>, f64, f64)> = Vec::new();
    let mut b = col.boundaries.iter().peekable();
    for s in &col.samples {
        let k = s.kind.as_ref().ok().map(|k| k.0);
        // the boundaries below this sample close the runs before it
        while let Some(p) = b.next_if(|p| p.bracket.1 <= s.mu) {
            if let Some(last) = out.last_mut() {
                last.2 = p.mu();
            }
            out.push((Some(p.between[1]), p.mu(), p.mu()));
        }
        match out.last_mut() {
            Some(last) if last.0 == k => last.2 = s.mu,
            Some(last) => {
                let cut = 0.5 * (last.2 + s.mu);
                last.2 = cut;
                out.push((k, cut, s.mu));
            }
            None => out.push((k, mu_ms, s.mu)),
        }
    }
    if let Some(last) = out.last_mut() {
        last.2 = factor * mu_ms;
    }
    out.retain(|r| r.2 > r.1);
    out
}

/// A column's notch of uniqueness: the band's boundary above it (the μ where the upper
/// branch ends), and [the lower branch's end, the upper branch's birth].
pub(super) type ColumnNotch = (f64, [f64; 2]);

/// `c` with a notch of uniqueness folded into the band (a `unique` run between two
/// `non_unique` runs: the three become one `non_unique` run, as its neighbours without the
/// notch have it), and the notch, where it has one: so a column whose samples fall in the
/// notch joins its neighbours, and the notch is a tongue of its edge (the regions' path).
pub(super) fn folded(c: &Column) -> (Column, Option<ColumnNotch>) {
    let kinds: Vec<Option<Kind>> = c.runs.iter().map(|r| r.0).collect();
    let notch = [Kind::NonUnique, Kind::Unique, Kind::NonUnique].map(Some);
    let Some(k) = kinds.windows(3).position(|w| w == notch) else {
        return (c.clone(), None);
    };
    let (lower, gap, upper) = (c.runs[k], c.runs[k + 1], c.runs[k + 2]);
    let mut f = c.clone();
    f.runs
        .splice(k..k + 3, [(Some(Kind::NonUnique), lower.1, upper.2)]);
    (f, Some((upper.2, [lower.2, gap.2])))
}
