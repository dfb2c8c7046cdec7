//! Weightless admissible directions: where η_s is an infimum (a discrete arch:
//! [`threshold`]; a continuous one: [`continuum_threshold`]).
//!
//! The admissible set P(η) = {x : g_i(η)·x + c_i(η) ≤ 0} of a discrete arch is unbounded
//! exactly when its recession cone {d : g_i(η)·d ≤ 0 for every contact i} holds a d ≠ 0:
//! a *weightless* state (the c_i carry the weight) that every joint admits, e.g. a
//! straight line of thrust through hinge points of a steep segment. The cone grows with η
//! (admissibility is monotone, and so is its weightless version). Once it has an interior,
//! P(η) is not empty either: far enough along such a d every φ_i is negative, whatever
//! the weight. So where P(η) is empty below the least η_rec with such a direction and
//! holds no bounded state at η_rec itself, η_s = η_rec is an infimum approached only as the
//! reactions grow without bound: no limit state there.
//!
//! At η_rec the cone is a single ray (generically): three contacts whose gradients have a
//! common null direction, a root of det[g_a(η) g_b(η) g_c(η)] — a cubic, the gradients
//! being affine in η (formulation §3). [`threshold`] brackets η_rec by the sign of the
//! cone's margin (a small LP with |d_k| ≤ 1) and then finds that cubic's root in the
//! bracket. On a continuous arch the weightless line of thrust is straight, and η_rec is
//! where it touches the extrados or intrados at three contacts, an interior one tangent:
//! Newton on that system from the unbounded Newton state's direction.

use crate::arch::{Arch, JointLayout};
use crate::contact::ContactKind;
use crate::lp;
use crate::settings::Settings;
use crate::statics::{actions, Affine, Reactions};

/// The cone's margin is positive beyond this (rows and directions of unit size).
pub(super) const MARGIN_TOL: f64 = 1e-12;

/// η_rec is bisected on the sign of the cone's margin to this width (relative) ...
const BISECTION_REL: f64 = 1e-13;

/// ... in at most this many halvings.
const BISECTION_MAX_STEPS: usize = 200;

/// At most this many contacts tight at a discrete arch's direction (the tightest) enter
/// the search for the three whose determinant vanishes at η_rec ...
const MAX_TIGHT_DISCRETE: usize = 8;

/// ... and at most this many local maxima of a continuous arch's weightless functions.
const MAX_TIGHT_CONTINUOUS: usize = 6;

/// The bracket of η_rec is cut into this many pieces, so that the cubic's roots there
/// are separated.
const DET_PIECES: usize = 64;

/// A root η of three tight contacts is where the cone opens when its margin is positive at
/// η (1 + this) (the margin LP's optimum is exactly 0, at d = 0, where the cone has no
/// interior).
const OPENS_ABOVE_REL: f64 = 3e-13;

/// The null direction of three gradients is the bracket's direction when the cosine of
/// the angle between them is above this.
const SAME_DIRECTION_COS: f64 = 0.5;

/// Newton on the weightless system of a continuous arch takes at most this many steps ...
const WEIGHTLESS_NEWTON_STEPS: usize = 60;

/// ... stops when no unknown moves by more than this many machine epsilons (relative to
/// 1 + its size) ...
const WEIGHTLESS_STALL_ULPS: f64 = 4.0;

/// ... and has converged when its largest residual is at most this (rows of unit size).
const WEIGHTLESS_RESIDUAL: f64 = 1e-13;

/// A weightless admissible direction at its least thickness.
#[derive(Debug, Clone, Copy)]
pub struct Recession {
    /// η_rec: the least η at which the direction is admissible.
    pub eta: f64,
    /// The direction, |d|∞ = 1.
    pub d: Reactions,
    /// Whether `eta` is the root of the determinant of three contacts (verified: every
    /// contact admits `d` there), rather than the upper end of the bisection bracket.
    pub exact: bool,
}

