//! `arch-enum atlas` as text: what it covers, each column's runs, the boundaries.

use super::format::sig;
use crate::atlas::{Atlas, Kind};
use crate::limit_states::EndCondition;
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

/// A boundary point as the summary counts it: (α, μ/μ_ms, tight, how its branch ends: 0
/// not solved, 1 a contact reaches its limit, 2 a mechanism rate falls to 0).
type Seen = (f64, f64, bool, usize);

/// Each pair of kinds that meet: how many points, over which openings, at what μ/μ_ms.
fn boundaries(s: &mut String, a: &Atlas) {
    let mut by_pair: BTreeMap<[Kind; 2], Vec<Seen>> = BTreeMap::new();
    for c in &a.columns {
        for p in &c.boundaries {
            let ratio = c.mu_ms.map_or(f64::NAN, |m| p.mu() / m);
            let how = match &p.end {
                Some(Ok(e)) if matches!(e.condition, EndCondition::Admissibility(_)) => 1,
                Some(Ok(_)) => 2,
                _ => 0,
            };
            by_pair
                .entry(p.between)
                .or_default()
                .push((p.alpha, ratio, p.tight, how));
        }
    }
    let _ = writeln!(
        s,
        "boundaries (bisected in mu at each column; where a branch of limit states ends, solved from the condition that ends it):"
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
        let how = |h: usize| pts.iter().filter(|p| p.3 == h).count();
        let solved = match (how(1), how(2)) {
            (0, 0) => String::new(),
            (l, r) => format!(
                "; {} solved ({l} where a contact reaches its limit, {r} where a mechanism rate falls to 0)",
                l + r
            ),
        };
        let _ = writeln!(
            s,
            "  {} / {}: {} point(s), alpha {:.5} to {:.5}, mu/mu_ms {} to {}{}{solved}",
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
    top_line(s, a);
    traced_line(s, a);
    let undecided = a
        .columns
        .iter()
        .flat_map(|c| &c.samples)
        .filter(|x| x.kind.is_err())
        .count();
    let _ = writeln!(s, "undecided samples   {undecided}");
    if a.rectangle.certify {
        let brackets: Vec<_> = a.columns.iter().flat_map(|c| &c.boundaries).collect();
        let count = |it: &mut dyn Iterator<Item = Option<&Result<bool, String>>>| {
            it.fold((0, 0, 0), |(n, ok, complete), r| match r {
                Some(Ok(c)) => (n + 1, ok + 1, complete + usize::from(*c)),
                _ => (n + 1, ok, complete),
            })
        };
        let b = count(&mut brackets.iter().map(|p| p.certified.as_ref()));
        let r = count(
            &mut a
                .columns
                .iter()
                .flat_map(|c| &c.runs_certified)
                .map(|r| Some(&r.1)),
        );
        let ms: Vec<Result<bool, String>> = a
            .columns
            .iter()
            .filter_map(|c| c.mu_ms_certified.clone().map(|m| m.map(|x| x.complete)))
            .collect();
        let m = count(&mut ms.iter().map(Some));
        let t = count(
            &mut a
                .traced
                .iter()
                .flatten()
                .flat_map(|t| &t.points)
                .map(|p| p.certified.as_ref()),
        );
        let _ = writeln!(
            s,
            "certified           kinds stated by verified certificates: {} of {} brackets (both ends), {} of {} runs (one sample each), mu_ms to 1e-6 at {} of {} openings, {} of {} traced points (both sides);\n                    lists of limit states proved complete (ridge evidence) at {}, {}, {} and {} of them, checked only elsewhere",
            b.1, b.0, r.1, r.0, m.1, m.0, t.1, t.0, b.2, r.2, m.2, t.2
        );
    }
}

/// The `non_unique`/`unique` boundary traced between columns, where it is.
fn traced_line(s: &mut String, a: &Atlas) {
    let strips: Vec<_> = a
        .columns
        .iter()
        .zip(a.columns.iter().skip(1))
        .zip(&a.traced)
        .filter_map(|((c, d), t)| t.as_ref().map(|t| (t, (c.alpha, d.alpha))))
        .collect();
    if strips.is_empty() {
        return;
    }
    let points: usize = strips.iter().map(|(t, _)| t.points.len()).sum();
    let with_points = strips.iter().filter(|(t, _)| !t.points.is_empty()).count();
    let notches = strips
        .iter()
        .flat_map(|(t, _)| &t.points)
        .filter(|p| p.notch.is_some())
        .count();
    let worst = strips
        .iter()
        .filter_map(|(t, span)| t.chord_departure(*span))
        .max_by(|p, q| p.0.total_cmp(&q.0));
    let _ = writeln!(
        s,
        "  traced between columns (non_unique / unique, by continuation in alpha): {points} point(s) in {with_points} strip(s){}{}",
        if notches > 0 {
            format!(", {notches} with a notch of uniqueness below (a branch ends before the next is born)")
        } else {
            String::new()
        },
        worst.map_or(String::new(), |(d, alpha)| format!(
            "; the straight segment between a strip's ends (columns or a tip) departs from them by up to {} of mu (alpha = {})",
            sig(d, 3),
            sig(alpha, 6)
        ))
    );
}

/// The top of the non-unique band, where the atlas has one.
fn top_line(s: &mut String, a: &Atlas) {
    if let Some(t) = &a.top {
        let same = t.conditions.0 == t.conditions.1;
        let _ = writeln!(
            s,
            "  top of the band: mu/mu_ms = {} at alpha = {} (mu = {}, {}): {}",
            sig(t.ratio, 12),
            sig(t.alpha, 12),
            sig(t.mu, 12),
            t.shape(),
            if same {
                t.conditions.0.clone()
            } else {
                format!("{} | {}", t.conditions.0, t.conditions.1)
            }
        );
    }
}
