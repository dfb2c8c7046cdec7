//! The answer of `modes` for an arch with fill as text: the boundary μ_min(η) of the region
//! where it stands, traced in η.

use super::format::{describe_arch, fmt_mu, short, sig, LEGEND};
use crate::arch::{Arch, ETA_TOP};
use crate::bridge::Intrados;
use crate::limit_curve::filled::{FillCurve, FrictionPoint};
use crate::render::json::FillJson;
use std::fmt::Write;

/// A point as `kind@beta` columns.
fn pattern(p: &FrictionPoint) -> String {
    let joints: Vec<String> = p
        .pattern
        .iter()
        .map(|c| format!("{}@{:.3}", short(c), c.beta.to_degrees()))
        .collect();
    joints.join(" ")
}

/// The human-readable answer of `modes` with fill.
pub fn modes_fill(
    arch: &Arch,
    fill: Option<&FillJson>,
    intrados: Option<&Intrados>,
    curve: &FillCurve,
) -> String {
    let metres = |eta: f64| {
        intrados.map_or(String::new(), |i| {
            format!(" (ring {} m)", sig(i.ring_of(eta).thickness, 6))
        })
    };
    let mut s = String::new();
    let _ = writeln!(s, "{}", describe_arch(arch));
    s.push_str(&super::bridge::bridge(fill, None, None, None));
    let Some(eta_inf) = curve.eta_inf else {
        for (_, m) in &curve.unresolved {
            let _ = writeln!(s, "no curve            {m}");
        }
        return s;
    };
    let _ = writeln!(
        s,
        "traced in eta       with fill the friction a ring needs moves with its thickness: the curve is mu_min(eta), from eta*(inf) = {}{} (no thinner ring stands at any friction) to the thickness limit {ETA_TOP}",
        sig(eta_inf, 12),
        metres(eta_inf)
    );
    if let Some(l) = &curve.least {
        let at_top = curve.samples.last().is_some_and(|p| p.eta <= l.eta);
        let shape = if at_top {
            "at the thickness limit: the whole curve is the least thickness eta_s(mu)"
        } else {
            "thinner than eta_f the curve is the least thickness eta_s(mu), thicker the greatest thickness that stands at mu"
        };
        let _ = writeln!(
            s,
            "least friction      mu_f = {} (friction angle {:.6} deg) at eta_f = {}{} ({}): nothing stands below it;\n                    {shape}",
            sig(l.mu, 12),
            l.mu.atan().to_degrees(),
            sig(l.eta, 12),
            metres(l.eta),
            l.mode.name()
        );
    }
    let _ = writeln!(
        s,
        "branches, by increasing eta (their ends: samples or the ends of a change):"
    );
    let _ = writeln!(
        s,
        "  {:>16}  {:>16}  {:>14}  {:>14}  {:<26} pattern at the thinner end",
        "eta from", "eta to", "mu_min (from)", "mu_min (to)", "mode"
    );
    for b in &curve.branches {
        let _ = writeln!(
            s,
            "  {:>16}  {:>16}  {:>14}  {:>14}  {:<26} {}",
            sig(b.ends[0].eta, 12),
            sig(b.ends[1].eta, 12),
            fmt_mu(b.ends[0].mu),
            fmt_mu(b.ends[1].mu),
            b.mode.name(),
            pattern(&b.ends[0])
        );
    }
    if !curve.changes.is_empty() {
        let _ = writeln!(
            s,
            "pattern changes, bisected in eta (both ends of each bracket):"
        );
        for c in &curve.changes {
            let tight = if c.tight {
                "bisected to neighbouring floats"
            } else {
                "bisection stopped before neighbouring floats"
            };
            for (i, e) in c.ends.iter().enumerate() {
                let _ = writeln!(
                    s,
                    "  {} eta = {:<16} mu_min = {:<14} {:<28} {}",
                    if i == 0 { "from" } else { "  to" },
                    sig(e.eta, 12),
                    fmt_mu(e.mu),
                    e.mode.name(),
                    pattern(e)
                );
            }
            let _ = writeln!(s, "       ({tight})");
        }
    }
    let _ = writeln!(s, "samples:");
    let ring = if intrados.is_some() { "ring [m]" } else { "" };
    let _ = writeln!(
        s,
        "  {:>16}  {ring:>10}  {:>16}  {:<28} pattern (kind@beta deg)",
        "eta", "mu_min", "mode"
    );
    for p in &curve.samples {
        let t = intrados.map_or(String::new(), |i| sig(i.ring_of(p.eta).thickness, 6));
        let _ = writeln!(
            s,
            "  {:>16}  {t:>10}  {:>16}  {:<28} {}",
            sig(p.eta, 12),
            fmt_mu(p.mu),
            p.mode.name(),
            pattern(p)
        );
    }
    for (eta, m) in &curve.unresolved {
        let _ = writeln!(s, "  unresolved at eta = {eta}: {m}");
    }
    s.push_str(LEGEND);
    s
}
