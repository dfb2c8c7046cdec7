//! Figure: the η–μ limit curves of one or more arches ([`CurveData`]). Each branch is
//! coloured by its collapse mode, corners are marked and labelled (μ, η), μ labels carry
//! the friction angle, the asymptote of an overturning branch is dashed. The safe domain of
//! each arch (above / right of its curve) is tinted with the same translucent green, so the
//! tint deepens with the number of arches that stand there and no arch's tint hides
//! another's; a single arch also gets its collapse domain tinted red.

use crate::collapse_mode::CollapseMode;
use crate::figures::CurveData;
use crate::render::fine::Fine;
use crate::render::plot::AxisCoord;
use crate::render::plot::{
    arch_label, boxed_text, legend_modes, legend_swatch, mode_color, short_num, text_width, Axis,
    FAMILY,
};
use plotters::coord::Shift;
use plotters::prelude::*;
use plotters::style::text_anchor::{HPos, Pos, VPos};
use std::ops::Range;

/// Fill of the safe domain (one translucent layer per arch).
pub const SAFE_TINT: RGBColor = RGBColor(0, 150, 60);
/// Opacity of one arch's safe layer.
pub const SAFE_OPACITY: f64 = 0.1;
/// Fill of the collapse domain (drawn for a single arch only).
pub const COLLAPSE_TINT: RGBColor = RGBColor(214, 39, 40);

const W: u32 = 1100;
const H: u32 = 640;
/// Width of the right margin: arch labels at the curve ends, then the legend.
const RIGHT: u32 = 340;

type Chart<'a, 'b> = ChartContext<'a, SVGBackend<'b>, Cartesian2d<AxisCoord, AxisCoord>>;

/// Where to draw: the axes and the chart coordinates of a point (μ, η).
struct Frame {
    mu: Axis,
    eta: Axis,
}

impl Frame {
    fn new(data: &[CurveData], log_eta: bool) -> Frame {
        let pts = || data.iter().flat_map(|d| d.outline());
        let mu_lo = data.iter().map(|d| d.mu_ms).fold(f64::INFINITY, f64::min) * 0.8;
        let mu_hi = pts().map(|p| p.0).fold(0.0f64, f64::max) * 1.05;
        let top = pts().map(|p| p.1).fold(0.0f64, f64::max);
        let low = pts()
            .map(|p| p.1)
            .chain(data.iter().filter_map(|d| d.asymptote))
            .fold(f64::INFINITY, f64::min);
        let eta = if log_eta {
            Axis {
                lo: 0.5 * low,
                hi: 1.6 * top,
                log: true,
            }
        } else {
            Axis {
                lo: 0.0,
                hi: 1.3 * top,
                log: false,
            }
        };
        Frame {
            mu: Axis {
                lo: mu_lo,
                hi: mu_hi,
                log: true,
            },
            eta,
        }
    }

    fn at(&self, (mu, eta): (f64, f64)) -> (f64, f64) {
        (self.mu.to(mu), self.eta.to(eta))
    }

    fn all(&self, pts: impl IntoIterator<Item = (f64, f64)>) -> Vec<(f64, f64)> {
        pts.into_iter().map(|p| self.at(p)).collect()
    }
}

fn err(e: impl std::fmt::Display) -> String {
    e.to_string()
}

/// Draws the curves of several arches in one SVG; `log_eta` puts η on a log scale.
pub fn svg(data: &[CurveData], log_eta: bool) -> Result<String, String> {
    if data.is_empty() {
        return Err("no curve to draw".into());
    }
    let f = Frame::new(data, log_eta);
    let mut buf = String::new();
    let fine = Fine::default();
    {
        let root = SVGBackend::with_string(&mut buf, (W, H)).into_drawing_area();
        root.fill(&WHITE).map_err(err)?;
        let (mu_ax, eta_ax) = (f.mu, f.eta);
        let mut chart = ChartBuilder::on(&root)
            .caption(
                if log_eta {
                    "Limit-state diagram: boundary η_s(μ) by collapse mode (log η)"
                } else {
                    "Limit-state diagram: boundary η_s(μ) by collapse mode"
                },
                (FAMILY, 22),
            )
            .margin(16)
            .margin_right(RIGHT)
            .x_label_area_size(56)
            .y_label_area_size(70)
            .build_cartesian_2d(mu_ax.range(), eta_ax.range())
            .map_err(err)?;
        chart
            .configure_mesh()
            .x_desc("friction coefficient μ = tan φ   (labels: μ (φ))")
            .y_desc(if log_eta {
                "thickness ratio η = t / r (log scale)"
            } else {
                "thickness ratio η = t / r"
            })
            .x_label_formatter(&|u| mu_ax.mu_label(*u))
            .y_label_formatter(&|u| eta_ax.label(*u))
            .label_style((FAMILY, 13))
            .axis_desc_style((FAMILY, 15))
            .draw()
            .map_err(err)?;
        draw_tints(&chart, &f, data, &fine)?;
        let mut modes: Vec<CollapseMode> = Vec::new();
        for d in data {
            draw_curve(&mut chart, &f, d, &mut modes, &fine)?;
        }
        draw_labels(&root, &chart, &f, data)?;
        let marks = (
            data.iter().any(|d| !d.transitions.is_empty()),
            data.iter().any(|d| !d.limit_states.is_empty()),
        );
        draw_legend(&root, &modes, data.len(), marks)?;
        root.present().map_err(err)?;
    }
    Ok(fine.finish(&buf))
}

