//! A thickness certificate: the bracket around η_s built from the exact limit state (see the
//! module documentation of [`crate::certificate`]), or, below μ_ms, a friction-only Farkas
//! certificate that no thickness stands; above it, Farkas certificates at η = 2 or over
//! cells of η; and the centred line of thrust of an arch that stands at every thickness.

use super::blank::empty;
use super::loaded::{cert_joints, Loaded};
use super::search::{evidence, limit_state_cert, FOUND};
use super::sides::{chord_pool, find_farkas, move_inside, widening, Row};
use crate::admissibility::{margin_over_arch, Goal, WorkingSet};
use crate::arch::{Arch, WeightModel};
use crate::certificate::format::{
    Certificate, Claim, Farkas, FarkasCell, NotCertified, SafeSide, Side,
};
use crate::certificate::verify::{prove_admissible_side, prove_farkas_cell, verify};
use crate::contact::{Contact, ContactKind, Location};
use crate::friction::{friction_limit, SLIDES};
use crate::limit::LeastLimitState;
use crate::limit_states::ridge::TracedEdge;
use crate::limit_states::{LimitStates, Survey};
use crate::search::candidates_at;
use crate::settings::Settings;
use crate::state::State;
use crate::statics::{actions, Affine, Reactions};

/// The thickness problem's Farkas search over contacts at (η, μ).
pub(super) fn find_contact_farkas(
    arch: &Arch,
    pool: &[Loaded],
    eta: f64,
    mu: f64,
    d: usize,
    check: impl Fn(&Farkas) -> bool,
) -> Option<Farkas> {
    let rows: Vec<(Loaded, Row)> = pool
        .iter()
        .map(|&(c, side)| {
            let row = actions(arch, eta, c.beta).activation(c.kind, 0, eta, mu);
            ((c, side), Row::from(row))
        })
        .collect();
    let make = |labelled: &[(Loaded, f64)]| Farkas {
        eta: (d == 3).then_some(eta),
        joints: cert_joints(None, labelled),
    };
    find_farkas(&rows, d, |l| check(&make(l))).map(|l| make(&l))
}

