//! The vertical branch μ = μ_ms (formulation §5): a μ at μ_ms, or within
//! `settings.mu_ms_resolution` above it, where the margin LP no longer resolves
//! admissibility (at μ_ms the friction conditions pin (h, v) to one point, and the static
//! feasible set has no interior at any η).
//!
//! Such a μ is answered from the friction-only limit (μ_ms, its sliding pattern, exact)
//! and the least limit state at μ₁, a friction clearly above the band (the lowest mixed
//! branch there): the patterns made of their contacts are refined by Newton *at the given
//! μ* and verified as any other (admissible over the whole arch, a mechanism on the
//! active set). At μ = μ_ms the least of them is the corner (μ_ms, η_ms): the end of that
//! branch, where the sliding contacts of μ_ms become active too. Below μ_ms by more than
//! the rounding of μ_ms itself no thickness stands.

use super::diagnosis::{below_mu_ms, unresolved};
use super::enumerate::enumerate;
use super::solution::{Candidate, Outcome};
use crate::admissibility::WorkingSet;
use crate::arch::{fmt_value, Arch, InputError};
use crate::contact::Contact;
use crate::friction::{friction_limit, least_friction, FrictionLimit, SLIDES};
use crate::search::margin_at;
use crate::settings::Settings;

/// A μ this close to μ_ms (relative) is μ_ms: the refined μ_ms is exact to a few
/// rounding errors, and a μ printed from it to 16 digits may differ from it in the last.
pub const MU_MS_ROUNDING: f64 = 1e-14;

/// A friction limit below this is zero to rounding: the friction-only bracket ends in
/// rounding (about 1e-35) where a state with no shear force at any joint exists; such an
/// arch has no vertical branch (it stands without friction, μ_ms = 0).
pub const MU_MS_ZERO: f64 = 1e-12;

/// The least limit state that starts the band's patterns is solved at
/// μ₁ = μ_ms (1 + this × `mu_ms_resolution`), where the LP resolves admissibility.
const ABOVE_BAND: f64 = 10.0;

/// Where μ stands with respect to the vertical branch.
pub(super) enum Band {
    /// Clearly above μ_ms: the ordinary solve.
    Above,
    /// Below μ_ms, at μ_ms, or in the band above it, with the friction limit.
    Near(FrictionLimit),
}

/// Whether μ is near μ_ms. One friction-only margin LP at μ / (1 + resolution) decides
/// most arches (admissible there: clearly above); otherwise μ_ms itself. An LP that cannot
/// decide leaves the ordinary solve to say so.
pub(super) fn band(arch: &Arch, mu: f64, settings: &Settings) -> Band {
    if !mu.is_finite() {
        return Band::Above;
    }
    let below = mu / (1.0 + settings.mu_ms_resolution);
    let mut ws = WorkingSet::initial(arch);
    match margin_at(arch, 1.0, below, &SLIDES, &mut ws, settings) {
        Ok(m) if m.margin >= 0.0 => return Band::Above,
        Ok(_) => {}
        Err(_) => return Band::Above,
    }
    // a friction limit approached only as the reactions grow without bound (a weightless
    // line of thrust along the chord of a sideways arch: μ_ms = tan(Δ/2)) pins no state:
    // it has no vertical branch to answer from
    let pinned = |fl: &FrictionLimit| {
        let cap = settings.unbounded_reactions * (1.0 + arch.span());
        fl.attained && fl.x[0].abs() <= cap && fl.x[1].abs() <= cap
    };
    match friction_limit(arch, settings) {
        Ok(Some(fl))
            if fl.mu >= MU_MS_ZERO
                && mu < fl.mu * (1.0 + settings.mu_ms_resolution)
                && pinned(&fl) =>
        {
            Band::Near(fl)
        }
        _ => Band::Above,
    }
}

/// At μ_ms itself (to its rounding) with a limit state: the sliding contacts of the
/// vertical branch ([`crate::limit::Solution::vertical`]).
pub(super) fn vertical_branch(
    mu: f64,
    fl: &FrictionLimit,
    outcome: &Outcome,
) -> Option<Vec<Contact>> {
    let at_ms = mu <= fl.mu * (1.0 + MU_MS_ROUNDING);
    (at_ms && matches!(outcome, Outcome::Limit(_))).then(|| fl.pattern.clone())
}

