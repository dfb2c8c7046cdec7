//! Figure: an [`ArchScene`] — the arch to scale with its line of thrust and line of
//! friction, the active joints by kind, and beneath it the collapse mechanism as displaced
//! rigid blocks (linearised kinematics, displacements magnified by a stated factor), with a
//! caption and a key to the joint kinds.

use crate::arch::JointLayout;
use crate::contact::{Contact, ContactKind};
use crate::figures::thrust_line::Eccentricity;
use crate::figures::ArchScene;
use crate::load::LiveLoad;
use crate::render::plot::{mode_color, short_num, FAMILY};
use plotters::coord::types::RangedCoordf64;
use plotters::coord::Shift;
use plotters::prelude::*;

/// Width of the SVG document.
const W: u32 = 960;
/// Joint lines are drawn only when neighbouring joints are at least this far apart on the
/// extrados (SVG pixels; 1.25 × that at the default 1200 px PNG width).
pub const MIN_JOINT_PX: f64 = 3.0;
/// Length of a sliding arrow and of its head, half-width of the head (SVG pixels).
const ARROW: (f64, f64, f64) = (46.0, 15.0, 7.0);
/// Colour of the state drawn when it is safe (no collapse mode).
const SAFE_COLOR: RGBColor = RGBColor(44, 160, 44);
const CAPTION_H: u32 = 128;
const Y_LABELS: u32 = 50;
const X_LABELS: u32 = 36;
const MARGIN: u32 = 12;

type Chart<'a, 'b> = ChartContext<'a, SVGBackend<'b>, Cartesian2d<RangedCoordf64, RangedCoordf64>>;

fn err(e: impl std::fmt::Display) -> String {
    e.to_string()
}

fn arc(r: f64, a: f64, b: f64, n: usize) -> Vec<(f64, f64)> {
    (0..=n)
        .map(|i| {
            let t = a + (b - a) * i as f64 / n as f64;
            (r * t.cos(), r * t.sin())
        })
        .collect()
}

/// The closed outline of the piece of arch between `a` and `b`.
fn block_outline(eta: f64, a: f64, b: f64) -> Vec<(f64, f64)> {
    let n = (((b - a) / 0.02).ceil() as usize).max(2);
    let mut p = arc(1.0 + eta / 2.0, a, b, n);
    let mut q = arc(1.0 - eta / 2.0, a, b, n);
    q.reverse();
    p.extend(q);
    p
}

fn closed(poly: &[(f64, f64)]) -> Vec<(f64, f64)> {
    let mut c = poly.to_vec();
    c.extend(poly.first());
    c
}

fn short(kind: ContactKind) -> &'static str {
    match kind {
        ContactKind::HingeExtrados => "E",
        ContactKind::HingeIntrados => "I",
        ContactKind::SlidePlus => "S+",
        ContactKind::SlideMinus => "S−",
    }
}

/// The window of the top panel (the arch with a margin) and its scale.
struct View {
    x: (f64, f64),
    y: (f64, f64),
    pad: f64,
    /// Plot width in SVG pixels.
    width_px: f64,
    /// Panel height in SVG pixels.
    panel_h: u32,
}

impl View {
    fn new(outline: &[(f64, f64)]) -> View {
        let ext = |f: fn(&(f64, f64)) -> f64| {
            outline
                .iter()
                .map(f)
                .fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), v| {
                    (a.min(v), b.max(v))
                })
        };
        let ((x0, x1), (y0, y1)) = (ext(|p| p.0), ext(|p| p.1));
        let pad = 0.08 * (x1 - x0).max(y1 - y0);
        let (x, y) = ((x0 - pad, x1 + pad), (y0 - pad, y1 + pad));
        let pw = W - Y_LABELS - 2 * MARGIN;
        let ph = (pw as f64 * (y.1 - y.0) / (x.1 - x.0)).round() as u32;
        View {
            x,
            y,
            pad,
            width_px: pw as f64,
            panel_h: ph + X_LABELS + 2 * MARGIN,
        }
    }

    /// Lengths / r per SVG pixel (the drawing is to scale).
    fn unit(&self) -> f64 {
        (self.x.1 - self.x.0) / self.width_px
    }
}

