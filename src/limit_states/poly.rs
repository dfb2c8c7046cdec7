//! Small real polynomials in η (degree ≤ ~8) and all their real roots in an interval.
//!
//! Along the path of a vertex of the admissible set, every activation function is a
//! rational function of η whose numerator is a polynomial of degree ≤ 5 (formulation §3:
//! the gradients are affine in η, the constant terms at most quadratic). Its roots are the
//! events of the sweep, found here without sampling: the roots of p′ cut the interval into
//! pieces on which p is monotone, and each piece holds at most one root (bisection, then
//! the bracket is narrowed to adjacent floats).

/// The most coefficients a polynomial of the sweep has (degree ≤ 11; the sweep's reach
/// degree 5, products in tests degree 7).
pub const MAX_COEFFS: usize = 12;

/// Trailing coefficients below this fraction of the largest are the rounding residue of
/// cancelled terms: the root finder drops them (of the polynomial and of its derivative).
const TRIM_REL: f64 = 1e-14;

/// A value of a polynomial at most this times its size on the interval (largest
/// coefficient × (1 + largest |end|)^degree) is zero: a root at that point.
const NEAR_ZERO_REL: f64 = 1e-13;

/// Roots closer than this (relative to 1 + |root|) are one root.
const SAME_ROOT_REL: f64 = 1e-12;

/// Bisection of a monotone piece stops at adjacent floats, or after this many halvings.
const BISECTION_MAX_STEPS: usize = 200;

/// Coefficients, lowest order first, in a fixed array (no allocation: the sweep builds
/// millions of these).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Poly {
    c: [f64; MAX_COEFFS],
    n: usize,
}

impl Poly {
    /// The polynomial with coefficients `c`, lowest order first (at most
    /// [`MAX_COEFFS`]; panics beyond, a programming error).
    pub fn from_coeffs(c: &[f64]) -> Poly {
        assert!(
            c.len() <= MAX_COEFFS,
            "polynomial of degree {} too large",
            c.len()
        );
        let mut p = Poly {
            c: [0.0; MAX_COEFFS],
            n: c.len(),
        };
        p.c[..c.len()].copy_from_slice(c);
        p
    }

    /// The coefficients, lowest order first.
    pub fn coeffs(&self) -> &[f64] {
        &self.c[..self.n]
    }

    /// The constant polynomial `c`.
    pub fn constant(c: f64) -> Poly {
        Poly::from_coeffs(&[c])
    }

    /// a + b η.
    pub fn linear(a: f64, b: f64) -> Poly {
        Poly::from_coeffs(&[a, b])
    }

    /// Value at `t` (Horner).
    #[inline]
    pub fn eval(&self, t: f64) -> f64 {
        self.coeffs().iter().rev().fold(0.0, |acc, &c| acc * t + c)
    }

    /// Sum.
    pub fn add(&self, o: &Poly) -> Poly {
        let mut r = Poly {
            c: [0.0; MAX_COEFFS],
            n: self.n.max(o.n),
        };
        for i in 0..r.n {
            r.c[i] = self.c[i] + o.c[i];
        }
        r
    }

    /// Difference.
    pub fn sub(&self, o: &Poly) -> Poly {
        let mut r = Poly {
            c: [0.0; MAX_COEFFS],
            n: self.n.max(o.n),
        };
        for i in 0..r.n {
            r.c[i] = self.c[i] - o.c[i];
        }
        r
    }

    /// Product.
    pub fn mul(&self, o: &Poly) -> Poly {
        if self.n == 0 || o.n == 0 {
            return Poly::from_coeffs(&[]);
        }
        let n = self.n + o.n - 1;
        assert!(n <= MAX_COEFFS, "product of degree {} too large", n - 1);
        let mut r = Poly {
            c: [0.0; MAX_COEFFS],
            n,
        };
        for i in 0..self.n {
            for j in 0..o.n {
                r.c[i + j] += self.c[i] * o.c[j];
            }
        }
        r
    }

