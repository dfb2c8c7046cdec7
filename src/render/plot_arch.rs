//! Figure: the arch to scale with its line of thrust and line of friction, the active
//! joints by kind, and beneath it the collapse mechanism as displaced rigid blocks
//! (linearised kinematics, displacements magnified by a stated factor), with a caption.

use crate::arch::{Arch, JointLayout};
use crate::collapse_mode::CollapseMode;
use crate::contact::Contact;
use crate::contact::ContactKind;
use crate::kinematics::block_motions;
use crate::mechanism::Mechanism;
use crate::render::plot::{mode_color, short_num, FAMILY};
use crate::statics::Reactions;
use crate::thrust_line::eccentricities;
use plotters::prelude::*;

/// What to draw.
#[derive(Debug, Clone)]
pub struct ArchFigure<'a> {
    /// The arch.
    pub arch: &'a Arch,
    /// Friction coefficient.
    pub mu: f64,
    /// Thickness ratio drawn.
    pub eta: f64,
    /// The state drawn.
    pub x: Reactions,
    /// Active contacts (limit state) or the least-slack contacts (safe state).
    pub pattern: &'a [Contact],
    /// The mechanism, at a limit state.
    pub mechanism: Option<&'a Mechanism>,
    /// The collapse mode, at a limit state; `None` draws a safe state.
    pub mode: Option<CollapseMode>,
}

const W: u32 = 960;

fn arc(r: f64, a: f64, b: f64, n: usize) -> Vec<(f64, f64)> {
    (0..=n)
        .map(|i| {
            let t = a + (b - a) * i as f64 / n as f64;
            (r * t.cos(), r * t.sin())
        })
        .collect()
}

fn block_outline(eta: f64, a: f64, b: f64) -> Vec<(f64, f64)> {
    let n = (((b - a) / 0.02).ceil() as usize).max(2);
    let mut p = arc(1.0 + eta / 2.0, a, b, n);
    let mut q = arc(1.0 - eta / 2.0, a, b, n);
    q.reverse();
    p.extend(q);
    p
}

fn short(mode: ContactKind) -> &'static str {
    match mode {
        ContactKind::HingeExtrados => "E",
        ContactKind::HingeIntrados => "I",
        ContactKind::SlidePlus => "S+",
        ContactKind::SlideMinus => "S−",
    }
}

