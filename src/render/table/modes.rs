//! The answer of `modes` as text: the branches of the static boundary and its corners,
//! as in a paper.

use super::format::{
    degrees, describe_arch, fmt_mu, fmt_opt_inf, right_half_angle, short, sig, LEGEND,
};
use crate::arch::Arch;
use crate::limit_curve::{CurveStatus, LimitCurve};
use std::fmt::Write;

/// The human-readable answer of `modes`: branches and corners, as in a paper.
pub fn modes(arch: &Arch, curve: &LimitCurve) -> String {
    let mut s = String::new();
    let _ = writeln!(s, "{}", describe_arch(arch));
    match curve.mu_ms {
        Some(m) => {
            let _ = writeln!(
                s,
                "least friction for equilibrium mu_ms = {} (friction angle {:.6} deg)",
                sig(m, 12),
                m.atan().to_degrees()
            );
        }
        None => {
            let _ = writeln!(s, "no finite friction coefficient admits equilibrium");
            return s;
        }
    }
    if !traced(&mut s, curve) {
        return s;
    }
    branches(&mut s, curve);
    changes(
        &mut s,
        arch,
        &curve.corners,
        "corners (kinks of eta_s(mu)), by decreasing mu (beta_N: intrados hinge, beta_T: sliding joint, right half):",
    );
    if !curve.transitions.is_empty() {
        changes(
            &mut s,
            arch,
            &curve.transitions,
            "smooth transitions (the pattern changes, eta_s(mu) has no kink), by decreasing mu:",
        );
    }
    limit_branches(&mut s, curve);
    for (mu, m) in &curve.unresolved {
        let _ = writeln!(s, "  unresolved sample at mu = {mu}: {m}");
    }
    s.push_str(LEGEND);
    s
}

/// Whether the curve was traced; if not, why there is no branch.
fn traced(s: &mut String, curve: &LimitCurve) -> bool {
    match curve.status() {
        CurveStatus::Traced => return true,
        CurveStatus::NoEquilibrium => {
            let _ = writeln!(
                s,
                "no branch: no thickness eta < 2 admits equilibrium at any friction (the opening is too large for the arch to stand)"
            );
        }
        CurveStatus::NoCollapse => {
            let _ = writeln!(
                s,
                "no collapse: at every sampled friction from mu = {} to inf a state is admissible at vanishing thickness, so the arch stands at every eta > 0",
                fmt_mu(curve.no_collapse.iter().copied().fold(f64::INFINITY, f64::min))
            );
            if let Some(m) = curve.no_equilibrium.iter().copied().reduce(f64::max) {
                let _ = writeln!(
                    s,
                    "  (no thickness stands at the sampled mu <= {})",
                    fmt_mu(m)
                );
            }
        }
        CurveStatus::Unresolved => {
            let _ = writeln!(s, "no branch could be traced:");
            for (mu, m) in &curve.unresolved {
                let _ = writeln!(s, "  at mu = {}: {m}", fmt_mu(*mu));
            }
        }
    }
    false
}

/// The branches of the static boundary, and where it reaches the thickness limit.
fn branches(s: &mut String, curve: &LimitCurve) {
    let _ = writeln!(
        s,
        "\nbranches of the static boundary eta_s(mu), by decreasing mu:"
    );
    let _ = writeln!(
        s,
        "  {:<30} {:>15} {:>15}   {:>15} {:>15}   pattern (kind@beta deg)",
        "mode", "mu from", "mu to", "eta from", "eta to"
    );
    for b in &curve.branches {
        let ends = [b.mu_max, b.mu_min, b.eta_min, b.eta_max];
        let _ = writeln!(s, "{}   {}", branch_row(b.mode, ends), degrees(&b.pattern));
    }
    if let Some(t) = &curve.thickness_limit {
        let _ = writeln!(
            s,
            "\nthe boundary reaches the thickness limit eta -> 2 at mu = {}{}: below it no thickness\n  eta < 2 stands (the purely sliding corner at mu_ms would need eta >= 2)",
            sig(t.mu, 12),
            if t.exact { "" } else { " (bracketed by bisection)" }
        );
    }
}