/// The gradients g_i(η) of every activation function at every joint, as (g(0), g(1) − g(0))
/// (exactly affine in η: g_E = ∇M − η∇N/2, g_I = −∇M − η∇N/2, g_S± independent of η).
fn gradients(arch: &Arch, mu: f64) -> Option<Vec<([f64; 3], [f64; 3])>> {
    let JointLayout::Discrete(joints) = arch.layout() else {
        return None;
    };
    let mut out = Vec::new();
    for &beta in joints {
        let (a0, a1) = (actions(arch, 0.0, beta), actions(arch, 1.0, beta));
        for &k in ContactKind::active_at(mu) {
            let (g0, g1) = (
                a0.activation(k, 0, 0.0, mu).g,
                a1.activation(k, 0, 1.0, mu).g,
            );
            out.push((g0, [g1[0] - g0[0], g1[1] - g0[1], g1[2] - g0[2]]));
        }
    }
    Some(out)
}

fn at(g: &([f64; 3], [f64; 3]), eta: f64) -> [f64; 3] {
    [0, 1, 2].map(|k| g.0[k] + eta * g.1[k])
}

fn dot(a: &[f64; 3], b: &[f64; 3]) -> f64 {
    a[0] * b[0] + a[1] * b[1] + a[2] * b[2]
}

fn norm(a: &[f64; 3]) -> f64 {
    dot(a, a).sqrt()
}

/// The margin of the recession cone at η: max s subject to ĝ_i(η)·d + s ≤ 0 for every
/// contact (unit gradients) and |d_k| ≤ 1 − s, with the maximiser d; `None` for a
/// continuous arch or an LP failure. Positive exactly when the cone has an interior.
pub fn margin(arch: &Arch, mu: f64, eta: f64, settings: &Settings) -> Option<(f64, Reactions)> {
    let grads = gradients(arch, mu)?;
    cone_margin(&grads, eta, settings)
}

fn cone_margin(
    grads: &[([f64; 3], [f64; 3])],
    eta: f64,
    settings: &Settings,
) -> Option<(f64, Reactions)> {
    let mut rows: Vec<Affine> = grads
        .iter()
        .map(|g| Affine {
            g: at(g, eta),
            c: 0.0,
        })
        .collect();
    for k in 0..3 {
        for s in [1.0, -1.0] {
            let mut g = [0.0; 3];
            g[k] = s;
            rows.push(Affine { g, c: -1.0 });
        }
    }
    let (d, s) = lp::max_margin(&rows, 1.0, settings).ok()?;
    Some((s, d))
}

/// η_rec in [lo, hi]: the least η with a weightless admissible direction, when the cone has
/// no interior at `lo` and has one at `hi` (`None` otherwise, or for a continuous arch).
/// Bisection on the sign of [`margin`] to a relative width of 1e-13 (`BISECTION_REL`), then
/// the exact root of det\[g_a g_b g_c\](η) for the contacts tight at the bracket's
/// direction, verified.
pub fn threshold(arch: &Arch, mu: f64, lo: f64, hi: f64, settings: &Settings) -> Option<Recession> {
    let grads = gradients(arch, mu)?;
    let positive = |eta: f64| cone_margin(&grads, eta, settings).map(|(s, d)| (s > MARGIN_TOL, d));
    let (lo0, mut lo, mut hi) = (lo, lo, hi);
    if positive(lo)?.0 {
        return None;
    }
    let (ok, mut d) = positive(hi)?;
    if !ok {
        return None;
    }
    for _ in 0..BISECTION_MAX_STEPS {
        if hi - lo <= BISECTION_REL * hi {
            break;
        }
        let m = 0.5 * (lo + hi);
        let (ok, dm) = positive(m)?;
        if ok {
            hi = m;
            d = dm;
        } else {
            lo = m;
        }
    }
    let scale = d.iter().fold(0.0f64, |a, v| a.max(v.abs()));
    let d = d.map(|v| v / scale);
    // the contacts tight at d (the cone's margin there is ~ 0): the tightest few
    let mut tight: Vec<(f64, usize)> = grads
        .iter()
        .enumerate()
        .map(|(i, g)| {
            let gi = at(g, hi);
            (-dot(&gi, &d) / norm(&gi).max(f64::MIN_POSITIVE), i)
        })
        .filter(|(slack, _)| *slack <= settings.recession_candidate_rel)
        .collect();
    tight.sort_by(|a, b| a.0.total_cmp(&b.0));
    tight.truncate(MAX_TIGHT_DISCRETE);
    let width = hi - lo;
    // every verified root, with whether the cone opens just above it: a triple can be tight
    // along a ray of a cone that has no interior yet (a root below η_rec, where a joint
    // nearly repeats a tight one); η_rec is the least root above which the cone opens
    let mut roots: Vec<(f64, Reactions, bool)> = Vec::new();
    for a in 0..tight.len() {
        for b in a + 1..tight.len() {
            for c in b + 1..tight.len() {
                let rows = [tight[a].1, tight[b].1, tight[c].1].map(|i| &grads[i]);
                // the bisection stops where the margin exceeds MARGIN_TOL, a little above
                // η_rec: the root lies in [lo0, hi]
                for eta in det_roots(&rows, lo0, hi + width) {
                    if let Some(dir) = verify(&grads, &rows, eta, &d, settings) {
                        let above = eta * (1.0 + OPENS_ABOVE_REL);
                        let opens = cone_margin(&grads, above, settings).is_some_and(|m| m.0 > 0.0);
                        roots.push((eta, dir, opens));
                    }
                }
            }
        }
    }
    // a root above which the cone does not open is not η_rec: without one, the bracket's
    // upper end stands, not exact
    let best = roots
        .into_iter()
        .filter(|r| r.2)
        .min_by(|a, b| a.0.total_cmp(&b.0))
        .map(|(eta, d, _)| Recession {
            eta,
            d,
            exact: true,
        });
    best.or(Some(Recession {
        eta: hi,
        d,
        exact: false,
    }))
}

