//! Exact refinement of a pattern (formulation §5): Newton on the pattern's system
//!
//!   φ_i(β_i; x, t, μ) = 0          for every contact i,
//!   dφ_i/dβ(β_i; x, t, μ) = 0      for every free (interior, continuous) contact,
//!
//! in the unknowns z = (h, v, w, the unknown parameters, free β_i), with the exact
//! derivatives of the rows of a problem [`Family`] (the thickness family: t = η; a load:
//! t = λ). This is the one Newton of the crate: every family calls it.
//!
//! With as many contacts as unknowns (less the free angles) this fixes the state (a
//! vertex; an over-determined but consistent system, as symmetry gives, is solved by
//! Gauss–Newton, which keeps quadratic convergence at a zero residual). With fewer, the
//! continuum's curvature matters: the optimum sits where the envelope of the active
//! tangencies is stationary, and the system is completed by the optimality (KKT)
//! conditions of min t (or max t) subject to φ_i ≤ 0 with multipliers y_i:
//!
//!   Σ y_i ∇ₓφ_i = 0,   Σ y_i ∂φ_i/∂t = ∓1,
//!
//! which are square again (unknowns y_i added). Linear steps use an SVD with column
//! equilibration (minimum-norm steps where the Jacobian is rank-deficient).

use crate::arch::Arch;
use crate::contact::Contact;
use crate::family::{Family, Param, Rows, Tagged, Thickness};
use crate::settings::Settings;
use crate::state::State;
use crate::statics::Reactions;
use nalgebra::{DMatrix, DVector};

/// Which parameters are unknowns of a system.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Unknowns {
    /// The family's parameter t at fixed μ (η of the thickness problem, λ of a load).
    T,
    /// The friction-only problem (sliding contacts only): unknown μ; its rows do not
    /// contain w, so three contacts fix it.
    Mu,
    /// A corner: both t and μ unknown (no KKT completion; the union of two patterns
    /// determines the state).
    TMu,
}

/// What the KKT completion of an under-determined system optimises: its one unknown
/// parameter, least or largest.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Objective {
    /// The least value (η_s, μ_ms, λ_min).
    Least,
    /// The largest value (λ_static).
    Largest,
}

impl Objective {
    /// Σ y_i ∂φ_i/∂p = `sign` at the optimum.
    fn sign(self) -> f64 {
        match self {
            Objective::Least => -1.0,
            Objective::Largest => 1.0,
        }
    }
}

/// A converged solution of a pattern's system.
#[derive(Debug, Clone)]
pub struct Refined<T = ()> {
    /// Reactions x.
    pub x: Reactions,
    /// The family's parameter t (η for the thickness family).
    pub t: f64,
    /// Friction coefficient μ.
    pub mu: f64,
    /// The contacts with their refined angles.
    pub contacts: Vec<Contact>,
    /// The contacts' row tags (as given).
    pub tags: Vec<T>,
    /// KKT multipliers of the contacts when the optimality conditions were used
    /// (fewer contacts than unknowns), else empty.
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
    /// The iterate left the domain (t or μ outside the family's domain, or a joint outside
    /// the arch).
    LeftDomain,
    /// No convergence within the iteration limit (residual reached).
    NoConvergence(f64),
    /// Converged, but a KKT multiplier is negative: not the optimum.
    NegativeMultiplier,
}

/// A starting point: reactions, the family's parameter and the friction (the values of
/// the unknown parameters are where Newton starts, those of the others stay fixed).
#[derive(Debug, Clone, Copy)]
pub struct Start {
    /// Reactions x.
    pub x: Reactions,
    /// The family's parameter t.
    pub t: f64,
    /// The friction coefficient μ.
    pub mu: f64,
}

/// The unknowns, flattened: x (3), the parameters (t and/or μ), free β (k), then
/// y (m) in KKT form.
struct System<'a, F: Family> {
    family: &'a F,
    t: f64,
    mu: f64,
    unknowns: Unknowns,
    objective: Objective,
    contacts: Vec<Contact>,
    tags: Vec<F::Tag>,
    free: Vec<usize>,
    kkt: bool,
}

