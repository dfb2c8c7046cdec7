//! A small self-contained interval arithmetic for certificate verification.
//!
//! Every operation rounds outward by one ulp on each side (`next_down`/`next_up`),
//! which encloses the exact result of the IEEE operation whatever the rounding mode.
//! `sin` and `cos` use the platform's libm, whose error is below 1 ulp on the supported
//! targets (glibc, musl, the Rust std fallbacks); we widen their results by 4 ulp on each
//! side, a margin of 4× over that bound. This keeps the binary portable (no GMP/MPFR, no
//! target-cpu flag) at the price of trusting libm's documented accuracy.

use std::ops::{Add, Mul, Neg, Sub};

/// A closed interval [lo, hi] of reals.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Interval {
    /// Lower end.
    pub lo: f64,
    /// Upper end.
    pub hi: f64,
}

fn down(v: f64) -> f64 {
    v.next_down()
}
fn up(v: f64) -> f64 {
    v.next_up()
}

impl Interval {
    /// The degenerate interval [v, v] (exact: `v` is a float).
    pub fn point(v: f64) -> Interval {
        Interval { lo: v, hi: v }
    }
    /// [lo, hi].
    pub fn new(lo: f64, hi: f64) -> Interval {
        debug_assert!(lo <= hi);
        Interval { lo, hi }
    }
    /// Midpoint.
    pub fn mid(self) -> f64 {
        0.5 * (self.lo + self.hi)
    }
    /// Width.
    pub fn width(self) -> f64 {
        self.hi - self.lo
    }
    /// Multiplication by a float.
    pub fn scale(self, k: f64) -> Interval {
        self * Interval::point(k)
    }
    /// An enclosure of 1/x, for an interval that excludes 0 (`None` otherwise).
    pub fn recip(self) -> Option<Interval> {
        (self.lo > 0.0 || self.hi < 0.0).then(|| Interval {
            lo: down(1.0 / self.hi),
            hi: up(1.0 / self.lo),
        })
    }
    /// The smallest interval holding both.
    pub fn hull(self, o: Interval) -> Interval {
        Interval {
            lo: self.lo.min(o.lo),
            hi: self.hi.max(o.hi),
        }
    }
    /// An enclosure of max(x, y) over x in `self`, y in `o` (exact: no rounding).
    pub fn max(self, o: Interval) -> Interval {
        Interval {
            lo: self.lo.max(o.lo),
            hi: self.hi.max(o.hi),
        }
    }
    /// An enclosure of min(x, y) over x in `self`, y in `o` (exact: no rounding).
    pub fn min(self, o: Interval) -> Interval {
        Interval {
            lo: self.lo.min(o.lo),
            hi: self.hi.min(o.hi),
        }
    }
    /// Whether 0 lies outside the interval.
    pub fn excludes_zero(self) -> bool {
        self.lo > 0.0 || self.hi < 0.0
    }
    /// An enclosure of sin over the interval.
    pub fn sin(self) -> Interval {
        trig(self, f64::sin, std::f64::consts::FRAC_PI_2)
    }
    /// An enclosure of cos over the interval.
    pub fn cos(self) -> Interval {
        trig(self, f64::cos, 0.0)
    }
}

fn widen(v: f64, ulps: usize) -> (f64, f64) {
    let (mut lo, mut hi) = (v, v);
    for _ in 0..ulps {
        lo = down(lo);
        hi = up(hi);
    }
    (lo, hi)
}

/// sin or cos over [lo, hi]: the values at the ends, plus ±1 where a maximum
/// (at `peak` + 2kπ) or minimum (`peak` + π + 2kπ) lies inside.
fn trig(x: Interval, f: fn(f64) -> f64, peak: f64) -> Interval {
    use std::f64::consts::PI;
    let (a_lo, a_hi) = widen(f(x.lo), 4);
    let (b_lo, b_hi) = widen(f(x.hi), 4);
    let mut lo = a_lo.min(b_lo);
    let mut hi = a_hi.max(b_hi);
    let contains = |p: f64| {
        // is some p + 2kπ in [x.lo, x.hi]? (computed loosely: a wider answer is safe)
        let k = ((x.lo - p) / (2.0 * PI)).floor() - 1.0;
        (0..4).any(|j| {
            let t = p + (k + j as f64) * 2.0 * PI;
            t >= x.lo - 1e-9 && t <= x.hi + 1e-9
        })
    };
    if contains(peak) {
        hi = 1.0;
    }
    if contains(peak + PI) {
        lo = -1.0;
    }
    Interval {
        lo: lo.max(-1.0),
        hi: hi.min(1.0),
    }
}

impl Add for Interval {
    type Output = Interval;
    fn add(self, o: Interval) -> Interval {
        Interval {
            lo: down(self.lo + o.lo),
            hi: up(self.hi + o.hi),
        }
    }
}

impl Sub for Interval {
    type Output = Interval;
    fn sub(self, o: Interval) -> Interval {
        Interval {
            lo: down(self.lo - o.hi),
            hi: up(self.hi - o.lo),
        }
    }
}

impl Neg for Interval {
    type Output = Interval;
    fn neg(self) -> Interval {
        Interval {
            lo: -self.hi,
            hi: -self.lo,
        }
    }
}

impl Mul for Interval {
    type Output = Interval;
    fn mul(self, o: Interval) -> Interval {
        let p = [
            self.lo * o.lo,
            self.lo * o.hi,
            self.hi * o.lo,
            self.hi * o.hi,
        ];
        let lo = p.iter().copied().fold(f64::INFINITY, f64::min);
        let hi = p.iter().copied().fold(f64::NEG_INFINITY, f64::max);
        Interval {
            lo: down(lo),
            hi: up(hi),
        }
    }
}

/// The determinant of a 3×3 matrix of intervals (columns).
pub fn det3(c: [[Interval; 3]; 3]) -> Interval {
    let m = |r: usize, k: usize| c[k][r];
    m(0, 0) * (m(1, 1) * m(2, 2) - m(1, 2) * m(2, 1))
        - m(0, 1) * (m(1, 0) * m(2, 2) - m(1, 2) * m(2, 0))
        + m(0, 2) * (m(1, 0) * m(2, 1) - m(1, 1) * m(2, 0))
}

/// The determinant of a 4×4 matrix of intervals (columns), by expansion along the
/// first row.
pub fn det4(c: [[Interval; 4]; 4]) -> Interval {
    let minor = |skip: usize| {
        let cols: Vec<usize> = (0..4).filter(|&k| k != skip).collect();
        det3([0, 1, 2].map(|k| [1, 2, 3].map(|r| c[cols[k]][r])))
    };
    c[0][0] * minor(0) - c[1][0] * minor(1) + c[2][0] * minor(2) - c[3][0] * minor(3)
}

/// The determinant of a 2×2 matrix of intervals (columns).
pub fn det2(c: [[Interval; 2]; 2]) -> Interval {
    c[0][0] * c[1][1] - c[1][0] * c[0][1]
}
