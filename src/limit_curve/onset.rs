//! Where a new contact becomes active along a branch of the static boundary.
//!
//! A branch's pattern determines its least state as a function of μ (Newton on the
//! pattern with η unknown, KKT-completed when it has fewer than four contacts). A corner
//! where a contact joins the pattern is the μ at which that contact's activation function,
//! evaluated at its peak for the branch's state, reaches zero: the root of a smooth scalar
//! function of μ, found by Illinois regula falsi to the resolution of μ. Unlike Newton on
//! the union of two patterns this needs no square system (a three-contact KKT pattern
//! plus one contact is not one), and it does not converge to a point of the other branch.

use super::transition::Located;
use crate::arch::Arch;
use crate::contact::{Contact, ContactKind, Location};
use crate::refine::{solve_system, Unknowns};
use crate::settings::Settings;
use crate::state::State;
use crate::statics::{magnitude, Reactions};

/// The branch of `pattern` (least state (x, η) at μ₀) followed to μ; `None` when Newton
/// does not converge.
fn follow(
    arch: &Arch,
    pattern: &[Contact],
    from: (Reactions, f64, f64),
    mu: f64,
    settings: &Settings,
) -> Option<(Reactions, f64, Vec<Contact>)> {
    let start = State {
        arch,
        eta: from.1,
        mu,
        x: from.0,
    };
    let r = solve_system(&start, pattern, Unknowns::T, settings).ok()?;
    Some((r.x, r.t, r.contacts))
}

/// The relative value of `c`'s activation function at its peak near `c.beta` (its
/// springing value for a springing contact) for the state (x, η, μ): negative while the
/// contact is inactive. `None` when no peak of that kind lies within `track_angle`.
fn peak_value(
    arch: &Arch,
    c: &Contact,
    (x, eta, mu): (Reactions, f64, f64),
    settings: &Settings,
) -> Option<(f64, Contact)> {
    let st = State { arch, eta, mu, x };
    let scale = magnitude(c.kind, eta, mu, &x, settings.magnitude_floor);
    st.peaks(settings)
        .into_iter()
        .filter(|p| {
            p.contact.kind == c.kind
                && p.contact.at == c.at
                && (c.at == Location::Springing
                    || (p.contact.beta - c.beta).abs() < settings.track_angle)
        })
        .map(|p| (p.value / scale, p.contact))
        .max_by(|a, b| a.0.total_cmp(&b.0))
}

/// The root in μ of `g` (negative at the branch's own sample `from` = (x, η, μ₀), positive
/// at `far_mu`) along the branch of `pattern`, to adjacent floats, by Illinois regula
/// falsi with bisection safeguards. `g` takes (x, η, μ) of the branch's state. Where the
/// branch cannot be followed (Newton leaves the domain, e.g. η ≥ 2), `g` counts as
/// positive when `failure_is_positive`, else the search gives up.
fn root_along(
    arch: &Arch,
    pattern: &[Contact],
    from: (Reactions, f64, f64),
    far_mu: f64,
    settings: &Settings,
    g: &dyn Fn(Reactions, f64, f64) -> Option<f64>,
    failure_is_positive: bool,
) -> Option<(f64, Reactions, f64, Vec<Contact>)> {
    type Point = (f64, Reactions, f64, Vec<Contact>);
    let at = |mu: f64, near: (Reactions, f64)| -> Option<Point> {
        match follow(arch, pattern, (near.0, near.1, mu), mu, settings) {
            Some((x, eta, cs)) => Some((g(x, eta, mu)?, x, eta, cs)),
            None if failure_is_positive => Some((f64::INFINITY, near.0, near.1, vec![])),
            None => None,
        }
    };
    let (mut m0, mut m1) = (from.2, far_mu);
    let first = at(m0, (from.0, from.1))?;
    let far = at(m1, (first.1, first.2))?;
    if !(first.0 < 0.0 && far.0 > 0.0) {
        return None;
    }
    let (mut g0, mut g1) = (first.0, far.0);
    let mut near = (first.1, first.2);
    let mut side = 0i8;
    let mut best = first;
    for _ in 0..300 {
        // to adjacent floats: the root is located to the resolution of μ
        if (m1 - m0).abs() <= 4.0 * f64::EPSILON * m0.abs().max(m1.abs()) {
            break;
        }
        // Illinois: a false-position step, halving the retained end's value when it is
        // kept twice; bisection when the step is undefined or lands too near an end
        let mut m = m1 - g1 * (m1 - m0) / (g1 - g0);
        let w = (m1 - m0).abs();
        if !(m.is_finite() && (m - m0).abs() > 1e-3 * w && (m - m1).abs() > 1e-3 * w) {
            m = 0.5 * (m0 + m1);
        }
        let p = at(m, near)?;
        let gm = p.0;
        if gm.is_finite() {
            near = (p.1, p.2);
        }
        if gm <= 0.0 {
            (m0, g0) = (m, gm);
            if side == -1 {
                g1 *= 0.5;
            }
            side = -1;
            best = p;
            if gm == 0.0 {
                break;
            }
        } else {
            (m1, g1) = (m, gm);
            if side == 1 {
                g0 *= 0.5;
            }
            side = 1;
        }
    }
    // the last point on the negative side (the contact just inactive, or η just below the
    // target), within a few ulps of the root
    Some((m0, best.1, best.2, best.3))
}