/// The safe domain of each arch (one translucent layer each), and for a single arch its
/// collapse domain. Both are bounded by the arch's own curve, so nothing is painted over.
fn draw_tints(chart: &Chart, f: &Frame, data: &[CurveData], fine: &Fine) -> Result<(), String> {
    let (mu_lo, mu_hi, eta_lo, eta_hi) = (f.mu.lo, f.mu.hi, f.eta.lo, f.eta.hi);
    for d in data {
        let outline = d.outline();
        let (Some(&right), Some(&left)) = (outline.first(), outline.last()) else {
            continue;
        };
        // increasing μ from the foot of the sliding branch to the right edge
        let rising: Vec<(f64, f64)> = outline.iter().rev().copied().collect();
        let mut safe = vec![(d.mu_ms, eta_hi), (d.mu_ms, left.1)];
        safe.extend(rising.iter().copied());
        safe.extend([(mu_hi, right.1), (mu_hi, eta_hi)]);
        fine.polygon(chart, &f.all(safe), SAFE_TINT.mix(SAFE_OPACITY).filled())?;
        if data.len() == 1 {
            let mut collapse = vec![(mu_lo, eta_lo), (mu_lo, eta_hi), (d.mu_ms, eta_hi)];
            collapse.push((d.mu_ms, left.1));
            collapse.extend(rising);
            collapse.extend([(mu_hi, right.1), (mu_hi, eta_lo)]);
            fine.polygon(chart, &f.all(collapse), COLLAPSE_TINT.mix(0.08).filled())?;
        }
    }
    Ok(())
}

/// One arch's branches, its vertical purely sliding branch, its asymptote and corners.
fn draw_curve(
    chart: &mut Chart,
    f: &Frame,
    d: &CurveData,
    modes: &mut Vec<CollapseMode>,
    fine: &Fine,
) -> Result<(), String> {
    let mut add = |m: CollapseMode| {
        if !modes.contains(&m) {
            modes.push(m);
        }
    };
    for (mode, pts) in &d.branches {
        let style = mode_color(*mode).stroke_width(3);
        fine.polyline(chart, &f.all(pts.iter().copied()), style, None)?;
        add(*mode);
    }
    let outline = d.outline();
    // a horizontal top branch goes on to the right edge at its constant η
    if let (None, Some(&(mu, eta))) = (d.asymptote, outline.first()) {
        let top_mu =
            |b: &(CollapseMode, Vec<(f64, f64)>)| b.1.iter().map(|p| p.0).fold(0.0, f64::max);
        let mode = d
            .branches
            .iter()
            .max_by(|a, b| top_mu(a).total_cmp(&top_mu(b)))
            .map_or(CollapseMode::PurelyRotational, |b| b.0);
        chart
            .draw_series(LineSeries::new(
                f.all([(mu, eta), (f.mu.hi, eta)]),
                mode_color(mode).stroke_width(3),
            ))
            .map_err(err)?;
    }
    let eta_ms = outline.last().map_or(f.eta.hi, |p| p.1);
    chart
        .draw_series(LineSeries::new(
            f.all([(d.mu_ms, eta_ms), (d.mu_ms, f.eta.hi)]),
            mode_color(CollapseMode::PurelySliding).stroke_width(3),
        ))
        .map_err(err)?;
    add(CollapseMode::PurelySliding);
    if let Some(eta_inf) = d.asymptote {
        chart
            .draw_series(DashedLineSeries::new(
                f.all([(f.mu.lo, eta_inf), (f.mu.hi, eta_inf)]),
                8,
                6,
                mode_color(CollapseMode::Overturning).stroke_width(2),
            ))
            .map_err(err)?;
        add(CollapseMode::Overturning);
    }
    for &c in &d.corners {
        chart
            .draw_series(std::iter::once(Circle::new(f.at(c), 5, BLACK.filled())))
            .map_err(err)?;
    }
    for &c in &d.transitions {
        chart
            .draw_series(std::iter::once(Circle::new(
                f.at(c),
                5,
                BLACK.stroke_width(2),
            )))
            .map_err(err)?;
    }
    for &p in &d.limit_states {
        chart
            .draw_series(std::iter::once(TriangleMarker::new(
                f.at(p),
                6,
                LIMIT_STATE_COLOR.filled(),
            )))
            .map_err(err)?;
    }
    Ok(())
}

