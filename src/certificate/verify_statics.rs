//! The statics of a certificate's arch in interval arithmetic, for `verify` (formulation
//! §3, written out again from the formulas, not the solver's [`crate::statics`]): N, T, M
//! and their β-derivatives, the activation functions, their affine form in x, and the proof
//! that they are ≤ 0 over pieces of the arch (Taylor enclosures) or at listed joints.

use super::format::ContactKind;
use super::interval::Interval as I;
use super::verify::{reject, Rejection};

/// The geometry and weight of the certificate's arch, for interval evaluation.
pub(super) struct Model {
    pub(super) beta_r: f64,
    pub(super) beta_l: f64,
    pub(super) centroid: bool,
    pub(super) joints: Option<Vec<f64>>,
}

/// Interval values of N, T, M and their first two β-derivatives at β ∈ `b`.
#[derive(Clone, Copy)]
pub(super) struct Ntm {
    pub(super) n: [I; 3],
    pub(super) t: [I; 3],
    pub(super) m: [I; 3],
}

impl Default for Ntm {
    /// All zero.
    fn default() -> Ntm {
        let z = I::point(0.0);
        Ntm {
            n: [z; 3],
            t: [z; 3],
            m: [z; 3],
        }
    }
}

impl Ntm {
    /// `self + k·o`, term by term (the dead actions plus λ times the live ones).
    pub(super) fn plus(&self, k: f64, o: &Ntm) -> Ntm {
        let k = I::point(k);
        let add = |a: [I; 3], b: [I; 3]| [0, 1, 2].map(|i| a[i] + k * b[i]);
        Ntm {
            n: add(self.n, o.n),
            t: add(self.t, o.t),
            m: add(self.m, o.m),
        }
    }
}

impl Model {
    /// A joint angle must be finite, inside [β_R, β_L], and for a discrete arch one of
    /// its listed joints.
    pub(super) fn check_joint(&self, beta: f64, what: &str) -> Result<(), Rejection> {
        if !(beta.is_finite() && beta >= self.beta_r && beta <= self.beta_l) {
            return reject(format!(
                "{what}: beta = {beta} lies outside the arch [beta_right, beta_left] = [{}, {}]",
                self.beta_r, self.beta_l
            ));
        }
        if let Some(js) = &self.joints {
            if !js.contains(&beta) {
                return reject(format!(
                    "{what}: beta = {beta} is not one of the joint_angles of this discrete arch"
                ));
            }
        }
        Ok(())
    }

    pub(super) fn rho(&self, eta: f64) -> I {
        if self.centroid {
            let e = I::point(eta);
            I::point(1.0) + e * e * I::new((1.0f64 / 12.0).next_down(), (1.0f64 / 12.0).next_up())
        } else {
            I::point(1.0)
        }
    }

    /// N, T, M of the reactions x alone (no weight): the linear part of the statics,
    /// N = h sin β + v cos β, T = h cos β − v sin β, M = −h (sin β − sin β_R) +
    /// v (cos β_R − cos β) + w, with dN = T, dT = −N, dM = −T.
    pub(super) fn ntm_weightless(&self, b: I, x: [f64; 3]) -> Ntm {
        let (h, v, w) = (I::point(x[0]), I::point(x[1]), I::point(x[2]));
        let (s, c) = (b.sin(), b.cos());
        let br = I::point(self.beta_r);
        let (sr, cr) = (br.sin(), br.cos());
        let n0 = h * s + v * c;
        let t0 = h * c - v * s;
        let m0 = -(h * (s - sr)) + v * (cr - c) + w;
        Ntm {
            n: [n0, t0, -n0],
            t: [t0, -n0, -t0],
            m: [m0, -t0, n0],
        }
    }

    pub(super) fn ntm(&self, b: I, x: [f64; 3], eta: f64) -> Ntm {
        let (h, v, w) = (I::point(x[0]), I::point(x[1]), I::point(x[2]));
        let (s, c) = (b.sin(), b.cos());
        let br = I::point(self.beta_r);
        let (sr, cr) = (br.sin(), br.cos());
        let d = b - br;
        let rho = self.rho(eta);
        let one = I::point(1.0);
        let two = I::point(2.0);
        let n0 = h * s + v * c - d * c;
        let t0 = h * c - v * s + d * s;
        let m0 = -(h * (s - sr)) + v * (cr - c) + w + d * c - rho * (s - sr);
        let n1 = t0 - c;
        let t1 = -n0 + s;
        let m1 = -t0 + (one - rho) * c;
        let n2 = two * s - n0;
        let t2 = two * c - t0;
        let m2 = n0 - (two - rho) * s;
        Ntm {
            n: [n0, n1, n2],
            t: [t0, t1, t2],
            m: [m0, m1, m2],
        }
    }
}

