//! Numerically hard cases as named regression tests, each saying why it is hard.
//! Each must give a verified limit state or an honest outcome — never a panic.

use crate::invariants::check_limit_state;
use arch_enum::{solve, Arch, CollapseMode, LeastLimitState, Outcome, Settings, WeightModel};
use std::f64::consts::PI;

fn outcome(arch: &Arch, mu: f64) -> Outcome {
    solve(arch, mu, &Settings::default()).unwrap().outcome
}

fn limit(arch: &Arch, mu: f64) -> LeastLimitState {
    match outcome(arch, mu) {
        Outcome::Limit(ls) => {
            check_limit_state(arch, &ls);
            ls
        }
        other => panic!("{arch:?}, mu = {mu}: {other:?}"),
    }
}

/// Very shallow segment: η* ~ 5e-7, so φ is a difference of O(1) terms that cancel
/// to 1e-7; absolute tolerances would accept wrong patterns.
#[test]
fn very_shallow_segment() {
    let arch = Arch::symmetric(-1.5, WeightModel::Centreline).unwrap();
    let ls = limit(&arch, f64::INFINITY);
    assert!(ls.eta > 0.0 && ls.eta < 1e-6, "{}", ls.eta);
    assert_eq!(ls.mode, CollapseMode::PurelyRotational);
    assert_eq!(ls.pattern.len(), 5, "{:?}", ls.pattern);
}

/// α = 1.15 at μ = ∞: the limit is an overturning mode with N = 0 at the crown, where
/// both hinge functions are active at once and the tangency conditions degenerate.
#[test]
fn overturning_horseshoe() {
    let arch = Arch::symmetric(1.15, WeightModel::Centreline).unwrap();
    let ls = limit(&arch, f64::INFINITY);
    assert_eq!(ls.mode, CollapseMode::Overturning);
    let crown: Vec<_> = ls
        .pattern
        .iter()
        .filter(|c| (c.beta - PI / 2.0).abs() < 1e-6)
        .collect();
    assert_eq!(crown.len(), 2, "E and I at the crown: {:?}", ls.pattern);
    let (n, _, _) = crate::model::ntm(arch.beta_right(), 1.0, ls.x, PI / 2.0);
    assert!(n.abs() < 1e-10, "N at the crown = {n}");
}

/// μ = 1e12 must give the infinite-friction answer (sliding functions are active in
/// the LP but far from binding).
#[test]
fn huge_friction_equals_infinite() {
    let arch = Arch::symmetric(0.3, WeightModel::Centreline).unwrap();
    let a = limit(&arch, 1e12);
    let b = limit(&arch, f64::INFINITY);
    assert!((a.eta - b.eta).abs() < 1e-13, "{} vs {}", a.eta, b.eta);
}

/// Friction so large that ‖∇(T − μN)‖² overflows to ∞ in a naive norm (μ ≥ 1e155): the
/// answer must still be the infinite-friction one, continuous and discrete, up to the
/// largest accepted finite μ; beyond it the input is refused.
#[test]
fn overflowing_friction_equals_infinite() {
    for arch in [
        Arch::symmetric(0.0, WeightModel::Centreline).unwrap(),
        Arch::symmetric(0.0, WeightModel::Centreline)
            .unwrap()
            .with_blocks(30)
            .unwrap(),
    ] {
        let b = limit(&arch, f64::INFINITY);
        for mu in [1e155, 1e180, arch_enum::arch::MU_MAX_FINITE] {
            let a = limit(&arch, mu);
            assert!(
                (a.eta - b.eta).abs() <= 1e-10 * b.eta,
                "mu = {mu}: {} vs {}",
                a.eta,
                b.eta
            );
        }
        for mu in [1e201, f64::MAX] {
            assert!(solve(&arch, mu, &Settings::default()).is_err(), "{mu}");
        }
    }
}

/// Just above μ_ms the arch needs almost the thickness of the sliding corner; just
/// below, nothing stands.
#[test]
fn just_around_mu_ms() {
    let arch = Arch::symmetric(0.0, WeightModel::Centreline).unwrap();
    let mu_ms = arch_enum::least_friction(&arch, &Settings::default())
        .unwrap()
        .unwrap();
    let ls = limit(&arch, mu_ms * (1.0 + 1e-6));
    assert!(ls.eta > 0.2 && ls.eta < 0.2007, "{}", ls.eta);
    assert!(matches!(
        outcome(&arch, mu_ms * (1.0 - 1e-6)),
        Outcome::NoEquilibrium { .. }
    ));
}

/// Horseshoe arches beyond a certain opening cannot stand at any thickness η < 2.
#[test]
fn opening_too_large_to_stand() {
    let arch = Arch::symmetric(1.35, WeightModel::Centreline).unwrap();
    assert!(matches!(
        outcome(&arch, f64::INFINITY),
        Outcome::NoEquilibrium { .. }
    ));
}

/// Discrete arches with very few blocks: with two or three voussoirs a thrust line
/// through the joint centres exists, so the arch stands at every thickness.
#[test]
fn very_few_blocks() {
    let arch = Arch::symmetric(0.0, WeightModel::Centreline).unwrap();
    for n in [1, 2, 3] {
        let out = outcome(&arch.clone().with_blocks(n).unwrap(), f64::INFINITY);
        assert!(
            matches!(out, Outcome::NoCollapse { .. }),
            "{n} blocks: {out:?}"
        );
    }
    let ls = limit(&arch.clone().with_blocks(4).unwrap(), f64::INFINITY);
    assert!(ls.eta > 0.0 && ls.eta < 0.10742645);
}

