//! `--mu`: a friction coefficient, `inf` (no sliding) or `ms` (the arch's own μ_ms).

use crate::arch::{Arch, InputError};
use crate::friction::least_friction;
use crate::limit::MU_MS_ZERO;
use crate::settings::Settings;
use std::str::FromStr;

/// The friction coefficient asked for.
#[derive(Debug, Clone, Copy)]
pub(crate) enum MuArg {
    /// A number (`inf` included); its range is checked by the solver.
    Value(f64),
    /// The least friction at which the arch stands, μ_ms: the vertical branch.
    Ms,
}

impl FromStr for MuArg {
    type Err = String;

    fn from_str(s: &str) -> Result<Self, Self::Err> {
        if s.eq_ignore_ascii_case("ms") {
            return Ok(MuArg::Ms);
        }
        s.parse::<f64>()
            .map(MuArg::Value)
            .map_err(|_| format!("expected a number, `inf` or `ms`, got `{s}`"))
    }
}

impl MuArg {
    /// The number: `ms` is μ_ms of `arch`, an error naming `--mu` when the arch has none
    /// (it stands without friction, or at no finite friction) or it cannot be computed.
    pub(crate) fn resolve(self, arch: &Arch, settings: &Settings) -> Result<f64, InputError> {
        if let MuArg::Value(mu) = self {
            return Ok(mu);
        }
        let reason = match least_friction(arch, settings) {
            Ok(Some(m)) if m >= MU_MS_ZERO => return Ok(m),
            Ok(Some(_)) => "this arch stands without friction (mu_ms = 0)".to_string(),
            Ok(None) => "no finite friction makes this arch stand".to_string(),
            Err(e) => format!("mu_ms could not be computed ({e})"),
        };
        Err(InputError::Inconsistent {
            arg: "--mu ms",
            reason,
        })
    }
}
