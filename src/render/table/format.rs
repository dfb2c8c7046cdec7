//! The text formats every table shares: numbers to their digits, μ, the arch in one line,
//! a pattern as a table or as `kind@beta`, the legend of the pattern columns, and the
//! dimensions of a real arch for results in metres and kilonewtons.

use crate::arch::{Arch, JointLayout};
use crate::contact::Contact;
use crate::limit::LeastLimitState;
pub use crate::render::dimensions::Dimensions;
use std::fmt::Write;

/// `v` with `digits` significant digits: fixed-point where that is readable
/// (1e-3 ≤ |v| < 1e7), scientific otherwise, so that small thicknesses of shallow arches
/// keep their digits.
pub fn sig(v: f64, digits: usize) -> String {
    if v == 0.0 || !v.is_finite() {
        return format!("{v}");
    }
    let e = v.abs().log10().floor() as i32;
    if (-3..7).contains(&e) {
        let decimals = (digits as i32 - 1 - e).max(0) as usize;
        format!("{v:.decimals$}")
    } else {
        format!("{:.*e}", digits - 1, v)
    }
}

/// The significant digits of η that its rounding leaves ([`LeastLimitState::eta_rounding`]): at
/// most 12, at least 3.
pub(super) fn eta_digits(ls: &LeastLimitState) -> usize {
    let r = ls.eta_rounding;
    if r > 0.0 && r.is_finite() {
        ((-r.log10()).floor() as i64).clamp(3, 12) as usize
    } else {
        12
    }
}

/// Formats μ (∞ for infinite friction).
pub fn fmt_mu(mu: f64) -> String {
    if mu.is_infinite() {
        "inf".to_string()
    } else if (1e-4..1e7).contains(&mu) {
        format!("{mu:.10}")
    } else {
        format!("{mu:e}")
    }
}

/// One line describing the arch.
pub fn describe_arch(arch: &Arch) -> String {
    let shape = if arch.is_symmetric() {
        let alpha = 0.0 - arch.beta_right();
        format!(
            "symmetric arch, opening alpha = {alpha:.10} rad ({:.4} deg)",
            alpha.to_degrees()
        )
    } else {
        format!(
            "unsymmetric arch, springings beta_R = {:.10} rad, beta_L = {:.10} rad",
            arch.beta_right(),
            arch.beta_left()
        )
    };
    let joints = match arch.layout() {
        JointLayout::Continuous => "continuous joints".to_string(),
        JointLayout::Discrete(j) => format!("{} voussoirs ({} joints)", j.len() - 1, j.len()),
    };
    format!(
        "{shape}; {joints}; weight along the {}",
        match arch.weight() {
            crate::arch::WeightModel::Centreline => "centreline",
            crate::arch::WeightModel::Centroid => "true centroid (Milankovitch)",
        }
    )
}

fn middle_name(arch: &Arch) -> &'static str {
    if arch.is_symmetric() {
        "crown"
    } else {
        "middle"
    }
}

/// A table of the contacts of a pattern, with optional rates.
pub fn pattern_table(arch: &Arch, pattern: &[Contact], rates: Option<&[f64]>) -> String {
    let mid = 0.5 * (arch.beta_right() + arch.beta_left());
    let mut s = String::new();
    let _ = writeln!(
        s,
        "  {:>2}  {:>14}  {:>10}  {:>14}  {:<15} {:<10}{}",
        "#",
        "beta [rad]",
        "beta [deg]",
        format!("from {} [deg]", middle_name(arch)),
        "kind",
        "at",
        if rates.is_some() { "  rate" } else { "" }
    );
    for (i, c) in pattern.iter().enumerate() {
        // no "-0.00000" at the middle: rounding residue of β − β_mid is not a sign
        let from_mid = (c.beta - mid).to_degrees();
        let from_mid = if from_mid.abs() < 5e-6 { 0.0 } else { from_mid };
        let _ = write!(
            s,
            "  {:>2}  {:>14.10}  {:>10.5}  {:>14.5}  {:<15} {:<10}",
            i + 1,
            c.beta,
            c.beta.to_degrees(),
            from_mid,
            c.kind.name(),
            match c.at {
                crate::contact::Location::Springing => "springing",
                crate::contact::Location::Interior => "interior",
            }
        );
        if let Some(r) = rates {
            let _ = write!(s, "  {:.6}", r[i]);
        }
        s.push('\n');
    }
    s.lines().map(|l| l.trim_end().to_string() + "\n").collect()
}

pub(crate) fn short(c: &Contact) -> &'static str {
    match c.kind {
        crate::contact::ContactKind::HingeExtrados => "E",
        crate::contact::ContactKind::HingeIntrados => "I",
        crate::contact::ContactKind::SlidePlus => "S+",
        crate::contact::ContactKind::SlideMinus => "S-",
    }
}

pub(super) fn fmt_opt_inf(v: f64, digits: usize) -> String {
    if v.is_infinite() {
        "inf".to_string()
    } else {
        format!("{v:.digits$}")
    }
}

/// The first interior contact of the right half of the arch (the middle joint itself
/// excluded) whose kind passes `pick`: β_N for intrados hinges, β_T for sliding joints,
/// as tables in papers give them.
pub fn right_half_angle(
    arch: &Arch,
    joints: &[Contact],
    pick: impl Fn(&Contact) -> bool,
) -> Option<f64> {
    let mid = 0.5 * (arch.beta_right() + arch.beta_left());
    joints
        .iter()
        .find(|c| c.at == crate::contact::Location::Interior && c.beta < mid - 1e-6 && pick(c))
        .map(|c| c.beta)
}

/// A pattern as `kind@beta` in degrees.
pub(super) fn degrees(p: &[crate::contact::Contact]) -> String {
    p.iter()
        .map(|c| format!("{}@{:.3}", short(c), c.beta.to_degrees()))
        .collect::<Vec<_>>()
        .join(" ")
}

/// The notation of every pattern column.
pub const LEGEND: &str =
    "\nE: hinge at the extrados, I: hinge at the intrados, S+/S-: sliding along \
the (radial) joint, the part beyond it (larger beta) moving outwards/inwards, (s): at a springing; \
angles from the horizontal through the centre.\n";
