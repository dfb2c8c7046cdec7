//! The certificate as read, checked before anything is proved: every number finite, the
//! arch well formed (it becomes the [`Model`] of the proofs), the stated gaps.

use super::report::{reject, Rejection};
use super::statics::Model;
use super::vertical::FillModel;
use crate::certificate::format::{Certificate, WeightModel};
use std::f64::consts::PI;

/// Every number of the certificate must be finite (JSON cannot carry NaN or ∞, but a
/// certificate built in memory can).
pub(super) fn check_finite(cert: &Certificate) -> Result<(), Rejection> {
    let mut nums: Vec<(&str, f64)> = vec![
        ("arch.beta_right", cert.arch.beta_right),
        ("arch.beta_left", cert.arch.beta_left),
    ];
    if let Some(js) = &cert.arch.joint_angles {
        nums.extend(js.iter().map(|&b| ("arch.joint_angles", b)));
    }
    if let Some(f) = &cert.arch.fill {
        nums.extend([
            ("arch.fill.weight_ratio", f.weight_ratio),
            ("arch.fill.depth", f.depth),
        ]);
    }
    if let Some(mu) = cert.mu {
        nums.push(("mu", mu));
    }
    if let Some(l) = &cert.load {
        for p in l.patches.iter().flatten() {
            nums.extend([
                ("load.patches", p.x_lo),
                ("load.patches", p.x_hi),
                ("load.patches", p.q),
            ]);
        }
        for p in l.points.iter().flatten() {
            nums.extend([("load.points", p.beta), ("load.points", p.q)]);
        }
    }
    if let Some(s) = &cert.safe {
        nums.push(("safe.eta", s.eta));
        nums.extend(s.x.iter().map(|&v| ("safe.x", v)));
    }
    if let Some(f) = &cert.collapse {
        if let Some(e) = f.eta {
            nums.push(("collapse.eta", e));
        }
        for j in &f.joints {
            nums.extend([("collapse.joints.beta", j.beta), ("collapse.joints.y", j.y)]);
        }
    }
    for cell in cert.collapse_cells.iter().flatten() {
        nums.extend([
            ("collapse_cells.eta_lo", cell.eta_lo),
            ("collapse_cells.eta_hi", cell.eta_hi),
        ]);
        for j in &cell.joints {
            nums.extend([
                ("collapse_cells.joints.beta", j.beta),
                ("collapse_cells.joints.y", j.y),
            ]);
        }
    }
    if let Some(ls) = &cert.limit_state {
        nums.push(("limit_state.eta", ls.eta));
        nums.extend(ls.x.iter().map(|&v| ("limit_state.x", v)));
        nums.extend(
            ls.pattern
                .iter()
                .map(|j| ("limit_state.pattern.beta", j.beta)),
        );
        nums.extend(ls.rates.iter().map(|&v| ("limit_state.rates", v)));
        nums.push((
            "limit_state.complementarity_residual",
            ls.complementarity_residual,
        ));
    }
    if let Some(g) = cert.gap {
        nums.push(("gap", g));
    }
    if let Some(g) = cert.gap_relative {
        nums.push(("gap_relative", g));
    }
    match nums.iter().find(|(_, v)| !v.is_finite()) {
        Some((field, v)) => reject(format!("{field}: {v} is not a finite number")),
        None => Ok(()),
    }
}

/// The arch of the certificate, checked: springings in order, the joints of a discrete
/// arch strictly increasing from β_R to β_L.
pub(super) fn model_of(cert: &Certificate) -> Result<Model, Rejection> {
    let a = &cert.arch;
    if !(a.beta_right < a.beta_left && a.beta_left - a.beta_right <= 2.0 * PI) {
        return reject(format!(
            "arch: need beta_right < beta_left <= beta_right + 2 pi, found beta_right = {}, beta_left = {}",
            a.beta_right, a.beta_left
        ));
    }
    if let Some(js) = &a.joint_angles {
        if js.len() < 2 {
            return reject(
                "arch: joint_angles of a discrete arch need at least the two springings",
            );
        }
        if js.first() != Some(&a.beta_right) || js.last() != Some(&a.beta_left) {
            return reject("arch: joint_angles must start at beta_right and end at beta_left (the springings are joints)");
        }
        if let Some(w) = js
            .windows(2)
            .find(|w| w[0].is_nan() || w[1].is_nan() || w[1] <= w[0])
        {
            return reject(format!(
                "arch: joint_angles must be strictly increasing, found {} then {}",
                w[0], w[1]
            ));
        }
    }
    let fill = match a.fill {
        Some(f) if !(f.weight_ratio >= 0.0 && f.depth >= 0.0) => {
            return reject(format!(
                "arch.fill: weight_ratio = {} and depth = {} must be >= 0",
                f.weight_ratio, f.depth
            ))
        }
        Some(f) => Some(FillModel {
            weight_ratio: f.weight_ratio,
            depth: f.depth,
        }),
        None => None,
    };
    Ok(Model {
        beta_r: a.beta_right,
        springing: super::statics::springing_trig(a.beta_right),
        joint_trig: super::statics::joint_trig(a.joint_angles.as_deref()),
        beta_l: a.beta_left,
        centroid: a.weight == WeightModel::Centroid,
        joints: a.joint_angles.clone(),
        fill,
    })
}

/// The stated gaps must be hi − lo and (hi − lo)/hi of the bracket of the parameter
/// `param` (`eta` or `lambda`), hi > 0.
pub(super) fn check_gap(
    cert: &Certificate,
    lo: f64,
    hi: f64,
    param: &str,
) -> Result<(), Rejection> {
    let gap = hi - lo;
    if let Some(g) = cert.gap {
        if !g.is_finite() || (g - gap).abs() > 1e-15 * hi.abs() + 1e-300 {
            return reject(format!(
                "stated gap {g} differs from {param}_hi - {param}_lo = {gap}"
            ));
        }
    }
    if let Some(g) = cert.gap_relative {
        let r = gap / hi;
        if !g.is_finite() || (g - r).abs() > 1e-15 + 1e-9 * r.abs() {
            return reject(format!(
                "stated gap_relative {g} differs from ({param}_hi - {param}_lo)/{param}_hi = {r}"
            ));
        }
    }
    Ok(())
}
