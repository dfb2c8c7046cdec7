//! Boundary points between `non_unique` and `unique` by continuation in α: the ends of the
//! branches known at neighbouring openings, each moved to a new opening by Newton on its
//! own defining condition ([`end_on`]); the last of them stands where it is a limit state
//! above η_s there and the search finds the arch unique just beyond it. The top of the band
//! and the traced boundary curves between columns both evaluate openings this way.

use super::classify::{classify, Kind};
use super::column::{Column, Rectangle};
use crate::arch::InputError;
use crate::limit_states::{end_on, BranchEnd};
use crate::settings::Settings;

/// A continued boundary point stands where the search finds the arch unique this far
/// beyond it (relative; the kinds decided to tolerances change within ~2e-10 of an end).
pub(super) const BEYOND: f64 = 1e-8;

/// The branches whose ends are continued in α, each with the opening of its latest end.
pub(super) struct Branches(Vec<(f64, BranchEnd)>);

impl Branches {
    /// The solved `non_unique`/`unique` ends of `columns`.
    pub(super) fn of<'a>(columns: impl IntoIterator<Item = &'a Column>) -> Branches {
        Branches(
            columns
                .into_iter()
                .flat_map(|c| &c.boundaries)
                .filter(|p| p.between == [Kind::NonUnique, Kind::Unique])
                .filter_map(|p| p.end.clone()?.ok().map(|e| (p.alpha, e)))
                .collect(),
        )
    }

    /// The boundary point at `alpha` by continuation, with μ_ms there: every known branch's
    /// end moved there (Newton on its defining condition, [`end_on`]), the last of them,
    /// accepted where it is a limit state above η_s and the search finds the arch unique
    /// [`BEYOND`] it (no branch ends later); each branch moved then starts from there.
    /// `None` where not.
    pub(super) fn at(
        &mut self,
        rect: &Rectangle,
        alpha: f64,
        settings: &Settings,
    ) -> Result<Option<(BranchEnd, f64)>, InputError> {
        let arch = rect.arch(alpha)?;
        let Some(mu_ms) = crate::friction::friction_limit(&arch, settings)
            .ok()
            .flatten()
        else {
            return Ok(None);
        };
        let moved: Vec<Option<BranchEnd>> = self
            .0
            .iter()
            .map(|(_, e)| end_on(&arch, e, settings).ok())
            .collect();
        let Some(last) = moved.iter().flatten().max_by(|a, b| a.mu.total_cmp(&b.mu)) else {
            return Ok(None);
        };
        // the end's state is a limit state above η_s there, and none is left beyond it
        let eta_s = match classify(&arch, last.mu, settings)? {
            // η_s carries a limit state (the kind of a band's side): etas[0] is η_s
            Ok((Kind::Unique | Kind::NonUnique, etas)) => etas[0],
            _ => return Ok(None),
        };
        if last.state.t <= eta_s * (1.0 + settings.root_slack) {
            return Ok(None);
        }
        let beyond = last.mu * (1.0 + BEYOND);
        if !matches!(classify(&arch, beyond, settings)?, Ok((Kind::Unique, _))) {
            return Ok(None);
        }
        let last = last.clone();
        for (b, m) in self.0.iter_mut().zip(moved) {
            if let Some(m) = m {
                *b = (alpha, m);
            }
        }
        Ok(Some((last, mu_ms.mu)))
    }
}
