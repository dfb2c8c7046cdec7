//! The data of the limit curve of an arch with fill: μ_min(η) sampled densely in η for
//! drawing ([`crate::limit_curve::filled`]: the curve is traced in η, and its least friction
//! μ_f may lie inside the range, where the curve turns back).

use super::NoFigure;
use crate::arch::{Arch, ETA_TOP};
use crate::collapse_mode::CollapseMode;
use crate::limit_curve::filled::{point, trace, FillCurve};
use crate::settings::Settings;

/// Points of μ_min(η) drawn besides the traced curve's own.
const DRAWN_POINTS: usize = 160;

/// The curve μ_min(η) of an arch with fill, for drawing.
#[derive(Debug, Clone)]
pub struct FillCurveData {
    /// The arch (with its fill).
    pub arch: Arch,
    /// (μ_min, η, mode) by increasing η: the traced curve's samples and the ends of its
    /// changes, and a dense geometric grid in η between.
    pub points: Vec<(f64, f64, CollapseMode)>,
    /// The least friction μ_f and its thickness η_f.
    pub least: (f64, f64),
    /// The pattern changes (μ, η): each bracket's thinner end.
    pub changes: Vec<(f64, f64)>,
    /// η\*(∞): no thinner ring stands at any friction.
    pub eta_inf: f64,
}

/// The curve of `arch` (with fill), traced and sampled densely on `threads` threads.
pub fn fill_curve(
    arch: &Arch,
    settings: &Settings,
    threads: usize,
) -> Result<FillCurveData, NoFigure> {
    let curve: FillCurve = trace(arch, settings, threads);
    let (Some(eta_inf), Some(least)) = (curve.eta_inf, curve.least.as_ref()) else {
        let why = curve
            .unresolved
            .first()
            .map_or("nothing stands".to_string(), |u| u.1.clone());
        return Err(NoFigure(format!("no limit curve with fill: {why}")));
    };
    let lo = eta_inf * (1.0 + settings.curve_start_rel);
    let grid: Vec<f64> = (0..DRAWN_POINTS)
        .map(|i| lo * (ETA_TOP / lo).powf(i as f64 / (DRAWN_POINTS - 1) as f64))
        .collect();
    let dense = crate::threads::map(&grid, threads, |_, &eta| point(arch, eta, settings));
    let traced = curve
        .samples
        .iter()
        .chain(curve.changes.iter().flat_map(|c| c.ends.iter()))
        .chain(std::iter::once(least));
    let mut points: Vec<(f64, f64, CollapseMode)> = dense
        .iter()
        .flatten()
        .chain(traced)
        .map(|p| (p.mu, p.eta, p.mode))
        .collect();
    points.sort_by(|a, b| a.1.total_cmp(&b.1));
    Ok(FillCurveData {
        arch: arch.clone(),
        points,
        least: (least.mu, least.eta),
        changes: curve
            .changes
            .iter()
            .map(|c| (c.ends[0].mu, c.ends[0].eta))
            .collect(),
        eta_inf,
    })
}
