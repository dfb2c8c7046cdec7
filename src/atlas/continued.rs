//! Boundary points between `non_unique` and `unique` by continuation in α: the ends of the
//! branches known at neighbouring openings, each moved to a new opening by Newton on its
//! own defining condition ([`end_on`]); the last of them stands where it is a limit state
//! above η_s there and the search finds the arch unique just beyond it. The top of the band
//! and the traced boundary curves between columns both evaluate openings this way.

use super::classify::{classify, Kind};
use super::column::{Column, Rectangle};
use crate::arch::{Arch, InputError};
use crate::limit_states::{end_on, BranchEnd};
use crate::settings::Settings;

/// A continued boundary point stands where the search finds the arch unique this far
/// beyond it (relative; the kinds decided to tolerances change within ~2e-10 of an end).
pub(super) const BEYOND: f64 = 1e-8;

/// The branches whose ends are continued in α, each with its ends accepted so far and their
/// openings (a branch moves from its end nearest the new opening).
pub(super) struct Branches(Vec<Vec<(f64, BranchEnd)>>);

impl Branches {
    /// The solved `non_unique`/`unique` ends of `columns`.
    pub(super) fn of<'a>(columns: impl IntoIterator<Item = &'a Column>) -> Branches {
        Branches(
            columns
                .into_iter()
                .flat_map(|c| &c.boundaries)
                .filter(|p| p.between == [Kind::NonUnique, Kind::Unique])
                .filter_map(|p| p.end.clone()?.ok().map(|e| vec![(p.alpha, e)]))
                .collect(),
        )
    }

    /// Branches of their own, one per end (`(opening, end)`), besides these.
    pub(super) fn with(mut self, ends: impl IntoIterator<Item = (f64, BranchEnd)>) -> Branches {
        self.0.extend(ends.into_iter().map(|e| vec![e]));
        self
    }

    /// These branches and `other`'s.
    pub(super) fn join(mut self, other: Branches) -> Branches {
        self.0.extend(other.0);
        self
    }

    /// Every end known, with its opening.
    pub(super) fn into_ends(self) -> Vec<(f64, BranchEnd)> {
        self.0.into_iter().flatten().collect()
    }

    /// The boundary point at `alpha` by continuation, with μ_ms there: every known branch's
    /// end nearest `alpha` moved there (Newton on its defining condition, [`end_on`]), the
    /// last of them, accepted where it is a limit state above η_s and the search finds the
    /// arch unique [`BEYOND`] it (no branch ends later, [`standing`]); each branch moved is
    /// then known there too. `None` where not.
    pub(super) fn at(
        &mut self,
        rect: &Rectangle,
        alpha: f64,
        settings: &Settings,
    ) -> Result<Option<(BranchEnd, f64)>, InputError> {
        let arch = rect.arch(alpha)?;
        let Some(mu_ms) = mu_ms_of(&arch, settings) else {
            return Ok(None);
        };
        let moved = self.moved(&arch, alpha, settings);
        let Some(mut standing) = standing(&arch, moved.iter().flatten(), false, settings)? else {
            return Ok(None);
        };
        self.record(alpha, moved);
        Ok(standing.pop().map(|end| (end, mu_ms)))
    }

    /// Every branch's end nearest `alpha` moved there (Newton on its defining condition,
    /// [`end_on`]; `None` where it does not converge), in the branches' order.
    fn moved(&self, arch: &Arch, alpha: f64, settings: &Settings) -> Vec<Option<BranchEnd>> {
        self.0
            .iter()
            .map(|known| end_on(arch, &nearest(known, alpha)?.1, settings).ok())
            .collect()
    }

    /// [`Branches::moved`], where a branch's Newton does not converge from its nearest
    /// end, by halving the step in α (at most [`HALVINGS`] times): a sweep across a wide
    /// strip moves each branch as far as its end stays within Newton's reach.
    pub(super) fn moved_in_steps(
        &self,
        rect: &Rectangle,
        alpha: f64,
        settings: &Settings,
    ) -> Result<Vec<Option<BranchEnd>>, InputError> {
        let mut out = Vec::new();
        for known in &self.0 {
            out.push(match nearest(known, alpha) {
                Some(start) => step(rect, start.clone(), alpha, HALVINGS, settings)?,
                None => None,
            });
        }
        Ok(out)
    }

    /// Each branch's `moved` end (from [`Branches::moved`]) known at `alpha` from now on.
    pub(super) fn record(&mut self, alpha: f64, moved: Vec<Option<BranchEnd>>) {
        for (known, m) in self.0.iter_mut().zip(moved) {
            if let Some(m) = m {
                known.push((alpha, m));
            }
        }
    }
}

