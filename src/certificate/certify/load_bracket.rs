//! The two sides of λ_static for a `largest_multiplier` certificate: the state at
//! λ_static with its active contacts, moved inside the admissible set at λ_lo, and a Farkas
//! certificate at λ_hi.

use super::loaded::{at_lambda, cert_joints, row_at, sorted, Loaded};
use super::sides::{chord_pool, find_farkas, move_inside, reduced, widening, Row};
use crate::arch::{Arch, JointLayout};
use crate::certificate::format::{
    Certificate, LoadFarkas, LoadSearchEvidence, LoadState, MultiplierSides, NotCertified,
};
use crate::certificate::verify::{prove_admissible_side, verify};
use crate::load::{rows, LiveLoad};
use crate::multiplier::continuum::extreme;
use crate::settings::Settings;
use crate::statics::{magnitude, Affine, Reactions};

/// The state at λ_static and its active contacts: for a discrete arch the rows within the
/// survey's event tolerance; for a continuous arch the exchange's own pattern (its state
/// must be the survey's λ_static).
pub(super) fn static_state(
    arch: &Arch,
    eta: f64,
    mu: f64,
    load: &LiveLoad,
    (lambda, x): (f64, Reactions),
    settings: &Settings,
) -> Result<(f64, Reactions, Vec<Loaded>), NotCertified> {
    match arch.layout() {
        JointLayout::Discrete(joints) => {
            let active: Vec<Loaded> = rows(arch, joints, eta, mu, load)
                .iter()
                .filter(|r| {
                    let size = magnitude(r.contact.kind, eta, mu, &x, settings.magnitude_floor);
                    r.at(&x, lambda).abs() <= settings.event_tol * size
                })
                .map(|r| (r.contact, r.side))
                .collect();
            Ok((lambda, x, sorted(active)))
        }
        JointLayout::Continuous => match extreme(arch, eta, mu, load, true, settings) {
            Ok(Some((l, xs, pattern))) if (l - lambda).abs() <= 1e-12 * (1.0 + lambda) => {
                Ok((l, xs, sorted(pattern)))
            }
            _ => Err(NotCertified(format!(
                "the static maximum lambda_static = {lambda} could not be recomputed with its pattern"
            ))),
        },
    }
}

/// The certificate of a finite λ_static `top` (claim `largest_multiplier` in `cert`): the
/// state there with its active contacts, the `load_search` evidence that `search` builds
/// from that state, then the bracket of λ_static to `gap`.
pub(super) fn largest(
    arch: &Arch,
    (eta, mu): (f64, f64),
    load: &LiveLoad,
    top: (f64, Reactions),
    (mut cert, gap): (Certificate, f64),
    settings: &Settings,
    search: impl FnOnce((f64, Reactions, &[Loaded])) -> Result<Option<LoadSearchEvidence>, NotCertified>,
) -> Result<Certificate, NotCertified> {
    let (lambda_s, x_s, pattern) = static_state(arch, eta, mu, load, top, settings)?;
    cert.load_search = search((lambda_s, x_s, &pattern))?;
    bracket(
        arch,
        eta,
        mu,
        load,
        (lambda_s, x_s, &pattern),
        cert,
        gap,
        settings,
    )
}

/// The two sides of λ_static: an admissible state at λ_lo, a Farkas certificate at λ_hi.
#[allow(clippy::too_many_arguments)]
fn bracket(
    arch: &Arch,
    eta: f64,
    mu: f64,
    load: &LiveLoad,
    (lambda_s, x_s, pattern): (f64, Reactions, &[Loaded]),
    cert: Certificate,
    gap: f64,
    settings: &Settings,
) -> Result<Certificate, NotCertified> {
    if lambda_s.is_nan() || lambda_s <= 0.0 {
        return Err(NotCertified(format!(
            "lambda_static = {lambda_s}: a relative bracket needs lambda_static > 0"
        )));
    }
    let row = |l: Loaded| row_at(arch, eta, mu, load, l);
    let pool = chord_pool(arch, pattern);
    let probe = |c: &Certificate| {
        let mut p = c.clone();
        p.load_search = None;
        p
    };
    let wide = |lo: f64, hi: f64, g: f64| hi - lo > g * hi;
    let found = widening(lambda_s, gap, wide, |lambda_lo, lambda_hi| {
        let lo_rows: Vec<Affine> = pattern
            .iter()
            .map(|&l| at_lambda(row(l), lambda_lo))
            .collect();
        let x = move_inside(&lo_rows, x_s, 1.0 / (lambda_s - lambda_lo), settings)?;
        let mut c = cert.clone();
        c.multiplier = Some(MultiplierSides {
            admissible: Some(LoadState {
                lambda: lambda_lo,
                x,
            }),
            infeasible: None,
            transfer: None,
            recession: None,
        });
        prove_admissible_side(&c).ok()?;
        let hi_rows: Vec<(Loaded, Row)> = pool
            .iter()
            .map(|&l| (l, Row::from(at_lambda(row(l), lambda_hi))))
            .collect();
        let with = |labelled: &[(Loaded, f64)]| {
            let mut full = c.clone();
            if let Some(m) = full.multiplier.as_mut() {
                m.infeasible = Some(LoadFarkas {
                    lambda: Some(lambda_hi),
                    joints: cert_joints(Some(load), labelled),
                    lambda_row: None,
                });
            }
            full.gap = Some(lambda_hi - lambda_lo);
            full.gap_relative = Some((lambda_hi - lambda_lo) / lambda_hi);
            full
        };
        // four rows in x, or three sliding rows in (h, v) (they do not involve w)
        let sliding = reduced(&hi_rows, |l| !l.0.kind.is_hinge(), &[2]);
        let l = find_farkas(&hi_rows, 3, |l| verify(&probe(&with(l))).is_ok())
            .or_else(|| find_farkas(&sliding, 2, |l| verify(&probe(&with(l))).is_ok()))?;
        let full = with(&l);
        Some(match verify(&full) {
            Ok(_) => Ok(full),
            Err(e) => Err(NotCertified(format!(
                "the evidence of the limit states does not verify: {}",
                e.0
            ))),
        })
    });
    found.unwrap_or_else(|| {
        Err(NotCertified(format!(
            "no certificate could be proved at a relative gap up to 1e-4 (lambda_static = {lambda_s})"
        )))
    })
}
