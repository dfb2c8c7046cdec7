//! Smooth pattern changes of the static boundary η_s(μ), located exactly.
//!
//! Not every change of the active pattern is a corner (formulation §6): a contact can
//! change character without a kink in η_s(μ). Two such changes have an exact extra
//! condition on the pattern that holds on both sides:
//!
//! * **merge**: two tangency contacts of one kind meet (e.g. two intrados hinges reaching
//!   the crown of a symmetric arch from both sides) and go on as one. At the meeting
//!   point the single contact's activation function is flat to second order:
//!   φ = dφ/dβ = d²φ/dβ² = 0 there.
//! * **springing**: an interior tangency contact reaches a springing and goes on as a
//!   springing contact: there φ = dφ/dβ = 0 at the springing.
//!
//! Each is the merged (or springing) side's pattern with μ unknown and the one extra
//! equation, a square system solved here by Gauss–Newton (the pattern's rows and their
//! analytic Jacobian come from [`crate::refine::residual_and_jacobian`]; the extra row's
//! Jacobian by central differences, which costs nothing in accuracy at the root since the
//! residual itself is exact).

use crate::arch::Arch;
use crate::contact::{Contact, Location};
use crate::refine::{residual_and_jacobian, Unknowns};
use crate::settings::Settings;
use crate::statics::{actions, reaction_scale, Reactions};
use nalgebra::{DMatrix, DVector};

/// The extra condition of a smooth change.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(super) enum Extra {
    /// The β-derivative `order` of the activation function of `pattern[contact]` vanishes
    /// too: 2 for a merge, 1 for a tangency reaching a springing.
    Flat {
        /// Index of the contact in the pattern.
        contact: usize,
        /// Order of the derivative.
        order: usize,
    },
    /// Two interior contacts of different kinds meet at one joint (a hinge crossing a
    /// sliding joint): their angles are equal.
    Coincide {
        /// Index of one contact in the pattern.
        a: usize,
        /// Index of the other.
        b: usize,
    },
}

/// A located change (smooth, an onset, a corner): the state on the boundary where it
/// happens.
#[derive(Debug, Clone)]
pub(super) struct Located {
    pub(super) mu: f64,
    pub(super) eta: f64,
    pub(super) x: Reactions,
    /// The pattern with its refined angles (an onset's: plus the contact that joins).
    pub(super) pattern: Vec<Contact>,
    /// Scaled Newton residual (0 for an onset, located by regula falsi).
    pub(super) residual: f64,
}

