//! `certify` then `verify` on random arches (thickness question), as a checker would try
//! them: symmetric and unsymmetric, continuous and discrete (2 to 60 voussoirs), both weight
//! models, μ below μ_ms, just above it, on the mixed branches and ∞. Prints how each ended
//! and every case that was not certified at the requested gap, with why.
//!
//! ```text
//! cargo run --release --example certify_campaign -- [cases] [seed]
//! ```

use arch_enum::certificate::{certify, verify, Certificate, Claim};
use arch_enum::{least_friction, Arch, Settings, WeightModel};
use arch_enum::{solve, Outcome};
use std::collections::BTreeMap;

#[path = "common/lcg.rs"]
mod lcg;
use lcg::Rng;

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
    let mut verified: Vec<Certificate> = Vec::new();
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
                    verified.push(c.clone());
                    failures.push(format!(
                        "{text} mu = {mu}: gap not reached (relative {:?})",
                        c.gap_relative
                    ));
                    format!("verified, gap not reached ({:?}{})", c.claim, unlisted(&c))
                }
                Ok(_) => {
                    verified.push(c.clone());
                    format!("verified at 1e-12 ({:?}{})", c.claim, unlisted(&c))
                }
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
    tamper(&verified, &mut rng, &settings);
}

/// ", no limit state listed" for a least-thickness certificate without one (an infimum, or
/// a least admissible state where the solve found no limit state: its bracket is a claim of
/// the statics alone).
fn unlisted(c: &Certificate) -> &'static str {
    match c.claim == Claim::LeastThickness && c.limit_state.is_none() {
        true => ", no limit state listed",
        false => "",
    }
}

/// Every numeric leaf of a JSON value, as a path of keys and indices.
fn leaves(v: &serde_json::Value, path: &mut Vec<String>, out: &mut Vec<Vec<String>>) {
    match v {
        serde_json::Value::Number(_) => out.push(path.clone()),
        serde_json::Value::Array(a) => {
            for (i, x) in a.iter().enumerate() {
                path.push(i.to_string());
                leaves(x, path, out);
                path.pop();
            }
        }
        serde_json::Value::Object(o) => {
            for (k, x) in o {
                path.push(k.clone());
                leaves(x, path, out);
                path.pop();
            }
        }
        _ => {}
    }
}

fn at<'a>(v: &'a mut serde_json::Value, path: &[String]) -> &'a mut serde_json::Value {
    path.iter().fold(v, |v, k| match v {
        serde_json::Value::Array(a) => &mut a[k.parse::<usize>().unwrap()],
        other => &mut other[k.as_str()],
    })
}

/// Whether an accepted certificate claims something true, by solving its arch anew.
fn still_true(c: &Certificate, settings: &Settings) -> Result<bool, String> {
    let a = &c.arch;
    let mut arch = Arch::new(a.beta_right, a.beta_left, a.weight).map_err(|e| e.to_string())?;
    if let Some(j) = &a.joint_angles {
        arch = arch.with_joints(j).map_err(|e| e.to_string())?;
    }
    let mu = c.mu.unwrap_or(f64::INFINITY);
    let out = solve(&arch, mu, settings)
        .map_err(|e| e.to_string())?
        .outcome;
    Ok(match (c.claim, out) {
        (Claim::NoEquilibrium, Outcome::NoEquilibrium { .. }) => true,
        (Claim::StandsAtEveryThickness, Outcome::NoCollapse { .. }) => true,
        (Claim::LeastThickness, out @ (Outcome::Limit(_) | Outcome::Unresolved { .. })) => {
            // η_s: the least admissible state's (also where the solve found no limit state
            // above it and the certificate takes the search's first)
            let e = match out {
                Outcome::Limit(ls) => ls.eta_static,
                Outcome::Unresolved {
                    least_static: Some((e, _)),
                    ..
                } => e,
                _ => return Ok(false),
            };
            let (lo, hi) = (
                c.collapse.as_ref().and_then(|f| f.eta),
                c.safe.as_ref().map(|s| s.eta),
            );
            let (Some(lo), Some(hi)) = (lo, hi) else {
                return Ok(false);
            };
            e >= lo * (1.0 - 1e-14) && e <= hi * (1.0 + 1e-14)
        }
        _ => false,
    })
}

/// The tamper campaign over the verified certificates (see the module).
fn tamper(certs: &[Certificate], rng: &mut Rng, settings: &Settings) {
    const EDITS: usize = 14;
    let factors = [1e-15, 1e-12, 1e-9, 1e-6, 1e-3];
    let (mut edits, mut refused, mut accepted_true) = (0, 0, 0);
    let mut false_claims = Vec::new();
    for c in certs {
        let v = serde_json::to_value(c).unwrap();
        let mut paths = Vec::new();
        leaves(&v, &mut Vec::new(), &mut paths);
        for _ in 0..EDITS {
            let path = &paths[(rng.next() * paths.len() as f64) as usize];
            let mut e = v.clone();
            let slot = at(&mut e, path);
            let x = slot.as_f64().unwrap();
            let k = (rng.next() * (factors.len() + 1) as f64) as usize;
            let sign = if rng.next() < 0.5 { -1.0 } else { 1.0 };
            let y = match factors.get(k) {
                Some(f) => x * (1.0 + sign * f),
                None => -x,
            };
            if y == x {
                continue;
            }
            edits += 1;
            *slot = serde_json::json!(y);
            let Ok(t) = serde_json::from_value::<Certificate>(e) else {
                refused += 1;
                continue;
            };
            if verify(&t).is_err() {
                refused += 1;
                continue;
            }
            match still_true(&t, settings) {
                Ok(true) => accepted_true += 1,
                Ok(false) => {
                    // kept for a look: the edited certificate that `verify` accepted
                    let file = std::env::temp_dir()
                        .join(format!("false_claim_{}.json", false_claims.len()));
                    let _ =
                        std::fs::write(&file, serde_json::to_string_pretty(&t).unwrap_or_default());
                    false_claims.push(format!(
                        "{}: {x} -> {y} ({} claim, mu = {:?}; written to {})",
                        path.join("."),
                        t.claim.name(),
                        t.mu,
                        file.display()
                    ))
                }
                Err(e) => false_claims.push(format!(
                    "{}: {x} -> {y} (arch refused: {e})",
                    path.join(".")
                )),
            }
        }
    }
    println!(
        "\ntamper campaign: {edits} edits of {} verified certificates: {refused} rejected, {accepted_true} accepted with a claim that is still true, {} accepted with a false claim",
        certs.len(),
        false_claims.len()
    );
    for f in &false_claims {
        println!("  FALSE CLAIM ACCEPTED: {f}");
    }
}
