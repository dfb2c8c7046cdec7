//! The collapse mechanism of a pattern (formulation §4–5): non-negative rates on the
//! pattern's contacts with B λ = 0, L_e ≥ 0, Σ λ = 1, found by the kinematic LP.
//!
//! Mechanisms are not unique: the cone {λ ≥ 0 : B λ = 0} of a 5-joint pattern has
//! dimension ≥ 2. We report its dimension, a representative in its relative interior
//! (the mean of the extreme rays found), and, for a mirror-symmetric pattern of a
//! symmetric arch, the symmetric representative; [`extreme_mechanisms`] lists every
//! extreme ray of the cone (the figures draw any one of them).

use crate::contact::{Contact, ContactKind};
use crate::kinematics::{column, compatibility_residual, mirror_indices, power};
use crate::load::{live_activation, LiveLoad, Side};
use crate::lp::{self, LpOutcome};
use crate::settings::Settings;
use crate::state::State;
use crate::statics::actions;
use itertools::Itertools;
use nalgebra::{DMatrix, DVector};

/// A kinematically admissible mechanism on a pattern.
#[derive(Debug, Clone)]
pub struct Mechanism {
    /// The contacts of the pattern, in order of increasing β.
    pub contacts: Vec<Contact>,
    /// The rate of each contact (same order), non-negative, summing to 1.
    pub rates: Vec<f64>,
    /// Dimension of the mechanism cone {λ ≥ 0 : B λ = 0} on the pattern.
    pub dof: usize,
    /// External power of self-weight L_e of these rates (≥ 0).
    pub power: f64,
    /// True when `rates` is mirror-symmetric (symmetric arch and pattern).
    pub symmetric: bool,
    /// ‖B λ‖∞: velocity left at the left springing (should be 0).
    pub compatibility: f64,
    /// Σ |φ_i| λ_i over the pattern at the static state (should be 0).
    pub complementarity: f64,
    /// μ Σ N_k (s⁺_k + s⁻_k): frictional dissipation, equal to L_e at a limit state.
    pub dissipation: f64,
}

/// Finds a mechanism on `contacts` (the active set of `state`), or `Ok(None)` when the
/// kinematic LP is infeasible.
///
/// A joint may slide one way only (s⁺ s⁻ = 0, formulation §4): where both sliding
/// contacts of a joint are active (a detached joint, N = 0), each sense is tried apart,
/// so that no "mechanism" is made of s⁺ and s⁻ cancelling each other.
pub fn find(
    state: &State,
    contacts: &[Contact],
    settings: &Settings,
) -> Result<Option<Mechanism>, LpOutcome> {
    let mut cs = contacts.to_vec();
    cs.sort_by(|a, b| a.beta.total_cmp(&b.beta).then(a.kind.cmp(&b.kind)));
    let same = |a: &Contact, b: &Contact| (a.beta - b.beta).abs() <= settings.same_joint;
    for keep in one_sense_choices(&cs, |c| *c, same) {
        if let Some(m) = find_one_sense(state, keep, settings)? {
            return Ok(Some(m));
        }
    }
    Ok(None)
}

/// Every way of keeping one sliding sense at each joint where both are listed (a joint
/// slides one way only, s⁺ s⁻ = 0): the sub-lists of `items`, whose contact is `contact(i)`,
/// and `same(a, b)` says whether two contacts are at one joint.
fn one_sense_choices<T: Copy>(
    items: &[T],
    contact: impl Fn(&T) -> Contact,
    same: impl Fn(&T, &T) -> bool,
) -> Vec<Vec<T>> {
    let both: Vec<T> = items
        .iter()
        .filter(|c| contact(c).kind == ContactKind::SlidePlus)
        .filter(|c| {
            items
                .iter()
                .any(|d| contact(d).kind == ContactKind::SlideMinus && same(d, c))
        })
        .copied()
        .collect();
    (0..(1usize << both.len()))
        .map(|choice| {
            items
                .iter()
                .copied()
                .filter(|c| {
                    let Some(k) = both.iter().position(|b| same(b, c)) else {
                        return true;
                    };
                    let plus = choice >> k & 1 == 0;
                    match contact(c).kind {
                        ContactKind::SlidePlus => plus,
                        ContactKind::SlideMinus => !plus,
                        _ => true,
                    }
                })
                .collect()
        })
        .collect()
}

