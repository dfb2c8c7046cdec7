//! The two ends of the load question for a certificate (see
//! [`certify_load()`](super::certify_load)): no admissible multiplier at all
//! (`no_equilibrium`, a Farkas certificate in (h, v, w, λ)), or no largest one
//! (`unbounded_multiplier`, a state and a transfer or recession direction).

use super::loaded::{at_lambda, carries, cert_joints, Loaded};
use super::sides::{find_farkas, reduced, Row};
use crate::arch::{Arch, JointLayout};
use crate::assess::safest_state;
use crate::certificate::format::{
    Certificate, LoadFarkas, LoadState, MultiplierSides, NotCertified, Transfer,
};
use crate::certificate::verify::verify;
use crate::load::{rows, LiveLoad};
use crate::lp;
use crate::settings::Settings;
use crate::statics::{Affine, Reactions};

/// An unbounded multiplier: a state admissible at λ_min and a transfer of the point load
/// to a springing (right, then left) that the verifier proves; else no certificate.
pub(super) fn unbounded(
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
        safest_state(arch, eta, mu, settings)
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
pub(super) fn no_equilibrium(
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
    let lambda = best_multiplier(|l: f64| margin(l).map_or(f64::NEG_INFINITY, |m| m.1));
    let Some((x, best)) = margin(lambda) else {
        return Err(NotCertified("the margin LP failed".into()));
    };
    if best >= 0.0 {
        return Err(NotCertified(format!(
            "no Farkas certificate: the rows used here admit a state at lambda = {lambda} (a continuous arch sampled at 721 angles, or the LP's tolerance)"
        )));
    }
    let pool = nearest_rows(arch, &all, lambda, x, best);
    farkas_among(load, &pool, &cert).ok_or_else(|| {
        NotCertified(format!(
            "no provable Farkas certificate of no equilibrium at eta = {eta} (best margin {best:e} at lambda = {lambda})"
        ))
    })
}

/// The multiplier λ* ≥ 0 that maximises the x-margin of the rows,
/// s(λ) = max_x min_i (−φ_i / ‖∇ₓφ_i‖): s is concave in λ, so its maximum is bracketed by
/// doubling, then found by golden section.
fn best_multiplier(s: impl Fn(f64) -> f64) -> f64 {
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
    if s(0.0) >= s(0.5 * (lo + hi)) {
        0.0
    } else {
        0.5 * (lo + hi)
    }
}

/// The Farkas pool at λ* (where the best state `x` has margin `best` < 0): the rows of `all`
/// nearest to binding there, and the row −λ ≤ 0 (label `None`).
fn nearest_rows(
    arch: &Arch,
    all: &[(Loaded, [f64; 4], f64)],
    lambda: f64,
    x: Reactions,
    best: f64,
) -> Vec<(Option<Loaded>, Row)> {
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
    pool
}

/// The certificate of no equilibrium from a proved Farkas combination among the `pool`'s
/// rows in (h, v, w, λ), or among fewer of their coordinates.
fn farkas_among(
    load: &LiveLoad,
    pool: &[(Option<Loaded>, Row)],
    cert: &Certificate,
) -> Option<Certificate> {
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
                joints: cert_joints(Some(load), &joints),
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
        (pool.to_vec(), 4),
        (reduced(pool, slides, &[2]), 3),
        (reduced(pool, unloaded, &[3]), 3),
        (reduced(pool, |l| slides(l) && unloaded(l), &[2, 3]), 2),
        (reduced(pool, loaded, &[3]), 3),
        (reduced(pool, |l| slides(l) && loaded(l), &[2, 3]), 2),
    ];
    tries
        .iter()
        .find_map(|(p, d)| find_farkas(p, *d, |l| verify(&with(l)).is_ok()))
        .map(|l| with(&l))
}
