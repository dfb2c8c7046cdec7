//! Human-readable tables: pure functions returning text.

use crate::arch::{Arch, JointLayout};
use crate::contact::Contact;
use crate::limit::{LimitState, Outcome, Solution};
use crate::limit_curve::{CurvePoint, CurveStatus};
use crate::limit_states::Survey;
use std::f64::consts::PI;
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

/// The significant digits of η that its rounding leaves ([`LimitState::eta_rounding`]): at
/// most 12, at least 3.
fn eta_digits(ls: &LimitState) -> usize {
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

/// The human-readable answer of `solve`: η_s, the limit state at η_s in detail when there
/// is one, and every limit state found above η_s.
pub fn solve(survey: &Survey, explain: bool) -> String {
    let sol = &survey.solution;
    let mut s = String::new();
    let _ = writeln!(s, "{}", describe_arch(&sol.arch));
    let _ = writeln!(
        s,
        "friction            mu = {}  (friction angle {:.6} deg)",
        fmt_mu(sol.mu),
        sol.mu.atan().to_degrees()
    );
    match (&sol.outcome, &survey.states) {
        (Outcome::Limit(ls), states) => {
            let _ = writeln!(
                s,
                "least thickness     eta_s = t/r = {}",
                sig(ls.eta_static, eta_digits(ls))
            );
            if eta_digits(ls) < 12 {
                let _ = writeln!(
                    s,
                    "note                eta to {} significant digits: the terms of M cancel to eta N/2 at\n                    this opening, and their double-precision rounding moves eta by ~{:.0e} (relative)",
                    eta_digits(ls),
                    ls.eta_rounding
                );
            }
            if states.as_ref().is_ok_and(|st| !st.attained) {
                let _ = writeln!(
                    s,
                    "note                eta_s is an infimum, approached only as the reactions grow without\n                    bound (a weightless line of thrust fits the arch): no finite state there, so no\n                    limit state at eta_s"
                );
            } else if ls.eta_static < ls.eta {
                let _ = writeln!(
                    s,
                    "note                the least admissible state carries no mechanism without dilatancy\n                    (non-associative gap): the least limit state found lies above it"
                );
            } else {
                s.push_str(&limit_detail(sol, ls));
            }
        }
        (
            Outcome::Unresolved {
                least_static: Some((eta, _)),
                ..
            },
            Ok(_),
        ) => {
            let _ = writeln!(s, "least thickness     eta_s = t/r = {}", sig(*eta, 12));
            let _ = writeln!(
                s,
                "note                the least admissible state carries no mechanism without dilatancy"
            );
        }
        (Outcome::NoEquilibrium { reason, .. }, _) => {
            let _ = writeln!(s, "no equilibrium: {reason}");
        }
        (Outcome::NoCollapse { reason }, _) => {
            let _ = writeln!(s, "no collapse: {reason}");
        }
        (
            Outcome::Unresolved {
                eta_lo,
                eta_hi,
                reason,
                ..
            },
            _,
        ) => {
            let _ = writeln!(
                s,
                "unresolved: {reason}; eta_s lies in [{}, {}]",
                sig(*eta_lo, 12),
                sig(*eta_hi, 12)
            );
        }
    }
    s.push_str(&limit_states(survey));
    if explain {
        let tried: Vec<_> = sol.candidates.iter().filter(|c| c.tried).collect();
        let _ = writeln!(
            s,
            "\npatterns tried ({}), in the order verified; contacts by angle, kind@beta rad (deg):",
            tried.len()
        );
        for c in tried {
            let mut contacts = c.contacts.clone();
            contacts.sort_by(|a, b| a.beta.total_cmp(&b.beta));
            let joints: Vec<String> = contacts
                .iter()
                .map(|k| format!("{}@{:.6} ({:.3})", short(k), k.beta, k.beta.to_degrees()))
                .collect();
            let eta = c.eta.map_or("-".to_string(), |e| sig(e, 12));
            let _ = writeln!(
                s,
                "  {}\n      eta = {eta}: {}",
                joints.join(" "),
                c.verdict
            );
        }
        let skipped = sol.candidates.iter().filter(|c| !c.tried).count();
        if skipped > 0 {
            let _ = writeln!(
                s,
                "  ({skipped} smaller subsets not tried: a limit state at the static least thickness was verified first)"
            );
        }
    }
    s
}

/// The limit state at η_s in detail: pattern, reactions, mechanism, checks.
fn limit_detail(sol: &Solution, ls: &LimitState) -> String {
    let mut s = String::new();
    let _ = writeln!(
        s,
        "collapse mode       {}{}",
        ls.mode.name(),
        if ls.mode.is_standard() {
            ""
        } else {
            "  (descriptive name: none of the standard mode names fits this pattern)"
        }
    );
    let _ = writeln!(s, "active pattern ({} contacts):", ls.pattern.len());
    s.push_str(&pattern_table(&sol.arch, &ls.pattern, None));
    let _ =
        writeln!(
        s,
        "reactions at the right springing (units of gamma t d r, r^2):\n  h = {}   v = {}   w = {}",
        sig(ls.x[0], 12), sig(ls.x[1], 12), sig(ls.x[2], 12)
    );
    let m = &ls.mechanism;
    let _ = writeln!(
        s,
        "mechanism: cone of dimension {} on the pattern; {} representative (rates sum to 1):",
        m.dof,
        if m.symmetric { "symmetric" } else { "interior" }
    );
    s.push_str(&pattern_table(&sol.arch, &m.contacts, Some(&m.rates)));
    let _ = writeln!(
        s,
        "  external power L_e = {:.3e}   frictional dissipation = {:.3e}",
        m.power, m.dissipation
    );
    let _ = writeln!(
        s,
        "checks: Newton residual {:.1e}; max phi over the arch {:.1e}; |B lambda| {:.1e}; complementarity {:.1e}",
        ls.newton_residual, ls.max_phi, m.compatibility, m.complementarity
    );
    let _ = writeln!(
        s,
        "        LP bracket of eta_s: [{}, {}]",
        sig(ls.bracket.0, 12),
        sig(ls.bracket.1, 12)
    );
    s
}

/// Every limit state with η in [η_s, 2) and the verdict, or why the search stopped.
fn limit_states(survey: &Survey) -> String {
    let mut s = String::new();
    let states = match &survey.states {
        Ok(st) => st,
        Err(reason) => {
            if matches!(survey.solution.outcome, Outcome::Limit(_)) {
                let _ = writeln!(
                    s,
                    "limit states above eta_s: not searched to the end ({reason}); uniqueness undecided"
                );
            }
            return s;
        }
    };
    let count = usize::from(states.mechanism_at_eta_s) + states.above.len();
    let _ = writeln!(
        s,
        "limit states with eta in [eta_s, 2) ({}, {} {}{}):",
        states.method,
        states.events,
        if states.method.contains("ridge") {
            "ridge points"
        } else {
            "events"
        },
        if states.attained {
            ""
        } else {
            "; eta_s is an infimum: the least states' reactions grow without bound"
        }
    );
    if let (true, Outcome::Limit(ls)) = (states.mechanism_at_eta_s, &survey.solution.outcome) {
        let _ = writeln!(
            s,
            "  eta = {}  {}  (at eta_s)",
            sig(ls.eta, eta_digits(ls)),
            ls.mode.name()
        );
    }
    for a in &states.above {
        let _ = writeln!(
            s,
            "  eta = {}  {}  {}",
            sig(a.eta, 12),
            a.mode.name(),
            a.pattern
                .iter()
                .map(|c| format!("{}@{:.4}", short(c), c.beta))
                .collect::<Vec<_>>()
                .join(" ")
        );
    }
    let _ = writeln!(
        s,
        "verdict             {}",
        match count {
            0 => "no limit state: the arch stands from eta_s on without one (safe)".to_string(),
            1 if states.mechanism_at_eta_s =>
                "unique: the limit state at eta_s is the only one".to_string(),
            1 => "unique: one limit state, above eta_s".to_string(),
            n => format!("not unique: {n} limit states"),
        }
    );
    s
}

pub(crate) fn short(c: &Contact) -> &'static str {
    match c.kind {
        crate::contact::ContactKind::HingeExtrados => "E",
        crate::contact::ContactKind::HingeIntrados => "I",
        crate::contact::ContactKind::SlidePlus => "S+",
        crate::contact::ContactKind::SlideMinus => "S-",
    }
}