/// The sign changes of det[g_a(η) g_b(η) g_c(η)] (a cubic in η) on [lo, hi], each
/// narrowed by bisection to adjacent floats: the interval is the bracket of η_rec
/// (≤ 2e-6 relative), split into [`DET_PIECES`] pieces so that the cubic's roots there are
/// separated.
fn det_roots(rows: &[&([f64; 3], [f64; 3]); 3], lo: f64, hi: f64) -> Vec<f64> {
    let det = |eta: f64| {
        let [a, b, c] = rows.map(|r| at(r, eta));
        a[0] * (b[1] * c[2] - b[2] * c[1]) - a[1] * (b[0] * c[2] - b[2] * c[0])
            + a[2] * (b[0] * c[1] - b[1] * c[0])
    };
    let n = DET_PIECES;
    let mut roots = Vec::new();
    let mut prev = (lo, det(lo));
    for i in 1..=n {
        let t = if i == n {
            hi
        } else {
            lo + (hi - lo) * i as f64 / n as f64
        };
        let cur = (t, det(t));
        if prev.1 == 0.0 {
            roots.push(prev.0);
        } else if prev.1.signum() != cur.1.signum() && cur.1 != 0.0 {
            let (mut a, mut b, fa) = (prev.0, cur.0, prev.1);
            loop {
                let m = 0.5 * (a + b);
                if m <= a || m >= b {
                    break;
                }
                let fm = det(m);
                if fm == 0.0 {
                    (a, b) = (m, m);
                    break;
                }
                if fm.signum() == fa.signum() {
                    a = m;
                } else {
                    b = m;
                }
            }
            roots.push(0.5 * (a + b));
        }
        prev = cur;
    }
    if prev.1 == 0.0 {
        roots.push(prev.0);
    }
    roots
}

/// The common null direction of three gradients at η (the sign of `near`), if every
/// contact admits it there (g_i·d ≤ `settings.recession_tol` |g_i| |d|).
fn verify(
    grads: &[([f64; 3], [f64; 3])],
    rows: &[&([f64; 3], [f64; 3]); 3],
    eta: f64,
    near: &Reactions,
    settings: &Settings,
) -> Option<Reactions> {
    let g = rows.map(|r| at(r, eta));
    let cross = |a: &[f64; 3], b: &[f64; 3]| {
        [
            a[1] * b[2] - a[2] * b[1],
            a[2] * b[0] - a[0] * b[2],
            a[0] * b[1] - a[1] * b[0],
        ]
    };
    // the largest of the three pairwise cross products (two rows may be parallel)
    let mut dir = [
        cross(&g[0], &g[1]),
        cross(&g[0], &g[2]),
        cross(&g[1], &g[2]),
    ]
    .into_iter()
    .max_by(|p, q| norm(p).total_cmp(&norm(q)))?;
    let n = dir.iter().fold(0.0f64, |a, v| a.max(v.abs()));
    if n == 0.0 || !n.is_finite() {
        return None;
    }
    let sign = if dot(&dir, near) < 0.0 { -1.0 } else { 1.0 };
    dir = dir.map(|v| sign * v / n);
    if dot(&dir, near) <= SAME_DIRECTION_COS * norm(near) * norm(&dir) {
        return None; // not the bracket's direction
    }
    grads
        .iter()
        .all(|gr| {
            let gi = at(gr, eta);
            dot(&gi, &dir) <= settings.recession_tol * norm(&gi) * norm(&dir)
        })
        .then_some(dir)
}

