//! Lines of thrust and of friction (formulation §3): the eccentricities
//! e_M = M/N (where the resultant cuts the joint, measured outward from the centreline)
//! and e_T = (T/N)/μ · η/2 (the friction demand scaled so that sliding occurs at ±η/2),
//! sampled along the arch for a state x. Plain numerics for the pictures.

use crate::arch::{Arch, JointLayout, Radians};
use crate::load::{LiveLoad, Side};
use crate::state::State;
use crate::statics::{internal_forces, Reactions};

/// Eccentricities at one joint.
#[derive(Debug, Clone, Copy)]
pub struct Eccentricity {
    /// Joint angle.
    pub beta: Radians,
    /// N (compression positive).
    pub n: f64,
    /// e_M = M/N (NaN where N = 0).
    pub e_m: f64,
    /// e_T = (T/N)/μ · η/2 (0 at μ = ∞; NaN where N = 0).
    pub e_t: f64,
}

/// e_M and e_T at `samples + 1` equally spaced angles, plus the listed joints of a discrete
/// arch when there are at most `samples + 1` of them.
pub fn eccentricities(state: &State, samples: usize) -> Vec<Eccentricity> {
    eccentricities_under(state, None, samples)
}

/// [`eccentricities`] with a live load at multiplier λ added to N, T and M (the section
/// at the point load's own angle taken after it).
pub fn eccentricities_under(
    state: &State,
    live: Option<(&LiveLoad, f64)>,
    samples: usize,
) -> Vec<Eccentricity> {
    let (arch, eta, mu, x) = (state.arch, state.eta, state.mu, &state.x);
    let (a, b) = (arch.beta_right(), arch.beta_left());
    let mut betas: Vec<Radians> = (0..=samples)
        .map(|i| a + (b - a) * i as f64 / samples as f64)
        .collect();
    if let JointLayout::Discrete(j) = arch.layout() {
        if j.len() > samples + 1 {
            // more joints than samples: the dense sampling is already finer than a picture
            return sample(arch, eta, mu, x, live, betas);
        }
        betas.extend_from_slice(j);
        betas.sort_by(f64::total_cmp);
        betas.dedup();
    }
    sample(arch, eta, mu, x, live, betas)
}

fn sample(
    arch: &Arch,
    eta: f64,
    mu: f64,
    x: &Reactions,
    live: Option<(&LiveLoad, f64)>,
    betas: Vec<Radians>,
) -> Vec<Eccentricity> {
    betas
        .into_iter()
        .map(|beta| {
            let (mut n, mut t, mut m) = internal_forces(arch, eta, x, beta);
            if let Some((load, lambda)) = live {
                let [nl, tl, ml] = load.actions(arch, eta, beta, Side::After);
                n += lambda * nl;
                t += lambda * tl;
                m += lambda * ml;
            }
            let e_t = if mu.is_finite() {
                t / n / mu * eta / 2.0
            } else {
                0.0
            };
            Eccentricity {
                beta,
                n,
                e_m: m / n,
                e_t,
            }
        })
        .collect()
}