    /// a₀b₀ + a₁b₁ + …: the same sums in the same order as folding [`Poly::mul`] and
    /// [`Poly::add`] over the terms (so the same bits), without the intermediate
    /// polynomials.
    pub fn sum_of_products<const N: usize>(terms: [(&Poly, &Poly); N]) -> Poly {
        let mut acc = Poly {
            c: [0.0; MAX_COEFFS],
            n: 0,
        };
        for (k, (a, b)) in terms.into_iter().enumerate() {
            let mut prod = [0.0; MAX_COEFFS];
            let n = if a.n == 0 || b.n == 0 {
                0
            } else {
                a.n + b.n - 1
            };
            assert!(n <= MAX_COEFFS, "product of degree {} too large", n - 1);
            if n > 0 {
                let bs = b.coeffs();
                for (i, &ai) in a.coeffs().iter().enumerate() {
                    for (p, &bj) in prod[i..i + bs.len()].iter_mut().zip(bs) {
                        *p += ai * bj;
                    }
                }
            }
            if k == 0 {
                acc = Poly { c: prod, n };
            } else {
                acc.n = acc.n.max(n);
                for (s, &p) in acc.c[..acc.n].iter_mut().zip(&prod) {
                    *s += p;
                }
            }
        }
        acc
    }

    /// `k` times the polynomial.
    pub fn scale(&self, k: f64) -> Poly {
        let mut r = *self;
        for v in r.c[..r.n].iter_mut() {
            *v *= k;
        }
        r
    }

    /// Derivative.
    pub fn derivative(&self) -> Poly {
        let mut r = Poly {
            c: [0.0; MAX_COEFFS],
            n: self.n.saturating_sub(1),
        };
        for i in 1..self.n {
            r.c[i - 1] = i as f64 * self.c[i];
        }
        r
    }

    /// Largest |coefficient|.
    pub fn norm(&self) -> f64 {
        self.coeffs().iter().fold(0.0, |m, c| m.max(c.abs()))
    }

    /// How many of the lowest coefficients are exactly zero (the order of the root at 0;
    /// 0 for the zero polynomial).
    pub fn zero_order(&self) -> usize {
        self.coeffs()
            .iter()
            .position(|&c| c != 0.0)
            .unwrap_or_default()
    }

    /// The polynomial divided by η^k (its `k` lowest coefficients dropped: exact when they
    /// are zero, see [`Poly::zero_order`]).
    pub fn shifted_down(&self, k: usize) -> Poly {
        let k = k.min(self.n);
        Poly::from_coeffs(&self.coeffs()[k..])
    }

    /// The polynomial without trailing coefficients below `tol` × its norm (they are
    /// rounding residue of cancelled terms).
    pub fn trimmed(&self, tol: f64) -> Poly {
        let floor = tol * self.norm();
        let mut r = *self;
        while r.n > 0 && r.c[r.n - 1].abs() <= floor {
            r.n -= 1;
            r.c[r.n] = 0.0;
        }
        r
    }

    /// Bounds of the polynomial over [lo, hi]: the least and largest of its Bernstein
    /// coefficients there (the range lies between them).
    pub fn bernstein_bounds(&self, lo: f64, hi: f64) -> (f64, f64) {
        let n = self.n;
        if n == 0 {
            return (0.0, 0.0);
        }
        let c = self.unit_scaled(lo, hi, n - 1);
        let mut row = PASCAL_START;
        (0..n).fold((f64::INFINITY, f64::NEG_INFINITY), |(lo_b, hi_b), i| {
            let b = bernstein_next(&mut row, &c, i);
            (lo_b.min(b), hi_b.max(b))
        })
    }

