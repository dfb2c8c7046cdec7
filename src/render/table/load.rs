//! The answer of `load` as text: the question, the admissible range of λ, the static
//! maximum, the collapse multiplier and every limit state.

use super::format::{describe_arch, fmt_mu, short, sig};
use crate::limit_states::LimitState;
use crate::load::LiveLoad;
use crate::multiplier::{LoadOutcome, LoadSurvey, LoadUnsettled};
use crate::render::live_load::{at_joint, force_unit_kn, merged, LoadQuestion};
use std::fmt::Write;

/// A pattern as `kind@beta`, `<`/`>` marking the contacts before/after the loaded section.
pub(super) fn pattern_text(load: &LiveLoad, s: &LimitState) -> String {
    merged(load, s.pattern.iter().zip(s.sides.iter().copied()))
        .iter()
        .map(|(c, side)| {
            let tag = match side {
                Some("before") => "<",
                Some("after") => ">",
                _ => "",
            };
            format!("{}@{:.4}{tag}", short(c), c.beta)
        })
        .collect::<Vec<_>>()
        .join(" ")
}

/// The human-readable answer of `load`.
pub fn load(q: &LoadQuestion, outcome: &Result<LoadOutcome, LoadUnsettled>) -> String {
    let mut s = String::new();
    let _ = writeln!(s, "{}", describe_arch(q.arch));
    let _ = writeln!(
        s,
        "thickness           eta = t/r = {}; friction mu = {}",
        sig(q.eta, 12),
        fmt_mu(q.mu)
    );
    let _ = writeln!(s, "load                {}", load_text(q));
    match outcome {
        Err(u) => unsettled(&mut s, q, u),
        Ok(LoadOutcome::NoEquilibrium) => {
            let _ = writeln!(
                s,
                "no equilibrium: no statically admissible state at any lambda >= 0"
            );
        }
        Ok(LoadOutcome::NoCollapse { lambda_min, .. }) => {
            let _ = writeln!(
                s,
                "no collapse: admissible states at every lambda >= {} and no limit state up to lambda = {:e}",
                sig(lambda_min.0, 12),
                crate::multiplier::UNBOUNDED_SEARCH_TOP
            );
        }
        Ok(LoadOutcome::Limits(sv)) => {
            multipliers(&mut s, q, sv);
            limit_states(&mut s, q, sv);
        }
    }
    s.lines().map(|l| l.trim_end().to_string() + "\n").collect()
}

/// An undecided survey: why, and what it decided all the same (the static maximum, the
/// limit states found, an upper bound on the collapse multiplier, "not unique").
fn unsettled(s: &mut String, q: &LoadQuestion, u: &LoadUnsettled) {
    if let Some(m) = u.lambda_static {
        let _ = writeln!(
            s,
            "{}",
            static_line(q, m, " (exact)", u.mechanism_at_static)
        );
    }
    let _ = writeln!(s, "unresolved: {}", u.why);
    let Some(at_most) = u.lambda_at_most() else {
        return;
    };
    let _ = writeln!(
        s,
        "found all the same (each a limit state, checked over the whole arch; others may lie below):"
    );
    for l in &u.found {
        let _ = writeln!(s, "{}", state_line(q, l));
    }
    let _ = writeln!(
        s,
        "collapse multiplier not decided: at most {}{}{}",
        sig(at_most, 12),
        physical(q, at_most),
        u.reduction_at_least().map_or(String::new(), |r| format!(
            " (reduction 1 - lambda/lambda_static at least {})",
            sig(r, 6)
        ))
    );
    if u.unique() == Some(false) {
        let _ = writeln!(s, "verdict             not unique (two limit states found)");
    }
}

/// The live load in words, with where a point load sits.
fn load_text(q: &LoadQuestion) -> String {
    match q.load {
        LiveLoad::Horizontal { towards_right } => format!(
            "horizontal body force lambda x self-weight, towards the {} springing",
            if towards_right { "right" } else { "left" }
        ),
        LiveLoad::Point { beta } => format!(
            "vertical point load lambda (units of gamma t d r) at the extrados point beta = {beta:.10} rad ({:.4} deg){}",
            beta.to_degrees(),
            match q.arch.layout() {
                crate::arch::JointLayout::Continuous => ", on the continuum (both sides of the loaded section checked)",
                _ if at_joint(q.arch, beta) => ", at a joint (both sides of its section checked)",
                _ => ", inside a voussoir",
            }
        ),
        LiveLoad::Pressure(p) => pressure_text(q, &p),
    }
}

/// A pressure on the extrados in words: its patches and points, and its load in kN (what
/// reaches the ring is the bridge lines' `carried` figure, computed by the caller).
pub(super) fn pressure_text(q: &LoadQuestion, p: &crate::pressure::Pressure) -> String {
    let kn = q.vehicle_kn.map_or(String::new(), |v| {
        format!("; at lambda = 1, {} kN in all", sig(v, 6))
    });
    format!(
        "vertical loads lambda x q on the extrados, {} spread over patches and {} at points{kn}",
        p.patches().len(),
        p.points().len(),
    )
}