/// Ten thousand voussoirs: the scan is over 10 001 listed joints, and the answer must
/// approach the continuous one from below.
#[test]
fn many_blocks() {
    let arch = Arch::symmetric(0.0, WeightModel::Centreline).unwrap();
    let c = limit(&arch, f64::INFINITY).eta;
    let d = limit(&arch.clone().with_blocks(10_000).unwrap(), f64::INFINITY).eta;
    assert!(d <= c && c - d < 1e-7, "{d} vs {c}");
}

/// One springing far below the other: strongly unsymmetric.
#[test]
fn strongly_unsymmetric() {
    let arch = Arch::new(-0.9, PI + 0.1, WeightModel::Centreline).unwrap();
    let ls = limit(&arch, f64::INFINITY);
    assert!(!ls.mechanism.symmetric);
    let ls = limit(&arch, 2.0);
    assert!(ls.eta > 0.0);
}

/// μ within 1e-12 (relative) of every exact corner, on both sides: a verified limit
/// state at the corner's η, named by a mode of one of the two branches or of the
/// corner's own pattern (within 1e-12 both patterns' contacts are active to rounding).
#[test]
fn within_1e_12_of_corners() {
    let s = Settings::default();
    for alpha in [0.0, PI / 6.0, 1.0, 1.15] {
        let arch = Arch::symmetric(alpha, WeightModel::Centreline).unwrap();
        let curve = arch_enum::limit_curve::trace(&arch, &s);
        for c in curve.corners.iter().filter(|c| c.mu.is_finite()) {
            for side in [-1.0, 1.0] {
                let mu = c.mu * (1.0 + side * 1e-12);
                match outcome(&arch, mu) {
                    Outcome::Limit(ls) => {
                        check_limit_state(&arch, &ls);
                        assert!(
                            (ls.eta - c.t).abs() <= 1e-9 * c.t,
                            "alpha {alpha} mu {mu}: {} vs corner {}",
                            ls.eta,
                            c.t
                        );
                        let allowed = [c.between()[0], c.between()[1], c.detail.mode];
                        assert!(
                            allowed.contains(&ls.mode),
                            "alpha {alpha} mu {mu}: mode {:?} not in {allowed:?}",
                            ls.mode
                        );
                    }
                    // just below mu_ms nothing stands; within the LP's resolution of it the
                    // solver says so
                    Outcome::NoEquilibrium { .. } | Outcome::Unresolved { .. } => {
                        assert!(
                            (c.mu - curve.mu_ms.unwrap()).abs() <= 1e-9 * c.mu,
                            "alpha {alpha}: no answer at {mu}"
                        )
                    }
                    other => panic!("alpha {alpha} mu {mu}: {other:?}"),
                }
            }
        }
    }
}

/// Openings close to the largest that can stand at all: η* → 2 (overturning at μ = ∞).
#[test]
fn nearly_the_largest_opening() {
    let arch = Arch::symmetric(1.21, WeightModel::Centreline).unwrap();
    let ls = limit(&arch, f64::INFINITY);
    assert!(ls.eta > 1.9 && ls.eta < 2.0, "{}", ls.eta);
    assert_eq!(ls.mode, CollapseMode::Overturning);
}

/// A continuous arch whose least states grow without bound: a weightless straight line of
/// thrust fits it, so η_s is an infimum, and Newton near it only approximates that η (its
/// equations hold relative to reactions of 1e6 and more: the 11th digit moved with the
/// LP's starting state). The line that needs the least thickness is the chord through the
/// extrados at both springings, tangent to the intrados at mid-span (the annular sector is
/// symmetric about its bisector): η = 2(1 − c)/(1 + c), c = cos(span/2), with friction
/// enough for the chord's inclination to the joints (μ ≥ tan(span/2)). Independent of the
/// solver's recession code; on random openings and orientations, at μ = ∞ and finite μ.
#[test]
fn continuous_infimum_is_the_chord_thickness() {
    let mut rng = crate::search_reference::Rng(0x1f1_0b0d);
    let mut infima = 0;
    for _ in 0..60 {
        let span = 1.3 + 0.9 * rng.next();
        let br = -1.4 + (1.4 + 1.2 - span) * rng.next();
        let arch = Arch::new(br, br + span, WeightModel::Centreline).unwrap();
        let half = 0.5 * span;
        let mu = if rng.next() < 0.5 {
            f64::INFINITY
        } else {
            half.tan() * (1.01 + 2.0 * rng.next())
        };
        let Outcome::Limit(ls) = outcome(&arch, mu) else {
            continue;
        };
        let unbounded = ls.x_static.iter().any(|v| v.abs() > 1e6 * (1.0 + span));
        if !unbounded {
            continue;
        }
        infima += 1;
        let c = half.cos();
        let chord = 2.0 * (1.0 - c) / (1.0 + c);
        assert!(
            (ls.eta_static - chord).abs() <= 1e-13 * chord,
            "span {span}, beta_R {br}, mu {mu}: eta_s = {} against the chord's {chord}",
            ls.eta_static
        );
    }
    assert!(
        infima >= 10,
        "only {infima} of the random arches had an infimum"
    );
}
