//! A state of a load certificate proved admissible: the dead actions of x plus λ times the
//! live ones, on every piece of the arch (both sides of a loaded section).

use super::enclosure::{prove_pieces, Piece};
use super::input::model_of;
use super::live::Live;
use super::report::{reject, Rejection};
use super::statics::{kinds, Model, Ntm};
use crate::certificate::format::{Certificate, LoadState};
use crate::certificate::interval::Interval as I;

pub(super) fn everywhere(model: &Model, live: &Live) -> &'static str {
    match (&model.joints, live.split()) {
        (Some(j), Some(bp)) if j.contains(&bp) => {
            "at every joint (both sides of the loaded section)"
        }
        (Some(_), _) => "at every joint",
        (None, Some(_)) => "over the whole arch (both sides of the loaded section)",
        (None, None) => "over the whole arch",
    }
}

pub(super) fn check_state(s: &LoadState, what: &str) -> Result<(), Rejection> {
    if !(s.lambda.is_finite() && s.lambda >= 0.0 && s.x.iter().all(|v| v.is_finite())) {
        return reject(format!(
            "{what}: lambda must be finite and >= 0 and x finite, found lambda = {}",
            s.lambda
        ));
    }
    Ok(())
}

/// Proves the state (x, λ) admissible on every piece of the arch (both sides of a
/// loaded section): the dead actions of x plus λ times the live ones.
pub(super) fn prove_state(
    model: &Model,
    live: &Live,
    s: &LoadState,
    mu: Option<f64>,
    what: &str,
) -> Result<usize, Rejection> {
    let (x, eta) = (s.x, live.eta);
    let dead = move |b: I| model.ntm(b, x, eta);
    prove_with_live(model, live, &dead, s.lambda, mu, what)
}

/// The actions over an interval of angles, boxed.
type Eval<'a> = Box<dyn Fn(I) -> Ntm + 'a>;

/// Proves φ ≤ 0 on every piece of the arch for the actions `base(β) + λ live(β)` (the
/// live part only where the piece's sections carry the load).
pub(super) fn prove_with_live(
    model: &Model,
    live: &Live,
    base: &dyn Fn(I) -> Ntm,
    lambda: f64,
    mu: Option<f64>,
    what: &str,
) -> Result<usize, Rejection> {
    let spec = live.pieces(model);
    let evals: Vec<Eval> = spec
        .iter()
        .map(|&(_, _, carries)| -> Eval {
            Box::new(move |b: I| {
                let n = base(b);
                match live.ntm(model, b, carries) {
                    Some(l) => n.plus(lambda, &l),
                    None => n,
                }
            })
        })
        .collect();
    let pieces: Vec<Piece> = spec
        .iter()
        .zip(&evals)
        .map(|(&(a, b, _), f)| Piece {
            a,
            b,
            eval: f.as_ref(),
        })
        .collect();
    prove_pieces(model, &pieces, live.eta, mu, kinds(mu), false, what)
}

/// Proves only the admissible side of a load certificate, `multiplier.admissible` (used
/// by `certify` while it searches for the other side).
pub(crate) fn prove_admissible_side(cert: &Certificate) -> Result<usize, Rejection> {
    let model = model_of(cert)?;
    let (Some(spec), Some(m)) = (&cert.load, &cert.multiplier) else {
        return reject("no load or multiplier section");
    };
    let Some(adm) = &m.admissible else {
        return reject("no admissible side");
    };
    check_state(adm, "multiplier.admissible")?;
    let live = Live::of(spec, &model)?;
    prove_state(&model, &live, adm, cert.mu, "admissible side")
}
