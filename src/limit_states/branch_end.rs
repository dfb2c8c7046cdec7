//! Where a branch of limit states ends in μ, solved from the condition that ends it.
//!
//! A limit state of a continuous arch lies on a branch: Newton on its pattern follows it
//! in μ ([`super::follow`]). The branch ends where the pattern's state stops being a limit
//! state, in one of two ways, each one equation more than the pattern's own:
//!
//! * **admissibility lost**: another contact c reaches its limit (φ_c = 0). The pattern
//!   and c together fix both η and μ: Newton with both unknown ([`Unknowns::TMu`]), as a
//!   corner of the η\*(μ) curve is located.
//! * **mechanism lost**: the rate of one contact c of the mechanism falls to 0. With four
//!   contacts the mechanism is the null vector of the 3 × 4 compatibility matrix B, whose
//!   entries are its cofactors; the end is a root in μ of c's cofactor (normalised by the
//!   others), each value taken at the pattern's state there (Newton), found by the secant
//!   method to the rounding level.
//!
//! Either way the end is a point solved from its defining condition, not the place where a
//! tolerance is crossed.

use super::follow::{checked, follow, refined};
use super::sweep::LimitState;
use crate::arch::Arch;
use crate::contact::{Contact, ContactKind, Location};
use crate::kinematics::column;
use crate::refine::{solve_system, Refined, Unknowns};
use crate::settings::Settings;
use crate::state::State;
use crate::statics::Reactions;
use nalgebra::Matrix3;
use std::f64::consts::FRAC_PI_2;

/// What ends a branch.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum EndCondition {
    /// This contact reaches its limit: beyond, the pattern's state violates it.
    Admissibility(Contact),
    /// This contact's mechanism rate falls to 0: beyond, the pattern carries no mechanism.
    Mechanism(Contact),
}

impl EndCondition {
    /// A sentence: what happens at the end.
    pub fn describe(&self) -> String {
        match self {
            EndCondition::Admissibility(c) => format!(
                "{} at beta = {:.10} reaches its limit",
                c.kind.name(),
                c.beta
            ),
            EndCondition::Mechanism(c) => format!(
                "the rate of {} at beta = {:.10} falls to 0",
                c.kind.name(),
                c.beta
            ),
        }
    }
}

/// The end of a branch of limit states, solved from its defining condition.
#[derive(Debug, Clone)]
pub struct BranchEnd {
    /// μ at the end.
    pub mu: f64,
    /// The branch's last limit state, at `mu` (its pattern holds the contact that ends the
    /// branch where admissibility is lost).
    pub state: LimitState,
    /// What ends the branch there.
    pub condition: EndCondition,
    /// The defining condition's residual at the end: Newton's scaled residual (admissibility)
    /// or the normalised rate left (mechanism).
    pub residual: f64,
}

/// Secant steps on the mechanism-lost condition at most.
const SECANT_STEPS: usize = 60;

/// Where the branch of `s` (a limit state at friction `mu_in`) ends on the way to `mu_out`
/// (where, followed on its pattern, it is no limit state), solved from the condition that
/// ends it. `Err` says why not: Newton on the pattern finds no state at `mu_out` (the branch
/// turns back, a fold), or neither condition is met there, or the solve does not converge.
pub fn branch_end(
    arch: &Arch,
    s: &LimitState,
    (mu_in, mu_out): (f64, f64),
    settings: &Settings,
) -> Result<BranchEnd, String> {
    let inside = follow(arch, mu_in, s, settings)?;
    let (inside, mu_in) = four_contacts(arch, inside, (mu_in, mu_out), settings);
    let out = pattern_state(arch, &inside, mu_out, settings)
        .ok_or("Newton on the pattern finds no state beyond the end (the branch may turn back)")?;
    let st = State {
        arch,
        eta: out.t,
        mu: mu_out,
        x: out.x,
    };
    if st.verdict(ContactKind::active_at(mu_out), settings).worst > settings.adm_tol {
        admissibility_end(arch, &inside, &st, settings)
    } else if inside.pattern.len() == 4 {
        mechanism_end(arch, &inside, (mu_in, mu_out), settings)
    } else {
        Err(format!(
            "the pattern has {} contacts (a rate condition is solved for four)",
            inside.pattern.len()
        ))
    }
}

