//! Figure: the η–μ limit curves of one or more arches. Safe domain (above/right of the
//! curve) and collapse domain shaded, each branch coloured by its collapse mode, corners
//! marked and labelled (μ, η), friction angles on the μ labels, the asymptote of an
//! overturning branch dashed.

use crate::collapse_mode::CollapseMode;
use crate::limit_curve::LimitCurve;
use crate::render::plot::{mode_color, mu_label, short_num, FAMILY};
use plotters::prelude::*;

/// One arch's curve, ready to draw: polylines per branch (μ, η), corners, asymptote.
#[derive(Debug, Clone)]
pub struct CurveData {
    /// Legend label of the arch (e.g. "α = 0").
    pub label: String,
    /// The branches: mode and points (μ, η) by decreasing μ.
    pub branches: Vec<(CollapseMode, Vec<(f64, f64)>)>,
    /// Finite corners (μ, η).
    pub corners: Vec<(f64, f64)>,
    /// η of the asymptote at μ = ∞ when the top branch only approaches it.
    pub asymptote: Option<f64>,
    /// μ_ms.
    pub mu_ms: f64,
}

/// Samples the branches of `curve` for drawing (`n` points per branch, μ up to `mu_cap`).
pub fn curve_data(
    arch: &crate::arch::Arch,
    label: &str,
    curve: &LimitCurve,
    mu_cap: f64,
    n: usize,
    settings: &crate::settings::Settings,
) -> Option<CurveData> {
    let mu_ms = curve.mu_ms?;
    let mut branches = Vec::new();
    for b in &curve.branches {
        if b.mode == CollapseMode::PurelySliding {
            continue;
        }
        let hi = b.mu_max.min(mu_cap);
        let lo = b.mu_min;
        let mut pts = vec![];
        // the upper end: a corner, or the horizontal branch's constant η at the cap
        // (an asymptotic branch is sampled only, it never reaches its η_min)
        if b.mu_max.is_finite() || b.eta_min == b.eta_max {
            pts.push((hi, b.eta_min));
        }
        for i in 1..n {
            let mu = hi * (lo / hi).powf(i as f64 / n as f64);
            if let Ok(crate::limit::Outcome::Limit(ls)) =
                crate::limit::solve(arch, mu, settings).map(|s| s.outcome)
            {
                pts.push((mu, ls.eta));
            }
        }
        pts.push((lo, b.eta_max));
        branches.push((b.mode, pts));
    }
    let corners = curve
        .corners
        .iter()
        .filter(|c| c.mu.is_finite())
        .map(|c| (c.mu, c.eta))
        .collect();
    let asymptote = curve
        .corners
        .iter()
        .find(|c| c.mu.is_infinite())
        .map(|c| c.eta);
    Some(CurveData {
        label: label.into(),
        branches,
        corners,
        asymptote,
        mu_ms,
    })
}

