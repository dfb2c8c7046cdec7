//! The least thickness of an arch with fill: below η_lo.
//!
//! With fill the admissible set need not grow with η (the fill's load is 1/η times the
//! ring's weight), so the Farkas certificate at η_lo of the bracket rules out η_lo alone.
//! The thicknesses (0, η_lo] are covered by Farkas cells, each proved over its whole
//! interval by the verifier (the rows times η, so that the fill's load stays bounded as
//! η → 0), built downwards from η_lo: a cell takes the joints of the one above it where
//! they prove, else the best proved 4-subset of the contacts at its middle (the interior
//! hinges also as chords); a cell that proves is followed by one twice as wide, one that
//! does not is halved. Near η_s the margin vanishes, so the cells start about as narrow as
//! the bracket and widen geometrically below it. The constants of the rows are enclosed
//! over a cell as they come, and the joints that prove change with the distance from η_s
//! (the chords of a tangency widen), so a cell proves to about a tenth of its distance from
//! η_s: on the order of 200 cells.

use super::blank::empty;
use super::loaded::Loaded;
use super::thickness::{find_contact_farkas, pool_at, spread_slides, CELL_SPREAD};
use crate::arch::Arch;
use crate::certificate::format::{CertJoint, Certificate, Claim, FarkasCell, NotCertified, Side};
use crate::certificate::verify::{prove_farkas_cell, verify};
use crate::settings::Settings;

/// A cell narrower than this relative to its top is not tried: `certify` gives up there.
const NARROWEST_REL: f64 = 1e-15;

/// At most this many cells are tried (proved or not) before `certify` gives up.
const MOST_TRIES: usize = 2000;

/// A cell after one that proved is this much wider ...
const GROW: f64 = 2.0;

/// ... and one after a cell that did not prove, this much narrower.
const SHRINK: f64 = 0.5;

/// The cells below η_lo of a bracketed least-thickness certificate `cert` of an arch with
/// fill, added to it, and the whole certificate verified.
pub(super) fn below_with_fill(
    mut cert: Certificate,
    (arch, mu): (&Arch, f64),
    settings: &Settings,
) -> Result<Certificate, NotCertified> {
    let (Some(col), Some(safe)) = (&cert.collapse, &cert.safe) else {
        return Err(NotCertified("the bracket has no Farkas side".into()));
    };
    let Some(eta_lo) = col.eta else {
        return Err(NotCertified("the bracket's Farkas side has no eta".into()));
    };
    let first_width = (safe.eta - eta_lo).max(eta_lo * 1e-12);
    let cells = cover_down(
        &cert,
        (arch, mu),
        eta_lo,
        &col.joints,
        first_width,
        settings,
    )?;
    cert.collapse_cells = Some(cells);
    verify(&cert).map_err(|r| NotCertified(format!("the certificate with its cells: {}", r.0)))?;
    Ok(cert)
}

/// No thickness of an arch with fill stands at `mu`: Farkas cells that cover [0, 2] (the
/// thickness limit), built downwards from 2 as below η_lo, and verified.
pub(super) fn no_equilibrium(
    arch: &Arch,
    mu: f64,
    settings: &Settings,
) -> Result<Certificate, NotCertified> {
    let mut cert = empty(arch, mu, Claim::NoEquilibrium);
    let cells = cover_down(&cert, (arch, mu), ETA_LIMIT, &[], ETA_LIMIT, settings)?;
    cert.collapse_cells = Some(cells);
    verify(&cert).map_err(|r| NotCertified(format!("the certificate with its cells: {}", r.0)))?;
    Ok(cert)
}

/// The thickness limit t = 2r, the top of a cover of every thickness.
const ETA_LIMIT: f64 = 2.0;

/// Cells covering [0, `top`], ascending, built downwards from `top` (see the module's
/// documentation), the first tried with `joints` over `width`.
fn cover_down(
    cert: &Certificate,
    (arch, mu): (&Arch, f64),
    top: f64,
    joints: &[CertJoint],
    width: f64,
    settings: &Settings,
) -> Result<Vec<FarkasCell>, NotCertified> {
    let mut cells: Vec<FarkasCell> = Vec::new();
    let (mut hi, mut width, mut joints) = (top, width, joints.to_vec());
    for _ in 0..MOST_TRIES {
        if hi <= 0.0 {
            cells.reverse();
            return Ok(cells);
        }
        // the last cell reaches 0 once it would cover most of what is left
        let lo = if width >= 0.75 * hi { 0.0 } else { hi - width };
        match cell_over(cert, (arch, mu), (lo, hi), &joints, settings)? {
            Some(cell) => {
                joints.clone_from(&cell.joints);
                cells.push(cell);
                width = GROW * (hi - lo);
                hi = lo;
            }
            None if width <= NARROWEST_REL * hi => break,
            None => width *= SHRINK,
        }
    }
    Err(NotCertified(format!(
        "no Farkas cells could be proved below eta = {hi} (mu = {mu}, {} cell(s) proved between it and eta_lo = {top})",
        cells.len()
    )))
}

/// A Farkas cell over [lo, hi] that the verifier proves: with `joints` (the cell above's),
/// else the best of the contacts at the cell's middle (with sliding rows spread over the
/// arch too); `None` where none proves.
fn cell_over(
    cert: &Certificate,
    (arch, mu): (&Arch, f64),
    (lo, hi): (f64, f64),
    joints: &[CertJoint],
    settings: &Settings,
) -> Result<Option<FarkasCell>, NotCertified> {
    let cell = |joints: &[CertJoint]| FarkasCell {
        eta_lo: lo,
        eta_hi: hi,
        joints: joints.to_vec(),
    };
    let proved = |c: &FarkasCell| prove_farkas_cell(cert, c).is_ok();
    if proved(&cell(joints)) {
        return Ok(Some(cell(joints)));
    }
    let mid = 0.5 * (lo + hi);
    let pool = pool_at(arch, mid, mu, settings)?;
    let wider = || -> Vec<Loaded> {
        let spread = spread_slides(arch, CELL_SPREAD).into_iter();
        pool.iter()
            .copied()
            .chain(spread.map(|c| (c, Side::After)))
            .collect()
    };
    let try_pool = |pool: &[Loaded], d| {
        find_contact_farkas(arch, pool, mid, mu, d, |f| proved(&cell(&f.joints)))
    };
    // failing the statics, friction alone: three sliding rows in (h, v)
    let slides = || -> Vec<Loaded> {
        let wider = wider();
        wider
            .into_iter()
            .filter(|(c, _)| !c.kind.is_hinge())
            .collect()
    };
    let found = try_pool(&pool, 3)
        .or_else(|| try_pool(&wider(), 3))
        .or_else(|| try_pool(&slides(), 2));
    Ok(found.map(|f| cell(&f.joints)))
}
