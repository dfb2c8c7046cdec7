//! Figure: the eccentricities e_M = M/N (line of thrust) and e_T = (T/N)/μ·η/2 (line of
//! friction) of an [`ArchScene`] against β, with the bounds ±η/2 where hinges (e_M) or
//! sliding (e_T) occur, and the active joints marked.

use crate::contact::ContactKind;
use crate::figures::ArchScene;
use crate::render::fine::Fine;
use crate::render::plot::{mode_color, short_num, Axis, AxisCoord, FAMILY};
use plotters::coord::Shift;
use plotters::prelude::*;
use plotters::style::text_anchor::{HPos, Pos, VPos};

/// Colour of the state drawn when it is safe (no collapse mode).
pub const SAFE_COLOR: RGBColor = RGBColor(44, 160, 44);
/// Colour of the line of friction.
pub const FRICTION_COLOR: RGBColor = RGBColor(255, 127, 14);

fn err(e: impl std::fmt::Display) -> String {
    e.to_string()
}

type Chart<'a, 'b> = ChartContext<'a, SVGBackend<'b>, Cartesian2d<AxisCoord, AxisCoord>>;

/// Draws the eccentricity figure as SVG.
pub fn svg(scene: &ArchScene) -> Result<String, String> {
    let eta = scene.eta;
    let b_ax = Axis {
        lo: scene.arch.beta_right().to_degrees(),
        hi: scene.arch.beta_left().to_degrees(),
        log: false,
    };
    let lim = 0.75 * eta;
    let e_ax = Axis {
        lo: -lim,
        hi: lim,
        log: false,
    };
    let mut buf = String::new();
    let fine = Fine::default();
    {
        let root = SVGBackend::with_string(&mut buf, (900, 520)).into_drawing_area();
        root.fill(&WHITE).map_err(err)?;
        let mut ch = chart(&root, scene, &b_ax, &e_ax)?;
        draw_bounds(&root, &mut ch, &b_ax, eta)?;
        draw_lines(&mut ch, scene, lim, &fine)?;
        draw_contacts(&mut ch, scene)?;
        ch.configure_series_labels()
            .position(SeriesLabelPosition::UpperRight)
            .background_style(WHITE.mix(0.9))
            .border_style(BLACK)
            .label_font((FAMILY, 12))
            .draw()
            .map_err(err)?;
        root.present().map_err(err)?;
    }
    Ok(fine.finish(&buf))
}

/// The chart under its title (η, μ and the state), with its labelled axes.
fn chart<'a, 'b>(
    root: &'a DrawingArea<SVGBackend<'b>, Shift>,
    scene: &ArchScene,
    b_ax: &Axis,
    e_ax: &Axis,
) -> Result<Chart<'a, 'b>, String> {
    let (eta, mu) = (scene.eta, scene.mu);
    let title = format!(
        "Eccentricities at η = {}, μ = {} — {}",
        short_num(eta),
        if mu.is_finite() {
            short_num(mu)
        } else {
            "∞".into()
        },
        scene.mode.map_or("safe state".to_string(), |m| format!(
            "limit state, {}",
            m.name()
        ))
    );
    let mut ch = ChartBuilder::on(root)
        .caption(title, (FAMILY, 18))
        .margin(14)
        .x_label_area_size(44)
        .y_label_area_size(70)
        .build_cartesian_2d(b_ax.range(), e_ax.range())
        .map_err(err)?;
    ch.configure_mesh()
        .x_desc("joint angle β [deg from the horizontal]")
        .y_desc("eccentricity / r (outward +)")
        .x_label_formatter(&|u| b_ax.label(*u))
        .y_label_formatter(&|u| e_ax.label(*u))
        .label_style((FAMILY, 12))
        .axis_desc_style((FAMILY, 14))
        .draw()
        .map_err(err)?;
    Ok(ch)
}