/// Whether the joints of a discrete arch are far enough apart to be drawn.
fn joints_visible(scene: &ArchScene, view: &View) -> bool {
    match scene.arch.layout() {
        JointLayout::Continuous => false,
        JointLayout::Discrete(js) => {
            let gap = js
                .windows(2)
                .map(|w| w[1] - w[0])
                .fold(f64::INFINITY, f64::min);
            gap * (1.0 + scene.eta / 2.0) / view.unit() >= MIN_JOINT_PX
        }
    }
}

/// Draws several states one under the other, each headed by its label (every limit
/// state of a non-unique case): the single-state figures nested in one SVG.
pub fn svg_panels(scenes: &[(String, ArchScene)]) -> Result<String, String> {
    let mut body = String::new();
    let mut y = 0u32;
    for (label, scene) in scenes {
        let one = svg(scene)?;
        let h = svg_height(&one).ok_or("a panel without a height")?;
        body.push_str(&format!(
            "<text x=\"16\" y=\"{}\" font-family=\"{FAMILY}\" font-size=\"16\" font-weight=\"bold\">{}</text>\n",
            y + 22,
            label.replace('&', "&amp;").replace('<', "&lt;")
        ));
        y += LABEL_H;
        let inner = one
            .split_once("?>")
            .map_or(one.as_str(), |(_, rest)| rest)
            .trim_start();
        // nest the panel at its offset
        body.push_str(&inner.replacen("<svg ", &format!("<svg x=\"0\" y=\"{y}\" "), 1));
        body.push('\n');
        y += h;
    }
    Ok(format!(
        "<svg width=\"{W}\" height=\"{y}\" viewBox=\"0 0 {W} {y}\" xmlns=\"http://www.w3.org/2000/svg\">\n<rect width=\"{W}\" height=\"{y}\" fill=\"white\"/>\n{body}</svg>\n"
    ))
}

/// Height of the label line above each panel of [`svg_panels`].
const LABEL_H: u32 = 34;

/// The `height` attribute of an SVG document's root element.
fn svg_height(svg: &str) -> Option<u32> {
    let start = svg.find("<svg")?;
    let tag = &svg[start..start + svg[start..].find('>')?];
    let h = tag.split("height=\"").nth(1)?;
    h[..h.find('"')?].parse().ok()
}

/// Draws the figure as SVG.
pub fn svg(scene: &ArchScene) -> Result<String, String> {
    let arch = &scene.arch;
    let outline = block_outline(scene.eta, arch.beta_right(), arch.beta_left());
    let view = View::new(&outline);
    let panels = if scene.mechanism.is_some() { 2 } else { 1 };
    let total_h = CAPTION_H + panels * view.panel_h;
    let color = scene.mode.map_or(SAFE_COLOR, mode_color);
    let mut buf = String::new();
    {
        let root = SVGBackend::with_string(&mut buf, (W, total_h)).into_drawing_area();
        root.fill(&WHITE).map_err(err)?;
        let (cap, rest) = root.split_vertically(CAPTION_H);
        caption(&cap, scene, joints_visible(scene, &view))?;
        let (top, bottom) = rest.split_vertically(view.panel_h);
        arch_panel(&top, scene, &view, &outline, color)?;
        if scene.mechanism.is_some() {
            mechanism_panel(&bottom, scene, &view, &outline, color)?;
        }
        root.present().map_err(err)?;
    }
    Ok(buf)
}

