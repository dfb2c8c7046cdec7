//! Figure: the influence line of a vehicle crossing the arch — the collapse multiplier λ_c
//! (the adequacy factor) against the road position X of its first axle, sampled (dots,
//! joined), every refined local minimum marked, the critical position X* labelled, its
//! mirror tie (a symmetric arch under a symmetric vehicle) hollow — above the arch at X*
//! with the vehicle, the lines of thrust and the collapse mechanism.

use crate::bridge::critical::Critical;
use crate::figures::ArchScene;
use crate::render::fine::Fine;
use crate::render::plot::{short_num, Axis, AxisCoord, FAMILY};
use plotters::prelude::*;

/// The width of the arch figures it stacks above.
const W: u32 = 960;
const H: u32 = 520;
/// Colour of the critical position.
const CRITICAL: RGBColor = RGBColor(214, 39, 40);
/// Colour of the other local minima.
const MINIMUM: RGBColor = RGBColor(31, 119, 180);

type Chart<'a, 'b> = ChartContext<'a, SVGBackend<'b>, Cartesian2d<AxisCoord, AxisCoord>>;

fn err(e: impl std::fmt::Display) -> String {
    e.to_string()
}

/// The influence line under `title`, and beneath it the arch at X* (`scene`, labelled),
/// with `vehicle_kn` the vehicle's total for the label in kN.
pub fn svg(
    title: &str,
    c: &Critical,
    vehicle_kn: Option<f64>,
    scene: Option<(String, &ArchScene)>,
) -> Result<String, String> {
    let line = chart_svg(title, c, vehicle_kn)?;
    let mut panels = vec![(String::new(), line)];
    if let Some((label, scene)) = scene {
        panels.push((label, super::plot_arch::svg(scene)?));
    }
    super::plot_arch::stack(&panels)
}

fn chart_svg(title: &str, c: &Critical, vehicle_kn: Option<f64>) -> Result<String, String> {
    let best = c
        .minima
        .first()
        .ok_or("no finite collapse multiplier on the crossing")?;
    let finite: Vec<(f64, f64)> = c
        .influence
        .iter()
        .map(|p| (p.at_m, p.collapse.value()))
        .filter(|p| p.1.is_finite())
        .collect();
    let (x_lo, x_hi) = (
        c.influence.first().map_or(0.0, |p| p.at_m),
        c.influence.last().map_or(1.0, |p| p.at_m),
    );
    // λ_c grows without bound where the vehicle leaves the ring: the axis shows up to six
    // times the critical value, larger samples run off the top
    let top = finite
        .iter()
        .map(|p| p.1)
        .fold(best.lambda, f64::max)
        .min(6.0 * best.lambda);
    let x_ax = Axis {
        lo: x_lo,
        hi: x_hi,
        log: false,
    };
    let y_ax = Axis {
        lo: 0.0,
        hi: top * 1.1,
        log: false,
    };
    let mut buf = String::new();
    let fine = Fine::default();
    {
        let root = SVGBackend::with_string(&mut buf, (W, H)).into_drawing_area();
        root.fill(&WHITE).map_err(err)?;
        let mut chart = ChartBuilder::on(&root)
            .caption(title, (FAMILY, 20))
            .margin(16)
            .margin_right(40)
            .x_label_area_size(56)
            .y_label_area_size(80)
            .build_cartesian_2d(x_ax.range(), y_ax.range())
            .map_err(err)?;
        chart
            .configure_mesh()
            .x_desc("road position X of the first axle (m from the left intrados springing)")
            .y_desc("collapse multiplier λ_c (adequacy factor)")
            .x_label_formatter(&|u| x_ax.label(*u))
            .y_label_formatter(&|u| y_ax.label(*u))
            .label_style((FAMILY, 13))
            .axis_desc_style((FAMILY, 15))
            .draw()
            .map_err(err)?;
        draw_line(&mut chart, c, top * 1.1, &fine)?;
        draw_minima(&mut chart, c, vehicle_kn, top)?;
        root.present().map_err(err)?;
    }
    Ok(fine.finish(&buf))
}

/// The sampled line: joined where consecutive samples are on the chart (a sample above it,
/// with no collapse or undecided breaks the line), dots at each.
fn draw_line(chart: &mut Chart, c: &Critical, top: f64, fine: &Fine) -> Result<(), String> {
    let mut pieces: Vec<Vec<(f64, f64)>> = vec![Vec::new()];
    for p in &c.influence {
        let v = p.collapse.value();
        if v <= top {
            pieces.last_mut().expect("one").push((p.at_m, v));
        } else if !pieces.last().expect("one").is_empty() {
            pieces.push(Vec::new());
        }
    }
    for piece in pieces.iter().filter(|p| p.len() > 1) {
        fine.polyline(chart, piece, BLACK.stroke_width(2), None)?;
    }
    chart
        .draw_series(
            pieces
                .iter()
                .flatten()
                .map(|&(x, y)| Circle::new((x, y), 3, BLACK.filled())),
        )
        .map_err(err)?;
    Ok(())
}

/// Every refined local minimum (blue), X* (red, labelled) and its mirror tie (hollow red).
fn draw_minima(
    chart: &mut Chart,
    c: &Critical,
    vehicle_kn: Option<f64>,
    top: f64,
) -> Result<(), String> {
    for m in c.minima.iter().skip(1) {
        chart
            .draw_series(std::iter::once(Circle::new(
                (m.at_m, m.lambda),
                6,
                MINIMUM.filled(),
            )))
            .map_err(err)?;
    }
    let best = &c.minima[0];
    chart
        .draw_series(std::iter::once(Circle::new(
            (best.at_m, best.lambda),
            8,
            CRITICAL.filled(),
        )))
        .map_err(err)?;
    if let Some(x) = c.mirror_m {
        chart
            .draw_series(std::iter::once(Circle::new(
                (x, best.lambda),
                8,
                CRITICAL.stroke_width(2),
            )))
            .map_err(err)?;
    }
    let kn = vehicle_kn.map_or(String::new(), |v| {
        format!(" ({} kN)", short_num(v * best.lambda))
    });
    let tie = if c.mirror_m.is_some() {
        ", its mirror ties"
    } else {
        ""
    };
    // the label in the chart's upper left corner, clear of the line (high there only where
    // the vehicle leaves the ring), joined to X* by a thin leader
    let (x0, x1) = c
        .influence
        .first()
        .zip(c.influence.last())
        .map_or((best.at_m, best.at_m), |(a, b)| (a.at_m, b.at_m));
    chart
        .draw_series(std::iter::once(PathElement::new(
            vec![(best.at_m, best.lambda), (best.at_m, 0.97 * top)],
            CRITICAL.mix(0.5).stroke_width(1),
        )))
        .map_err(err)?;
    chart
        .draw_series(std::iter::once(Text::new(
            format!(
                "X* = {} m, λ_c = {}{kn}{tie}",
                short_num(best.at_m),
                short_num(best.lambda)
            ),
            (x0 + 0.03 * (x1 - x0), 1.05 * top),
            (FAMILY, 16).into_font().color(&CRITICAL),
        )))
        .map_err(err)?;
    Ok(())
}
