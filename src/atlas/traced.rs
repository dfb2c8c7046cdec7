//! The boundary between `non_unique` and `unique` between two columns, traced by
//! continuation in α: at [`TRACE_STEPS`] − 1 openings inside the strip (and more where the
//! curve bends or a notch of uniqueness begins or ends, [`refine`]), the ends of both
//! columns' branches are moved there by Newton on their defining conditions, one opening
//! at a time from their own column ([`Branches::moved_in_steps`]), and the last end stands
//! where it is a limit state above η_s and the search finds the arch unique just beyond it
//! ([`standing`]). So the regions' polygons follow the curve through exact points, not the
//! chord between the columns.

use super::certified::states_kind;
use super::classify::classify;
use super::classify::Kind;
use super::column::{certify_point, folded, locate, BoundaryPoint, Column, Rectangle};
use super::continued::{mu_ms_of, standing, Branches, BEYOND};
use super::tips::Tip;
use crate::arch::{Arch, InputError};
use crate::limit_curve::pattern_changes;
use crate::limit_states::BranchEnd;
use crate::settings::Settings;
use crate::threads;

/// Steps per strip between two columns at which the boundary is traced (the points lie at
/// the TRACE_STEPS − 1 openings inside it, equally spaced).
pub const TRACE_STEPS: usize = 8;

/// A point of the boundary curve inside a strip, solved by continuation.
#[derive(Debug, Clone)]
pub struct TracedPoint {
    /// The opening.
    pub alpha: f64,
    /// μ_ms there.
    pub mu_ms: f64,
    /// The branch's end there, solved from its defining condition.
    pub end: BranchEnd,
    /// With [`Rectangle::certify`]: verified certificates at the end (listing its last
    /// limit state) and 10⁻⁸ beyond it state `non_unique` and `unique` (`Ok`, true where the
    /// verifier proved both lists complete), or why not; where there is a notch, at its
    /// lower end and across its birth too.
    pub certified: Option<Result<bool, String>>,
    /// A notch of uniqueness below the end: another branch ends below the birth of the
    /// end's branch.
    pub notch: Option<Notch>,
}

/// A notch of uniqueness inside the band at one opening: from the end of a lower branch
/// (`non_unique` below it, `unique` just beyond it) up to where the upper branch is born
/// (`unique` below, `non_unique` above).
#[derive(Debug, Clone)]
pub struct Notch {
    /// The lower branch's end, solved from its defining condition.
    pub below: BranchEnd,
    /// The birth of the upper branch, bisected between `unique` and `non_unique` (as a
    /// column's boundary point is).
    pub birth: BoundaryPoint,
}

/// The upper branch is looked for this far (relative) below its end when a notch is
/// located.
const NOTCH_INSIDE: f64 = 1e-6;

/// The boundary traced from a column's `non_unique`/`unique` point to the next column's, or
/// between a column's point and a tip of the band on the μ_ms curve inside the strip.
#[derive(Debug, Clone)]
pub struct Traced {
    /// The μ of the traced curve's left end: the column's boundary point, or μ_ms at a tip.
    pub from_mu: f64,
    /// The μ of its right end: the next column's boundary point, or μ_ms at a tip.
    pub to_mu: f64,
    /// The points inside, ascending in α (an opening where the continuation is not
    /// accepted has none).
    pub points: Vec<TracedPoint>,
    /// Where the band meets the μ_ms curve inside the strip, (α, μ_ms) ([`super::Tip`]):
    /// the curve's left end (the band lies to its right) or its right end (to its left).
    pub tip: Option<[f64; 2]>,
}

impl Traced {
    /// The largest departure of the points from the straight segment between the strip's
    /// ends, relative to μ, and the opening where it lies (`None`: no points).
    pub fn chord_departure(&self, (a0, a1): (f64, f64)) -> Option<(f64, f64)> {
        let (a0, a1) = match self.tip {
            Some(t) if t[1] == self.from_mu => (t[0], a1),
            Some(t) => (a0, t[0]),
            None => (a0, a1),
        };
        self.points
            .iter()
            .map(|p| {
                let chord = self.from_mu + (self.to_mu - self.from_mu) * (p.alpha - a0) / (a1 - a0);
                ((p.end.mu - chord).abs() / p.end.mu, p.alpha)
            })
            .max_by(|a, b| a.0.total_cmp(&b.0))
    }
}