/// Draws the figure as SVG.
pub fn svg(fig: &ArchFigure) -> Result<String, String> {
    let arch = fig.arch;
    let (eta, mu) = (fig.eta, fig.mu);
    let (br, bl) = (arch.beta_right(), arch.beta_left());
    let outline = block_outline(eta, br, bl);
    let (mut x0, mut x1, mut y0, mut y1) = (
        f64::INFINITY,
        f64::NEG_INFINITY,
        f64::INFINITY,
        f64::NEG_INFINITY,
    );
    for &(x, y) in &outline {
        x0 = x0.min(x);
        x1 = x1.max(x);
        y0 = y0.min(y);
        y1 = y1.max(y);
    }
    let pad = 0.08 * (x1 - x0).max(y1 - y0);
    let (x0, x1, y0, y1) = (x0 - pad, x1 + pad, y0 - pad, y1 + pad);
    let (ylab, xlab, margin) = (50u32, 36u32, 12u32);
    let pw = W - ylab - 2 * margin;
    let ph = (pw as f64 * (y1 - y0) / (x1 - x0)).round() as u32;
    let panel_h = ph + xlab + 2 * margin;
    let caption_h = 96u32;
    let panels = if fig.mechanism.is_some() { 2 } else { 1 };
    let total_h = caption_h + panels * panel_h;
    let mut buf = String::new();
    {
        let root = SVGBackend::with_string(&mut buf, (W, total_h)).into_drawing_area();
        root.fill(&WHITE).map_err(|e| e.to_string())?;
        let (cap, rest) = root.split_vertically(caption_h);
        let color = fig.mode.map_or(RGBColor(44, 160, 44), mode_color);
        let alpha = 0.0 - arch.beta_right();
        let head = format!(
            "{}, μ = {} (φ = {:.2}°), η = {}  —  {}",
            if arch.is_symmetric() {
                format!("α = {} rad ({:.2}°)", short_num(alpha), alpha.to_degrees())
            } else {
                format!("β_R = {}, β_L = {}", short_num(br), short_num(bl))
            },
            if mu.is_finite() {
                short_num(mu)
            } else {
                "∞".into()
            },
            mu.atan().to_degrees(),
            short_num(eta),
            match fig.mode {
                Some(m) => format!("limit state, mode {}", m.name()),
                None => "safe: the state of greatest margin".into(),
            }
        );
        cap.draw(&Text::new(head, (14, 10), (FAMILY, 18).into_font()))
            .map_err(|e| e.to_string())?;
        let joints: Vec<String> = fig
            .pattern
            .iter()
            .map(|c| format!("{} {:.3}°", short(c.kind), c.beta.to_degrees()))
            .collect();
        cap.draw(&Text::new(
            format!(
                "{} joints (angle from the horizontal): {}",
                if fig.mode.is_some() {
                    "active"
                } else {
                    "least-slack"
                },
                joints.join(", ")
            ),
            (14, 38),
            (FAMILY, 14).into_font(),
        ))
        .map_err(|e| e.to_string())?;
        cap.draw(&Text::new(
            "black: line of thrust e = M/N;  dashed orange: line of friction (T/N)/μ·η/2;  ● hinge;  → sliding of the crown-side block",
            (14, 60),
            (FAMILY, 13).into_font(),
        ))
        .map_err(|e| e.to_string())?;
        let (top, bottom) = rest.split_vertically(panel_h);

        // --- top panel: arch, lines, contacts
        let mut ch = ChartBuilder::on(&top)
            .margin(margin)
            .x_label_area_size(xlab)
            .y_label_area_size(ylab)
            .build_cartesian_2d(x0..x1, y0..y1)
            .map_err(|e| e.to_string())?;
        axes(&mut ch)?;
        ch.draw_series(std::iter::once(Polygon::new(
            outline.clone(),
            RGBColor(225, 215, 195),
        )))
        .map_err(|e| e.to_string())?;
        let mut closed = outline.clone();
        closed.push(outline[0]);
        ch.draw_series(std::iter::once(PathElement::new(
            closed,
            BLACK.stroke_width(1),
        )))
        .map_err(|e| e.to_string())?;
        if let JointLayout::Discrete(js) = arch.layout() {
            for &b in js {
                let (c, s) = (b.cos(), b.sin());
                ch.draw_series(std::iter::once(PathElement::new(
                    vec![
                        ((1.0 - eta / 2.0) * c, (1.0 - eta / 2.0) * s),
                        ((1.0 + eta / 2.0) * c, (1.0 + eta / 2.0) * s),
                    ],
                    RGBColor(120, 110, 100).stroke_width(1),
                )))
                .map_err(|e| e.to_string())?;
            }
        }
        let ecc = eccentricities(arch, eta, mu, &fig.x, 600);
        let line = |f: &dyn Fn(&crate::thrust_line::Eccentricity) -> f64| -> Vec<(f64, f64)> {
            ecc.iter()
                .filter(|e| e.n > 0.0 && f(e).is_finite())
                .map(|e| {
                    let r = 1.0 + f(e).clamp(-eta, eta);
                    (r * e.beta.cos(), r * e.beta.sin())
                })
                .collect()
        };
        ch.draw_series(std::iter::once(PathElement::new(
            line(&|e| e.e_m),
            BLACK.stroke_width(2),
        )))
        .map_err(|e| e.to_string())?;
        if mu.is_finite() {
            ch.draw_series(DashedLineSeries::new(
                line(&|e| e.e_t),
                6,
                4,
                RGBColor(255, 127, 14).stroke_width(2),
            ))
            .map_err(|e| e.to_string())?;
        }
        for c in fig.pattern {
            let (cs, sn) = (c.beta.cos(), c.beta.sin());
            let (ri, re) = (1.0 - eta / 2.0, 1.0 + eta / 2.0);
            ch.draw_series(std::iter::once(PathElement::new(
                vec![(ri * cs, ri * sn), (re * cs, re * sn)],
                color.stroke_width(3),
            )))
            .map_err(|e| e.to_string())?;
            match c.kind {
                ContactKind::HingeExtrados | ContactKind::HingeIntrados => {
                    let r = if c.kind == ContactKind::HingeExtrados {
                        re
                    } else {
                        ri
                    };
                    ch.draw_series(std::iter::once(Circle::new(
                        (r * cs, r * sn),
                        6,
                        color.filled(),
                    )))
                    .map_err(|e| e.to_string())?;
                }
                ContactKind::SlidePlus | ContactKind::SlideMinus => {
                    // relative motion of the block on the crown side of the joint
                    let after = if c.kind == ContactKind::SlidePlus {
                        1.0
                    } else {
                        -1.0
                    };
                    let sign = if c.beta < 0.5 * (br + bl) {
                        after
                    } else {
                        -after
                    };
                    let len = 0.3 * eta.clamp(0.08, 0.5);
                    let (px, py) = (cs, sn);
                    let (tx, ty) = (sign * cs * len, sign * sn * len);
                    let tip = (px + tx, py + ty);
                    // arrow head
                    let (hx, hy) = (-ty * 0.3, tx * 0.3);
                    ch.draw_series(std::iter::once(PathElement::new(
                        vec![(px, py), tip],
                        color.stroke_width(3),
                    )))
                    .map_err(|e| e.to_string())?;
                    ch.draw_series(std::iter::once(Polygon::new(
                        vec![
                            tip,
                            (tip.0 - 0.35 * tx + hx, tip.1 - 0.35 * ty + hy),
                            (tip.0 - 0.35 * tx - hx, tip.1 - 0.35 * ty - hy),
                        ],
                        color.filled(),
                    )))
                    .map_err(|e| e.to_string())?;
                }
            }
        }

        // --- bottom panel: mechanism as displaced blocks
        if let Some(m) = fig.mechanism {
            let blocks = block_motions(eta, &m.contacts, &m.rates);
            let disp = |v: &[f64; 3], (x, y): (f64, f64)| (v[0] - v[2] * y, v[1] + v[2] * x);
            let vmax = blocks
                .iter()
                .flat_map(|(a, b, v)| {
                    block_outline(eta, *a, *b).into_iter().map(move |p| {
                        let d = disp(v, p);
                        (d.0 * d.0 + d.1 * d.1).sqrt()
                    })
                })
                .fold(0.0f64, f64::max);
            let k = if vmax > 0.0 {
                0.08 * (x1 - x0) / vmax
            } else {
                0.0
            };
            let moved: Vec<Vec<(f64, f64)>> = blocks
                .iter()
                .map(|(a, b, v)| {
                    block_outline(eta, *a, *b)
                        .into_iter()
                        .map(|p| {
                            let d = disp(v, p);
                            (p.0 + k * d.0, p.1 + k * d.1)
                        })
                        .collect()
                })
                .collect();
            let (mut u0, mut u1, mut w0, mut w1) = (x0, x1, y0, y1);
            for &(x, y) in moved.iter().flatten() {
                u0 = u0.min(x - pad);
                u1 = u1.max(x + pad);
                w0 = w0.min(y - pad);
                w1 = w1.max(y + pad);
            }
            // keep the aspect: widen the shorter extent
            let (du, dw) = (u1 - u0, w1 - w0);
            let target = du * (y1 - y0) / (x1 - x0);
            if dw < target {
                w1 += target - dw;
            } else {
                let extra = dw * (x1 - x0) / (y1 - y0) - du;
                u0 -= extra / 2.0;
                u1 += extra / 2.0;
            }
            let mut ch2 = ChartBuilder::on(&bottom)
                .margin(margin)
                .x_label_area_size(xlab)
                .y_label_area_size(ylab)
                .caption(format!("collapse mechanism: rigid blocks displaced by {} × the rates (linearised), {} dof", short_num(k), m.dof), (FAMILY, 14))
                .build_cartesian_2d(u0..u1, w0..w1)
                .map_err(|e| e.to_string())?;
            axes(&mut ch2)?;
            let mut closed = outline.clone();
            closed.push(outline[0]);
            ch2.draw_series(DashedLineSeries::new(
                closed,
                4,
                4,
                RGBColor(150, 150, 150).stroke_width(1),
            ))
            .map_err(|e| e.to_string())?;
            // pieces at rest
            let first = blocks.first().map_or(bl, |b| b.0);
            let last = blocks.last().map_or(br, |b| b.1);
            for (a, b) in [(br, first), (last, bl)] {
                if b > a {
                    ch2.draw_series(std::iter::once(Polygon::new(
                        block_outline(eta, a, b),
                        RGBColor(200, 200, 200),
                    )))
                    .map_err(|e| e.to_string())?;
                }
            }
            for poly in moved {
                let mut closed = poly.clone();
                closed.push(poly[0]);
                ch2.draw_series(std::iter::once(Polygon::new(poly, color.mix(0.45))))
                    .map_err(|e| e.to_string())?;
                ch2.draw_series(std::iter::once(PathElement::new(
                    closed,
                    color.stroke_width(2),
                )))
                .map_err(|e| e.to_string())?;
            }
        }
        root.present().map_err(|e| e.to_string())?;
    }
    Ok(buf)
}

type Chart<'a, 'b> = ChartContext<
    'a,
    SVGBackend<'b>,
    Cartesian2d<plotters::coord::types::RangedCoordf64, plotters::coord::types::RangedCoordf64>,
>;

/// The plain x/r, y/r axes of both panels (no grid: the drawing is to scale).
fn axes(ch: &mut Chart<'_, '_>) -> Result<(), String> {
    ch.configure_mesh()
        .disable_mesh()
        .x_desc("x / r")
        .y_desc("y / r")
        .label_style((FAMILY, 12))
        .draw()
        .map_err(|e| e.to_string())
}
