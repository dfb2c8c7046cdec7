//! The description of the arch shared by every command (`--alpha`, `--beta-right`, ...).

use crate::arch::{fmt_value, Arch, InputError, WeightModel};
use clap::{Args, ValueEnum};

/// Where self-weight acts.
#[derive(ValueEnum, Clone, Copy, Debug)]
pub(crate) enum WeightArg {
    /// Self-weight along the centreline (Heyman).
    Centreline,
    /// Self-weight at the true centroid of each piece (Milankovitch).
    Centroid,
}

impl From<WeightArg> for WeightModel {
    fn from(w: WeightArg) -> WeightModel {
        match w {
            WeightArg::Centreline => WeightModel::Centreline,
            WeightArg::Centroid => WeightModel::Centroid,
        }
    }
}

#[derive(Args, Debug)]
pub(crate) struct ArchArgs {
    /// Opening of a symmetric arch in radians, -pi/2 < alpha < pi/2 (0: semicircle).
    #[arg(long, allow_hyphen_values = true, group = "shape")]
    alpha: Option<f64>,
    /// Opening of a symmetric arch in degrees, -90 < alpha-deg < 90.
    #[arg(long, allow_hyphen_values = true, group = "shape")]
    alpha_deg: Option<f64>,
    /// Right springing angle of an unsymmetric arch (radians); needs --beta-left.
    #[arg(
        long,
        allow_hyphen_values = true,
        group = "shape",
        requires = "beta_left"
    )]
    beta_right: Option<f64>,
    /// Left springing angle (radians), beta_right < beta_left <= beta_right + 2 pi.
    #[arg(long, allow_hyphen_values = true, requires = "beta_right")]
    beta_left: Option<f64>,
    /// N equal voussoirs: joints only at the N + 1 equally spaced angles (1 to 100000).
    #[arg(long, conflicts_with = "joints", allow_hyphen_values = true)]
    blocks: Option<usize>,
    /// Explicit joint angles in radians, comma-separated, increasing, within the springings.
    #[arg(long, value_delimiter = ',', allow_hyphen_values = true)]
    joints: Option<Vec<f64>>,
    /// Where self-weight acts.
    #[arg(long, value_enum, default_value = "centreline")]
    pub(crate) weight: WeightArg,
}

impl ArchArgs {
    pub(crate) fn build(&self) -> Result<Arch, InputError> {
        let weight = WeightModel::from(self.weight);
        let arch = match (self.alpha, self.alpha_deg, self.beta_right, self.beta_left) {
            (Some(a), _, _, _) => Arch::symmetric(a, weight)?,
            (_, Some(d), _, _) => Arch::symmetric(d.to_radians(), weight).map_err(|_| InputError::OutOfRange {
                arg: "--alpha-deg",
                value: fmt_value(d),
                range: "(-90, 90) degrees".into(),
            })?,
            (_, _, Some(r), Some(l)) => Arch::new(r, l, weight)?,
            _ => {
                return Err(InputError::Inconsistent {
                    arg: "--alpha/--alpha-deg/--beta-right/--beta-left",
                    reason: "describe the arch with --alpha A, --alpha-deg D, or --beta-right B1 --beta-left B2".into(),
                })
            }
        };
        match (&self.blocks, &self.joints) {
            (Some(n), _) => arch.with_blocks(*n),
            (_, Some(j)) => arch.with_joints(j),
            _ => Ok(arch),
        }
    }
}
