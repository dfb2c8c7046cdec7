//! Figure: the limit curve of an arch with fill ([`FillCurveData`]): the least friction
//! μ_min(η) of every thickness, coloured by collapse mode, with the least friction μ_f at
//! which the arch stands at all, the pattern changes, η\*(∞) below which no ring stands, and
//! the safe (right of the curve) and collapse domains tinted as in the limit-state diagram.

use crate::collapse_mode::CollapseMode;
use crate::figures::fill_curve::FillCurveData;
use crate::render::fine::Fine;
use crate::render::plot::{
    arch_label, boxed_text, legend_modes, legend_swatch, mode_color, short_num, Axis, AxisCoord,
    FAMILY,
};
use crate::render::plot_curve::{COLLAPSE_TINT, SAFE_OPACITY, SAFE_TINT};
use plotters::prelude::*;
use plotters::style::text_anchor::{HPos, Pos, VPos};

const W: u32 = 1100;
const H: u32 = 640;
/// Width of the right margin (the legend).
const RIGHT: u32 = 300;
/// The μ axis ends at most this many times μ_f (μ_min grows without bound near η\*(∞) where
/// the least state at μ = ∞ slides).
const MU_SPAN: f64 = 20.0;

/// The μ axis is logarithmic when it spans more than this ratio.
const LOG_FROM: f64 = 4.0;

fn err(e: impl std::fmt::Display) -> String {
    e.to_string()
}

/// The figure as an SVG document.
pub fn svg(d: &FillCurveData) -> Result<String, String> {
    let (mu_f, eta_f) = d.least;
    let top_mu = d.points.iter().map(|p| p.0).fold(mu_f, f64::max);
    let hi = 1.1 * top_mu.min(MU_SPAN * mu_f);
    // a narrow range of μ reads better on a linear axis (a log one would have one tick)
    let mu = Axis {
        lo: 0.9 * mu_f,
        hi,
        log: hi > LOG_FROM * mu_f,
    };
    let eta_lo = d.points.iter().map(|p| p.1).fold(d.eta_inf, f64::min);
    let eta = Axis {
        lo: 0.8 * eta_lo,
        hi: 2.4,
        log: true,
    };
    let at = |(m, e): (f64, f64)| (mu.to(m), eta.to(e));
    // the curve where it is inside the μ axis, by increasing η
    let seen: Vec<(f64, f64, CollapseMode)> =
        d.points.iter().copied().filter(|p| p.0 <= mu.hi).collect();
    let (Some(first), Some(last)) = (seen.first(), seen.last()) else {
        return Err("no point of the curve to draw".into());
    };
    let mut buf = String::new();
    let fine = Fine::default();
    {
        let root = SVGBackend::with_string(&mut buf, (W, H)).into_drawing_area();
        root.fill(&WHITE).map_err(err)?;
        let title = format!(
            "Limit curve with fill: least friction μ_min(η) by collapse mode ({}, g_f = {}, h = {})",
            arch_label(&d.arch),
            d.arch.fill().map_or(String::new(), |f| short_num(f.weight_ratio)),
            d.arch.fill().map_or(String::new(), |f| short_num(f.depth)),
        );
        let mut chart = ChartBuilder::on(&root)
            .caption(title, (FAMILY, 20))
            .margin(16)
            .margin_right(RIGHT)
            .x_label_area_size(56)
            .y_label_area_size(70)
            .build_cartesian_2d::<AxisCoord, AxisCoord>(mu.range(), eta.range())
            .map_err(err)?;
        chart
            .configure_mesh()
            .x_desc("friction coefficient μ = tan φ   (labels: μ (φ))")
            .y_desc("thickness ratio η = t / r (log scale)")
            .x_label_formatter(&|u| mu.mu_label(*u))
            .y_label_formatter(&|u| eta.label(*u))
            .label_style((FAMILY, 13))
            .axis_desc_style((FAMILY, 15))
            .draw()
            .map_err(err)?;
        // safe: right of the curve; collapse: the rest of the plot
        let curve: Vec<(f64, f64)> = seen.iter().map(|p| at((p.0, p.1))).collect();
        let edge = |e: f64| at((mu.hi, e));
        let mut safe = vec![edge(first.1)];
        safe.extend(curve.iter().copied());
        safe.push(edge(last.1));
        fine.polygon(&chart, &safe, SAFE_TINT.mix(SAFE_OPACITY).filled())?;
        let mut collapse = vec![at((mu.lo, eta.lo)), edge(eta.lo), edge(first.1)];
        collapse.extend(curve.iter().copied());
        collapse.extend([edge(last.1), edge(eta.hi), at((mu.lo, eta.hi))]);
        fine.polygon(&chart, &collapse, COLLAPSE_TINT.mix(0.08).filled())?;
        fine.polyline(
            &chart,
            &[at((mu.lo, d.eta_inf)), at((mu.hi, d.eta_inf))],
            BLACK.mix(0.6).stroke_width(1),
            Some((6.0, 5.0)),
        )?;
        let modes = draw_branches(&chart, &fine, &seen, &at)?;
        for &c in d.changes.iter().filter(|c| c.0 <= mu.hi) {
            chart
                .draw_series(std::iter::once(Circle::new(
                    at(c),
                    4,
                    BLACK.stroke_width(2),
                )))
                .map_err(err)?;
        }
        chart
            .draw_series(std::iter::once(Circle::new(at(d.least), 6, BLACK.filled())))
            .map_err(err)?;
        let px = |p: (f64, f64)| chart.backend_coord(&at(p));
        let (x, y) = px(d.least);
        let text = format!(
            "μ_f = {} (η_f = {}): least friction",
            short_num(mu_f),
            short_num(eta_f)
        );
        boxed_text(
            &root,
            &text,
            (x - 10, y + 8),
            12,
            Pos::new(HPos::Right, VPos::Top),
            BLACK,
        )?;
        let (_, y) = px((mu.hi, d.eta_inf));
        let text = format!("η*(∞) = {}: no thinner ring stands", short_num(d.eta_inf));
        boxed_text(
            &root,
            &text,
            (x.max(px((mu.lo, 1.0)).0 + 200), y + 4),
            12,
            Pos::new(HPos::Left, VPos::Top),
            BLACK,
        )?;
        draw_legend(&root, &modes)?;
        root.present().map_err(err)?;
    }
    Ok(fine.finish(&buf))
}

