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

    /// Every end known, with its opening.
    pub(super) fn into_ends(self) -> Vec<(f64, BranchEnd)> {
        self.0.into_iter().flatten().collect()
    }

    /// The boundary point at `alpha` by continuation, with μ_ms there: every known branch's
    /// end nearest `alpha` moved there (Newton on its defining condition, [`end_on`]), the
    /// last of them, accepted where it is a limit state above η_s and the search finds the
    /// arch unique [`BEYOND`] it (no branch ends later); each branch moved is then known
    /// there too. `None` where not.
    pub(super) fn at(
        &mut self,
        rect: &Rectangle,
        alpha: f64,
        settings: &Settings,
    ) -> Result<Option<(BranchEnd, f64)>, InputError> {
        Ok(self
            .all_at(rect, alpha, false, settings)?
            .and_then(|(mut ends, mu_ms)| Some((ends.pop()?, mu_ms))))
    }

    /// [`Branches::at`], with (`all`) the other moved ends that stand as well (each a limit
    /// state above η_s with the arch unique just beyond it: a branch that ends below
    /// another's birth), ascending in μ (the last is [`Branches::at`]'s; the ends of one
    /// branch continued from two columns counted once).
    pub(super) fn all_at(
        &mut self,
        rect: &Rectangle,
        alpha: f64,
        all: bool,
        settings: &Settings,
    ) -> Result<Option<(Vec<BranchEnd>, f64)>, InputError> {
        let arch = rect.arch(alpha)?;
        let Some(mu_ms) = crate::friction::friction_limit(&arch, settings)
            .ok()
            .flatten()
        else {
            return Ok(None);
        };
        let nearest = |known: &[(f64, BranchEnd)]| {
            known
                .iter()
                .min_by(|p, q| (p.0 - alpha).abs().total_cmp(&(q.0 - alpha).abs()))
                .map(|k| k.1.clone())
        };
        let moved: Vec<Option<BranchEnd>> = self
            .0
            .iter()
            .map(|known| end_on(&arch, &nearest(known)?, settings).ok())
            .collect();
        let mut ends: Vec<&BranchEnd> = moved.iter().flatten().collect();
        ends.sort_by(|a, b| a.mu.total_cmp(&b.mu));
        ends.dedup_by(|a, b| {
            (a.mu - b.mu).abs() <= SAME_END * a.mu
                && a.condition.describe() == b.condition.describe()
        });
        let Some(&last) = ends.last() else {
            return Ok(None);
        };
        if !stands(&arch, last, settings)? {
            return Ok(None);
        }
        let mut standing = Vec::new();
        for &e in &ends[..ends.len() - 1] {
            if all && stands(&arch, e, settings)? {
                standing.push(e.clone());
            }
        }
        standing.push(last.clone());
        for (known, m) in self.0.iter_mut().zip(moved) {
            if let Some(m) = m {
                known.push((alpha, m));
            }
        }
        Ok(Some((standing, mu_ms.mu)))
    }
}

/// Two moved ends within this (relative) of each other, with the same condition, are one.
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
