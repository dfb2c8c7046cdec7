//! Building a certificate around the exact limit state (see the module documentation of
//! [`crate::certificate`]).

use super::format::*;
use super::verify::{prove_safe_only, verify};
use crate::arch::{Arch, JointLayout};
use crate::contact::Contact;
use crate::contact::ContactKind;
use crate::friction::friction_limit;
use crate::kinematics::{column, power};
use crate::limit::{LimitState, Outcome};
use crate::limit_states::{survey, LimitStates, Survey, SweptState};
use crate::lp;
use crate::mechanism::Mechanism;
use crate::settings::{LimitStateSearch, Settings};
use crate::state::State;
use crate::statics::{actions, Affine, Reactions};
use itertools::Itertools;

pub(super) fn spec(arch: &Arch) -> ArchSpec {
    ArchSpec {
        beta_right: arch.beta_right(),
        beta_left: arch.beta_left(),
        weight: arch.weight(),
        joint_angles: match arch.layout() {
            JointLayout::Continuous => None,
            JointLayout::Discrete(j) => Some(j.clone()),
        },
    }
}

pub(super) fn empty(arch: &Arch, mu: f64, claim: Claim) -> Certificate {
    Certificate {
        format: FORMAT.into(),
        version: VERSION,
        tool: format!("arch-enum {}", env!("CARGO_PKG_VERSION")),
        arch: spec(arch),
        mu: mu.is_finite().then_some(mu),
        claim,
        safe: None,
        collapse: None,
        limit_state: None,
        gap: None,
        gap_relative: None,
        search: None,
        load: None,
        multiplier: None,
        load_search: None,
    }
}

/// An affine function of d unknowns (d = 2, 3 or 4): `g · u + c`.
#[derive(Debug, Clone)]
pub(super) struct Row {
    /// Gradient (the first d components are used).
    pub(super) g: Vec<f64>,
    /// Constant term.
    pub(super) c: f64,
}

impl From<Affine> for Row {
    fn from(a: Affine) -> Row {
        Row {
            g: a.g.to_vec(),
            c: a.c,
        }
    }
}

/// Float cofactor multipliers of d + 1 affine functions (gradients in the first d
/// components), normalised to sum 1 when they share a sign, with the Farkas constant.
fn farkas_float(rows: &[Row], d: usize) -> Option<(Vec<f64>, f64)> {
    let y: Vec<f64> = (0..=d)
        .map(|i| {
            let cols: Vec<usize> = (0..=d).filter(|&k| k != i).collect();
            let sign = if i % 2 == 0 { 1.0 } else { -1.0 };
            let g = |k: usize, r: usize| rows[cols[k]].g[r];
            sign * match d {
                4 => nalgebra::Matrix4::from_fn(|r, k| g(k, r)).determinant(),
                3 => nalgebra::Matrix3::from_fn(|r, k| g(k, r)).determinant(),
                _ => nalgebra::Matrix2::from_fn(|r, k| g(k, r)).determinant(),
            }
        })
        .collect();
    let total: f64 = y.iter().sum();
    if total == 0.0 || !y.iter().all(|v| v * total > 0.0) {
        return None;
    }
    let y: Vec<f64> = y.iter().map(|v| v / total).collect();
    let c: f64 = y.iter().zip(rows).map(|(a, r)| a * r.c).sum();
    (c > 0.0).then_some((y, c))
}

/// Searches `pool` (labels and their rows) for a (d+1)-subset with a valid float Farkas
/// combination, best margin first, and returns the first (labels with their multipliers)
/// that `check` accepts (the verifier proves).
pub(super) fn find_farkas<T: Clone>(
    pool: &[(T, Row)],
    d: usize,
    check: impl Fn(&[(T, f64)]) -> bool,
) -> Option<Vec<(T, f64)>> {
    let mut found: Vec<(f64, Vec<usize>, Vec<f64>)> = Vec::new();
    for sub in (0..pool.len()).combinations(d + 1) {
        let rows: Vec<Row> = sub.iter().map(|&i| pool[i].1.clone()).collect();
        if let Some((y, c)) = farkas_float(&rows, d) {
            let norm: f64 = y
                .iter()
                .zip(&rows)
                .map(|(a, r)| a * r.c.abs())
                .sum::<f64>()
                .max(f64::MIN_POSITIVE);
            found.push((c / norm, sub, y));
        }
    }
    found.sort_by(|a, b| b.0.total_cmp(&a.0));
    found.into_iter().take(12).find_map(|(_, sub, y)| {
        let labelled: Vec<(T, f64)> = sub
            .iter()
            .zip(&y)
            .map(|(&i, &y)| (pool[i].0.clone(), y))
            .collect();
        check(&labelled).then_some(labelled)
    })
}

