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

use super::certify::{empty, farkas_cover, find_farkas, move_inside, Row};
use super::format::*;
use super::verify::verify;
use super::verify_load::prove_admissible_side;
use crate::admissibility::{max_margin, Goal, WorkingSet};
use crate::arch::{Arch, JointLayout};
use crate::contact::{Contact, ContactKind};
use crate::kinematics::{column, power};
use crate::limit_states::sweep::{sweep_load, CheckedPoint};
use crate::load::{live_activation, rows, LiveLoad};
use crate::lp;
use crate::multiplier::continuum::{extreme, LoadedContact};
use crate::multiplier::{
    static_range, survey, LoadLimitState, LoadOutcome, LoadSurvey, StaticRange,
    UNBOUNDED_SEARCH_TOP,
};
use crate::settings::Settings;
use crate::statics::{actions, magnitude, Affine, Reactions};

/// A contact of the loaded problem: the activation function and the side of the loaded
/// section it belongs to (`After` away from a point load).
type Loaded = (Contact, Side);

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
fn at_lambda((a, c): ([f64; 4], f64), lambda: f64) -> Affine {
    Affine {
        g: [a[0], a[1], a[2]],
        c: c + a[3] * lambda,
    }
}

/// Sorts loaded contacts by (β, side, kind), `Before` first: the order of certificates.
fn sorted(mut p: Vec<Loaded>) -> Vec<Loaded> {
    p.sort_by(|a, b| {
        a.0.beta
            .total_cmp(&b.0.beta)
            .then((a.1 == Side::After).cmp(&(b.1 == Side::After)))
            .then(a.0.kind.cmp(&b.0.kind))
    });
    p
}