/// Whether the activation function `kind` exists at friction `mu` (`None` = ∞: hinges only).
pub(super) fn exists(kind: ContactKind, mu: Option<f64>) -> bool {
    kind.is_hinge() || mu.is_some()
}

/// φ of `kind` (β-derivative `k`). Sliding rows need a finite μ: callers check
/// [`exists`] first, and a sliding row at μ = ∞ evaluates to an unbounded interval.
pub(super) fn phi(kind: ContactKind, k: usize, a: &Ntm, eta: f64, mu: Option<f64>) -> I {
    let he = I::point(eta) * I::point(0.5);
    let slide = |sign: f64| match mu {
        Some(mu) => a.t[k].scale(sign) - I::point(mu) * a.n[k],
        None => I::new(f64::NEG_INFINITY, f64::INFINITY),
    };
    match kind {
        ContactKind::HingeExtrados => a.m[k] - he * a.n[k],
        ContactKind::HingeIntrados => -a.m[k] - he * a.n[k],
        ContactKind::SlidePlus => slide(1.0),
        ContactKind::SlideMinus => slide(-1.0),
    }
}

/// The activation functions that exist at friction `mu` (`None` = ∞).
pub(super) fn kinds(mu: Option<f64>) -> &'static [ContactKind] {
    match mu {
        Some(_) => &ContactKind::ALL,
        None => &ContactKind::HINGES,
    }
}

/// Upper bound of φ over [a, b] by the second-order Taylor form at the midpoint
/// (`eval`: the actions over an interval of angles).
fn taylor_upper(
    eval: &dyn Fn(I) -> Ntm,
    kind: ContactKind,
    a: f64,
    b: f64,
    eta: f64,
    mu: Option<f64>,
) -> (f64, f64) {
    let m = 0.5 * (a + b);
    let r = (b - m).max(m - a);
    let at_m = eval(I::point(m));
    let over = eval(I::new(a, b));
    let f0 = phi(kind, 0, &at_m, eta, mu);
    let f1 = phi(kind, 1, &at_m, eta, mu);
    let f2 = phi(kind, 2, &over, eta, mu);
    let p = f1.lo.abs().max(f1.hi.abs());
    let q = f2.hi;
    // max over |t| ≤ r of p|t| + q t²/2
    let g = |t: f64| p * t + 0.5 * q * t * t;
    let mut best = g(r).max(0.0);
    if q < 0.0 {
        let t = (p / -q).min(r);
        best = best.max(g(t));
    }
    // a little slack for the rounding of this final bound
    let upper = (f0.hi + best * (1.0 + 1e-12)).next_up();
    (upper, f0.lo)
}

/// Proves φ ≤ 0 for every activation function over the arch at (η, x).
/// With `strict`, proves φ < 0 instead (the state lies in the interior of P(η)).
pub(super) fn prove_admissible(
    model: &Model,
    x: [f64; 3],
    eta: f64,
    mu: Option<f64>,
    strict: bool,
) -> Result<usize, Rejection> {
    let eval = |b: I| model.ntm(b, x, eta);
    let whole = Piece {
        a: model.beta_r,
        b: model.beta_l,
        eval: &eval,
    };
    prove_pieces(model, &[whole], eta, mu, kinds(mu), strict, "safe side")
}

/// A smooth piece [a, b] of the arch and its actions over an interval of angles (the
/// sections of one side of a loaded section, for a point load).
pub(super) struct Piece<'a> {
    /// First angle.
    pub(super) a: f64,
    /// Last angle.
    pub(super) b: f64,
    /// N, T, M and their β-derivatives over an interval of angles inside [a, b].
    pub(super) eval: &'a dyn Fn(I) -> Ntm,
}

