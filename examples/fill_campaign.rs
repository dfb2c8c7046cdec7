//! The least thickness of continuous arches with fill on random arches (bridge spec §2):
//! how often each outcome comes (a limit state, no equilibrium, unresolved), whether the
//! scan finds the admissible thicknesses an interval, whether the limit-state search
//! completed, and η_s against the same arch cut into 509 equal voussoirs (joints only
//! restrict where the line of thrust is checked: η_s of the voussoirs is never above, and
//! within about (π/509)² relative). The times of the solve alone and of the survey (solve
//! and the complete limit-state search) are printed as distributions.
//!
//! ```text
//! cargo run --release --example fill_campaign -- 200 7
//! ```

use arch_enum::bridge::Fill;
use arch_enum::limit::Outcome;
use arch_enum::limit_states::survey;
use arch_enum::{Arch, Settings, WeightModel};
use std::time::Instant;

#[path = "common/lcg.rs"]
mod lcg;
use lcg::Rng;

fn main() {
    let args: Vec<String> = std::env::args().collect();
    let count: usize = args.get(1).and_then(|v| v.parse().ok()).unwrap_or(100);
    let seed: u64 = args.get(2).and_then(|v| v.parse().ok()).unwrap_or(7);
    let mut rng = Rng(seed);
    let settings = Settings::default();
    let (mut limits, mut noeq, mut unresolved, mut gaps, mut incomplete) = (0, 0, 0, 0, 0);
    let (mut worst, mut above) = (0.0f64, 0);
    let (mut times, mut solve_times) = (Vec::new(), Vec::new());
    for case in 0..count {
        let alpha = -0.9 + 1.7 * rng.next();
        let weight = if rng.next() < 0.3 {
            WeightModel::Centroid
        } else {
            WeightModel::Centreline
        };
        let fill = Fill::new(0.1 + 1.5 * rng.next(), 0.01 + 0.4 * rng.next()).unwrap();
        let mu = if rng.next() < 0.15 {
            f64::INFINITY
        } else {
            0.2 + 1.5 * rng.next()
        };
        let arch = Arch::symmetric(alpha, weight).unwrap().with_fill(fill);
        let start = Instant::now();
        let solved = arch_enum::limit::solve(&arch, mu, &settings).unwrap();
        solve_times.push(start.elapsed().as_secs_f64());
        let start = Instant::now();
        let s = survey(&arch, mu, &settings).unwrap();
        times.push(start.elapsed().as_secs_f64());
        assert_eq!(
            format!("{:?}", solved.outcome),
            format!("{:?}", s.solution.outcome)
        );
        if let Some(sc) = s.solution.scan.as_ref().filter(|sc| !sc.gaps().is_empty()) {
            gaps += 1;
            println!(
                "case {case}: alpha {alpha:?} mu {mu:?} {fill:?} {weight:?}: admissible from eta = {:?}, not at {:?}",
                sc.lowest().map(|i| sc.etas[i]),
                sc.gaps()
            );
        }
        match &s.solution.outcome {
            Outcome::Limit(ls) => {
                limits += 1;
                if s.states.is_err() {
                    incomplete += 1;
                    println!(
                        "case {case}: alpha {alpha} mu {mu} {fill:?}: search {:?}",
                        s.states
                    );
                }
                let n = 509;
                // the springings as `Arch::new` stores them (it may round β_L by an ulp)
                let base = Arch::new(arch.beta_right(), arch.beta_left(), weight).unwrap();
                let (br, bl) = (base.beta_right(), base.beta_left());
                // the last joint is the springing itself (br + (bl − br) may round off it)
                let joints: Vec<f64> = (0..=n)
                    .map(|i| {
                        if i == n {
                            bl
                        } else {
                            br + (bl - br) * i as f64 / n as f64
                        }
                    })
                    .collect();
                let cut = base.with_joints(&joints).unwrap().with_fill(fill);
                match arch_enum::limit::solve(&cut, mu, &settings)
                    .unwrap()
                    .outcome
                {
                    Outcome::Limit(d) => {
                        let rel = (ls.eta_static - d.eta_static) / ls.eta_static;
                        if rel < -1e-12 {
                            above += 1;
                            println!("case {case}: voussoirs above the continuum: rel {rel:e}");
                        }
                        worst = worst.max(rel.abs());
                    }
                    other => println!("case {case}: alpha {alpha} mu {mu}: voussoirs {other:?}"),
                }
            }
            Outcome::NoEquilibrium { .. } => noeq += 1,
            other => {
                unresolved += 1;
                println!("case {case}: alpha {alpha} mu {mu} {fill:?}: {other:?}");
            }
        }
    }
    times.sort_by(f64::total_cmp);
    solve_times.sort_by(f64::total_cmp);
    let q = |p: f64| times[((times.len() - 1) as f64 * p) as usize] * 1e3;
    let qs = |p: f64| solve_times[((solve_times.len() - 1) as f64 * p) as usize] * 1e3;
    println!(
        "{count} continuous arches with fill (seed {seed}): {limits} least thicknesses, {noeq} no equilibrium, {unresolved} unresolved"
    );
    println!(
        "scans not an interval: {gaps}; limit-state searches not completed: {incomplete}; \
         509 voussoirs above the continuum: {above}; largest |relative gap| {worst:.2e}"
    );
    println!(
        "time per survey (solve + search): median {:.1} ms, 90 % {:.1} ms, max {:.1} ms",
        q(0.5),
        q(0.9),
        q(1.0)
    );
    println!(
        "time of the solve alone (eta_s and its limit state): median {:.1} ms, 90 % {:.1} ms, max {:.1} ms",
        qs(0.5),
        qs(0.9),
        qs(1.0)
    );
}