type Chart<'a, 'b> = ChartContext<'a, SVGBackend<'b>, Cartesian2d<AxisCoord, AxisCoord>>;

/// The curve in runs of one mode (each run shares its end point with the next); the modes
/// drawn, in order.
fn draw_branches(
    chart: &Chart,
    fine: &Fine,
    seen: &[(f64, f64, CollapseMode)],
    at: &dyn Fn((f64, f64)) -> (f64, f64),
) -> Result<Vec<CollapseMode>, String> {
    let mut modes: Vec<CollapseMode> = Vec::new();
    let mut start = 0;
    for k in 1..=seen.len() {
        if k < seen.len() && seen[k].2 == seen[start].2 {
            continue;
        }
        let end = k.min(seen.len() - 1);
        let run: Vec<(f64, f64)> = seen[start..=end].iter().map(|p| at((p.0, p.1))).collect();
        let mode = seen[start].2;
        fine.polyline(chart, &run, mode_color(mode).stroke_width(3), None)?;
        if !modes.contains(&mode) {
            modes.push(mode);
        }
        start = k;
    }
    Ok(modes)
}

/// The legend in the right margin: modes, markers, tints.
fn draw_legend(
    root: &DrawingArea<SVGBackend, plotters::coord::Shift>,
    modes: &[CollapseMode],
) -> Result<(), String> {
    let lx = W as i32 - RIGHT as i32 + 60;
    let mut ly = legend_modes(root, "collapse mode at μ_min", modes, (lx, 70))?;
    ly += 30;
    root.draw(&Circle::new((lx + 13, ly + 7), 6, BLACK.filled()))
        .map_err(err)?;
    root.draw(&Text::new(
        "least friction μ_f",
        (lx + 34, ly),
        (FAMILY, 13),
    ))
    .map_err(err)?;
    ly += 24;
    root.draw(&Circle::new((lx + 13, ly + 7), 4, BLACK.stroke_width(2)))
        .map_err(err)?;
    root.draw(&Text::new("pattern change", (lx + 34, ly), (FAMILY, 13)))
        .map_err(err)?;
    legend_swatch(
        root,
        (lx, ly + 24),
        SAFE_TINT,
        SAFE_OPACITY,
        "stands (right of the curve)",
    )?;
    legend_swatch(root, (lx, ly + 48), COLLAPSE_TINT, 0.08, "collapses (left)")?;
    Ok(())
}
