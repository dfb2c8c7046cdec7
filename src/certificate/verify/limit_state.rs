//! The floating-point consistency checks of a thickness certificate's limit state
//! (evidence, not proof): the pattern active, B λ = 0, λ ≥ 0, Σ λ = 1, L_e ≥ 0.

use super::report::{reject, Rejection};
use super::statics::{phi, Model};
use crate::certificate::format::{ContactKind, LimitStateCert};
use crate::certificate::interval::Interval as I;

/// Tolerances of the floating-point consistency checks of the limit state.
pub const LIMIT_STATE_TOL: f64 = 1e-9;

pub(super) fn check_limit_state(
    model: &Model,
    mu: Option<f64>,
    ls: &LimitStateCert,
    eta_lo: f64,
    eta_hi: f64,
) -> Result<(), Rejection> {
    let tol = LIMIT_STATE_TOL;
    if !(ls.eta >= eta_lo && ls.eta <= eta_hi) {
        return reject(format!(
            "limit state: eta = {} outside [eta_lo, eta_hi]",
            ls.eta
        ));
    }
    if ls.rates.len() != ls.pattern.len() || ls.rates.iter().any(|&r| r < 0.0) {
        return reject("limit state: rates must be one non-negative number per pattern joint");
    }
    if (ls.rates.iter().sum::<f64>() - 1.0).abs() > tol {
        return reject("limit state: rates do not sum to 1");
    }
    let eta = ls.eta;
    let scale = 1.0 + ls.x.iter().map(|v| v.abs()).sum::<f64>();
    let (re, ri) = (1.0 + eta / 2.0, 1.0 - eta / 2.0);
    let mut b = [0.0; 3];
    for (j, &r) in ls.pattern.iter().zip(&ls.rates) {
        let (s, c) = (j.beta.sin(), j.beta.cos());
        let col = match j.kind {
            ContactKind::HingeExtrados => [-re * s, re * c, -1.0],
            ContactKind::HingeIntrados => [ri * s, -ri * c, 1.0],
            ContactKind::SlidePlus => [c, s, 0.0],
            ContactKind::SlideMinus => [-c, -s, 0.0],
        };
        for i in 0..3 {
            b[i] += r * col[i];
        }
        let v = phi(j.kind, 0, &model.ntm(I::point(j.beta), ls.x, eta), eta, mu);
        if v.mid().is_nan() || v.mid().abs() > tol * scale {
            return reject(format!(
                "limit state: {} at beta = {} is not active (phi = {:e})",
                j.kind.name(),
                j.beta,
                v.mid()
            ));
        }
    }
    if b.iter().any(|v| v.abs() > tol) {
        return reject(format!("limit state: B lambda = {b:?} is not zero"));
    }
    // external power: blocks between distinct pattern joints
    let rho = model.rho(eta).mid();
    let mut angles: Vec<f64> = ls.pattern.iter().map(|j| j.beta).collect();
    angles.sort_by(f64::total_cmp);
    angles.dedup();
    let mut power = 0.0;
    for w in angles.windows(2) {
        let (mut vy, mut psi) = (0.0, 0.0);
        for (j, &r) in ls.pattern.iter().zip(&ls.rates) {
            if j.beta <= w[0] {
                let (s, c) = (j.beta.sin(), j.beta.cos());
                let (cy, cp) = match j.kind {
                    ContactKind::HingeExtrados => (re * c, -1.0),
                    ContactKind::HingeIntrados => (-ri * c, 1.0),
                    ContactKind::SlidePlus => (s, 0.0),
                    ContactKind::SlideMinus => (-s, 0.0),
                };
                vy += r * cy;
                psi += r * cp;
            }
        }
        power -= (w[1] - w[0]) * vy + psi * rho * (w[1].sin() - w[0].sin());
    }
    if power < -tol {
        return reject(format!(
            "limit state: external power L_e = {power:e} is negative"
        ));
    }
    Ok(())
}
