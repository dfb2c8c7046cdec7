//! Re-checking a load certificate (issue 11): the claims about the largest admissible
//! multiplier λ_static of a live load at fixed (η, μ), with the live actions of
//! [`super::live`] (docs/loads.md, written out again) and the same interval arithmetic
//! as the thickness certificates.
//!
//! * `largest_multiplier`: the state (x_lo, λ_lo) is *proved* admissible — at every joint
//!   of a discrete arch, or over the whole continuum by Taylor enclosures, on both sides of
//!   a loaded section — and the Farkas certificate at λ_hi is *proved* (four contacts, the
//!   signed cofactors of their x-gradients; the live terms enter the constants). The
//!   admissible (x, λ) form a convex set: a state at some λ ≥ λ_hi would put one at λ_hi on
//!   the segment from (x_lo, λ_lo). So λ_lo ≤ λ_static < λ_hi.
//! * `unbounded_multiplier`: (x_0, λ_0) is *proved* admissible and the stated transfer is
//!   *proved* to keep it admissible as λ grows: along (x_0 + t d, λ_0 + t) every activation
//!   function is φ(x_0, λ_0) + t ψ, with ψ ≤ 0 proved at every section (ψ = 0 identically
//!   where the transfer cancels the load, by an identity of the statics).
//! * `no_equilibrium` under a load: five rows in (h, v, w, λ) (with, possibly, −λ ≤ 0),
//!   the cofactors of their 4-gradients: no state at any λ ≥ 0.

use super::format::{CertJoint, Certificate, Claim, ContactKind, LoadFarkas, LoadState, Transfer};
use super::interval::Interval as I;
use super::live::Live;
use super::verify::{check_farkas_joint, prove_cofactors, reject, Rejection, Report};
use super::verify_search::{sections, side_text};
use super::verify_statics::{affine, kinds, phi, prove_pieces, Model, Ntm, Piece};

