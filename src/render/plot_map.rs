//! Figure: the admissibility margin ([`MapData`], see [`crate::figures::margin_map`]) over
//! the η–μ plane as filled bands (log axis for μ, optionally for η), with the exact limit
//! curve overlaid in black and a colour bar that gives the value of each band.

use crate::figures::MapData;
use crate::render::fine::Fine;
use crate::render::plot::{arch_label, cell_edges, Axis, AxisCoord, FAMILY};
use plotters::coord::Shift;
use plotters::prelude::*;
use plotters::style::text_anchor::{HPos, Pos, VPos};

/// Bands on each side of zero.
const BANDS: usize = 5;
/// Colour of cells where the LP failed.
pub const NAN_COLOR: RGBColor = RGBColor(220, 220, 220);
const W: u32 = 1000;
const H: u32 = 640;
const RIGHT: u32 = 150;

/// The band of `v` (0 ..= BANDS − 1) on its side of zero.
fn band(v: f64, vmax: f64) -> usize {
    ((v.abs() / vmax * BANDS as f64).floor() as usize).min(BANDS - 1)
}

/// The colour of band `k` on the safe (`v ≥ 0`, greens) or collapse (blues) side.
fn band_color(k: usize, safe: bool) -> RGBColor {
    let t = k as f64 / (BANDS - 1) as f64;
    let mix = |a: u8, b: u8| (a as f64 + (b as f64 - a as f64) * t) as u8;
    if safe {
        RGBColor(mix(229, 0), mix(245, 109), mix(224, 44))
    } else {
        RGBColor(mix(222, 33), mix(235, 102), mix(247, 172))
    }
}

fn value_color(v: f64, vmax_pos: f64, vmax_neg: f64) -> RGBColor {
    if v.is_nan() {
        NAN_COLOR
    } else if v < 0.0 {
        band_color(band(v, vmax_neg), false)
    } else {
        band_color(band(v, vmax_pos), true)
    }
}

fn err(e: impl std::fmt::Display) -> String {
    e.to_string()
}

type Chart<'a, 'b> = ChartContext<'a, SVGBackend<'b>, Cartesian2d<AxisCoord, AxisCoord>>;

/// The axes of the map and the edges of its cells.
struct Frame {
    mu: Axis,
    eta: Axis,
    /// Cell edges in μ and in η.
    mu_edges: Vec<f64>,
    eta_edges: Vec<f64>,
}

impl Frame {
    fn new(map: &MapData, log_eta: bool) -> Frame {
        let (me, ee) = (
            cell_edges(&map.mus, true),
            cell_edges(&map.etas, map.log_eta),
        );
        Frame {
            mu: Axis {
                lo: me[0],
                hi: me[me.len() - 1],
                log: true,
            },
            eta: Axis {
                lo: if log_eta { ee[0] } else { ee[0].max(0.0) },
                hi: ee[ee.len() - 1],
                log: log_eta,
            },
            mu_edges: me,
            eta_edges: ee,
        }
    }

    /// The chart coordinates of (μ, η), η clamped to the axis.
    fn at(&self, mu: f64, eta: f64) -> (f64, f64) {
        (self.mu.to(mu), self.eta.to(eta.max(self.eta.lo)))
    }
}

/// Draws the map (`values[i][j]` at the cell centred on (`etas[i]`, `mus[j]`)); `log_eta`
/// puts η on a log scale.
pub fn svg(map: &MapData, log_eta: bool) -> Result<String, String> {
    if map.etas.len() < 2 || map.mus.len() < 2 {
        return Err("a map needs at least 2 x 2 cells".into());
    }
    let finite = || {
        map.values
            .iter()
            .flatten()
            .copied()
            .filter(|v| v.is_finite())
    };
    let vmax_pos = finite().fold(0.0f64, f64::max).max(f64::MIN_POSITIVE);
    let vmax_neg = finite()
        .fold(0.0f64, |m, v| m.max(-v))
        .max(f64::MIN_POSITIVE);
    let f = Frame::new(map, log_eta);
    let mut buf = String::new();
    let fine = Fine::default();
    {
        let root = SVGBackend::with_string(&mut buf, (W, H)).into_drawing_area();
        root.fill(&WHITE).map_err(err)?;
        let mut ch = ChartBuilder::on(&root)
            .caption(
                format!(
                    "Admissibility margin, {}: safe where > 0, collapse where < 0",
                    arch_label(&map.curve.arch)
                ),
                (FAMILY, 17),
            )
            .margin(14)
            .margin_right(RIGHT)
            .x_label_area_size(50)
            .y_label_area_size(70)
            .build_cartesian_2d(f.mu.range(), f.eta.range())
            .map_err(err)?;
        draw_cells(&mut ch, &f, map, vmax_pos, vmax_neg)?;
        ch.configure_mesh()
            .disable_mesh()
            .x_desc("friction coefficient μ   (labels: μ (φ))")
            .y_desc(if log_eta {
                "thickness ratio η = t / r (log scale)"
            } else {
                "thickness ratio η = t / r"
            })
            .x_label_formatter(&|u| f.mu.mu_label(*u))
            .y_label_formatter(&|u| f.eta.label(*u))
            .label_style((FAMILY, 12))
            .axis_desc_style((FAMILY, 14))
            .draw()
            .map_err(err)?;
        draw_curve(&mut ch, &f, map, &fine)?;
        ch.configure_series_labels()
            .position(SeriesLabelPosition::LowerRight)
            .background_style(WHITE.mix(0.9))
            .border_style(BLACK)
            .label_font((FAMILY, 12))
            .draw()
            .map_err(err)?;
        let (xr, yr) = ch.plotting_area().get_pixel_range();
        colour_bar(&root, xr.end + 30, yr, vmax_pos, vmax_neg)?;
        root.present().map_err(err)?;
    }
    Ok(fine.finish(&buf))
}