/// Colour of the limit states above the boundary (non-associative non-uniqueness).
const LIMIT_STATE_COLOR: RGBColor = RGBColor(200, 0, 160);

/// Labels on white boxes: corners (below-left of the corner, where a monotone curve never
/// passes), each arch at the top of its sliding branch (staggered) and at the right end of
/// its curve (in the margin), asymptotes (under the dashed line at the right).
fn draw_labels(
    root: &DrawingArea<SVGBackend, Shift>,
    chart: &Chart,
    f: &Frame,
    data: &[CurveData],
) -> Result<(), String> {
    let px = |p: (f64, f64)| chart.backend_coord(&f.at(p));
    let (xr, yr) = chart.plotting_area().get_pixel_range();
    let top_right = Pos::new(HPos::Right, VPos::Top);
    // boxes already placed, to keep corner labels of different arches apart
    let mut placed: Vec<[i32; 4]> = Vec::new();
    for d in data {
        for &c in &d.corners {
            let text = format!("({}, {})", short_num(c.0), short_num(c.1));
            corner_label(root, &text, px(c), (&xr, &yr), &mut placed)?;
        }
        if let Some(eta_inf) = d.asymptote {
            let (x, y) = px((f.mu.hi, eta_inf));
            let text = format!(
                "{}: overturning asymptote η = {} as μ → ∞",
                arch_label(&d.arch),
                short_num(eta_inf)
            );
            let color = mode_color(CollapseMode::Overturning);
            boxed_text(root, &text, (x - 6, y + 5), 12, top_right, color)?;
        }
    }
    // arch labels at the top of the sliding branches, staggered from left to right
    let mut order: Vec<&CurveData> = data.iter().collect();
    order.sort_by(|a, b| a.mu_ms.total_cmp(&b.mu_ms));
    for (k, d) in order.iter().enumerate() {
        let x = px((d.mu_ms, f.eta.hi)).0;
        let y = yr.start + 6 + 20 * k as i32;
        let pos = Pos::new(HPos::Left, VPos::Top);
        boxed_text(root, &arch_label(&d.arch), (x + 5, y), 13, pos, BLACK)?;
    }
    // arch labels at the right end of each curve, pushed apart to 16 px
    let mut ends: Vec<(i32, String)> = data
        .iter()
        .filter_map(|d| {
            let p = d.outline().first().copied()?;
            Some((px((f.mu.hi, p.1)).1, arch_label(&d.arch)))
        })
        .collect();
    ends.sort_by_key(|e| e.0);
    for k in 1..ends.len() {
        ends[k].0 = ends[k].0.max(ends[k - 1].0 + 16);
    }
    for (y, text) in ends {
        root.draw(&Text::new(
            text,
            (xr.end + 6, y),
            TextStyle::from((FAMILY, 13).into_font()).pos(Pos::new(HPos::Left, VPos::Center)),
        ))
        .map_err(err)?;
    }
    Ok(())
}

