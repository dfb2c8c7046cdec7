//! `arch-enum atlas` as text: what it covers, each column's runs, the boundaries.

use super::format::sig;
use crate::atlas::{Atlas, Kind};
use std::collections::BTreeMap;
use std::fmt::Write;

/// The atlas as text.
pub fn atlas(a: &Atlas) -> String {
    let r = &a.rectangle;
    let mut s = String::new();
    let _ = writeln!(
        s,
        "atlas of uniqueness: symmetric arches, alpha in [{}, {}] ({} openings); mu from mu_ms(alpha) to {} mu_ms(alpha) ({} samples each, dense near mu_ms); {}; weight along the {}",
        r.alpha_min,
        r.alpha_max,
        r.columns,
        r.mu_max_factor,
        r.samples,
        r.blocks.map_or("continuous joints".into(), |n| format!("{n} voussoirs")),
        r.weight.name()
    );
    let _ = writeln!(
        s,
        "kinds: unique (eta_s carries the only limit state), non_unique (others above eta_s), no_mechanism_at_eta (eta_s carries none), no_equilibrium (mu < mu_ms)"
    );
    let _ = writeln!(
        s,
        "      alpha            mu_ms  runs from mu_ms up (kind to mu)"
    );
    for c in &a.columns {
        let Some(mu_ms) = c.mu_ms else {
            let _ = writeln!(s, "  {:>9.5}  no finite mu_ms", c.alpha);
            continue;
        };
        let runs: Vec<String> = c
            .runs
            .iter()
            .map(|r| {
                format!(
                    "{} to {}",
                    r.0.map_or("undecided", Kind::name),
                    sig(r.2, 10)
                )
            })
            .collect();
        let _ = writeln!(
            s,
            "  {:>9.5}  {:>15}  {}",
            c.alpha,
            sig(mu_ms, 10),
            runs.join(" | ")
        );
    }
    boundaries(&mut s, a);
    s
}

/// Each pair of kinds that meet: how many points, over which openings, at what μ/μ_ms.
fn boundaries(s: &mut String, a: &Atlas) {
    let mut by_pair: BTreeMap<[Kind; 2], Vec<(f64, f64, bool)>> = BTreeMap::new();
    for c in &a.columns {
        for p in &c.boundaries {
            let ratio = c.mu_ms.map_or(f64::NAN, |m| p.mu() / m);
            by_pair
                .entry(p.between)
                .or_default()
                .push((p.alpha, ratio, p.tight));
        }
    }
    let _ = writeln!(
        s,
        "boundaries (located by bisection in mu at each column; not solved from their defining conditions):"
    );
    if by_pair.is_empty() {
        let _ = writeln!(s, "  none: one kind above mu_ms at every opening");
    }
    for (k, pts) in by_pair {
        let (amin, amax) = pts.iter().fold((f64::INFINITY, f64::NEG_INFINITY), |m, p| {
            (m.0.min(p.0), m.1.max(p.0))
        });
        let (rmin, rmax) = pts.iter().fold((f64::INFINITY, f64::NEG_INFINITY), |m, p| {
            (m.0.min(p.1), m.1.max(p.1))
        });
        let loose = pts.iter().filter(|p| !p.2).count();
        let _ = writeln!(
            s,
            "  {} / {}: {} point(s), alpha {:.5} to {:.5}, mu/mu_ms {} to {}{}",
            k[0].name(),
            k[1].name(),
            pts.len(),
            amin,
            amax,
            sig(rmin, 8),
            sig(rmax, 8),
            if loose > 0 {
                format!(" ({loose} not to neighbouring floats)")
            } else {
                String::new()
            }
        );
    }
    for t in &a.tips {
        let _ = writeln!(
            s,
            "  tip on mu_ms: {} / {} at alpha = {} (bracket [{}, {}]{}), mu_ms = {}",
            t.between[0].name(),
            t.between[1].name(),
            sig(0.5 * (t.alpha.0 + t.alpha.1), 12),
            t.alpha.0,
            t.alpha.1,
            t.stopped
                .as_ref()
                .map_or(String::new(), |w| format!("; stopped: {w}")),
            sig(t.mu_ms, 12)
        );
    }
    let undecided = a
        .columns
        .iter()
        .flat_map(|c| &c.samples)
        .filter(|x| x.kind.is_err())
        .count();
    let _ = writeln!(s, "undecided samples   {undecided}");
    if a.rectangle.certify {
        let brackets: Vec<_> = a.columns.iter().flat_map(|c| &c.boundaries).collect();
        let proved = brackets
            .iter()
            .filter(|p| matches!(p.certified, Some(Ok(()))))
            .count();
        let runs: Vec<_> = a.columns.iter().flat_map(|c| &c.runs_certified).collect();
        let held = runs.iter().filter(|r| r.1.is_ok()).count();
        let ms: Vec<_> = a
            .columns
            .iter()
            .filter_map(|c| c.mu_ms_certified.as_ref())
            .collect();
        let _ = writeln!(
            s,
            "certified           {proved} of {} brackets (both ends' kinds stated by verified certificates); {held} of {} runs (one sample each); mu_ms to 1e-6 at {} of {} openings",
            brackets.len(),
            runs.len(),
            ms.iter().filter(|m| m.is_ok()).count(),
            ms.len()
        );
    }
}