/// Verifies a certificate with a `load` section (`cert.load` must be present).
pub(super) fn verify_load(cert: &Certificate, model: &Model) -> Result<Report, Rejection> {
    let Some(spec) = &cert.load else {
        return reject(format!(
            "a {} claim needs a load section",
            cert.claim.name()
        ));
    };
    if matches!(cert.claim, Claim::LeastThickness) {
        return reject("a least_thickness claim carries no load section");
    }
    if cert.safe.is_some()
        || cert.collapse.is_some()
        || cert.limit_state.is_some()
        || cert.search.is_some()
    {
        return reject("a load certificate carries none of the thickness sections (safe, collapse, limit_state, search)");
    }
    let live = Live::of(spec, model)?;
    let Some(sides) = &cert.multiplier else {
        return reject("a load certificate needs a multiplier section");
    };
    let mu = cert.mu;
    let mut checks = Vec::new();
    let lambda_bracket = match cert.claim {
        Claim::LargestMultiplier => {
            let (Some(adm), Some(inf), None, None) = (
                &sides.admissible,
                &sides.infeasible,
                sides.transfer,
                &sides.recession,
            ) else {
                return reject("largest_multiplier: needs multiplier.admissible and multiplier.infeasible (and no transfer or recession)");
            };
            let Some(lambda_hi) = inf.lambda else {
                return reject(
                    "largest_multiplier: multiplier.infeasible.lambda (lambda_hi) is missing",
                );
            };
            check_state(adm, "multiplier.admissible")?;
            if !(lambda_hi.is_finite() && adm.lambda <= lambda_hi) {
                return reject(format!(
                    "need 0 <= lambda_lo <= lambda_hi, found lambda_lo = {}, lambda_hi = {lambda_hi}",
                    adm.lambda
                ));
            }
            let pieces = prove_state(model, &live, adm, mu, "admissible side")?;
            checks.push(format!(
                "proved (interval arithmetic): the state x = [{}, {}, {}] is admissible at lambda_lo = {} {} ({pieces} enclosures)",
                adm.x[0], adm.x[1], adm.x[2], adm.lambda, everywhere(model, &live)
            ));
            let margin = prove_farkas_at(model, &live, inf, lambda_hi, mu)?;
            checks.push(format!(
                "proved (interval arithmetic): no state is admissible at lambda_hi = {lambda_hi} (Farkas on {} joints{}, margin {margin:.3e}); the admissible (x, lambda) are convex, so none at any lambda >= lambda_hi",
                inf.joints.len(),
                if inf.joints.len() == 3 { ", sliding rows in (h, v): w does not enter them" } else { "" }
            ));
            check_gap(cert, adm.lambda, lambda_hi)?;
            Some((adm.lambda, Some(lambda_hi)))
        }
        Claim::UnboundedMultiplier => {
            let (Some(adm), None) = (&sides.admissible, &sides.infeasible) else {
                return reject("unbounded_multiplier: needs multiplier.admissible and a transfer or a recession direction (and no infeasible side)");
            };
            check_state(adm, "multiplier.admissible")?;
            if cert.gap.is_some() || cert.gap_relative.is_some() {
                return reject("unbounded_multiplier: a gap is stated, but there is no bracket");
            }
            let pieces = prove_state(model, &live, adm, mu, "admissible side")?;
            checks.push(format!(
                "proved (interval arithmetic): the state x = [{}, {}, {}] is admissible at lambda = {} {} ({pieces} enclosures)",
                adm.x[0], adm.x[1], adm.x[2], adm.lambda, everywhere(model, &live)
            ));
            checks.push(match (sides.transfer, &sides.recession) {
                (Some(transfer), None) => prove_transfer(model, &live, transfer, mu)?,
                (None, Some(d)) => prove_recession(model, &live, d, mu)?,
                _ => return reject("unbounded_multiplier: needs exactly one of multiplier.transfer and multiplier.recession"),
            });
            Some((adm.lambda, None))
        }
        Claim::NoEquilibrium => {
            let (None, Some(inf), None, None) = (
                &sides.admissible,
                &sides.infeasible,
                sides.transfer,
                &sides.recession,
            ) else {
                return reject("no_equilibrium under a load: needs multiplier.infeasible only");
            };
            if inf.lambda.is_some() {
                return reject("no_equilibrium under a load: multiplier.infeasible.lambda must be null (the certificate covers every lambda >= 0)");
            }
            if cert.gap.is_some() || cert.gap_relative.is_some() {
                return reject("no_equilibrium: a gap is stated, but there is no bracket");
            }
            let margin = prove_farkas_any(model, &live, inf, mu)?;
            checks.push(format!(
                "proved (interval arithmetic): no state (h, v, w, lambda) with lambda >= 0 is admissible (Farkas on {} joints{}, margin {margin:.3e})",
                inf.joints.len(),
                if inf.lambda_row.is_some() { " and the row -lambda <= 0" } else { "" }
            ));
            None
        }
        Claim::LeastThickness => unreachable!("checked above"),
    };
    let limit_states = match &cert.load_search {
        Some(search) => {
            let Some((lo, hi)) = lambda_bracket else {
                return reject("load_search: the limit states need a multiplier claim with an admissible state");
            };
            let (lines, verdict) =
                super::verify_load_search::verify_load_search(model, &live, mu, search, lo, hi)?;
            checks.extend(lines);
            Some(verdict)
        }
        None => None,
    };
    Ok(Report {
        claim: cert.claim,
        mu,
        bracket: None,
        arch: cert.arch.clone(),
        checks,
        limit_states,
        load: Some(live.text()),
        lambda_bracket,
    })
}

fn everywhere(model: &Model, live: &Live) -> &'static str {
    match (&model.joints, live.split()) {
        (Some(j), Some(bp)) if j.contains(&bp) => {
            "at every joint (both sides of the loaded section)"
        }
        (Some(_), _) => "at every joint",
        (None, Some(_)) => "over the whole arch (both sides of the loaded section)",
        (None, None) => "over the whole arch",
    }
}

fn check_state(s: &LoadState, what: &str) -> Result<(), Rejection> {
    if !(s.lambda.is_finite() && s.lambda >= 0.0 && s.x.iter().all(|v| v.is_finite())) {
        return reject(format!(
            "{what}: lambda must be finite and >= 0 and x finite, found lambda = {}",
            s.lambda
        ));
    }
    Ok(())
}

