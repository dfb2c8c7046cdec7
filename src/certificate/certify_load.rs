//! Building a load certificate (issue 11) around the solver's answer to the load
//! question ([`crate::multiplier::survey`]); every certificate is verified before it is
//! returned.
//!
//! * `largest_multiplier`: the static maximum (x_s, λ_s) moved into the admissible set at
//!   λ_lo = λ_s (1 − g/2) by a small LP on its active contacts (rows scaled by
//!   1/(λ_s − λ_lo)), and a Farkas certificate at λ_hi = λ_s (1 + g/2) from 4-subsets of
//!   the active contacts (interior tangencies of a continuous arch also as chords β ± δ),
//!   chosen by their float cofactors and proved by the verifier; the gap is widened
//!   tenfold (up to 1e-4) when a side cannot be proved.
//! * `unbounded_multiplier`: a state admissible at λ_min (the unloaded arch's safest
//!   state when λ_min = 0) and the transfer of the point load to a springing that keeps it
//!   admissible as λ grows; where neither transfer is proved, no certificate.
//! * `no_equilibrium`: the multiplier λ* that maximises the x-margin of the rows (a
//!   concave function of λ: doubling, then golden section), and 5-subsets of the rows
//!   nearest to binding there (and −λ ≤ 0), as for the other Farkas certificates.
//! * the limit states: the survey's list with its mechanisms, the state at λ_static
//!   without a mechanism and every point the sweep checked without one, each with the
//!   Farkas alternative of the kinematic LP with the live power. Where the survey leaves
//!   the limit states undecided, the certificate covers the static range alone (no
//!   `load_search`).

use super::certify::{empty, find_farkas, move_inside, Row};
use super::certify_load_ends::{no_equilibrium, unbounded};
use super::certify_load_search::{evidence, unbounded_evidence};
use super::format::*;
use super::verify::verify;
use super::verify_load::prove_admissible_side;
use crate::arch::{Arch, JointLayout};
use crate::contact::Contact;
use crate::load::{live_activation, rows, LiveLoad};
use crate::multiplier::continuum::{extreme, LoadedContact};
use crate::multiplier::{static_range, survey, LoadOutcome, StaticRange};
use crate::settings::Settings;
use crate::statics::{actions, magnitude, Affine, Reactions};

/// A contact of the loaded problem: the activation function and the side of the loaded
/// section it belongs to (`After` away from a point load).
pub(super) type Loaded = (Contact, Side);

/// Builds a certificate for the live `load` on `arch` at thickness `eta` and friction
/// `mu` with requested relative gap `gap` of the multiplier bracket (e.g. 1e-12): the
/// largest admissible multiplier (two-sided), its unboundedness, or no equilibrium at any
/// λ ≥ 0, with the evidence of the limit states where the search is complete. Verified
/// before it is returned; [`Certificate::delivers_gap`] says whether the gap was met.
pub fn certify_load(
    arch: &Arch,
    eta: f64,
    mu: f64,
    load: &LiveLoad,
    gap: f64,
    settings: &Settings,
) -> Result<Certificate, NotCertified> {
    let base = |claim: Claim| {
        let mut c = empty(arch, mu, claim);
        c.load = Some(load_spec(eta, load));
        c
    };
    let outcome =
        match survey(arch, eta, mu, load, settings).map_err(|e| NotCertified(e.to_string()))? {
            Ok(o) => o,
            // the limit states undecided: the static range alone, without their evidence
            Err(reason) => {
                let range = static_range(arch, eta, mu, load, settings)
                    .map_err(|e| NotCertified(e.to_string()))?
                    .map_err(|e| NotCertified(format!("the load question is not decided: {e}")))?;
                return match range {
                    StaticRange::NoEquilibrium => {
                        no_equilibrium(arch, eta, mu, load, base(Claim::NoEquilibrium), settings)
                    }
                    StaticRange::Interval { min, max: None } => unbounded(
                        arch,
                        eta,
                        mu,
                        load,
                        min,
                        base(Claim::UnboundedMultiplier),
                        settings,
                    ),
                    StaticRange::Interval { max: Some(top), .. } => {
                        let (lambda_s, x_s, pattern) =
                            static_state(arch, eta, mu, load, top, settings)?;
                        bracket(
                            arch,
                            eta,
                            mu,
                            load,
                            (lambda_s, x_s, &pattern),
                            base(Claim::LargestMultiplier),
                            gap,
                            settings,
                        )
                    }
                }
                .map_err(|e| {
                    NotCertified(format!(
                        "{} (the limit states are not decided: {reason})",
                        e.0
                    ))
                });
            }
        };
    match outcome {
        LoadOutcome::NoEquilibrium => {
            no_equilibrium(arch, eta, mu, load, base(Claim::NoEquilibrium), settings)
        }
        LoadOutcome::NoCollapse { lambda_min, .. } => {
            let mut cert = base(Claim::UnboundedMultiplier);
            cert.load_search = unbounded_evidence(arch, eta, mu, load, lambda_min, settings);
            unbounded(arch, eta, mu, load, lambda_min, cert, settings)
        }
        LoadOutcome::Limits(sv) => match sv.lambda_static {
            Some(top) => {
                let (lambda_s, x_s, pattern) = static_state(arch, eta, mu, load, top, settings)?;
                let mut cert = base(Claim::LargestMultiplier);
                cert.load_search = Some(evidence(
                    arch,
                    eta,
                    load,
                    &sv,
                    Some((lambda_s, x_s, &pattern)),
                    settings,
                )?);
                bracket(
                    arch,
                    eta,
                    mu,
                    load,
                    (lambda_s, x_s, &pattern),
                    cert,
                    gap,
                    settings,
                )
            }
            None => {
                let mut cert = base(Claim::UnboundedMultiplier);
                cert.load_search = Some(evidence(arch, eta, load, &sv, None, settings)?);
                unbounded(arch, eta, mu, load, sv.lambda_min, cert, settings)
            }
        },
    }
}

