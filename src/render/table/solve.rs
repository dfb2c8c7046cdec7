//! The answer of `solve` as text: η_s, the limit state at η_s in detail, every limit state
//! above it, and with `--explain` the patterns tried.

use super::format::{describe_arch, eta_digits, fmt_mu, pattern_table, short, sig};
use crate::limit::{LeastLimitState, Outcome, Solution};
use crate::limit_states::{LimitStates, Rays, Survey};
use crate::undecided::Undecided;
use std::fmt::Write;

/// The human-readable answer of `solve`: η_s, the limit state at η_s in detail when there
/// is one, and every limit state found above η_s.
pub fn solve(survey: &Survey, explain: bool, rays: &Rays) -> String {
    let sol = &survey.solution;
    let mut s = String::new();
    let _ = writeln!(s, "{}", describe_arch(&sol.arch));
    let _ = writeln!(
        s,
        "friction            mu = {}  (friction angle {:.6} deg)",
        fmt_mu(sol.mu),
        sol.mu.atan().to_degrees()
    );
    if let Some(scan) = &sol.scan {
        thickness_scan(&mut s, scan);
    }
    least_thickness(&mut s, survey, rays);
    s.push_str(&limit_states(survey));
    if explain {
        patterns_tried(&mut s, sol);
    }
    s
}

/// The scan of the thickness range of an arch with fill: where η_s was bracketed, and
/// whether the admissible thicknesses scanned form an interval.
fn thickness_scan(s: &mut String, scan: &crate::limit::filled::ThicknessScan) {
    let n = scan.etas.len();
    let _ = write!(
        s,
        "thickness scan      with fill the margin need not grow with eta: {n} thicknesses scanned from eta = {} to {}",
        sig(scan.etas[0], 3),
        sig(scan.etas[n - 1], 3)
    );
    let gaps = scan.gaps();
    match scan.lowest() {
        None => {
            let _ = writeln!(s, ", none admissible");
        }
        Some(i) if gaps.is_empty() => {
            let _ = writeln!(
                s,
                ";\n                    admissible from eta = {} up, at every one: an interval (to the scan's spacing)",
                sig(scan.etas[i], 6)
            );
        }
        Some(i) => {
            let list: Vec<String> = gaps.iter().map(|g| sig(*g, 6)).collect();
            let _ = writeln!(
                s,
                ";\n                    admissible from eta = {} but NOT an interval: inadmissible again at eta = {}",
                sig(scan.etas[i], 6),
                list.join(", ")
            );
        }
    }
}

/// η_s and the limit state there, or why there is none.
fn least_thickness(s: &mut String, survey: &Survey, rays: &Rays) {
    let sol = &survey.solution;
    match (&sol.outcome, &survey.states) {
        (Outcome::Limit(ls), states) => least_limit_state(s, sol, ls, states, rays),
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
}

/// η_s found with a limit state: its digits, and the state in detail unless η_s is an
/// infimum or the least admissible state carries no mechanism.
fn least_limit_state(
    s: &mut String,
    sol: &Solution,
    ls: &LeastLimitState,
    states: &Result<LimitStates, Undecided>,
    rays: &Rays,
) {
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
    if !ls.attained || states.as_ref().is_ok_and(|st| !st.attained) {
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
        s.push_str(&limit_detail(sol, ls, rays));
    }
}

/// With `--explain`: every pattern tried, in the order verified, and its verdict.
fn patterns_tried(s: &mut String, sol: &Solution) {
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

/// The extreme rays of a mechanism cone of dimension > 1, one line each: the rates on the
/// rows of the table above, in its order (each ray sums to 1).
fn extreme_rays(s: &mut String, rays: &Rays) {
    let rays = rays.least.as_deref().unwrap_or_default();
    let _ = writeln!(
        s,
        "  extreme rays of the cone ({}; `plot arch --mechanism K` draws ray K), rates on the rows above:",
        rays.len()
    );
    for (k, r) in rays.iter().enumerate() {
        let rates: Vec<String> = r.iter().map(|v| format!("{v:.6}")).collect();
        let _ = writeln!(s, "  {:>3}  {}", k + 1, rates.join("  "));
    }
}

/// The limit state at η_s in detail: pattern, reactions, mechanism, checks.
fn limit_detail(sol: &Solution, ls: &LeastLimitState, rays: &Rays) -> String {
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
    if m.dof > 1 {
        extreme_rays(&mut s, rays);
    }
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
    if sol.vertical.is_some() {
        let _ = writeln!(
            s,
            "        at mu_ms: eta_s is the least eta among the patterns of the friction limit's sliding contacts and of the branch above (no LP bracket)"
        );
    } else {
        let _ = writeln!(
            s,
            "        LP bracket of eta_s: [{}, {}]",
            sig(ls.bracket.0, 12),
            sig(ls.bracket.1, 12)
        );
    }
    s
}

/// Every limit state with η in [η_s, 2) and the verdict, or why the search stopped.
fn limit_states(survey: &Survey) -> String {
    let mut s = String::new();
    let states = match &survey.states {
        Ok(st) => st,
        Err(reason) => {
            if !matches!(survey.solution.outcome, Outcome::Limit(_)) {
                return s;
            }
            let found: Vec<String> = survey.found.iter().map(|f| sig(f.t, 12)).collect();
            let _ = match survey.unique() {
                Some(_) => writeln!(
                    s,
                    "limit states above eta_s: not searched to the end ({reason}); not unique all the same: limit states found above eta_s at eta = {} (each verified on the continuum; others may exist)",
                    found.join(", ")
                ),
                None => writeln!(
                    s,
                    "limit states above eta_s: not searched to the end ({reason}); uniqueness undecided"
                ),
            };
            return s;
        }
    };
    let count = usize::from(states.mechanism_at_eta_s) + states.above.len();
    if states.vertical.is_some() {
        let _ = writeln!(
            s,
            "limit states with eta in [eta_s, 2) (the vertical branch at mu = mu_ms):"
        );
    } else {
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
    }
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
            sig(a.t, 12),
            a.mode.name(),
            a.pattern
                .iter()
                .map(|c| format!("{}@{:.4}", short(c), c.beta))
                .collect::<Vec<_>>()
                .join(" ")
        );
    }
    if let Some(sliding) = &states.vertical {
        let _ = writeln!(
            s,
            "  every eta >= eta_s  purely_sliding  {}  (mu = mu_ms: every admissible state is a limit state)",
            sliding
                .iter()
                .map(|c| format!("{}@{:.4}", short(c), c.beta))
                .collect::<Vec<_>>()
                .join(" ")
        );
        let _ = writeln!(
            s,
            "verdict             not unique: the vertical branch (a purely sliding limit state at every eta >= eta_s)"
        );
        return s;
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
