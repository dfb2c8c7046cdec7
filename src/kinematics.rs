//! Kinematics of a pattern (formulation §4): the compatibility matrix B and the
//! external power of self-weight L_e, both linear in the rates λ of the pattern's
//! contacts, and the mirror map used for symmetric representatives.
//!
//! Blocks are the rigid pieces between consecutive active joints; the pieces
//! between a springing and the first/last active joint are at rest.

use crate::arch::{Arch, Radians};
use crate::contact::Contact;
use crate::contact::ContactKind;
use std::f64::consts::PI;

/// The contribution of one unit rate of `mode` at `beta` to (V_x(O), V_y(O), ψ) of
/// everything after the joint (formulation §4): one column of B.
pub fn column(mode: ContactKind, beta: Radians, eta: f64) -> [f64; 3] {
    let (s, c) = beta.sin_cos();
    let (re, ri) = (1.0 + 0.5 * eta, 1.0 - 0.5 * eta);
    match mode {
        ContactKind::HingeExtrados => [-re * s, re * c, -1.0],
        ContactKind::HingeIntrados => [ri * s, -ri * c, 1.0],
        ContactKind::SlidePlus => [c, s, 0.0],
        ContactKind::SlideMinus => [-c, -s, 0.0],
    }
}

/// The coefficients p with L_e = p · λ for the given contacts (any order).
///
/// L_e = −Σ_m [W_m V_y,m + ψ_m (W G_x)_m] over the blocks m between consecutive
/// distinct active joints, with W_m = β_{m+1} − β_m and
/// (W G_x)_m = ρ (sin β_{m+1} − sin β_m) (ρ = 1 for centreline weight,
/// 1 + η²/12 for the true centroid), plus the fill's resultant and first moment on the
/// block when the arch carries fill.
pub fn power(arch: &Arch, eta: f64, contacts: &[Contact]) -> Vec<f64> {
    let rho = arch.weight().rho(eta);
    let mut joints: Vec<Radians> = contacts.iter().map(|c| c.beta).collect();
    joints.sort_by(f64::total_cmp);
    joints.dedup();
    // For each joint angle, the sum over all blocks after it of (W, W·G_x).
    let fill = arch.fill();
    let blocks: Vec<(Radians, f64, f64)> = joints
        .windows(2)
        .map(|w| {
            let (weight, moment) = (w[1] - w[0], rho * (w[1].sin() - w[0].sin()));
            match fill {
                None => (w[0], weight, moment),
                // the fill's resultant F and first moment S on the block: differences of
                // the free body's (bridge spec §2)
                Some(f) => {
                    let [a, b] = [w[0], w[1]].map(|beta| f.load(arch.springings(), eta, beta));
                    (w[0], weight + (b.f[0] - a.f[0]), moment + (b.s[0] - a.s[0]))
                }
            }
        })
        .collect();
    contacts
        .iter()
        .map(|c| {
            let col = column(c.kind, c.beta, eta);
            -blocks
                .iter()
                .filter(|(start, _, _)| *start >= c.beta)
                .map(|(_, w, wgx)| w * col[1] + wgx * col[2])
                .sum::<f64>()
        })
        .collect()
}

/// B λ: the velocity of the left springing, which compatibility requires to vanish.
pub fn compatibility_residual(eta: f64, contacts: &[Contact], rates: &[f64]) -> [f64; 3] {
    let mut r = [0.0; 3];
    for (c, &l) in contacts.iter().zip(rates) {
        let col = column(c.kind, c.beta, eta);
        for i in 0..3 {
            r[i] += l * col[i];
        }
    }
    r
}

/// Index of the mirror image (π − β, mirrored mode) of each contact within the same
/// list, or `None` when some contact has no mirror image in the list.
pub fn mirror_indices(contacts: &[Contact], tol: f64) -> Option<Vec<usize>> {
    contacts
        .iter()
        .map(|c| {
            contacts
                .iter()
                .position(|d| d.kind == c.kind.mirrored() && (d.beta - (PI - c.beta)).abs() <= tol)
        })
        .collect()
}

/// The rigid motion (V_x(O), V_y(O), ψ) of each block of a mechanism: the pieces between
/// consecutive distinct active joints, as (β_start, β_end, motion); active joints closer than
/// `same_joint` (`Settings::same_joint`) are one. Pieces before the first and after the last
/// active joint are at rest and not listed.
pub fn block_motions(
    eta: f64,
    contacts: &[Contact],
    rates: &[f64],
    same_joint: f64,
) -> Vec<(Radians, Radians, [f64; 3])> {
    let mut joints: Vec<Radians> = contacts.iter().map(|c| c.beta).collect();
    joints.sort_by(f64::total_cmp);
    // two contacts at one joint (E and I at a detached joint) bound no block between them,
    // even when their angles differ in the last bits
    joints.dedup_by(|b, a| *b - *a <= same_joint);
    joints
        .windows(2)
        .map(|w| {
            let mut v = [0.0; 3];
            for (c, &r) in contacts.iter().zip(rates) {
                if c.beta <= w[0] + same_joint {
                    let col = column(c.kind, c.beta, eta);
                    for i in 0..3 {
                        v[i] += r * col[i];
                    }
                }
            }
            (w[0], w[1], v)
        })
        .collect()
}
