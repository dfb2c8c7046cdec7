//! Bracketing the root of an increasing function (the continuum margin s(η) in the
//! thickness problem, s(μ) in the friction-only problem): inverse quadratic interpolation
//! and Illinois regula falsi with a geometric-bisection safeguard, and the LP evaluation
//! it calls.

use crate::admissibility::{margin_over_arch, Goal, Margin, WorkingSet};
use crate::arch::Arch;
use crate::contact::ContactKind;
use crate::lp::LpOutcome;
use crate::settings::Settings;
use crate::undecided::Undecided;

/// The continuum margin at (η, μ) restricted to `kinds`, decided (the LP stops once its
/// sign is known); an LP failure becomes its message.
pub fn margin_at(
    arch: &Arch,
    eta: f64,
    mu: f64,
    kinds: &[ContactKind],
    ws: &mut WorkingSet,
    settings: &Settings,
) -> Result<Margin, Undecided> {
    margin_over_arch(arch, eta, mu, kinds, ws, Goal::Decide, settings).map_err(|e| match e {
        LpOutcome::Infeasible => Undecided::Lp("margin LP infeasible".to_string()),
        LpOutcome::Failed(m) => Undecided::Lp(m),
    })
}

/// A secant point is kept this fraction of the bracket's width away from its ends, so
/// that each step shrinks the bracket.
const SECANT_GUARD: f64 = 1e-3;

/// The ends of a bracket: (η, f) below the root, (η, f, payload) at or above it.
pub type Bracket<T> = ((f64, f64), (f64, f64, T));

/// Root of an increasing function f on [lo, hi] with f(lo) < 0 ≤ f(hi): inverse quadratic
/// interpolation through the two ends and the end last replaced (Illinois regula falsi
/// until there is one), with geometric bisection as a safeguard. `eval` returns f and the
/// payload kept for the upper end. Stops when hi − lo ≤ rel · hi.
pub fn bracket_root<T: Clone, E>(
    mut lo: (f64, f64),
    mut hi: (f64, f64, T),
    rel: f64,
    max_iter: usize,
    mut eval: impl FnMut(f64) -> Result<(f64, T), E>,
) -> Result<Bracket<T>, E> {
    let mut side = 0i32;
    let (mut flo, mut fhi) = (lo.1, hi.1);
    let mut widths = [f64::INFINITY; 3];
    let mut prev: Option<(f64, f64)> = None;
    for _ in 0..max_iter {
        if hi.0 - lo.0 <= rel * hi.0 {
            break;
        }
        let width = hi.0 - lo.0;
        let secant = match prev {
            Some(p) => inverse_quadratic((lo.0, lo.1), (hi.0, hi.1), p),
            None => None,
        }
        .unwrap_or(hi.0 - fhi * (hi.0 - lo.0) / (fhi - flo));
        let bisect = if lo.0 > 0.0 && hi.0 / lo.0 > 4.0 {
            (lo.0 * hi.0).sqrt()
        } else if lo.0 <= 0.0 {
            hi.0 / 8.0
        } else {
            0.5 * (lo.0 + hi.0)
        };
        widths = [widths[1], widths[2], width];
        let stalled = widths[2] > 0.5 * widths[0];
        // (a secant point on an end, where f is 0 there, is moved inside like any other)
        let t = if stalled || !(secant >= lo.0 && secant <= hi.0) {
            bisect
        } else {
            // keep the secant point away from the ends
            secant.clamp(lo.0 + SECANT_GUARD * width, hi.0 - SECANT_GUARD * width)
        };
        let (f, payload) = eval(t)?;
        if stalled {
            widths = [f64::INFINITY; 3];
        }
        if f >= 0.0 {
            prev = Some((hi.0, hi.1));
            hi = (t, f, payload);
            fhi = f;
            if side == 1 {
                flo *= 0.5;
            }
            side = 1;
        } else {
            prev = Some(lo);
            lo = (t, f);
            flo = f;
            if side == -1 {
                fhi *= 0.5;
            }
            side = -1;
        }
    }
    Ok((lo, hi))
}

/// The root of the quadratic in f through three points (t, f) (inverse quadratic
/// interpolation, as in Brent's method); `None` unless the three values of f differ.
fn inverse_quadratic((a, fa): (f64, f64), (b, fb): (f64, f64), (c, fc): (f64, f64)) -> Option<f64> {
    (fa != fb && fa != fc && fb != fc).then(|| {
        a * fb * fc / ((fa - fb) * (fa - fc))
            + b * fa * fc / ((fb - fa) * (fb - fc))
            + c * fa * fb / ((fc - fa) * (fc - fb))
    })
}

/// Where the root of an increasing f is expected: near `eta`, within about `rel` of it
/// (relative). Only a starting point: the bracket found from it is decided by f itself.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct RootGuess {
    /// The expected root.
    pub eta: f64,
    /// Its expected relative distance from the true root (> 0).
    pub rel: f64,
}

/// How many times the step of [`bracket_near`] is widened on a side before it gives up.
const GUESS_WIDENINGS: usize = 3;

/// A bracket of the root of an increasing f found from a guess: f at g(1 + r) and
/// g(1 − r), the step widened eightfold on a side whose end does not straddle the root
/// (each evaluation still narrows the bracket, since f is increasing), at most
/// `GUESS_WIDENINGS` times, within (0, `top`]. `Ok(None)` when no bracket was found so
/// (the caller brackets from its own ends); an evaluation's error is returned as is.
pub fn bracket_near<T: Clone, E>(
    guess: RootGuess,
    top: f64,
    mut eval: impl FnMut(f64) -> Result<(f64, T), E>,
) -> Result<Option<Bracket<T>>, E> {
    let g = guess.eta;
    if !(g > 0.0 && g < top && guess.rel > 0.0 && guess.rel.is_finite()) {
        return Ok(None);
    }
    let mut lo: Option<(f64, f64)> = None;
    let mut hi: Option<(f64, f64, T)> = None;
    let mut r = guess.rel;
    // the upper end first: its state is the one the caller keeps
    for _ in 0..=GUESS_WIDENINGS {
        let t = (g * (1.0 + r)).min(top);
        let (f, payload) = eval(t)?;
        if f >= 0.0 {
            hi = Some((t, f, payload));
            break;
        }
        lo = Some((t, f));
        if t >= top {
            return Ok(None);
        }
        r *= 8.0;
    }
    let Some(hi) = hi else { return Ok(None) };
    if lo.is_none() {
        let mut r = guess.rel;
        let mut hi = hi;
        for _ in 0..=GUESS_WIDENINGS {
            let t = g * (1.0 - r.min(0.5));
            let (f, payload) = eval(t)?;
            if f < 0.0 {
                return Ok(Some(((t, f), hi)));
            }
            hi = (t, f, payload);
            r *= 8.0;
        }
        return Ok(None);
    }
    Ok(lo.map(|lo| (lo, hi)))
}