/// The gradient row of `kind`'s activation function at (η, β): its β-derivatives of order
/// 0, 1, 2 and, for each, its η-derivative (−∇N/2 for hinges, 0 for sliding). The weight
/// enters only the constant terms, so these are the weightless rows of either weight model.
fn weightless_rows(
    arch: &Arch,
    eta: f64,
    mu: f64,
    kind: ContactKind,
    beta: f64,
) -> [([f64; 3], [f64; 3]); 3] {
    let a = actions(arch, eta, beta);
    [0, 1, 2].map(|order| {
        let g = a.activation(kind, order, eta, mu).g;
        let d_eta = if kind.is_hinge() {
            a.n[order].g.map(|v| -0.5 * v)
        } else {
            [0.0; 3]
        };
        (g, d_eta)
    })
}

/// The local maxima over a continuous arch of every weightless activation function
/// g(η, β)·d, with their normalised values g·d / (|g| |d|).
fn weightless_peaks(
    arch: &Arch,
    eta: f64,
    mu: f64,
    d: &Reactions,
    settings: &Settings,
) -> Vec<(f64, crate::contact::Contact)> {
    use crate::contact::Location;
    let modes = ContactKind::active_at(mu);
    let phi = |beta: f64, orders: usize, _only: Option<usize>| {
        let mut out = [[0.0; 3]; 4];
        for (k, &kind) in modes.iter().enumerate() {
            let rows = weightless_rows(arch, eta, mu, kind, beta);
            for (o, slot) in out[k].iter_mut().enumerate().take(orders) {
                *slot = dot(&rows[o].0, d);
            }
        }
        out
    };
    crate::scan::peaks_over(
        (arch.beta_right(), Location::Springing),
        (arch.beta_left(), Location::Springing),
        modes,
        settings.scan_points,
        &phi,
    )
    .into_iter()
    .map(|p| {
        let g = weightless_rows(arch, eta, mu, p.contact.kind, p.contact.beta)[0].0;
        (
            p.value / (norm(&g) * norm(d)).max(f64::MIN_POSITIVE),
            p.contact,
        )
    })
    .collect()
}

