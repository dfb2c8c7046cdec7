//! The atlas of uniqueness: over openings α ∈ [α_min, α_max] of symmetric arches and
//! friction coefficients μ ∈ [μ_ms(α), K μ_ms(α)], where the least thickness carries the only
//! limit state, where other limit states lie above it, where it carries none, and (below
//! μ_ms) where no equilibrium exists.
//!
//! Each α is a column: μ_ms(α) from [`crate::friction::friction_limit`], then samples at μ = μ_ms (1 + d) with
//! d geometric from 10⁻⁶ to K − 1 (dense near μ_ms, where the non-unique band lies), each
//! classified by the complete limit-state search ([`crate::limit_states::survey`]); between two samples of
//! different kinds the change is located by bisection in μ down to neighbouring floats (a
//! sample of a third kind in between splits the bracket). Between columns the regions are
//! joined through their boundaries' points where both columns hold the same kinds in the
//! same order (the `non_unique`/`unique` boundary traced inside the strip by continuation
//! in α where both columns solve one, [`Traced`]; other boundaries by straight segments);
//! elsewhere each column's runs hold up to the middle of the strip, or up to a tip where
//! a kind begins or ends on the μ_ms curve inside it (the `non_unique`/`unique`
//! boundary is traced from the column to the tip). Between
//! `non_unique` and `unique` on a continuous arch the non-unique end's branches of limit
//! states are followed and the point is where the last one ends, solved from the condition
//! that ends it ([`crate::limit_states::branch_end()`]); other boundary points are brackets
//! to the last float of μ. With [`Rectangle::certify`] both sides are certified.

mod certified;
mod classify;
mod column;
mod continued;
pub mod loads;
mod regions;
mod tips;
mod top;
mod traced;

pub use certified::{certified_kind, certified_reduction};
pub use classify::{classify, Classified, Kind};
pub use column::{
    BoundaryPoint, Column, MuMsCertified, Rectangle, Sample, CURVE_STEPS, FIRST_OFFSET,
    MU_MS_BRACKET,
};
pub use tips::Tip;
pub use top::BandTop;
pub use traced::{Traced, TracedPoint, TRACE_STEPS};

use crate::arch::InputError;
use crate::settings::Settings;
use crate::threads;

/// The whole atlas.
#[derive(Debug, Clone)]
pub struct Atlas {
    /// What it covers.
    pub rectangle: Rectangle,
    /// One per opening, ascending.
    pub columns: Vec<Column>,
    /// The regions as polygons of (α, μ) vertices (closed: the last vertex joins the first).
    pub regions: Vec<(Kind, Vec<[f64; 2]>)>,
    /// The μ_ms curve: (α, μ_ms) at the columns and between them, ascending in α.
    pub curve: Vec<[f64; 2]>,
    /// Where a kind begins or ends along the μ_ms curve, located to neighbouring floats of α.
    pub tips: Vec<Tip>,
    /// The top of the non-unique band (its largest μ/μ_ms), where the columns solve its
    /// boundary points.
    pub top: Option<BandTop>,
    /// One per column: the `non_unique`/`unique` boundary traced by continuation towards
    /// the next column, or to a tip of the band on the μ_ms curve between them (`None`:
    /// neither).
    pub traced: Vec<Option<Traced>>,
}

impl Atlas {
    /// μ_ms at `alpha`, linear between the points of [`Atlas::curve`].
    pub fn mu_ms_at(&self, alpha: f64) -> f64 {
        regions::interpolate(&self.curve, alpha)
    }
}

/// The atlas over `rect` on `threads` threads (columns in parallel); `progress(done,
/// total)` after each column.
pub fn atlas(
    rect: &Rectangle,
    settings: &Settings,
    threads: usize,
    progress: &(dyn Fn(usize, usize) + Sync),
) -> Result<Atlas, InputError> {
    rect.check()?;
    let alphas = rect.alphas();
    for &a in &alphas {
        rect.arch(a)?;
    }
    let columns = threads::map_with_progress(&alphas, threads, progress, |k, &alpha| {
        column::column(rect, (alpha, alphas.get(k + 1).copied()), settings)
    })
    .into_iter()
    .collect::<Result<Vec<Column>, InputError>>()?;
    let tips = tips::tips(rect, &columns, settings)?;
    let top = top::band_top(rect, &columns, settings)?;
    let known = top.as_ref().map_or(&[][..], |t| &t.ends[..]);
    let traced = traced::trace(rect, &columns, (&tips, known), settings, threads)?;
    let regions = regions::regions(&columns, &traced, top.as_ref().map(|t| [t.alpha, t.mu]));
    let with_ms: Vec<&Column> = columns.iter().filter(|c| c.mu_ms.is_some()).collect();
    let curve = regions::mu_ms_curve(&with_ms);
    Ok(Atlas {
        rectangle: *rect,
        columns,
        regions,
        curve,
        tips,
        top,
        traced,
    })
}
