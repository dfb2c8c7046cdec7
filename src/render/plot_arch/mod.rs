//! Figure: an [`ArchScene`] — the arch to scale with its line of thrust and line of
//! friction, the active joints by kind, and beneath it the collapse mechanism as displaced
//! rigid blocks (linearised kinematics, displacements magnified by a stated factor), with a
//! caption and a key to the joint kinds.

mod arch_panel;
mod caption;
mod mechanism_panel;

use crate::arch::JointLayout;
use crate::contact::ContactKind;
use crate::figures::ArchScene;
use crate::render::plot::{mode_color, FAMILY};
use arch_panel::arch_panel;
use caption::caption;
use mechanism_panel::mechanism_panel;
use plotters::coord::types::RangedCoordf64;
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
