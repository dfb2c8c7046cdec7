//! The least thickness of an arch under fill (bridge spec §2): without the monotone
//! shortcut.
//!
//! The fill's load relative to the ring's weight grows as 1/η, so "admissible at η ⇒
//! admissible at every larger η" is no longer a theorem and the margin s(η) need not be
//! increasing. The whole range is therefore scanned first: the margin LP at
//! [`SCAN_NODES`] thicknesses spaced geometrically from [`SCAN_FLOOR`] to the thickness
//! limit. η_s is bracketed between the lowest admissible node and the node below it, and
//! the scan says whether the admissible nodes form an interval (every node above the lowest
//! admissible one admissible too). Between two nodes the margin is taken as monotone: an
//! admissible island narrower than the spacing of the nodes (a ratio of about 1.26) is not
//! seen, and the answer says so. Where no node is admissible, the margin's maximum near
//! the best node is searched for such an island (just above the least friction at which
//! the arch stands, the thicknesses that stand are one narrow island).

use crate::admissibility::{Margin, WorkingSet};
use crate::arch::{Arch, ETA_TOP};
use crate::contact::ContactKind;
use crate::search::{golden_min, margin_at, Bracket};
use crate::settings::Settings;
use crate::undecided::Undecided;

/// How many thicknesses the scan of an arch with fill evaluates.
pub const SCAN_NODES: usize = 64;

/// The thinnest ring the scan evaluates (η): the fill's 1/η has no finite limit at η = 0.
pub const SCAN_FLOOR: f64 = 1e-6;

/// The margin LP's verdict at each scanned thickness of an arch with fill.
#[derive(Debug, Clone, PartialEq)]
pub struct ThicknessScan {
    /// The thicknesses scanned, increasing from [`SCAN_FLOOR`] to the thickness limit.
    pub etas: Vec<f64>,
    /// Whether a statically admissible state exists there (margin ≥ 0).
    pub admissible: Vec<bool>,
}

impl ThicknessScan {
    /// The index of the lowest admissible thickness scanned, if any.
    pub fn lowest(&self) -> Option<usize> {
        self.admissible.iter().position(|&a| a)
    }

    /// The scanned thicknesses above the lowest admissible one where no state is
    /// admissible: empty when the admissible nodes form an interval.
    pub fn gaps(&self) -> Vec<f64> {
        let Some(i) = self.lowest() else {
            return Vec::new();
        };
        (i..self.etas.len())
            .filter(|&k| !self.admissible[k])
            .map(|k| self.etas[k])
            .collect()
    }
}

/// The thicknesses of the scan.
fn nodes() -> Vec<f64> {
    let ratio = (ETA_TOP / SCAN_FLOOR).ln() / (SCAN_NODES - 1) as f64;
    (0..SCAN_NODES)
        .map(|k| {
            if k + 1 == SCAN_NODES {
                ETA_TOP
            } else {
                SCAN_FLOOR * (ratio * k as f64).exp()
            }
        })
        .collect()
}

/// The scan of `arch` at friction `mu`, with the bracket of η_s it gives: the lowest
/// admissible node and the one below it (`None` when no node is admissible or the lowest
/// is the floor). An LP the back end cannot solve ends the scan.
pub(super) fn scan(
    arch: &Arch,
    mu: f64,
    modes: &[ContactKind],
    ws: &mut WorkingSet,
    settings: &Settings,
) -> Result<(ThicknessScan, Option<Bracket<Margin>>), Undecided> {
    let mut etas = nodes();
    let mut margins = Vec::with_capacity(etas.len());
    for &eta in &etas {
        margins.push(margin_at(arch, eta, mu, modes, ws, settings)?);
    }
    if margins.iter().all(|m| m.margin < 0.0) {
        let mut at = |eta: f64| margin_at(arch, eta, mu, modes, ws, settings);
        if let Some((eta, m)) = island(&etas, &margins, &mut at)? {
            let k = etas.partition_point(|&e| e < eta);
            etas.insert(k, eta);
            margins.insert(k, m);
        }
    }
    let admissible: Vec<bool> = margins.iter().map(|m| m.margin >= 0.0).collect();
    let scan = ThicknessScan { etas, admissible };
    let bracket = match scan.lowest() {
        Some(i) if i > 0 => {
            let lo = (scan.etas[i - 1], margins[i - 1].margin);
            let m = margins.swap_remove(i);
            Some((lo, (scan.etas[i], m.margin, m)))
        }
        _ => None,
    };
    Ok((scan, bracket))
}

/// The golden-section search for an admissible island between the nodes stops when its
/// bracket is narrower than this, relative to η.
const ISLAND_REL: f64 = 1e-12;

/// When no node is admissible: an admissible thickness near the node of greatest margin,
/// found by golden-section search for the margin's maximum between that node's neighbours
/// (the margin taken as unimodal there). Just above the least friction at which the arch
/// with its fill stands, the thicknesses that stand are a narrow island around one
/// thickness, narrower than the spacing of the nodes.
fn island(
    etas: &[f64],
    margins: &[Margin],
    at: &mut impl FnMut(f64) -> Result<Margin, Undecided>,
) -> Result<Option<(f64, Margin)>, Undecided> {
    let k = (0..margins.len())
        .max_by(|&i, &j| margins[i].margin.total_cmp(&margins[j].margin))
        .expect("nodes");
    let bracket = (etas[k.saturating_sub(1)], etas[(k + 1).min(etas.len() - 1)]);
    let stands = |m: &Margin| m.margin >= 0.0;
    let found = golden_min(bracket, ISLAND_REL, at, |m| -m.margin, stands)?;
    Ok(found.filter(|(_, m)| stands(m)))
}
