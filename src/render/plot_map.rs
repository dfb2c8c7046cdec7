//! Figure: the admissibility margin ([`crate::margin_map`]) over the η–μ plane as filled
//! contour bands (log axis for μ), with the exact limit curve overlaid in black.

use crate::render::plot::{mu_label, short_num, FAMILY};
use crate::render::plot_curve::CurveData;
use plotters::prelude::*;

fn band_color(v: f64, vmax_pos: f64, vmax_neg: f64) -> RGBColor {
    if v.is_nan() {
        return RGBColor(220, 220, 220);
    }
    // 10 bands: 5 blues (collapse) and 5 greens (safe), by |v| / vmax
    let t = (v.abs() / if v < 0.0 { vmax_neg } else { vmax_pos }).min(1.0);
    let band = (t * 5.0).floor().min(4.0) / 4.0;
    let mix = |a: u8, b: u8| (a as f64 + (b as f64 - a as f64) * band) as u8;
    if v < 0.0 {
        RGBColor(mix(222, 33), mix(235, 102), mix(247, 172))
    } else {
        RGBColor(mix(229, 0), mix(245, 109), mix(224, 44))
    }
}

/// Draws the map: `values[i][j]` at (`etas[i]`, `mus[j]`) (centres of cells).
pub fn svg(
    label: &str,
    etas: &[f64],
    mus: &[f64],
    values: &[Vec<f64>],
    curve: Option<&CurveData>,
) -> Result<String, String> {
    let finite = || values.iter().flatten().copied().filter(|v| v.is_finite());
    let vmax_pos = finite().fold(0.0f64, f64::max).max(f64::MIN_POSITIVE);
    let vmax_neg = finite()
        .fold(0.0f64, |m, v| m.max(-v))
        .max(f64::MIN_POSITIVE);
    let edges = |c: &[f64], log: bool| -> Vec<f64> {
        let mut e = Vec::with_capacity(c.len() + 1);
        for i in 0..=c.len() {
            let v = if i == 0 {
                if log {
                    c[0] * (c[0] / c[1]).sqrt()
                } else {
                    c[0] - 0.5 * (c[1] - c[0])
                }
            } else if i == c.len() {
                let n = c.len();
                if log {
                    c[n - 1] * (c[n - 1] / c[n - 2]).sqrt()
                } else {
                    c[n - 1] + 0.5 * (c[n - 1] - c[n - 2])
                }
            } else if log {
                (c[i - 1] * c[i]).sqrt()
            } else {
                0.5 * (c[i - 1] + c[i])
            };
            e.push(v);
        }
        e
    };
    let (me, ee) = (edges(mus, true), edges(etas, false));
    let (m0, m1) = (me[0], *me.last().unwrap());
    let (e0, e1) = (ee[0].max(0.0), *ee.last().unwrap());
    let mut buf = String::new();
    {
        let root = SVGBackend::with_string(&mut buf, (900, 640)).into_drawing_area();
        root.fill(&WHITE).map_err(|e| e.to_string())?;
        let mut ch = ChartBuilder::on(&root)
            .caption(
                format!(
                    "Admissibility margin, {label}: green safe (bands of {} r), blue collapse (bands of {} r)",
                    short_num(0.2 * vmax_pos),
                    short_num(0.2 * vmax_neg)
                ),
                (FAMILY, 16),
            )
            .margin(14)
            .margin_right(40)
            .x_label_area_size(50)
            .y_label_area_size(70)
            .build_cartesian_2d((m0..m1).log_scale().with_key_points(crate::render::plot_curve::log_keys(m0, m1)), e0..e1)
            .map_err(|e| e.to_string())?;
        for (i, row) in values.iter().enumerate() {
            for (j, &v) in row.iter().enumerate() {
                ch.draw_series(std::iter::once(Rectangle::new(
                    [(me[j], ee[i]), (me[j + 1], ee[i + 1])],
                    band_color(v, vmax_pos, vmax_neg).filled(),
                )))
                .map_err(|e| e.to_string())?;
            }
        }
        ch.configure_mesh()
            .disable_mesh()
            .x_desc("friction coefficient μ   (labels: μ (φ))")
            .y_desc("thickness ratio η = t / r")
            .x_label_formatter(&|m| mu_label(*m))
            .y_label_formatter(&|e| short_num(*e))
            .label_style((FAMILY, 12))
            .axis_desc_style((FAMILY, 14))
            .draw()
            .map_err(|e| e.to_string())?;
        if let Some(d) = curve {
            let mut pts: Vec<(f64, f64)> = d
                .branches
                .iter()
                .flat_map(|b| b.1.iter().copied())
                .filter(|p| p.0 >= m0 && p.0 <= m1)
                .collect();
            pts.sort_by(|a, b| b.0.total_cmp(&a.0));
            if let Some(&(_, eta_ms)) = pts.last() {
                pts.push((d.mu_ms, eta_ms));
                pts.push((d.mu_ms, e1));
            }
            ch.draw_series(std::iter::once(PathElement::new(
                pts,
                BLACK.stroke_width(3),
            )))
            .map_err(|e| e.to_string())?
            .label("exact limit curve η*(μ)")
            .legend(|(x, y)| PathElement::new(vec![(x, y), (x + 22, y)], BLACK.stroke_width(3)));
            for &(mu, eta) in &d.corners {
                ch.draw_series(std::iter::once(Circle::new((mu, eta), 5, BLACK.filled())))
                    .map_err(|e| e.to_string())?;
            }
        }
        ch.configure_series_labels()
            .position(SeriesLabelPosition::LowerRight)
            .background_style(WHITE.mix(0.9))
            .border_style(BLACK)
            .label_font((FAMILY, 12))
            .draw()
            .map_err(|e| e.to_string())?;
        root.present().map_err(|e| e.to_string())?;
    }
    Ok(buf)
}
