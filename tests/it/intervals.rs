//! The interval arithmetic of the certificate verifier (`certificate::interval`), on
//! seeded random intervals: every enclosure (sum, difference, negation, product, scale,
//! sin, cos, det2, det3, det4) contains the float value of the same expression at sample points
//! of its inputs (by induction over the expression, an outward-rounded enclosure must
//! contain every float evaluation of it; sums and products are also checked against the
//! exact real result, via TwoSum and FMA), and is not absurdly wide: never wider than a
//! first-order bound of the true range plus a few ulps.

use arch_enum::certificate::interval::{det2, det3, det4, Interval as I};
use proptest::prelude::*;
use proptest::test_runner::RngSeed;

/// Slack for the width bounds: a few ulps of the magnitudes involved.
fn ulps(scale: f64) -> f64 {
    16.0 * f64::EPSILON * (1.0 + scale)
}

/// An interval from a centre and a width.
fn iv(c: f64, w: f64) -> I {
    I::new(c - 0.5 * w, c + 0.5 * w)
}

/// `n` + 1 evenly spaced points of `x`, ends included.
fn samples(x: I, n: usize) -> Vec<f64> {
    (0..=n)
        .map(|i| {
            let t = i as f64 / n as f64;
            (x.lo + t * (x.hi - x.lo)).clamp(x.lo, x.hi)
        })
        .collect()
}

fn contains(x: I, v: f64) -> bool {
    x.lo <= v && v <= x.hi
}

/// Whether the exact real p + e (p a float, e its error term) lies in `x`.
fn contains_exact(x: I, p: f64, e: f64) -> bool {
    (x.lo < p || (x.lo == p && e >= 0.0)) && (p < x.hi || (p == x.hi && e <= 0.0))
}

/// x·y exactly, as a float and its error (FMA).
fn two_prod(x: f64, y: f64) -> (f64, f64) {
    let p = x * y;
    (p, x.mul_add(y, -p))
}

/// x + y exactly, as a float and its error (Knuth's TwoSum).
fn two_sum(x: f64, y: f64) -> (f64, f64) {
    let s = x + y;
    let bb = s - x;
    (s, (x - (s - bb)) + (y - bb))
}

fn mag(x: I) -> f64 {
    x.lo.abs().max(x.hi.abs())
}

/// Centre/width pairs: widths from 0 (a point) to wide, centres of either sign.
fn interval() -> impl Strategy<Value = I> {
    (
        -20.0f64..20.0,
        prop_oneof![Just(0.0), 0.0f64..1e-6, 0.0f64..0.5, 0.0f64..14.0],
    )
        .prop_map(|(c, w)| iv(c, w))
}

fn config() -> ProptestConfig {
    ProptestConfig {
        cases: 256,
        rng_seed: RngSeed::Fixed(20_240_917),
        ..ProptestConfig::default()
    }
}

