//! Figure: the load multiplier against friction at a fixed thickness — λ_static (the
//! largest statically admissible multiplier, dashed grey) and the collapse multiplier λ
//! (the least limit state, points coloured by its collapse mode, joined), over a log μ axis,
//! with the μ = ∞ value as a dotted asymptote. Where λ < λ_static non-associative friction
//! lowers the collapse load; the gap is shaded.

use crate::collapse_mode::CollapseMode;
use crate::multiplier::{LoadAnswer, LoadCurve, LoadOutcome};
use crate::render::fine::Fine;
use crate::render::plot::{mode_color, short_num, Axis, AxisCoord, FAMILY};
use plotters::coord::Shift;
use plotters::prelude::*;

const W: u32 = 1100;
const H: u32 = 620;
/// Colour of λ_static.
const STATIC_COLOR: RGBColor = RGBColor(110, 110, 110);
/// Colour of the μ = ∞ asymptote.
const ASYMPTOTE_COLOR: RGBColor = RGBColor(30, 90, 200);
/// λ equal on both sides of a corner to this relative tolerance: no jump.
const CONTINUOUS_TOL: f64 = 1e-9;

type Chart<'a, 'b> = ChartContext<'a, SVGBackend<'b>, Cartesian2d<AxisCoord, AxisCoord>>;

fn err(e: impl std::fmt::Display) -> String {
    e.to_string()
}

/// One sample: μ, λ_static, and the least limit state (λ, mode) where there is one.
type Sample = (f64, Option<f64>, Option<(f64, CollapseMode)>);

fn point((mu, o): &(f64, LoadAnswer)) -> Sample {
    match o {
        Ok(LoadOutcome::Limits(s)) => (
            *mu,
            s.lambda_static.map(|m| m.0),
            s.limit_states.first().map(|l| (l.t, l.mode)),
        ),
        _ => (*mu, None, None),
    }
}

/// Draws the traced curve (samples, a last one at μ = ∞ allowed, and the corners: the
/// answers on both sides of each join the line, which breaks where λ jumps; exact corners
/// are marked) with `title` on top.
pub fn svg(title: &str, curve: &LoadCurve) -> Result<String, String> {
    let seq = sequence(curve);
    let pts: Vec<Sample> = seq.iter().map(|p| p.0).collect();
    let finite: Vec<&Sample> = pts.iter().filter(|p| p.0.is_finite()).collect();
    let at_inf = pts.iter().find(|p| p.0.is_infinite());
    if finite.iter().all(|p| p.1.is_none()) {
        return Err("no sample with a finite static maximum to draw".into());
    }
    let (mu_ax, lam_ax) = axes(&finite, &pts);
    let mut buf = String::new();
    let fine = Fine::default();
    {
        let root = SVGBackend::with_string(&mut buf, (W, H)).into_drawing_area();
        root.fill(&WHITE).map_err(err)?;
        let mut chart = chart(&root, title, &mu_ax, &lam_ax)?;
        draw_gap(&chart, &mu_ax, &finite, &fine)?;
        draw_static(&mut chart, &mu_ax, &finite, &fine)?;
        draw_lambda(&mut chart, &mu_ax, &seq, &fine)?;
        draw_corners(&mut chart, &mu_ax, curve)?;
        draw_modes(&mut chart, &mu_ax, curve)?;
        if let Some((_, Some(s), _)) = at_inf {
            draw_asymptote(&mut chart, &mu_ax, *s)?;
        }
        chart
            .configure_series_labels()
            .position(SeriesLabelPosition::LowerRight)
            .margin(8)
            .border_style(BLACK)
            .background_style(WHITE.mix(0.9))
            .label_font((FAMILY, 13))
            .draw()
            .map_err(err)?;
        root.present().map_err(err)?;
    }
    Ok(fine.finish(&buf))
}

