//! A limit state of a continuous arch on its pattern: Newton from where it was (a discrete
//! limit state carried over, or one found at another friction), then the checks (admissible
//! over the whole arch, a mechanism on its active contacts), or why the pattern carries no
//! limit state there.

use super::sweep::LimitState;
use crate::arch::Arch;
use crate::contact::{Contact, ContactKind};
use crate::mechanism;
use crate::refine::{solve_system, Unknowns};
use crate::settings::Settings;
use crate::state::State;
use crate::statics::Reactions;

/// Newton on the continuous pattern from a discrete limit state, then the checks: the state
/// admissible over the whole arch, a mechanism on its active contacts.
pub(crate) fn refine(
    arch: &Arch,
    mu: f64,
    eta: f64,
    x: Reactions,
    pattern: &[Contact],
    settings: &Settings,
) -> Option<LimitState> {
    refined(arch, mu, (eta, x), pattern, settings).ok()
}

/// [`refine`], or why the pattern carries no limit state at `mu`.
pub(crate) fn refined(
    arch: &Arch,
    mu: f64,
    (eta, x): (f64, Reactions),
    pattern: &[Contact],
    settings: &Settings,
) -> Result<LimitState, String> {
    if pattern.len() < 4 {
        return Err(format!("{} contacts fix no state", pattern.len()));
    }
    let start = State { arch, eta, mu, x };
    let r = solve_system(&start, pattern, Unknowns::T, settings)
        .map_err(|e| format!("Newton on the pattern finds no state ({e:?})"))?;
    checked(arch, mu, (r.t, r.x), None, settings)
}

/// The state (η, x) at `mu` checked as a limit state: admissible over the whole arch, and a
/// mechanism on `contacts` (its active contacts where `None`); or why not.
pub(crate) fn checked(
    arch: &Arch,
    mu: f64,
    (eta, x): (f64, Reactions),
    contacts: Option<Vec<Contact>>,
    settings: &Settings,
) -> Result<LimitState, String> {
    let st = State { arch, eta, mu, x };
    let v = st.verdict(ContactKind::active_at(mu), settings);
    if v.worst > settings.adm_tol {
        return Err(format!(
            "the pattern's state (eta = {eta}) is not admissible: violated by {:.2e} (relative)",
            v.worst
        ));
    }
    let contacts = contacts.unwrap_or(v.active);
    let mech = match mechanism::find(&st, &contacts, settings) {
        Ok(Some(m)) => m,
        Ok(None) => {
            return Err(format!(
                "the pattern's state (eta = {eta}) carries no mechanism without dilatancy"
            ))
        }
        Err(e) => return Err(format!("the mechanism LP failed ({e:?})")),
    };
    Ok(LimitState::unloaded(
        arch,
        (eta, x),
        contacts,
        mech,
        settings,
    ))
}

/// The limit state `s` of a continuous arch (found at another friction) followed to `mu`:
/// Newton on its pattern from where it was, the state admissible over the whole arch and a
/// mechanism on its active contacts; or why that pattern carries no limit state at `mu`.
/// A state with more than four active contacts (one just reaching its limit, where a
/// branch ends) is followed on the contacts its mechanism moves, where they are four.
pub fn follow(
    arch: &Arch,
    mu: f64,
    s: &LimitState,
    settings: &Settings,
) -> Result<LimitState, String> {
    refined(arch, mu, (s.t, s.x), &moving(s, settings), settings)
}

/// The contacts of `s` to follow it on: its pattern, or where that has more than four, the
/// four its mechanism moves (rates above `rate_tol` times the largest), if they are four.
fn moving(s: &LimitState, settings: &Settings) -> Vec<Contact> {
    if s.pattern.len() <= 4 {
        return s.pattern.clone();
    }
    let m = &s.mechanism;
    let big = m.rates.iter().fold(0.0f64, |a, r| a.max(r.abs()));
    let moved: Vec<Contact> = m
        .contacts
        .iter()
        .zip(&m.rates)
        .filter(|(_, r)| r.abs() > settings.rate_tol * big)
        .map(|(c, _)| *c)
        .collect();
    if moved.len() == 4 {
        moved
    } else {
        s.pattern.clone()
    }
}

/// Why the limit state `s` of a continuous arch (found at another friction) is not one at
/// `mu`, followed as [`follow`] does (its pattern, or the four contacts its mechanism
/// moves), Newton from where it was: `None` where it still is one there.
/// With its smallest mechanism rate, which tends to zero where a branch ends because its
/// mechanism is lost.
pub fn lost_at(arch: &Arch, mu: f64, s: &LimitState, settings: &Settings) -> Option<String> {
    let why = follow(arch, mu, s, settings).err()?;
    let least = s
        .mechanism
        .contacts
        .iter()
        .zip(&s.mechanism.rates)
        .min_by(|a, b| a.1.total_cmp(b.1));
    Some(match least {
        Some((c, r)) => format!(
            "{why}; its smallest rate before was {r:.2e} ({} at beta = {:.6})",
            c.kind.name(),
            c.beta
        ),
        None => why,
    })
}
