//! Figure: the eccentricities e_M = M/N (line of thrust) and e_T = (T/N)/μ·η/2 (line of
//! friction) against β, with the bounds ±η/2 where hinges (e_M) or sliding (e_T) occur,
//! and the active joints marked.

use crate::arch::Arch;
use crate::collapse_mode::CollapseMode;
use crate::contact::Contact;
use crate::contact::ContactKind;
use crate::render::plot::{mode_color, short_num, FAMILY};
use crate::statics::Reactions;
use crate::thrust_line::eccentricities;
use plotters::prelude::*;

/// Draws the eccentricity figure as SVG.
pub fn svg(
    arch: &Arch,
    eta: f64,
    mu: f64,
    x: &Reactions,
    pattern: &[Contact],
    mode: Option<CollapseMode>,
) -> Result<String, String> {
    let ecc = eccentricities(arch, eta, mu, x, 800);
    let (b0, b1) = (
        arch.beta_right().to_degrees(),
        arch.beta_left().to_degrees(),
    );
    let lim = 0.75 * eta;
    let color = mode.map_or(RGBColor(44, 160, 44), mode_color);
    let mut buf = String::new();
    {
        let root = SVGBackend::with_string(&mut buf, (900, 520)).into_drawing_area();
        root.fill(&WHITE).map_err(|e| e.to_string())?;
        let title = format!(
            "Eccentricities at η = {}, μ = {} — {}",
            short_num(eta),
            if mu.is_finite() {
                short_num(mu)
            } else {
                "∞".into()
            },
            mode.map_or("safe state".to_string(), |m| format!(
                "limit state, {}",
                m.name()
            ))
        );
        let mut ch = ChartBuilder::on(&root)
            .caption(title, (FAMILY, 18))
            .margin(14)
            .x_label_area_size(44)
            .y_label_area_size(70)
            .build_cartesian_2d(b0..b1, -lim..lim)
            .map_err(|e| e.to_string())?;
        ch.configure_mesh()
            .x_desc("joint angle β [deg from the horizontal]")
            .y_desc("eccentricity / r (outward +)")
            .y_label_formatter(&|v| short_num(*v))
            .label_style((FAMILY, 12))
            .axis_desc_style((FAMILY, 14))
            .draw()
            .map_err(|e| e.to_string())?;
        for sgn in [-1.0, 1.0] {
            ch.draw_series(DashedLineSeries::new(
                [(b0, sgn * eta / 2.0), (b1, sgn * eta / 2.0)],
                6,
                4,
                BLACK.stroke_width(1),
            ))
            .map_err(|e| e.to_string())?;
        }
        ch.draw_series(std::iter::once(Text::new(
            "+η/2: extrados",
            (b0 + 0.3 * (b1 - b0), eta / 2.0 + 0.06 * lim),
            (FAMILY, 12),
        )))
        .map_err(|e| e.to_string())?;
        ch.draw_series(std::iter::once(Text::new(
            "−η/2: intrados",
            (b0 + 0.3 * (b1 - b0), -eta / 2.0 - 0.02 * lim),
            (FAMILY, 12),
        )))
        .map_err(|e| e.to_string())?;
        let em: Vec<(f64, f64)> = ecc
            .iter()
            .filter(|e| e.n > 0.0)
            .map(|e| (e.beta.to_degrees(), e.e_m.clamp(-lim, lim)))
            .collect();
        ch.draw_series(LineSeries::new(em, BLACK.stroke_width(2)))
            .map_err(|e| e.to_string())?
            .label("e_M = M/N (line of thrust)")
            .legend(|(x, y)| PathElement::new(vec![(x, y), (x + 22, y)], BLACK.stroke_width(2)));
        if mu.is_finite() {
            let et: Vec<(f64, f64)> = ecc
                .iter()
                .filter(|e| e.n > 0.0)
                .map(|e| (e.beta.to_degrees(), e.e_t.clamp(-lim, lim)))
                .collect();
            let orange = RGBColor(255, 127, 14);
            ch.draw_series(DashedLineSeries::new(et, 6, 4, orange.stroke_width(2)))
                .map_err(|e| e.to_string())?
                .label("e_T = (T/N)/μ · η/2 (line of friction)")
                .legend(move |(x, y)| {
                    PathElement::new(vec![(x, y), (x + 22, y)], orange.stroke_width(2))
                });
        }
        for c in pattern {
            let b = c.beta.to_degrees();
            let (y, shape_tri) = match c.kind {
                ContactKind::HingeExtrados => (eta / 2.0, false),
                ContactKind::HingeIntrados => (-eta / 2.0, false),
                ContactKind::SlidePlus => (eta / 2.0, true),
                ContactKind::SlideMinus => (-eta / 2.0, true),
            };
            if shape_tri {
                ch.draw_series(std::iter::once(TriangleMarker::new(
                    (b, y),
                    8,
                    color.filled(),
                )))
                .map_err(|e| e.to_string())?;
            } else {
                ch.draw_series(std::iter::once(Circle::new((b, y), 6, color.filled())))
                    .map_err(|e| e.to_string())?;
            }
        }
        ch.configure_series_labels()
            .position(SeriesLabelPosition::UpperRight)
            .background_style(WHITE.mix(0.9))
            .border_style(BLACK)
            .label_font((FAMILY, 12))
            .draw()
            .map_err(|e| e.to_string())?;
        root.present().map_err(|e| e.to_string())?;
    }
    Ok(buf)
}
