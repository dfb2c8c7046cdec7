//! Exact refinement of a pattern (formulation §5): Newton on the pattern's system
//!
//!   φ_i(β_i; x, η) = 0            for every contact i,
//!   dφ_i/dβ(β_i; x, η) = 0        for every free (interior, continuous) contact,
//!
//! in the unknowns z = (h, v, w, η, free β_i), with the exact derivatives of
//! [`crate::statics`]. Square systems are solved exactly; an over-determined but
//! consistent system (symmetry) by Gauss–Newton, which keeps quadratic convergence
//! at a zero residual. Linear steps use an SVD with column equilibration.

use crate::arch::Arch;
use crate::contact::Contact;
use crate::settings::Settings;
use crate::statics::{actions, Reactions};
use nalgebra::{DMatrix, DVector};

/// A converged solution of a pattern's system.
#[derive(Debug, Clone)]
pub struct Refined {
    /// Reactions x.
    pub x: Reactions,
    /// Thickness ratio η.
    pub eta: f64,
    /// The contacts with their refined angles.
    pub contacts: Vec<Contact>,
    /// Final residual ‖F‖∞, scaled by 1 + ‖x‖₁.
    pub residual: f64,
    /// Newton iterations used.
    pub iterations: usize,
}

/// Why Newton did not converge.
#[derive(Debug, Clone, PartialEq)]
pub enum NewtonFailure {
    /// Fewer equations than unknowns: the pattern does not fix the state.
    Underdetermined,
    /// The iterate left the domain (η ∉ (0, 2) or a joint outside the arch).
    LeftDomain,
    /// No convergence within the iteration limit (residual reached).
    NoConvergence(f64),
}

fn residual(arch: &Arch, mu: f64, contacts: &[Contact], x: &Reactions, eta: f64) -> Vec<f64> {
    let mut f = Vec::with_capacity(2 * contacts.len());
    for c in contacts {
        let a = actions(arch, eta, c.beta);
        f.push(a.activation(c.mode, 0, eta, mu).at(x));
        if c.free {
            f.push(a.activation(c.mode, 1, eta, mu).at(x));
        }
    }
    f
}

fn scale_of(x: &Reactions) -> f64 {
    1.0 + x.iter().map(|v| v.abs()).sum::<f64>()
}

/// Solves the system of `contacts` at friction `mu` from the starting point (x0, η0).
pub fn solve_pattern(
    arch: &Arch,
    mu: f64,
    contacts: &[Contact],
    x0: Reactions,
    eta0: f64,
    settings: &Settings,
) -> Result<Refined, NewtonFailure> {
    let free: Vec<usize> = (0..contacts.len()).filter(|&i| contacts[i].free).collect();
    let n_unknowns = 4 + free.len();
    let n_eq = contacts.len() + free.len();
    if n_eq < n_unknowns {
        return Err(NewtonFailure::Underdetermined);
    }
    let (lo, hi) = (arch.beta_right(), arch.beta_left());
    let mut cs = contacts.to_vec();
    let mut x = x0;
    let mut eta = eta0;
    let mut f = residual(arch, mu, &cs, &x, eta);
    let norm = |f: &[f64]| f.iter().fold(0.0f64, |m, v| m.max(v.abs()));
    let mut fnorm = norm(&f) / scale_of(&x);
    for iter in 0..settings.newton_max_iter {
        if fnorm <= settings.newton_tol {
            return Ok(Refined { x, eta, contacts: cs, residual: fnorm, iterations: iter });
        }
        // Jacobian.
        let mut jac = DMatrix::<f64>::zeros(n_eq, n_unknowns);
        let mut row = 0;
        let mut col_beta = 4;
        for c in &cs {
            let a = actions(arch, eta, c.beta);
            let f0 = a.activation(c.mode, 0, eta, mu);
            let f1 = a.activation(c.mode, 1, eta, mu);
            for k in 0..3 {
                jac[(row, k)] = f0.g[k];
            }
            jac[(row, 3)] = a.activation_d_eta(c.mode, 0, &x);
            if c.free {
                jac[(row, col_beta)] = f1.at(&x);
                let f2 = a.activation(c.mode, 2, eta, mu);
                for k in 0..3 {
                    jac[(row + 1, k)] = f1.g[k];
                }
                jac[(row + 1, 3)] = a.activation_d_eta(c.mode, 1, &x);
                jac[(row + 1, col_beta)] = f2.at(&x);
                row += 2;
                col_beta += 1;
            } else {
                row += 1;
            }
        }
        // Column equilibration, then least-squares step by SVD.
        let mut colscale = vec![1.0; n_unknowns];
        for j in 0..n_unknowns {
            let s = jac.column(j).norm();
            if s > 0.0 {
                colscale[j] = 1.0 / s;
                jac.column_mut(j).scale_mut(1.0 / s);
            }
        }
        let rhs = DVector::from_iterator(n_eq, f.iter().map(|v| -v));
        let svd = jac.svd(true, true);
        let smax = svd.singular_values.max();
        let step = match svd.solve(&rhs, smax * 1e-13) {
            Ok(s) => s,
            Err(_) => return Err(NewtonFailure::NoConvergence(fnorm)),
        };
        // Damped update: accept the first step length that reduces the residual.
        let mut t = 1.0;
        let mut accepted = false;
        for _ in 0..30 {
            let mut xn = x;
            for k in 0..3 {
                xn[k] += t * step[k] * colscale[k];
            }
            let etan = eta + t * step[3] * colscale[3];
            let mut csn = cs.clone();
            for (j, &i) in free.iter().enumerate() {
                csn[i].beta += t * step[4 + j] * colscale[4 + j];
            }
            let inside = etan > 0.0
                && etan < 2.0
                && csn.iter().all(|c| c.beta > lo && c.beta < hi || !c.free);
            if inside {
                let fn_ = residual(arch, mu, &csn, &xn, etan);
                let nn = norm(&fn_) / scale_of(&xn);
                if nn < fnorm || nn <= settings.newton_tol {
                    x = xn;
                    eta = etan;
                    cs = csn;
                    f = fn_;
                    fnorm = nn;
                    accepted = true;
                    break;
                }
            }
            t *= 0.5;
        }
        if !accepted {
            if fnorm <= 1e3 * settings.newton_tol {
                return Ok(Refined { x, eta, contacts: cs, residual: fnorm, iterations: iter });
            }
            let any_outside = !(eta > 0.0 && eta < 2.0);
            return Err(if any_outside {
                NewtonFailure::LeftDomain
            } else {
                NewtonFailure::NoConvergence(fnorm)
            });
        }
    }
    if fnorm <= settings.newton_tol * 1e3 {
        Ok(Refined { x, eta, contacts: cs, residual: fnorm, iterations: settings.newton_max_iter })
    } else {
        Err(NewtonFailure::NoConvergence(fnorm))
    }
}