pub(super) fn certify_no_equilibrium(
    arch: &Arch,
    mu: f64,
    settings: &Settings,
) -> Result<Certificate, NotCertified> {
    let fl = friction_limit(arch, settings)
        .map_err(|e| NotCertified(e.to_string()))?
        .ok_or_else(|| NotCertified("no finite friction admits equilibrium".into()))?;
    let mut cert = empty(arch, mu, Claim::NoEquilibrium);
    // the friction limit's sliding contacts; failing them, with sliding rows spread over
    // the arch too (where the limit is the weightless chord line, its two springings alone
    // prove nothing)
    let proved = |f: &Farkas| {
        let mut c = cert.clone();
        c.collapse = Some(f.clone());
        verify(&c).is_ok()
    };
    let pool: Vec<Loaded> = fl.pattern.iter().map(|&c| (c, Side::After)).collect();
    let f = find_contact_farkas(arch, &pool, 1.0, mu, 2, proved)
        .or_else(|| {
            let mut wider = pool.clone();
            wider.extend(
                spread_slides(arch, SPREAD)
                    .into_iter()
                    .map(|c| (c, Side::After)),
            );
            find_contact_farkas(arch, &wider, 1.0, mu, 2, proved)
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

/// Sliding rows spread over the arch for a friction-only Farkas search: both kinds at
/// every joint of a discrete arch of at most this many (else at as many spread joints), or at
/// as many equally spaced angles of a continuous one.
const SPREAD: usize = 48;

/// As many spread angles for the Farkas cells over η, each tried with the whole pool (a
/// pool of n rows costs C(n, 4) float certificates).
pub(super) const CELL_SPREAD: usize = 12;

pub(super) fn spread_slides(arch: &Arch, spread: usize) -> Vec<Contact> {
    let all = arch.angles(spread);
    let angles: Vec<f64> = all
        .iter()
        .step_by(all.len().div_ceil(spread).max(1))
        .copied()
        .collect();
    let ends = (arch.beta_right(), arch.beta_left());
    angles
        .into_iter()
        .flat_map(|beta| {
            let at = if beta == ends.0 || beta == ends.1 {
                Location::Springing
            } else {
                Location::Interior
            };
            SLIDES.map(|kind| Contact {
                beta,
                kind,
                at,
                free: false,
            })
        })
        .collect()
}

/// The thickness limit t = 2r, where a no-equilibrium certificate proves that no state
/// is admissible.
const ETA_LIMIT: f64 = 2.0;

/// No thickness stands at μ although μ is not below μ_ms (or no μ_ms exists). With the
/// weight along the centreline, a Farkas certificate that no state is admissible at the
/// thickness limit η = 2: the admissible set only grows with η (the verifier says why), so
/// that proves it for every η < 2. With the true-centroid weight the weight itself moves
/// with η: Farkas cells that cover [0, 2], each proved over its whole interval of η.
pub(super) fn certify_no_equilibrium_at_top(
    arch: &Arch,
    mu: f64,
    settings: &Settings,
) -> Result<Certificate, NotCertified> {
    let cert = empty(arch, mu, Claim::NoEquilibrium);
    if arch.weight() != WeightModel::Centreline {
        let mut cells = Vec::new();
        cover(&cert, (arch, mu), (0.0, ETA_LIMIT), 0, &mut cells, settings)?;
        return Ok(Certificate {
            collapse_cells: Some(cells),
            ..cert
        });
    }
    let pool = pool_at(arch, ETA_LIMIT, mu, settings)?;
    let f = find_contact_farkas(arch, &pool, ETA_LIMIT, mu, 3, |f| {
        let mut c = cert.clone();
        c.collapse = Some(f.clone());
        verify(&c).is_ok()
    })
    .ok_or_else(|| {
        NotCertified(format!(
            "no provable Farkas certificate that no state stands at eta = 2 (mu = {mu})"
        ))
    })?;
    Ok(Certificate {
        collapse: Some(f),
        ..cert
    })
}

/// A Farkas cell is halved at most this many times below [0, 2] before `certify` gives up.
const CELL_DEPTH: usize = 10;

/// Covers the thicknesses `[lo, hi]` with Farkas cells, left to right: a certificate at the
/// middle proved over the whole cell, else the two halves.
fn cover(
    cert: &Certificate,
    (arch, mu): (&Arch, f64),
    (lo, hi): (f64, f64),
    depth: usize,
    cells: &mut Vec<FarkasCell>,
    settings: &Settings,
) -> Result<(), NotCertified> {
    let mid = 0.5 * (lo + hi);
    let cell = |f: &Farkas| FarkasCell {
        eta_lo: lo,
        eta_hi: hi,
        joints: f.joints.clone(),
    };
    let pool = pool_at(arch, mid, mu, settings)?;
    let proved = |f: &Farkas| prove_farkas_cell(cert, &cell(f)).is_ok();
    // failing the pool, with sliding rows spread over the arch too (near μ_ms the
    // friction rows alone are nearly infeasible, and the LP's local maxima miss them)
    let found = find_contact_farkas(arch, &pool, mid, mu, 3, proved).or_else(|| {
        let mut wider = pool.clone();
        wider.extend(
            spread_slides(arch, CELL_SPREAD)
                .into_iter()
                .map(|c| (c, Side::After)),
        );
        find_contact_farkas(arch, &wider, mid, mu, 3, proved)
    });
    if let Some(f) = found {
        cells.push(cell(&f));
        return Ok(());
    }
    if depth == CELL_DEPTH {
        return Err(NotCertified(format!(
            "no Farkas certificate could be proved over eta in [{lo}, {hi}] (mu = {mu})"
        )));
    }
    cover(cert, (arch, mu), (lo, mid), depth + 1, cells, settings)?;
    cover(cert, (arch, mu), (mid, hi), depth + 1, cells, settings)
}

/// The contacts for a Farkas certificate that no state stands at `eta`: the local maxima
/// at the margin LP's best state there, every row at both springings (a Farkas row need not
/// be a local maximum of its function at the LP's state), and their chords.
pub(super) fn pool_at(
    arch: &Arch,
    eta: f64,
    mu: f64,
    settings: &Settings,
) -> Result<Vec<Loaded>, NotCertified> {
    let modes = ContactKind::active_at(mu);
    let mut ws = WorkingSet::initial(arch);
    let m = margin_over_arch(arch, eta, mu, modes, &mut ws, Goal::Optimise, settings)
        .map_err(|e| NotCertified(format!("the margin LP at eta = {eta} failed: {e:?}")))?;
    let best = State {
        arch,
        eta,
        mu,
        x: m.x,
    };
    let mut contacts = candidates_at(&best, None, modes, settings);
    for beta in [arch.beta_right(), arch.beta_left()] {
        for &kind in modes {
            if !contacts.iter().any(|c| c.kind == kind && c.beta == beta) {
                contacts.push(Contact {
                    beta,
                    kind,
                    at: Location::Springing,
                    free: false,
                });
            }
        }
    }
    let active: Vec<Loaded> = contacts.into_iter().map(|c| (c, Side::After)).collect();
    Ok(chord_pool(arch, &active))
}

/// An arch that stands at every thickness η > 0: the centred line of thrust, proved by the
/// verifier (a discrete arch of three joints; otherwise, or where it is not proved, no
/// certificate, with `reason`, the solver's answer, and why not).
pub(super) fn certify_stands(
    arch: &Arch,
    mu: f64,
    reason: &str,
) -> Result<Certificate, NotCertified> {
    let cert = empty(arch, mu, Claim::StandsAtEveryThickness);
    match verify(&cert) {
        Ok(_) => Ok(cert),
        Err(r) => Err(NotCertified(format!("{reason}; not certified: {}", r.0))),
    }
}

/// The least-thickness certificate around the least admissible state (η_s, x_s): with the
/// solve's limit state there where it carries the mechanism, else (a non-associative gap)
/// the search's least limit state above it; the ridge's trace, where `certify` made one, is
/// the search's evidence.
pub(super) fn certify_limit(
    (arch, mu): (&Arch, f64),
    (survey, traced): (&Survey, Option<&[TracedEdge]>),
    (eta_s, x_s, at_eta_s): (f64, Reactions, Option<&LeastLimitState>),
    gap: f64,
    settings: &Settings,
) -> Result<Certificate, NotCertified> {
    let mut cert = empty(arch, mu, Claim::LeastThickness);
    // the bracket is around η_s, the least admissible state, which need not carry a
    // mechanism (non-associative gap): its pattern is its active set
    let pattern_s: Vec<Contact> = match at_eta_s {
        Some(ls) => ls.pattern.clone(),
        None => {
            State {
                arch,
                eta: eta_s,
                mu,
                x: x_s,
            }
            .verdict(ContactKind::active_at(mu), settings)
            .active
        }
    };
    // the limit state: the one at η_s, else the least above it (only when the search is
    // complete: otherwise the widened state is not known to be the least)
    cert.limit_state = match (at_eta_s, &survey.states) {
        (Some(ls), _) => Some(limit_state_cert(ls.eta, ls.x, &ls.mechanism)),
        (None, Ok(found)) if arch.fill().is_none() => found
            .above
            .first()
            .map(|s| limit_state_cert(s.t, s.x, &s.mechanism)),
        (None, _) => None,
    };
    // with fill no search section: its evidence rests on the ring's weight alone
    // a search not completed lists what it found where that decides `unique = false`
    // (η_s carries a limit state, and another lies above it)
    let unsettled = LimitStates {
        eta_s,
        attained: true,
        mechanism_at_eta_s: true,
        above: survey.found.clone(),
        events: 0,
        no_mechanism: Vec::new(),
        method: FOUND.into(),
        vertical: None,
    };
    let listed = match (&survey.states, survey.unique(), arch.fill()) {
        (Ok(found), Some(unique), None) => Some((found, unique)),
        (Err(_), Some(false), None) if at_eta_s.is_some() => Some((&unsettled, false)),
        _ => None,
    };
    if let Some((found, unique)) = listed {
        cert.search = Some(evidence(
            (arch, traced),
            found,
            (eta_s, x_s, &pattern_s),
            unique,
            settings,
        ));
    }
    let pattern: Vec<Loaded> = pattern_s.iter().map(|&c| (c, Side::After)).collect();
    let pool = chord_pool(arch, &pattern);
    bracket_around((arch, mu), eta_s, gap, &pool, |eta_hi| {
        let x = safe_state(arch, mu, (eta_s, x_s, &pattern_s), eta_hi, settings)?;
        let mut c = cert.clone();
        c.safe = Some(SafeSide { eta: eta_hi, x });
        prove_admissible_side(&c).ok()?;
        Some(c)
    })
    .ok_or_else(|| {
        NotCertified(format!(
            "no certificate could be proved at a relative gap up to 1e-4 (eta_s = {eta_s})"
        ))
    })
}

/// The widening loop of a least-thickness bracket around η_s: at each relative gap,
/// `safe_side(η_hi)` gives the certificate with its safe side proved, then a Farkas
/// certificate at η_lo from `pool` that the verifier proves completes it.
pub(super) fn bracket_around(
    (arch, mu): (&Arch, f64),
    eta_s: f64,
    gap: f64,
    pool: &[Loaded],
    safe_side: impl Fn(f64) -> Option<Certificate>,
) -> Option<Certificate> {
    let wide = |lo: f64, hi: f64, g: f64| (hi - lo) / hi > g;
    widening(eta_s, gap, wide, |eta_lo, eta_hi| {
        let mut c = safe_side(eta_hi)?;
        c.gap = Some(eta_hi - eta_lo);
        c.gap_relative = Some((eta_hi - eta_lo) / eta_hi);
        c.collapse = Some(find_contact_farkas(arch, pool, eta_lo, mu, 3, |f| {
            let mut full = c.clone();
            full.collapse = Some(f.clone());
            match arch.fill() {
                // the cells below η_lo come after the bracket: here the Farkas side alone
                Some(_) => prove_farkas_cell(&full, &point_cell(eta_lo, f)).is_ok(),
                None => verify(&full).is_ok(),
            }
        })?);
        Some(c)
    })
}

/// A Farkas certificate at one thickness as a cell of width zero.
fn point_cell(eta: f64, f: &Farkas) -> FarkasCell {
    FarkasCell {
        eta_lo: eta,
        eta_hi: eta,
        joints: f.joints.clone(),
    }
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
