//! Exact refinement of a pattern (formulation §5): Newton on the pattern's system
//!
//!   φ_i(β_i; x, η) = 0            for every contact i,
//!   dφ_i/dβ(β_i; x, η) = 0        for every free (interior, continuous) contact,
//!
//! in the unknowns z = (h, v, w, η, free β_i), with the exact derivatives of
//! [`crate::statics`].
//!
//! With four or more contacts this fixes the state (a vertex; an over-determined but
//! consistent system, as symmetry gives, is solved by Gauss–Newton, which keeps
//! quadratic convergence at a zero residual). With fewer, the continuum's curvature
//! matters: the least η sits where the envelope of the active tangencies is
//! stationary, and the system is completed by the optimality (KKT) conditions of
//! min η subject to φ_i ≤ 0 with multipliers y_i:
//!
//!   Σ y_i ∇ₓφ_i = 0,   1 + Σ y_i ∂φ_i/∂η = 0,
//!
//! which are square again (unknowns y_i added). Linear steps use an SVD with column
//! equilibration (minimum-norm steps where the Jacobian is rank-deficient).

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
    /// KKT multipliers of the contacts when the optimality conditions were used
    /// (fewer than four contacts), else empty.
    pub multipliers: Vec<f64>,
    /// Final residual ‖F‖∞, scaled by 1 + ‖x‖₁.
    pub residual: f64,
    /// Newton iterations used.
    pub iterations: usize,
}

/// Why Newton did not converge.
#[derive(Debug, Clone, PartialEq)]
pub enum NewtonFailure {
    /// The pattern is empty.
    Empty,
    /// The iterate left the domain (η ∉ (0, 2) or a joint outside the arch).
    LeftDomain,
    /// No convergence within the iteration limit (residual reached).
    NoConvergence(f64),
    /// Converged, but a KKT multiplier is negative: not a least thickness.
    NegativeMultiplier,
}

/// The unknowns, flattened: x (3), η, free β (k), then y (m) in KKT form.
struct System<'a> {
    arch: &'a Arch,
    mu: f64,
    contacts: Vec<Contact>,
    free: Vec<usize>,
    kkt: bool,
}