proptest! {
    #![proptest_config(config())]

    #[test]
    fn arithmetic_encloses_and_is_tight(a in interval(), b in interval(), k in -5.0f64..5.0) {
        let (sum, diff, prod, neg, sc) = (a + b, a - b, a * b, -a, a.scale(k));
        for &x in &samples(a, 12) {
            prop_assert!(contains(neg, -x));
            prop_assert!(contains(sc, x * k), "{sc:?} misses {x} * {k}");
            for &y in &samples(b, 12) {
                prop_assert!(contains(sum, x + y), "{sum:?} misses {x} + {y}");
                prop_assert!(contains(diff, x - y), "{diff:?} misses {x} - {y}");
                prop_assert!(contains(prod, x * y), "{prod:?} misses {x} * {y}");
                // and the exact real results, not only their roundings
                let (p, e) = two_sum(x, y);
                prop_assert!(contains_exact(sum, p, e), "{sum:?} misses the exact {x} + {y}");
                let (p, e) = two_sum(x, -y);
                prop_assert!(contains_exact(diff, p, e), "{diff:?} misses the exact {x} - {y}");
                let (p, e) = two_prod(x, y);
                prop_assert!(contains_exact(prod, p, e), "{prod:?} misses the exact {x} * {y}");
            }
        }
        let s = mag(a) + mag(b);
        prop_assert!(sum.width() <= a.width() + b.width() + ulps(s));
        prop_assert!(diff.width() <= a.width() + b.width() + ulps(s));
        prop_assert!(neg.width() == a.width());
        prop_assert!(
            prod.width() <= mag(a) * b.width() + mag(b) * a.width() + ulps(mag(a) * mag(b)),
            "{a:?} * {b:?} = {prod:?} too wide"
        );
        prop_assert!(sc.width() <= k.abs() * a.width() + ulps(k.abs() * mag(a)));
    }

    #[test]
    fn sin_cos_enclose_and_are_tight(a in interval()) {
        let (s, c) = (a.sin(), a.cos());
        for &x in &samples(a, 400) {
            prop_assert!(contains(s, x.sin()), "sin {a:?} = {s:?} misses sin({x}) = {}", x.sin());
            prop_assert!(contains(c, x.cos()), "cos {a:?} = {c:?} misses cos({x}) = {}", x.cos());
        }
        // |sin'| <= 1: the range is no wider than the input, nor than [-1, 1]
        let bound = a.width().min(2.0) + 1e-14;
        prop_assert!(s.width() <= bound, "sin {a:?} = {s:?} too wide");
        prop_assert!(c.width() <= bound, "cos {a:?} = {c:?} too wide");
        prop_assert!(s.lo >= -1.0 && s.hi <= 1.0 && c.lo >= -1.0 && c.hi <= 1.0);
    }

    #[test]
    fn determinants_enclose_and_are_tight(
        cs in proptest::collection::vec((-3.0f64..3.0, prop_oneof![Just(0.0), 0.0f64..1e-9, 0.0f64..0.1]), 9),
        picks in proptest::collection::vec(0usize..7, 64),
    ) {
        let m: Vec<I> = cs.iter().map(|&(c, w)| iv(c, w)).collect();
        let col = |k: usize| [m[3 * k], m[3 * k + 1], m[3 * k + 2]];
        let d3 = det3([col(0), col(1), col(2)]);
        let d2 = det2([[m[0], m[1]], [m[3], m[4]]]);
        // sample matrices: each entry at one of 7 points of its interval
        for s in picks.chunks(9).filter(|s| s.len() == 9) {
            let v: Vec<f64> = (0..9).map(|i| samples(m[i], 6)[s[i]]).collect();
            let e = |r: usize, k: usize| v[3 * k + r];
            // the float determinant by the same expansion as det3 (columns)
            let f3 = e(0, 0) * (e(1, 1) * e(2, 2) - e(1, 2) * e(2, 1))
                - e(0, 1) * (e(1, 0) * e(2, 2) - e(1, 2) * e(2, 0))
                + e(0, 2) * (e(1, 0) * e(2, 1) - e(1, 1) * e(2, 0));
            prop_assert!(contains(d3, f3), "det3 {d3:?} misses {f3}");
            let f2 = v[0] * v[4] - v[3] * v[1];
            prop_assert!(contains(d2, f2), "det2 {d2:?} misses {f2}");
        }
        // width: first-order bound, Σ |∂det/∂m_i| w_i with magnitudes, plus ulps
        let w: f64 = m.iter().map(|x| x.width()).sum();
        let big = m.iter().map(|&x| mag(x)).fold(0.0, f64::max) + w;
        prop_assert!(d3.width() <= 6.0 * big * big * w + ulps(6.0 * big.powi(3)), "det3 {d3:?} too wide");
        prop_assert!(d2.width() <= 2.0 * big * w + ulps(2.0 * big * big), "det2 {d2:?} too wide");
    }

    #[test]
    fn det4_encloses_and_is_tight(
        cs in proptest::collection::vec((-3.0f64..3.0, prop_oneof![Just(0.0), 0.0f64..1e-9, 0.0f64..0.1]), 16),
        picks in proptest::collection::vec(0usize..7, 64),
    ) {
        let m: Vec<I> = cs.iter().map(|&(c, w)| iv(c, w)).collect();
        let col = |k: usize| [m[4 * k], m[4 * k + 1], m[4 * k + 2], m[4 * k + 3]];
        let d4 = det4([col(0), col(1), col(2), col(3)]);
        for s in picks.chunks(16).filter(|s| s.len() == 16) {
            let v: Vec<f64> = (0..16).map(|i| samples(m[i], 6)[s[i]]).collect();
            let e = |r: usize, k: usize| v[4 * k + r];
            // the float determinant by the same expansion as det4: along the first row,
            // each minor (rows 1..3, the other columns) by det3's expansion
            let minor = |skip: usize| {
                let c: Vec<usize> = (0..4).filter(|&k| k != skip).collect();
                let f = |r: usize, k: usize| e(r + 1, c[k]);
                f(0, 0) * (f(1, 1) * f(2, 2) - f(1, 2) * f(2, 1))
                    - f(0, 1) * (f(1, 0) * f(2, 2) - f(1, 2) * f(2, 0))
                    + f(0, 2) * (f(1, 0) * f(2, 1) - f(1, 1) * f(2, 0))
            };
            let f4 = e(0, 0) * minor(0) - e(0, 1) * minor(1) + e(0, 2) * minor(2) - e(0, 3) * minor(3);
            prop_assert!(contains(d4, f4), "det4 {d4:?} misses {f4}");
        }
        let w: f64 = m.iter().map(|x| x.width()).sum();
        let big = m.iter().map(|&x| mag(x)).fold(0.0, f64::max) + w;
        prop_assert!(d4.width() <= 24.0 * big.powi(3) * w + ulps(24.0 * big.powi(4)), "det4 {d4:?} too wide");
    }
}

/// Point intervals of sin and cos are a few ulps wide, and contain the exact values at
/// the points where they are known.
#[test]
fn trig_of_points_is_a_few_ulps_wide() {
    for x in [
        0.0,
        1e-300,
        0.5,
        1.0,
        std::f64::consts::FRAC_PI_2,
        3.0,
        -7.5,
    ] {
        let (s, c) = (I::point(x).sin(), I::point(x).cos());
        assert!(s.width() <= 16.0 * f64::EPSILON, "sin {x}: {s:?}");
        assert!(c.width() <= 16.0 * f64::EPSILON, "cos {x}: {c:?}");
    }
    assert!(contains(I::point(0.0).sin(), 0.0));
    assert!(contains(I::point(0.0).cos(), 1.0));
    // an interval straddling a maximum or minimum must reach it
    assert_eq!(I::new(1.5, 1.7).sin().hi, 1.0);
    assert_eq!(I::new(3.1, 3.2).cos().lo, -1.0);
    assert_eq!(I::new(-0.1, 0.1).cos().hi, 1.0);
}
