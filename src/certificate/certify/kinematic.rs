//! The Farkas alternatives of the kinematic LP for a state without a mechanism, in either
//! problem: one for the whole pattern, else one per choice of one sliding sense per section.

use super::loaded::{joint, sorted, Loaded};
use crate::arch::Arch;
use crate::certificate::format::{ContactKind, KinematicFarkas, PatternJoint, Side};
use crate::certificate::verify::one_sense_choices;
use crate::contact::Contact;
use crate::kinematics::{column, power};
use crate::load::LiveLoad;
use crate::lp;
use crate::settings::Settings;

/// The ratios a : b of the combined power rows a P + b q tried under a load, in turn.
const RATIOS: [(f64, f64); 7] = [
    (1.0, 0.0),
    (0.0, 1.0),
    (1.0, 1.0),
    (1.0, 0.1),
    (0.1, 1.0),
    (1.0, 0.01),
    (0.01, 1.0),
];

/// A state without a mechanism at thickness η (under `load` at λ): its `pattern` in the
/// certificate's order, and the Farkas alternatives of the kinematic LP for every
/// one-sense choice, max z with c_j·y + z + u P_j + v q_j ≤ 0 — P the total external power
/// (the weight's alone without a load, and then v = 0), q the live power — tried under a
/// load with the power rows combined as a P + b q (u = a w, v = b w) for a few ratios;
/// z is halved to leave the verifier room for rounding. Those that cannot be found are
/// left out (the verifier then reports the state as not proved).
pub(super) fn no_mechanism(
    arch: &Arch,
    eta: f64,
    load: Option<(&LiveLoad, f64)>,
    pattern: Vec<Loaded>,
    settings: &Settings,
) -> (Vec<PatternJoint>, Vec<KinematicFarkas>) {
    let pattern = sorted(pattern);
    let keys: Vec<(f64, ContactKind, Side)> =
        pattern.iter().map(|(c, s)| (c.beta, c.kind, *s)).collect();
    let ratios = if load.is_some() {
        &RATIOS[..]
    } else {
        &RATIOS[..1]
    };
    let farkas = farkas_cover(&keys, |drop: Vec<usize>| {
        let kept: Vec<Loaded> = (0..pattern.len())
            .filter(|i| !drop.contains(i))
            .map(|i| pattern[i])
            .collect();
        let plain: Vec<Contact> = kept.iter().map(|p| p.0).collect();
        let cols: Vec<[f64; 3]> = plain.iter().map(|c| column(c.kind, c.beta, eta)).collect();
        let dead = power(arch, eta, &plain);
        let live = load.map(|(load, lambda)| {
            let q = load.power(arch, eta, &kept);
            let total: Vec<f64> = dead.iter().zip(&q).map(|(d, l)| d + lambda * l).collect();
            (total, q)
        });
        ratios.iter().find_map(|&(a, b)| {
            let p: Vec<f64> = match &live {
                Some((total, q)) => total.iter().zip(q).map(|(t, l)| a * t + b * l).collect(),
                None => dead.clone(),
            };
            let (y, z, u) = lp::kinematic_farkas(&cols, &p, settings).ok()?;
            (z > 0.0).then_some(KinematicFarkas {
                drop: drop.clone(),
                y,
                z: 0.5 * z,
                u: (a * u).max(0.0),
                v: (b * u).max(0.0),
            })
        })
    });
    let load = load.map(|(load, _)| load);
    (pattern.iter().map(|&l| joint(load, l)).collect(), farkas)
}

/// Farkas certificates for every one-sense choice of a pattern whose contacts have the
/// keys (angle, kind, section): first `one` on the whole pattern, else on each choice of
/// one sliding sense per section where both are listed (indices of the left-out contacts).
fn farkas_cover<S: PartialEq>(
    keys: &[(f64, ContactKind, S)],
    one: impl Fn(Vec<usize>) -> Option<KinematicFarkas>,
) -> Vec<KinematicFarkas> {
    if let Some(f) = one(Vec::new()) {
        return vec![f];
    }
    match one_sense_choices(keys) {
        Some(choices) if choices.len() > 1 => choices.into_iter().filter_map(one).collect(),
        _ => Vec::new(),
    }
}
