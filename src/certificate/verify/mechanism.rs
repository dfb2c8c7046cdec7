//! A state listed without a mechanism, re-checked (thickness and load certificates alike):
//! its pattern is its whole active set (floating point), and the Farkas alternatives of the
//! kinematic LP, proved in interval arithmetic, cover every choice of one sliding sense per
//! section.

use super::joints::check_pattern;
use super::live::{sections, side_text, StateAt};
use super::report::{reject, Rejection};
use super::statics::{kinds, phi, Model, LIMIT_STATE_TOL};
use super::vertical::fill_jets;
use crate::certificate::format::{ContactKind, KinematicFarkas, PatternJoint, Side};
use crate::certificate::interval::Interval as I;

/// A contact not listed in a state's pattern must lie at least this far below zero,
/// relative to (1 + ‖x‖₁), for the pattern to count as the state's whole active set.
pub const INACTIVE_REL: f64 = 1e-12;

/// Checks a state listed without mechanism (its `pattern` and `farkas` at `state`);
/// `Ok(true)` when the Farkas certificates prove it for every one-sense choice,
/// `Ok(false)` when they do not cover them all, `Err` when something stated is false.
pub(super) fn no_mechanism(
    model: &Model,
    mu: Option<f64>,
    state: StateAt,
    pattern: &[PatternJoint],
    farkas: &[KinematicFarkas],
    whose: &str,
) -> Result<bool, Rejection> {
    if !(state.eta.is_finite()
        && state.eta > 0.0
        && state.eta < 2.0
        && state.x.iter().all(|v| v.is_finite()))
    {
        return reject(format!("{whose}: eta must lie in (0, 2) and x be finite"));
    }
    if let Some((_, lambda)) = state.load {
        if !(lambda.is_finite() && lambda >= 0.0) {
            return reject(format!(
                "{whose}: lambda = {lambda} must be finite and >= 0"
            ));
        }
    }
    if pattern.len() > 64 {
        return reject(format!("{whose}: more than 64 contacts"));
    }
    let keyed: Vec<(f64, ContactKind, Option<Side>)> =
        pattern.iter().map(|j| (j.beta, j.kind, j.side)).collect();
    // the pattern: valid joints, active (floating point), and the whole active set
    check_pattern(model, pattern, mu, state.splits(), whose)?;
    let scale = state.scale();
    for &(b, k, side) in &keyed {
        let v = phi(k, 0, &state.ntm(model, b, side), state.eta, mu).mid();
        if v.is_nan() || v.abs() > LIMIT_STATE_TOL * scale {
            return reject(format!(
                "{whose}: {} at beta = {b} is not active (phi = {v:e})",
                k.name()
            ));
        }
    }
    if let Some(joints) = &model.joints {
        for &b in joints {
            for side in sections(b, state.splits()) {
                let a = state.ntm(model, b, side);
                for &k in kinds(mu) {
                    if keyed.contains(&(b, k, side)) {
                        continue;
                    }
                    let v = phi(k, 0, &a, state.eta, mu).mid();
                    if v.is_nan() || v > -INACTIVE_REL * scale {
                        return reject(format!(
                            "{whose}: {} at beta = {b}{} is active or violated (phi = {v:e}) but not in the pattern",
                            k.name(),
                            side_text(side)
                        ));
                    }
                }
            }
        }
    }
    // every one-sense choice must be covered by a proved Farkas certificate (a section
    // slides one way only)
    let Some(choices) = one_sense_choices(&keyed) else {
        return Ok(false);
    };
    let mut proved: Vec<&KinematicFarkas> = Vec::new();
    for (i, f) in farkas.iter().enumerate() {
        if f.drop.iter().any(|&d| d >= keyed.len()) {
            return reject(format!(
                "{whose}: farkas {i} drops a contact that is not in the pattern"
            ));
        }
        if state.load.is_none() && f.v != 0.0 {
            return reject(format!(
                "{whose}: farkas {i} has a live-power multiplier v, but there is no live load"
            ));
        }
        if prove_farkas(model, state, &keyed, f) {
            proved.push(f);
        } else {
            return reject(format!(
                "{whose}: farkas {i} does not prove that the kinematic LP is infeasible"
            ));
        }
    }
    Ok(choices.iter().all(|dropped| {
        proved
            .iter()
            .any(|f| f.drop.iter().all(|d| dropped.contains(d)))
    }))
}

/// The choices of one sliding sense per section of a pattern whose contacts have the keys
/// (angle, kind, section), each as the indices of the contacts left out (one choice, none
/// left out, where no section lists both senses); `None` beyond 8 such sections.
pub(crate) fn one_sense_choices<S: PartialEq>(
    keys: &[(f64, ContactKind, S)],
) -> Option<Vec<Vec<usize>>> {
    // sections with both senses: (index of S+, index of S−)
    let both: Vec<(usize, usize)> = (0..keys.len())
        .filter(|&i| keys[i].1 == ContactKind::SlidePlus)
        .filter_map(|i| {
            (0..keys.len())
                .find(|&k| {
                    keys[k].1 == ContactKind::SlideMinus
                        && keys[k].0 == keys[i].0
                        && keys[k].2 == keys[i].2
                })
                .map(|k| (i, k))
        })
        .collect();
    if both.len() > 8 {
        return None;
    }
    let choice = |c: usize| -> Vec<usize> {
        both.iter()
            .enumerate()
            .map(|(b, &(p, m))| if c >> b & 1 == 0 { m } else { p })
            .collect()
    };
    Some((0..1usize << both.len()).map(choice).collect())
}

