//! The proof that the activation functions are ≤ 0 (or < 0) over pieces of the arch, for a
//! state of either problem (the dead actions, plus λ times the live ones under a load):
//! second-order Taylor enclosures with adaptive splitting over a continuum of angles, or the
//! values at the listed joints of a discrete arch, in interval arithmetic.

use super::live::{Live, Span, StateAt};
use super::report::{reject, Rejection};
use super::statics::{kinds, phi, Model, Ntm};
use crate::certificate::format::ContactKind;
use crate::certificate::interval::Interval as I;

/// Upper bound of φ over [a, b], and a lower bound at the midpoint (`eval`: the actions over
/// an interval of angles): by the second-order Taylor form at the midpoint where φ' is
/// continuous (`smooth`), else by the enclosure of φ itself (the sliver around a patch's
/// edge, where φ' jumps).
fn upper_bound(
    eval: &dyn Fn(I) -> Ntm,
    kind: ContactKind,
    (a, b, smooth): (f64, f64, bool),
    eta: f64,
    mu: Option<f64>,
) -> (f64, f64) {
    let m = 0.5 * (a + b);
    let r = (b - m).max(m - a);
    let at_m = eval(I::point(m));
    let over = eval(I::new(a, b));
    let f0 = phi(kind, 0, &at_m, eta, mu);
    if !smooth {
        return (phi(kind, 0, &over, eta, mu).hi, f0.lo);
    }
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

/// Proves φ ≤ 0 (φ < 0 with `strict`, the state in the interior of P) for every
/// activation function at `state`: its dead actions plus λ times the live ones, over the
/// whole arch (both sides of a loaded section). `what` starts the rejection messages.
pub(super) fn prove_state(
    model: &Model,
    state: StateAt,
    mu: Option<f64>,
    strict: bool,
    what: &str,
) -> Result<usize, Rejection> {
    let (x, eta) = (state.x, state.eta);
    let dead = move |b: I| model.ntm(b, x, eta);
    prove_with_live(model, &dead, eta, state.load, mu, strict, what)
}

/// The actions over an interval of angles, boxed.
type Eval<'a> = Box<dyn Fn(I) -> Ntm + 'a>;

/// Proves φ ≤ 0 (φ < 0 with `strict`) on every piece of the arch at thickness `eta` for the
/// actions `base(β)`, plus λ times the live ones of `load` where the piece's sections carry
/// it: the whole arch as one piece without a load.
pub(super) fn prove_with_live(
    model: &Model,
    base: &dyn Fn(I) -> Ntm,
    eta: f64,
    load: Option<(&Live, f64)>,
    mu: Option<f64>,
    strict: bool,
    what: &str,
) -> Result<usize, Rejection> {
    let whole = [Span::whole(model)];
    let spec = match load {
        Some((live, _)) => live.pieces(),
        None => &whole[..],
    };
    let evals: Vec<Eval> = spec
        .iter()
        .map(|span| -> Eval {
            let at = span.at;
            Box::new(move |b: I| {
                let n = base(b);
                match load.and_then(|(live, lambda)| Some((live.ntm(model, b, at)?, lambda))) {
                    Some((l, lambda)) => n.plus(lambda, &l),
                    None => n,
                }
            })
        })
        .collect();
    let pieces: Vec<Piece> = spec
        .iter()
        .zip(&evals)
        .map(|(span, f)| Piece {
            a: span.a,
            b: span.b,
            eval: f.as_ref(),
            smooth: span.smooth,
        })
        .collect();
    prove_pieces(model, &pieces, eta, mu, kinds(mu), strict, what)
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
    /// Whether φ' is continuous on [a, b] (a Taylor form holds); else φ is enclosed over
    /// each subinterval directly (the sliver around a patch's edge).
    pub(super) smooth: bool,
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
                let (upper, lower_mid) = upper_bound(eval, kind, (a, b, piece.smooth), eta, mu);
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