/// The caption: arch, friction, thickness and state; the active joints; a key.
fn caption(
    cap: &DrawingArea<SVGBackend, Shift>,
    scene: &ArchScene,
    joints_drawn: bool,
) -> Result<(), String> {
    let arch = &scene.arch;
    let (br, bl) = (arch.beta_right(), arch.beta_left());
    let alpha = 0.0 - br;
    let mu = scene.mu;
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
        short_num(scene.eta),
        match scene.mode {
            Some(m) => format!("limit state, mode {}", m.name()),
            None => "safe: the state of greatest margin".into(),
        }
    );
    let joints: Vec<String> = scene
        .pattern
        .iter()
        .map(|c| format!("{} {:.3}°", short(c.kind), c.beta.to_degrees()))
        .collect();
    let mut lines = vec![
        (head, 18),
        (
            format!(
                "{} joints (angle from the horizontal): {}",
                if scene.mode.is_some() {
                    "active"
                } else {
                    "least-slack"
                },
                joints.join(", ")
            ),
            14,
        ),
        (
            "black: line of thrust e = M/N;  dashed orange: line of friction (T/N)/μ·η/2;  \
             ● hinge;  → sliding of the crown-side block"
                .to_string(),
            13,
        ),
        (
            "E hinge at the extrados, I hinge at the intrados, S+/S− sliding in the positive/negative \
             sense"
                .to_string(),
            13,
        ),
        (
            "(S+: the block on the side of increasing β moves outward along the joint face \
             relative to the other; S−: inward)"
                .to_string(),
            13,
        ),
    ];
    if let JointLayout::Discrete(js) = arch.layout() {
        if !joints_drawn {
            lines.push((
                format!(
                    "{} voussoirs: joints closer than {MIN_JOINT_PX} px, not drawn",
                    js.len() - 1
                ),
                13,
            ));
        }
    }
    let mut y = 10;
    for (text, size) in lines {
        cap.draw(&Text::new(text, (14, y), (FAMILY, size).into_font()))
            .map_err(err)?;
        y += size + 7;
    }
    Ok(())
}

/// The plain x/r, y/r axes of both panels (no grid: the drawing is to scale).
fn axes(ch: &mut Chart<'_, '_>) -> Result<(), String> {
    ch.configure_mesh()
        .disable_mesh()
        .x_desc("x / r")
        .y_desc("y / r")
        .x_label_formatter(&|v| format!("{v:.1}"))
        .y_label_formatter(&|v| format!("{v:.1}"))
        .label_style((FAMILY, 12))
        .draw()
        .map_err(err)
}

/// The top panel: the arch, its joints, the lines of thrust and friction, the contacts.
fn arch_panel(
    area: &DrawingArea<SVGBackend, Shift>,
    scene: &ArchScene,
    view: &View,
    outline: &[(f64, f64)],
    color: RGBColor,
) -> Result<(), String> {
    let mut ch = ChartBuilder::on(area)
        .margin(MARGIN)
        .x_label_area_size(X_LABELS)
        .y_label_area_size(Y_LABELS)
        .build_cartesian_2d(view.x.0..view.x.1, view.y.0..view.y.1)
        .map_err(err)?;
    axes(&mut ch)?;
    ch.draw_series(std::iter::once(Polygon::new(
        outline.to_vec(),
        RGBColor(225, 215, 195),
    )))
    .map_err(err)?;
    ch.draw_series(std::iter::once(PathElement::new(
        closed(outline),
        BLACK.stroke_width(1),
    )))
    .map_err(err)?;
    if joints_visible(scene, view) {
        if let JointLayout::Discrete(js) = scene.arch.layout() {
            joint_lines(&mut ch, scene.eta, js)?;
        }
    }
    lines_of_thrust_and_friction(&mut ch, scene)?;
    for c in &scene.pattern {
        contact(&mut ch, scene, view, c, color)?;
    }
    if let Some((load, lambda)) = &scene.load {
        load_arrows(&mut ch, scene, view, load, *lambda)?;
    }
    Ok(())
}

/// The colour of live-load arrows.
const LOAD_COLOR: RGBColor = RGBColor(30, 90, 200);

/// An arrow from `tail` to `tip` with a head of `head` units.
fn arrow(ch: &mut Chart, tail: (f64, f64), tip: (f64, f64), head: f64) -> Result<(), String> {
    let (dx, dy) = (tip.0 - tail.0, tip.1 - tail.1);
    let len = (dx * dx + dy * dy).sqrt().max(f64::MIN_POSITIVE);
    let (ux, uy) = (dx / len, dy / len);
    let wing = |side: f64| {
        (
            tip.0 - head * (ux + 0.5 * side * uy),
            tip.1 - head * (uy - 0.5 * side * ux),
        )
    };
    ch.draw_series([
        PathElement::new(vec![tail, tip], LOAD_COLOR.stroke_width(3)),
        PathElement::new(vec![wing(1.0), tip, wing(-1.0)], LOAD_COLOR.stroke_width(3)),
    ])
    .map_err(err)?;
    Ok(())
}

