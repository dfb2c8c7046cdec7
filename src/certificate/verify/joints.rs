//! The listed joints of a certificate checked against its arch: the joints of a Farkas
//! certificate and the pattern of a listed state (on the arch, a kind that exists at μ, a
//! side exactly at the point load's angle, the order of the list).

use super::report::{reject, Rejection};
use super::statics::{exists, Model};
use crate::certificate::format::{CertJoint, Location, PatternJoint, Side};

/// A joint of a Farkas certificate: on the arch (a listed joint of a discrete arch), a
/// kind that exists at μ, a finite multiplier, and a `side` exactly at the point load's
/// angles `splits` (never without a point load).
pub(super) fn check_farkas_joint(
    model: &Model,
    i: usize,
    j: &CertJoint,
    mu: Option<f64>,
    splits: &[f64],
) -> Result<(), Rejection> {
    model.check_joint(j.beta, &format!("collapse side: joint {i}"))?;
    if !exists(j.kind, mu) {
        return reject(format!(
            "collapse side: joint {i} is {} at beta = {}, but there is no sliding at infinite friction (mu = null): that constraint does not exist in this problem",
            j.kind.name(),
            j.beta
        ));
    }
    if !(j.y.is_finite()) {
        return reject(format!(
            "collapse side: multiplier of joint {i} is not a finite number"
        ));
    }
    check_side(j.beta, j.side, splits, &format!("collapse side: joint {i}"))
}

/// `side` must be given exactly at a point load's angle (`splits`: the two sections
/// there differ) and nowhere else.
pub(super) fn check_side(
    beta: f64,
    side: Option<Side>,
    splits: &[f64],
    what: &str,
) -> Result<(), Rejection> {
    match (splits.contains(&beta), side) {
        (true, None) => reject(format!(
            "{what}: beta = {beta} is the point load's angle: give the side of the loaded section (before or after)"
        )),
        (false, Some(_)) => reject(format!(
            "{what}: a side is given at beta = {beta}, but only the point load's own section has two sides"
        )),
        _ => Ok(()),
    }
}

/// The pattern of the limit state: every joint inside the arch (at a listed joint of a
/// discrete arch), `at` matching its angle, its kind existing at μ, and the list strictly
/// increasing in (β, kind) (two contacts may share a joint).
pub(super) fn check_pattern(
    model: &Model,
    pattern: &[PatternJoint],
    mu: Option<f64>,
    splits: &[f64],
    whose: &str,
) -> Result<(), Rejection> {
    for (i, j) in pattern.iter().enumerate() {
        let what = format!("{whose}: pattern joint {i}");
        model.check_joint(j.beta, &what)?;
        check_side(j.beta, j.side, splits, &what)?;
        if !exists(j.kind, mu) {
            return reject(format!(
                "{what} is {}, but there is no sliding at infinite friction (mu = null)",
                j.kind.name()
            ));
        }
        let at_springing = j.beta == model.beta_r || j.beta == model.beta_l;
        if at_springing != (j.at == Location::Springing) {
            return reject(format!(
                "{what}: at = {} does not match beta = {} (the springings are {} and {})",
                if j.at == Location::Springing {
                    "springing"
                } else {
                    "interior"
                },
                j.beta,
                model.beta_r,
                model.beta_l
            ));
        }
    }
    // the side of the loaded section orders `before` first (no side: one section)
    let key = |j: &PatternJoint| (j.side != Some(Side::Before), j.kind);
    if let Some(w) = pattern
        .windows(2)
        .find(|w| !(w[0].beta < w[1].beta || (w[0].beta == w[1].beta && key(&w[0]) < key(&w[1]))))
    {
        return reject(format!(
            "{whose}: pattern must be strictly increasing in (beta, {}kind), found {} at {} then {} at {}",
            if !splits.is_empty() { "side, " } else { "" },
            w[0].kind.name(),
            w[0].beta,
            w[1].kind.name(),
            w[1].beta
        ));
    }
    Ok(())
}