/// Steps back from the end to where the branch's state has the four contacts of its own
/// pattern: a state at (or within rounding of) the end where admissibility is lost has the
/// fifth contact active too, and which one that is shows only where it is not. The
/// sub-pattern of four that is a limit state a little inside (up to 1e-7 relative) is the
/// branch's; the state is left as it is where none is (or it has four contacts already).
fn four_contacts(
    arch: &Arch,
    inside: LimitState,
    (mu_in, mu_out): (f64, f64),
    settings: &Settings,
) -> (LimitState, f64) {
    if inside.pattern.len() != 5 {
        return (inside, mu_in);
    }
    for step in [1e-10, 1e-9, 1e-8, 1e-7] {
        let m = mu_in - (mu_out - mu_in).signum() * step * mu_in.abs();
        for k in 0..5 {
            let mut sub = inside.pattern.clone();
            sub.remove(k);
            if let Ok(r) = refined(arch, m, (inside.t, inside.x), &sub, settings) {
                if r.pattern.len() == 4 {
                    return (r, m);
                }
            }
        }
    }
    (inside, mu_in)
}

/// The pattern's state at `mu`, Newton from `s` (η unknown, free angles refined), whether a
/// limit state or not.
fn pattern_state(arch: &Arch, s: &LimitState, mu: f64, settings: &Settings) -> Option<Refined> {
    let start = State {
        arch,
        eta: s.t,
        mu,
        x: s.x,
    };
    solve_system(&start, &s.pattern, Unknowns::T, settings).ok()
}

/// The end where a contact outside the pattern reaches its limit: every contact the state
/// `out` beyond the end violates (or nearly) is tried with the pattern, both η and μ
/// unknown; the end is the admissible limit state so found nearest `inside`.
fn admissibility_end(
    arch: &Arch,
    inside: &LimitState,
    out: &State,
    settings: &Settings,
) -> Result<BranchEnd, String> {
    let in_pattern = |c: &Contact| {
        inside
            .pattern
            .iter()
            .any(|p| p.kind == c.kind && (p.beta - c.beta).abs() <= settings.same_state_angle)
    };
    let mag = |k: ContactKind| {
        crate::statics::magnitude(k, out.eta, out.mu, &out.x, settings.magnitude_floor)
    };
    let mut violated: Vec<(f64, Contact)> = out
        .peaks(settings)
        .into_iter()
        .filter(|p| ContactKind::active_at(out.mu).contains(&p.contact.kind))
        .map(|p| (p.value / mag(p.contact.kind), p.contact))
        .filter(|(v, _)| *v > settings.adm_tol)
        .collect();
    violated.sort_by(|a, b| b.0.total_cmp(&a.0));
    let mut why = Vec::new();
    for &(_, c) in &violated {
        // a contact of a pattern of five (one more than a limit state needs) is active
        // only where the branch ends: the pattern as it is fixes the end
        let pattern: Vec<Contact> = match (in_pattern(&c), inside.pattern.len()) {
            (true, 5) => inside.pattern.clone(),
            (false, 4) => [inside.pattern.clone(), vec![c]].concat(),
            (_, n) => {
                why.push(format!("{} with a pattern of {n}", c.kind.name()));
                continue;
            }
        };
        match five_contacts(arch, (out.eta, out.mu, out.x), &pattern, c, settings) {
            Ok(end) => return Ok(end),
            Err(e) => why.push(format!("with {}: {e}", c.kind.name())),
        }
    }
    Err(format!(
        "no contact the state beyond the end violates closes the branch ({})",
        why.join("; ")
    ))
}

