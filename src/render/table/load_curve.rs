//! The answer of `load-curve` as text: the λ–μ table and its corners.

use super::format::{describe_arch, fmt_mu, sig};
use super::load::pattern_text;
use crate::load::LiveLoad;
use crate::multiplier::{LoadAnswer, LoadCurve, LoadOutcome};
use crate::render::json::curve_row;
use crate::render::live_load::{LoadQuestion, CONTINUOUS_TOL};
use std::fmt::Write;

/// The least limit state of an answer in words: mode and pattern (or the status).
fn least_text(load: &LiveLoad, o: &LoadAnswer) -> String {
    match o {
        Err(u) => match u.found.first() {
            None => "unresolved".into(),
            Some(l) => format!(
                "unresolved; found lambda = {}  {}  {}  (the collapse multiplier is at most this)",
                sig(l.t, 12),
                l.mode.name(),
                pattern_text(load, l)
            ),
        },
        Ok(LoadOutcome::NoEquilibrium) => "no equilibrium".into(),
        Ok(LoadOutcome::NoCollapse { .. }) => "no collapse".into(),
        Ok(LoadOutcome::Limits(sv)) => match sv.limit_states.first() {
            None => "no limit state".into(),
            Some(l) => format!(
                "lambda = {}  {}  {}{}",
                sig(l.t, 12),
                l.mode.name(),
                pattern_text(load, l),
                if sv.reduction().is_some_and(|r| r > 0.0) {
                    "  (below lambda_static)"
                } else {
                    ""
                }
            ),
        },
    }
}

/// The human-readable λ–μ table.
pub fn load_curve(q: &LoadQuestion, curve: &LoadCurve) -> String {
    let mut s = String::new();
    let _ = writeln!(s, "{}", describe_arch(q.arch));
    let _ = writeln!(s, "thickness           eta = t/r = {}", sig(q.eta, 12));
    let _ = writeln!(
        s,
        "load                {}",
        match q.load {
            LiveLoad::Horizontal { towards_right } => format!(
                "horizontal body force lambda x self-weight, towards the {} springing",
                if towards_right { "right" } else { "left" }
            ),
            LiveLoad::Point { beta } => format!(
                "vertical point load at the extrados point beta = {beta:.10} rad ({:.4} deg)",
                beta.to_degrees()
            ),
            LiveLoad::Pressure(p) => super::load::pressure_text(q, &p),
        }
    );
    let _ = writeln!(
        s,
        "{:>16}  {:>16}  {:>16}  {:>11}  {:>6}  mode of the least limit state",
        "mu", "lambda_static", "lambda", "reduction", "states"
    );
    for (mu, o) in &curve.samples {
        sample_row(&mut s, *mu, o);
    }
    corners(&mut s, q, curve);
    s.lines().map(|l| l.trim_end().to_string() + "\n").collect()
}

/// One row of the table: λ_static, λ, the reduction, the number of limit states and the
/// least one's mode, or the status.
fn sample_row(s: &mut String, mu: f64, o: &LoadAnswer) {
    let r = curve_row(mu, o);
    let num = |v: Option<f64>| v.map_or("-".to_string(), |v| sig(v, 12));
    if r.status == "ok" {
        let _ = writeln!(
            s,
            "{:>16}  {:>16}  {:>16}  {:>11}  {:>6}  {}",
            fmt_mu(mu),
            num(r.lambda_static),
            num(r.lambda),
            r.reduction.map_or("-".to_string(), |v| sig(v, 4)),
            r.limit_states,
            r.mode.unwrap_or("-")
        );
    } else {
        let bound = match (r.lambda_at_most, r.reduction_at_least) {
            (Some(l), Some(red)) => format!(
                " (lambda <= {}, at least {} below lambda_static)",
                sig(l, 12),
                sig(red, 4)
            ),
            (Some(l), None) => format!(" (lambda <= {})", sig(l, 12)),
            _ => String::new(),
        };
        let _ = writeln!(
            s,
            "{:>16}  {}{bound}{}",
            fmt_mu(mu),
            r.status,
            r.message.map_or(String::new(), |m| format!(": {m}"))
        );
    }
}

/// The corners: where each is (exact, or the bisection's bracket), how λ changes there,
/// and the least limit state on either side.
fn corners(s: &mut String, q: &LoadQuestion, curve: &LoadCurve) {
    if curve.corners.is_empty() {
        let _ = writeln!(s, "corners             none between the samples");
    } else {
        let _ = writeln!(
            s,
            "corners             where the least limit state changes (exact: five contacts active at one state, or four sliding ones where the least states are faces along w, Newton in h, v, w, lambda, mu; else the bisection's neighbouring floats in mu):"
        );
    }
    for c in &curve.corners {
        let (below, above) = c.lambdas();
        let change = match (below, above) {
            _ if !c.exact && c.detail.changes > 1 => format!(
                "the answer changes {} times in this stretch (no single corner: near a singularity the survey's answer flickers)",
                c.detail.changes
            ),
            (Some(_), Some(_)) if c.continuous(CONTINUOUS_TOL) => "continuous".into(),
            (Some(a), Some(b)) => format!("lambda jumps {} -> {}", sig(a, 12), sig(b, 12)),
            _ => "a change of status".into(),
        };
        let (below, above) = (c.below(), c.above());
        let at = match c.exact {
            true => format!("mu = {}  lambda = {} (exact)", c.mu, sig(c.t, 15)),
            false => format!(
                "mu in [{}, {}]{}",
                below.0,
                if above.0.is_finite() {
                    above.0.to_string()
                } else {
                    "inf".into()
                },
                if c.detail.bracketed || c.detail.changes > 1 {
                    ""
                } else {
                    " (not bisected to the end)"
                }
            ),
        };
        let _ = writeln!(s, "  {at}  {change}");
        let _ = writeln!(s, "      below: {}", least_text(&q.load, &below.1));
        let _ = writeln!(s, "      above: {}", least_text(&q.load, &above.1));
    }
}