/// The load as the certificate records it.
fn load_spec(eta: f64, load: &LiveLoad) -> LoadSpec {
    match *load {
        LiveLoad::Horizontal { towards_right } => LoadSpec {
            eta,
            kind: LoadKind::Horizontal,
            towards: Some(if towards_right {
                Towards::Right
            } else {
                Towards::Left
            }),
            beta: None,
        },
        LiveLoad::Point { beta } => LoadSpec {
            eta,
            kind: LoadKind::Point,
            towards: None,
            beta: Some(beta),
        },
    }
}

/// The side as the certificate records it: only at the point load's own angle.
fn cert_side(load: &LiveLoad, beta: f64, side: Side) -> Option<Side> {
    load.splits(beta).then_some(side)
}

/// The activation function of a loaded contact as a row in (h, v, w, λ): `(a, c)`.
fn row_at(arch: &Arch, eta: f64, mu: f64, load: &LiveLoad, (c, side): Loaded) -> ([f64; 4], f64) {
    let dead = actions(arch, eta, c.beta).activation(c.kind, 0, eta, mu);
    let live = live_activation(c.kind, eta, mu, load.actions(arch, eta, c.beta, side));
    ([dead.g[0], dead.g[1], dead.g[2], live], dead.c)
}

/// The row at a fixed λ, affine in x.
pub(super) fn at_lambda((a, c): ([f64; 4], f64), lambda: f64) -> Affine {
    Affine {
        g: [a[0], a[1], a[2]],
        c: c + a[3] * lambda,
    }
}

/// Sorts loaded contacts by (β, side, kind), `Before` first: the order of certificates.
pub(super) fn sorted(mut p: Vec<Loaded>) -> Vec<Loaded> {
    p.sort_by(|a, b| {
        a.0.beta
            .total_cmp(&b.0.beta)
            .then((a.1 == Side::After).cmp(&(b.1 == Side::After)))
            .then(a.0.kind.cmp(&b.0.kind))
    });
    p
}

pub(super) fn joint(load: &LiveLoad, (c, side): Loaded) -> PatternJoint {
    PatternJoint {
        beta: c.beta,
        kind: c.kind,
        at: c.at,
        side: cert_side(load, c.beta, side),
    }
}

/// The state at λ_static and its active contacts: for a discrete arch the rows within the
/// survey's event tolerance; for a continuous arch the exchange's own pattern (its state
/// must be the survey's λ_static).
fn static_state(
    arch: &Arch,
    eta: f64,
    mu: f64,
    load: &LiveLoad,
    (lambda, x): (f64, Reactions),
    settings: &Settings,
) -> Result<(f64, Reactions, Vec<Loaded>), NotCertified> {
    match arch.layout() {
        JointLayout::Discrete(joints) => {
            let active: Vec<Loaded> = rows(arch, joints, eta, mu, load)
                .iter()
                .filter(|r| {
                    let size = magnitude(r.contact.kind, eta, mu, &x, settings.magnitude_floor);
                    r.at(&x, lambda).abs() <= settings.event_tol * size
                })
                .map(|r| (r.contact, r.side))
                .collect();
            Ok((lambda, x, sorted(active)))
        }
        JointLayout::Continuous => match extreme(arch, eta, mu, load, true, settings) {
            Ok(Some((l, xs, pattern))) if (l - lambda).abs() <= 1e-12 * (1.0 + lambda) => {
                let p = pattern
                    .iter()
                    .map(|c: &LoadedContact| (c.contact, c.side))
                    .collect();
                Ok((l, xs, sorted(p)))
            }
            _ => Err(NotCertified(format!(
                "the static maximum lambda_static = {lambda} could not be recomputed with its pattern"
            ))),
        },
    }
}

