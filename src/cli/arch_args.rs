//! The description of the arch shared by every command (`--alpha`, `--beta-right`, ...).

use crate::arch::{check_eta, fmt_value, Arch, InputError, WeightModel};
use crate::bridge::{Geometry, Intrados};
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
    /// Clear span of the intrados between its springings, in metres (a symmetric arch; with
    /// --rise).
    #[arg(long, allow_hyphen_values = true, group = "shape", requires = "rise")]
    span: Option<f64>,
    /// Rise of the intrados above its springings, in metres (with --span; rise = span/2 is
    /// the semicircle, above it a horseshoe).
    #[arg(long, allow_hyphen_values = true, requires = "span")]
    rise: Option<f64>,
    /// Ring thickness t in metres on the --span/--rise intrados: gives eta = t/r, with the
    /// mean radius r = R_i + t/2.
    #[arg(long, allow_hyphen_values = true, requires = "span")]
    pub(crate) ring: Option<f64>,
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
            _ => match self.intrados()? {
                Some(i) => Arch::symmetric(i.alpha(), weight)?,
                None => {
                    return Err(InputError::Inconsistent {
                        arg: "--alpha/--alpha-deg/--beta-right/--beta-left/--span",
                        reason: "describe the arch with --alpha A, --alpha-deg D, --beta-right B1 --beta-left B2, or --span L --rise F".into(),
                    })
                }
            },
        };
        match (&self.blocks, &self.joints) {
            (Some(n), _) => arch.with_blocks(*n),
            (_, Some(j)) => arch.with_joints(j),
            _ => Ok(arch),
        }
    }

    /// [`ArchArgs::build`] for a command that takes no thickness (`modes`, `curve`, `plot
    /// map`): `--ring` is refused there rather than ignored.
    pub(crate) fn build_without_ring(&self) -> Result<Arch, InputError> {
        if self.ring.is_some() {
            return Err(InputError::Inconsistent {
                arg: "--ring",
                reason: "this command takes no thickness (it finds eta* over mu); --ring is for solve, assess, load, load-curve, certify under a load and plot arch/load/eccentricity".into(),
            });
        }
        self.build()
    }

    /// The intrados of `--span/--rise`, when given.
    pub(crate) fn intrados(&self) -> Result<Option<Intrados>, InputError> {
        match (self.span, self.rise) {
            (Some(l), Some(f)) => Intrados::new(l, f).map(Some),
            _ => Ok(None),
        }
    }

    /// The engineering description (`--span/--rise`, and `--ring`), when given.
    pub(crate) fn geometry(&self) -> Result<Option<Geometry>, InputError> {
        let Some(intrados) = self.intrados()? else {
            return Ok(None);
        };
        let ring = self.ring.map(|t| intrados.ring(t)).transpose()?;
        Ok(Some(Geometry { intrados, ring }))
    }

    /// The thickness ratio: `--eta`, or that of `--ring` (exactly one of them).
    pub(crate) fn eta(&self, eta: Option<f64>) -> Result<f64, InputError> {
        let ring = self.geometry()?.and_then(|g| g.ring);
        match (eta, ring) {
            (Some(e), None) => check_eta(e),
            (None, Some(r)) => Ok(r.eta),
            (Some(_), Some(_)) => Err(InputError::Inconsistent {
                arg: "--eta/--ring",
                reason: "give the thickness as --eta or as --ring (with --span and --rise), not both".into(),
            }),
            (None, None) => Err(InputError::Inconsistent {
                arg: "--eta",
                reason: "give the thickness ratio --eta (0 < eta < 2), or --ring T with --span and --rise".into(),
            }),
        }
    }
}
