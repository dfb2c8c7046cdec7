//! Re-checking a thickness certificate (`least_thickness`, `no_equilibrium` or
//! `stands_at_every_thickness`): the safe state proved admissible at η_hi over the whole
//! arch, the Farkas certificate proved at η_lo (or over cells of η), the limit state
//! checked, and the `search` section re-checked ([`super::search`]); the centred line of
//! thrust of a three-joint arch ([`super::centred`]).

use super::centred::prove_centred;
use super::enclosure::prove_state;
use super::farkas::prove_farkas;
use super::input::check_gap;
use super::joints::check_pattern;
use super::limit_state::check_limit_state;
use super::live::StateAt;
use super::report::{mu_text, reject, Rejection, Report};
use super::search::verify_search;
use super::statics::{Model, ETA_LIMIT, LIMIT_STATE_TOL};
use crate::certificate::format::{CertJoint, Certificate, Claim, FarkasCell};
use crate::certificate::interval::Interval as I;

/// Re-checks a certificate of the thickness problem (`least_thickness` or
/// `no_equilibrium`, no load section) on its checked arch `model`.
pub(super) fn verify_thickness(cert: &Certificate, model: &Model) -> Result<Report, Rejection> {
    let mut checks = Vec::new();
    let mut limit_states = None;
    if model.fill.is_some() {
        filled_sections(cert)?;
    }
    let least_with_fill = cert.claim == Claim::LeastThickness && model.fill.is_some();
    if cert.collapse_cells.is_some() && cert.claim != Claim::NoEquilibrium && !least_with_fill {
        return reject(format!(
            "collapse_cells belong to a no_equilibrium claim or to the least thickness of an \
             arch with fill, not to {}",
            cert.claim.name()
        ));
    }
    let bracket = match cert.claim {
        Claim::LargestMultiplier | Claim::UnboundedMultiplier => {
            unreachable!("load claims are verified by verify_load")
        }
        Claim::NoEquilibrium => {
            checks.push(no_equilibrium(cert, model)?);
            None
        }
        Claim::StandsAtEveryThickness => {
            checks.push(stands(cert, model)?);
            None
        }
        Claim::LeastThickness => {
            let (bracket, verdict) = least_thickness(cert, model, &mut checks)?;
            limit_states = verdict;
            Some(bracket)
        }
    };
    Ok(Report {
        claim: cert.claim,
        mu: cert.mu,
        bracket,
        arch: cert.arch.clone(),
        checks,
        limit_states,
        load: None,
        lambda_bracket: None,
    })
}

/// What a thickness certificate of an arch with fill may carry. The fill's load is 1/η
/// times the ring's weight, so the arguments that rest on the ring's weight alone do not
/// hold: that the admissible set grows with η (a Farkas certificate at η = 2, the
/// hinges-only search), that friction alone decides at one η, the ridge's rows linear in
/// η, and the centred line of thrust over [0, 2]. Its `least_thickness` proves "no state
/// below η_lo" by cells over [0, η_lo] instead, and lists no `search` (the limit states
/// above η_s are not certified with fill); its `no_equilibrium`, by cells over [0, 2].
fn filled_sections(cert: &Certificate) -> Result<(), Rejection> {
    let why = match cert.claim {
        Claim::StandsAtEveryThickness => Some("a stands_at_every_thickness claim"),
        Claim::NoEquilibrium if cert.collapse_cells.is_none() => {
            Some("a no_equilibrium claim without collapse_cells")
        }
        Claim::LeastThickness if cert.collapse_cells.is_none() => {
            Some("a least_thickness claim without collapse_cells")
        }
        Claim::LeastThickness if cert.search.is_some() => Some("a search section"),
        _ => None,
    };
    match why {
        Some(what) => reject(format!(
            "arch.fill: {what} is not verified with fill (the fill's load grows as 1/eta \
             against the ring's weight, so the admissible set need not grow with eta)"
        )),
        None => Ok(()),
    }
}

/// `no_equilibrium`: the friction-only Farkas certificate (`eta` null), or the Farkas
/// certificate at the thickness limit η = 2 (centreline weight); proved; returns the
/// report's line.
fn no_equilibrium(cert: &Certificate, model: &Model) -> Result<String, Rejection> {
    if cert.safe.is_some() || cert.limit_state.is_some() || cert.search.is_some() {
        return reject("a no_equilibrium claim cannot carry a safe state or a limit state");
    }
    match (&cert.collapse, &cert.collapse_cells) {
        (None, Some(cells)) => return no_equilibrium_over_cells(cert, model, cells),
        (Some(_), Some(_)) => {
            return reject("a no_equilibrium claim carries collapse or collapse_cells, not both")
        }
        _ => {}
    }
    let Some(f) = &cert.collapse else {
        return reject("no_equilibrium claim without a Farkas certificate");
    };
    if let Some(eta) = f.eta {
        return no_equilibrium_at_limit(cert, model, &f.joints, eta);
    }
    if cert.mu.is_none() {
        return reject("no_equilibrium claim at infinite friction (mu = null): the friction-only problem has no sliding rows there");
    }
    let margin = prove_farkas(model, &f.joints, I::point(1.0), cert.mu, true)?;
    Ok(format!(
        "proved (interval arithmetic): no (h, v) satisfies |T| <= mu N at the {} listed joints (Farkas, margin {margin:.3e}), so no thickness can stand at mu = {}",
        f.joints.len(),
        mu_text(cert.mu)
    ))
}