/// The two sides of λ_static: an admissible state at λ_lo, a Farkas certificate at λ_hi.
#[allow(clippy::too_many_arguments)]
fn bracket(
    arch: &Arch,
    eta: f64,
    mu: f64,
    load: &LiveLoad,
    (lambda_s, x_s, pattern): (f64, Reactions, &[Loaded]),
    cert: Certificate,
    gap: f64,
    settings: &Settings,
) -> Result<Certificate, NotCertified> {
    if lambda_s.is_nan() || lambda_s <= 0.0 {
        return Err(NotCertified(format!(
            "lambda_static = {lambda_s}: a relative bracket needs lambda_static > 0"
        )));
    }
    let row = |l: Loaded| row_at(arch, eta, mu, load, l);
    // the Farkas pool: active contacts, interior tangencies also as chords β ± δ
    let mut pool: Vec<Loaded> = pattern.to_vec();
    if matches!(arch.layout(), JointLayout::Continuous) {
        for &(c, side) in pattern {
            if c.free {
                for delta in [1e-2, 1e-3, 1e-4] {
                    for b in [c.beta - delta, c.beta + delta] {
                        if b > arch.beta_right() && b < arch.beta_left() {
                            pool.push((Contact { beta: b, ..c }, side));
                        }
                    }
                }
            }
        }
    }
    let probe = |c: &Certificate| {
        let mut p = c.clone();
        p.load_search = None;
        p
    };
    let mut g = gap.max(1e-15);
    while g <= 1e-4 {
        let lambda_hi = lambda_s * (1.0 + 0.5 * g);
        let mut lambda_lo = lambda_s * (1.0 - 0.5 * g);
        while lambda_hi - lambda_lo > g * lambda_hi {
            lambda_lo = lambda_lo.next_up();
        }
        let lo_rows: Vec<Affine> = pattern
            .iter()
            .map(|&l| at_lambda(row(l), lambda_lo))
            .collect();
        let x_lo = move_inside(&lo_rows, x_s, 1.0 / (lambda_s - lambda_lo), settings);
        if let Some(x) = x_lo {
            let mut c = cert.clone();
            c.multiplier = Some(MultiplierSides {
                admissible: Some(LoadState {
                    lambda: lambda_lo,
                    x,
                }),
                infeasible: None,
                transfer: None,
                recession: None,
            });
            if prove_admissible_side(&c).is_ok() {
                let hi_rows: Vec<(Loaded, Row)> = pool
                    .iter()
                    .map(|&l| (l, Row::from(at_lambda(row(l), lambda_hi))))
                    .collect();
                let with = |labelled: &[(Loaded, f64)]| {
                    let mut full = c.clone();
                    if let Some(m) = full.multiplier.as_mut() {
                        m.infeasible = Some(LoadFarkas {
                            lambda: Some(lambda_hi),
                            joints: cert_joints(load, labelled),
                            lambda_row: None,
                        });
                    }
                    full.gap = Some(lambda_hi - lambda_lo);
                    full.gap_relative = Some((lambda_hi - lambda_lo) / lambda_hi);
                    full
                };
                // four rows in x, or three sliding rows in (h, v) (they do not involve w)
                let sliding = reduced(&hi_rows, |l| !l.0.kind.is_hinge(), &[2]);
                let found = find_farkas(&hi_rows, 3, |l| verify(&probe(&with(l))).is_ok())
                    .or_else(|| find_farkas(&sliding, 2, |l| verify(&probe(&with(l))).is_ok()));
                if let Some(l) = found {
                    let full = with(&l);
                    return match verify(&full) {
                        Ok(_) => Ok(full),
                        Err(e) => Err(NotCertified(format!(
                            "the evidence of the limit states does not verify: {}",
                            e.0
                        ))),
                    };
                }
            }
        }
        g *= 10.0;
    }
    Err(NotCertified(format!(
        "no certificate could be proved at a relative gap up to 1e-4 (lambda_static = {lambda_s})"
    )))
}

/// The rows of `pool` that `keep` accepts, with the coordinates `drop` left out: they do
/// not enter those rows (w in the sliding rows: T and N do not involve it; λ in the rows of
/// sections that do not carry the point load, or, through x − λ d, in all that do), so a
/// Farkas certificate among them is that much lower in dimension.
pub(super) fn reduced<T: Clone>(
    pool: &[(T, Row)],
    keep: impl Fn(&T) -> bool,
    drop: &[usize],
) -> Vec<(T, Row)> {
    pool.iter()
        .filter(|(l, _)| keep(l))
        .map(|(l, r)| {
            let g =
                r.g.iter()
                    .enumerate()
                    .filter(|(k, _)| !drop.contains(k))
                    .map(|(_, v)| *v)
                    .collect();
            (l.clone(), Row { g, c: r.c })
        })
        .collect()
}

/// Whether the section of a loaded contact carries the live load (every section for a
/// horizontal load; for a point load those after it, and the `After` side of its own).
pub(super) fn carries(load: &LiveLoad, (c, side): Loaded) -> bool {
    match *load {
        LiveLoad::Horizontal { .. } => true,
        LiveLoad::Point { beta } => c.beta > beta || (c.beta == beta && side == Side::After),
    }
}

pub(super) fn cert_joints(load: &LiveLoad, labelled: &[(Loaded, f64)]) -> Vec<CertJoint> {
    labelled
        .iter()
        .map(|&((c, side), y)| CertJoint {
            beta: c.beta,
            kind: c.kind,
            side: cert_side(load, c.beta, side),
            y,
        })
        .collect()
}
