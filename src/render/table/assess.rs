//! The answer of `assess` as text, in units of the arch and, given its [`Dimensions`], in
//! metres and kilonewtons.

use super::format::{describe_arch, eta_digits, fmt_mu, sig, Dimensions};
use crate::arch::Arch;
use crate::assess::{Assessment, LeastFriction};
use crate::limit::Outcome;
use std::fmt::Write;

/// The human-readable answer of `assess`.
pub fn assess(arch: &Arch, a: &Assessment, dims: Option<Dimensions>) -> String {
    let mut s = String::new();
    let _ = writeln!(s, "{}", describe_arch(arch));
    let _ = writeln!(
        s,
        "thickness           eta = t/r = {}\nfriction            mu = {}  (friction angle {:.6} deg)",
        sig(a.eta, 12),
        fmt_mu(a.mu),
        a.mu.atan().to_degrees()
    );
    let _ = writeln!(
        s,
        "verdict             {}",
        if a.stands {
            "STANDS (a statically admissible state exists)"
        } else {
            "DOES NOT STAND (no statically admissible state)"
        }
    );
    match &a.limit {
        Outcome::Limit(ls) => {
            let _ = writeln!(
                s,
                "least thickness     eta*(mu) = {}  ({})",
                sig(ls.eta, eta_digits(ls)),
                ls.mode.name()
            );
        }
        Outcome::NoCollapse { reason } => {
            let _ = writeln!(s, "least thickness     none: {reason}");
        }
        Outcome::NoEquilibrium { reason, .. } | Outcome::Unresolved { reason, .. } => {
            let _ = writeln!(s, "least thickness     not found: {reason}");
        }
    }
    if let Some(g) = a.geometric_factor {
        let _ = writeln!(s, "geometric factor    eta / eta* = {}", sig(g, 10));
    }
    least_friction(&mut s, a);
    if let Some(d) = dims {
        in_units(&mut s, arch, a, d);
    }
    s
}

/// μ_min(η), the friction factor and the safest state.
fn least_friction(s: &mut String, a: &Assessment) {
    match &a.least_friction {
        LeastFriction::Finite { mu, exact, .. } => {
            let _ = writeln!(
                s,
                "least friction      mu_min(eta) = {}  (friction angle {:.6} deg){}",
                if mu.is_finite() {
                    sig(*mu, 12)
                } else {
                    "inf".into()
                },
                mu.atan().to_degrees(),
                if *exact {
                    ""
                } else {
                    "  (LP bound, not refined)"
                }
            );
        }
        LeastFriction::Never => {
            let _ = writeln!(
                s,
                "least friction      none: this thickness stands at no friction"
            );
        }
    }
    if let Some(f) = a.friction_factor {
        let _ = writeln!(
            s,
            "friction factor     mu / mu_min = {}",
            if f.is_finite() {
                sig(f, 10)
            } else {
                "inf".into()
            }
        );
    }
    if let Some(st) = &a.safest {
        let _ = writeln!(
            s,
            "safest state        h = {}   v = {}   w = {}   (margin {})",
            sig(st.x[0], 10),
            sig(st.x[1], 10),
            sig(st.x[2], 10),
            sig(st.margin, 4)
        );
    }
}

/// Lengths in metres and forces in kilonewtons.
fn in_units(s: &mut String, arch: &Arch, a: &Assessment, d: Dimensions) {
    // forces in units of γ t d r with γ = ρ g and t = η r
    let force = d.density * d.g * a.eta * d.radius * d.depth * d.radius / 1000.0;
    let _ = writeln!(
        s,
        "in units            r = {} m, t = {} m, d = {} m; weight of the arch {} kN",
        sig(d.radius, 6),
        sig(a.eta * d.radius, 6),
        sig(d.depth, 6),
        sig(force * arch.span(), 6)
    );
    if let Outcome::Limit(ls) = &a.limit {
        let _ = match d.intrados {
            None => writeln!(
                s,
                "                    least thickness t* = {} m",
                sig(ls.eta * d.radius, 6)
            ),
            Some(i) => writeln!(
                s,
                "                    least ring t* = {} m (span and rise held)",
                sig(i.ring_of(ls.eta).thickness, 6)
            ),
        };
    }
    if let Some(st) = &a.safest {
        let _ = writeln!(
            s,
            "                    safest state at the right springing: H = {} kN, V = {} kN, M = {} kN m",
            sig(st.x[0] * force, 6),
            sig(st.x[1] * force, 6),
            sig(st.x[2] * force * d.radius, 6)
        );
    }
}