/// The μ between the branch's own sample `from` = (x, η, μ₀) and `far_mu` at which
/// `joining` becomes active along the branch of `pattern`. `None` when the branch cannot be
/// followed across the range or the contact does not change sign on it.
pub(super) fn locate(
    arch: &Arch,
    pattern: &[Contact],
    joining: &Contact,
    from: (Reactions, f64, f64),
    far_mu: f64,
    settings: &Settings,
) -> Option<Located> {
    let g = |x: Reactions, eta: f64, mu: f64| {
        peak_value(arch, joining, (x, eta, mu), settings).map(|p| p.0)
    };
    // the contact must be clearly inactive at the branch's own sample (not one of its own
    // contacts that the scan did not separate from a neighbour of the same kind), else
    // there is no onset to find
    if g(from.0, from.1, from.2)? > -10.0 * settings.adm_tol {
        return None;
    }
    let (mu, x, eta, mut cs) = root_along(arch, pattern, from, far_mu, settings, &g, false)?;
    let (_, contact) = peak_value(arch, joining, (x, eta, mu), settings)?;
    cs.push(Contact {
        free: contact.at == Location::Interior,
        ..contact
    });
    cs.sort_by(|a, b| a.beta.total_cmp(&b.beta).then(a.kind.cmp(&b.kind)));
    Some(Located {
        mu,
        eta,
        x,
        pattern: cs,
        residual: 0.0,
    })
}

/// The μ between the branch's sample `from` and `far_mu` at which η along the branch of
/// `pattern` reaches `eta_top` (the thickness limit): where the lowest branch of an arch
/// whose purely-sliding corner would need η_ms ≥ 2 ends.
pub(super) fn reach_eta(
    arch: &Arch,
    pattern: &[Contact],
    from: (Reactions, f64, f64),
    far_mu: f64,
    eta_top: f64,
    settings: &Settings,
) -> Option<Located> {
    // past the thickness limit, or no longer the boundary (another contact violated: the
    // Newton continuation of the pattern is then not the least state), counts as beyond
    let g = |x: Reactions, eta: f64, mu: f64| {
        let st = State { arch, eta, mu, x };
        let worst = st.verdict(ContactKind::active_at(mu), settings).worst;
        Some(if worst > settings.adm_tol {
            f64::INFINITY
        } else {
            eta - eta_top
        })
    };
    let (mu, x, eta, cs) = root_along(arch, pattern, from, far_mu, settings, &g, true)?;
    if (eta - eta_top).abs() > settings.boundary_match * eta_top {
        return None; // the branch ended before the limit: another pattern change
    }
    Some(Located {
        mu,
        eta,
        x,
        pattern: cs,
        residual: 0.0,
    })
}