/// `no_equilibrium` by a Farkas certificate at η = 2: no state is admissible at the
/// thickness limit. With the weight along the centreline N, T and M do not involve η; a
/// state admissible at some η < 2 has N ≥ 0 (the sum of its two hinge rows is −ηN ≤ 0),
/// so its hinge rows ±M − ηN/2 only decrease as η grows to 2: it would be admissible
/// at η = 2. So no thickness stands.
fn no_equilibrium_at_limit(
    cert: &Certificate,
    model: &Model,
    joints: &[CertJoint],
    eta: f64,
) -> Result<String, Rejection> {
    if eta != ETA_LIMIT {
        return reject(format!(
            "collapse side: a no_equilibrium certificate with a thickness has eta = 2 (the thickness limit), found {eta}"
        ));
    }
    if model.centroid {
        return reject("a no_equilibrium certificate at eta = 2 needs the centreline weight (with the true-centroid weight the admissible set is not monotone in eta)");
    }
    let margin = prove_farkas(model, joints, I::point(eta), cert.mu, false)?;
    Ok(format!(
        "proved (interval arithmetic): no state is admissible at the thickness limit eta = 2 (Farkas on 4 joints, margin {margin:.3e}); with the weight along the centreline a state admissible at any eta < 2 (N >= 0 there) would be admissible at eta = 2, so no thickness stands at mu = {}",
        mu_text(cert.mu)
    ))
}

/// `no_equilibrium` by Farkas cells that cover the thicknesses [0, 2], each proved over its
/// whole η interval (the cofactors are enclosed with η an interval): no state is admissible
/// at any thickness, for either weight model.
fn no_equilibrium_over_cells(
    cert: &Certificate,
    model: &Model,
    cells: &[FarkasCell],
) -> Result<String, Rejection> {
    let least = prove_cover(model, cells, ETA_LIMIT, cert.mu)?;
    Ok(format!(
        "proved (interval arithmetic): no state is admissible at any thickness eta in [0, 2] ({} cell(s), each a Farkas certificate on 4 joints{} proved over its whole eta interval; least margin {least:.3e}), so no thickness stands at mu = {}",
        cells.len(),
        cells_with_fill(model),
        mu_text(cert.mu)
    ))
}

/// What the cells of an arch with fill are besides four joints.
fn cells_with_fill(model: &Model) -> &'static str {
    match model.fill {
        Some(_) => " (or 3 sliding joints: friction alone), the rows times eta so that the fill's load stays bounded,",
        None => "",
    }
}

/// Every cell proved over its whole η interval, the cells covering [0, `top`]; returns the
/// least margin.
fn prove_cover(
    model: &Model,
    cells: &[FarkasCell],
    top: f64,
    mu: Option<f64>,
) -> Result<f64, Rejection> {
    check_cover(cells, top)?;
    let mut least = f64::INFINITY;
    for (i, cell) in cells.iter().enumerate() {
        let margin = prove_cell(model, cell, mu).map_err(|r| {
            Rejection(format!(
                "collapse_cells[{i}] (eta in [{}, {}]): {}",
                cell.eta_lo, cell.eta_hi, r.0
            ))
        })?;
        least = least.min(margin);
    }
    Ok(least)
}

/// The cells must cover [0, `top`] in order, each ending exactly where the next begins.
fn check_cover(cells: &[FarkasCell], top: f64) -> Result<(), Rejection> {
    let (Some(first), Some(last)) = (cells.first(), cells.last()) else {
        return reject("collapse_cells is empty");
    };
    if first.eta_lo != 0.0 || last.eta_hi != top {
        return reject(format!(
            "collapse_cells must cover the thicknesses [0, {top}]; they cover [{}, {}]",
            first.eta_lo, last.eta_hi
        ));
    }
    if let Some(i) = cells.iter().position(|c| c.eta_lo >= c.eta_hi) {
        return reject(format!(
            "collapse_cells[{i}]: eta_lo = {} is not below eta_hi = {}",
            cells[i].eta_lo, cells[i].eta_hi
        ));
    }
    if let Some(i) = cells.windows(2).position(|w| w[0].eta_hi != w[1].eta_lo) {
        return reject(format!(
            "collapse_cells[{i}] ends at eta = {} but collapse_cells[{}] begins at {}",
            cells[i].eta_hi,
            i + 1,
            cells[i + 1].eta_lo
        ));
    }
    Ok(())
}

