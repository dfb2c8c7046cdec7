//! Figure: the load map of the atlas ([`LoadMap`], `atlas --horizontal`): one panel per
//! friction coefficient, the openings α across and the thickness η up (log scale; the cells
//! of an opening at η = f η\*(α, μ), so the coloured area starts at η\*), each cell filled by
//! its answer — λ_c = λ_static (no reduction), a reduction
//! 1 − λ_c/λ_static (a sequential scale, its value written in the cell), no collapse, no
//! ring, not decided — and the boundaries of the reduction bisected along η drawn at their
//! brackets (a tick at each side of the cell where the bracket closed, a vertical bar over
//! the stretch left where the bisection stopped).

use crate::atlas::loads::{CellAnswer, LoadBoundary, LoadCell, LoadMap};
use crate::render::plot::{cell_edges, legend_swatch, short_trimmed, Axis, AxisCoord, FAMILY};
use plotters::coord::Shift;
use plotters::prelude::*;
use plotters::style::text_anchor::{HPos, Pos, VPos};

const W: u32 = 1000;
/// The height of one μ's panel.
const PANEL: u32 = 360;
/// The band above the panels (the title).
const TITLE: u32 = 40;
/// The column right of the panels (legend and colour bar).
const RIGHT: u32 = 210;

/// λ_c = λ_static: the load's limit state is its static maximum.
pub const NOT_REDUCED: RGBColor = RGBColor(199, 233, 192);
/// The load drives no mechanism.
pub const NO_COLLAPSE: RGBColor = RGBColor(158, 202, 225);
/// No ring of the map (no η\*, or η at its limit).
pub const NO_RING: RGBColor = RGBColor(255, 255, 255);
/// The survey reached no decision.
pub const UNDECIDED: RGBColor = RGBColor(200, 200, 200);

/// The colour of a reduction `r` on a scale whose darkest end is `top`.
fn reduction_color(r: f64, top: f64) -> RGBColor {
    let t = (r / top).clamp(0.0, 1.0);
    let mix = |a: u8, b: u8| (a as f64 + (b as f64 - a as f64) * t).round() as u8;
    RGBColor(mix(254, 165), mix(217, 15), mix(118, 21))
}

/// The fill of a cell, on a reduction scale ending at `top`.
fn cell_color(c: &LoadCell, top: f64) -> RGBColor {
    match &c.answer {
        CellAnswer::Ratio { .. } if c.reduced() => reduction_color(c.reduction().unwrap(), top),
        CellAnswer::Ratio { .. } => NOT_REDUCED,
        CellAnswer::NoCollapse => NO_COLLAPSE,
        CellAnswer::NoRing => NO_RING,
        CellAnswer::Undecided(_) => UNDECIDED,
    }
}

/// The end of the reduction scale: the largest reduction of the map rounded up to a
/// multiple of 5 % (5 % where none is larger).
fn scale_top(map: &LoadMap) -> f64 {
    let most = map
        .cells
        .iter()
        .filter(|c| c.reduced())
        .filter_map(LoadCell::reduction)
        .fold(0.0, f64::max);
    ((most / 0.05 - 1e-9).ceil() * 0.05).max(0.05)
}

fn err(e: impl std::fmt::Display) -> String {
    e.to_string()
}

type Chart<'a, 'b> = ChartContext<'a, SVGBackend<'b>, Cartesian2d<AxisCoord, AxisCoord>>;

/// The axes of one μ's panel and the edges of its cells: opening α across and, up (log
/// scale), the thickness factor f or (`by_eta`) the thickness η = f η\*(α, μ); an
/// opening's cells reach midway between its thicknesses.
struct Frame {
    by_eta: bool,
    alpha: Axis,
    up: Axis,
    alpha_edges: Vec<f64>,
    factor_edges: Vec<f64>,
    /// What each opening's factors are multiplied by up the axis: η\*(α, μ) by η (`None`
    /// where the opening has no ring: no η\* to scale), else 1.
    scales: Vec<Option<f64>>,
}