/// The band's boundary at a column: its last `non_unique`/`unique` point (above a notch of
/// uniqueness where its samples meet one), where it is solved.
fn the_end(c: &Column) -> Option<&BranchEnd> {
    let last = c
        .boundaries
        .iter()
        .rfind(|p| p.between == [Kind::NonUnique, Kind::Unique])?;
    last.end.as_ref()?.as_ref().ok()
}

/// The traced boundary of every strip (one per column: towards the next), strips on
/// `threads` threads: between two columns that both hold a solved `non_unique`/`unique`
/// point ([`the_end`]), or from the one
/// column of the strip that holds one to a tip of the band on the μ_ms curve between them
/// (`tips`); `None` elsewhere. The branch ends `known` elsewhere (the top's search) whose
/// openings lie inside a strip are continued there too: a branch that ends last only
/// between two columns is found so.
pub(super) fn trace(
    rect: &Rectangle,
    columns: &[Column],
    (tips, known): (&[Tip], &[(f64, BranchEnd)]),
    settings: &Settings,
    threads: usize,
) -> Result<Vec<Option<Traced>>, InputError> {
    // the kinds with a column's notch of uniqueness folded into the band
    let kinds = |c: &Column| folded(c).0.runs.iter().map(|r| r.0).collect::<Vec<_>>();
    let strips: Vec<usize> = (0..columns.len()).collect();
    threads::map(&strips, threads, |_, &k| {
        let (c, d) = (&columns[k], columns.get(k + 1)?);
        let inner: Vec<(f64, BranchEnd)> = known
            .iter()
            .filter(|e| e.0 > c.alpha && e.0 < d.alpha)
            .cloned()
            .collect();
        let inside = |t: &&Tip| {
            t.alpha.0 > c.alpha && t.alpha.1 < d.alpha && t.stopped.is_none() && t.mu_ms.is_finite()
        };
        let tip = |between: [Kind; 2]| tips.iter().filter(inside).find(|t| t.between == between);
        let at_tip = |t: &Tip| [0.5 * (t.alpha.0 + t.alpha.1), t.mu_ms];
        let (span, ends) = match (the_end(c), the_end(d)) {
            (Some(e0), Some(e1)) if kinds(c) == kinds(d) => ((c.alpha, d.alpha), (e0.mu, e1.mu)),
            // the band ends on the μ_ms curve inside the strip: from the column to the tip
            (Some(e0), None) => {
                let t = at_tip(tip([Kind::NonUnique, Kind::Unique])?);
                return Some(
                    strip(
                        rect,
                        (&[c], &inner),
                        ((c.alpha, t[0]), (e0.mu, t[1])),
                        settings,
                    )
                    .map(|s| Traced { tip: Some(t), ..s }),
                );
            }
            (None, Some(e1)) => {
                let t = at_tip(tip([Kind::Unique, Kind::NonUnique])?);
                return Some(
                    strip(
                        rect,
                        (&[d], &inner),
                        ((d.alpha, t[0]), (e1.mu, t[1])),
                        settings,
                    )
                    .map(|s| Traced {
                        from_mu: s.to_mu,
                        to_mu: s.from_mu,
                        points: s.points.into_iter().rev().collect(),
                        tip: Some(t),
                    }),
                );
            }
            _ => return None,
        };
        Some(strip(rect, (&[c, d], &inner), (span, ends), settings))
    })
    .into_iter()
    .map(Option::transpose)
    .collect()
}