fn joints_of(contacts: &[Contact], y: &[f64]) -> Vec<CertJoint> {
    contacts
        .iter()
        .zip(y)
        .map(|(c, &y)| CertJoint {
            beta: c.beta,
            kind: c.kind,
            side: None,
            y,
        })
        .collect()
}

/// The thickness problem's Farkas search over contacts at (η, μ).
fn find_contact_farkas(
    arch: &Arch,
    pool: &[Contact],
    eta: f64,
    mu: f64,
    d: usize,
    check: impl Fn(&Farkas) -> bool,
) -> Option<Farkas> {
    let rows: Vec<(Contact, Row)> = pool
        .iter()
        .map(|c| {
            let row = actions(arch, eta, c.beta).activation(c.kind, 0, eta, mu);
            (*c, Row::from(row))
        })
        .collect();
    let make = |labelled: &[(Contact, f64)]| {
        let (contacts, y): (Vec<Contact>, Vec<f64>) = labelled.iter().copied().unzip();
        Farkas {
            eta: (d == 3).then_some(eta),
            joints: joints_of(&contacts, &y),
        }
    };
    find_farkas(&rows, d, |l| check(&make(l))).map(|l| make(&l))
}

/// Builds a certificate for `arch` at friction `mu` with requested relative gap `gap`
/// (e.g. 1e-12). The certificate is verified before it is returned. When the requested
/// gap cannot be proved the gap is widened tenfold (up to 1e-4) and the best certificate
/// found is returned: check [`Certificate::delivers_gap`] to know whether the request
/// was met.
pub fn certify(
    arch: &Arch,
    mu: f64,
    gap: f64,
    settings: &Settings,
) -> Result<Certificate, NotCertified> {
    // a discrete arch's certificate carries the sweep's checked points as evidence (the
    // ridge walk has no evidence format yet): its search is the sweep
    let settings = &match arch.layout() {
        JointLayout::Discrete(_) => Settings {
            limit_state_search: LimitStateSearch::Sweep,
            ..settings.clone()
        },
        JointLayout::Continuous => settings.clone(),
    };
    let survey = survey(arch, mu, settings).map_err(|e| NotCertified(e.to_string()))?;
    match survey.solution.outcome.clone() {
        Outcome::Limit(ls) => certify_limit(arch, mu, &survey, &ls, gap, settings),
        Outcome::NoEquilibrium { mu_ms: Some(m), .. } if mu < m => {
            certify_no_equilibrium(arch, mu, settings)
        }
        Outcome::NoEquilibrium { reason, .. }
        | Outcome::Unresolved { reason, .. }
        | Outcome::NoCollapse { reason } => Err(NotCertified(reason)),
    }
}

fn certify_no_equilibrium(
    arch: &Arch,
    mu: f64,
    settings: &Settings,
) -> Result<Certificate, NotCertified> {
    let fl = friction_limit(arch, settings)
        .map_err(NotCertified)?
        .ok_or_else(|| NotCertified("no finite friction admits equilibrium".into()))?;
    let mut cert = empty(arch, mu, Claim::NoEquilibrium);
    let f = find_contact_farkas(arch, &fl.pattern, 1.0, mu, 2, |f| {
        let mut c = cert.clone();
        c.collapse = Some(f.clone());
        verify(&c).is_ok()
    })
    .ok_or_else(|| {
        NotCertified(format!(
            "no provable Farkas certificate for mu = {mu} below mu_ms = {}",
            fl.mu
        ))
    })?;
    cert.collapse = Some(f);
    Ok(cert)
}

/// A limit state in the format's order: pattern increasing in (β, kind), rates alongside.
fn limit_state_cert(eta: f64, x: Reactions, mechanism: &Mechanism) -> LimitStateCert {
    let mut joints: Vec<(PatternJoint, f64)> = mechanism
        .contacts
        .iter()
        .zip(&mechanism.rates)
        .map(|(c, &r)| (pattern_joint(c), r))
        .collect();
    joints.sort_by(|a, b| a.0.beta.total_cmp(&b.0.beta).then(a.0.kind.cmp(&b.0.kind)));
    LimitStateCert {
        eta,
        x,
        pattern: joints.iter().map(|(j, _)| j.clone()).collect(),
        rates: joints.iter().map(|&(_, r)| r).collect(),
        complementarity_residual: mechanism.complementarity,
    }
}

pub(super) fn pattern_joint(c: &Contact) -> PatternJoint {
    PatternJoint {
        beta: c.beta,
        kind: c.kind,
        at: c.at,
        side: None,
    }
}