/// A multiplier in physical units, when the question has dimensions: the point load in kN,
/// the horizontal acceleration in m/s² and in g.
fn physical(q: &LoadQuestion, l: f64) -> String {
    let unit = q.dims.as_ref().map(|d| (force_unit_kn(q, d), d.g));
    match (unit, q.load) {
        (Some((u, _)), LiveLoad::Point { .. }) => format!("  ({} kN)", sig(l * u, 6)),
        (Some(_), LiveLoad::Pressure(_)) => match q.vehicle_kn {
            Some(v) => format!("  ({} kN)", sig(l * v, 6)),
            None => String::new(),
        },
        (Some((_, g)), LiveLoad::Horizontal { .. }) => {
            format!("  ({} m/s^2 = {} g)", sig(l * g, 6), sig(l, 6))
        }
        _ => String::new(),
    }
}

/// The admissible range of λ, the static maximum and the collapse multiplier.
fn multipliers(s: &mut String, q: &LoadQuestion, sv: &LoadSurvey) {
    let stat = sv
        .lambda_static
        .map_or("unbounded".to_string(), |m| sig(m.0, 12));
    let _ = writeln!(
        s,
        "admissible          lambda in [{}, {}]{}",
        sig(sv.lambda_min.0, 12),
        stat,
        if sv.lambda_min.0 > 0.0 {
            "  (the arch needs the load to stand: the lower end is an unloading limit, never a collapse)"
        } else {
            ""
        }
    );
    if let Some(m) = sv.lambda_static {
        let _ = writeln!(
            s,
            "{}",
            static_line(q, m.0, "", Some(sv.mechanism_at_static))
        );
    }
    match sv.lambda() {
        Some(l) => {
            let _ =
                writeln!(
                    s,
                    "collapse multiplier lambda = {}{}{}",
                    sig(l, 12),
                    physical(q, l),
                    sv.reduction()
                        .filter(|r| *r > 0.0)
                        .map_or(String::new(), |r| format!(
                        "; {} below the static maximum (reduction 1 - lambda/lambda_static = {})",
                        if r >= 1.0 { "infinitely" } else { "non-associative friction brings it" },
                        sig(r, 6)
                    ))
                );
        }
        None => {
            let _ = writeln!(
                s,
                "collapse multiplier none: no limit state with lambda in the admissible range"
            );
        }
    }
}

/// Every limit state (how they were found, one line each) and the verdict.
fn limit_states(s: &mut String, q: &LoadQuestion, sv: &LoadSurvey) {
    let how = match sv.method {
        "sweep" => format!("{} events of the sweep", sv.events),
        "faces" => format!(
            "{} vertices of the admissible (x, lambda) with a sliding row active, each checked: the face search",
            sv.events
        ),
        "refined" => format!(
            "two discretisations swept ({} events in the finer) and refined on the continuum",
            sv.events
        ),
        _ => "mu = inf: associative, the static maximum is the only limit state".to_string(),
    };
    let _ = writeln!(
        s,
        "limit states ({how}; E/I hinge at extrados/intrados, S+/S- sliding, < > before/after the loaded section):"
    );
    for l in &sv.limit_states {
        let _ = writeln!(s, "{}", state_line(q, l));
    }
    let _ = writeln!(
        s,
        "verdict             {}",
        if sv.limit_states.is_empty() {
            "no limit state"
        } else if sv.unique() {
            "unique limit state"
        } else {
            "not unique"
        }
    );
}

/// One limit state as a line: its λ, mode and pattern, and where it is the least of a
/// continuum of limit states, up to where.
fn state_line(q: &LoadQuestion, l: &LimitState) -> String {
    let continuum = l.continuum_to.map_or(String::new(), |to| if to > l.t {
        format!(
            "  (least of a continuum of limit states up to lambda = {})",
            sig(to, 12)
        )
    } else {
        "  (a continuum of limit states at this lambda: every state of a face of the admissible set)".to_string()
    });
    format!(
        "  lambda = {}  {}  {}{continuum}",
        sig(l.t, 12),
        l.mode.name(),
        pattern_text(&q.load, l)
    )
}

/// The static maximum as a line: λ_static, in units where given, `note`, and whether its
/// state carries a mechanism with positive live power (where decided).
fn static_line(q: &LoadQuestion, lambda: f64, note: &str, mechanism: Option<bool>) -> String {
    format!(
        "static maximum      lambda_static = {}{}{note}{}",
        sig(lambda, 12),
        physical(q, lambda),
        match mechanism {
            Some(true) => "; carries a mechanism with positive live power",
            Some(false) => "; carries NO mechanism with positive live power",
            None => "",
        }
    )
}
