//! Figure: the atlas of uniqueness ([`Atlas`]) over openings α (across) and μ/μ_ms − 1 (up,
//! log scale: the non-unique band lies within a few per cent above μ_ms): each region filled
//! in the colour of its kind, the located boundary points in black, stretches the search
//! did not decide left grey. Below the axis (μ < μ_ms) no thickness stands.

use crate::atlas::{Atlas, Kind, FIRST_OFFSET};
use crate::render::fine::Fine;
use crate::render::plot::{Axis, AxisCoord, FAMILY};
use plotters::prelude::*;

const W: u32 = 1000;
const H: u32 = 620;

/// The fill of a kind.
fn kind_color(k: Kind) -> RGBColor {
    match k {
        Kind::Unique => RGBColor(199, 233, 192),
        Kind::NonUnique => RGBColor(227, 74, 51),
        Kind::NoMechanismAtEta => RGBColor(107, 174, 214),
        Kind::NoEquilibrium => RGBColor(255, 255, 255),
    }
}

/// Where the search did not decide (no region covers it).
const UNDECIDED: RGBColor = RGBColor(200, 200, 200);

fn err(e: impl std::fmt::Display) -> String {
    e.to_string()
}

/// Draws the atlas.
pub fn svg(a: &Atlas) -> Result<String, String> {
    let r = &a.rectangle;
    if a.curve.len() < 2 {
        return Err("no opening of the rectangle has a finite mu_ms".into());
    }
    let (x, y) = (
        Axis {
            lo: r.alpha_min,
            hi: r.alpha_max,
            log: false,
        },
        Axis {
            lo: FIRST_OFFSET,
            hi: r.mu_max_factor - 1.0,
            log: true,
        },
    );
    let at = |p: [f64; 2]| {
        let d = (p[1] / a.mu_ms_at(p[0]) - 1.0).clamp(y.lo, y.hi);
        (x.to(p[0]), y.to(d))
    };
    let mut buf = String::new();
    let fine = Fine::default();
    {
        let root = SVGBackend::with_string(&mut buf, (W, H)).into_drawing_area();
        root.fill(&WHITE).map_err(err)?;
        let title = format!(
            "Atlas of uniqueness: symmetric arches, {}, weight along the {}",
            r.blocks
                .map_or("continuous joints".into(), |n| format!("{n} voussoirs")),
            r.weight.name()
        );
        let mut ch = ChartBuilder::on(&root)
            .caption(title, (FAMILY, 18))
            .margin(16)
            .margin_right(28)
            .x_label_area_size(64)
            .y_label_area_size(84)
            .build_cartesian_2d(x.range(), y.range())
            .map_err(err)?;
        ch.plotting_area().fill(&UNDECIDED).map_err(err)?;
        for (k, poly) in a.regions.iter().filter(|(k, _)| *k != Kind::NoEquilibrium) {
            let pts: Vec<(f64, f64)> = poly.iter().map(|&p| at(p)).collect();
            let c = kind_color(*k);
            fine.polygon(&ch, &pts, c.filled())?;
            let mut edge = pts.clone();
            edge.extend(pts.first());
            fine.polyline(&ch, &edge, c.stroke_width(1), None)?;
        }
        // one legend entry per kind drawn (and grey where the search did not decide)
        let mut kinds: Vec<Kind> = a
            .regions
            .iter()
            .map(|r| r.0)
            .filter(|k| *k != Kind::NoEquilibrium)
            .collect();
        kinds.sort();
        kinds.dedup();
        let undecided = a
            .columns
            .iter()
            .flat_map(|c| &c.runs)
            .any(|r| r.0.is_none());
        let entries = kinds
            .iter()
            .map(|k| (k.name().to_string(), kind_color(*k)))
            .chain(undecided.then(|| ("not decided".to_string(), UNDECIDED)));
        for (name, c) in entries {
            ch.draw_series(std::iter::empty::<Circle<(f64, f64), i32>>())
                .map_err(err)?
                .label(name)
                .legend(move |(px, py)| {
                    Rectangle::new([(px, py - 6), (px + 14, py + 6)], c.filled())
                });
        }
        points(&mut ch, a, &at, (x, y))?;
        ch.configure_mesh()
            .disable_mesh()
            .x_desc("opening α (rad)   (below the axis, μ < μ_ms: no equilibrium)")
            .y_desc("μ / μ_ms(α) − 1 (log scale)")
            .x_label_formatter(&|u| x.label(*u))
            .y_label_formatter(&|u| format!("{:.0e}", y.from(*u)))
            .label_style((FAMILY, 15))
            .axis_desc_style((FAMILY, 16))
            .draw()
            .map_err(err)?;
        ch.configure_series_labels()
            .position(SeriesLabelPosition::LowerLeft)
            .background_style(WHITE.mix(0.9))
            .border_style(BLACK)
            .label_font((FAMILY, 14))
            .draw()
            .map_err(err)?;
        root.present().map_err(err)?;
    }
    Ok(fine.finish(&buf))
}

/// The boundary points (filled where solved from what ends the branch, open where a bracket
/// of the decided kinds) and the top of the band, with their legend entries.
fn points(
    ch: &mut ChartContext<'_, SVGBackend<'_>, Cartesian2d<AxisCoord, AxisCoord>>,
    a: &Atlas,
    at: &dyn Fn([f64; 2]) -> (f64, f64),
    (x, y): (Axis, Axis),
) -> Result<(), String> {
    // boundary points: filled where solved from what ends the branch, open where a
    // bracket of the decided kinds
    let points: Vec<_> = a.columns.iter().flat_map(|c| &c.boundaries).collect();
    for (exact, name) in [
        (true, "change of kind, solved"),
        (false, "change of kind, bracketed"),
    ] {
        let style = if exact {
            BLACK.filled()
        } else {
            BLACK.stroke_width(1)
        };
        let these: Vec<(f64, f64)> = points
            .iter()
            .filter(|p| p.exact() == exact)
            .map(|p| at([p.alpha, p.mu()]))
            .collect();
        if these.is_empty() {
            continue;
        }
        ch.draw_series(these.into_iter().map(|q| Circle::new(q, 3, style)))
            .map_err(err)?
            .label(name)
            .legend(move |(px, py)| Circle::new((px + 7, py), 3, style));
    }
    if let Some(t) = &a.top {
        let q = (x.to(t.alpha), y.to((t.ratio - 1.0).clamp(y.lo, y.hi)));
        let mark = TriangleMarker::new(q, 7, BLACK.filled());
        ch.draw_series(std::iter::once(mark))
            .map_err(err)?
            .label(format!(
                "top of the band: μ/μ_ms = {:.6} at α = {:.6}",
                t.ratio, t.alpha
            ))
            .legend(|(px, py)| TriangleMarker::new((px + 7, py), 6, BLACK.filled()));
    }
    Ok(())
}
