//! The bottom panel of the arch figure: the collapse mechanism as rigid blocks displaced by
//! a stated multiple of their rates.

use super::canvas::{axes, block_outline, closed, err, View, MARGIN, X_LABELS, Y_LABELS};
use crate::figures::ArchScene;
use crate::render::fine::Fine;
use crate::render::plot::{short_num, FAMILY};
use plotters::coord::Shift;
use plotters::prelude::*;

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

/// The magnification of the rates that makes the largest displacement 8 % of the width
/// of the view.
fn magnification(scene: &ArchScene, view: &View) -> f64 {
    let unit_moves = displaced(scene, 1.0);
    let originals = displaced(scene, 0.0);
    let vmax = unit_moves
        .iter()
        .flatten()
        .zip(originals.iter().flatten())
        .map(|(a, b)| (a.0 - b.0).hypot(a.1 - b.1))
        .fold(0.0f64, f64::max);
    let (x0, x1) = view.x;
    if vmax > 0.0 {
        0.08 * (x1 - x0) / vmax
    } else {
        0.0
    }
}

/// The window of the bottom panel: the view widened to hold the displaced blocks with the
/// view's margin, at the view's aspect ratio (the shorter extent widened).
fn window(view: &View, moved: &[Vec<(f64, f64)>]) -> ((f64, f64), (f64, f64)) {
    let (x0, x1) = view.x;
    let (y0, y1) = view.y;
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
    ((u0, u1), (w0, w1))
}

/// The bottom panel: the pieces at rest, the original outline dashed, the moving blocks
/// displaced so that the largest displacement is 8 % of the panel width.
pub(super) fn mechanism_panel(
    area: &DrawingArea<SVGBackend, Shift>,
    scene: &ArchScene,
    view: &View,
    outline: &[(f64, f64)],
    color: RGBColor,
    fine: &Fine,
) -> Result<(), String> {
    let eta = scene.eta;
    let (br, bl) = (scene.arch.beta_right(), scene.arch.beta_left());
    let dof = scene.mechanism.as_ref().map_or(0, |m| m.dof);
    let k = magnification(scene, view);
    let moved = displaced(scene, k);
    let ((u0, u1), (w0, w1)) = window(view, &moved);
    let mut ch = ChartBuilder::on(area)
        .margin(MARGIN)
        .x_label_area_size(X_LABELS)
        .y_label_area_size(Y_LABELS)
        .caption(
            format!(
                "collapse mechanism{}: rigid blocks displaced by {} × the rates (linearised), {dof} dof",
                scene
                    .ray
                    .map_or(String::new(), |(i, n)| format!(" (extreme {i} of {n})")),
                short_num(k)
            ),
            (FAMILY, 14),
        )
        .build_cartesian_2d(u0..u1, w0..w1)
        .map_err(err)?;
    axes(&mut ch)?;
    let grey = RGBColor(150, 150, 150).stroke_width(1);
    fine.polyline(&ch, &closed(outline), grey, Some((4.0, 4.0)))?;
    let first = scene.blocks.first().map_or(bl, |b| b.from);
    let last = scene.blocks.last().map_or(br, |b| b.to);
    for (a, b) in [(br, first), (last, bl)] {
        if b > a {
            let still = RGBColor(200, 200, 200).filled();
            fine.polygon(&ch, &block_outline(eta, a, b), still)?;
        }
    }
    for poly in moved {
        let edge = closed(&poly);
        fine.polygon(&ch, &poly, color.mix(0.45).filled())?;
        fine.polyline(&ch, &edge, color.stroke_width(2), None)?;
    }
    Ok(())
}