/// One Farkas cell proved over its whole η interval; returns its margin. Three sliding
/// joints are a certificate of friction alone (no (h, v) satisfies their |T| ≤ μN), four
/// joints one of the whole statics.
pub(super) fn prove_cell(
    model: &Model,
    cell: &FarkasCell,
    mu: Option<f64>,
) -> Result<f64, Rejection> {
    let eta = I::new(cell.eta_lo, cell.eta_hi);
    let friction_only = cell.joints.len() == 3 && cell.joints.iter().all(|j| !j.kind.is_hinge());
    prove_farkas(model, &cell.joints, eta, mu, friction_only)
}

/// `stands_at_every_thickness`: no other section; the centred line of thrust proved.
fn stands(cert: &Certificate, model: &Model) -> Result<String, Rejection> {
    if cert.safe.is_some()
        || cert.collapse.is_some()
        || cert.limit_state.is_some()
        || cert.search.is_some()
        || cert.gap.is_some()
    {
        return reject("a stands_at_every_thickness claim carries no other section (safe, collapse, limit_state, search, gap)");
    }
    let (cells, x) = prove_centred(model, cert.mu)?;
    Ok(format!(
        "proved (interval arithmetic): the line of thrust through the centre of each of the 3 joints (M = 0 there; x = [{}, {}, {}] at eta = 0) has N > 0{} at every joint for every eta in [0, 2] ({cells} cell(s)), so every hinge row -eta N/2 < 0: a state is admissible at every thickness eta > 0",
        x[0],
        x[1],
        x[2],
        if cert.mu.is_some() { " and |T| < mu N" } else { "" }
    ))
}

/// `least_thickness`: the safe state proved admissible at η_hi, the Farkas certificate
/// proved at η_lo, the stated gaps, the limit state checked and the `search` section
/// re-checked; pushes the report's lines and returns (η_lo, η_hi) and the verdict on the
/// limit states (with a `search` section).
fn least_thickness(
    cert: &Certificate,
    model: &Model,
    checks: &mut Vec<String>,
) -> Result<((f64, f64), Option<String>), Rejection> {
    let (Some(safe), Some(col)) = (&cert.safe, &cert.collapse) else {
        return reject("least_thickness claim needs both a safe state and a Farkas certificate");
    };
    let Some(eta_lo) = col.eta else {
        return reject("collapse side: missing eta");
    };
    if !(eta_lo > 0.0 && safe.eta < 2.0 && eta_lo <= safe.eta) {
        return reject(format!(
            "need 0 < eta_lo <= eta_hi < 2, found eta_lo = {eta_lo}, eta_hi = {}",
            safe.eta
        ));
    }
    if let Some(ls) = &cert.limit_state {
        check_pattern(model, &ls.pattern, cert.mu, &[], "limit state")?;
    }
    let pieces = prove_state(
        model,
        StateAt::bare(safe.x, safe.eta),
        cert.mu,
        false,
        "safe side",
    )?;
    checks.push(format!(
        "proved (interval arithmetic): the state x = [{}, {}, {}] is admissible at eta_hi = {} over the whole arch ({pieces} enclosures)",
        safe.x[0], safe.x[1], safe.x[2], safe.eta
    ));
    let margin = prove_farkas(model, &col.joints, I::point(eta_lo), cert.mu, false)?;
    checks.push(format!(
        "proved (interval arithmetic): no state is admissible at eta_lo = {eta_lo} (Farkas on {} joints, margin {margin:.3e})",
        col.joints.len()
    ));
    if let Some(cells) = &cert.collapse_cells {
        let least = prove_cover(model, cells, eta_lo, cert.mu)?;
        checks.push(format!(
            "proved (interval arithmetic): no state is admissible at any thickness eta in (0, eta_lo] ({} cell(s), each a Farkas certificate on 4 joints{} proved over its whole eta interval; least margin {least:.3e}): with fill the admissible set need not grow with eta, so every thinner ring is ruled out",
            cells.len(),
            cells_with_fill(model)
        ));
    }
    check_gap(cert, eta_lo, safe.eta, "eta")?;
    if let Some(ls) = &cert.limit_state {
        // the least limit state lies above η_s where η_s carries no mechanism
        let above = cert.search.as_ref().is_some_and(|s| !s.mechanism_at_eta);
        check_limit_state(
            model,
            cert.mu,
            ls,
            eta_lo,
            if above { 2.0 } else { safe.eta },
        )?;
        checks.push(format!(
            "checked (floating point, tolerance {LIMIT_STATE_TOL:e}; evidence, not proof): the limit state at eta = {} is consistent (pattern active, B lambda = 0, lambda >= 0, sum 1, L_e >= 0)",
            ls.eta
        ));
    }
    if cert.limit_state.is_none() {
        checks.push("not listed: a limit state (a state with a mechanism); the bracket is a claim of the statics alone (no state stands below eta_lo, one stands at eta_hi)".to_string());
    }
    let mut verdict = None;
    if let Some(search) = &cert.search {
        let (lines, v) = verify_search(model, cert, search, eta_lo, safe)?;
        checks.extend(lines);
        verdict = Some(v);
    }
    Ok(((eta_lo, safe.eta), verdict))
}
