//! The ridge walk over the friction polygon (the default limit-state search of a discrete
//! arch with the centreline weight at finite μ) against the sweep of P(η) (the reference
//! method, `LimitStateSearch::Sweep`), on seeded random arches: the same limit states
//! (η, reactions, active pattern, collapse mode), in the same order, on every arch. The
//! brute force of `search_reference` checks both against the formulas on smaller samples.

use crate::search_reference::{least_friction, random_joints, Rng};
use arch_enum::limit_states::{search, LimitState, LimitStates};
use arch_enum::settings::LimitStateSearch;
use arch_enum::{Arch, Settings, WeightModel};
use std::f64::consts::PI;

fn discrete(br: f64, bl: f64, joints: &[f64]) -> Arch {
    Arch::new(br, bl, WeightModel::Centreline)
        .unwrap()
        .with_joints(joints)
        .unwrap()
}

fn sweep_settings() -> Settings {
    Settings {
        limit_state_search: LimitStateSearch::Sweep,
        ..Settings::default()
    }
}

/// A random arch: every fourth (`case` % 4 = 3) with arbitrary springings, the others
/// arch-like; 2–12 voussoirs of random sizes. The springings and every joint angle.
fn random_arch(rng: &mut Rng, case: usize) -> (f64, f64, Vec<f64>) {
    let (br, bl) = if case % 4 == 3 {
        let br = -1.2 + 2.6 * rng.next();
        (br, br + 0.4 + 3.3 * rng.next())
    } else {
        (-0.6 + 1.2 * rng.next(), PI - 0.6 + 1.2 * rng.next())
    };
    let blocks = 2 + (rng.next() * 11.0) as usize;
    (br, bl, random_joints(rng, br, bl, blocks))
}

/// The two answers agree state by state; `Err` describes the first difference.
fn same_answer(ridge: &LimitStates, sweep: &LimitStates) -> Result<(), String> {
    if ridge.mechanism_at_eta_s != sweep.mechanism_at_eta_s || ridge.eta_s != sweep.eta_s {
        return Err(format!(
            "eta_s {} / {}, mechanism at eta_s {} / {}",
            ridge.eta_s, sweep.eta_s, ridge.mechanism_at_eta_s, sweep.mechanism_at_eta_s
        ));
    }
    let list = |s: &LimitStates| {
        s.above
            .iter()
            .map(|a| format!("{:.15} {:?} {:?}", a.t, a.x, a.pattern))
            .collect::<Vec<_>>()
    };
    if ridge.above.len() != sweep.above.len() {
        return Err(format!(
            "ridge {:#?}\nsweep {:#?}",
            list(ridge),
            list(sweep)
        ));
    }
    for (p, q) in ridge.above.iter().zip(&sweep.above) {
        let scale = 1.0 + q.x.iter().map(|v| v.abs()).sum::<f64>();
        let same = (p.t - q.t).abs() <= 1e-10 * q.t
            && (0..3).all(|k| (p.x[k] - q.x[k]).abs() <= 1e-8 * scale)
            && p.mode == q.mode
            && p.pattern.len() == q.pattern.len()
            && p.pattern
                .iter()
                .zip(&q.pattern)
                .all(|(a, b)| a.kind == b.kind && (a.beta - b.beta).abs() <= 1e-12);
        if !same {
            return Err(format!(
                "ridge {:#?}\nsweep {:#?}",
                list(ridge),
                list(sweep)
            ));
        }
    }
    Ok(())
}

/// 1 500 random discrete arches: arch-like and arbitrary springings, 2–12 voussoirs of
/// random sizes, μ from just above μ_ms to 4 μ_ms. Every answer agrees, the ridge decides
/// most of them itself (not by falling back to the sweep), and limit states above η_s are
/// met on many (the comparison is not vacuous).
#[test]
fn ridge_and_sweep_agree_on_random_discrete_arches() {
    let mut rng = Rng(0x05ee_d0f4_1d6e);
    let (mut compared, mut by_ridge, mut above, mut both_failed) = (0, 0, 0, 0);
    let mut differ: Vec<String> = Vec::new();
    for case in 0..1500 {
        let (br, bl, joints) = random_arch(&mut rng, case);
        let ms = least_friction(br, bl, &joints);
        let mu = ms * (1.0 + 1e-3 + 3.0 * rng.next().powi(2));
        if !mu.is_finite() {
            continue;
        }
        let arch = discrete(br, bl, &joints);
        let ridge = search(&arch, mu, &Settings::default()).unwrap();
        let sweep = search(&arch, mu, &sweep_settings()).unwrap();
        let text = format!(
            "case {case}: beta_r = {br:?}, beta_l = {bl:?}, joints = {joints:?}, mu = {mu:?}"
        );
        match (ridge, sweep) {
            (Ok(r), Ok(s)) => {
                compared += 1;
                by_ridge += usize::from(r.method == "ridge");
                above += usize::from(!s.above.is_empty());
                if let Err(e) = same_answer(&r, &s) {
                    differ.push(format!("{text}\n{e}"));
                }
            }
            (Err(_), Err(_)) => both_failed += 1,
            (r, s) => differ.push(format!(
                "{text}\nridge {:?}\nsweep {:?}",
                r.map(|r| r.method),
                s.map(|s| s.method)
            )),
        }
    }
    println!(
        "{compared} compared ({by_ridge} by the ridge itself, {above} with limit states above eta_s), {both_failed} undecided by both, {} differ",
        differ.len()
    );
    assert!(differ.is_empty(), "{}", differ.join("\n\n"));
    assert!(compared >= 1200, "only {compared} arches compared");
    assert!(
        by_ridge * 10 >= compared * 9,
        "the ridge decided only {by_ridge} of {compared}"
    );
    assert!(
        above >= 60,
        "only {above} arches with limit states above eta_s"
    );
}

