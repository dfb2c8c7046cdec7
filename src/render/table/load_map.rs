//! `arch-enum atlas --horizontal` as text: per friction coefficient, how many cells show a
//! reduction of the collapse multiplier below the static maximum, the largest and where,
//! the semicircle's; then every cell with a reduction.

use super::format::sig;
use crate::atlas::loads::{CellAnswer, LoadMap, BOUNDARY_REL, FACTOR_MIN};
use std::fmt::Write;

/// The load map as text.
pub fn load_map(map: &LoadMap) -> String {
    let r = &map.grid.rect;
    let mut s = String::new();
    let _ = writeln!(
        s,
        "load map: a horizontal acceleration (towards the right springing) on symmetric arches, alpha in [{}, {}] ({} openings), eta = f eta*(alpha, mu) with f from {FACTOR_MIN} to {} ({} thicknesses, geometric); {}; weight along the {}",
        r.alpha_min,
        r.alpha_max,
        map.alphas.len(),
        map.grid.factor_max,
        map.factors.len(),
        r.blocks.map_or("continuous joints".into(), |n| format!("{n} voussoirs")),
        r.weight.name()
    );
    let _ = writeln!(
        s,
        "each cell is the complete load survey: lambda_static and every limit state below it; a reduction is lambda_c < lambda_static (a sampled map: a reduction narrower than the grid is not seen)"
    );
    let _ = writeln!(
        s,
        "          mu   cells  answered  undecided  reduced  largest reduction (alpha, eta)   semicircle's largest"
    );
    for &mu in &map.grid.mus {
        let count = |f: &dyn Fn(&CellAnswer) -> bool| map.at(mu).filter(|c| f(&c.answer)).count();
        let largest = map.largest(mu).map_or("none".to_string(), |c| {
            format!(
                "{} ({}, {})",
                sig(c.reduction().unwrap_or(0.0), 4),
                sig(c.alpha, 5),
                c.eta.map_or("-".into(), |e| sig(e, 5))
            )
        });
        let _ = writeln!(
            s,
            "  {:>10}  {:>6}  {:>8}  {:>9}  {:>7}  {largest:<32}  {}",
            sig(mu, 6),
            map.at(mu).count(),
            count(&|a| matches!(a, CellAnswer::Ratio { .. })),
            count(&|a| matches!(a, CellAnswer::Undecided(_))),
            map.at(mu).filter(|c| c.reduced()).count(),
            map.semicircle(mu)
                .map_or("not in the map".into(), |r| sig(r, 4)),
        );
    }
    for c in &map.cells {
        if let CellAnswer::Undecided(why) = &c.answer {
            let _ = writeln!(
                s,
                "undecided at mu = {}, alpha = {}, eta = {}: {why}",
                sig(c.mu, 6),
                sig(c.alpha, 6),
                c.eta.map_or("-".into(), |e| sig(e, 6))
            );
        }
    }
    let reduced: Vec<_> = map.cells.iter().filter(|c| c.reduced()).collect();
    if !reduced.is_empty() {
        let _ = writeln!(s, "cells with a reduction:");
        let _ = writeln!(
            s,
            "          mu       alpha         eta  lambda_static      lambda_c  reduction  {}",
            if r.certify {
                format!("{:<24}  certified (at least)", "least limit state")
            } else {
                "least limit state".into()
            }
        );
    }
    for c in reduced {
        let Some((lambda_static, lambda_c, mode)) = c.ratio() else {
            continue;
        };
        // a survey that did not settle: λ_c at most the least state found
        let bound = if c.at_least() { ">=" } else { "" };
        let _ = writeln!(
            s,
            "  {:>10}  {:>10}  {:>10}  {:>13}  {:>12}  {:>9}  {}{}",
            sig(c.mu, 6),
            sig(c.alpha, 6),
            c.eta.map_or("-".into(), |e| sig(e, 6)),
            sig(lambda_static, 8),
            (if bound.is_empty() { "" } else { "<=" }).to_string() + &sig(lambda_c, 8),
            bound.to_string() + &sig(c.reduction().unwrap_or(0.0), 4),
            match c.certified {
                Some(_) => format!("{:<24}", mode.name()),
                None => mode.name().into(),
            },
            match &c.certified {
                Some(Ok(r)) => format!("  {}", sig(*r, 4)),
                Some(Err(why)) => format!("  not certified: {why}"),
                None => String::new(),
            }
        );
    }
    boundaries(&mut s, map);
    s
}

/// Where the reduction begins or ends along η, between neighbouring cells.
fn boundaries(s: &mut String, map: &LoadMap) {
    if map.boundaries.is_empty() {
        return;
    }
    let _ = writeln!(
        s,
        "where the reduction begins or ends (bisected in eta to {} of it, each midpoint the complete load survey):",
        sig(BOUNDARY_REL, 1)
    );
    let _ = writeln!(
        s,
        "          mu       alpha  eta (bracket)                  reduction at its reduced side"
    );
    for b in &map.boundaries {
        let _ = writeln!(
            s,
            "  {:>10}  {:>10}  [{}, {}]  {}{} {}{}{}{}{}",
            sig(b.mu, 6),
            sig(b.alpha, 6),
            sig(b.etas.0, 12),
            sig(b.etas.1, 12),
            if b.at_least { ">= " } else { "" },
            sig(b.reduction, 4),
            if b.reduced_below {
                "thinner"
            } else {
                "thicker"
            },
            if b.followed > 0 {
                format!(
                    " ({} midpoints decided by following its limit state)",
                    b.followed
                )
            } else {
                String::new()
            },
            if b.bounded > 0 {
                format!(
                    " ({} midpoints decided by a limit state the survey found: at least)",
                    b.bounded
                )
            } else {
                String::new()
            },
            b.stopped
                .as_ref()
                .map_or(String::new(), |w| format!(" (stopped: {w})")),
            match &b.certified {
                Some(Ok(r)) => format!("; certified at least {}", sig(*r, 4)),
                Some(Err(why)) => format!("; not certified: {why}"),
                None => String::new(),
            }
        );
    }
    for &mu in &map.grid.mus {
        if let Some(b) = map.largest_at_boundary(mu) {
            let (_, eta) = b.reduced_end();
            let cells = map.largest(mu).and_then(|c| c.reduction()).unwrap_or(0.0);
            let _ = writeln!(
                s,
                "largest reduction at a boundary's reduced end, mu = {}: {}{} (alpha {}, eta {}){}",
                sig(mu, 6),
                if b.at_least { "at least " } else { "" },
                sig(b.reduction, 4),
                sig(b.alpha, 6),
                sig(eta, 10),
                if b.reduction > cells {
                    ", more than any cell's"
                } else {
                    ""
                }
            );
        }
    }
}