/// The samples and both sides of every corner, by μ; `true` after a corner's below side
/// where λ jumps (the line breaks there).
fn sequence(curve: &LoadCurve) -> Vec<(Sample, bool)> {
    let mut seq: Vec<(Sample, bool)> = curve.samples.iter().map(|s| (point(s), false)).collect();
    for c in &curve.corners {
        let jump = !c.continuous(CONTINUOUS_TOL);
        seq.push((point(c.below()), jump));
        seq.push((point(c.above()), false));
    }
    seq.sort_by(|a, b| a.0 .0.total_cmp(&b.0 .0));
    seq
}

/// The log μ axis over the finite samples, and the λ axis from 0 to above the largest λ.
fn axes(finite: &[&Sample], pts: &[Sample]) -> (Axis, Axis) {
    let (mu_lo, mu_hi) = finite.iter().fold((f64::INFINITY, 0.0f64), |(a, b), p| {
        (a.min(p.0), b.max(p.0))
    });
    let lam_hi = pts
        .iter()
        .filter_map(|p| p.1)
        .fold(0.0f64, f64::max)
        .max(1e-12);
    let mu_ax = Axis {
        lo: mu_lo,
        hi: mu_hi.max(mu_lo * 1.01),
        log: true,
    };
    let lam_ax = Axis {
        lo: 0.0,
        hi: lam_hi * 1.12,
        log: false,
    };
    (mu_ax, lam_ax)
}

/// The chart under its title, with its labelled axes.
fn chart<'a, 'b>(
    root: &'a DrawingArea<SVGBackend<'b>, Shift>,
    title: &str,
    mu_ax: &Axis,
    lam_ax: &Axis,
) -> Result<Chart<'a, 'b>, String> {
    let mut chart = ChartBuilder::on(root)
        .caption(title, (FAMILY, 20))
        .margin(16)
        .margin_right(40)
        .x_label_area_size(56)
        .y_label_area_size(70)
        .build_cartesian_2d(mu_ax.range(), lam_ax.range())
        .map_err(err)?;
    chart
        .configure_mesh()
        .x_desc("friction coefficient μ = tan φ   (labels: μ (φ))")
        .y_desc("load multiplier λ")
        .x_label_formatter(&|u| mu_ax.mu_label(*u))
        .y_label_formatter(&|u| lam_ax.label(*u))
        .label_style((FAMILY, 13))
        .axis_desc_style((FAMILY, 15))
        .draw()
        .map_err(err)?;
    Ok(chart)
}

/// The gap between λ and λ_static, shaded where λ lies below.
fn draw_gap(chart: &Chart, mu_ax: &Axis, finite: &[&Sample], fine: &Fine) -> Result<(), String> {
    for w in finite.windows(2) {
        if let ((m0, Some(s0), Some((l0, _))), (m1, Some(s1), Some((l1, _)))) = (*w[0], *w[1]) {
            if l0 < s0 * (1.0 - 1e-9) || l1 < s1 * (1.0 - 1e-9) {
                let (u0, u1) = (mu_ax.to(m0), mu_ax.to(m1));
                let gap = [(u0, l0), (u1, l1), (u1, s1), (u0, s0)];
                fine.polygon(chart, &gap, RGBColor(214, 39, 40).mix(0.25).filled())?;
            }
        }
    }
    Ok(())
}

/// λ_static, dashed.
fn draw_static(
    chart: &mut Chart,
    mu_ax: &Axis,
    finite: &[&Sample],
    fine: &Fine,
) -> Result<(), String> {
    let stat: Vec<(f64, f64)> = finite
        .iter()
        .filter_map(|p| p.1.map(|s| (mu_ax.to(p.0), s)))
        .collect();
    fine.polyline(chart, &stat, STATIC_COLOR.stroke_width(2), Some((8.0, 5.0)))?;
    chart
        .draw_series(LineSeries::new(Vec::<(f64, f64)>::new(), STATIC_COLOR))
        .map_err(err)?
        .label("λ_static (largest admissible)")
        .legend(|(x, y)| PathElement::new(vec![(x, y), (x + 20, y)], STATIC_COLOR.stroke_width(2)));
    Ok(())
}