/// Farkas certificates that the kinematic LP on `pattern` at η is infeasible for every
/// one-sense choice (a joint where both sliding senses are active slides one way only):
/// first for the whole pattern, else one per choice. z is halved so that every inequality
/// holds with room for the verifier's rounding. Those that cannot be found are left out
/// (the verifier then reports the state as not proved).
fn kinematic_farkas(
    arch: &Arch,
    eta: f64,
    pattern: &[Contact],
    settings: &Settings,
) -> Vec<KinematicFarkas> {
    let keys: Vec<(f64, ContactKind, bool)> =
        pattern.iter().map(|c| (c.beta, c.kind, false)).collect();
    farkas_cover(&keys, |drop: Vec<usize>| {
        let kept: Vec<Contact> = (0..pattern.len())
            .filter(|i| !drop.contains(i))
            .map(|i| pattern[i])
            .collect();
        let cols: Vec<[f64; 3]> = kept.iter().map(|c| column(c.kind, c.beta, eta)).collect();
        let p = power(arch, eta, &kept);
        let (y, z, u) = lp::kinematic_farkas(&cols, &p, settings).ok()?;
        (z > 0.0).then_some(KinematicFarkas {
            drop,
            y,
            z: 0.5 * z,
            u: u.max(0.0),
            v: 0.0,
        })
    })
}

/// Farkas certificates for every one-sense choice of a pattern whose contacts have the
/// keys (angle, kind, section): first `one` on the whole pattern, else on each choice of
/// one sliding sense per section where both are listed (indices of the left-out contacts).
pub(super) fn farkas_cover<S: PartialEq>(
    keys: &[(f64, ContactKind, S)],
    one: impl Fn(Vec<usize>) -> Option<KinematicFarkas>,
) -> Vec<KinematicFarkas> {
    if let Some(f) = one(Vec::new()) {
        return vec![f];
    }
    // sections with both senses: (index of S+, index of S−)
    let both: Vec<(usize, usize)> = (0..keys.len())
        .filter(|&i| keys[i].1 == ContactKind::SlidePlus)
        .filter_map(|i| {
            (0..keys.len())
                .find(|&k| {
                    keys[k].1 == ContactKind::SlideMinus
                        && keys[k].0 == keys[i].0
                        && keys[k].2 == keys[i].2
                })
                .map(|k| (i, k))
        })
        .collect();
    if both.is_empty() || both.len() > 8 {
        return Vec::new();
    }
    (0..1usize << both.len())
        .filter_map(|choice| {
            let drop: Vec<usize> = both
                .iter()
                .enumerate()
                .map(|(b, &(p, m))| if choice >> b & 1 == 0 { m } else { p })
                .collect();
            one(drop)
        })
        .collect()
}

fn no_mechanism(
    arch: &Arch,
    eta: f64,
    x: Reactions,
    pattern: &[Contact],
    settings: &Settings,
) -> NoMechanism {
    let mut pattern = pattern.to_vec();
    pattern.sort_by(|a, b| a.beta.total_cmp(&b.beta).then(a.kind.cmp(&b.kind)));
    NoMechanism {
        eta,
        x,
        pattern: pattern.iter().map(pattern_joint).collect(),
        farkas: kinematic_farkas(arch, eta, &pattern, settings),
    }
}

/// The evidence of the limit-state search, for the certificate.
fn evidence(
    arch: &Arch,
    found: &LimitStates,
    least: (f64, Reactions, &[Contact]),
    unique: bool,
    settings: &Settings,
) -> SearchEvidence {
    let method = if found.method.starts_with("sweep") {
        SearchMethod::Sweep
    } else if found.method.starts_with("hinges only") {
        SearchMethod::HingesOnly
    } else {
        SearchMethod::Refined
    };
    let above = |s: &SweptState| limit_state_cert(s.eta, s.x, &s.mechanism);
    SearchEvidence {
        method,
        events: found.events,
        mechanism_at_eta: found.mechanism_at_eta_s,
        unique,
        least_state: (!found.mechanism_at_eta_s && found.attained)
            .then(|| no_mechanism(arch, least.0, least.1, least.2, settings)),
        limit_states_above: found.above.iter().map(above).collect(),
        no_mechanism: found
            .no_mechanism
            .iter()
            .map(|p| no_mechanism(arch, p.eta, p.x, &p.pattern, settings))
            .collect(),
    }
}