/// Newton on the weightless system of three contacts of a continuous arch: g_i·d = 0 at
/// each, g_i'·d = 0 (tangency) at each free one, and d·d₀ = 1; unknowns d, η and the free
/// angles. `None` when it does not converge.
fn weightless_newton(
    arch: &Arch,
    mu: f64,
    contacts: &[crate::contact::Contact],
    eta0: f64,
    d0: &Reactions,
) -> Option<(f64, Reactions)> {
    use nalgebra::{DMatrix, DVector};
    let free: Vec<usize> = (0..contacts.len()).filter(|&i| contacts[i].free).collect();
    let n = 4 + free.len();
    if contacts.len() + free.len() + 1 != n {
        return None;
    }
    let mut z: Vec<f64> = vec![d0[0], d0[1], d0[2], eta0];
    z.extend(free.iter().map(|&i| contacts[i].beta));
    let dref = *d0;
    let eval = |z: &[f64]| -> (Vec<f64>, DMatrix<f64>) {
        let d = [z[0], z[1], z[2]];
        let eta = z[3];
        let mut f = Vec::with_capacity(n);
        let mut jac = DMatrix::<f64>::zeros(n, n);
        let mut row = 0;
        let mut fr = 0;
        for c in contacts {
            let beta = if c.free { z[4 + fr] } else { c.beta };
            let rows = weightless_rows(arch, eta, mu, c.kind, beta);
            let orders: &[usize] = if c.free { &[0, 1] } else { &[0] };
            for &o in orders {
                f.push(dot(&rows[o].0, &d));
                for k in 0..3 {
                    jac[(row, k)] = rows[o].0[k];
                }
                jac[(row, 3)] = dot(&rows[o].1, &d);
                if c.free {
                    jac[(row, 4 + fr)] = dot(&rows[o + 1].0, &d);
                }
                row += 1;
            }
            if c.free {
                fr += 1;
            }
        }
        f.push(dot(&d, &dref) - 1.0);
        for k in 0..3 {
            jac[(row, k)] = dref[k];
        }
        (f, jac)
    };
    let size = |f: &[f64]| f.iter().fold(0.0f64, |m, v| m.max(v.abs()));
    let (mut f, mut jac) = eval(&z);
    for _ in 0..WEIGHTLESS_NEWTON_STEPS {
        let step = jac
            .clone()
            .lu()
            .solve(&DVector::from_iterator(n, f.iter().map(|v| -v)))?;
        let zn: Vec<f64> = z.iter().zip(step.iter()).map(|(a, b)| a + b).collect();
        let (fnew, jnew) = eval(&zn);
        let moved = step
            .iter()
            .zip(&zn)
            .all(|(s, v)| s.abs() <= WEIGHTLESS_STALL_ULPS * f64::EPSILON * (1.0 + v.abs()));
        let decreased = size(&fnew) < size(&f);
        if !decreased && !moved {
            break;
        }
        z = zn;
        f = fnew;
        jac = jnew;
        if moved {
            break;
        }
    }
    let eta = z[3];
    (size(&f) <= WEIGHTLESS_RESIDUAL && eta > 0.0 && eta.is_finite())
        .then_some((eta, [z[0], z[1], z[2]]))
}

/// η_rec of a continuous arch near `eta0`, where its least states grow without bound along
/// the direction of `x0`: the weightless activation functions at the direction's tightest
/// local maxima (at most six, `MAX_TIGHT_CONTINUOUS`), every three of them refined exactly
/// by Newton (a straight line of thrust touching the intrados or extrados at those points,
/// a free one tangent), and the least η whose direction every joint admits (each local
/// maximum of g·d at most `settings.recession_tol` |g| |d|, by the continuum scan of the
/// weightless functions). `None` when no triple verifies.
pub fn continuum_threshold(
    arch: &Arch,
    mu: f64,
    eta0: f64,
    x0: &Reactions,
    settings: &Settings,
) -> Option<Recession> {
    if !matches!(arch.layout(), JointLayout::Continuous) {
        return None;
    }
    let scale = x0.iter().fold(0.0f64, |a, v| a.max(v.abs()));
    if !(scale > 0.0 && scale.is_finite()) {
        return None;
    }
    let d0 = x0.map(|v| v / scale);
    let mut tight: Vec<(f64, crate::contact::Contact)> =
        weightless_peaks(arch, eta0, mu, &d0, settings)
            .into_iter()
            .filter(|(v, _)| *v >= -settings.recession_candidate_rel)
            .collect();
    tight.sort_by(|a, b| b.0.total_cmp(&a.0));
    tight.truncate(MAX_TIGHT_CONTINUOUS);
    let mut best: Option<Recession> = None;
    for a in 0..tight.len() {
        for b in a + 1..tight.len() {
            for c in b + 1..tight.len() {
                let contacts = [tight[a].1, tight[b].1, tight[c].1];
                let Some((eta, d)) = weightless_newton(arch, mu, &contacts, eta0, &d0) else {
                    continue;
                };
                if best.is_some_and(|r| r.eta <= eta) {
                    continue;
                }
                let admits = weightless_peaks(arch, eta, mu, &d, settings)
                    .iter()
                    .all(|(v, _)| *v <= settings.recession_tol);
                if admits {
                    let s = d.iter().fold(0.0f64, |m, v| m.max(v.abs()));
                    best = Some(Recession {
                        eta,
                        d: d.map(|v| v / s),
                        exact: true,
                    });
                }
            }
        }
    }
    best
}