impl System<'_> {
    fn n_unknowns(&self) -> usize {
        4 + self.free.len() + if self.kkt { self.contacts.len() } else { 0 }
    }

    fn unpack(&self, z: &[f64]) -> (Reactions, f64, Vec<Contact>) {
        let mut cs = self.contacts.clone();
        for (j, &i) in self.free.iter().enumerate() {
            cs[i].beta = z[4 + j];
        }
        ([z[0], z[1], z[2]], z[3], cs)
    }

    fn multipliers<'z>(&self, z: &'z [f64]) -> &'z [f64] {
        &z[4 + self.free.len()..]
    }

    /// Residual F(z) and, when `jac` is given, its Jacobian.
    fn eval(&self, z: &[f64], mut jac: Option<&mut DMatrix<f64>>) -> Vec<f64> {
        let (x, eta, cs) = self.unpack(z);
        let mu = self.mu;
        let y = if self.kkt {
            self.multipliers(z)
        } else {
            &[][..]
        };
        let col_y = 4 + self.free.len();
        let mut f = Vec::new();
        let mut stat = [0.0; 3];
        let mut norm_eq = 1.0;
        let mut col_beta = 4;
        let n_rows = cs.len() + self.free.len();
        for (i, c) in cs.iter().enumerate() {
            let a = actions(self.arch, eta, c.beta);
            let f0 = a.activation(c.mode, 0, eta, mu);
            let f1 = a.activation(c.mode, 1, eta, mu);
            let row = f.len();
            f.push(f0.at(&x));
            if c.free {
                f.push(f1.at(&x));
            }
            // ∂(∇ₓφ)/∂η: −½∇ₓN for hinges, 0 for sliding.
            let dg_deta = |order: usize| -> [f64; 3] {
                if c.mode.is_hinge() {
                    a.n[order].g.map(|v| -0.5 * v)
                } else {
                    [0.0; 3]
                }
            };
            let d_eta0 = a.activation_d_eta(c.mode, 0, &x);
            if self.kkt {
                for (st, g) in stat.iter_mut().zip(f0.g) {
                    *st += y[i] * g;
                }
                norm_eq += y[i] * d_eta0;
            }
            if let Some(j) = jac.as_deref_mut() {
                for k in 0..3 {
                    j[(row, k)] = f0.g[k];
                }
                j[(row, 3)] = d_eta0;
                if c.free {
                    let f2 = a.activation(c.mode, 2, eta, mu);
                    j[(row, col_beta)] = f1.at(&x);
                    for k in 0..3 {
                        j[(row + 1, k)] = f1.g[k];
                    }
                    j[(row + 1, 3)] = a.activation_d_eta(c.mode, 1, &x);
                    j[(row + 1, col_beta)] = f2.at(&x);
                }
                if self.kkt {
                    let (ds, dn) = (n_rows, n_rows + 3);
                    let g_eta = dg_deta(0);
                    for k in 0..3 {
                        // stationarity rows
                        j[(ds + k, 3)] += y[i] * g_eta[k];
                        j[(ds + k, col_y + i)] = f0.g[k];
                        if c.free {
                            j[(ds + k, col_beta)] += y[i] * f1.g[k];
                        }
                        // normalisation row, ∂/∂x
                        j[(dn, k)] += y[i] * g_eta[k];
                    }
                    let d2 = self.arch.weight().d2rho_deta2(eta)
                        * -(c.beta.sin() - self.arch.beta_right().sin());
                    let d2 = match c.mode {
                        crate::statics::JointMode::HingeExtrados => d2,
                        crate::statics::JointMode::HingeIntrados => -d2,
                        _ => 0.0,
                    };
                    j[(dn, 3)] += y[i] * d2;
                    if c.free {
                        j[(dn, col_beta)] += y[i] * a.activation_d_eta(c.mode, 1, &x);
                    }
                    j[(dn, col_y + i)] = d_eta0;
                }
            }
            if c.free {
                col_beta += 1;
            }
        }
        if self.kkt {
            f.extend_from_slice(&stat);
            f.push(norm_eq);
        }
        f
    }
}

fn scale_of(x: &[f64]) -> f64 {
    1.0 + x[..3].iter().map(|v| v.abs()).sum::<f64>()
}

fn inf_norm(f: &[f64]) -> f64 {
    f.iter().fold(0.0f64, |m, v| m.max(v.abs()))
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
    if contacts.is_empty() {
        return Err(NewtonFailure::Empty);
    }
    let free: Vec<usize> = (0..contacts.len()).filter(|&i| contacts[i].free).collect();
    let kkt = contacts.len() < 4;
    let sys = System {
        arch,
        mu,
        contacts: contacts.to_vec(),
        free,
        kkt,
    };
    let mut z: Vec<f64> = x0.to_vec();
    z.push(eta0);
    z.extend(sys.free.iter().map(|&i| contacts[i].beta));
    if kkt {
        z.extend(initial_multipliers(arch, mu, contacts, &x0, eta0));
    }
    let (z, fnorm, iterations) = newton(&sys, z, settings)?;
    // Restart once from the solution rounded to 9 significant digits: the LP's
    // starting point differs in its last bits from run to run (good_lp builds rows
    // from hash maps), and this makes the converged digits a function of the input.
    let snapped: Vec<f64> = z.iter().map(|&v| round_sig(v, 9)).collect();
    let (z, fnorm, iterations) = match newton(&sys, snapped, settings) {
        Ok((zs, fs, is)) => (zs, fs, iterations + is),
        Err(_) => (z, fnorm, iterations),
    };
    let (x, eta, cs) = sys.unpack(&z);
    let multipliers = if kkt {
        sys.multipliers(&z).to_vec()
    } else {
        Vec::new()
    };
    if multipliers.iter().any(|&y| y < 0.0) {
        return Err(NewtonFailure::NegativeMultiplier);
    }
    Ok(Refined {
        x,
        eta,
        contacts: cs,
        multipliers,
        residual: fnorm,
        iterations,
    })
}