/// The limit states above the boundary, grouped into branches over the samples.
fn limit_branches(s: &mut String, curve: &LimitCurve) {
    if curve.limit_branches.is_empty() {
        let _ = writeln!(
            s,
            "\nlimit states above the boundary: none at the {} sampled mu",
            curve.samples
        );
        return;
    }
    let _ = writeln!(
        s,
        "\nlimit states above the boundary eta_s(mu) (non-associative non-uniqueness), by sample:"
    );
    let _ = writeln!(
        s,
        "  {:<30} {:>15} {:>15}   {:>15} {:>15}  samples  pattern (kind@beta deg)",
        "mode", "mu from", "mu to", "eta from", "eta to"
    );
    for lb in &curve.limit_branches {
        let b = &lb.branch;
        let ends = [b.mu_max, b.mu_min, b.eta_min, b.eta_max];
        let _ = writeln!(
            s,
            "{}  {:>7}  {}",
            branch_row(b.mode, ends),
            lb.samples,
            degrees(&b.pattern)
        );
    }
}

/// A branch's mode and its ends [μ from, μ to, η from, η to] as table columns.
fn branch_row(mode: crate::collapse_mode::CollapseMode, ends: [f64; 4]) -> String {
    let [a, b, c, d] = ends.map(|v| fmt_opt_inf(v, 10));
    format!("  {:<30} {a:>15} {b:>15}   {c:>15} {d:>15}", mode.name())
}

/// One-sided slope for the tables: `vertical` for −∞, `-` where undefined.
fn fmt_slope(v: f64) -> String {
    if v == f64::NEG_INFINITY {
        "vertical".into()
    } else if v.is_nan() {
        "-".into()
    } else {
        sig(v, 8)
    }
}

/// The table of located pattern changes (corners or transitions).
fn changes(s: &mut String, arch: &Arch, list: &[crate::limit_curve::Corner], title: &str) {
    use crate::contact::ContactKind;
    let _ = writeln!(s, "\n{title}");
    let _ = writeln!(
        s,
        "  {:>16} {:>11} {:>16} {:>14} {:>14}  {:<52} exact",
        "mu", "phi [deg]", "eta", "beta_N [rad]", "beta_T [rad]", "between"
    );
    for c in list {
        let bn = right_half_angle(arch, &c.pattern, |c| c.kind == ContactKind::HingeIntrados);
        let bt = right_half_angle(arch, &c.pattern, |c| !c.kind.is_hinge());
        let f = |v: Option<f64>| v.map_or("-".to_string(), |b| format!("{b:.10}"));
        let _ = writeln!(
            s,
            "  {:>16} {:>11} {:>16} {:>14} {:>14}  {:<52} {}",
            fmt_opt_inf(c.mu, 12),
            fmt_opt_inf(c.mu.atan().to_degrees(), 6),
            sig(c.t, 12),
            f(bn),
            f(bt),
            format!("{} / {}", c.between()[0].name(), c.between()[1].name()),
            if c.exact { "yes" } else { "no (bracketed)" }
        );
        let joints: Vec<String> = c
            .pattern
            .iter()
            .map(|j| {
                format!(
                    "{}@{:.10}{}",
                    short(j),
                    j.beta,
                    if j.at == crate::contact::Location::Springing {
                        "(s)"
                    } else {
                        ""
                    }
                )
            })
            .collect();
        let _ = writeln!(
            s,
            "  {:>16} pattern: {}\n  {:>16} named by its own pattern: {}; slopes d eta/d mu: left {}, right {}",
            "",
            joints.join(" "),
            "",
            c.detail.mode.name(),
            fmt_slope(c.sides[0].slope),
            fmt_slope(c.sides[1].slope)
        );
    }
}