/// The human-readable table of `curve`.
pub fn curve(arch: &Arch, mu_ms: Option<f64>, points: &[CurvePoint]) -> String {
    let mut s = String::new();
    let _ = writeln!(s, "{}", describe_arch(arch));
    match mu_ms {
        Some(m) => {
            let _ = writeln!(s, "least friction for equilibrium mu_ms = {}", sig(m, 12));
        }
        None => {
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

fn fmt_opt_inf(v: f64, digits: usize) -> String {
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

/// The human-readable answer of `modes`: branches and corners, as in a paper.
pub fn modes(arch: &Arch, curve: &crate::limit_curve::LimitCurve) -> String {
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
    match curve.status() {
        CurveStatus::Traced => {}
        CurveStatus::NoEquilibrium => {
            let _ = writeln!(
                s,
                "no branch: no thickness eta < 2 admits equilibrium at any friction (the opening is too large for the arch to stand)"
            );
            return s;
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
            return s;
        }
        CurveStatus::Unresolved => {
            let _ = writeln!(s, "no branch could be traced:");
            for (mu, m) in &curve.unresolved {
                let _ = writeln!(s, "  at mu = {}: {m}", fmt_mu(*mu));
            }
            return s;
        }
    }
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
    if curve.limit_branches.is_empty() {
        let _ = writeln!(
            s,
            "\nlimit states above the boundary: none at the {} sampled mu",
            curve.samples
        );
    } else {
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
    for (mu, m) in &curve.unresolved {
        let _ = writeln!(s, "  unresolved sample at mu = {mu}: {m}");
    }
    s.push_str(LEGEND);
    s
}

/// A branch's mode and its ends [μ from, μ to, η from, η to] as table columns.
fn branch_row(mode: crate::collapse_mode::CollapseMode, ends: [f64; 4]) -> String {
    let [a, b, c, d] = ends.map(|v| fmt_opt_inf(v, 10));
    format!("  {:<30} {a:>15} {b:>15}   {c:>15} {d:>15}", mode.name())
}

/// A pattern as `kind@beta` in degrees.
fn degrees(p: &[crate::contact::Contact]) -> String {
    p.iter()
        .map(|c| format!("{}@{:.3}", short(c), c.beta.to_degrees()))
        .collect::<Vec<_>>()
        .join(" ")
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
        let bn = right_half_angle(arch, &c.joints, |c| c.kind == ContactKind::HingeIntrados);
        let bt = right_half_angle(arch, &c.joints, |c| !c.kind.is_hinge());
        let f = |v: Option<f64>| v.map_or("-".to_string(), |b| format!("{b:.10}"));
        let _ = writeln!(
            s,
            "  {:>16} {:>11} {:>16} {:>14} {:>14}  {:<52} {}",
            fmt_opt_inf(c.mu, 12),
            fmt_opt_inf(c.mu.atan().to_degrees(), 6),
            sig(c.eta, 12),
            f(bn),
            f(bt),
            format!("{} / {}", c.between[0].name(), c.between[1].name()),
            if c.exact { "yes" } else { "no (bracketed)" }
        );
        let joints: Vec<String> = c
            .joints
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
            c.mode.name(),
            fmt_slope(c.slope_left),
            fmt_slope(c.slope_right)
        );
    }
}

/// The notation of every pattern column.
pub const LEGEND: &str =
    "\nE: hinge at the extrados, I: hinge at the intrados, S+/S-: sliding along \
the (radial) joint, the part beyond it (larger beta) moving outwards/inwards, (s): at a springing; \
angles from the horizontal through the centre.\n";

/// Dimensions of a real arch, for printing results in metres and kilonewtons.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Dimensions {
    /// Mean radius r (m).
    pub radius: f64,
    /// Depth d of the arch barrel, perpendicular to its plane (m).
    pub depth: f64,
    /// Density ρ (kg/m³).
    pub density: f64,
    /// Gravitational acceleration g (m/s²).
    pub g: f64,
}

/// The human-readable answer of `assess`.
pub fn assess(arch: &Arch, a: &crate::assess::Assessment, dims: Option<Dimensions>) -> String {
    use crate::assess::LeastFriction;
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
    if let Some(d) = dims {
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
            let _ = writeln!(
                s,
                "                    least thickness t* = {} m",
                sig(ls.eta * d.radius, 6)
            );
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
    s
}

/// The header of [`corner_rows`].
pub const CORNER_HEADER: &str =
    "| α_s | μ | φ [°] | η | β_N | β_T | between |\n|---:|---:|---:|---:|---:|---:|:---|";

/// The corners of a symmetric arch's limit curve as Markdown rows in the layout of a
/// paper's results table: α_s, μ and φ = atan μ (degrees), η, the intrados hinge β_N and
/// the sliding joint β_T in the right half (radians), the two modes the corner separates.
pub fn corner_rows(arch: &Arch, curve: &crate::limit_curve::LimitCurve) -> Vec<String> {
    use crate::contact::ContactKind;
    let alpha = 0.0 - arch.beta_right();
    let mut all: Vec<&crate::limit_curve::Corner> =
        curve.corners.iter().chain(&curve.transitions).collect();
    all.sort_by(|a, b| b.mu.total_cmp(&a.mu));
    all.into_iter()
        .map(|c| {
            let f = |v: Option<f64>| v.map_or("–".to_string(), |b| format!("{b:.8}"));
            let (mu, phi) = if c.mu.is_finite() {
                (
                    format!("{:.8}", c.mu),
                    format!("{:.4}", c.mu.atan().to_degrees()),
                )
            } else {
                ("∞".to_string(), "90".to_string())
            };
            format!(
                "| {alpha:.6} | {mu} | {phi} | {:.8} | {} | {} | {} / {}{} |",
                c.eta,
                f(right_half_angle(arch, &c.joints, |j| j.kind == ContactKind::HingeIntrados)),
                f(right_half_angle(arch, &c.joints, |j| !j.kind.is_hinge())),
                c.between[0].name(),
                c.between[1].name(),
                match (c.exact, c.kink) {
                    (true, true) => "",
                    (true, false) if c.mu.is_infinite() => " (asymptote)",
                    (true, false) => " (smooth transition)",
                    (false, _) => " (bracketed only)",
                }
            )
        })
        .collect()
}
