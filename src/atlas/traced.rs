//! The boundary between `non_unique` and `unique` between two columns, traced by
//! continuation in α: at [`TRACE_STEPS`] − 1 openings inside the strip, the ends of both
//! columns' branches are moved there by Newton on their defining conditions
//! ([`Branches::at`]), and the last end stands where it is a limit state above η_s and the
//! search finds the arch unique just beyond it. So the regions' polygons follow the curve
//! through exact points, not the chord between the columns.

use super::certified::states_kind;
use super::classify::Kind;
use super::column::{Column, Rectangle};
use super::continued::{Branches, BEYOND};
use crate::arch::{Arch, InputError};
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
    /// limit state) and [`BEYOND`] it state `non_unique` and `unique` (`Ok`, true where the
    /// verifier proved both lists complete), or why not.
    pub certified: Option<Result<bool, String>>,
}

/// The boundary traced from a column's `non_unique`/`unique` point to the next column's.
#[derive(Debug, Clone)]
pub struct Traced {
    /// The μ of the column's boundary point (the strip's left end).
    pub from_mu: f64,
    /// The μ of the next column's boundary point (the strip's right end).
    pub to_mu: f64,
    /// The points inside the strip, ascending in α (an opening where the continuation is
    /// not accepted has none).
    pub points: Vec<TracedPoint>,
}

impl Traced {
    /// The largest departure of the points from the straight segment between the strip's
    /// ends, relative to μ, and the opening where it lies (`None`: no points).
    pub fn chord_departure(&self, (a0, a1): (f64, f64)) -> Option<(f64, f64)> {
        self.points
            .iter()
            .map(|p| {
                let chord = self.from_mu + (self.to_mu - self.from_mu) * (p.alpha - a0) / (a1 - a0);
                ((p.end.mu - chord).abs() / p.end.mu, p.alpha)
            })
            .max_by(|a, b| a.0.total_cmp(&b.0))
    }
}

/// The solved `non_unique`/`unique` point of a column, where it has exactly one.
fn the_end(c: &Column) -> Option<&BranchEnd> {
    let mut ends = c
        .boundaries
        .iter()
        .filter(|p| p.between == [Kind::NonUnique, Kind::Unique]);
    let one = ends.next()?;
    match (ends.next(), &one.end) {
        (None, Some(Ok(e))) => Some(e),
        _ => None,
    }
}

/// The traced boundary of every strip (one per column: towards the next; `None` where the
/// two columns do not both hold exactly one solved `non_unique`/`unique` point with the same
/// kinds in the same order), strips on `threads` threads.
pub(super) fn trace(
    rect: &Rectangle,
    columns: &[Column],
    settings: &Settings,
    threads: usize,
) -> Result<Vec<Option<Traced>>, InputError> {
    let kinds = |c: &Column| c.runs.iter().map(|r| r.0).collect::<Vec<_>>();
    let strips: Vec<usize> = (0..columns.len()).collect();
    threads::map(&strips, threads, |_, &k| {
        let (c, d) = (&columns[k], columns.get(k + 1)?);
        let (e0, e1) = (the_end(c)?, the_end(d)?);
        if kinds(c) != kinds(d) {
            return None;
        }
        Some(strip(rect, &columns[k..=k + 1], (e0.mu, e1.mu), settings))
    })
    .into_iter()
    .map(Option::transpose)
    .collect()
}

/// The points inside the strip between `pair` (two columns), from the left.
fn strip(
    rect: &Rectangle,
    pair: &[Column],
    (from_mu, to_mu): (f64, f64),
    settings: &Settings,
) -> Result<Traced, InputError> {
    let (a0, a1) = (pair[0].alpha, pair[1].alpha);
    let mut branches = Branches::of(pair);
    let mut points = Vec::new();
    for i in 1..TRACE_STEPS {
        let alpha = a0 + (a1 - a0) * i as f64 / TRACE_STEPS as f64;
        if let Some((end, mu_ms)) = branches.at(rect, alpha, settings)? {
            let arch = rect.arch(alpha)?;
            let certified = rect.certify.then(|| certify(&arch, &end, settings));
            points.push(TracedPoint {
                alpha,
                mu_ms,
                end,
                certified,
            });
        }
    }
    Ok(Traced {
        from_mu,
        to_mu,
        points,
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