fn certify_limit(
    arch: &Arch,
    mu: f64,
    survey: &Survey,
    ls: &LimitState,
    gap: f64,
    settings: &Settings,
) -> Result<Certificate, NotCertified> {
    let mut cert = empty(arch, mu, Claim::LeastThickness);
    // the bracket is around η_s, the least admissible state, which need not carry a
    // mechanism (non-associative gap): its pattern is its active set
    let (eta_s, x_s) = (ls.eta_static, ls.x_static);
    let gap_case = ls.eta != ls.eta_static;
    let pattern_s: Vec<Contact> = if gap_case {
        State {
            arch,
            eta: eta_s,
            mu,
            x: x_s,
        }
        .verdict(ContactKind::active_at(mu), settings)
        .active
    } else {
        ls.pattern.clone()
    };
    // the limit state: the one at η_s, else the least above it (only when the search is
    // complete: otherwise the widened state is not known to be the least)
    cert.limit_state = match (&survey.states, gap_case) {
        (_, false) => Some(limit_state_cert(ls.eta, ls.x, &ls.mechanism)),
        (Ok(found), true) => found
            .above
            .first()
            .map(|s| limit_state_cert(s.eta, s.x, &s.mechanism)),
        (Err(_), true) => None,
    };
    if let (Ok(found), Some(unique)) = (&survey.states, survey.unique()) {
        cert.search = Some(evidence(
            arch,
            found,
            (eta_s, x_s, &pattern_s),
            unique,
            settings,
        ));
    }
    // the Farkas pool: active contacts, interior tangencies also as chords β ± δ
    let mut pool: Vec<Contact> = pattern_s.clone();
    if matches!(arch.layout(), JointLayout::Continuous) {
        for c in &pattern_s {
            if c.free {
                for delta in [1e-2, 1e-3, 1e-4] {
                    for b in [c.beta - delta, c.beta + delta] {
                        if b > arch.beta_right() && b < arch.beta_left() {
                            pool.push(Contact { beta: b, ..*c });
                        }
                    }
                }
            }
        }
    }
    let mut g = gap.max(1e-15);
    while g <= 1e-4 {
        let eta_hi = eta_s * (1.0 + 0.5 * g);
        let mut eta_lo = eta_s * (1.0 - 0.5 * g);
        // the gap as computed in floating point must not exceed g (rounding of the two
        // ends could otherwise push it over by a few ulps)
        while (eta_hi - eta_lo) / eta_hi > g {
            eta_lo = eta_lo.next_up();
        }
        if let Some(x) = safe_state(arch, mu, (eta_s, x_s, &pattern_s), eta_hi, settings) {
            let mut c = cert.clone();
            c.safe = Some(SafeSide { eta: eta_hi, x });
            let safe_ok = {
                let mut probe = c.clone();
                probe.claim = Claim::LeastThickness;
                // check the safe side alone with a trivially failing lower side removed
                prove_safe_only(&probe).is_ok()
            };
            if safe_ok {
                let found = find_contact_farkas(arch, &pool, eta_lo, mu, 3, |f| {
                    let mut full = c.clone();
                    full.collapse = Some(f.clone());
                    full.gap = Some(eta_hi - eta_lo);
                    full.gap_relative = Some((eta_hi - eta_lo) / eta_hi);
                    verify(&full).is_ok()
                });
                if let Some(f) = found {
                    c.collapse = Some(f);
                    c.gap = Some(eta_hi - eta_lo);
                    c.gap_relative = Some((eta_hi - eta_lo) / eta_hi);
                    return Ok(c);
                }
            }
        }
        g *= 10.0;
    }
    Err(NotCertified(format!(
        "no certificate could be proved at a relative gap up to 1e-4 (eta_s = {eta_s})"
    )))
}

/// The limit state moved into the interior of the admissible set at η_hi: a small LP in
/// the displacement δ on the active contacts, rows scaled by 1/(η_hi − η*).
fn safe_state(
    arch: &Arch,
    mu: f64,
    (eta_s, x_s, pattern): (f64, Reactions, &[Contact]),
    eta_hi: f64,
    settings: &Settings,
) -> Option<Reactions> {
    let rows: Vec<Affine> = pattern
        .iter()
        .map(|c| actions(arch, eta_hi, c.beta).activation(c.kind, 0, eta_hi, mu))
        .collect();
    move_inside(&rows, x_s, 1.0 / (eta_hi - eta_s), settings)
}

/// A state near `x_s` strictly inside the `rows` (affine in x, at the target parameter):
/// the margin LP in the displacement δ with every row's value at x_s scaled by `k`
/// (1 over the parameter step, so that the LP works with O(1) numbers).
pub(super) fn move_inside(
    rows: &[Affine],
    x_s: Reactions,
    k: f64,
    settings: &Settings,
) -> Option<Reactions> {
    let rows: Vec<Affine> = rows
        .iter()
        .map(|a| Affine {
            g: a.g,
            c: k * a.at(&x_s),
        })
        .collect();
    let (d, s) = lp::max_margin(&rows, 1.0, settings).ok()?;
    if s.is_nan() || s <= 0.0 {
        return None;
    }
    Some([x_s[0] + d[0] / k, x_s[1] + d[1] / k, x_s[2] + d[2] / k])
}
