//! An unbounded multiplier: the proof that a transfer of the point load to a springing, or
//! a recession direction of the admissible set, keeps the admissible state admissible as λ
//! grows.

use super::enclosure::{prove_pieces, prove_with_live, Piece};
use super::live::{everywhere, sections, side_text, Live};
use super::report::{reject, Rejection};
use super::statics::{kinds, phi, Model, Ntm};
use super::vertical::At;
use crate::certificate::format::{ContactKind, LoadState, Side, Transfer};
use crate::certificate::interval::Interval as I;

/// Proves that a transfer keeps every section admissible as λ grows (see [`Transfer`]):
/// the sections whose actions change along the ray (those that do not carry the load for
/// `right`, those that do for `left`) change by ∓ the live unit actions u = (−cos β,
/// sin β, cos β − (1 + η/2) cos β_P), and φ of that change must be ≤ 0. Its extrados
/// hinge row is (1 + η/2)(cos β_P − cos β) for `right` and the opposite for `left`: zero at
/// β_P itself (the force passes through the extrados point of its own section), and on a
/// continuous piece between β_P and a springing ≤ 0 exactly when sin((β + β_P)/2) ≥ 0 there
/// (cos β − cos β_P = 2 sin((β + β_P)/2) sin((β_P − β)/2), the second factor of known sign
/// on the arch's span ≤ 2π), proved on the enclosure of (β + β_P)/2 over the piece. Every
/// other row is proved in intervals: joint by joint, or over the piece by Taylor
/// enclosures.
pub(super) fn prove_transfer(
    model: &Model,
    live: &Live,
    transfer: Transfer,
    mu: Option<f64>,
) -> Result<String, Rejection> {
    let Some(bp) = live.point() else {
        return reject(
            "multiplier.transfer: a transfer carries a point load, not a horizontal one",
        );
    };
    let name = transfer_name(transfer);
    // right: the sections that do not carry the load change by −u; left: those that do, by u
    let (sign, carrying) = match transfer {
        Transfer::Right => (-1.0, false),
        Transfer::Left => (1.0, true),
    };
    let others: Vec<ContactKind> = kinds(mu)
        .iter()
        .copied()
        .filter(|&k| k != ContactKind::HingeExtrados)
        .collect();
    let unit = |b: I| -> Ntm {
        let u = live
            .ntm(
                model,
                b,
                At {
                    beta: bp,
                    after: true,
                },
            )
            .expect("a point load's unit actions");
        Ntm::default().plus(sign, &u)
    };
    let (mut proved, mut zero) = (0usize, 0usize);
    let changing = match &model.joints {
        Some(joints) => {
            let sections: Vec<(f64, Option<Side>)> = joints
                .iter()
                .flat_map(|&b| sections(b, &[bp]).into_iter().map(move |s| (b, s)))
                .filter(|&(b, s)| live.carries(b, s) == carrying)
                .collect();
            for &(b, side) in &sections {
                let u = unit(I::point(b));
                for &kind in kinds(mu) {
                    let v = phi(kind, 0, &u, live.eta, mu);
                    if b == bp && kind == ContactKind::HingeExtrados {
                        zero += 1; // identically zero: through the extrados point of β_P
                        continue;
                    }
                    if v.hi.is_nan() || v.hi > 0.0 {
                        return reject(format!(
                            "multiplier.transfer {name}: {} at beta = {b}{} grows along the ray (upper bound {:e}): not proved",
                            kind.name(),
                            side_text(side),
                            v.hi
                        ));
                    }
                    proved += 1;
                }
            }
            format!("{} section(s)", sections.len())
        }
        None => {
            let (a, b) = match transfer {
                Transfer::Right => (model.beta_r, bp),
                Transfer::Left => (bp, model.beta_l),
            };
            // the extrados hinge row: the sign of sin((β + β_P)/2) over the piece
            let half = (I::point(a) + I::point(bp)) * I::point(0.5);
            let other = (I::point(b) + I::point(bp)) * I::point(0.5);
            let arg = I::new(half.lo.min(other.lo), half.hi.max(other.hi));
            if a < b {
                let s = arg.sin();
                if s.lo.is_nan() || s.lo < 0.0 {
                    return reject(format!(
                        "multiplier.transfer {name}: hinge_extrados over [{a}, {b}] is not proved <= 0 (sin((beta + beta_P)/2) >= {:e})",
                        s.lo
                    ));
                }
            }
            zero += 1;
            let piece = Piece {
                a,
                b,
                eval: &unit,
                smooth: true,
            };
            proved += prove_pieces(
                model,
                &[piece],
                live.eta,
                mu,
                &others,
                false,
                &format!("multiplier.transfer {name}"),
            )?;
            format!("the sections over [{a}, {b}]")
        }
    };
    Ok(format!(
        "proved (interval arithmetic): transferring the load to the {name} springing (reactions changed by {} per unit lambda) keeps every activation function <= 0 as lambda grows: {changing} change ({proved} rows or enclosures proved non-increasing; the extrados hinge row {}); the others are unchanged (an identity of the statics)",
        match transfer {
            Transfer::Right => "(0, 1, (1 + eta/2) cos beta_P - cos beta_R)",
            Transfer::Left => "nothing",
        },
        if model.joints.is_some() {
            format!("of the loaded section identically zero ({zero})")
        } else {
            "by the sign of sin((beta + beta_P)/2)".to_string()
        }
    ))
}

/// Proves that a direction (d_x, d_λ), d_λ > 0, is a recession direction of the admissible
/// set: the linear part of every activation function along it — the weightless actions of
/// d_x plus d_λ times the live ones — is ≤ 0 at every section (every joint, or over each
/// piece of a continuous arch by Taylor enclosures), so that (x + t d_x, λ + t d_λ) stays
/// admissible for every t ≥ 0.
pub(super) fn prove_recession(
    model: &Model,
    live: &Live,
    d: &LoadState,
    mu: Option<f64>,
) -> Result<String, Rejection> {
    if !(d.lambda.is_finite() && d.lambda > 0.0 && d.x.iter().all(|v| v.is_finite())) {
        return reject(format!(
            "multiplier.recession: needs a finite direction with lambda > 0, found lambda = {}",
            d.lambda
        ));
    }
    let (dx, dl) = (d.x, d.lambda);
    let weightless = move |b: I| model.ntm_weightless(b, dx);
    let load = Some((live, dl));
    let count = prove_with_live(
        model,
        &weightless,
        live.eta,
        load,
        mu,
        false,
        "multiplier.recession",
    )?;
    Ok(format!(
        "proved (interval arithmetic): along the direction (d_x, d_lambda) = ([{}, {}, {}], {dl}) no activation function grows {} ({count} enclosures), so the admissible state stays admissible at every larger lambda",
        dx[0], dx[1], dx[2], everywhere(model, live)
    ))
}

fn transfer_name(t: Transfer) -> &'static str {
    match t {
        Transfer::Right => "right",
        Transfer::Left => "left",
    }
}