/// Solves `pattern` (unknowns x, η, μ and the free angles) with the extra condition, from
/// (x, η, μ). `None` when Newton does not converge or leaves the domain.
pub(super) fn locate(
    arch: &Arch,
    pattern: &[Contact],
    extra: Extra,
    start: (Reactions, f64, f64),
    settings: &Settings,
) -> Option<Located> {
    // On a symmetric arch the least state is symmetric, so a single contact near the
    // middle is at the middle: fixing it there removes the double degeneracy of a merge
    // at the crown (there d³φ/dβ³ = 0 too, and a free angle is resolved only to the
    // cube root of the residual).
    let mut pattern = pattern.to_vec();
    if let (true, Extra::Flat { contact, .. }) = (arch.is_symmetric(), extra) {
        let mid = 0.5 * (arch.beta_right() + arch.beta_left());
        let c = &mut pattern[contact];
        if c.free && (c.beta - mid).abs() < settings.track_angle {
            c.beta = mid;
            c.free = false;
        }
    }
    let pattern = &pattern[..];
    let free: Vec<usize> = (0..pattern.len()).filter(|&i| pattern[i].free).collect();
    let mut z: Vec<f64> = start.0.to_vec();
    z.extend([start.1, start.2]);
    z.extend(free.iter().map(|&i| pattern[i].beta));
    let beta_of = |z: &[f64], i: usize| match free.iter().position(|&f| f == i) {
        Some(k) => z[5 + k],
        None => pattern[i].beta,
    };
    let extra_row = |z: &[f64]| match extra {
        Extra::Flat { contact, order } => {
            let c = &pattern[contact];
            let (eta, mu) = (z[3], z[4]);
            actions(arch, eta, beta_of(z, contact))
                .activation(c.kind, order, eta, mu)
                .at(&[z[0], z[1], z[2]])
        }
        Extra::Coincide { a, b } => beta_of(z, a) - beta_of(z, b),
    };
    let eval = |z: &[f64]| -> Option<(Vec<f64>, Vec<Vec<f64>>)> {
        let (mut f, mut j) = residual_and_jacobian(arch, pattern, z[3], z[4], Unknowns::TMu, z)?;
        f.push(extra_row(z));
        let row = (0..z.len())
            .map(|k| {
                let h = 1e-7 * (1.0 + z[k].abs());
                let (mut zp, mut zm) = (z.to_vec(), z.to_vec());
                zp[k] += h;
                zm[k] -= h;
                (extra_row(&zp) - extra_row(&zm)) / (2.0 * h)
            })
            .collect();
        j.push(row);
        Some((f, j))
    };
    let (lo, hi) = (arch.beta_right(), arch.beta_left());
    let inside = |z: &[f64]| {
        z[3] > 0.0 && z[3] < 2.0 && z[4] > 0.0 && z[5..].iter().all(|&b| b > lo && b < hi)
    };
    let norm = |f: &[f64], z: &[f64]| {
        f.iter().fold(0.0f64, |m, v| m.max(v.abs())) / reaction_scale(&[z[0], z[1], z[2]])
    };
    let (mut f, mut jac) = eval(&z)?;
    let mut fnorm = norm(&f, &z);
    for _ in 0..settings.newton_max_iter {
        if fnorm <= settings.newton_tol {
            break;
        }
        let mut m = DMatrix::from_fn(f.len(), z.len(), |r, c| jac[r][c]);
        let mut colscale = vec![1.0; z.len()];
        for (c, s) in colscale.iter_mut().enumerate() {
            let n = m.column(c).norm();
            if n > 0.0 {
                *s = 1.0 / n;
                m.column_mut(c).scale_mut(1.0 / n);
            }
        }
        let rhs = DVector::from_iterator(f.len(), f.iter().map(|v| -v));
        let svd = m.svd(true, true);
        let cutoff = svd.singular_values.max() * settings.svd_cutoff;
        let step = svd.solve(&rhs, cutoff).ok()?;
        let mut t = 1.0;
        let mut accepted = false;
        for _ in 0..30 {
            let zn: Vec<f64> = (0..z.len())
                .map(|k| z[k] + t * step[k] * colscale[k])
                .collect();
            if inside(&zn) {
                if let Some((fnew, jnew)) = eval(&zn) {
                    let nn = norm(&fnew, &zn);
                    if nn < fnorm {
                        (z, f, jac, fnorm, accepted) = (zn, fnew, jnew, nn, true);
                        break;
                    }
                }
            }
            t *= 0.5;
        }
        if !accepted {
            break;
        }
    }
    if fnorm > settings.newton_accept {
        return None;
    }
    let mut refined = pattern.to_vec();
    for (k, &i) in free.iter().enumerate() {
        refined[i].beta = z[5 + k];
    }
    Some(Located {
        mu: z[4],
        eta: z[3],
        x: [z[0], z[1], z[2]],
        pattern: refined,
        residual: fnorm,
    })
}

/// The smooth changes that could turn pattern `p` into `q`: for each kind with more
/// interior contacts in `p` than in `q`, a merge on `q`'s interior contacts of that kind
/// (and the reverse); for each kind interior in one and at a springing in the other, the
/// tangency reaching that springing; for two interior contacts of different kinds whose
/// order along the arch is reversed in the other pattern, their meeting at one joint. Each
/// entry: which of the two patterns carries the system (false: `p`, true: `q`) and the
/// extra condition.
pub(super) fn candidates(p: &[Contact], q: &[Contact]) -> Vec<(bool, Extra)> {
    let count = |s: &[Contact], k, at| s.iter().filter(|c| c.kind == k && c.at == at).count();
    let interior = |c: &Contact| c.at == Location::Interior && c.free;
    // the angle of the interior contact of `c`'s kind in `s` nearest to `c`
    let nearest = |s: &[Contact], c: &Contact| {
        s.iter()
            .filter(|d| interior(d) && d.kind == c.kind)
            .map(|d| d.beta)
            .min_by(|a, b| (a - c.beta).abs().total_cmp(&(b - c.beta).abs()))
    };
    let mut out = Vec::new();
    for (on_q, merged, split) in [(true, q, p), (false, p, q)] {
        for (i, c) in merged.iter().enumerate() {
            let (k, at) = (c.kind, c.at);
            if interior(c)
                && count(split, k, Location::Interior) > count(merged, k, Location::Interior)
            {
                out.push((
                    on_q,
                    Extra::Flat {
                        contact: i,
                        order: 2,
                    },
                ));
            }
            if at == Location::Springing
                && count(split, k, Location::Springing) < count(merged, k, Location::Springing)
                && count(split, k, Location::Interior) > count(merged, k, Location::Interior)
            {
                out.push((
                    on_q,
                    Extra::Flat {
                        contact: i,
                        order: 1,
                    },
                ));
            }
        }
        for (a, b) in (0..merged.len()).flat_map(|a| (a + 1..merged.len()).map(move |b| (a, b))) {
            let (ca, cb) = (&merged[a], &merged[b]);
            if !(interior(ca) && interior(cb) && ca.kind != cb.kind) {
                continue;
            }
            if let (Some(na), Some(nb)) = (nearest(split, ca), nearest(split, cb)) {
                if (ca.beta < cb.beta) != (na < nb) {
                    out.push((on_q, Extra::Coincide { a, b }));
                }
            }
        }
    }
    out
}