/// The bounds ±η/2, dashed, labelled outside them (where no admissible line goes).
fn draw_bounds(
    root: &DrawingArea<SVGBackend, Shift>,
    ch: &mut Chart,
    b_ax: &Axis,
    eta: f64,
) -> Result<(), String> {
    for sgn in [-1.0, 1.0] {
        ch.draw_series(DashedLineSeries::new(
            [(b_ax.lo, sgn * eta / 2.0), (b_ax.hi, sgn * eta / 2.0)],
            6,
            4,
            BLACK.stroke_width(1),
        ))
        .map_err(err)?;
    }
    let x = b_ax.lo + 0.02 * (b_ax.hi - b_ax.lo);
    let (above, below) = (
        Pos::new(HPos::Left, VPos::Bottom),
        Pos::new(HPos::Left, VPos::Top),
    );
    for (text, y, pos) in [
        (
            "+η/2: e_M at the extrados (hinge E), e_T at sliding S+",
            eta / 2.0,
            above,
        ),
        (
            "−η/2: e_M at the intrados (hinge I), e_T at sliding S−",
            -eta / 2.0,
            below,
        ),
    ] {
        let (px, py) = ch.backend_coord(&(x, y));
        let dy = if y > 0.0 { -10 } else { 10 };
        root.draw(&Text::new(
            text,
            (px, py + dy),
            TextStyle::from((FAMILY, 12).into_font()).pos(pos),
        ))
        .map_err(err)?;
    }
    Ok(())
}

/// The line of thrust e_M and, at finite friction, the line of friction e_T, clamped to
/// the plot where they leave it; each labelled for the legend by an empty series.
fn draw_lines(ch: &mut Chart, scene: &ArchScene, lim: f64, fine: &Fine) -> Result<(), String> {
    let line = |f: &dyn Fn(&crate::figures::thrust_line::Eccentricity) -> f64| {
        scene
            .lines
            .iter()
            .filter(|e| e.n > 0.0 && f(e).is_finite())
            .map(|e| (e.beta.to_degrees(), f(e).clamp(-lim, lim)))
            .collect::<Vec<_>>()
    };
    let none = || LineSeries::new(Vec::<(f64, f64)>::new(), BLACK);
    fine.polyline(ch, &line(&|e| e.e_m), BLACK.stroke_width(2), None)?;
    ch.draw_series(none())
        .map_err(err)?
        .label("e_M = M/N (line of thrust)")
        .legend(|(x, y)| PathElement::new(vec![(x, y), (x + 22, y)], BLACK.stroke_width(2)));
    if scene.mu.is_finite() {
        let style = FRICTION_COLOR.stroke_width(2);
        fine.polyline(ch, &line(&|e| e.e_t), style, Some((6.0, 4.0)))?;
        ch.draw_series(none())
            .map_err(err)?
            .label("e_T = (T/N)/μ · η/2 (line of friction)")
            .legend(|(x, y)| {
                PathElement::new(vec![(x, y), (x + 22, y)], FRICTION_COLOR.stroke_width(2))
            });
    }
    Ok(())
}

/// The active contacts on their bound, in the mode's colour: a dot at a hinge, a triangle
/// at a sliding joint.
fn draw_contacts(ch: &mut Chart, scene: &ArchScene) -> Result<(), String> {
    let (eta, color) = (scene.eta, scene.mode.map_or(SAFE_COLOR, mode_color));
    for c in &scene.pattern {
        let b = c.beta.to_degrees();
        let y = match c.kind {
            ContactKind::HingeExtrados | ContactKind::SlidePlus => eta / 2.0,
            ContactKind::HingeIntrados | ContactKind::SlideMinus => -eta / 2.0,
        };
        if !c.kind.is_hinge() {
            ch.draw_series(std::iter::once(TriangleMarker::new(
                (b, y),
                8,
                color.filled(),
            )))
            .map_err(err)?;
        } else {
            ch.draw_series(std::iter::once(Circle::new((b, y), 6, color.filled())))
                .map_err(err)?;
        }
    }
    Ok(())
}