/// Every cell filled with the colour of its band.
fn draw_cells(
    ch: &mut Chart,
    f: &Frame,
    map: &MapData,
    vmax_pos: f64,
    vmax_neg: f64,
) -> Result<(), String> {
    let (me, ee) = (&f.mu_edges, &f.eta_edges);
    for (i, row) in map.values.iter().enumerate() {
        for (j, &v) in row.iter().enumerate() {
            let (corners, color) = (
                [f.at(me[j], ee[i]), f.at(me[j + 1], ee[i + 1])],
                value_color(v, vmax_pos, vmax_neg),
            );
            // the outline in the same colour closes the anti-aliasing seams
            ch.draw_series([
                Rectangle::new(corners, color.filled()),
                Rectangle::new(corners, color.stroke_width(1)),
            ])
            .map_err(err)?;
        }
    }
    Ok(())
}

/// The exact limit curve over the map (with its vertical sliding branch) and its corners.
fn draw_curve(ch: &mut Chart, f: &Frame, map: &MapData, fine: &Fine) -> Result<(), String> {
    let d = &map.curve;
    let mut pts: Vec<(f64, f64)> = d
        .outline()
        .into_iter()
        .filter(|p| p.0 >= f.mu.lo && p.0 <= f.mu.hi)
        .collect();
    if let Some(&(_, eta_ms)) = pts.last() {
        pts.push((d.mu_ms, eta_ms));
        pts.push((d.mu_ms, f.eta.hi));
    }
    let line: Vec<(f64, f64)> = pts.into_iter().map(|p| f.at(p.0, p.1)).collect();
    fine.polyline(ch, &line, BLACK.stroke_width(3), None)?;
    ch.draw_series(LineSeries::new(Vec::<(f64, f64)>::new(), BLACK))
        .map_err(err)?
        .label("exact limit curve η*(μ)")
        .legend(|(x, y)| PathElement::new(vec![(x, y), (x + 22, y)], BLACK.stroke_width(3)));
    for &(mu, eta) in &d.corners {
        ch.draw_series(std::iter::once(Circle::new(
            f.at(mu, eta),
            5,
            BLACK.filled(),
        )))
        .map_err(err)?;
    }
    Ok(())
}

/// The colour bar: the safe bands (greens) above zero, the collapse bands (blues) below,
/// each edge labelled with its value in one format, titled with the quantity and its units.
fn colour_bar(
    root: &DrawingArea<SVGBackend, Shift>,
    x: i32,
    yr: std::ops::Range<i32>,
    vmax_pos: f64,
    vmax_neg: f64,
) -> Result<(), String> {
    let (top, bottom) = (yr.start + 42, yr.end - 10);
    let h = (bottom - top) as f64 / (2 * BANDS) as f64;
    let y_of = |k: usize| top + (k as f64 * h).round() as i32;
    let mut labels = Vec::new();
    for k in 0..2 * BANDS {
        // from the top: safe bands BANDS-1 .. 0, then collapse bands 0 .. BANDS-1
        let (color, lo_edge) = if k < BANDS {
            let b = BANDS - 1 - k;
            (
                band_color(b, true),
                (b + 1) as f64 / BANDS as f64 * vmax_pos,
            )
        } else {
            let b = k - BANDS;
            (band_color(b, false), -(b as f64) / BANDS as f64 * vmax_neg)
        };
        root.draw(&Rectangle::new(
            [(x, y_of(k)), (x + 22, y_of(k + 1))],
            color.filled(),
        ))
        .map_err(err)?;
        labels.push((y_of(k), lo_edge));
    }
    labels.push((y_of(2 * BANDS), -vmax_neg));
    root.draw(&Rectangle::new(
        [(x, top), (x + 22, bottom)],
        BLACK.stroke_width(1),
    ))
    .map_err(err)?;
    // one format for all labels: enough decimals for the finer of the two steps
    let step = (vmax_pos.min(vmax_neg) / BANDS as f64).max(f64::MIN_POSITIVE);
    let d = ((-(step.log10()).floor()) as i32 + 1).clamp(0, 8) as usize;
    for (y, v) in labels {
        let v = if v.abs() < step * 1e-9 { 0.0 } else { v };
        root.draw(&Text::new(
            format!("{v:+.d$}"),
            (x + 27, y),
            TextStyle::from((FAMILY, 11).into_font()).pos(Pos::new(HPos::Left, VPos::Center)),
        ))
        .map_err(err)?;
    }
    for (i, line) in ["margin [–]", "(h, v, w)-distance", "÷ (β_L − β_R)"]
        .iter()
        .enumerate()
    {
        root.draw(&Text::new(
            line.to_string(),
            (x - 8, yr.start - 6 + 13 * i as i32),
            (FAMILY, 11),
        ))
        .map_err(err)?;
    }
    Ok(())
}
