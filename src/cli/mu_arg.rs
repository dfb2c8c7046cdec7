//! `--mu`: a friction coefficient, `inf` (no sliding) or `ms` (the arch's own μ_ms).

use crate::arch::{Arch, InputError};
use crate::limit::mu_ms_of;
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
    /// The number: `ms` is μ_ms of `arch` ([`crate::limit::mu_ms_of`]).
    pub(crate) fn resolve(self, arch: &Arch, settings: &Settings) -> Result<f64, InputError> {
        match self {
            MuArg::Value(mu) => Ok(mu),
            MuArg::Ms => mu_ms_of(arch, settings),
        }
    }
}
