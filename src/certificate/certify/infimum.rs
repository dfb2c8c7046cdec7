//! A thickness certificate where η_s is an infimum approached only as the reactions grow
//! without bound (a weightless line of thrust fits the arch, [`crate::limit::recession`]):
//! no state is attained at η_s, so the safe side is a state far out along the weightless
//! direction d at η_hi, where every activation function is negative, and the collapse side
//! the Farkas certificate at η_lo as for an attained η_s. The farther out the state, the more
//! its reactions (about 1/gap) cost the verifier's interval rounding: such a bracket
//! reaches a wider gap than an attained one, and says so.

use super::blank::empty;
use super::loaded::Loaded;
use super::sides::chord_pool;
use super::thickness::bracket_around;
use crate::arch::{Arch, JointLayout};
use crate::certificate::format::{Certificate, Claim, NotCertified, SafeSide, Side};
use crate::certificate::verify::prove_admissible_side;
use crate::contact::ContactKind;
use crate::limit::recession::{continuum_threshold, threshold};
use crate::limit::LeastLimitState;
use crate::search::candidates_at;
use crate::settings::Settings;
use crate::state::State;
use crate::statics::{actions, Reactions};

/// A continuous arch's rows are sampled at this many angles for the distance out along d
/// (the verifier then proves the state over the whole arch).
const SAMPLES: usize = 2049;

/// The state is taken this many times farther out than the sampled rows need, and again
/// this many times farther when the verifier cannot prove it ...
const FAR: f64 = 4.0;

/// ... at most this many times.
const FARTHER: usize = 4;

/// The certificate of an infimum η_s (`ls.attained` false) at the requested relative gap,
/// or the widest up to 1e-4 that could be proved.
pub(super) fn certify_infimum(
    arch: &Arch,
    mu: f64,
    ls: &LeastLimitState,
    gap: f64,
    settings: &Settings,
) -> Result<Certificate, NotCertified> {
    let eta_s = ls.eta_static;
    let rec = match arch.layout() {
        JointLayout::Discrete(_) => {
            let r = settings.infimum_rel;
            threshold(arch, mu, eta_s * (1.0 - r), eta_s * (1.0 + r), settings)
        }
        JointLayout::Continuous => continuum_threshold(arch, mu, eta_s, &ls.x_static, settings),
    }
    .ok_or_else(|| {
        NotCertified(format!(
            "no weightless direction found at the infimum eta_s = {eta_s}"
        ))
    })?;

    let modes = ContactKind::active_at(mu);
    let least = State {
        arch,
        eta: eta_s,
        mu,
        x: ls.x_static,
    };
    // the contacts tight along d, and the best others (the fourth row of a Farkas
    // certificate need not be tight at the least state)
    let mut contacts = least.verdict(modes, settings).active;
    for c in candidates_at(&least, None, modes, settings) {
        if !contacts
            .iter()
            .any(|a| a.kind == c.kind && a.beta == c.beta)
        {
            contacts.push(c);
        }
    }
    let active: Vec<Loaded> = contacts.into_iter().map(|c| (c, Side::After)).collect();
    let pool = chord_pool(arch, &active);
    let cert = empty(arch, mu, Claim::LeastThickness);
    bracket_around((arch, mu), eta_s, gap, &pool, |eta_hi| {
        far_state(arch, mu, eta_hi, &rec.d, &cert)
    })
    .ok_or_else(|| {
        NotCertified(format!(
            "no certificate of the infimum eta_s = {eta_s} could be proved at a relative gap up to 1e-4"
        ))
    })
}

/// `cert` with a safe side at η: the state t·d far enough out along the weightless
/// direction d that the verifier proves it admissible, or `None`.
fn far_state(
    arch: &Arch,
    mu: f64,
    eta: f64,
    d: &Reactions,
    cert: &Certificate,
) -> Option<Certificate> {
    // φ(t d) = c + t g·d < 0 needs t > c / (−g·d) wherever g·d < 0; a row with g·d > 0
    // turns positive far out (d is no weightless direction there)
    let mut t: f64 = 1.0;
    for beta in arch.angles(SAMPLES) {
        let a = actions(arch, eta, beta);
        for &kind in ContactKind::active_at(mu) {
            let row = a.activation(kind, 0, eta, mu);
            let gd = row.g[0] * d[0] + row.g[1] * d[1] + row.g[2] * d[2];
            if gd < 0.0 {
                t = t.max(row.c / -gd);
            } else if gd > 0.0 || row.c >= 0.0 {
                return None;
            }
        }
    }
    let mut scale = FAR * t;
    for _ in 0..FARTHER {
        let mut c = cert.clone();
        c.safe = Some(SafeSide {
            eta,
            x: d.map(|v| scale * v),
        });
        if prove_admissible_side(&c).is_ok() {
            return Some(c);
        }
        scale *= FAR;
    }
    None
}
