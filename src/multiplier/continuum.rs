//! The static multiplier range of a loaded **continuous** arch: the exchange method on the
//! semi-infinite LP in (h, v, w, λ), then Newton on the active pattern.
//!
//! At fixed η and μ the activation functions are affine in z = (h, v, w, λ) at every angle
//! of the continuum (at the point load's angle on both sides). The LP on a finite working
//! set of angles gives z; a scan of each smooth piece of the arch at z
//! ([`crate::scan::peaks_over`], exact derivatives) finds the most violated angles, which
//! join the working set, until the whole arch is admissible to `EXCHANGE_TOL`. The LP's z
//! (good to the back end's tolerance) then starts Newton on the square system of the active
//! pattern — φ = 0 at each contact, dφ/dβ = 0 at each interior tangency, unknowns z and
//! the tangency angles — whose root is verified by a scan (every φ ≤ `adm_tol` × its
//! magnitude): exact to rounding.

use crate::arch::{Arch, Radians};
use crate::contact::{Contact, ContactKind, Location, Peak};
use crate::load::{live_activation, LiveLoad, Side};
use crate::lp::{self, LpOutcome};
use crate::scan::peaks_over;
use crate::settings::Settings;
use crate::statics::{actions, magnitude, Reactions};
use nalgebra::{DMatrix, DVector};

/// Relative violation at which the exchange stops (Newton finishes the job).
const EXCHANGE_TOL: f64 = 1e-9;
/// At most this many exchange rounds.
const MAX_ROUNDS: usize = 200;
/// The multiplier is capped here in the LP (a finite working set can leave it unbounded);
/// an answer at the cap means unbounded.
const LAMBDA_CAP: f64 = 1e9;

/// A contact of the loaded continuum: an activation function at an angle, on a side of the
/// loaded section.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct LoadedContact {
    /// The contact.
    pub contact: Contact,
    /// The side of the loaded section.
    pub side: Side,
}

/// A smooth piece of the arch: its two ends (angle, location) and the side of the loaded
/// section its sections are on.
type Piece = ((Radians, Location), (Radians, Location), Side);

/// The problem: arch, η, μ, load.
struct Loaded<'a> {
    arch: &'a Arch,
    eta: f64,
    mu: f64,
    load: &'a LiveLoad,
}

impl Loaded<'_> {
    /// (a, c) of the activation function `kind` at β on `side`, β-derivative `order`:
    /// a · (h, v, w, λ) + c.
    fn row(&self, kind: ContactKind, beta: Radians, side: Side, order: usize) -> ([f64; 4], f64) {
        let dead = actions(self.arch, self.eta, beta).activation(kind, order, self.eta, self.mu);
        let live = self.load.actions_d(self.arch, self.eta, beta, side)[order];
        (
            [
                dead.g[0],
                dead.g[1],
                dead.g[2],
                live_activation(kind, self.eta, self.mu, live),
            ],
            dead.c,
        )
    }

    /// The smooth pieces of the arch: one, or two at a point load strictly inside (each
    /// end with its location, and the side of the section that belongs to the piece).
    fn pieces(&self) -> Vec<Piece> {
        let (a, b) = (self.arch.beta_right(), self.arch.beta_left());
        match *self.load {
            LiveLoad::Point { beta } if beta > a && beta < b => vec![
                (
                    (a, Location::Springing),
                    (beta, Location::Interior),
                    Side::Before,
                ),
                (
                    (beta, Location::Interior),
                    (b, Location::Springing),
                    Side::After,
                ),
            ],
            // a load at the left springing is carried by the section there (its free body is
            // the whole arch); at the right springing by every section but the springing's
            LiveLoad::Point { beta } if beta == b => {
                vec![(
                    (a, Location::Springing),
                    (b, Location::Springing),
                    Side::After,
                )]
            }
            _ => vec![(
                (a, Location::Springing),
                (b, Location::Springing),
                Side::Before,
            )],
        }
    }

    /// The local maxima of every activation function at (x, λ) over the whole arch.
    fn peaks(&self, x: &Reactions, lambda: f64, settings: &Settings) -> Vec<(Peak, Side)> {
        let modes = ContactKind::active_at(self.mu);
        let mut out = Vec::new();
        for (from, to, side) in self.pieces() {
            let phi = |beta: Radians, orders: usize| {
                let mut v = [[0.0; 3]; 4];
                let act = actions(self.arch, self.eta, beta);
                let live = self.load.actions_d(self.arch, self.eta, beta, side);
                for (k, &mode) in modes.iter().enumerate() {
                    for (d, slot) in v[k].iter_mut().enumerate().take(orders) {
                        *slot = act.activation(mode, d, self.eta, self.mu).at(x)
                            + lambda * live_activation(mode, self.eta, self.mu, live[d]);
                    }
                }
                v
            };
            out.extend(
                peaks_over(from, to, modes, settings.scan_points, &phi)
                    .into_iter()
                    .map(|p| (p, side)),
            );
        }
        out
    }

    fn magnitude(&self, kind: ContactKind, x: &Reactions, lambda: f64, settings: &Settings) -> f64 {
        magnitude(kind, self.eta, self.mu, x, settings.magnitude_floor) * (1.0 + lambda.abs())
    }
}

