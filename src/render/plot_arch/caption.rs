//! The caption of the arch figure: arch, friction, thickness and state; the active joints;
//! a key to the lines and the joint kinds.

use super::canvas::{err, short, MIN_JOINT_PX};
use crate::arch::JointLayout;
use crate::figures::ArchScene;
use crate::render::plot::{short_num, FAMILY};
use plotters::coord::Shift;
use plotters::prelude::*;

/// The first line: the arch, μ and φ, η, and the state drawn.
fn headline(scene: &ArchScene) -> String {
    let arch = &scene.arch;
    let (br, bl) = (arch.beta_right(), arch.beta_left());
    let alpha = 0.0 - br;
    let mu = scene.mu;
    format!(
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
    )
}

/// The caption: arch, friction, thickness and state; the active joints; a key.
pub(super) fn caption(
    cap: &DrawingArea<SVGBackend, Shift>,
    scene: &ArchScene,
    joints_drawn: bool,
) -> Result<(), String> {
    let arch = &scene.arch;
    let head = headline(scene);
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