fn joint(load: &LiveLoad, (c, side): Loaded) -> PatternJoint {
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
fn reduced<T: Clone>(
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
fn carries(load: &LiveLoad, (c, side): Loaded) -> bool {
    match *load {
        LiveLoad::Horizontal { .. } => true,
        LiveLoad::Point { beta } => c.beta > beta || (c.beta == beta && side == Side::After),
    }
}

fn cert_joints(load: &LiveLoad, labelled: &[(Loaded, f64)]) -> Vec<CertJoint> {
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

/// An unbounded multiplier: a state admissible at λ_min and a transfer of the point load
/// to a springing (right, then left) that the verifier proves; else no certificate.
fn unbounded(
    arch: &Arch,
    eta: f64,
    mu: f64,
    load: &LiveLoad,
    (lambda_min, x_min): (f64, Reactions),
    mut cert: Certificate,
    settings: &Settings,
) -> Result<Certificate, NotCertified> {
    let unproved = |why: &str| {
        NotCertified(format!(
            "lambda_static is unbounded (admissible states at every lambda >= {lambda_min}), but it is not certified: {why}"
        ))
    };
    // a state strictly inside the admissible set at the start of the ray
    let start = if lambda_min == 0.0 {
        let mut ws = WorkingSet::initial(arch);
        max_margin(
            arch,
            eta,
            mu,
            ContactKind::active_at(mu),
            &mut ws,
            Goal::Optimise,
            settings,
        )
        .ok()
        .filter(|m| m.margin > 0.0)
        .map(|m| (0.0, m.x))
    } else if let JointLayout::Discrete(joints) = arch.layout() {
        let lambda = 2.0 * lambda_min;
        let r: Vec<Affine> = rows(arch, joints, eta, mu, load)
            .iter()
            .map(|r| at_lambda(r.pair(), lambda))
            .collect();
        lp::max_margin(&r, 1.0, settings)
            .ok()
            .filter(|m| m.1 > 0.0)
            .map(|m| (lambda, m.0))
    } else {
        None
    };
    let (lambda, x) = start.unwrap_or((lambda_min, x_min));
    let sides = |transfer, recession| MultiplierSides {
        admissible: Some(LoadState { lambda, x }),
        infeasible: None,
        transfer,
        recession,
    };
    for transfer in [Transfer::Right, Transfer::Left] {
        cert.multiplier = Some(sides(Some(transfer), None));
        if verify(&cert).is_ok() {
            return Ok(cert);
        }
    }
    // a direction along which every row decreases strictly: the margin LP on the rows'
    // linear parts g · d_x + a_λ (every joint, or a fine sample of a continuous arch)
    let joints: Vec<f64> = match arch.layout() {
        JointLayout::Discrete(j) => j.clone(),
        JointLayout::Continuous => sample(arch, load),
    };
    let linear: Vec<Affine> = rows(arch, &joints, eta, mu, load)
        .iter()
        .map(|r| Affine {
            g: [r.a[0], r.a[1], r.a[2]],
            c: r.a[3],
        })
        .collect();
    if let Ok((d, s)) = lp::max_margin(&linear, 1.0, settings) {
        if s > 0.0 {
            cert.multiplier = Some(sides(None, Some(LoadState { lambda: 1.0, x: d })));
            if verify(&cert).is_ok() {
                return Ok(cert);
            }
        }
    }
    Err(unproved(
        "neither a transfer of the load to a springing nor a direction along which every activation function decreases strictly was proved (the recession directions of the admissible set leave some activation functions exactly at zero, which interval arithmetic cannot prove <= 0)",
    ))
}

/// 721 equally spaced angles of a continuous arch, and the point load's own.
fn sample(arch: &Arch, load: &LiveLoad) -> Vec<f64> {
    let (a, b) = (arch.beta_right(), arch.beta_left());
    // the last angle exactly the springing (a + (b − a) can round past it)
    let mut j: Vec<f64> = (0..=720)
        .map(|i| {
            if i == 720 {
                b
            } else {
                a + (b - a) * i as f64 / 720.0
            }
        })
        .collect();
    if let LiveLoad::Point { beta } = *load {
        j.push(beta);
        j.sort_by(f64::total_cmp);
        j.dedup();
    }
    j
}

/// No state at any λ ≥ 0: a Farkas certificate over (h, v, w, λ).
fn no_equilibrium(
    arch: &Arch,
    eta: f64,
    mu: f64,
    load: &LiveLoad,
    cert: Certificate,
    settings: &Settings,
) -> Result<Certificate, NotCertified> {
    // the rows: every joint's, or a fine sample of a continuous arch (a certificate on a
    // subset of sections holds for the whole arch)
    let joints: Vec<f64> = match arch.layout() {
        JointLayout::Discrete(j) => j.clone(),
        JointLayout::Continuous => sample(arch, load),
    };
    let all: Vec<(Loaded, [f64; 4], f64)> = rows(arch, &joints, eta, mu, load)
        .iter()
        .map(|r| ((r.contact, r.side), r.a, r.c))
        .collect();
    let margin = |lambda: f64| {
        let r: Vec<Affine> = all
            .iter()
            .map(|(_, a, c)| at_lambda((*a, *c), lambda))
            .collect();
        lp::max_margin(&r, 1.0, settings).ok()
    };
    // s(λ) = max_x min_i (−φ_i / ‖∇ₓφ_i‖) is concave in λ: bracket its maximum by
    // doubling, then golden section
    let s = |l: f64| margin(l).map_or(f64::NEG_INFINITY, |m| m.1);
    let (mut a, mut b) = (0.0, 1.0);
    let mut prev = s(0.0);
    while b < 1e8 {
        let v = s(b);
        if v <= prev {
            break;
        }
        prev = v;
        a = 0.5 * b;
        b *= 2.0;
    }
    let phi = 0.5 * (5f64.sqrt() - 1.0);
    let (mut lo, mut hi) = (if a > 0.0 { 0.5 * a } else { 0.0 }, b);
    for _ in 0..80 {
        let m1 = hi - phi * (hi - lo);
        let m2 = lo + phi * (hi - lo);
        if s(m1) < s(m2) {
            lo = m1;
        } else {
            hi = m2;
        }
    }
    let lambda = if s(0.0) >= s(0.5 * (lo + hi)) {
        0.0
    } else {
        0.5 * (lo + hi)
    };
    let Some((x, best)) = margin(lambda) else {
        return Err(NotCertified("the margin LP failed".into()));
    };
    if best >= 0.0 {
        return Err(NotCertified(format!(
            "no Farkas certificate: the rows used here admit a state at lambda = {lambda} (a continuous arch sampled at 721 angles, or the LP's tolerance)"
        )));
    }
    // the rows nearest to binding there
    let mut near: Vec<(f64, usize)> = all
        .iter()
        .enumerate()
        .map(|(i, (_, a, c))| {
            let r = at_lambda((*a, *c), lambda);
            let slack = -r.at(&x) / r.grad_norm().max(f64::MIN_POSITIVE);
            (slack - best, i)
        })
        .collect();
    near.sort_by(|p, q| p.0.total_cmp(&q.0));
    // on a sampled continuum the neighbours of one binding angle crowd the nearest rows:
    // one row per (kind, side) within a few samples
    let spacing = match arch.layout() {
        JointLayout::Continuous => 3.5 * (arch.beta_left() - arch.beta_right()) / 720.0,
        JointLayout::Discrete(_) => 0.0,
    };
    let mut chosen: Vec<usize> = Vec::new();
    for &(_, i) in &near {
        if chosen.len() == 10 {
            break;
        }
        let (c, side) = all[i].0;
        let crowded = chosen.iter().any(|&k| {
            let (o, s) = all[k].0;
            o.kind == c.kind && s == side && (o.beta - c.beta).abs() < spacing
        });
        if !crowded {
            chosen.push(i);
        }
    }
    let mut pool: Vec<(Option<Loaded>, Row)> = chosen
        .iter()
        .map(|&i| {
            let (l, a, c) = all[i];
            (Some(l), Row { g: a.to_vec(), c })
        })
        .collect();
    pool.push((
        None,
        Row {
            g: vec![0.0, 0.0, 0.0, -1.0],
            c: 0.0,
        },
    ));
    let with = |labelled: &[(Option<Loaded>, f64)]| {
        let mut c = cert.clone();
        let joints: Vec<(Loaded, f64)> = labelled
            .iter()
            .filter_map(|(l, y)| l.map(|l| (l, *y)))
            .collect();
        c.multiplier = Some(MultiplierSides {
            admissible: None,
            infeasible: Some(LoadFarkas {
                lambda: None,
                joints: cert_joints(load, &joints),
                lambda_row: labelled.iter().find(|(l, _)| l.is_none()).map(|p| p.1),
            }),
            transfer: None,
            recession: None,
        });
        c
    };
    // all five rows, or fewer where w (sliding rows) or λ does not enter them: sections the
    // point load does not reach fail on their own, whatever λ; those it reaches see it only
    // through x − λ d (a certificate in x among them holds at every λ)
    let slides = |l: &Option<Loaded>| l.is_none_or(|l| !l.0.kind.is_hinge());
    let unloaded = |l: &Option<Loaded>| l.is_some_and(|l| !carries(load, l));
    let point = matches!(load, LiveLoad::Point { .. });
    let loaded = |l: &Option<Loaded>| point && l.is_some_and(|l| carries(load, l));
    let tries = [
        (pool.clone(), 4),
        (reduced(&pool, slides, &[2]), 3),
        (reduced(&pool, unloaded, &[3]), 3),
        (reduced(&pool, |l| slides(l) && unloaded(l), &[2, 3]), 2),
        (reduced(&pool, loaded, &[3]), 3),
        (reduced(&pool, |l| slides(l) && loaded(l), &[2, 3]), 2),
    ];
    tries
        .iter()
        .find_map(|(p, d)| find_farkas(p, *d, |l| verify(&with(l)).is_ok()))
        .map(|l| with(&l))
        .ok_or_else(|| {
            NotCertified(format!(
                "no provable Farkas certificate of no equilibrium at eta = {eta} (best margin {best:e} at lambda = {lambda})"
            ))
        })
}

/// The evidence of the limit states of a survey (`static`: the state at λ_static and its
/// active contacts, when finite).
fn evidence(
    arch: &Arch,
    eta: f64,
    load: &LiveLoad,
    sv: &LoadSurvey,
    at_static: Option<(f64, Reactions, &[Loaded])>,
    settings: &Settings,
) -> Result<LoadSearchEvidence, NotCertified> {
    let method = match sv.method {
        "sweep" => LoadSearchMethod::Sweep,
        "associative" => LoadSearchMethod::Associative,
        _ => LoadSearchMethod::Refined,
    };
    let limit_states = sv
        .limit_states
        .iter()
        .map(|s| limit_state_cert(load, s))
        .collect::<Result<Vec<_>, _>>()?;
    let static_state = match at_static {
        Some((lambda, x, pattern)) if !sv.mechanism_at_static => Some(no_mechanism(
            arch,
            eta,
            load,
            (lambda, x, pattern.to_vec()),
            settings,
        )),
        _ => None,
    };
    Ok(LoadSearchEvidence {
        method,
        events: sv.events,
        lambda_min: sv.lambda_min.0,
        mechanism_at_static: sv.mechanism_at_static,
        unique: sv.unique(),
        lambda: sv.lambda(),
        limit_states,
        static_state,
        no_mechanism: checked(arch, eta, load, &sv.no_mechanism, settings),
    })
}

/// Where λ_static is unbounded and no limit state exists (`NoCollapse`): at μ = ∞ the
/// associative argument; at finite μ on a discrete arch the sweep again (the survey keeps
/// no list there), its points without a mechanism as evidence.
fn unbounded_evidence(
    arch: &Arch,
    eta: f64,
    mu: f64,
    load: &LiveLoad,
    (lambda_min, x_min): (f64, Reactions),
    settings: &Settings,
) -> Option<LoadSearchEvidence> {
    let empty = |method, events, no_mechanism| LoadSearchEvidence {
        method,
        events,
        lambda_min,
        mechanism_at_static: false,
        unique: false,
        lambda: None,
        limit_states: Vec::new(),
        static_state: None,
        no_mechanism,
    };
    if mu.is_infinite() {
        return Some(empty(LoadSearchMethod::Associative, 0, Vec::new()));
    }
    if !matches!(arch.layout(), JointLayout::Discrete(_)) {
        return None;
    }
    let sw = sweep_load(
        arch,
        eta,
        mu,
        load,
        (lambda_min, x_min),
        UNBOUNDED_SEARCH_TOP,
        settings,
    );
    if sw.failure.is_some() || !sw.states.is_empty() {
        return None;
    }
    Some(empty(
        LoadSearchMethod::Sweep,
        sw.events,
        checked(arch, eta, load, &sw.no_mechanism, settings),
    ))
}

/// The sweep's points without a mechanism, each with its proof.
fn checked(
    arch: &Arch,
    eta: f64,
    load: &LiveLoad,
    points: &[CheckedPoint],
    settings: &Settings,
) -> Vec<LoadNoMechanism> {
    points
        .iter()
        .map(|p| {
            let pattern: Vec<Loaded> = p
                .pattern
                .iter()
                .copied()
                .zip(p.sides.iter().copied())
                .collect();
            no_mechanism(arch, eta, load, (p.eta, p.x, sorted(pattern)), settings)
        })
        .collect()
}

/// A limit state under the load in the certificate's order, its rates on its pattern.
fn limit_state_cert(
    load: &LiveLoad,
    s: &LoadLimitState,
) -> Result<LoadLimitStateCert, NotCertified> {
    let pattern = sorted(
        s.pattern
            .iter()
            .copied()
            .zip(s.sides.iter().copied())
            .collect(),
    );
    let rates = rates_on(&pattern, &s.mechanism.contacts, &s.mechanism.rates).ok_or_else(|| {
        NotCertified(format!(
            "the mechanism of the limit state at lambda = {} does not match its pattern",
            s.lambda
        ))
    })?;
    Ok(LoadLimitStateCert {
        lambda: s.lambda,
        x: s.x,
        pattern: pattern.iter().map(|&l| joint(load, l)).collect(),
        rates,
        live_power: s.live_power,
        continuum: s.continuum_to.map(|to| ContinuumEnd {
            to: to.is_finite().then_some(to),
        }),
    })
}

/// The rates of a mechanism (on the kept contacts of one sliding sense per section, in
/// the pattern's (β, side, kind) order but without sides) on the whole `pattern`: at each
/// angle the kept contacts of the `before` side come first, one fewer than listed where a
/// section has both sliding senses; a contact left out gets rate 0.
fn rates_on(pattern: &[Loaded], kept: &[Contact], rates: &[f64]) -> Option<Vec<f64>> {
    let mut out = vec![0.0; pattern.len()];
    let mut next = 0;
    let mut i = 0;
    while i < pattern.len() {
        // the section (β, side) from i
        let (beta, side) = (pattern[i].0.beta, pattern[i].1);
        let end = (i..pattern.len())
            .find(|&k| pattern[k].0.beta != beta || pattern[k].1 != side)
            .unwrap_or(pattern.len());
        let has = |kind| (i..end).any(|k| pattern[k].0.kind == kind);
        let n = end - i - usize::from(has(ContactKind::SlidePlus) && has(ContactKind::SlideMinus));
        for _ in 0..n {
            let c = kept.get(next)?;
            let k =
                (i..end).find(|&k| pattern[k].0.kind == c.kind && pattern[k].0.beta == c.beta)?;
            out[k] = *rates.get(next)?;
            next += 1;
        }
        i = end;
    }
    (next == kept.len()).then_some(out)
}

/// A state without a mechanism with positive live power, with the Farkas alternative of
/// the kinematic LP for every one-sense choice: max z with c_j·y + z + u P_j + v q_j ≤ 0
/// (P total, q live power), tried with the power rows combined as a P + b q (u = a w,
/// v = b w) for a few ratios; z is halved to leave the verifier room for rounding.
fn no_mechanism(
    arch: &Arch,
    eta: f64,
    load: &LiveLoad,
    (lambda, x, pattern): (f64, Reactions, Vec<Loaded>),
    settings: &Settings,
) -> LoadNoMechanism {
    let keys: Vec<(f64, ContactKind, Side)> =
        pattern.iter().map(|(c, s)| (c.beta, c.kind, *s)).collect();
    let farkas = farkas_cover(&keys, |drop: Vec<usize>| {
        let kept: Vec<Loaded> = (0..pattern.len())
            .filter(|i| !drop.contains(i))
            .map(|i| pattern[i])
            .collect();
        let plain: Vec<Contact> = kept.iter().map(|p| p.0).collect();
        let cols: Vec<[f64; 3]> = plain.iter().map(|c| column(c.kind, c.beta, eta)).collect();
        let dead = power(arch, eta, &plain);
        let live = load.power(arch, eta, &kept);
        let total: Vec<f64> = dead
            .iter()
            .zip(&live)
            .map(|(d, l)| d + lambda * l)
            .collect();
        [
            (1.0, 0.0),
            (0.0, 1.0),
            (1.0, 1.0),
            (1.0, 0.1),
            (0.1, 1.0),
            (1.0, 0.01),
            (0.01, 1.0),
        ]
        .iter()
        .find_map(|&(a, b)| {
            let p: Vec<f64> = total
                .iter()
                .zip(&live)
                .map(|(t, l)| a * t + b * l)
                .collect();
            let (y, z, u) = lp::kinematic_farkas(&cols, &p, settings).ok()?;
            (z > 0.0).then_some(KinematicFarkas {
                drop: drop.clone(),
                y,
                z: 0.5 * z,
                u: (a * u).max(0.0),
                v: (b * u).max(0.0),
            })
        })
    });
    LoadNoMechanism {
        lambda,
        x,
        pattern: pattern.iter().map(|&l| joint(load, l)).collect(),
        farkas,
    }
}