impl Frame {
    fn new(map: &LoadMap, mu: f64, by_eta: bool) -> Frame {
        let (ae, fe) = (
            cell_edges(&map.alphas, false),
            cell_edges(&map.factors, true),
        );
        let scales: Vec<Option<f64>> = map
            .alphas
            .iter()
            .map(|&a| match by_eta {
                true => map
                    .at(mu)
                    .find(|c| c.alpha == a && c.eta.is_some())
                    .map(|c| c.eta.unwrap() / c.factor),
                false => Some(1.0),
            })
            .collect();
        let (lo, hi) = scales
            .iter()
            .flatten()
            .fold((f64::INFINITY, 0.0f64), |(l, h), s| {
                (l.min(fe[0] * s), h.max(fe[fe.len() - 1] * s))
            });
        let (lo, hi) = match (by_eta, lo < hi) {
            (true, true) => (lo, hi.min(2.0)),
            (true, false) => (0.1, 2.0),
            (false, _) => (fe[0], fe[fe.len() - 1]),
        };
        Frame {
            by_eta,
            alpha: Axis {
                lo: ae[0],
                hi: ae[ae.len() - 1],
                log: false,
            },
            up: Axis { lo, hi, log: true },
            alpha_edges: ae,
            factor_edges: fe,
            scales,
        }
    }

    /// The chart point at `alpha` of the factor `factor` of the opening with index `i`.
    fn at(&self, i: usize, alpha: f64, factor: f64) -> Option<(f64, f64)> {
        let y = factor * self.scales[i]?;
        Some((
            self.alpha.to(alpha),
            self.up.to(y.clamp(self.up.lo, self.up.hi)),
        ))
    }
}

/// Draws the load map, up the thickness factor η/η\*(α, μ), or the thickness η itself
/// (`by_eta`: a change at one η across openings then lies level).
pub fn svg(map: &LoadMap, by_eta: bool) -> Result<String, String> {
    if map.alphas.len() < 2 || map.factors.len() < 2 {
        return Err("a load map needs at least 2 openings and 2 thicknesses".into());
    }
    let top = scale_top(map);
    let mus = &map.grid.mus;
    let h = TITLE + PANEL * mus.len() as u32;
    let mut buf = String::new();
    {
        let root = SVGBackend::with_string(&mut buf, (W, h)).into_drawing_area();
        root.fill(&WHITE).map_err(err)?;
        let r = &map.grid.rect;
        let title = format!(
            "Load map: λ_c / λ_static of a horizontal acceleration, symmetric arches, {}, weight along the {}",
            r.blocks
                .map_or("continuous joints".into(), |n| format!("{n} voussoirs")),
            r.weight.name()
        );
        let (head, body) = root.split_vertically(TITLE);
        head.titled(&title, (FAMILY, 17)).map_err(err)?;
        let (panels, side) = body.split_horizontally(W - RIGHT);
        for (area, &mu) in panels.split_evenly((mus.len(), 1)).iter().zip(mus) {
            panel(area, &Frame::new(map, mu, by_eta), map, mu, top)?;
        }
        legend(&side, map, top)?;
        root.present().map_err(err)?;
    }
    Ok(buf)
}

/// The caption of the panel at `mu`: its cells, the reduced ones and the largest.
fn caption(map: &LoadMap, mu: f64) -> String {
    let answered = map.at(mu).filter(|c| c.ratio().is_some()).count();
    let reduced = map.at(mu).filter(|c| c.reduced()).count();
    let head = format!(
        "μ = {}: λ_c < λ_static in {reduced} of {answered} cells",
        short_trimmed(mu)
    );
    let cells = match map.largest(mu) {
        Some(c) => format!(
            "{head}, most {}{:.1} % (α = {}, η = {})",
            if c.at_least() { "≥ " } else { "" },
            100.0 * c.reduction().unwrap(),
            short_trimmed(c.alpha),
            short_trimmed(c.eta.unwrap_or(f64::NAN))
        ),
        None => head,
    };
    match map.largest_at_boundary(mu) {
        Some(b) => format!(
            "{cells}; {}{:.1} % at a boundary (α = {})",
            if b.at_least { "≥ " } else { "" },
            100.0 * b.reduction,
            short_trimmed(b.alpha)
        ),
        None => cells,
    }
}