/// The end where the five contacts of `pattern` are active at once (one of them `c`, the
/// one that ends the branch): Newton with η and μ unknown from (η, μ, x), the state there
/// admissible and carrying a mechanism.
fn five_contacts(
    arch: &Arch,
    (eta, mu, x): (f64, f64, Reactions),
    pattern: &[Contact],
    c: Contact,
    settings: &Settings,
) -> Result<BranchEnd, String> {
    let start = State { arch, eta, mu, x };
    let r = solve_system(&start, pattern, Unknowns::TMu, settings)
        .map_err(|e| format!("Newton on the five contacts: {e:?}"))?;
    let state = checked(arch, r.mu, (r.t, r.x), Some(r.contacts.clone()), settings)?;
    Ok(BranchEnd {
        mu: r.mu,
        condition: EndCondition::Admissibility(nearest(&r.contacts, &c)),
        state,
        residual: r.residual,
    })
}

/// The mechanism's four contacts (the pattern's contacts with a positive rate), and the
/// null vector of their compatibility matrix at thickness `eta` (cofactors, signed so that
/// it is `reference`'s direction), normalised to Σ|v| = 1.
fn null_rates(contacts: &[Contact], eta: f64, reference: &[f64]) -> Option<[f64; 4]> {
    let cols: Vec<[f64; 3]> = contacts
        .iter()
        .map(|c| column(c.kind, c.beta, eta))
        .collect();
    let mut v = [0.0; 4];
    for (i, vi) in v.iter_mut().enumerate() {
        let rest: Vec<&[f64; 3]> = (0..4).filter(|&j| j != i).map(|j| &cols[j]).collect();
        let m = Matrix3::from_fn(|r, k| rest[k][r]);
        *vi = if i % 2 == 0 { 1.0 } else { -1.0 } * m.determinant();
    }
    let dot: f64 = v.iter().zip(reference).map(|(a, b)| a * b).sum();
    let norm: f64 = v.iter().map(|a| a.abs()).sum();
    if norm == 0.0 || dot == 0.0 {
        return None;
    }
    let sign = dot.signum() / norm;
    Some(v.map(|a| a * sign))
}

/// The end where a rate of the mechanism falls to 0: the contact whose cofactor changes
/// sign between `mu_in` and `mu_out`, and the root of that cofactor in μ ([`rate_root`]).
fn mechanism_end(
    arch: &Arch,
    inside: &LimitState,
    (mu_in, mu_out): (f64, f64),
    settings: &Settings,
) -> Result<BranchEnd, String> {
    let support = support_of(inside)?;
    let (_, v_out) = rates_at(arch, inside, &support, mu_out, settings)
        .ok_or("Newton on the pattern fails beyond the end")?;
    let Some(c) = (0..4).min_by(|&a, &b| v_out[a].total_cmp(&v_out[b])) else {
        return Err("no rate".into());
    };
    if v_out[c] > 0.0 {
        return Err("every rate stays positive beyond the end".into());
    }
    // from a point well inside the branch and the point beyond its end
    let span = (mu_out - mu_in).abs().max(1e-7 * mu_in.abs());
    let a = mu_in - span * (mu_out - mu_in).signum();
    rate_root(arch, inside, (&support, c), (a, mu_out), settings)
}

/// The mechanism's four contacts with their rates.
fn support_of(s: &LimitState) -> Result<Vec<(Contact, f64)>, String> {
    let m = &s.mechanism;
    if m.contacts.len() != 4 {
        return Err(format!(
            "the mechanism is on {} contacts (a rate condition is solved for four)",
            m.contacts.len()
        ));
    }
    Ok(m.contacts.iter().copied().zip(m.rates.clone()).collect())
}

/// The pattern's state at `mu` (Newton from `s`, free angles refined there) and the
/// null vector of the support's compatibility matrix there ([`null_rates`]).
fn rates_at(
    arch: &Arch,
    s: &LimitState,
    support: &[(Contact, f64)],
    mu: f64,
    settings: &Settings,
) -> Option<(LimitState, [f64; 4])> {
    let r = pattern_state(arch, s, mu, settings)?;
    let cs: Vec<Contact> = support
        .iter()
        .map(|(c, _)| nearest(&r.contacts, c))
        .collect();
    let reference: Vec<f64> = support.iter().map(|p| p.1).collect();
    let v = null_rates(&cs, r.t, &reference)?;
    let mut moved = s.clone();
    (moved.t, moved.x, moved.pattern) = (r.t, r.x, r.contacts);
    Some((moved, v))
}