/// Damped Gauss–Newton from `z0`; returns the solution, its scaled residual and the
/// iterations used.
fn newton(
    sys: &System,
    z0: Vec<f64>,
    settings: &Settings,
) -> Result<(Vec<f64>, f64, usize), NewtonFailure> {
    let arch = sys.arch;
    let contacts = &sys.contacts;
    let kkt = sys.kkt;
    let (lo, hi) = (arch.beta_right(), arch.beta_left());
    let n = sys.n_unknowns();
    let n_eq = contacts.len() + sys.free.len() + if kkt { 4 } else { 0 };
    let mut z = z0;
    let mut f = sys.eval(&z, None);
    let mut fnorm = inf_norm(&f) / scale_of(&z);
    let mut iterations = 0;
    let converged = loop {
        if fnorm <= settings.newton_tol {
            break true;
        }
        if iterations >= settings.newton_max_iter {
            break fnorm <= 1e3 * settings.newton_tol;
        }
        iterations += 1;
        let mut jac = DMatrix::<f64>::zeros(n_eq, n);
        sys.eval(&z, Some(&mut jac));
        let mut colscale = vec![1.0; n];
        for (j, cs) in colscale.iter_mut().enumerate() {
            let s = jac.column(j).norm();
            if s > 0.0 {
                *cs = 1.0 / s;
                jac.column_mut(j).scale_mut(1.0 / s);
            }
        }
        let rhs = DVector::from_iterator(n_eq, f.iter().map(|v| -v));
        let svd = jac.svd(true, true);
        let smax = svd.singular_values.max();
        let Ok(step) = svd.solve(&rhs, smax * 1e-13) else {
            return Err(NewtonFailure::NoConvergence(fnorm));
        };
        // Damped update: the first step length that reduces the residual.
        let mut t = 1.0;
        let mut accepted = false;
        for _ in 0..30 {
            let zn: Vec<f64> = z
                .iter()
                .enumerate()
                .map(|(j, v)| v + t * step[j] * colscale[j])
                .collect();
            let inside = zn[3] > 0.0
                && zn[3] < 2.0
                && zn[4..4 + sys.free.len()].iter().all(|&b| b > lo && b < hi);
            if inside {
                let fnew = sys.eval(&zn, None);
                let nn = inf_norm(&fnew) / scale_of(&zn);
                if nn < fnorm {
                    z = zn;
                    f = fnew;
                    fnorm = nn;
                    accepted = true;
                    break;
                }
            }
            t *= 0.5;
        }
        if !accepted {
            // Stagnation at the rounding level counts as convergence.
            if fnorm <= 1e3 * settings.newton_tol {
                break true;
            }
            let out = !(z[3] > 0.0 && z[3] < 2.0);
            return Err(if out {
                NewtonFailure::LeftDomain
            } else {
                NewtonFailure::NoConvergence(fnorm)
            });
        }
    };
    if converged {
        Ok((z, fnorm, iterations))
    } else {
        Err(NewtonFailure::NoConvergence(fnorm))
    }
}

/// `v` rounded to `digits` significant decimal digits.
fn round_sig(v: f64, digits: i32) -> f64 {
    if v == 0.0 || !v.is_finite() {
        return v;
    }
    let e = digits - 1 - v.abs().log10().floor() as i32;
    let p = 10f64.powi(e);
    (v * p).round() / p
}

/// Least-squares multipliers of [∇ₓφ_i; ∂φ_i/∂η] y = [0; −1] at the starting point.
fn initial_multipliers(
    arch: &Arch,
    mu: f64,
    contacts: &[Contact],
    x: &Reactions,
    eta: f64,
) -> Vec<f64> {
    let m = contacts.len();
    let a = DMatrix::from_fn(4, m, |r, i| {
        let act = actions(arch, eta, contacts[i].beta);
        if r < 3 {
            act.activation(contacts[i].mode, 0, eta, mu).g[r]
        } else {
            act.activation_d_eta(contacts[i].mode, 0, x)
        }
    });
    let b = DVector::from_vec(vec![0.0, 0.0, 0.0, -1.0]);
    let svd = a.svd(true, true);
    let tol = svd.singular_values.max() * 1e-12;
    svd.solve(&b, tol)
        .map(|y| y.iter().copied().collect())
        .unwrap_or_else(|_| vec![1.0; m])
}