/// The outcome at a μ near μ_ms ([`band`]): no equilibrium below μ_ms; at it and in the
/// band above it, the least verified limit state among the patterns of μ_ms's sliding
/// contacts and the least limit state at μ₁ (see the module), `solve_above` being the
/// ordinary solve there. Every pattern tried goes to `log`.
pub(super) fn near_mu_ms(
    arch: &Arch,
    mu: f64,
    fl: &FrictionLimit,
    settings: &Settings,
    log: &mut Vec<Candidate>,
    solve_above: impl Fn(f64) -> Outcome,
) -> Outcome {
    if mu < fl.mu * (1.0 - MU_MS_ROUNDING) {
        return below_mu_ms(mu, fl.mu);
    }
    let at = format!(
        "mu = {} is at or within {} (relative) above mu_ms = {:.10}",
        fmt_value(mu),
        settings.mu_ms_resolution,
        fl.mu
    );
    if !fl.exact {
        return unresolved(
            0.0,
            2.0,
            format!("{at}, whose sliding pattern was not refined exactly"),
        );
    }
    let mu1 = fl.mu * (1.0 + ABOVE_BAND * settings.mu_ms_resolution);
    let above = solve_above(mu1);
    let l1 = match above {
        Outcome::Limit(l) => l,
        Outcome::NoEquilibrium { .. } => {
            return Outcome::NoEquilibrium {
                mu_ms: None,
                reason: format!(
                    "{at}, and no thickness eta < 2 admits equilibrium at mu = {} above it",
                    fmt_value(mu1)
                ),
            }
        }
        Outcome::Unresolved { reason, .. } | Outcome::NoCollapse { reason } => {
            return unresolved(
                0.0,
                2.0,
                format!(
                    "{at}; the solve at mu = {} above it gave no limit state: {reason}",
                    fmt_value(mu1)
                ),
            )
        }
    };
    let cand = union(&l1.pattern, &fl.pattern, settings.same_joint);
    let sizes: Vec<usize> = (2..=5).collect();
    let start = (l1.x_static, l1.eta_static);
    let found = enumerate(
        arch,
        mu,
        &cand,
        &sizes,
        start.0,
        start.1,
        (0.0, l1.eta),
        0.0,
        settings,
        log,
    );
    match found.limit {
        Some(mut ls) => {
            ls.bracket = (ls.eta, ls.eta);
            Outcome::Limit(ls)
        }
        None => unresolved(
            0.0,
            l1.eta,
            format!("{at}: no pattern of its sliding contacts and of the limit state at mu = {} gave a verified limit state", fmt_value(mu1)),
        ),
    }
}

/// The contacts of `a` and those of `b` not already in `a` (same kind and location, the
/// same joint within `same_joint`), by increasing β.
fn union(a: &[Contact], b: &[Contact], same_joint: f64) -> Vec<Contact> {
    let mut out = a.to_vec();
    for c in b {
        let dup = out
            .iter()
            .any(|d| d.kind == c.kind && d.at == c.at && (d.beta - c.beta).abs() <= same_joint);
        if !dup {
            out.push(*c);
        }
    }
    out.sort_by(|x, y| x.beta.total_cmp(&y.beta));
    out
}

/// The friction `--mu ms` (or `mu="ms"`) asks for: μ_ms of `arch`, the corner of its
/// vertical branch. An error naming the argument when the arch has none (it stands
/// without friction, or at no finite friction) or it cannot be computed.
pub fn mu_ms_of(arch: &Arch, settings: &Settings) -> Result<f64, InputError> {
    let reason = match least_friction(arch, settings) {
        Ok(Some(m)) if m >= MU_MS_ZERO => return Ok(m),
        Ok(Some(_)) => "this arch stands without friction (mu_ms = 0)".to_string(),
        Ok(None) => "no finite friction makes this arch stand".to_string(),
        Err(e) => format!("mu_ms could not be computed ({e})"),
    };
    Err(InputError::Inconsistent {
        arg: "--mu ms",
        reason,
    })
}