/// [`find`] on contacts with at most one sliding sense per joint (sorted by β).
fn find_one_sense(
    state: &State,
    cs: Vec<Contact>,
    settings: &Settings,
) -> Result<Option<Mechanism>, LpOutcome> {
    let (arch, eta, mu, x) = (state.arch, state.eta, state.mu, &state.x);
    let n = cs.len();
    let cols: Vec<[f64; 3]> = cs.iter().map(|c| column(c.kind, c.beta, eta)).collect();
    let p = power(arch, eta, &cs);
    let lp = lp::Kinematic::new(&cols, &p, settings);
    let first = match lp.solve(&vec![0.0; n]) {
        Ok(l) => l,
        Err(LpOutcome::Infeasible) => return Ok(None),
        Err(e) => return Err(e),
    };
    let mut rays = vec![first];
    for i in 0..n {
        if rays.iter().any(|r| r[i] > settings.rate_tol) {
            continue;
        }
        let mut obj = vec![0.0; n];
        obj[i] = 1.0;
        let l = lp.solve(&obj)?;
        if l[i] > settings.rate_tol {
            rays.push(l);
        }
    }
    let mut rates = vec![0.0; n];
    for r in &rays {
        for i in 0..n {
            rates[i] += r[i] / rays.len() as f64;
        }
    }
    let support: Vec<usize> = (0..n).filter(|&i| rates[i] > settings.rate_tol).collect();
    let b = DMatrix::from_fn(3, support.len(), |r, c| cols[support[c]][r]);
    let rank = if support.is_empty() {
        0
    } else {
        b.rank(settings.rank_tol)
    };
    let dof = support.len() - rank;

    let mut symmetric = false;
    if arch.is_symmetric() {
        if let Some(mirror) = mirror_indices(&cs, settings.same_joint) {
            let sym: Vec<f64> = (0..n)
                .map(|i| 0.5 * (rates[i] + rates[mirror[i]]))
                .collect();
            rates = sym;
            symmetric = true;
        }
    }
    let total: f64 = rates.iter().sum();
    rates.iter_mut().for_each(|r| *r /= total);
    // Rates that are zero up to the LP tolerance are reported as exactly zero.
    rates.iter_mut().for_each(|r| {
        if *r <= settings.rate_tol {
            *r = 0.0
        }
    });

    let residual = compatibility_residual(eta, &cs, &rates);
    let compatibility = residual.iter().fold(0.0f64, |m, v| m.max(v.abs()));
    let power_value: f64 = p.iter().zip(&rates).map(|(a, b)| a * b).sum();
    let mut complementarity = 0.0;
    let mut dissipation = 0.0;
    for (c, &l) in cs.iter().zip(&rates) {
        let a = actions(arch, eta, c.beta);
        complementarity += a.activation(c.kind, 0, eta, mu).at(x).abs() * l;
        if !c.kind.is_hinge() {
            dissipation += mu * a.n[0].at(x) * l;
        }
    }
    Ok(Some(Mechanism {
        contacts: cs,
        rates,
        dof,
        power: power_value,
        symmetric,
        compatibility,
        complementarity,
        dissipation,
    }))
}

