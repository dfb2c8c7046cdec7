//! `arch-enum load`: the collapse multiplier of a live load (horizontal acceleration or a
//! point load) at a given thickness and friction, with every limit state.

use super::arch_args::ArchArgs;
use super::dimension_args::DimensionArgs;
use super::{to_json, Exit, Io};
use crate::arch::{fmt_value, InputError, JointLayout};
use crate::load::LiveLoad;
use crate::multiplier::{survey, LoadOutcome};
use crate::render::load::{json, table, LoadQuestion};
use crate::settings::Settings;
use clap::{ArgGroup, Args};

#[derive(Args, Debug)]
#[command(group(ArgGroup::new("live").required(true).args(["horizontal", "horizontal_left", "point_load", "point_load_deg", "point_load_joint"])))]
pub(crate) struct LoadArgs {
    #[command(flatten)]
    arch: ArchArgs,
    /// Thickness ratio eta = t/r of the arch, 0 < eta < 2.
    #[arg(long, allow_hyphen_values = true)]
    eta: f64,
    /// Friction coefficient mu = tan(phi) > 0; `inf` for no sliding.
    #[arg(long, allow_hyphen_values = true)]
    mu: f64,
    /// A horizontal body force lambda x self-weight towards +x (the right springing):
    /// a constant horizontal acceleration lambda g.
    #[arg(long)]
    horizontal: bool,
    /// The same towards -x (the left springing).
    #[arg(long)]
    horizontal_left: bool,
    /// A vertical point load lambda (units of gamma t d r) at the extrados point of angle B
    /// (radians, between the springings; at a joint or inside a voussoir).
    #[arg(long, value_name = "B", allow_hyphen_values = true)]
    point_load: Option<f64>,
    /// The same with the angle in degrees. On a discrete arch an angle within 1e-9 rad of
    /// a joint is that joint.
    #[arg(long, value_name = "DEG", allow_hyphen_values = true)]
    point_load_deg: Option<f64>,
    /// A vertical point load at the extrados point of joint K of a discrete arch, counted
    /// from the right springing (0) to the left one.
    #[arg(long, value_name = "K")]
    point_load_joint: Option<usize>,
    #[command(flatten)]
    dims: DimensionArgs,
    /// Print one JSON document instead of text.
    #[arg(long)]
    pub(crate) json: bool,
}

pub(crate) fn run(a: LoadArgs, settings: &Settings, io: &mut Io) -> Exit {
    let dims = match a.dims.build() {
        Ok(d) => d,
        Err(e) => return io.bad_input(&e),
    };
    let arch = match a.arch.build() {
        Ok(arch) => arch,
        Err(e) => return io.bad_input(&e),
    };
    let joints: Vec<f64> = match arch.layout() {
        JointLayout::Discrete(j) => j.clone(),
        JointLayout::Continuous => Vec::new(),
    };
    // an angle given within 1e-9 rad of a joint means the joint (decimal degrees rarely
    // land on it exactly)
    let snap = |b: f64| {
        joints
            .iter()
            .copied()
            .find(|j| (j - b).abs() <= 1e-9)
            .unwrap_or(b)
    };
    let load = match (
        a.horizontal,
        a.horizontal_left,
        a.point_load,
        a.point_load_deg,
        a.point_load_joint,
    ) {
        (true, ..) => LiveLoad::Horizontal {
            towards_right: true,
        },
        (_, true, ..) => LiveLoad::Horizontal {
            towards_right: false,
        },
        (_, _, Some(b), _, _) => LiveLoad::Point { beta: snap(b) },
        (_, _, _, Some(d), _) => LiveLoad::Point {
            beta: snap(d.to_radians()),
        },
        (_, _, _, _, Some(k)) => match joints.get(k) {
            Some(&beta) => LiveLoad::Point { beta },
            None => {
                return io.bad_input(&InputError::OutOfRange {
                    arg: "--point-load-joint",
                    value: k.to_string(),
                    range: if joints.is_empty() {
                        "a joint index of a discrete arch (give --blocks or --joints)".into()
                    } else {
                        format!("0 <= K <= {}", joints.len() - 1)
                    },
                })
            }
        },
        _ => unreachable!("clap requires one load"),
    };
    let outcome = match survey(&arch, a.eta, a.mu, &load, settings) {
        Ok(o) => o,
        Err(e) => {
            // name the degree flag when the angle came in degrees
            if let (
                InputError::OutOfRange {
                    arg: "--point-load",
                    ..
                },
                Some(d),
            ) = (&e, a.point_load_deg)
            {
                return io.bad_input(&InputError::OutOfRange {
                    arg: "--point-load-deg",
                    value: fmt_value(d),
                    range: format!(
                        "between the springings, {} to {} degrees",
                        arch.beta_right().to_degrees(),
                        arch.beta_left().to_degrees()
                    ),
                });
            }
            return io.bad_input(&e);
        }
    };
    let q = LoadQuestion {
        arch: &arch,
        eta: a.eta,
        mu: a.mu,
        load,
        dims,
    };
    if a.json {
        io.out(&to_json(&json(&q, &outcome)));
    } else {
        io.out(&table(&q, &outcome));
    }
    match outcome {
        Ok(LoadOutcome::Limits(_)) => Exit::Answered,
        _ => Exit::NoAnswer,
    }
}
