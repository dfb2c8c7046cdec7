//! The top panel of the arch figure: the arch to scale, its joints, the lines of thrust and
//! friction, the active contacts and the live load.

use super::canvas::{
    axes, closed, err, joints_visible, Chart, View, ARROW, MARGIN, X_LABELS, Y_LABELS,
};
use crate::arch::JointLayout;
use crate::contact::{Contact, ContactKind};
use crate::figures::thrust_line::Eccentricity;
use crate::figures::ArchScene;
use crate::load::LiveLoad;
use crate::pressure::Pressure;
use crate::render::fine::Fine;
use crate::render::plot::{short_num, FAMILY};
use plotters::coord::Shift;
use plotters::prelude::*;

/// The top panel: the arch, its joints, the lines of thrust and friction, the contacts.
pub(super) fn arch_panel(
    area: &DrawingArea<SVGBackend, Shift>,
    scene: &ArchScene,
    view: &View,
    outline: &[(f64, f64)],
    color: RGBColor,
    fine: &Fine,
) -> Result<(), String> {
    let mut ch = ChartBuilder::on(area)
        .margin(MARGIN)
        .x_label_area_size(X_LABELS)
        .y_label_area_size(Y_LABELS)
        .build_cartesian_2d(view.x.0..view.x.1, view.y.0..view.y.1)
        .map_err(err)?;
    axes(&mut ch)?;
    let fill = fill_region(scene);
    if !fill.is_empty() {
        fine.polygon(&ch, &fill, FILL_COLOR.filled())?;
        // the road: the fill's level top
        let road = vec![fill[0], fill[fill.len() - 1]];
        ch.draw_series(std::iter::once(PathElement::new(
            road,
            RGBColor(90, 80, 60).stroke_width(3),
        )))
        .map_err(err)?;
        if let Some(f) = scene.arch.fill() {
            // at the foot of the panel, clear of the load's arrows above the road
            let x = fill[0].0.min(fill[fill.len() - 1].0);
            let label = format!(
                "fill (shaded): g_f = {} of the masonry's weight, road h = {} r above the extrados",
                short_num(f.weight_ratio),
                short_num(f.depth)
            );
            ch.draw_series(std::iter::once(Text::new(
                label,
                (x, view.y.0 + 0.55 * view.pad),
                (FAMILY, 15).into_font().color(&RGBColor(90, 80, 60)),
            )))
            .map_err(err)?;
        }
    }
    fine.polygon(&ch, outline, RGBColor(225, 215, 195).filled())?;
    fine.polyline(&ch, &closed(outline), BLACK.stroke_width(1), None)?;
    if joints_visible(scene, view) {
        if let JointLayout::Discrete(js) = scene.arch.layout() {
            joint_lines(&mut ch, scene.eta, js)?;
        }
    }
    lines_of_thrust_and_friction(&ch, scene, fine)?;
    for c in &scene.pattern {
        contact(&mut ch, scene, view, c, color)?;
    }
    if let Some((load, lambda)) = &scene.load {
        load_arrows(&mut ch, scene, view, load, *lambda)?;
    }
    Ok(())
}

/// The colour of the fill.
const FILL_COLOR: RGBColor = RGBColor(240, 232, 170);

/// The fill above the extrados up to the road (bridge spec §2): the region between the
/// loaded extrados (0 ≤ β ≤ π within the arch) and the road's level, as a polygon from the
/// road over the first end, along the extrados, back to the road; empty without fill.
pub(super) fn fill_region(scene: &ArchScene) -> Vec<(f64, f64)> {
    let arch = &scene.arch;
    let Some(fill) = arch.fill() else {
        return Vec::new();
    };
    let (a, b) = (
        arch.beta_right().max(0.0),
        arch.beta_left().min(std::f64::consts::PI),
    );
    if b <= a {
        return Vec::new();
    }
    let kappa = 1.0 + scene.eta / 2.0;
    let road = fill.road(arch.springings(), scene.eta);
    let n = 96;
    let mut out = vec![(kappa * a.cos(), road)];
    out.extend((0..=n).map(|i| {
        let t = a + (b - a) * i as f64 / n as f64;
        (kappa * t.cos(), kappa * t.sin())
    }));
    out.push((kappa * b.cos(), road));
    out
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
        LiveLoad::Pressure(p) => pressure_arrows(ch, scene, &p, (len, head), lambda)?,
    };
    ch.draw_series(std::iter::once(Text::new(
        label,
        at,
        (FAMILY, 18).into_font().color(&LOAD_COLOR),
    )))
    .map_err(err)?;
    Ok(())
}

/// A pressure on the extrados: arrows down onto each patch, their lengths growing with the
/// intensity, a long arrow onto each point load, and the label beside the last drawn.
fn pressure_arrows(
    ch: &mut Chart,
    scene: &ArchScene,
    p: &Pressure,
    (len, head): (f64, f64),
    lambda: f64,
) -> Result<(String, (f64, f64)), String> {
    let top = 1.0 + scene.eta / 2.0;
    let (lo_end, hi_end) = Pressure::extrados(&scene.arch, scene.eta);
    let q_max = p.patches().iter().map(|q| q.q).fold(0.0, f64::max);
    let mut label_at = (0.0, top + 2.5 * len);
    for patch in p.patches() {
        let (lo, hi) = (patch.x_lo.max(lo_end), patch.x_hi.min(hi_end));
        if lo >= hi || q_max <= 0.0 {
            continue;
        }
        let shaft = len * (0.6 + 1.4 * patch.q / q_max);
        let n = ((hi - lo) / (0.08 * top)).ceil().max(1.0) as usize + 1;
        for i in 0..n {
            let x = lo + (hi - lo) * i as f64 / (n - 1).max(1) as f64;
            let y = (top * top - x * x).max(0.0).sqrt();
            arrow(ch, (x, y + shaft), (x, y), head)?;
        }
        let y = (top * top - lo * lo).max(0.0).sqrt();
        if patch.q == q_max {
            label_at = (hi + 0.02, y + shaft);
        }
    }
    for point in p.points() {
        let tip = (top * point.beta.cos(), top * point.beta.sin());
        let tail = (tip.0, tip.1 + 2.5 * len);
        arrow(ch, tail, tip, head)?;
        label_at = (tail.0 + 0.02, tail.1);
    }
    Ok((format!("λ = {}", short_num(lambda)), label_at))
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
fn lines_of_thrust_and_friction(ch: &Chart, scene: &ArchScene, fine: &Fine) -> Result<(), String> {
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
    fine.polyline(ch, &line(&|e| e.e_m), BLACK.stroke_width(2), None)?;
    if scene.mu.is_finite() {
        let orange = RGBColor(255, 127, 14).stroke_width(2);
        fine.polyline(ch, &line(&|e| e.e_t), orange, Some((6.0, 4.0)))?;
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
