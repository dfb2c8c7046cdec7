//! A margin over the η–μ plane for the map figure: at each (η, μ) the largest
//! admissibility margin of any state over the whole arch (the continuum margin of the
//! constraint-generation LP, an x-space distance divided by the span β_L − β_R). It is
//! positive in the safe domain, negative in the collapse domain, and vanishes on the
//! limit curve η*(μ). Rows are computed in parallel, each from a fresh working set (so
//! the values do not depend on the number of threads); progress goes through a callback.

use crate::admissibility::{margin_over_arch, Goal, WorkingSet};
use crate::arch::Arch;
use crate::contact::ContactKind;
use crate::settings::Settings;
use std::sync::atomic::{AtomicUsize, Ordering};

/// The margin at every (η, μ) of the grid, `result[i][j]` at (`etas[i]`, `mus[j]`); NaN
/// where the LP failed. `progress(done, total)` is called after each cell.
pub fn margin_map(
    arch: &Arch,
    etas: &[f64],
    mus: &[f64],
    settings: &Settings,
    threads: usize,
    progress: &(dyn Fn(usize, usize) + Sync),
) -> Vec<Vec<f64>> {
    let total = etas.len() * mus.len();
    let done = AtomicUsize::new(0);
    // rows are handed out one at a time, so a slow row does not hold up a whole chunk
    crate::threads::map(etas, threads, |_, &eta| {
        let mut ws = WorkingSet::initial(arch);
        mus.iter()
            .map(|&mu| {
                let v = margin_over_arch(
                    arch,
                    eta,
                    mu,
                    ContactKind::active_at(mu),
                    &mut ws,
                    Goal::Optimise,
                    settings,
                )
                .map_or(f64::NAN, |m| m.margin / arch.span());
                progress(done.fetch_add(1, Ordering::Relaxed) + 1, total);
                v
            })
            .collect()
    })
}
