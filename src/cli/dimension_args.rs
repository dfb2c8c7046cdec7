//! The physical dimensions shared by the commands that can answer in metres and
//! kilonewtons (`--radius --depth --density [--g]`).

use crate::arch::{fmt_value, InputError};
use crate::render::table::Dimensions;
use clap::Args;

#[derive(Args, Debug)]
pub(crate) struct DimensionArgs {
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

impl DimensionArgs {
    /// The dimensions, when given; each must be a finite positive number.
    pub(crate) fn build(&self) -> Result<Option<Dimensions>, InputError> {
        match (self.radius, self.depth, self.density) {
            (Some(r), Some(d), Some(rho)) => Ok(Some(Dimensions {
                radius: positive("--radius", r)?,
                depth: positive("--depth", d)?,
                density: positive("--density", rho)?,
                g: positive("--g", self.g)?,
            })),
            _ => Ok(None),
        }
    }
}