/// The stated gaps must be λ_hi − λ_lo and (λ_hi − λ_lo)/λ_hi.
fn check_gap(cert: &Certificate, lo: f64, hi: f64) -> Result<(), Rejection> {
    let gap = hi - lo;
    if let Some(g) = cert.gap {
        if !g.is_finite() || (g - gap).abs() > 1e-15 * hi.abs() + 1e-300 {
            return reject(format!(
                "stated gap {g} differs from lambda_hi - lambda_lo = {gap}"
            ));
        }
    }
    if let Some(g) = cert.gap_relative {
        let r = gap / hi;
        if !g.is_finite() || (g - r).abs() > 1e-15 + 1e-9 * r.abs() {
            return reject(format!(
                "stated gap_relative {g} differs from (lambda_hi - lambda_lo)/lambda_hi = {r}"
            ));
        }
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
fn prove_with_live(
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

/// The live part per unit λ of the activation function `kind` at the joint β on `side`
/// (zero where the section does not carry the load).
fn live_row(model: &Model, live: &Live, j: &CertJoint, mu: Option<f64>) -> I {
    match live.ntm(model, I::point(j.beta), live.carries(j.beta, j.side)) {
        Some(l) => phi(j.kind, 0, &l, live.eta, mu),
        None => I::point(0.0),
    }
}

fn labels(joints: &[CertJoint]) -> Vec<(f64, String)> {
    joints
        .iter()
        .map(|j| (j.y, format!("beta = {}{}", j.beta, side_text(j.side))))
        .collect()
}

/// The Farkas proof for rows over the unknowns (h, v, w) — and λ when `with_lambda` — after
/// leaving out the coordinates that do not enter them: w when every joint slides (T and N
/// do not involve w); λ, when the row −λ ≤ 0 is not used, if no joint's section carries
/// the point load (their λ-coefficients are zero) or if every one does (a point load enters
/// the sections that carry it only through x − λ d, d = (0, 1, (1 + η/2) cos β_P − cos β_R):
/// the live actions there are minus the weightless actions of d — an identity of the
/// statics — so a certificate in x covers every (x, λ)). The certificate must have one row
/// more than the coordinates kept; `rows` are (gradient, constant) with the full gradient.
fn prove_reduced(
    model: &Model,
    live: &Live,
    f: &LoadFarkas,
    mu: Option<f64>,
    rows: Vec<(Vec<I>, I)>,
    with_lambda: bool,
) -> Result<f64, Rejection> {
    for (i, j) in f.joints.iter().enumerate() {
        check_farkas_joint(model, i, j, mu, live.split())?;
    }
    let mut dropped = Vec::new();
    if f.joints.iter().all(|j| !j.kind.is_hinge()) {
        dropped.push(2); // w
    }
    let carried: Vec<bool> = f
        .joints
        .iter()
        .map(|j| live.carries(j.beta, j.side))
        .collect();
    let point = live.split().is_some();
    if with_lambda
        && f.lambda_row.is_none()
        && (carried.iter().all(|c| !c) || (point && carried.iter().all(|&c| c)))
    {
        dropped.push(3); // λ
    }
    let unknowns = if with_lambda { 4 } else { 3 } - dropped.len();
    if rows.len() != unknowns + 1 {
        return reject(format!(
            "collapse side: a Farkas certificate here needs exactly {} rows ({} unknowns{}), found {}",
            unknowns + 1,
            unknowns,
            if dropped.is_empty() {
                String::new()
            } else {
                format!(
                    " once {} left out: they do not enter these rows",
                    dropped
                        .iter()
                        .map(|&k| if k == 2 { "w" } else { "lambda" })
                        .collect::<Vec<_>>()
                        .join(" and ")
                )
            },
            rows.len()
        ));
    }
    let rows: Vec<(Vec<I>, I)> = rows
        .into_iter()
        .map(|(g, c)| {
            let g = g
                .into_iter()
                .enumerate()
                .filter(|(k, _)| !dropped.contains(k))
                .map(|(_, v)| v)
                .collect();
            (g, c)
        })
        .collect();
    let mut stored = labels(&f.joints);
    if let Some(y) = f.lambda_row {
        stored.push((y, "the row -lambda <= 0".to_string()));
    }
    prove_cofactors(&rows, &stored)
}

/// The Farkas certificate at λ_hi: four rows in x = (h, v, w) (three sliding rows in
/// (h, v)), constants with the live terms at λ_hi.
fn prove_farkas_at(
    model: &Model,
    live: &Live,
    f: &LoadFarkas,
    lambda: f64,
    mu: Option<f64>,
) -> Result<f64, Rejection> {
    if f.lambda_row.is_some() {
        return reject(
            "collapse side: the row -lambda <= 0 belongs to a no_equilibrium certificate only",
        );
    }
    let rows: Vec<(Vec<I>, I)> = f
        .joints
        .iter()
        .map(|j| {
            let (g, c) = affine(model, j.kind, j.beta, live.eta, mu.unwrap_or(0.0));
            (
                g.to_vec(),
                c + I::point(lambda) * live_row(model, live, j, mu),
            )
        })
        .collect();
    prove_reduced(model, live, f, mu, rows, false)
}

/// The Farkas certificate over every λ ≥ 0: five rows in (h, v, w, λ) — the joints', and
/// −λ ≤ 0 when `lambda_row` is given — or fewer where w or λ does not enter them.
fn prove_farkas_any(
    model: &Model,
    live: &Live,
    f: &LoadFarkas,
    mu: Option<f64>,
) -> Result<f64, Rejection> {
    let mut rows: Vec<(Vec<I>, I)> = f
        .joints
        .iter()
        .map(|j| {
            let (g, c) = affine(model, j.kind, j.beta, live.eta, mu.unwrap_or(0.0));
            (vec![g[0], g[1], g[2], live_row(model, live, j, mu)], c)
        })
        .collect();
    if let Some(y) = f.lambda_row {
        if !y.is_finite() {
            return reject("collapse side: the multiplier of -lambda <= 0 is not a finite number");
        }
        let z = I::point(0.0);
        rows.push((vec![z, z, z, I::point(-1.0)], z));
    }
    prove_reduced(model, live, f, mu, rows, true)
}

/// Proves that a transfer keeps every section admissible as λ grows (see [`Transfer`]):
/// the sections whose actions change along the ray (those that do not carry the load for
/// `right`, those that do for `left`) change by ∓ the live unit actions u = (−cos β,
/// sin β, cos β − (1 + η/2) cos β_P), and φ of that change must be ≤ 0. Its extrados
/// hinge row is (1 + η/2)(cos β_P − cos β) for `right` and the opposite for `left`: zero at
/// β_P itself (the force passes through the extrados point of its own section), and on a
/// continuous piece between β_P and a springing ≤ 0 exactly when sin((β + β_P)/2) ≥ 0 there
/// (cos β − cos β_P = 2 sin((β + β_P)/2) sin((β_P − β)/2), the second factor of known sign
/// on the arch's span ≤ 2π), proved on the enclosure of (β + β_P)/2 over the piece. Every
/// other row is proved in intervals: joint by joint, or over the piece by Taylor
/// enclosures.
fn prove_transfer(
    model: &Model,
    live: &Live,
    transfer: Transfer,
    mu: Option<f64>,
) -> Result<String, Rejection> {
    let Some(bp) = live.split() else {
        return reject(
            "multiplier.transfer: a transfer carries a point load, not a horizontal one",
        );
    };
    let name = transfer_name(transfer);
    // right: the sections that do not carry the load change by −u; left: those that do, by u
    let (sign, carrying) = match transfer {
        Transfer::Right => (-1.0, false),
        Transfer::Left => (1.0, true),
    };
    let others: Vec<ContactKind> = kinds(mu)
        .iter()
        .copied()
        .filter(|&k| k != ContactKind::HingeExtrados)
        .collect();
    let unit = |b: I| -> Ntm {
        let u = live
            .ntm(model, b, true)
            .expect("a point load's unit actions");
        Ntm::default().plus(sign, &u)
    };
    let (mut proved, mut zero) = (0usize, 0usize);
    let changing = match &model.joints {
        Some(joints) => {
            let sections: Vec<(f64, Option<super::format::Side>)> = joints
                .iter()
                .flat_map(|&b| sections(b, Some(bp)).into_iter().map(move |s| (b, s)))
                .filter(|&(b, s)| live.carries(b, s) == carrying)
                .collect();
            for &(b, side) in &sections {
                let u = unit(I::point(b));
                for &kind in kinds(mu) {
                    let v = phi(kind, 0, &u, live.eta, mu);
                    if b == bp && kind == ContactKind::HingeExtrados {
                        zero += 1; // identically zero: through the extrados point of β_P
                        continue;
                    }
                    if v.hi.is_nan() || v.hi > 0.0 {
                        return reject(format!(
                            "multiplier.transfer {name}: {} at beta = {b}{} grows along the ray (upper bound {:e}): not proved",
                            kind.name(),
                            side_text(side),
                            v.hi
                        ));
                    }
                    proved += 1;
                }
            }
            format!("{} section(s)", sections.len())
        }
        None => {
            let (a, b) = match transfer {
                Transfer::Right => (model.beta_r, bp),
                Transfer::Left => (bp, model.beta_l),
            };
            // the extrados hinge row: the sign of sin((β + β_P)/2) over the piece
            let half = (I::point(a) + I::point(bp)) * I::point(0.5);
            let other = (I::point(b) + I::point(bp)) * I::point(0.5);
            let arg = I::new(half.lo.min(other.lo), half.hi.max(other.hi));
            if a < b {
                let s = arg.sin();
                if s.lo.is_nan() || s.lo < 0.0 {
                    return reject(format!(
                        "multiplier.transfer {name}: hinge_extrados over [{a}, {b}] is not proved <= 0 (sin((beta + beta_P)/2) >= {:e})",
                        s.lo
                    ));
                }
            }
            zero += 1;
            let piece = Piece { a, b, eval: &unit };
            proved += prove_pieces(
                model,
                &[piece],
                live.eta,
                mu,
                &others,
                false,
                &format!("multiplier.transfer {name}"),
            )?;
            format!("the sections over [{a}, {b}]")
        }
    };
    Ok(format!(
        "proved (interval arithmetic): transferring the load to the {name} springing (reactions changed by {} per unit lambda) keeps every activation function <= 0 as lambda grows: {changing} change ({proved} rows or enclosures proved non-increasing; the extrados hinge row {}); the others are unchanged (an identity of the statics)",
        match transfer {
            Transfer::Right => "(0, 1, (1 + eta/2) cos beta_P - cos beta_R)",
            Transfer::Left => "nothing",
        },
        if model.joints.is_some() {
            format!("of the loaded section identically zero ({zero})")
        } else {
            "by the sign of sin((beta + beta_P)/2)".to_string()
        }
    ))
}

/// Proves that a direction (d_x, d_λ), d_λ > 0, is a recession direction of the admissible
/// set: the linear part of every activation function along it — the weightless actions of
/// d_x plus d_λ times the live ones — is ≤ 0 at every section (every joint, or over each
/// piece of a continuous arch by Taylor enclosures), so that (x + t d_x, λ + t d_λ) stays
/// admissible for every t ≥ 0.
fn prove_recession(
    model: &Model,
    live: &Live,
    d: &LoadState,
    mu: Option<f64>,
) -> Result<String, Rejection> {
    if !(d.lambda.is_finite() && d.lambda > 0.0 && d.x.iter().all(|v| v.is_finite())) {
        return reject(format!(
            "multiplier.recession: needs a finite direction with lambda > 0, found lambda = {}",
            d.lambda
        ));
    }
    let (dx, dl) = (d.x, d.lambda);
    let weightless = move |b: I| model.ntm_weightless(b, dx);
    let count = prove_with_live(model, live, &weightless, dl, mu, "multiplier.recession")?;
    Ok(format!(
        "proved (interval arithmetic): along the direction (d_x, d_lambda) = ([{}, {}, {}], {dl}) no activation function grows {} ({count} enclosures), so the admissible state stays admissible at every larger lambda",
        dx[0], dx[1], dx[2], everywhere(model, live)
    ))
}

fn transfer_name(t: Transfer) -> &'static str {
    match t {
        Transfer::Right => "right",
        Transfer::Left => "left",
    }
}

/// Proves only the admissible side of a load certificate, `multiplier.admissible` (used
/// by `certify` while it searches for the other side).
pub(super) fn prove_admissible_side(cert: &Certificate) -> Result<usize, Rejection> {
    let model = super::verify::model_of(cert)?;
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