/// G1 on clusters of joints: three joints 2·10⁻⁵ to 3·10⁻⁴ apart among a few voussoirs,
/// whose sliding lines pass within G1's tolerance of a vertex of Q where they bound it (as
/// neighbouring joints of arches of 10⁴ voussoirs do). Where their columns cannot balance
/// without hinge rates the ridge goes on past such a vertex (it used to hand the arch to
/// the sweep): it decides every arch here itself, with the sweep's answer.
#[test]
fn ridge_passes_clusters_of_sliding_lines_that_cannot_slide_alone() {
    let mut rng = Rng(0x6c05_7e12);
    let (mut compared, mut above) = (0, 0);
    for case in 0..400 {
        // near the two arches of 10⁴ voussoirs that met G1 (α = −1 at μ = 0.6, the joint
        // at 96 % of the span; α = −0.5 at μ = 1, 80 %)
        let (alpha0, mu0, at) = [(-1.0, 0.6, 0.9601), (-0.5, 1.0, 0.7996)][case % 2];
        let alpha = alpha0 + 0.1 * (rng.next() - 0.5);
        let (br, bl) = (-alpha, PI + alpha);
        let blocks = 3 + (rng.next() * 4.0) as usize;
        let centre = br + (bl - br) * (at + 0.02 * (rng.next() - 0.5));
        let gap = 2e-5 * 15f64.powf(rng.next());
        let mut joints: Vec<f64> = (1..blocks)
            .map(|k| br + (bl - br) * k as f64 / blocks as f64)
            .filter(|b| (b - centre).abs() > 0.05)
            .chain([centre - gap, centre, centre + gap])
            .collect();
        joints.sort_by(f64::total_cmp);
        let mut all = vec![br];
        all.extend(&joints);
        all.push(bl);
        let ms = least_friction(br, bl, &all);
        let mu = if case % 4 < 2 {
            mu0 * (1.0 + 0.1 * (rng.next() - 0.5))
        } else {
            ms * (1.0 + 1e-3 + 0.5 * rng.next().powi(2))
        };
        if ms.is_nan() || mu <= ms || !mu.is_finite() {
            continue;
        }
        let arch = discrete(br, bl, &joints);
        let ridge = search(&arch, mu, &Settings::default()).unwrap();
        let sweep = search(&arch, mu, &sweep_settings()).unwrap();
        let text = format!("case {case}: alpha = {alpha:?}, joints = {joints:?}, mu = {mu:?}");
        match (ridge, sweep) {
            (Ok(r), Ok(s)) => {
                compared += 1;
                above += usize::from(!s.above.is_empty());
                assert_eq!(r.method, "ridge", "{text}");
                if let Err(e) = same_answer(&r, &s) {
                    panic!("{text}\n{e}");
                }
            }
            (r, s) => assert_eq!(r.is_ok(), s.is_ok(), "{text}"),
        }
    }
    println!("{compared} compared, {above} with limit states above eta_s");
    assert!(compared >= 300, "only {compared} compared");
}

