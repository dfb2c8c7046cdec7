//! The answer of `curve` as text: one row per sampled μ.

use super::format::{describe_arch, eta_digits, fmt_mu, short, sig};
use crate::arch::Arch;
use crate::limit::Outcome;
use crate::limit_curve::CurvePoint;
use crate::render::json::FillJson;
use std::f64::consts::PI;
use std::fmt::Write;

/// The human-readable table of `curve`.
pub fn curve(
    arch: &Arch,
    mu_ms: Option<f64>,
    fill: Option<&FillJson>,
    points: &[CurvePoint],
) -> String {
    let mut s = String::new();
    let _ = writeln!(s, "{}", describe_arch(arch));
    match (mu_ms, fill) {
        (Some(m), _) => {
            let _ = writeln!(s, "least friction for equilibrium mu_ms = {}", sig(m, 12));
        }
        (None, Some(f)) => {
            s.push_str(&super::bridge::bridge(Some(f), None, None, None));
            let _ = writeln!(
                s,
                "least friction      with fill a curve mu_ms(eta), not one number: where no thickness stands the sample says so"
            );
        }
        (None, None) => {
            let _ = writeln!(s, "no finite friction coefficient admits equilibrium");
        }
    }
    let _ = writeln!(
        s,
        "{:>16}  {:>10}  {:>16}  {:<28} pattern (kind@beta deg)",
        "mu", "phi [deg]", "eta*", "mode"
    );
    for p in points {
        let phi = p.mu.atan() * 180.0 / PI;
        match &p.outcome {
            Outcome::Limit(ls) => {
                let joints: Vec<String> = ls
                    .pattern
                    .iter()
                    .map(|c| format!("{}@{:.3}", short(c), c.beta.to_degrees()))
                    .collect();
                let _ = writeln!(
                    s,
                    "{:>16}  {:>10.5}  {:>16}  {:<28} {}",
                    fmt_mu(p.mu),
                    phi,
                    sig(ls.eta, eta_digits(ls)),
                    ls.mode.name(),
                    joints.join(" ")
                );
            }
            Outcome::NoEquilibrium { .. } => {
                let _ = writeln!(
                    s,
                    "{:>16}  {:>10.5}  {:>16}  {:<28}",
                    fmt_mu(p.mu),
                    phi,
                    "-",
                    "no_equilibrium"
                );
            }
            Outcome::NoCollapse { .. } => {
                let _ = writeln!(
                    s,
                    "{:>16}  {:>10.5}  {:>16}  {:<28}",
                    fmt_mu(p.mu),
                    phi,
                    "0",
                    "no_collapse"
                );
            }
            Outcome::Unresolved { eta_lo, eta_hi, .. } => {
                let _ = writeln!(
                    s,
                    "{:>16}  {:>10.5}  {:>16}  unresolved in [{}, {}]",
                    fmt_mu(p.mu),
                    phi,
                    "?",
                    sig(*eta_lo, 10),
                    sig(*eta_hi, 10)
                );
            }
        }
    }
    s
}