/// The root in μ of the cofactor of `support[c]` along the pattern of `s`, by the secant
/// method from `a` and `b` to the rounding level; the state there checked (admissible, the
/// other rates positive, a mechanism).
fn rate_root(
    arch: &Arch,
    s: &LimitState,
    (support, c): (&[(Contact, f64)], usize),
    (a, b): (f64, f64),
    settings: &Settings,
) -> Result<BranchEnd, String> {
    let at = |s: &LimitState, mu: f64| rates_at(arch, s, support, mu, settings);
    let (_, va) = at(s, a).ok_or("Newton on the pattern fails inside")?;
    let (sb, vb) = at(s, b).ok_or("Newton on the pattern fails beyond")?;
    let (mut a, mut ga) = (a, va[c]);
    let (mut b, mut sb, mut vb) = (b, sb, vb);
    for _ in 0..SECANT_STEPS {
        if vb[c] == ga {
            break;
        }
        let next = b - vb[c] * (b - a) / (vb[c] - ga);
        let (sn, vn) = at(&sb, next).ok_or("Newton on the pattern fails on the way")?;
        (a, ga) = (b, vb[c]);
        (b, sb, vb) = (next, sn, vn);
        if (b - a).abs() <= 4.0 * f64::EPSILON * b.abs() || vb[c] == 0.0 {
            break;
        }
    }
    let gb = vb[c];
    if gb.abs() > settings.rate_tol {
        return Err(format!(
            "the secant on the rate did not converge (rate {gb:.1e} left)"
        ));
    }
    if (0..4).any(|i| i != c && vb[i] <= settings.rate_tol) {
        return Err(format!(
            "another rate is not positive where this one falls to 0 ({vb:?})"
        ));
    }
    let state = checked(arch, b, (sb.t, sb.x), Some(sb.pattern.clone()), settings)?;
    Ok(BranchEnd {
        mu: b,
        state,
        condition: EndCondition::Mechanism(nearest(&sb.pattern, &support[c].0)),
        residual: gb.abs(),
    })
}

/// The same end on another arch (a nearby opening): its defining condition solved again from
/// this end, the contacts at the springings moved to the new arch's (continuation in α).
pub fn end_on(arch: &Arch, end: &BranchEnd, settings: &Settings) -> Result<BranchEnd, String> {
    let moved = |c: &Contact| match c.at {
        Location::Springing if c.beta < FRAC_PI_2 => Contact {
            beta: arch.beta_right(),
            ..*c
        },
        Location::Springing => Contact {
            beta: arch.beta_left(),
            ..*c
        },
        Location::Interior => *c,
    };
    let mut s = end.state.clone();
    s.pattern = s.pattern.iter().map(moved).collect();
    s.mechanism.contacts = s.mechanism.contacts.iter().map(moved).collect();
    match end.condition {
        EndCondition::Admissibility(c) => {
            five_contacts(arch, (s.t, end.mu, s.x), &s.pattern, moved(&c), settings)
        }
        EndCondition::Mechanism(c) => {
            let support = support_of(&s)?;
            let c = moved(&c);
            let k = (0..4)
                .filter(|&i| support[i].0.kind == c.kind)
                .min_by(|&i, &j| {
                    (support[i].0.beta - c.beta)
                        .abs()
                        .total_cmp(&(support[j].0.beta - c.beta).abs())
                })
                .ok_or("the vanishing contact is not in the mechanism")?;
            let mu = end.mu;
            rate_root(arch, &s, (&support, k), (mu * (1.0 - 1e-7), mu), settings)
        }
    }
}

/// The contact of `among` of `c`'s kind nearest to it in β (`c` itself if none).
fn nearest(among: &[Contact], c: &Contact) -> Contact {
    among
        .iter()
        .filter(|p| p.kind == c.kind)
        .min_by(|p, q| (p.beta - c.beta).abs().total_cmp(&(q.beta - c.beta).abs()))
        .copied()
        .unwrap_or(*c)
}