/// A branch's known end nearest `alpha`, with its opening.
fn nearest(known: &[(f64, BranchEnd)], alpha: f64) -> Option<&(f64, BranchEnd)> {
    known
        .iter()
        .min_by(|p, q| (p.0 - alpha).abs().total_cmp(&(q.0 - alpha).abs()))
}

/// A branch's step in α is halved at most this many times.
const HALVINGS: usize = 3;

/// The branch's end `start` (with its opening) moved to `alpha` by Newton, through the
/// middle of the step where it does not converge (`depth` halvings left).
fn step(
    rect: &Rectangle,
    (from, start): (f64, BranchEnd),
    alpha: f64,
    depth: usize,
    settings: &Settings,
) -> Result<Option<BranchEnd>, InputError> {
    if let Ok(e) = end_on(&rect.arch(alpha)?, &start, settings) {
        return Ok(Some(e));
    }
    if depth == 0 {
        return Ok(None);
    }
    let mid = 0.5 * (from + alpha);
    match step(rect, (from, start), mid, depth - 1, settings)? {
        Some(e) => step(rect, (mid, e), alpha, depth - 1, settings),
        None => Ok(None),
    }
}

/// μ_ms of `arch`, where it has one.
pub(super) fn mu_ms_of(arch: &Arch, settings: &Settings) -> Option<f64> {
    crate::friction::friction_limit(arch, settings)
        .ok()
        .flatten()
        .map(|l| l.mu)
}

/// The boundary point among moved `ends` (ascending in μ, the ends of one branch continued
/// from two sides counted once): the last of them, where it [`stands`], with (`all`) the
/// others that stand as well (each a limit state above η_s with the arch unique just beyond
/// it: a branch that ends below another's birth); `None` where the last does not stand.
pub(super) fn standing<'a>(
    arch: &Arch,
    ends: impl IntoIterator<Item = &'a BranchEnd>,
    all: bool,
    settings: &Settings,
) -> Result<Option<Vec<BranchEnd>>, InputError> {
    let mut sorted: Vec<&BranchEnd> = ends.into_iter().collect();
    sorted.sort_by(|a, b| a.mu.total_cmp(&b.mu));
    // one end continued from two sides, or a mirror pair's two ends: one point, the
    // highest (where two branches' ends cross, the boundary is the later one)
    let mut ends: Vec<&BranchEnd> = Vec::new();
    for e in sorted {
        match ends.last_mut() {
            Some(last) if (e.mu - last.mu).abs() <= SAME_END * e.mu => *last = e,
            _ => ends.push(e),
        }
    }
    let Some(&last) = ends.last() else {
        return Ok(None);
    };
    if !stands(arch, last, settings)? {
        return Ok(None);
    }
    let mut out = Vec::new();
    for &e in &ends[..ends.len() - 1] {
        if all && stands(arch, e, settings)? {
            out.push(e.clone());
        }
    }
    out.push(last.clone());
    Ok(Some(out))
}

/// Two moved ends within this (relative) of each other are one (the same branch's, or a
/// mirror pair's).
const SAME_END: f64 = 1e-9;

/// Whether `end` is a boundary point on `arch`: its state is a limit state above η_s at its
/// μ, and the search finds the arch unique [`BEYOND`] it.
fn stands(arch: &Arch, end: &BranchEnd, settings: &Settings) -> Result<bool, InputError> {
    let eta_s = match classify(arch, end.mu, settings)? {
        // η_s carries a limit state (the kind of a band's side): etas[0] is η_s
        Ok((Kind::Unique | Kind::NonUnique, etas)) => etas[0],
        _ => return Ok(false),
    };
    if end.state.t <= eta_s * (1.0 + settings.root_slack) {
        return Ok(false);
    }
    let beyond = end.mu * (1.0 + BEYOND);
    Ok(matches!(
        classify(arch, beyond, settings)?,
        Ok((Kind::Unique, _))
    ))
}