/// The live load drawn on the arch: arrows along the centreline for the horizontal body
/// force, one arrow onto the extrados point for a point load, with the multiplier.
fn load_arrows(
    ch: &mut Chart,
    scene: &ArchScene,
    view: &View,
    load: &LiveLoad,
    lambda: f64,
) -> Result<(), String> {
    let size = (view.x.1 - view.x.0).max(view.y.1 - view.y.0);
    let (len, head) = (0.07 * size, 0.018 * size);
    let (br, bl) = (scene.arch.beta_right(), scene.arch.beta_left());
    let top = 1.0 + scene.eta / 2.0;
    let (label, at) = match *load {
        LiveLoad::Horizontal { towards_right } => {
            let k = if towards_right { 1.0 } else { -1.0 };
            for i in 1..8 {
                let b = br + (bl - br) * i as f64 / 8.0;
                let (s, c) = b.sin_cos();
                arrow(ch, (c - 0.5 * k * len, s), (c + 0.5 * k * len, s), head)?;
            }
            let mid = 0.5 * (br + bl);
            (
                format!("horizontal λ·weight, λ = {}", short_num(lambda)),
                (top * mid.cos() - 0.2 * size, top * mid.sin() + 0.06 * size),
            )
        }
        LiveLoad::Point { beta } => {
            let tip = (top * beta.cos(), top * beta.sin());
            let tail = (tip.0, tip.1 + 2.5 * len);
            arrow(ch, tail, tip, head)?;
            (
                format!("λ = {}", short_num(lambda)),
                (tail.0 + 0.02 * size, tail.1),
            )
        }
    };
    ch.draw_series(std::iter::once(Text::new(
        label,
        at,
        (FAMILY, 18).into_font().color(&LOAD_COLOR),
    )))
    .map_err(err)?;
    Ok(())
}

/// The radial joints of a discrete arch (one line each; called only when they are visible).
fn joint_lines(ch: &mut Chart, eta: f64, joints: &[f64]) -> Result<(), String> {
    let (ri, re) = (1.0 - eta / 2.0, 1.0 + eta / 2.0);
    let segments = joints.iter().map(|&b| {
        let (s, c) = b.sin_cos();
        PathElement::new(
            vec![(ri * c, ri * s), (re * c, re * s)],
            RGBColor(120, 110, 100).stroke_width(1),
        )
    });
    ch.draw_series(segments).map_err(err)?;
    Ok(())
}