/// One μ's panel: the cells, the reductions written in, the boundaries, the axes.
fn panel(
    area: &DrawingArea<SVGBackend, Shift>,
    f: &Frame,
    map: &LoadMap,
    mu: f64,
    top: f64,
) -> Result<(), String> {
    let mut ch = ChartBuilder::on(area)
        .caption(caption(map, mu), (FAMILY, 15))
        .margin(12)
        .margin_right(20)
        .x_label_area_size(48)
        .y_label_area_size(70)
        .build_cartesian_2d(f.alpha.range(), f.up.range())
        .map_err(err)?;
    let (ae, fe) = (&f.alpha_edges, &f.factor_edges);
    for c in map.at(mu) {
        let i = map.alphas.iter().position(|&a| a == c.alpha).unwrap_or(0);
        let j = map.factors.iter().position(|&x| x == c.factor).unwrap_or(0);
        let (Some(p0), Some(p1)) = (f.at(i, ae[i], fe[j]), f.at(i, ae[i + 1], fe[j + 1])) else {
            continue;
        };
        let color = cell_color(c, top);
        // the outline in the same colour closes the anti-aliasing seams
        ch.draw_series([
            Rectangle::new([p0, p1], color.filled()),
            Rectangle::new([p0, p1], color.stroke_width(1)),
        ])
        .map_err(err)?;
        if let (true, Some(at)) = (c.reduced(), f.at(i, c.alpha, c.factor)) {
            percent(&mut ch, c, at, top)?;
        }
    }
    for b in map.boundaries.iter().filter(|b| b.mu == mu) {
        boundary(&mut ch, f, map, b)?;
    }
    ch.configure_mesh()
        .disable_mesh()
        .x_desc("opening α (rad)")
        .y_desc(if f.by_eta {
            "thickness ratio η = t / r (log scale)"
        } else {
            "η / η*(α, μ) (log scale)"
        })
        .x_label_formatter(&|u| f.alpha.label(*u))
        .y_label_formatter(&|u| f.up.label(*u))
        .label_style((FAMILY, 12))
        .axis_desc_style((FAMILY, 14))
        .draw()
        .map_err(err)?;
    Ok(())
}

/// The reduction of cell `c` written at its centre `at`, in per cent (white on the darker
/// half of the scale ending at `top`).
fn percent(ch: &mut Chart, c: &LoadCell, at: (f64, f64), top: f64) -> Result<(), String> {
    let r = c.reduction().unwrap_or(0.0);
    let ink = if r > 0.6 * top { WHITE } else { BLACK };
    let style = TextStyle::from((FAMILY, 11).into_font())
        .pos(Pos::new(HPos::Center, VPos::Center))
        .color(&ink);
    // a survey that did not settle: at least this much
    let text = format!("{}{:.1}", if c.at_least() { "≥" } else { "" }, 100.0 * r);
    ch.draw_series(std::iter::once(Text::new(text, at, style)))
        .map_err(err)?;
    Ok(())
}

/// The part of a cell's width each tick of a boundary covers, from its side.
const TICK: f64 = 0.22;

/// A boundary of the reduction at its opening: a tick at each side of the opening's cell at
/// the bracket where it closed, or a vertical bar over the bracket left where it stopped.
fn boundary(ch: &mut Chart, f: &Frame, map: &LoadMap, b: &LoadBoundary) -> Result<(), String> {
    let i = map.alphas.iter().position(|&a| a == b.alpha).unwrap_or(0);
    let (lo, hi) = b.factors;
    let (l, r) = (f.alpha_edges[i], f.alpha_edges[i + 1]);
    let w = TICK * (r - l);
    let y = (lo * hi).sqrt();
    let lines = if b.stopped.is_none() {
        // a tick at each side of the cell, leaving its middle to the reduction's value
        vec![[(l, y), (l + w, y)], [(r - w, y), (r, y)]]
    } else {
        vec![[(b.alpha, lo), (b.alpha, hi)]]
    };
    for [p, q] in lines {
        if let (Some(p), Some(q)) = (f.at(i, p.0, p.1), f.at(i, q.0, q.1)) {
            ch.draw_series(std::iter::once(PathElement::new(
                vec![p, q],
                BLACK.stroke_width(3),
            )))
            .map_err(err)?;
        }
    }
    Ok(())
}

