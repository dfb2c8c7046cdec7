//! The physical dimensions shared by the commands that can answer in metres and
//! kilonewtons (`--radius --depth --density [--g]`, or with `--span --rise --ring` the
//! engineer's `--width --unit-weight`).

use super::arch_args::ArchArgs;
use crate::arch::{check_positive as positive, InputError};
use crate::bridge::Geometry;
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
    /// Barrel width d in metres (with --span, --rise, --ring and --unit-weight: results in
    /// m and kN).
    #[arg(
        long,
        allow_hyphen_values = true,
        requires_all = ["unit_weight", "ring"],
        conflicts_with = "radius"
    )]
    width: Option<f64>,
    /// Unit weight of the masonry in kN/m^3 (e.g. 20 for stone).
    #[arg(long, allow_hyphen_values = true, requires = "width")]
    unit_weight: Option<f64>,
}

impl DimensionArgs {
    /// The dimensions, when given; each must be a finite positive number. With `--width`
    /// and `--unit-weight` the mean radius is the ring's (`geometry`), and the density the
    /// unit weight over g.
    pub(crate) fn build(
        &self,
        geometry: Option<Geometry>,
    ) -> Result<Option<Dimensions>, InputError> {
        if let (Some(d), Some(gamma)) = (self.width, self.unit_weight) {
            let Some(ring) = geometry.and_then(|g| g.ring) else {
                return Err(InputError::Inconsistent {
                    arg: "--width/--unit-weight",
                    reason: "need the ring's mean radius: give --span, --rise and --ring".into(),
                });
            };
            let g = positive("--g", self.g)?;
            return Ok(Some(Dimensions {
                radius: ring.radius,
                depth: positive("--width", d)?,
                density: positive("--unit-weight", gamma)? * 1000.0 / g,
                g,
                intrados: geometry.map(|g| g.intrados),
            }));
        }
        match (self.radius, self.depth, self.density) {
            (Some(r), Some(d), Some(rho)) => Ok(Some(Dimensions {
                radius: positive("--radius", r)?,
                depth: positive("--depth", d)?,
                density: positive("--density", rho)?,
                g: positive("--g", self.g)?,
                intrados: None,
            })),
            _ => Ok(None),
        }
    }
}

/// The engineer's geometry, the dimensions and the thickness ratio of a command that takes
/// `--eta` (or `--ring`) with the arch and `DimensionArgs`.
pub(crate) fn sized(
    arch: &ArchArgs,
    dims: &DimensionArgs,
    eta: Option<f64>,
) -> Result<(Option<Geometry>, Option<Dimensions>, f64), InputError> {
    let geometry = arch.geometry()?;
    Ok((geometry, dims.build(geometry)?, arch.eta(eta)?))
}
