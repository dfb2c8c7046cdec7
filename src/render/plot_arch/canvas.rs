//! The drawing's canvas: its sizes, the window and scale of the arch panel, the outlines
//! and axes every panel draws with.

use crate::arch::JointLayout;
use crate::contact::ContactKind;
use crate::figures::ArchScene;
use crate::render::plot::FAMILY;
use plotters::coord::types::RangedCoordf64;
use plotters::prelude::*;

/// Width of the SVG document.
pub(super) const W: u32 = 960;
/// Joint lines are drawn only when neighbouring joints are at least this far apart on the
/// extrados (SVG pixels; 1.25 × that at the default 1200 px PNG width).
pub const MIN_JOINT_PX: f64 = 3.0;
/// Length of a sliding arrow and of its head, half-width of the head (SVG pixels).
pub(super) const ARROW: (f64, f64, f64) = (46.0, 15.0, 7.0);
/// Colour of the state drawn when it is safe (no collapse mode).
pub(super) const SAFE_COLOR: RGBColor = RGBColor(44, 160, 44);
pub(super) const CAPTION_H: u32 = 128;
pub(super) const Y_LABELS: u32 = 50;
pub(super) const X_LABELS: u32 = 36;
pub(super) const MARGIN: u32 = 12;

pub(super) type Chart<'a, 'b> =
    ChartContext<'a, SVGBackend<'b>, Cartesian2d<RangedCoordf64, RangedCoordf64>>;

pub(super) fn err(e: impl std::fmt::Display) -> String {
    e.to_string()
}

pub(super) fn arc(r: f64, a: f64, b: f64, n: usize) -> Vec<(f64, f64)> {
    (0..=n)
        .map(|i| {
            let t = a + (b - a) * i as f64 / n as f64;
            (r * t.cos(), r * t.sin())
        })
        .collect()
}

/// The closed outline of the piece of arch between `a` and `b`.
pub(super) fn block_outline(eta: f64, a: f64, b: f64) -> Vec<(f64, f64)> {
    let n = (((b - a) / 0.02).ceil() as usize).max(2);
    let mut p = arc(1.0 + eta / 2.0, a, b, n);
    let mut q = arc(1.0 - eta / 2.0, a, b, n);
    q.reverse();
    p.extend(q);
    p
}

pub(super) fn closed(poly: &[(f64, f64)]) -> Vec<(f64, f64)> {
    let mut c = poly.to_vec();
    c.extend(poly.first());
    c
}

pub(super) fn short(kind: ContactKind) -> &'static str {
    match kind {
        ContactKind::HingeExtrados => "E",
        ContactKind::HingeIntrados => "I",
        ContactKind::SlidePlus => "S+",
        ContactKind::SlideMinus => "S−",
    }
}

/// The window of the top panel (the arch with a margin) and its scale.
pub(super) struct View {
    pub(super) x: (f64, f64),
    pub(super) y: (f64, f64),
    pub(super) pad: f64,
    /// Plot width in SVG pixels.
    pub(super) width_px: f64,
    /// Panel height in SVG pixels.
    pub(super) panel_h: u32,
}

impl View {
    pub(super) fn new(outline: &[(f64, f64)]) -> View {
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
    pub(super) fn unit(&self) -> f64 {
        (self.x.1 - self.x.0) / self.width_px
    }
}

/// Whether the joints of a discrete arch are far enough apart to be drawn.
pub(super) fn joints_visible(scene: &ArchScene, view: &View) -> bool {
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

/// The plain x/r, y/r axes of both panels (no grid: the drawing is to scale).
pub(super) fn axes(ch: &mut Chart<'_, '_>) -> Result<(), String> {
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