/// The points at the openings inside `span`, in its order (`from`: the columns whose ends
/// are continued: the span's two ends, or its first end only); `from_mu`/`to_mu` the
/// curve's μ at the span's first and second end. The [`TRACE_STEPS`] − 1 openings first,
/// then [`refine`]d where the curve bends or a notch begins or ends.
fn strip(
    rect: &Rectangle,
    (from, inner): (&[&Column], &[(f64, BranchEnd)]),
    ((a0, a1), (from_mu, to_mu)): ((f64, f64), (f64, f64)),
    settings: &Settings,
) -> Result<Traced, InputError> {
    let alphas: Vec<f64> = (1..TRACE_STEPS)
        .map(|i| a0 + (a1 - a0) * i as f64 / TRACE_STEPS as f64)
        .collect();
    let (openings, mut branches) = swept(rect, (from, inner), &alphas, settings)?;
    let mut points = Vec::new();
    for (alpha, arch, mu_ms, moved) in openings {
        points.extend(point_at(rect, (alpha, &arch, mu_ms), &moved, settings)?);
    }
    let ends = ((a0, from_mu), (a1, to_mu));
    for _ in 0..REFINEMENTS {
        let more = refine(&points, ends);
        if more.is_empty() {
            break;
        }
        for alpha in more {
            let arch = rect.arch(alpha)?;
            let Some(mu_ms) = mu_ms_of(&arch, settings) else {
                continue;
            };
            let moved = branches.moved_in_steps(rect, alpha, settings)?;
            let ends: Vec<BranchEnd> = moved.iter().flatten().cloned().collect();
            branches.record(alpha, moved);
            points.extend(point_at(rect, (alpha, &arch, mu_ms), &ends, settings)?);
        }
        // in the span's order
        points
            .sort_by(|p, q| ((p.alpha - a0) * (a1 - a0)).total_cmp(&((q.alpha - a0) * (a1 - a0))));
    }
    Ok(Traced {
        from_mu,
        to_mu,
        points,
        tip: None,
    })
}

/// A strip's points are refined at most this many times (each time halving the step
/// where they are refined).
const REFINEMENTS: usize = 3;

/// A point departing from the chord between its neighbours by more than this (relative
/// to μ) is refined on both sides.
const BEND: f64 = 1e-4;

/// The openings to add between consecutive points of a strip (its `ends`, (α, μ), count as
/// points without a notch): the middle of every step next to a point that departs from
/// its neighbours' chord by more than [`BEND`] of μ, and of every step between a point with
/// a notch and one without.
fn refine(points: &[TracedPoint], ends: ((f64, f64), (f64, f64))) -> Vec<f64> {
    let mut all: Vec<(f64, f64, bool)> = vec![(ends.0 .0, ends.0 .1, false)];
    all.extend(
        points
            .iter()
            .map(|p| (p.alpha, p.end.mu, p.notch.is_some())),
    );
    all.push((ends.1 .0, ends.1 .1, false));
    let mut split = vec![false; all.len() - 1];
    for k in 1..all.len() - 1 {
        let (p, q, r) = (all[k - 1], all[k], all[k + 1]);
        let chord = p.1 + (r.1 - p.1) * (q.0 - p.0) / (r.0 - p.0);
        if (q.1 - chord).abs() > BEND * q.1 {
            split[k - 1] = true;
            split[k] = true;
        }
        // a notch begins or ends between two points of the strip
        if k + 1 < all.len() - 1 && q.2 != r.2 {
            split[k] = true;
        }
    }
    split
        .iter()
        .zip(all.windows(2))
        .filter(|(s, _)| **s)
        .map(|(_, w)| 0.5 * (w[0].0 + w[1].0))
        .collect()
}

/// The traced point at one opening from the branch ends `moved` there: the last that stands,
/// with the notch below it where another stands too; `None` where none stands.
fn point_at(
    rect: &Rectangle,
    (alpha, arch, mu_ms): (f64, &Arch, f64),
    moved: &[BranchEnd],
    settings: &Settings,
) -> Result<Option<TracedPoint>, InputError> {
    let Some(mut ends) = standing(arch, moved, true, settings)? else {
        return Ok(None);
    };
    let end = ends.pop().expect("the last end stands");
    let notch = match ends.pop() {
        Some(below) => notch(arch, alpha, below, &end, settings)?,
        None => None,
    };
    let certified = rect.certify.then(|| {
        let at_end = certify(arch, &end, settings)?;
        match &notch {
            Some(n) => Ok(at_end
                && certify(arch, &n.below, settings)?
                && certify_point(arch, &n.birth, settings)?),
            None => Ok(at_end),
        }
    });
    Ok(Some(TracedPoint {
        alpha,
        mu_ms,
        end,
        certified,
        notch,
    }))
}