/// A collapse mechanism under a live load at multiplier λ: non-negative rates
/// on `contacts` (each with the side of the loaded section it belongs to) with B λ̇ = 0,
/// Σ λ̇ = 1, total external power L_dead + λ L_live ≥ 0 and **positive live power**
/// L_live > 0 (the load drives the mechanism; one with L_live ≤ 0 is no collapse under
/// this load). The LP maximises L_live; a joint slides one way only, as in [`find`].
/// Returns the mechanism (its `power` is the total external power) and its live power.
pub fn find_under_load(
    state: &State,
    lambda: f64,
    load: &LiveLoad,
    contacts: &[(Contact, Side)],
    settings: &Settings,
) -> Result<Option<(Mechanism, f64)>, LpOutcome> {
    let (arch, eta, mu, x) = (state.arch, state.eta, state.mu, &state.x);
    let mut cs = contacts.to_vec();
    cs.sort_by(|a, b| {
        a.0.beta
            .total_cmp(&b.0.beta)
            .then((a.1 == Side::After).cmp(&(b.1 == Side::After)))
            .then(a.0.kind.cmp(&b.0.kind))
    });
    let mut best: Option<(Mechanism, f64)> = None;
    let same = |a: &(Contact, Side), b: &(Contact, Side)| a.0.beta == b.0.beta && a.1 == b.1;
    for keep in one_sense_choices(&cs, |c| c.0, same) {
        let plain: Vec<Contact> = keep.iter().map(|(c, _)| *c).collect();
        let cols: Vec<[f64; 3]> = plain.iter().map(|c| column(c.kind, c.beta, eta)).collect();
        let dead = power(arch, eta, &plain);
        let live = load.power(arch, eta, &keep);
        let total: Vec<f64> = dead
            .iter()
            .zip(&live)
            .map(|(d, l)| d + lambda * l)
            .collect();
        let rates = match lp::kinematic(&cols, &total, &live, settings) {
            Ok(r) => r,
            Err(LpOutcome::Infeasible) => continue,
            Err(e) => return Err(e),
        };
        let live_power: f64 = live.iter().zip(&rates).map(|(a, b)| a * b).sum();
        if live_power <= settings.rate_tol {
            continue;
        }
        let sum: f64 = rates.iter().sum();
        let rates: Vec<f64> = rates
            .iter()
            .map(|r| {
                if *r / sum <= settings.rate_tol {
                    0.0
                } else {
                    r / sum
                }
            })
            .collect();
        let live_power: f64 = live.iter().zip(&rates).map(|(a, b)| a * b).sum();
        let support: Vec<usize> = (0..rates.len()).filter(|&i| rates[i] > 0.0).collect();
        let b = DMatrix::from_fn(3, support.len(), |r, c| cols[support[c]][r]);
        let dof = support.len()
            - if support.is_empty() {
                0
            } else {
                b.rank(settings.rank_tol)
            };
        let residual = compatibility_residual(eta, &plain, &rates);
        let (mut complementarity, mut dissipation) = (0.0, 0.0);
        for ((c, side), &r) in keep.iter().zip(&rates) {
            let a = actions(arch, eta, c.beta);
            let la = load.actions(arch, eta, c.beta, *side);
            let phi = a.activation(c.kind, 0, eta, mu).at(x)
                + lambda * live_activation(c.kind, eta, mu, la);
            complementarity += phi.abs() * r;
            if !c.kind.is_hinge() {
                dissipation += mu * (a.n[0].at(x) + lambda * la[0]) * r;
            }
        }
        let m = Mechanism {
            contacts: plain,
            power: total.iter().zip(&rates).map(|(a, b)| a * b).sum(),
            rates,
            dof,
            symmetric: false,
            compatibility: residual.iter().fold(0.0f64, |m, v| m.max(v.abs())),
            complementarity,
            dissipation,
        };
        if best.as_ref().is_none_or(|(_, l)| live_power > *l) {
            best = Some((m, live_power));
        }
    }
    Ok(best)
}

/// Supports of at most this many contacts are tried for a vertex: four equations
/// (B λ = 0, Σ λ = 1), and a fifth (L_e = 0) on the face where the power vanishes.
const VERTEX_SUPPORT: usize = 5;

/// Every extreme mechanism on `m`'s contacts: the vertices of
/// {λ ≥ 0 : B λ = 0, Σ λ = 1, L_e(λ) ≥ 0} (the kinematic LP's feasible set at thickness
/// `eta`), each as rates on `m.contacts`, in the order of their supports. A vertex has a
/// support of at most four contacts whose equations fix it, or five with L_e = 0; every
/// such support is tried (a pattern has at most a few contacts).
pub fn extreme_mechanisms(
    arch: &crate::arch::Arch,
    eta: f64,
    m: &Mechanism,
    settings: &Settings,
) -> Vec<Vec<f64>> {
    let cs = &m.contacts;
    let n = cs.len();
    let cols: Vec<[f64; 3]> = cs.iter().map(|c| column(c.kind, c.beta, eta)).collect();
    let p = power(arch, eta, cs);
    let scale = p.iter().fold(1.0_f64, |a, v| a.max(v.abs()));
    let mut found: Vec<Vec<f64>> = Vec::new();
    for size in 1..=n.min(VERTEX_SUPPORT) {
        for support in (0..n).combinations(size) {
            let rows = if size == VERTEX_SUPPORT { 5 } else { 4 };
            let a = DMatrix::from_fn(rows, size, |r, c| match r {
                0..=2 => cols[support[c]][r],
                3 => 1.0,
                _ => p[support[c]] / scale,
            });
            let mut rhs = DVector::zeros(rows);
            rhs[3] = 1.0;
            let svd = a.clone().svd(true, true);
            if svd.rank(settings.rank_tol) < size {
                continue;
            }
            let Ok(sol) = svd.solve(&rhs, settings.rank_tol) else {
                continue;
            };
            let fits = (&a * &sol - &rhs).amax() <= settings.rate_tol;
            if !fits || sol.iter().any(|&v| v <= settings.rate_tol) {
                continue;
            }
            let mut rates = vec![0.0; n];
            for (c, &i) in support.iter().enumerate() {
                rates[i] = sol[c];
            }
            let power: f64 = p.iter().zip(&rates).map(|(a, b)| a * b).sum();
            let same = |f: &Vec<f64>| {
                f.iter()
                    .zip(&rates)
                    .all(|(a, b)| (a - b).abs() <= settings.rate_tol.sqrt())
            };
            if power >= -settings.rate_tol * scale && !found.iter().any(same) {
                found.push(rates);
            }
        }
    }
    found
}