/// Symmetric arches of equal voussoirs (mirror images share η: the order of states with
/// equal η is by pattern in both methods), and the equal-piece discretisations a
/// continuous arch is searched on (48 and 96 pieces).
#[test]
fn ridge_and_sweep_agree_on_symmetric_and_fine_arches() {
    let mut rng = Rng(99);
    let mut compared = 0;
    for case in 0..120 {
        let alpha = -0.8 + 1.9 * rng.next();
        let blocks = match case % 10 {
            8 => 48,
            9 => 96,
            _ => 3 + (rng.next() * 14.0) as usize,
        };
        let (br, bl) = (-alpha, PI + alpha);
        let joints: Vec<f64> = (0..=blocks)
            .map(|i| {
                if i == blocks {
                    bl
                } else {
                    br + (bl - br) * i as f64 / blocks as f64
                }
            })
            .collect();
        let ms = least_friction(br, bl, &joints);
        let mu = ms * (1.0 + 1e-3 + 2.0 * rng.next());
        let arch = discrete(br, bl, &joints);
        let ridge = search(&arch, mu, &Settings::default()).unwrap();
        let sweep = search(&arch, mu, &sweep_settings()).unwrap();
        if let (Ok(r), Ok(s)) = (&ridge, &sweep) {
            compared += 1;
            if let Err(e) = same_answer(r, s) {
                panic!("case {case}: alpha = {alpha:?}, {blocks} voussoirs, mu = {mu:?}\n{e}");
            }
        } else {
            assert_eq!(
                ridge.is_ok(),
                sweep.is_ok(),
                "case {case}: alpha = {alpha:?}, {blocks} voussoirs, mu = {mu:?}"
            );
        }
    }
    assert!(compared >= 100, "only {compared} compared");
}

/// G1 at vertices of Q that carry a limit state above η_s: on random arches with a limit
/// state at a vertex q of Q (two sliding contacts at interior joints), a joint is added
/// where a third sliding line passes through q (its root by bisection), so that three
/// lines meet there. Where their columns cannot balance without hinge rates the ridge goes
/// on past q (it used to hand every such arch to the sweep) and finds the state at q with
/// its three sliding contacts; where they can, it hands back. Every answer is the sweep's.
#[test]
fn ridge_passes_three_sliding_lines_at_a_limit_state() {
    use arch_enum::contact::Location;
    let mut rng = Rng(0x05ee_d0f4_1d6e);
    let (mut compared, mut through_triple) = (0, 0);
    for case in 0..9000 {
        let (br, bl, all) = random_arch(&mut rng, case);
        let arch0 = discrete(br, bl, &all[1..all.len() - 1]);
        // (the library's μ_ms: the reference's LP bisection costs more than the searches)
        let Ok(Some(ms)) = arch_enum::least_friction(&arch0, &Settings::default()) else {
            continue;
        };
        let mu = ms * (1.0 + 1e-3 + 3.0 * rng.next().powi(2));
        if !mu.is_finite() {
            continue;
        }
        let inner = &all[1..all.len() - 1];
        let sliding = |c: &&arch_enum::Contact| !c.kind.is_hinge() && c.at == Location::Interior;
        let Ok(Ok(found)) = search(&arch0, mu, &Settings::default()) else {
            continue;
        };
        let Some(state) = found
            .above
            .iter()
            .find(|st| st.pattern.iter().filter(sliding).count() >= 2)
        else {
            continue;
        };
        // where the sliding line of a joint at b (either sense) passes through q
        let (h, v) = (state.x[0], state.x[1]);
        let line = |b: f64, sg: f64| {
            let d = b - br;
            let n = h * b.sin() + v * b.cos() - d * b.cos();
            let t = h * b.cos() - v * b.sin() + d * b.sin();
            sg * t - mu * n
        };
        for (m, sg) in (0..400).flat_map(|m| [(m, 1.0), (m, -1.0)]) {
            let at = |k: usize| br + (bl - br) * k as f64 / 400.0;
            let (mut a, mut b) = (at(m), at(m + 1));
            if line(a, sg) * line(b, sg) >= 0.0 {
                continue;
            }
            for _ in 0..80 {
                let mid = 0.5 * (a + b);
                if line(a, sg) * line(mid, sg) <= 0.0 {
                    b = mid;
                } else {
                    a = mid;
                }
            }
            let root = 0.5 * (a + b);
            if inner.iter().any(|&j| (j - root).abs() < 1e-3) {
                continue;
            }
            let mut joints: Vec<f64> = inner.to_vec();
            joints.push(root);
            joints.sort_by(f64::total_cmp);
            let arch = discrete(br, bl, &joints);
            let text =
                format!("case {case}: br = {br:?}, bl = {bl:?}, joints = {joints:?}, mu = {mu:?}");
            let ridge = search(&arch, mu, &Settings::default()).unwrap();
            let sweep = search(&arch, mu, &sweep_settings()).unwrap();
            match (&ridge, &sweep) {
                (Ok(r), Ok(s)) => {
                    compared += 1;
                    if let Err(e) = same_answer(r, s) {
                        panic!("{text}\n{e}");
                    }
                    let triple = |st: &LimitState| st.pattern.iter().filter(sliding).count() >= 3;
                    through_triple +=
                        usize::from(r.method == "ridge" && r.above.iter().any(triple));
                }
                _ => assert_eq!(ridge.is_ok(), sweep.is_ok(), "{text}"),
            }
        }
    }
    println!("{compared} compared, {through_triple} decided by the ridge at a vertex with three sliding contacts");
    assert!(compared >= 40, "only {compared} compared");
    assert!(
        through_triple >= 10,
        "only {through_triple} through three lines"
    );
}