    /// Whether every Bernstein coefficient of the polynomial over [lo, hi] has the strict
    /// sign of `sign` (±1; anything else: no), so that the polynomial has that sign on the
    /// whole interval: the decision of `sign`·[`Poly::bernstein_bounds`] (the least > 0), taken with less work.
    /// In t ∈ [0, 1] the Bernstein coefficients are b_i = Σ_{k≤i} C(i,k) a_k with b_0 = a_0,
    /// and a_k has the sign of the k-th coefficient in η − lo (times w^k / C(deg, k), w > 0).
    /// Where sign·a_0 > 0 and no sign·a_k is negative, every product has a_k's sign and
    /// every sum keeps a_0's in floating point too (adding terms of one sign never crosses
    /// zero), so the answer is yes without the sums; otherwise they are formed in turn up to
    /// the first that fails. (A NaN coefficient is passed over, as the bounds' min and max
    /// pass it over.)
    pub fn bernstein_sign(&self, lo: f64, hi: f64, sign: f64) -> bool {
        let n = self.n;
        if n == 0 || !(sign == 1.0 || sign == -1.0) {
            return false;
        }
        // the signs of the coefficients in s = η − lo are those in t (s = w t with w > 0
        // scales a_k by w^k, and C(deg, k) > 0 divides it)
        let mut c = self.taylor_at(lo, n - 1);
        let w = hi - lo;
        if w > 0.0 && sign * c[0] > 0.0 && c[1..n].iter().all(|&a| sign * a >= 0.0) {
            return true;
        }
        unit_scale(&mut c, w, n - 1);
        let mut row = PASCAL_START;
        (0..n).all(|i| {
            let b = sign * bernstein_next(&mut row, &c, i);
            b > 0.0 || b.is_nan()
        })
    }

    /// The Bernstein coefficients of degree `deg` (at least the polynomial's degree, less
    /// than [`MAX_COEFFS`]) over [lo, hi], the first `deg + 1` entries: a linear function of
    /// the coefficients.
    pub fn bernstein(&self, lo: f64, hi: f64, deg: usize) -> [f64; MAX_COEFFS] {
        let c = self.unit_scaled(lo, hi, deg);
        let mut row = PASCAL_START;
        let mut out = [0.0; MAX_COEFFS];
        for (i, o) in out[..=deg].iter_mut().enumerate() {
            *o = bernstein_next(&mut row, &c, i);
        }
        out
    }

    /// The coefficients a_k / C(deg, k) in t ∈ [0, 1], η = lo + (hi − lo) t, from which the
    /// Bernstein coefficients of degree `deg` over [lo, hi] are b_i = Σ_{k≤i} C(i,k) a_k /
    /// C(deg,k) ([`bernstein_next`]).
    #[inline]
    fn unit_scaled(&self, lo: f64, hi: f64, deg: usize) -> [f64; MAX_COEFFS] {
        let mut c = self.taylor_at(lo, deg);
        unit_scale(&mut c, hi - lo, deg);
        c
    }

    /// The coefficients in s = η − lo, the first `deg + 1` (at least the polynomial's
    /// degree + 1, at most [`MAX_COEFFS`]; a Horner-like shift).
    #[inline]
    fn taylor_at(&self, lo: f64, deg: usize) -> [f64; MAX_COEFFS] {
        let n = deg + 1;
        assert!(n >= self.n && n <= MAX_COEFFS, "Bernstein degree {deg}");
        let mut c = self.c;
        for k in 0..n {
            for j in (k..n - 1).rev() {
                c[j] += lo * c[j + 1];
            }
        }
        c
    }

    /// The polynomial times t^k (its degree stays below [`MAX_COEFFS`]).
    pub fn shifted_up(&self, k: usize) -> Poly {
        assert!(self.n + k <= MAX_COEFFS, "degree too large");
        let mut r = Poly {
            c: [0.0; MAX_COEFFS],
            n: if self.n == 0 { 0 } else { self.n + k },
        };
        r.c[k..k + self.n].copy_from_slice(&self.c[..self.n]);
        r
    }

