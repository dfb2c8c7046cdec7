//! Outcomes other than a limit state: no equilibrium at any thickness (with μ_ms from the
//! friction-only problem when μ is below it) and an honestly unresolved bracket.

use super::solution::Outcome;
use crate::admissibility::WorkingSet;
use crate::arch::{fmt_value, Arch, ETA_TOP};
use crate::contact::ContactKind;
use crate::friction::least_friction;
use crate::search::margin_at;
use crate::settings::Settings;

pub(crate) fn unresolved(eta_lo: f64, eta_hi: f64, reason: String) -> Outcome {
    Outcome::Unresolved {
        eta_lo,
        eta_hi,
        reason,
        least_static: None,
    }
}

/// No equilibrium at μ below μ_ms: no thickness can stand.
pub(crate) fn below_mu_ms(mu: f64, mu_ms: f64) -> Outcome {
    Outcome::NoEquilibrium {
        mu_ms: Some(mu_ms),
        reason: format!(
            "mu = {} is below mu_ms = {mu_ms:.10}: no thickness can stand (purely sliding collapse)",
            fmt_value(mu)
        ),
    }
}

pub(crate) fn no_equilibrium(arch: &Arch, mu: f64, settings: &Settings) -> Outcome {
    match least_friction(arch, settings) {
        Ok(Some(mu_ms)) if mu < mu_ms => below_mu_ms(mu, mu_ms),
        Ok(Some(mu_ms)) if mu < mu_ms * (1.0 + settings.mu_ms_resolution) && !stands_at_all(arch, settings) => {
            Outcome::NoEquilibrium {
                mu_ms: Some(mu_ms),
                reason: format!(
                    "mu = {} is within {} (relative) of mu_ms = {mu_ms:.10}, but no thickness eta < 2 admits equilibrium even without sliding (mu = inf)",
                    fmt_value(mu),
                    settings.mu_ms_resolution
                ),
            }
        }
        Ok(Some(mu_ms)) if mu < mu_ms * (1.0 + settings.mu_ms_resolution) => Outcome::Unresolved {
            eta_lo: 0.0,
            eta_hi: 2.0,
            reason: format!(
                "mu = {} is within {} (relative) of mu_ms = {mu_ms:.10}, closer than the LP resolves admissibility",
                fmt_value(mu),
                settings.mu_ms_resolution
            ),
            least_static: None,
        },
        Ok(Some(mu_ms)) => Outcome::NoEquilibrium {
            mu_ms: Some(mu_ms),
            reason: format!(
                "mu = {} is above mu_ms = {mu_ms:.10}, but no thickness eta < 2 admits equilibrium at this friction",
                fmt_value(mu)
            ),
        },
        Ok(None) => Outcome::NoEquilibrium {
            mu_ms: None,
            reason: "no friction coefficient admits equilibrium for this opening".into(),
        },
        Err(e) => Outcome::NoEquilibrium {
            mu_ms: None,
            reason: format!("no thickness eta < 2 admits equilibrium (mu_ms not computed: {e})"),
        },
    }
}

/// Whether some thickness below the limit admits equilibrium without sliding (μ = ∞):
/// admissibility only grows with μ, so an arch that fails this stands at no friction. An
/// LP that cannot decide counts as standing (the caller then says "unresolved").
fn stands_at_all(arch: &Arch, settings: &Settings) -> bool {
    let mu = f64::INFINITY;
    let mut ws = WorkingSet::initial(arch);
    let modes = ContactKind::active_at(mu);
    margin_at(arch, ETA_TOP, mu, modes, &mut ws, settings).map_or(true, |m| m.margin >= 0.0)
}
