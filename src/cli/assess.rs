//! `arch-enum assess`: a given thickness at a given friction — does it stand, and with
//! what margins?

use super::arch_args::ArchArgs;
use super::{to_json, Exit, Io};
use crate::arch::{fmt_value, InputError};
use crate::assess::assess;
use crate::render::table::Dimensions;
use crate::render::{json, table};
use crate::settings::Settings;
use clap::Args;

#[derive(Args, Debug)]
pub(crate) struct AssessArgs {
    #[command(flatten)]
    arch: ArchArgs,
    /// Thickness ratio eta = t/r of the arch, 0 < eta < 2.
    #[arg(long, allow_hyphen_values = true)]
    eta: f64,
    /// Friction coefficient mu = tan(phi) > 0; `inf` for no sliding.
    #[arg(long, allow_hyphen_values = true)]
    mu: f64,
    /// Mean radius r in metres (with --depth and --density: results in m and kN).
    #[arg(long, allow_hyphen_values = true, requires_all = ["depth", "density"])]
    radius: Option<f64>,
    /// Depth of the barrel in metres (perpendicular to the arch's plane).
    #[arg(long, allow_hyphen_values = true, requires = "radius")]
    depth: Option<f64>,
    /// Density in kg/m^3 (e.g. 2000 for brickwork).
    #[arg(long, allow_hyphen_values = true, requires = "radius")]
    density: Option<f64>,
    /// Gravitational acceleration in m/s^2.
    #[arg(long, default_value_t = 9.81, allow_hyphen_values = true)]
    g: f64,
    /// Print one JSON document instead of text.
    #[arg(long)]
    pub(crate) json: bool,
}

fn positive(arg: &'static str, v: f64) -> Result<f64, InputError> {
    if v.is_finite() && v > 0.0 {
        Ok(v)
    } else {
        Err(InputError::OutOfRange {
            arg,
            value: fmt_value(v),
            range: "a finite number > 0".into(),
        })
    }
}

pub(crate) fn run(a: AssessArgs, settings: &Settings, io: &mut Io) -> Exit {
    let dims = match (a.radius, a.depth, a.density) {
        (Some(r), Some(d), Some(rho)) => {
            match (|| {
                Ok::<_, InputError>(Dimensions {
                    radius: positive("--radius", r)?,
                    depth: positive("--depth", d)?,
                    density: positive("--density", rho)?,
                    g: positive("--g", a.g)?,
                })
            })() {
                Ok(d) => Some(d),
                Err(e) => return io.bad_input(&e),
            }
        }
        _ => None,
    };
    let (arch, res) = match a.arch.build() {
        Ok(arch) => {
            let r = assess(&arch, a.eta, a.mu, settings);
            (arch, r)
        }
        Err(e) => return io.bad_input(&e),
    };
    let res = match res {
        Ok(r) => r,
        Err(e) => return io.bad_input(&e),
    };
    if a.json {
        io.out(&to_json(&json::assess(&arch, &res)));
    } else {
        io.out(&table::assess(&arch, &res, dims));
    }
    match res.limit {
        crate::limit::Outcome::Unresolved { .. } => Exit::NoAnswer,
        _ => Exit::Answered,
    }
}
