//! The check of a candidate, like a point of the sweep: admissible at every joint, and a
//! mechanism on its active contacts; with a cheap pre-filter on the joints' rows and a
//! closed form for the common case of exactly four active contacts.

use super::rows::{det3, ev, Candidate, JointRows};
use crate::arch::Arch;
use crate::contact::{Contact, ContactKind};
use crate::kinematics::column;
use crate::limit_states::sweep::LimitState;
use crate::mechanism;
use crate::settings::Settings;
use crate::state::State;
use crate::undecided::Undecided;

/// The pre-filter calls a contact clearly violated when φ exceeds this many times
/// `adm_tol` of its magnitude, and clearly inactive below −this many times.
const CLEAR_FACTOR: f64 = 100.0;

/// The pre-filter leaves a cofactor of four columns within this fraction of the largest to
/// the LP (the null space may be larger).
const PREFILTER_ZERO_COFACTOR: f64 = 1e-6;

/// The check's own sign test of the cofactors: a cofactor within this fraction of the
/// largest is zero, and the LP decides.
const ZERO_COFACTOR: f64 = 1e-9;

/// A pre-filter on the joints' rows (no trigonometry): `false` only where the answer of
/// [`check`] is sure to be [`Checked::No`] — the candidate is clearly not admissible
/// (some φ above [`CLEAR_FACTOR`] `adm_tol` times its magnitude), or every contact is
/// clearly active or clearly not (|φ| below `adm_tol`, or φ below −[`CLEAR_FACTOR`]
/// `adm_tol`, in units of its magnitude), exactly four are active, one sliding sense per
/// joint, and the cofactors of their columns have mixed signs (and not only just: not one
/// of the other sign within `almost_rate` of the largest). Everything in between is
/// left to `check`. Only the joints of the candidate's subset are looked at.
pub(super) fn may_carry_mechanism(
    js: &[JointRows],
    (mu, almost_rate): (f64, f64),
    c: &Candidate,
    subsets: &[Vec<usize>],
    settings: &Settings,
) -> bool {
    let p = [c.x[0], c.x[1]];
    let tol = settings.adm_tol;
    let mut active: [(usize, ContactKind); 4] = [(0, ContactKind::HingeExtrados); 4];
    let mut count = 0;
    // the magnitudes depend on the kind only through hinge or sliding: two per candidate
    let mag_of = |kind| crate::statics::magnitude(kind, c.eta, mu, &c.x, settings.magnitude_floor);
    let (mag_hinge, mag_slide) = (
        mag_of(ContactKind::HingeExtrados),
        mag_of(ContactKind::SlidePlus),
    );
    // the joints outside the candidate's subset are clearly inactive (`super::near`)
    let every: Vec<usize>;
    let joints: &[usize] = match c.near {
        Some(k) => &subsets[k],
        None => {
            every = (0..js.len()).collect();
            &every
        }
    };
    let clear = -CLEAR_FACTOR * tol;
    // φ below these is clearly inactive whatever the rounding of φ / magnitude (a margin of
    // 4 ε on a test whose quotient rounds by at most ε)
    let (clear_hinge, clear_slide) = (
        clear * mag_hinge * (1.0 + 4.0 * f64::EPSILON),
        clear * mag_slide * (1.0 + 4.0 * f64::EPSILON),
    );
    for &j in joints {
        let jr = &js[j];
        let (n, t, m) = (ev(&jr.n, p), ev(&jr.t, p), ev(&jr.m, p) + c.x[2]);
        // φ of the joint's four rows, in the order of `ContactKind::ALL`
        let phis = [
            m - 0.5 * c.eta * n,
            -m - 0.5 * c.eta * n,
            t - mu * n,
            -t - mu * n,
        ];
        // most joints: all four rows clearly inactive (one test, no division, no branch per
        // row); the others are classified exactly as `check`'s tolerances say
        if (phis[0] < clear_hinge)
            & (phis[1] < clear_hinge)
            & (phis[2] < clear_slide)
            & (phis[3] < clear_slide)
        {
            continue;
        }
        let mags = [mag_hinge, mag_hinge, mag_slide, mag_slide];
        for (k, kind) in ContactKind::ALL.into_iter().enumerate() {
            let r = phis[k] / mags[k];
            if r > CLEAR_FACTOR * tol {
                return false;
            }
            if r < clear {
                continue;
            }
            if r.abs() > tol || count == 4 {
                return true; // near the tolerance, or more than four active: let `check` decide
            }
            active[count] = (j, kind);
            count += 1;
        }
    }
    if count != 4 {
        return true;
    }
    let slides = |k: ContactKind| matches!(k, ContactKind::SlidePlus | ContactKind::SlideMinus);
    for a in 0..4 {
        for b in a + 1..4 {
            if active[a].0 == active[b].0 && slides(active[a].1) && slides(active[b].1) {
                return true; // both senses at one joint
            }
        }
    }
    let cols: [[f64; 3]; 4] =
        std::array::from_fn(|k| column(active[k].1, js[active[k].0].beta, c.eta));
    null_vector_signs(&cols, PREFILTER_ZERO_COFACTOR) != NullSigns::Mixed
        || almost_mechanism(&cols, almost_rate)
}