    /// Every real root in the closed interval [lo, hi], ascending, each once; roots of even
    /// multiplicity (touching zero) are included. `None` when the polynomial vanishes
    /// identically (all coefficients below `zero_tol` × `scale`).
    pub fn roots_in(&self, lo: f64, hi: f64, zero_tol: f64, scale: f64) -> Option<Vec<f64>> {
        let p = self.trimmed(TRIM_REL);
        if p.norm() <= zero_tol * scale {
            return None;
        }
        Some(real_roots(&p, lo, hi))
    }
}

/// Pascal's triangle for the Bernstein coefficients b_i = Σ_{k≤i} C(i,k) c_k of the
/// coefficients c of [`Poly::unit_scaled`]: `row` holds C(i − 1, ·) (start: [`PASCAL_START`])
/// and becomes C(i, ·), and b_i is returned. Called for i = 0, 1, … in turn: one
/// implementation for the coefficients, their bounds and their sign.
#[inline]
fn bernstein_next(row: &mut [f64; MAX_COEFFS], c: &[f64; MAX_COEFFS], i: usize) -> f64 {
    for k in (1..=i).rev() {
        row[k] += row[k - 1];
    }
    (0..=i).map(|k| row[k] * c[k]).sum()
}

/// The row C(0, ·) of [`bernstein_next`].
const PASCAL_START: [f64; MAX_COEFFS] = {
    let mut r = [0.0; MAX_COEFFS];
    r[0] = 1.0;
    r
};

/// Coefficients in s = η − lo to those of [`Poly::unit_scaled`]: times w^k (t = s / w),
/// divided by C(deg, k).
#[inline]
fn unit_scale(c: &mut [f64; MAX_COEFFS], w: f64, deg: usize) {
    let mut scale = 1.0;
    for ck in c[..=deg].iter_mut() {
        *ck *= scale;
        scale *= w;
    }
    let mut cdeg = 1.0;
    for (k, ck) in c[..=deg].iter_mut().enumerate() {
        *ck /= cdeg;
        cdeg = cdeg * (deg - k) as f64 / (k + 1) as f64;
    }
}

fn real_roots(p: &Poly, lo: f64, hi: f64) -> Vec<f64> {
    let deg = p.n.saturating_sub(1);
    if deg == 0 {
        return vec![];
    }
    if deg == 1 {
        let r = -p.c[0] / p.c[1];
        return if r >= lo && r <= hi { vec![r] } else { vec![] };
    }
    // critical points split [lo, hi] into monotone pieces
    let mut cuts = vec![lo];
    cuts.extend(real_roots(&p.derivative().trimmed(TRIM_REL), lo, hi));
    cuts.push(hi);
    let scale = p.norm() * (1.0 + lo.abs().max(hi.abs())).powi(deg as i32);
    let near_zero = |v: f64| v.abs() <= NEAR_ZERO_REL * scale;
    let mut roots: Vec<f64> = Vec::new();
    for w in cuts.windows(2) {
        let (a, b) = (w[0], w[1]);
        let (fa, fb) = (p.eval(a), p.eval(b));
        if near_zero(fa) {
            roots.push(a);
        }
        if fa.signum() != fb.signum() && !near_zero(fa) && !near_zero(fb) {
            roots.push(bisect(p, a, b, fa));
        }
        if near_zero(fb) {
            roots.push(b);
        }
    }
    roots.sort_by(f64::total_cmp);
    roots.dedup_by(|a, b| (*a - *b).abs() <= SAME_ROOT_REL * (1.0 + a.abs()));
    roots
}

/// The root of a monotone piece with a sign change, to adjacent floats.
fn bisect(p: &Poly, mut a: f64, mut b: f64, mut fa: f64) -> f64 {
    for _ in 0..BISECTION_MAX_STEPS {
        let m = 0.5 * (a + b);
        if m <= a || m >= b {
            break;
        }
        let fm = p.eval(m);
        if fm == 0.0 {
            return m;
        }
        if fm.signum() == fa.signum() {
            a = m;
            fa = fm;
        } else {
            b = m;
        }
    }
    0.5 * (a + b)
}