impl<'a, F: Family> System<'a, F> {
    /// The system of `pattern` with the given unknowns; `t` and `mu` are the values of
    /// the parameters that are not unknowns (and the starting values of those that are).
    fn new(
        family: &'a F,
        pattern: &[Tagged<F::Tag>],
        (t, mu): (f64, f64),
        unknowns: Unknowns,
        objective: Objective,
    ) -> System<'a, F> {
        let contacts: Vec<Contact> = pattern.iter().map(|p| p.0).collect();
        let free: Vec<usize> = (0..contacts.len()).filter(|&i| contacts[i].free).collect();
        let needed = match unknowns {
            Unknowns::Mu => 3,
            Unknowns::T => 4,
            Unknowns::TMu => 5,
        };
        let kkt = unknowns != Unknowns::TMu && contacts.len() < needed;
        System {
            family,
            t,
            mu,
            unknowns,
            objective,
            contacts,
            tags: pattern.iter().map(|p| p.1).collect(),
            free,
            kkt,
        }
    }

    /// The unknown parameters, in the order of the unknown vector.
    fn params(&self) -> &'static [Param] {
        match self.unknowns {
            Unknowns::T => &[Param::T],
            Unknowns::Mu => &[Param::Mu],
            Unknowns::TMu => &[Param::T, Param::Mu],
        }
    }

    fn col_beta(&self) -> usize {
        3 + self.params().len()
    }

    fn n_unknowns(&self) -> usize {
        self.col_beta() + self.free.len() + if self.kkt { self.contacts.len() } else { 0 }
    }

    fn n_equations(&self) -> usize {
        self.contacts.len() + self.free.len() + if self.kkt { 4 } else { 0 }
    }

    fn unpack(&self, z: &[f64]) -> (Reactions, f64, f64, Vec<Contact>) {
        let (mut t, mut mu) = (self.t, self.mu);
        for (k, &p) in self.params().iter().enumerate() {
            match p {
                Param::T => t = z[3 + k],
                Param::Mu => mu = z[3 + k],
            }
        }
        let mut cs = self.contacts.clone();
        for (j, &i) in self.free.iter().enumerate() {
            cs[i].beta = z[self.col_beta() + j];
        }
        ([z[0], z[1], z[2]], t, mu, cs)
    }

    fn multipliers<'z>(&self, z: &'z [f64]) -> &'z [f64] {
        &z[self.col_beta() + self.free.len()..]
    }

    fn inside(&self, z: &[f64]) -> bool {
        let arch = self.family.arch();
        let (lo, hi) = (arch.beta_right(), arch.beta_left());
        let (_, t, mu, _) = self.unpack(z);
        let cb = self.col_beta();
        self.family.inside(t, mu)
            && z[cb..cb + self.free.len()]
                .iter()
                .all(|&b| b > lo && b < hi)
    }

    /// Residual F(z) and, when `jac` is given, its Jacobian.
    fn eval(&self, z: &[f64], mut jac: Option<&mut DMatrix<f64>>) -> Vec<f64> {
        let (x, t, mu, cs) = self.unpack(z);
        let y = if self.kkt {
            self.multipliers(z)
        } else {
            &[][..]
        };
        let params = self.params();
        let col_y = self.col_beta() + self.free.len();
        let (ds, dn) = (cs.len() + self.free.len(), cs.len() + self.free.len() + 3);
        let mut f = Vec::with_capacity(self.n_equations());
        let mut stat = [0.0; 3];
        let mut norm_eq = -self.objective.sign();
        let mut col_beta = self.col_beta();
        for (i, c) in cs.iter().enumerate() {
            let local = self.family.local(c.kind, c.beta, self.tags[i], t, mu);
            let f0 = local.phi(0);
            let f1 = local.phi(1);
            let row = f.len();
            f.push(f0.at(&x));
            if c.free {
                f.push(f1.at(&x));
            }
            // the KKT objective is the first (only) parameter
            let objective = local.d_param(0, &x, params[0]);
            if self.kkt {
                for (st, g) in stat.iter_mut().zip(f0.g) {
                    *st += y[i] * g;
                }
                norm_eq += y[i] * objective.value;
            }
            let Some(j) = jac.as_deref_mut() else {
                if c.free {
                    col_beta += 1;
                }
                continue;
            };
            for k in 0..3 {
                j[(row, k)] = f0.g[k];
            }
            for (k, &p) in params.iter().enumerate() {
                j[(row, 3 + k)] = local.d_param(0, &x, p).value;
                if c.free {
                    j[(row + 1, 3 + k)] = local.d_param(1, &x, p).value;
                }
            }
            if c.free {
                let f2 = local.phi(2);
                j[(row, col_beta)] = f1.at(&x);
                for k in 0..3 {
                    j[(row + 1, k)] = f1.g[k];
                }
                j[(row + 1, col_beta)] = f2.at(&x);
            }
            if self.kkt {
                for k in 0..3 {
                    // stationarity rows Σ y ∇ₓφ = 0
                    j[(ds + k, 3)] += y[i] * objective.grad[k];
                    j[(ds + k, col_y + i)] = f0.g[k];
                    if c.free {
                        j[(ds + k, col_beta)] += y[i] * f1.g[k];
                    }
                    // normalisation row Σ y ∂φ/∂p ± 1 = 0, ∂/∂x
                    j[(dn, k)] += y[i] * objective.grad[k];
                }
                j[(dn, 3)] += y[i] * objective.second;
                if c.free {
                    j[(dn, col_beta)] += y[i] * local.d_param(1, &x, params[0]).value;
                }
                j[(dn, col_y + i)] = objective.value;
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

/// The residual F(z) and the analytic Jacobian ∂F/∂z (row-major) of the thickness system
/// that [`solve_system`] solves for `contacts` with the given `unknowns` (see
/// [`residual_and_jacobian_in`]); `eta` and `mu` give the parameters that are not unknowns.
pub fn residual_and_jacobian(
    arch: &Arch,
    contacts: &[Contact],
    eta: f64,
    mu: f64,
    unknowns: Unknowns,
    z: &[f64],
) -> Option<(Vec<f64>, Vec<Vec<f64>>)> {
    let pattern: Vec<Tagged<()>> = contacts.iter().map(|&c| (c, ())).collect();
    let family = Thickness { arch };
    residual_and_jacobian_in(&family, &pattern, (eta, mu), unknowns, Objective::Least, z)
}

/// The residual F(z) and the analytic Jacobian ∂F/∂z (row-major) of the system that
/// [`solve`] solves for `pattern` of `family` with the given `unknowns`, at the point
/// z = (h, v, w, the unknown parameters (t before μ), the free β_i in contact order,
/// then one KKT multiplier y_i per contact when the system is KKT-completed for
/// `objective`, i.e. when `unknowns` is not [`Unknowns::TMu`] and there are fewer than 4
/// contacts (3 for [`Unknowns::Mu`])). `(t, mu)` give the parameters that are not
/// unknowns. Returns `None` when `z` does not have that length. Exposed so that tests can
/// compare every family's Jacobian with finite differences of the residual; Newton uses the
/// same code.
pub fn residual_and_jacobian_in<F: Family>(
    family: &F,
    pattern: &[Tagged<F::Tag>],
    (t, mu): (f64, f64),
    unknowns: Unknowns,
    objective: Objective,
    z: &[f64],
) -> Option<(Vec<f64>, Vec<Vec<f64>>)> {
    let sys = System::new(family, pattern, (t, mu), unknowns, objective);
    if pattern.is_empty() || z.len() != sys.n_unknowns() {
        return None;
    }
    let mut jac = DMatrix::<f64>::zeros(sys.n_equations(), sys.n_unknowns());
    let f = sys.eval(z, Some(&mut jac));
    let rows = (0..jac.nrows())
        .map(|r| jac.row(r).iter().copied().collect())
        .collect();
    Some((f, rows))
}

fn scale_of(z: &[f64]) -> f64 {
    crate::statics::reaction_scale(&[z[0], z[1], z[2]])
}

fn inf_norm(f: &[f64]) -> f64 {
    f.iter().fold(0.0f64, |m, v| m.max(v.abs()))
}

/// Solves the thickness system of `contacts` at the friction of `start` (unknown η, the
/// least) from the starting point `start`.
pub fn solve_pattern(
    start: &State,
    contacts: &[Contact],
    settings: &Settings,
) -> Result<Refined, NewtonFailure> {
    solve_system(start, contacts, Unknowns::T, settings)
}

/// Solves the thickness system of `contacts` with the given parameters unknown (t = η),
/// from the starting point `start` (its η and μ are the starting values of the unknown
/// ones and the fixed values of the others). With fewer contacts than unknowns (a single
/// unknown parameter and fewer than four contacts, three for μ), the KKT conditions of
/// minimising that parameter complete the system.
pub fn solve_system(
    start: &State,
    contacts: &[Contact],
    unknowns: Unknowns,
    settings: &Settings,
) -> Result<Refined, NewtonFailure> {
    let family = Thickness { arch: start.arch };
    let pattern: Vec<Tagged<()>> = contacts.iter().map(|&c| (c, ())).collect();
    let from = Start {
        x: start.x,
        t: start.eta,
        mu: start.mu,
    };
    solve(
        &family,
        &pattern,
        from,
        unknowns,
        Objective::Least,
        settings,
    )
}

/// Solves the system of `pattern` in `family` with the given parameters unknown, from
/// `start`; an under-determined system with one unknown parameter is completed by the KKT
/// conditions of `objective`. The one Newton of the crate.
pub fn solve<F: Family>(
    family: &F,
    pattern: &[Tagged<F::Tag>],
    start: Start,
    unknowns: Unknowns,
    objective: Objective,
    settings: &Settings,
) -> Result<Refined<F::Tag>, NewtonFailure> {
    if pattern.is_empty() {
        return Err(NewtonFailure::Empty);
    }
    let sys = System::new(family, pattern, (start.t, start.mu), unknowns, objective);
    let kkt = sys.kkt;
    let mut z: Vec<f64> = start.x.to_vec();
    for &p in sys.params() {
        z.push(match p {
            Param::T => start.t,
            Param::Mu => start.mu,
        });
    }
    z.extend(sys.free.iter().map(|&i| sys.contacts[i].beta));
    if kkt {
        z.extend(initial_multipliers(
            &sys,
            &start.x,
            settings.multiplier_cutoff,
        ));
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
    let (x, t, mu, contacts) = sys.unpack(&z);
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
        t,
        mu,
        contacts,
        tags: sys.tags,
        multipliers,
        residual: fnorm,
        iterations,
    })
}
/// Damped Gauss–Newton from `z0`; returns the solution, its scaled residual and the
/// iterations used.
fn newton<F: Family>(
    sys: &System<F>,
    z0: Vec<f64>,
    settings: &Settings,
) -> Result<(Vec<f64>, f64, usize), NewtonFailure> {
    let n = sys.n_unknowns();
    let n_eq = sys.n_equations();
    let mut z = z0;
    let mut f = sys.eval(&z, None);
    let mut fnorm = inf_norm(&f) / scale_of(&z);
    let mut iterations = 0;
    loop {
        if fnorm <= settings.newton_tol {
            return Ok((z, fnorm, iterations));
        }
        if iterations >= settings.newton_max_iter {
            break;
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
        let Some(step) = fast_step(&jac, &rhs).or_else(|| {
            let svd = jac.svd(true, true);
            let smax = svd.singular_values.max();
            svd.solve(&rhs, smax * settings.svd_cutoff).ok()
        }) else {
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
            if sys.inside(&zn) {
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
            break;
        }
    }
    // Stagnation at the rounding level counts as convergence.
    if fnorm <= settings.newton_accept {
        Ok((z, fnorm, iterations))
    } else if !sys.inside(&z) {
        Err(NewtonFailure::LeftDomain)
    } else {
        Err(NewtonFailure::NoConvergence(fnorm))
    }
}

/// Below this ratio of the least to the largest pivot of a square Jacobian's LU
/// factorisation (full pivoting, columns equilibrated) the step is taken from the SVD
/// instead: well short of singular, so that the fast path only solves well-conditioned
/// systems, to the same step as the SVD up to rounding.
const LU_PIVOT_RATIO: f64 = 1e-8;

/// The Newton step of a square, well-conditioned system by LU with full pivoting (of an
/// over-determined one by [`qr_step`]); `None` when the system has fewer equations than
/// unknowns or its pivots fall below [`LU_PIVOT_RATIO`] (the SVD's minimum-norm step then
/// decides).
fn fast_step(jac: &DMatrix<f64>, rhs: &DVector<f64>) -> Option<DVector<f64>> {
    if jac.nrows() > jac.ncols() && jac.ncols() > 0 {
        return qr_step(jac, rhs);
    }
    if !jac.is_square() || jac.nrows() == 0 {
        return None;
    }
    let lu = jac.clone().full_piv_lu();
    let pivots = lu.u().diagonal().map(f64::abs);
    let (lo, hi) = (pivots.min(), pivots.max());
    if !(hi > 0.0 && lo >= LU_PIVOT_RATIO * hi) {
        return None;
    }
    lu.solve(rhs)
}

/// The least-squares (Gauss–Newton) step of an over-determined system of full column rank
/// by Householder QR; `None` when a diagonal entry of R falls below [`LU_PIVOT_RATIO`] of
/// the largest (the SVD then decides).
fn qr_step(jac: &DMatrix<f64>, rhs: &DVector<f64>) -> Option<DVector<f64>> {
    let qr = jac.clone().qr();
    let r = qr.r();
    let diag = r.diagonal().map(f64::abs);
    let (lo, hi) = (diag.min(), diag.max());
    if !(hi > 0.0 && lo >= LU_PIVOT_RATIO * hi) {
        return None;
    }
    let qtb = qr.q().transpose() * rhs;
    r.solve_upper_triangular(&qtb)
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

/// Least-squares multipliers of [∇ₓφ_i; ∂φ_i/∂p] y = [0; ±1] at the starting point.
fn initial_multipliers<F: Family>(sys: &System<F>, x: &Reactions, cutoff: f64) -> Vec<f64> {
    let m = sys.contacts.len();
    let p = sys.params()[0];
    let a = DMatrix::from_fn(4, m, |r, i| {
        let c = &sys.contacts[i];
        let local = sys.family.local(c.kind, c.beta, sys.tags[i], sys.t, sys.mu);
        if r < 3 {
            local.phi(0).g[r]
        } else {
            local.d_param(0, x, p).value
        }
    });
    let b = DVector::from_vec(vec![0.0, 0.0, 0.0, sys.objective.sign()]);
    let svd = a.svd(true, true);
    let tol = svd.singular_values.max() * cutoff;
    svd.solve(&b, tol)
        .map(|y| y.iter().copied().collect())
        .unwrap_or_else(|_| vec![1.0; m])
}
