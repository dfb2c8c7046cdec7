//! How the complete limit-state search (the ridge walk) grows with the number of voussoirs:
//! the median wall time of `survey` (η_s, the least limit state and every limit state above
//! it) for semicircular and horseshoe arches of 10² to 10⁴ voussoirs, with what it found.
//! Run: `cargo run --release --example ridge_scale`. `-- --dump` prints instead the limit
//! states of 400 pseudo-random arches bit for bit (to compare two builds).

use arch_enum::limit_states::survey;
use arch_enum::{Arch, Settings, WeightModel};
use std::time::Instant;

#[path = "common/lcg.rs"]
mod lcg;
#[path = "common/found.rs"]
mod summary;
#[path = "common/timing.rs"]
mod timing;
use lcg::Rng;
use timing::median;

/// The limit states of one survey, one line, every float as its bits.
fn dump_line(arch: &Arch, mu: f64, s: &Settings) -> String {
    let Ok(sv) = survey(arch, mu, s) else {
        return "error".into();
    };
    match &sv.states {
        Ok(ls) => {
            let mut out = format!("{} {} {} |", ls.method, ls.events, ls.mechanism_at_eta_s);
            for st in &ls.above {
                out += &format!(" {:x}", st.t.to_bits());
                for v in st.x {
                    out += &format!(",{:x}", v.to_bits());
                }
                for c in &st.pattern {
                    out += &format!(",{:?}@{:x}", c.kind, c.beta.to_bits());
                }
            }
            out
        }
        Err(e) => format!("undecided: {e}"),
    }
}

fn dump() {
    let s = Settings::default();
    let mut rng = Rng(12345);
    let mut next = move || rng.next();
    for k in 0..400 {
        let (a, b) = (-1.2 + 2.6 * next(), -1.2 + 2.6 * next());
        let symmetric = k % 2 == 0;
        let blocks = [0, 3, 5, 8, 12, 20, 40, 100, 300][k % 9];
        let mu = 0.3 + 2.0 * next();
        let arch = if symmetric {
            Arch::symmetric(a, WeightModel::Centreline)
        } else {
            Arch::new(a.min(b), a.max(b) + 0.5, WeightModel::Centreline)
        };
        let Ok(mut arch) = arch else { continue };
        if blocks > 0 {
            match arch.with_blocks(blocks) {
                Ok(b) => arch = b,
                Err(_) => continue,
            }
        }
        println!("{k} {blocks} {}", dump_line(&arch, mu, &s));
    }
}

fn main() {
    if std::env::args().any(|a| a == "--dump") {
        return dump();
    }
    let args: Vec<String> = std::env::args().collect();
    if let Some(k) = args.iter().position(|a| a == "--one") {
        // one survey, for a profiler: --one N ALPHA MU
        let n: usize = args[k + 1].parse().expect("N");
        let alpha: f64 = args[k + 2].parse().expect("ALPHA");
        let mu: f64 = args[k + 3].parse().expect("MU");
        let s = Settings {
            ridge_max_joints: 1_000_000,
            ..Settings::default()
        };
        let arch = Arch::symmetric(alpha, WeightModel::Centreline)
            .unwrap()
            .with_blocks(n)
            .unwrap();
        let t = Instant::now();
        let sv = survey(&arch, mu, &s).unwrap();
        println!(
            "{:.1} ms, unique {:?}",
            1e3 * t.elapsed().as_secs_f64(),
            sv.unique()
        );
        if let Err(e) = &sv.states {
            println!("not searched: {e}");
        }
        return;
    }
    let s = Settings {
        ridge_max_joints: 1_000_000,
        ..Settings::default()
    };
    println!("| arch | mu | voussoirs | survey [ms] | limit states | method, events |");
    println!("|---|---:|---:|---:|---:|---|");
    for (name, alpha, mu) in [("semicircle", 0.0, 0.6), ("alpha = 1", 1.0, 2.0)] {
        for n in [100, 300, 1000, 3000, 10000] {
            let arch = Arch::symmetric(alpha, WeightModel::Centreline)
                .unwrap()
                .with_blocks(n)
                .unwrap();
            let reps = if n >= 3000 { 1 } else { 3 };
            let t = median(|| drop(survey(&arch, mu, &s).unwrap()), reps);
            let sv = survey(&arch, mu, &s).unwrap();
            let (found, how) = summary::found(&sv);
            println!("| {name} | {mu} | {n} | {:.1} | {found} | {how} |", 1e3 * t);
        }
    }
}