/// A corner's label `text` near its pixel `(x, y)`: below-left first (a falling curve
/// never passes there), then above-right, below-right, above-left, higher above-right —
/// the first inside the plot `(xr, yr)` and clear of the boxes `placed` (to which its box
/// is added).
fn corner_label(
    root: &DrawingArea<SVGBackend, Shift>,
    text: &str,
    (x, y): (i32, i32),
    (xr, yr): (&Range<i32>, &Range<i32>),
    placed: &mut Vec<[i32; 4]>,
) -> Result<(), String> {
    let (w, h) = (text_width(text, 12) + 4, 16);
    let candidates = [
        (x - 7 - w, y + 7, HPos::Right, VPos::Top),
        (x + 7, y - 7 - h, HPos::Left, VPos::Bottom),
        (x + 7, y + 7, HPos::Left, VPos::Top),
        (x - 7 - w, y - 7 - h, HPos::Right, VPos::Bottom),
        (x + 7, y - 9 - 2 * h, HPos::Left, VPos::Bottom),
        (x + 7, y - 11 - 3 * h, HPos::Left, VPos::Bottom),
    ];
    let inside =
        |b: &[i32; 4]| b[0] >= xr.start && b[2] <= xr.end && b[1] >= yr.start && b[3] <= yr.end;
    let clear = |b: &[i32; 4]| {
        placed
            .iter()
            .all(|p| b[2] <= p[0] || b[0] >= p[2] || b[3] <= p[1] || b[1] >= p[3])
    };
    let boxes: Vec<([i32; 4], HPos, VPos)> = candidates
        .iter()
        .map(|&(x0, y0, hp, vp)| ([x0, y0, x0 + w, y0 + h], hp, vp))
        .collect();
    let (b, hp, vp) = boxes
        .iter()
        .find(|c| inside(&c.0) && clear(&c.0))
        .or_else(|| boxes.iter().find(|c| inside(&c.0)))
        .unwrap_or(&boxes[0]);
    let at = (
        if matches!(hp, HPos::Right) {
            b[2] - 2
        } else {
            b[0] + 2
        },
        if matches!(vp, VPos::Top) {
            b[1] + 1
        } else {
            b[3] - 1
        },
    );
    boxed_text(root, text, at, 12, Pos::new(*hp, *vp), BLACK)?;
    placed.push(*b);
    Ok(())
}

/// The legend in the right margin: modes, corner marker (and the transition and limit-state
/// markers where `marks` says the figure has them), what the tints mean.
fn draw_legend(
    root: &DrawingArea<SVGBackend, Shift>,
    modes: &[CollapseMode],
    arches: usize,
    marks: (bool, bool),
) -> Result<(), String> {
    let lx = W as i32 - RIGHT as i32 + 100;
    let mut ly = legend_modes(root, "collapse mode", modes, (lx, 70))?;
    ly += 30;
    root.draw(&Circle::new((lx + 13, ly + 7), 5, BLACK.filled()))
        .map_err(err)?;
    root.draw(&Text::new("corner (μ, η)", (lx + 34, ly), (FAMILY, 13)))
        .map_err(err)?;
    if marks.0 {
        ly += 24;
        root.draw(&Circle::new((lx + 13, ly + 7), 5, BLACK.stroke_width(2)))
            .map_err(err)?;
        root.draw(&Text::new(
            "smooth transition (no kink)",
            (lx + 34, ly),
            (FAMILY, 13),
        ))
        .map_err(err)?;
    }
    if marks.1 {
        ly += 24;
        root.draw(&TriangleMarker::new(
            (lx + 13, ly + 7),
            6,
            LIMIT_STATE_COLOR.filled(),
        ))
        .map_err(err)?;
        root.draw(&Text::new(
            "limit state above η_s (not safe there)",
            (lx + 34, ly),
            (FAMILY, 13),
        ))
        .map_err(err)?;
    }
    let swatch = |ly: i32, color: RGBColor, opacity: f64, text: &str| {
        legend_swatch(root, (lx, ly), color, opacity, text)
    };
    ly += 30;
    if arches == 1 {
        swatch(ly, SAFE_TINT, SAFE_OPACITY, "safe (above / right)")?;
        swatch(ly + 24, COLLAPSE_TINT, 0.08, "collapse (below / left)")?;
    } else {
        swatch(ly, SAFE_TINT, SAFE_OPACITY, "safe for one arch")?;
        swatch(ly + 24, SAFE_TINT, 2.0 * SAFE_OPACITY, "safe for two, ...")?;
        root.draw(&Text::new(
            "each arch is safe above / right",
            (lx, ly + 52),
            (FAMILY, 12),
        ))
        .map_err(err)?;
        root.draw(&Text::new(
            "of its own curve; white: all collapse",
            (lx, ly + 68),
            (FAMILY, 12),
        ))
        .map_err(err)?;
    }
    Ok(())
}