/// λ: one polyline per stretch without a jump.
fn draw_lambda(
    chart: &mut Chart,
    mu_ax: &Axis,
    seq: &[(Sample, bool)],
    fine: &Fine,
) -> Result<(), String> {
    let mut pieces: Vec<Vec<(f64, f64)>> = vec![Vec::new()];
    for (p, breaks) in seq.iter().filter(|p| p.0 .0.is_finite()) {
        if let Some((l, _)) = p.2 {
            pieces.last_mut().expect("one").push((mu_ax.to(p.0), l));
        } else if !pieces.last().expect("one").is_empty() {
            pieces.push(Vec::new());
        }
        if *breaks {
            pieces.push(Vec::new());
        }
    }
    for (i, piece) in pieces.into_iter().enumerate() {
        fine.polyline(chart, &piece, BLACK.stroke_width(2), None)?;
        if i == 0 {
            chart
                .draw_series(LineSeries::new(Vec::<(f64, f64)>::new(), BLACK))
                .map_err(err)?
                .label("λ (least limit state: collapse)")
                .legend(|(x, y)| {
                    PathElement::new(vec![(x, y), (x + 20, y)], BLACK.stroke_width(2))
                });
        }
    }
    Ok(())
}

/// The corners: exact ones marked by a cross; a jump by a dotted vertical.
fn draw_corners(chart: &mut Chart, mu_ax: &Axis, curve: &LoadCurve) -> Result<(), String> {
    let mut labelled = false;
    for c in &curve.corners {
        if c.exact && c.above().0.is_finite() {
            let (u, l) = (mu_ax.to(c.mu), c.t);
            let drawn = chart
                .draw_series(std::iter::once(Cross::new(
                    (u, l),
                    6,
                    BLACK.stroke_width(2),
                )))
                .map_err(err)?;
            if !labelled {
                labelled = true;
                drawn
                    .label("exact corner (five contacts, or four sliding, active)")
                    .legend(|(x, y)| Cross::new((x + 10, y), 6, BLACK.stroke_width(2)));
            }
        }
        if let ((Some(a), Some(b)), false, true) = (
            c.lambdas(),
            c.continuous(CONTINUOUS_TOL),
            c.above().0.is_finite(),
        ) {
            let u = mu_ax.to(c.mu);
            chart
                .draw_series(DashedLineSeries::new(
                    vec![(u, a), (u, b)],
                    3,
                    3,
                    BLACK.stroke_width(1),
                ))
                .map_err(err)?;
        }
    }
    Ok(())
}

/// The finite samples' least limit states, coloured by mode, and a legend entry per mode.
fn draw_modes(chart: &mut Chart, mu_ax: &Axis, curve: &LoadCurve) -> Result<(), String> {
    let mut modes: Vec<CollapseMode> = Vec::new();
    for p in curve.samples.iter().map(point).filter(|p| p.0.is_finite()) {
        if let Some((l, m)) = p.2 {
            if !modes.contains(&m) {
                modes.push(m);
            }
            chart
                .draw_series(std::iter::once(Circle::new(
                    (mu_ax.to(p.0), l),
                    5,
                    mode_color(m).filled(),
                )))
                .map_err(err)?;
        }
    }
    for m in modes {
        chart
            .draw_series(std::iter::empty::<Circle<(f64, f64), i32>>())
            .map_err(err)?
            .label(m.name())
            .legend(move |(x, y)| Circle::new((x + 10, y), 5, mode_color(m).filled()));
    }
    Ok(())
}

/// λ at μ = ∞ (λ_static there), dotted across the plot.
fn draw_asymptote(chart: &mut Chart, mu_ax: &Axis, s: f64) -> Result<(), String> {
    let (u0, u1) = (mu_ax.to(mu_ax.lo), mu_ax.to(mu_ax.hi));
    chart
        .draw_series(DashedLineSeries::new(
            vec![(u0, s), (u1, s)],
            2,
            6,
            ASYMPTOTE_COLOR.stroke_width(1),
        ))
        .map_err(err)?
        .label(format!("μ = ∞: λ = {}", short_num(s)))
        .legend(|(x, y)| {
            PathElement::new(vec![(x, y), (x + 20, y)], ASYMPTOTE_COLOR.stroke_width(1))
        });
    Ok(())
}