/// The line of thrust (solid black) and, at finite friction, of friction (dashed orange),
/// drawn at radius 1 + e.
fn lines_of_thrust_and_friction(ch: &mut Chart, scene: &ArchScene) -> Result<(), String> {
    let eta = scene.eta;
    let line = |f: &dyn Fn(&Eccentricity) -> f64| -> Vec<(f64, f64)> {
        scene
            .lines
            .iter()
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
    .map_err(err)?;
    if scene.mu.is_finite() {
        ch.draw_series(DashedLineSeries::new(
            line(&|e| e.e_t),
            6,
            4,
            RGBColor(255, 127, 14).stroke_width(2),
        ))
        .map_err(err)?;
    }
    Ok(())
}

/// One active contact: the joint in the mode's colour, a dot at a hinge, an arrow (of
/// fixed size on the page) for the sliding of the crown-side block.
fn contact(
    ch: &mut Chart,
    scene: &ArchScene,
    view: &View,
    c: &Contact,
    color: RGBColor,
) -> Result<(), String> {
    let eta = scene.eta;
    let (sn, cs) = c.beta.sin_cos();
    let (ri, re) = (1.0 - eta / 2.0, 1.0 + eta / 2.0);
    ch.draw_series(std::iter::once(PathElement::new(
        vec![(ri * cs, ri * sn), (re * cs, re * sn)],
        color.stroke_width(3),
    )))
    .map_err(err)?;
    if c.kind.is_hinge() {
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
        .map_err(err)?;
        return Ok(());
    }
    // relative motion of the block on the crown side of the joint: along +t for S+ when
    // that block is the one after the joint (right half), reversed on the left half
    let after = if c.kind == ContactKind::SlidePlus {
        1.0
    } else {
        -1.0
    };
    let mid = 0.5 * (scene.arch.beta_right() + scene.arch.beta_left());
    let sign = if c.beta < mid { after } else { -after };
    let u = view.unit();
    let (len, head, half) = (ARROW.0 * u, ARROW.1 * u, ARROW.2 * u);
    let (dx, dy) = (sign * cs, sign * sn);
    let tip = (cs + dx * len, sn + dy * len);
    let base = (tip.0 - dx * head, tip.1 - dy * head);
    let (nx, ny) = (-dy * half, dx * half);
    ch.draw_series(std::iter::once(PathElement::new(
        vec![(cs, sn), base],
        color.stroke_width(4),
    )))
    .map_err(err)?;
    ch.draw_series(std::iter::once(Polygon::new(
        vec![tip, (base.0 + nx, base.1 + ny), (base.0 - nx, base.1 - ny)],
        color.filled(),
    )))
    .map_err(err)?;
    Ok(())
}

/// Block outlines displaced by `k` × their rigid motions.
fn displaced(scene: &ArchScene, k: f64) -> Vec<Vec<(f64, f64)>> {
    scene
        .blocks
        .iter()
        .map(|b| {
            let v = b.motion;
            block_outline(scene.eta, b.from, b.to)
                .into_iter()
                .map(|(x, y)| (x + k * (v[0] - v[2] * y), y + k * (v[1] + v[2] * x)))
                .collect()
        })
        .collect()
}

/// The bottom panel: the pieces at rest, the original outline dashed, the moving blocks
/// displaced so that the largest displacement is 8 % of the panel width.
fn mechanism_panel(
    area: &DrawingArea<SVGBackend, Shift>,
    scene: &ArchScene,
    view: &View,
    outline: &[(f64, f64)],
    color: RGBColor,
) -> Result<(), String> {
    let eta = scene.eta;
    let (br, bl) = (scene.arch.beta_right(), scene.arch.beta_left());
    let dof = scene.mechanism.as_ref().map_or(0, |m| m.dof);
    let unit_moves = displaced(scene, 1.0);
    let originals = displaced(scene, 0.0);
    let vmax = unit_moves
        .iter()
        .flatten()
        .zip(originals.iter().flatten())
        .map(|(a, b)| (a.0 - b.0).hypot(a.1 - b.1))
        .fold(0.0f64, f64::max);
    let (x0, x1) = view.x;
    let (y0, y1) = view.y;
    let k = if vmax > 0.0 {
        0.08 * (x1 - x0) / vmax
    } else {
        0.0
    };
    let moved = displaced(scene, k);
    let pad = view.pad;
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
    let mut ch = ChartBuilder::on(area)
        .margin(MARGIN)
        .x_label_area_size(X_LABELS)
        .y_label_area_size(Y_LABELS)
        .caption(
            format!(
                "collapse mechanism: rigid blocks displaced by {} × the rates (linearised), {dof} dof",
                short_num(k)
            ),
            (FAMILY, 14),
        )
        .build_cartesian_2d(u0..u1, w0..w1)
        .map_err(err)?;
    axes(&mut ch)?;
    ch.draw_series(DashedLineSeries::new(
        closed(outline),
        4,
        4,
        RGBColor(150, 150, 150).stroke_width(1),
    ))
    .map_err(err)?;
    let first = scene.blocks.first().map_or(bl, |b| b.from);
    let last = scene.blocks.last().map_or(br, |b| b.to);
    for (a, b) in [(br, first), (last, bl)] {
        if b > a {
            ch.draw_series(std::iter::once(Polygon::new(
                block_outline(eta, a, b),
                RGBColor(200, 200, 200),
            )))
            .map_err(err)?;
        }
    }
    for poly in moved {
        let edge = closed(&poly);
        ch.draw_series(std::iter::once(Polygon::new(poly, color.mix(0.45))))
            .map_err(err)?;
        ch.draw_series(std::iter::once(PathElement::new(
            edge,
            color.stroke_width(2),
        )))
        .map_err(err)?;
    }
    Ok(())
}