/// Draws the curves of several arches in one SVG.
pub fn svg(data: &[CurveData], title: &str) -> Result<String, String> {
    let mu_lo = data.iter().map(|d| d.mu_ms).fold(f64::INFINITY, f64::min) * 0.8;
    let mu_hi = data
        .iter()
        .flat_map(|d| d.branches.iter().flat_map(|b| b.1.iter().map(|p| p.0)))
        .fold(0.0f64, f64::max)
        * 1.05;
    let eta_hi = data
        .iter()
        .flat_map(|d| d.branches.iter().flat_map(|b| b.1.iter().map(|p| p.1)))
        .fold(0.0f64, f64::max)
        * 1.3;
    let mut buf = String::new();
    {
        let root = SVGBackend::with_string(&mut buf, (1010, 620)).into_drawing_area();
        root.fill(&WHITE).map_err(|e| e.to_string())?;
        let mut chart = ChartBuilder::on(&root)
            .caption(title, (FAMILY, 22))
            .margin(16)
            .margin_right(250)
            .x_label_area_size(56)
            .y_label_area_size(70)
            .build_cartesian_2d(
                (mu_lo..mu_hi)
                    .log_scale()
                    .with_key_points(log_keys(mu_lo, mu_hi)),
                0.0..eta_hi,
            )
            .map_err(|e| e.to_string())?;
        chart
            .configure_mesh()
            .x_desc("friction coefficient μ = tan φ   (labels: μ (φ))")
            .y_desc("thickness ratio η = t / r")
            .x_label_formatter(&|m| mu_label(*m))
            .y_label_formatter(&|e| short_num(*e))
            .x_labels(8)
            .label_style((FAMILY, 13))
            .axis_desc_style((FAMILY, 15))
            .draw()
            .map_err(|e| e.to_string())?;
        // collapse domain: everything no arch's safe domain covers (drawn first, light red)
        chart
            .draw_series(std::iter::once(Rectangle::new(
                [(mu_lo, 0.0), (mu_hi, eta_hi)],
                RGBColor(214, 39, 40).mix(0.07).filled(),
            )))
            .map_err(|e| e.to_string())?;
        let mut legend_modes: Vec<CollapseMode> = Vec::new();
        for d in data {
            // the whole curve as one polyline (decreasing μ), then the vertical branch
            let mut outline: Vec<(f64, f64)> = d
                .branches
                .iter()
                .flat_map(|b| b.1.iter().copied())
                .collect();
            outline.sort_by(|a, b| b.0.total_cmp(&a.0));
            let eta_ms = outline.last().map_or(eta_hi, |p| p.1);
            // safe domain: above the curve, right of μ_ms
            let mut safe = vec![(d.mu_ms, eta_hi), (d.mu_ms, eta_ms)];
            safe.extend(outline.iter().rev().copied());
            safe.extend([
                (mu_hi, outline.first().map_or(0.0, |p| p.1)),
                (mu_hi, eta_hi),
            ]);
            let safe_copy = safe.clone();
            chart
                .draw_series(std::iter::once(Polygon::new(safe, WHITE.mix(0.75))))
                .map_err(|e| e.to_string())?;
            chart
                .draw_series(std::iter::once(Polygon::new(
                    safe_copy,
                    RGBColor(44, 160, 44).mix(0.05),
                )))
                .map_err(|e| e.to_string())?;
            for (mode, pts) in &d.branches {
                let color = mode_color(*mode);
                chart
                    .draw_series(LineSeries::new(pts.iter().copied(), color.stroke_width(3)))
                    .map_err(|e| e.to_string())?;
                if !legend_modes.contains(mode) {
                    legend_modes.push(*mode);
                }
            }
            // vertical purely-sliding branch
            let color = mode_color(CollapseMode::PurelySliding);
            chart
                .draw_series(LineSeries::new(
                    [(d.mu_ms, eta_ms), (d.mu_ms, eta_hi)],
                    color.stroke_width(3),
                ))
                .map_err(|e| e.to_string())?;
            if !legend_modes.contains(&CollapseMode::PurelySliding) {
                legend_modes.push(CollapseMode::PurelySliding);
            }
            if d.asymptote.is_some() && !legend_modes.contains(&CollapseMode::Overturning) {
                legend_modes.push(CollapseMode::Overturning);
            }
            if let Some(eta_inf) = d.asymptote {
                let color = mode_color(CollapseMode::Overturning);
                chart
                    .draw_series(DashedLineSeries::new(
                        [(mu_lo, eta_inf), (mu_hi, eta_inf)],
                        8,
                        6,
                        color.stroke_width(2),
                    ))
                    .map_err(|e| e.to_string())?;
                chart
                    .draw_series(std::iter::once(Text::new(
                        format!(
                            "{}: overturning asymptote η = {} as μ → ∞",
                            d.label,
                            short_num(eta_inf)
                        ),
                        (mu_lo * 1.05, eta_inf + 0.045 * eta_hi),
                        (FAMILY, 12).into_font().color(&color),
                    )))
                    .map_err(|e| e.to_string())?;
            }
            for &(mu, eta) in &d.corners {
                chart
                    .draw_series(std::iter::once(Circle::new((mu, eta), 5, BLACK.filled())))
                    .map_err(|e| e.to_string())?;
                chart
                    .draw_series(std::iter::once(Text::new(
                        format!("({}, {})", short_num(mu), short_num(eta)),
                        (mu * 1.03, eta + 0.012 * eta_hi),
                        (FAMILY, 12),
                    )))
                    .map_err(|e| e.to_string())?;
            }
            // arch label at the top of its vertical branch
            chart
                .draw_series(std::iter::once(Text::new(
                    d.label.clone(),
                    (d.mu_ms * 1.02, eta_hi * 0.96),
                    (FAMILY, 13),
                )))
                .map_err(|e| e.to_string())?;
        }
        chart
            .draw_series(std::iter::once(Text::new(
                "safe (above / right of each curve)",
                (mu_hi * 0.25, eta_hi * 0.9),
                (FAMILY, 14),
            )))
            .map_err(|e| e.to_string())?;
        chart
            .draw_series(std::iter::once(Text::new(
                "collapse",
                (mu_lo * 1.01, eta_hi * 0.6),
                (FAMILY, 14),
            )))
            .map_err(|e| e.to_string())?;
        // legend in the right margin, outside the data
        let (lx, mut ly) = (1010 - 240, 70);
        root.draw(&Text::new("collapse mode", (lx, ly), (FAMILY, 14)))
            .map_err(|e| e.to_string())?;
        for mode in &legend_modes {
            ly += 24;
            let c = mode_color(*mode);
            root.draw(&PathElement::new(
                vec![(lx, ly + 7), (lx + 26, ly + 7)],
                c.stroke_width(3),
            ))
            .map_err(|e| e.to_string())?;
            root.draw(&Text::new(mode.name(), (lx + 34, ly), (FAMILY, 13)))
                .map_err(|e| e.to_string())?;
        }
        ly += 30;
        root.draw(&Circle::new((lx + 13, ly + 7), 5, BLACK.filled()))
            .map_err(|e| e.to_string())?;
        root.draw(&Text::new("corner (μ, η)", (lx + 34, ly), (FAMILY, 13)))
            .map_err(|e| e.to_string())?;
        root.present().map_err(|e| e.to_string())?;
    }
    Ok(buf)
}

/// Tick positions 1, 2, 3, 5 × 10^k inside [lo, hi].
pub fn log_keys(lo: f64, hi: f64) -> Vec<f64> {
    let mut keys = Vec::new();
    let mut p = 10f64.powi(lo.log10().floor() as i32);
    while p <= hi {
        for m in [1.0, 2.0, 3.0, 5.0] {
            let v = m * p;
            if v >= lo && v <= hi {
                keys.push(v);
            }
        }
        p *= 10.0;
    }
    if keys.len() > 6 {
        keys.retain(|v| {
            let m = v / 10f64.powi(v.log10().floor() as i32);
            (m - 1.0).abs() < 1e-9 || (m - 3.0).abs() < 1e-9
        });
    }
    keys
}