/// The least (`maximise` false) or largest admissible λ ≥ 0 of a continuous arch, with the
/// state there and its active pattern. `Ok(None)`: unbounded; `Err(Infeasible)`: no state
/// at any λ ≥ 0; `Err(Failed)`: no decision (the text says why).
pub fn extreme(
    arch: &Arch,
    eta: f64,
    mu: f64,
    load: &LiveLoad,
    maximise: bool,
    settings: &Settings,
) -> Result<Option<(f64, Reactions, Vec<LoadedContact>)>, LpOutcome> {
    let p = Loaded {
        arch,
        eta,
        mu,
        load,
    };
    let (a, b) = (arch.beta_right(), arch.beta_left());
    let modes = ContactKind::active_at(mu);
    // the working set: equally spaced angles, both sides of a point load's section
    let mut work: Vec<(Radians, Side)> = (0..=64)
        .map(|i| (a + (b - a) * i as f64 / 64.0, Side::After))
        .collect();
    if let LiveLoad::Point { beta } = *load {
        work.retain(|(w, _)| (w - beta).abs() > 1e-12);
        work.push((beta, Side::Before));
        work.push((beta, Side::After));
    }
    for _ in 0..MAX_ROUNDS {
        let mut rows: Vec<([f64; 4], f64)> = Vec::new();
        for &(beta, side) in &work {
            for &kind in modes {
                rows.push(p.row(kind, beta, side, 0));
            }
        }
        if maximise {
            rows.push(([0.0, 0.0, 0.0, 1.0], -LAMBDA_CAP));
        }
        let z = match lp::multiplier_extreme(&rows, &[], maximise, settings)? {
            Some(z) => z,
            None => return Ok(None),
        };
        let (x, lambda) = ([z[0], z[1], z[2]], z[3]);
        if maximise && lambda >= LAMBDA_CAP * (1.0 - 1e-9) {
            return Ok(None);
        }
        let peaks = p.peaks(&x, lambda, settings);
        let violated: Vec<&(Peak, Side)> = peaks
            .iter()
            .filter(|(pk, _)| {
                pk.value > EXCHANGE_TOL * p.magnitude(pk.contact.kind, &x, lambda, settings)
            })
            .collect();
        let before = work.len();
        for (pk, side) in violated {
            let beta = pk.contact.beta;
            if !work
                .iter()
                .any(|(w, s)| (w - beta).abs() <= 1e-9 && s == side)
            {
                work.push((beta, *side));
            }
        }
        // admissible to the exchange's tolerance, or every violation sits at an angle
        // already in the working set (the LP's own tolerance): Newton takes over
        if work.len() == before {
            return refine(&p, x, lambda, &peaks, maximise, settings).map(Some);
        }
    }
    Err(LpOutcome::Failed(format!(
        "the exchange did not converge in {MAX_ROUNDS} rounds"
    )))
}