/// The legend of the fills and the boundaries, and the colour bar of the reductions.
fn legend(area: &DrawingArea<SVGBackend, Shift>, map: &LoadMap, top: f64) -> Result<(), String> {
    let (lx, mut ly) = (8, 20);
    area.draw(&Text::new("cells", (lx, ly), (FAMILY, 14)))
        .map_err(err)?;
    let has = |p: fn(&CellAnswer) -> bool| map.cells.iter().any(|c| p(&c.answer));
    let rows = [
        (NOT_REDUCED, "λ_c = λ_static", true),
        (
            NO_COLLAPSE,
            "no collapse (no limit state)",
            has(|a| matches!(a, CellAnswer::NoCollapse)),
        ),
        (
            NO_RING,
            "no ring (μ < μ_ms, or η ≥ 1.9)",
            has(|a| matches!(a, CellAnswer::NoRing)),
        ),
        (
            UNDECIDED,
            "not decided",
            has(|a| matches!(a, CellAnswer::Undecided(_))),
        ),
    ];
    for (color, text, shown) in rows {
        if shown {
            ly += 22;
            legend_swatch(area, (lx, ly), color, 1.0, text)?;
            area.draw(&Rectangle::new(
                [(lx + 2, ly + 1), (lx + 24, ly + 14)],
                RGBColor(120, 120, 120).stroke_width(1),
            ))
            .map_err(err)?;
        }
    }
    let stopped = map.boundaries.iter().any(|b| b.stopped.is_some());
    if !map.boundaries.is_empty() {
        let rows = [
            ("a reduction begins or ends", false),
            ("  (bracket where it stopped)", true),
        ];
        for (text, vertical) in rows.into_iter().filter(|r| stopped || !r.1) {
            ly += 22;
            let segs = if vertical {
                vec![vec![(lx + 13, ly - 2), (lx + 13, ly + 16)]]
            } else {
                vec![
                    vec![(lx + 2, ly + 7), (lx + 9, ly + 7)],
                    vec![(lx + 17, ly + 7), (lx + 24, ly + 7)],
                ]
            };
            for seg in segs {
                area.draw(&PathElement::new(seg, BLACK.stroke_width(3)))
                    .map_err(err)?;
            }
            area.draw(&Text::new(text, (lx + 34, ly), (FAMILY, 13)))
                .map_err(err)?;
        }
    }
    colour_bar(area, (lx, ly + 44), top)
}

/// The colour bar of the reduction 1 − λ_c/λ_static, in per cent, from 0 to `top`.
fn colour_bar(
    area: &DrawingArea<SVGBackend, Shift>,
    (x, y): (i32, i32),
    top: f64,
) -> Result<(), String> {
    area.draw(&Text::new(
        "reduction 1 − λ_c/λ_static (%)",
        (x, y - 22),
        (FAMILY, 13),
    ))
    .map_err(err)?;
    let (steps, h) = (20, 8);
    for k in 0..steps {
        let v = top * (steps - k) as f64 / steps as f64;
        let y0 = y + k * h;
        area.draw(&Rectangle::new(
            [(x + 2, y0), (x + 24, y0 + h)],
            reduction_color(v, top).filled(),
        ))
        .map_err(err)?;
    }
    area.draw(&Rectangle::new(
        [(x + 2, y), (x + 24, y + steps * h)],
        BLACK.stroke_width(1),
    ))
    .map_err(err)?;
    let label = TextStyle::from((FAMILY, 12).into_font()).pos(Pos::new(HPos::Left, VPos::Center));
    for (v, at) in [
        (top, y),
        (0.5 * top, y + steps * h / 2),
        (0.0, y + steps * h),
    ] {
        area.draw(&Text::new(
            format!("{:.1}", 100.0 * v),
            (x + 30, at),
            label.clone(),
        ))
        .map_err(err)?;
    }
    Ok(())
}
