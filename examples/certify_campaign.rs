//! `certify` then `verify` on random arches (thickness question), as a checker would try
//! them: symmetric and unsymmetric, continuous and discrete (2 to 60 voussoirs), both weight
//! models, μ below μ_ms, just above it, on the mixed branches and ∞. Prints how each ended
//! and every case that was not certified at the requested gap, with why.
//!
//! ```text
//! cargo run --release --example certify_campaign -- [cases] [seed]
//! ```

use arch_enum::certificate::{certify, verify};
use arch_enum::{least_friction, Arch, Settings, WeightModel};
use std::collections::BTreeMap;

/// A small deterministic generator (64-bit LCG), so that a run can be repeated.
struct Rng(u64);

impl Rng {
    fn next(&mut self) -> f64 {
        self.0 = self
            .0
            .wrapping_mul(6364136223846793005)
            .wrapping_add(1442695040888963407);
        (self.0 >> 11) as f64 / (1u64 << 53) as f64
    }
    fn range(&mut self, a: f64, b: f64) -> f64 {
        a + (b - a) * self.next()
    }
}

/// A random arch and a description of it.
fn random_arch(rng: &mut Rng) -> Option<(Arch, String)> {
    let weight = if rng.next() < 0.3 {
        WeightModel::Centroid
    } else {
        WeightModel::Centreline
    };
    let arch = if rng.next() < 0.5 {
        Arch::symmetric(rng.range(-1.2, 1.2), weight).ok()?
    } else {
        let br = rng.range(-1.4, 1.4);
        Arch::new(br, br + rng.range(1.0, 3.6), weight).ok()?
    };
    let arch = if rng.next() < 0.4 {
        arch.with_blocks(2 + (rng.next() * 58.0) as usize).ok()?
    } else {
        arch
    };
    let layout = match arch.layout() {
        arch_enum::JointLayout::Continuous => "continuous".to_string(),
        arch_enum::JointLayout::Discrete(j) => format!("{} voussoirs", j.len() - 1),
    };
    let text = format!(
        "--beta-right {} --beta-left {} ({layout}, {:?})",
        arch.beta_right(),
        arch.beta_left(),
        arch.weight()
    );
    Some((arch, text))
}

fn main() {
    let args: Vec<String> = std::env::args().collect();
    let cases: usize = args.get(1).and_then(|s| s.parse().ok()).unwrap_or(200);
    let seed: u64 = args.get(2).and_then(|s| s.parse().ok()).unwrap_or(22);
    let settings = Settings::default();
    let mut rng = Rng(seed);
    let mut tally: BTreeMap<String, usize> = BTreeMap::new();
    let mut failures = Vec::new();
    let mut done = 0;
    while done < cases {
        let Some((arch, text)) = random_arch(&mut rng) else {
            continue;
        };
        let Ok(Some(ms)) = least_friction(&arch, &settings) else {
            continue;
        };
        let mu = match (rng.next() * 5.0) as usize {
            0 => ms * 0.9,
            1 => ms * 1.001,
            2 => ms * rng.range(1.01, 3.0),
            3 => ms * rng.range(3.0, 30.0),
            _ => f64::INFINITY,
        };
        if ms <= 0.0 && mu <= 0.0 {
            continue;
        }
        done += 1;
        let outcome = match certify(&arch, mu, 1e-12, &settings) {
            Err(e) => {
                failures.push(format!("{text} mu = {mu}: not certified: {}", e.0));
                "not certified".to_string()
            }
            Ok(c) => match verify(&c) {
                Err(r) => {
                    failures.push(format!("{text} mu = {mu}: REJECTED by verify: {}", r.0));
                    "rejected by verify (defect)".to_string()
                }
                Ok(_) if !c.delivers_gap(1e-12) => {
                    failures.push(format!(
                        "{text} mu = {mu}: gap not reached (relative {:?})",
                        c.gap_relative
                    ));
                    format!("verified, gap not reached ({:?})", c.claim)
                }
                Ok(_) => format!("verified at 1e-12 ({:?})", c.claim),
            },
        };
        *tally.entry(outcome).or_default() += 1;
    }
    println!("{cases} random arches (seed {seed}), certify --gap 1e-12 then verify:");
    for (k, n) in &tally {
        println!("  {n:5}  {k}");
    }
    println!("\nnot certified at 1e-12:");
    for f in &failures {
        println!("  {f}");
    }
}
