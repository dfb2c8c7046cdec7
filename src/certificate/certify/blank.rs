//! The frame of a certificate: format, version, tool, the arch, μ and the claim, every
//! section still empty.

use crate::arch::{Arch, JointLayout};
use crate::certificate::format::{ArchSpec, Certificate, Claim, FillSpec, FORMAT, VERSION};

pub(super) fn spec(arch: &Arch) -> ArchSpec {
    ArchSpec {
        beta_right: arch.beta_right(),
        beta_left: arch.beta_left(),
        weight: arch.weight(),
        joint_angles: match arch.layout() {
            JointLayout::Continuous => None,
            JointLayout::Discrete(j) => Some(j.clone()),
        },
        fill: arch.fill().map(|f| FillSpec {
            weight_ratio: f.weight_ratio,
            depth: f.depth,
        }),
    }
}

pub(super) fn empty(arch: &Arch, mu: f64, claim: Claim) -> Certificate {
    Certificate {
        format: FORMAT.into(),
        version: VERSION,
        tool: format!("arch-enum {}", env!("CARGO_PKG_VERSION")),
        arch: spec(arch),
        mu: mu.is_finite().then_some(mu),
        claim,
        safe: None,
        collapse: None,
        collapse_cells: None,
        limit_state: None,
        gap: None,
        gap_relative: None,
        search: None,
        load: None,
        multiplier: None,
        load_search: None,
    }
}
