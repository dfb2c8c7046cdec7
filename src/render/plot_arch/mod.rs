//! Figure: an [`ArchScene`] — the arch to scale with its line of thrust and line of
//! friction, the active joints by kind, and beneath it the collapse mechanism as displaced
//! rigid blocks (linearised kinematics, displacements magnified by a stated factor), with a
//! caption and a key to the joint kinds.

mod arch_panel;
mod canvas;
mod caption;
mod mechanism_panel;

pub use canvas::MIN_JOINT_PX;

use crate::figures::ArchScene;
use crate::render::fine::Fine;
use crate::render::plot::{mode_color, FAMILY};
use arch_panel::arch_panel;
use canvas::{block_outline, err, joints_visible, View, CAPTION_H, SAFE_COLOR, W};
use caption::caption;
use mechanism_panel::mechanism_panel;
use plotters::prelude::*;

/// Draws several states one under the other, each headed by its label (every limit
/// state of a non-unique case): the single-state figures nested in one SVG.
pub fn svg_panels(scenes: &[(String, ArchScene)]) -> Result<String, String> {
    let panels = scenes
        .iter()
        .map(|(label, scene)| Ok((label.clone(), svg(scene)?)))
        .collect::<Result<Vec<_>, String>>()?;
    stack(&panels)
}

/// SVG documents one under the other in one SVG, each headed by its label (none for an
/// empty label), at the width of the arch figures.
pub fn stack(panels: &[(String, String)]) -> Result<String, String> {
    let mut body = String::new();
    let mut y = 0u32;
    for (label, one) in panels {
        let h = svg_height(one).ok_or("a panel without a height")?;
        if !label.is_empty() {
            body.push_str(&format!(
                "<text x=\"16\" y=\"{}\" font-family=\"{FAMILY}\" font-size=\"16\" font-weight=\"bold\">{}</text>\n",
                y + 22,
                label.replace('&', "&amp;").replace('<', "&lt;")
            ));
            y += LABEL_H;
        }
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
    let view = View::new(&[outline.clone(), arch_panel::fill_region(scene)].concat());
    let panels = if scene.mechanism.is_some() { 2 } else { 1 };
    let total_h = CAPTION_H + panels * view.panel_h;
    let color = scene.mode.map_or(SAFE_COLOR, mode_color);
    let mut buf = String::new();
    let fine = Fine::default();
    {
        let root = SVGBackend::with_string(&mut buf, (W, total_h)).into_drawing_area();
        root.fill(&WHITE).map_err(err)?;
        let (cap, rest) = root.split_vertically(CAPTION_H);
        caption(&cap, scene, joints_visible(scene, &view))?;
        let (top, bottom) = rest.split_vertically(view.panel_h);
        arch_panel(&top, scene, &view, &outline, color, &fine)?;
        if scene.mechanism.is_some() {
            mechanism_panel(&bottom, scene, &view, &outline, color, &fine)?;
        }
        root.present().map_err(err)?;
    }
    Ok(fine.finish(&buf))
}