/// Newton on the active pattern from the exchange's (x, λ), verified by a scan; λ = 0
/// with the arch standing unloaded needs no refinement.
fn refine(
    p: &Loaded,
    x: Reactions,
    lambda: f64,
    peaks: &[(Peak, Side)],
    maximise: bool,
    settings: &Settings,
) -> Result<(f64, Reactions, Vec<LoadedContact>), LpOutcome> {
    let active = |x: &Reactions, lambda: f64, peaks: &[(Peak, Side)], slack: f64| {
        peaks
            .iter()
            .filter(|(pk, _)| {
                pk.value >= -slack * p.magnitude(pk.contact.kind, x, lambda, settings)
            })
            .map(|(pk, side)| LoadedContact {
                contact: pk.contact,
                side: *side,
            })
            .collect::<Vec<_>>()
    };
    if !maximise && lambda == 0.0 {
        return Ok((0.0, x, active(&x, 0.0, peaks, 10.0 * settings.adm_tol)));
    }
    let mut pattern = active(&x, lambda, peaks, 1e-7);
    // twins (one function for two contacts: the extrados hinge rows of both sides of the
    // point load's section) are one equation
    let twin = |p1: &LoadedContact, p2: &LoadedContact| {
        let (a1, c1) = p.row(p1.contact.kind, p1.contact.beta, p1.side, 0);
        let (a2, c2) = p.row(p2.contact.kind, p2.contact.beta, p2.side, 0);
        p1.contact.kind == p2.contact.kind
            && p1.contact.beta == p2.contact.beta
            && (c1 - c2).abs() <= 1e-13 * (1.0 + c1.abs())
            && (0..4).all(|k| (a1[k] - a2[k]).abs() <= 1e-13 * (1.0 + a1[k].abs()))
    };
    let mut unique: Vec<LoadedContact> = Vec::new();
    for c in &pattern {
        if !unique.iter().any(|u| twin(u, c)) {
            unique.push(*c);
        }
    }
    std::mem::swap(&mut pattern, &mut unique);
    let free: Vec<usize> = (0..pattern.len())
        .filter(|&i| pattern[i].contact.free)
        .collect();
    let unknowns = 4 + free.len();
    let equations = pattern.len() + free.len();
    if equations != unknowns {
        return Err(LpOutcome::Failed(format!(
            "the pattern at the {} multiplier has {} contacts ({} tangencies): not a vertex, no square system to refine",
            if maximise { "largest" } else { "least" },
            pattern.len(),
            free.len()
        )));
    }
    // unknowns: z = (h, v, w, λ), then the free angles
    let mut u = DVector::from_fn(unknowns, |i, _| match i {
        0..=2 => x[i],
        3 => lambda,
        _ => pattern[free[i - 4]].contact.beta,
    });
    let residual = |u: &DVector<f64>| -> (DVector<f64>, DMatrix<f64>) {
        let z = [u[0], u[1], u[2], u[3]];
        let mut r = DVector::zeros(equations);
        let mut j = DMatrix::zeros(equations, unknowns);
        let mut row = 0;
        for (i, c) in pattern.iter().enumerate() {
            let slot = free.iter().position(|&f| f == i);
            let beta = slot.map_or(c.contact.beta, |s| u[4 + s]);
            let (a0, c0) = p.row(c.contact.kind, beta, c.side, 0);
            let (a1, c1) = p.row(c.contact.kind, beta, c.side, 1);
            let dot = |a: &[f64; 4], c: f64| a.iter().zip(&z).map(|(p, q)| p * q).sum::<f64>() + c;
            r[row] = dot(&a0, c0);
            for k in 0..4 {
                j[(row, k)] = a0[k];
            }
            if let Some(s) = slot {
                j[(row, 4 + s)] = dot(&a1, c1);
                row += 1;
                let (a2, c2) = p.row(c.contact.kind, beta, c.side, 2);
                r[row] = dot(&a1, c1);
                for k in 0..4 {
                    j[(row, k)] = a1[k];
                }
                j[(row, 4 + s)] = dot(&a2, c2);
            }
            row += 1;
        }
        (r, j)
    };
    let mut converged = false;
    for _ in 0..50 {
        let (r, j) = residual(&u);
        let scale = 1.0 + u.iter().take(4).map(|v| v.abs()).sum::<f64>();
        if r.amax() <= 1e-15 * scale {
            converged = true;
            break;
        }
        let Some(step) = j.lu().solve(&(-r)) else {
            break;
        };
        u += &step;
        if step.amax() <= 1e-16 * scale {
            converged = true;
            break;
        }
    }
    let (r, _) = residual(&u);
    let scale = 1.0 + u.iter().take(4).map(|v| v.abs()).sum::<f64>();
    if !converged && r.amax() > 1e-13 * scale {
        return Err(LpOutcome::Failed(format!(
            "Newton on the active pattern did not converge (residual {:e})",
            r.amax()
        )));
    }
    let (x, lambda) = ([u[0], u[1], u[2]], u[3]);
    // verify over the whole arch
    let peaks = p.peaks(&x, lambda, settings);
    let worst = peaks
        .iter()
        .map(|(pk, _)| pk.value / p.magnitude(pk.contact.kind, &x, lambda, settings))
        .fold(f64::NEG_INFINITY, f64::max);
    if worst > settings.adm_tol {
        return Err(LpOutcome::Failed(format!(
            "the refined state is not admissible over the arch (worst relative violation {worst:e})"
        )));
    }
    let mut pattern = active(&x, lambda, &peaks, 10.0 * settings.adm_tol);
    pattern.sort_by(|a, b| {
        a.contact
            .beta
            .total_cmp(&b.contact.beta)
            .then((a.side == Side::After).cmp(&(b.side == Side::After)))
            .then(a.contact.kind.cmp(&b.contact.kind))
    });
    Ok((lambda, x, pattern))
}