/// Whether the cofactors of four columns have exactly one of the other sign, of at most
/// `rate` times the largest (`Settings::carry_almost_rate`): their contacts carry no
/// mechanism, but only just (the rate of one has passed through zero).
fn almost_mechanism(cols: &[[f64; 3]; 4], rate: f64) -> bool {
    let lam = cofactors(cols);
    let big = lam.iter().fold(0.0f64, |m, v| m.max(v.abs()));
    let neg = lam.iter().filter(|&&v| v < 0.0).count();
    let odd = match neg {
        1 => lam.iter().find(|&&v| v < 0.0),
        3 => lam.iter().find(|&&v| v > 0.0),
        _ => None,
    };
    rate > 0.0 && odd.is_some_and(|v| v.abs() <= rate * big)
}

/// The null vector of four compatibility columns (3 × 4): their signed cofactors.
fn cofactors(cols: &[[f64; 3]; 4]) -> [f64; 4] {
    [
        det3(cols[1], cols[2], cols[3]),
        -det3(cols[0], cols[2], cols[3]),
        det3(cols[0], cols[1], cols[3]),
        -det3(cols[0], cols[1], cols[2]),
    ]
}

/// The signs of the null vector of four compatibility columns (3 × 4), its cofactors.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum NullSigns {
    /// Every cofactor strictly of one sign: the rates of a mechanism.
    OneSign,
    /// Cofactors of both signs, none near zero: no mechanism on these four.
    Mixed,
    /// A cofactor within `zero_rel` of the largest: the null space may be larger (an LP
    /// decides).
    NearZero,
}

fn null_vector_signs(cols: &[[f64; 3]; 4], zero_rel: f64) -> NullSigns {
    let lam = cofactors(cols);
    let big = lam.iter().fold(0.0f64, |m, v| m.max(v.abs()));
    if lam.iter().any(|v| v.abs() <= zero_rel * big) {
        NullSigns::NearZero
    } else if lam.iter().all(|&v| v > 0.0) || lam.iter().all(|&v| v < 0.0) {
        NullSigns::OneSign
    } else {
        NullSigns::Mixed
    }
}

/// What a candidate is.
pub(super) enum Checked {
    /// A limit state.
    Limit(LimitState),
    /// Admissible, with four active contacts whose mechanism only just fails (one rate of
    /// the other sign, of at most the given fraction of the largest): the contacts.
    Almost(Vec<Contact>),
    /// Neither.
    No,
}

/// A candidate checked like a point of the sweep: admissible at every joint, and a
/// mechanism on its active contacts. When exactly four contacts are active, one sliding
/// sense per joint, with no zero cofactor, the mechanism exists iff the null vector of
/// their 3 × 4 columns has one strict sign (O(1)); the LP then only builds it. `Err`: the
/// LP back end did not decide.
pub(super) fn check(
    arch: &Arch,
    (mu, almost_rate): (f64, f64),
    c: &Candidate,
    settings: &Settings,
) -> Result<Checked, Undecided> {
    let st = State {
        arch,
        eta: c.eta,
        mu,
        x: c.x,
    };
    let v = st.verdict(ContactKind::active_at(mu), settings);
    if v.worst > settings.adm_tol {
        return Ok(Checked::No);
    }
    let a = &v.active;
    let two_senses = a.iter().any(|p| {
        p.kind == ContactKind::SlidePlus
            && a.iter().any(|q| {
                q.kind == ContactKind::SlideMinus && (q.beta - p.beta).abs() <= settings.same_joint
            })
    });
    if a.len() == 4 && !two_senses {
        let cols: [[f64; 3]; 4] = std::array::from_fn(|k| column(a[k].kind, a[k].beta, c.eta));
        if null_vector_signs(&cols, ZERO_COFACTOR) == NullSigns::Mixed {
            return Ok(if almost_mechanism(&cols, almost_rate) {
                Checked::Almost(v.active)
            } else {
                Checked::No
            });
        }
    }
    let mech = mechanism::find(&st, a, settings).map_err(|e| {
        Undecided::Lp(format!(
            "the kinematic LP at eta = {} was not decided by the LP back end: {e:?}",
            c.eta
        ))
    })?;
    Ok(match mech {
        Some(m) => Checked::Limit(LimitState::unloaded(
            arch,
            (c.eta, c.x),
            v.active,
            m,
            settings,
        )),
        None => Checked::No,
    })
}