/// The compatibility column of a contact at η (formulation §4), in intervals.
pub(super) fn column(kind: ContactKind, beta: f64, eta: f64) -> [I; 3] {
    column_over(kind, beta, I::point(eta))
}

/// The compatibility column of a contact over an interval of η.
pub(super) fn column_over(kind: ContactKind, beta: f64, eta: I) -> [I; 3] {
    let b = I::point(beta);
    let (s, c) = (b.sin(), b.cos());
    let half = I::point(0.5) * eta;
    let (re, ri) = (I::point(1.0) + half, I::point(1.0) - half);
    let (one, zero) = (I::point(1.0), I::point(0.0));
    match kind {
        ContactKind::HingeExtrados => [-(re * s), re * c, -one],
        ContactKind::HingeIntrados => [ri * s, -(ri * c), one],
        ContactKind::SlidePlus => [c, s, zero],
        ContactKind::SlideMinus => [-c, -s, zero],
    }
}

/// `c_j · y + z + u p_j` proved ≤ 0 in intervals for every kept contact, with z > 0
/// and u ≥ 0. The external power p_j of a contact: minus the work of the weight of the
/// blocks beyond it (between consecutive distinct kept joints) in its unit motion,
/// p_j = −Σ_m [W_m c_j,y + ρ (sin β_{m+1} − sin β_m) c_j,ψ], W_m = β_{m+1} − β_m.
/// Under a live load at λ the power is the total one, P_j = p_j + λ q_j, and the live
/// power q_j ([`super::live::Live::power`]) enters again with its own multiplier v ≥ 0:
/// `c_j · y + z + u P_j + v q_j ≤ 0`.
pub(super) fn prove_farkas(
    model: &Model,
    state: StateAt,
    pattern: &[(f64, ContactKind, Option<Side>)],
    f: &KinematicFarkas,
) -> bool {
    prove_farkas_over(model, (I::point(state.eta), state.load), pattern, f)
}

/// [`prove_farkas`] over an interval of η (the columns and the weight's work enclosed over
/// it): one proof for every state of a cell of the ridge.
pub(super) fn prove_farkas_over(
    model: &Model,
    (eta, load): (I, Option<(&super::live::Live, f64)>),
    pattern: &[(f64, ContactKind, Option<Side>)],
    f: &KinematicFarkas,
) -> bool {
    if !(f.z > 0.0
        && f.u >= 0.0
        && f.v >= 0.0
        && f.z.is_finite()
        && f.u.is_finite()
        && f.v.is_finite())
        || f.y.iter().any(|v| !v.is_finite())
    {
        return false;
    }
    let kept: Vec<(f64, ContactKind, Option<Side>)> = (0..pattern.len())
        .filter(|i| !f.drop.contains(i))
        .map(|i| pattern[i])
        .collect();
    let columns: Vec<[I; 3]> = kept
        .iter()
        .map(|&(beta, kind, _)| column_over(kind, beta, eta))
        .collect();
    let work = weight_work(model, eta, &kept, &columns);
    let live: Option<(Vec<I>, I)> = load.map(|(l, lambda)| {
        (
            l.power(model, &kept, &columns),
            I::point(f.u) * I::point(lambda) + I::point(f.v),
        )
    });
    let y = f.y.map(I::point);
    (0..kept.len()).all(|i| {
        let col = &columns[i];
        let mut value =
            col[0] * y[0] + col[1] * y[1] + col[2] * y[2] + I::point(f.z) - I::point(f.u) * work[i];
        if let Some((q, k)) = &live {
            value = value + *k * q[i];
        }
        value.hi <= 0.0
    })
}

/// The work of the weight in the unit motion of each contact of `kept` (with its
/// compatibility `columns`): Σ over the blocks after it (between consecutive distinct
/// kept angles) of W_m c_y + ρ (sin β_{m+1} − sin β_m) c_ψ, W_m = β_{m+1} − β_m, and with
/// fill of ΔF_m c_y + ΔS_m c_ψ (its resultant and first moment on the block); the
/// external power of the dead load is its negative, p_j.
pub(super) fn weight_work(
    model: &Model,
    eta: I,
    kept: &[(f64, ContactKind, Option<Side>)],
    columns: &[[I; 3]],
) -> Vec<I> {
    let mut angles: Vec<f64> = kept.iter().map(|&(b, _, _)| b).collect();
    angles.sort_by(f64::total_cmp);
    angles.dedup();
    let rho = model.rho_over(eta);
    // the fill's resultant and first moment on the free body [β_R, β]
    let fill = |beta: f64| {
        let f = model.fill.as_ref()?;
        let (f, s) = fill_jets(f, (model.beta_r, model.beta_l), I::point(beta), eta);
        Some((f[0], s[0]))
    };
    let blocks: Vec<(f64, I, I)> = angles
        .windows(2)
        .map(|w| {
            let (a, b) = (I::point(w[0]), I::point(w[1]));
            let (weight, moment) = (b - a, rho * (b.sin() - a.sin()));
            // without fill nothing is added: the same bounds as the ring's alone
            match (fill(w[0]), fill(w[1])) {
                (Some((fa, sa)), Some((fb, sb))) => (w[0], weight + (fb - fa), moment + (sb - sa)),
                _ => (w[0], weight, moment),
            }
        })
        .collect();
    kept.iter()
        .zip(columns)
        .map(|(&(beta, _, _), col)| {
            blocks
                .iter()
                .filter(|(start, _, _)| *start >= beta)
                .fold(I::point(0.0), |acc, &(_, w, wgx)| {
                    acc + w * col[1] + wgx * col[2]
                })
        })
        .collect()
}