/// The opening, arch, μ_ms and the moved branch ends at each of `alphas` (in the span's order; those
/// without μ_ms left out of the continuation): the first column's branches (and the ends
/// `inner` known inside) swept across the openings in order, the second column's (where
/// `from` has two) in reverse, each branch moved from its end at the opening before, so that
/// every branch moves by one opening's step whatever its column; with every branch and the
/// ends it reached.
fn swept(
    rect: &Rectangle,
    (from, inner): (&[&Column], &[(f64, BranchEnd)]),
    alphas: &[f64],
    settings: &Settings,
) -> Result<(Vec<Opening>, Branches), InputError> {
    let mut out = Vec::new();
    for &alpha in alphas {
        let arch = rect.arch(alpha)?;
        if let Some(mu_ms) = mu_ms_of(&arch, settings) {
            out.push((alpha, arch, mu_ms, Vec::new()));
        }
    }
    let sweep = |columns: &[&Column],
                 order: &mut dyn Iterator<Item = usize>,
                 out: &mut Vec<Opening>|
     -> Result<Branches, InputError> {
        let mut branches = Branches::of(columns.iter().copied()).with(inner.iter().cloned());
        for k in order {
            let (alpha, _, _, ends) = &mut out[k];
            let moved = branches.moved_in_steps(rect, *alpha, settings)?;
            ends.extend(moved.iter().flatten().cloned());
            branches.record(*alpha, moved);
        }
        Ok(branches)
    };
    let n = out.len();
    let mut branches = sweep(&from[..1], &mut (0..n), &mut out)?;
    if from.len() == 2 {
        branches = branches.join(sweep(&from[1..], &mut (0..n).rev(), &mut out)?);
    }
    Ok((out, branches))
}

/// An opening of a strip: α, the arch, μ_ms and the branch ends moved there.
type Opening = (f64, Arch, f64, Vec<BranchEnd>);

/// The bracket of a birth between `unique` at `lo` and `non_unique` at `hi`, narrowed to
/// [`SEED`] (relative) either side of a pattern change of η_s(μ) inside it where the
/// kinds there agree (a branch born from η_s is born at a corner of η*(μ)); else as given.
/// The bisection from it ends at the same neighbouring floats where the kind changes once.
fn seeded(
    arch: &Arch,
    (lo, hi): (f64, f64),
    settings: &Settings,
) -> Result<(f64, f64), InputError> {
    for c in pattern_changes(arch, (lo, hi), SEED_SAMPLES, settings) {
        let (a, b) = (c.mu * (1.0 - SEED), c.mu * (1.0 + SEED));
        if a > lo
            && b < hi
            && matches!(classify(arch, a, settings)?, Ok((Kind::Unique, _)))
            && matches!(classify(arch, b, settings)?, Ok((Kind::NonUnique, _)))
        {
            return Ok((a, b));
        }
    }
    Ok((lo, hi))
}

/// A birth's bracket is seeded this close to the corner either side (relative).
const SEED: f64 = 1e-10;

/// The samples of η_s(μ) between a notch's two ends that locate its corners.
const SEED_SAMPLES: usize = 4;

/// The notch between the end `below` (the arch unique just beyond it) and the upper
/// branch's end `end`: the upper branch's birth located between them ([`locate`]) where
/// the arch is `non_unique` just below `end`; `None` where not, or where the bisection
/// meets a third kind.
fn notch(
    arch: &Arch,
    alpha: f64,
    below: BranchEnd,
    end: &BranchEnd,
    settings: &Settings,
) -> Result<Option<Notch>, InputError> {
    let (lo, hi) = (below.mu * (1.0 + BEYOND), end.mu * (1.0 - NOTCH_INSIDE));
    if hi <= lo || !matches!(classify(arch, hi, settings)?, Ok((Kind::NonUnique, _))) {
        return Ok(None);
    }
    let (lo, hi) = seeded(arch, (lo, hi), settings)?;
    let mut out = Vec::new();
    locate(
        arch,
        alpha,
        (lo, Kind::Unique),
        (hi, Kind::NonUnique),
        settings,
        &mut out,
        0,
    )?;
    Ok(match <[BoundaryPoint; 1]>::try_from(out) {
        Ok([birth]) if birth.between == [Kind::Unique, Kind::NonUnique] => {
            Some(Notch { below, birth })
        }
        _ => None,
    })
}

/// Verified certificates at the end (its last limit state listed) and just beyond it
/// state `non_unique` and `unique`.
fn certify(arch: &Arch, end: &BranchEnd, settings: &Settings) -> Result<bool, String> {
    let below = states_kind(
        arch,
        end.mu,
        Kind::NonUnique,
        std::slice::from_ref(&end.state),
        settings,
    )?;
    let beyond = states_kind(arch, end.mu * (1.0 + BEYOND), Kind::Unique, &[], settings)?;
    Ok(below && beyond)
}