/// Proves φ ≤ 0 (φ < 0 with `strict`) for the activation functions `kinds` on every
/// piece: at each listed joint inside it (discrete arch), else over its whole continuum of
/// angles (Taylor enclosures, adaptive splitting). `what` starts the rejection messages.
pub(super) fn prove_pieces(
    model: &Model,
    pieces: &[Piece],
    eta: f64,
    mu: Option<f64>,
    kinds: &[ContactKind],
    strict: bool,
    what: &str,
) -> Result<usize, Rejection> {
    let mut count = 0usize;
    for &kind in kinds {
        for piece in pieces {
            let eval = piece.eval;
            if let Some(joints) = &model.joints {
                for &b in joints.iter().filter(|&&b| b >= piece.a && b <= piece.b) {
                    let v = phi(kind, 0, &eval(I::point(b)), eta, mu);
                    if v.hi.is_nan() || v.hi > 0.0 || (strict && v.hi >= 0.0) {
                        return reject(format!("{what}: {} at the joint beta = {b} is not proved <= 0 (upper bound {:e})", kind.name(), v.hi));
                    }
                    count += 1;
                }
                continue;
            }
            let n0 = 64;
            let (lo, hi) = (piece.a, piece.b);
            let mut stack: Vec<(f64, f64, usize)> = (0..n0)
                .map(|i| {
                    let a = if i == 0 {
                        lo
                    } else {
                        lo + (hi - lo) * i as f64 / n0 as f64
                    };
                    let b = if i + 1 == n0 {
                        hi
                    } else {
                        lo + (hi - lo) * (i + 1) as f64 / n0 as f64
                    };
                    (a, b, 0)
                })
                .collect();
            while let Some((a, b, depth)) = stack.pop() {
                count += 1;
                if count > 2_000_000 {
                    return reject(format!(
                        "{what}: enclosure work limit reached without a proof"
                    ));
                }
                let (upper, lower_mid) = taylor_upper(eval, kind, a, b, eta, mu);
                if upper < 0.0 || (!strict && upper <= 0.0) {
                    continue;
                }
                if lower_mid > 0.0 {
                    return reject(format!(
                        "{what}: {} is positive at beta = {} (phi >= {lower_mid:e}): the state is not admissible",
                        kind.name(),
                        0.5 * (a + b)
                    ));
                }
                if depth >= 60 || b - a <= 4.0 * f64::EPSILON * a.abs().max(1.0) || upper.is_nan() {
                    return reject(format!(
                        "{what}: {} near beta = {a} could not be proved <= 0 (bound {upper:e})",
                        kind.name()
                    ));
                }
                let m = 0.5 * (a + b);
                stack.push((a, m, depth + 1));
                stack.push((m, b, depth + 1));
            }
        }
    }
    Ok(count)
}

/// Interval gradient (w.r.t. x) and constant term of an activation function at β.
pub(super) fn affine(
    model: &Model,
    kind: ContactKind,
    beta: f64,
    eta: f64,
    mu: f64,
) -> ([I; 3], I) {
    let b = I::point(beta);
    let (s, c) = (b.sin(), b.cos());
    let br = I::point(model.beta_r);
    let (sr, cr) = (br.sin(), br.cos());
    let d = b - br;
    let rho = model.rho(eta);
    let z = I::point(0.0);
    let gn = [s, c, z];
    let gt = [c, -s, z];
    let gm = [-(s - sr), cr - c, I::point(1.0)];
    let (n0, t0, m0) = (-(d * c), d * s, d * c - rho * (s - sr));
    let he = I::point(0.5) * I::point(eta);
    let m = I::point(mu);
    let comb = |a: I, g1: [I; 3], c1: I, k: I, g2: [I; 3], c2: I| {
        (
            [
                a * g1[0] + k * g2[0],
                a * g1[1] + k * g2[1],
                a * g1[2] + k * g2[2],
            ],
            a * c1 + k * c2,
        )
    };
    match kind {
        ContactKind::HingeExtrados => comb(I::point(1.0), gm, m0, -he, gn, n0),
        ContactKind::HingeIntrados => comb(I::point(-1.0), gm, m0, -he, gn, n0),
        ContactKind::SlidePlus => comb(I::point(1.0), gt, t0, -m, gn, n0),
        ContactKind::SlideMinus => comb(I::point(-1.0), gt, t0, -m, gn, n0),
    }
}
