//! A loop of one library call, for profilers: `perf record` shares and callgrind
//! instruction counts (stable where wall times on a shared machine are not). The speed
//! notes compare builds by `(I(2n) − I(n)) / n`, the instructions of one call without
//! start-up:
//!
//! `valgrind --tool=callgrind --callgrind-out-file=/dev/null target/release/examples/profile_loop solve 0 0.35 20`
//! (and again with 40), then the difference of the two "Collected" counts over 20.
//!
//! Usage: `profile_loop solve|limit|curve|modes|mix|chain ALPHA MU N [BLOCKS [centroid]]`: N times `survey`
//! (solve with the limit-state search) at friction MU (`inf` allowed), `limit::solve`
//! (η_s and the least limit state, no search), `sample` (`curve`: 400 friction
//! coefficients from MU to MU + 0.2 on one thread, as `curve` samples them) or `trace`
//! (modes, one thread), of the symmetric arch of opening ALPHA (radians, centreline weight, or
//! the true centroid's with `centroid`), continuous (BLOCKS 0) or of BLOCKS equal voussoirs; `mix` and `chain` (ALPHA and MU ignored) solve a fixed set of
//! arches N times and print their η (see `mix`). Prints the mean time per call on standard
//! error.

use arch_enum::limit::solve;
use arch_enum::limit_curve::{sample, trace};
use arch_enum::limit_states::survey;
use arch_enum::{Arch, Settings, WeightModel};

const CURVE_POINTS: usize = 400;

/// `limit::solve` on 40 symmetric arches (α from −0.6 to 1.2 (8 openings), μ from 1.02
/// μ_ms to 10 μ_ms (5 values)), or with `chain` the curve `sample` of 60 μ from 1.02 μ_ms
/// up on each opening; each η* and η_s printed in full to stdout (a change of the bracket
/// must not change them); `BLOCKS` > 0 uses that many voussoirs.
fn mix(s: &Settings, blocks: usize, chain: bool) {
    for k in 0..8 {
        let alpha = -0.6 + 1.8 * k as f64 / 7.0;
        let arch = Arch::symmetric(alpha, WeightModel::Centreline).expect("an opening");
        let arch = if blocks > 0 {
            arch.with_blocks(blocks).expect("a voussoir count")
        } else {
            arch
        };
        let ms = arch_enum::least_friction(&arch, s)
            .expect("valid input")
            .expect("a friction limit");
        if chain {
            let mus: Vec<f64> = (0..60)
                .map(|i| ms * (1.02f64).powf(1.0 + i as f64))
                .collect();
            for p in sample(&arch, &mus, s, 1, &|_, _| {}).expect("valid input") {
                match p.outcome {
                    arch_enum::limit::Outcome::Limit(ls) => {
                        println!("{alpha} {} {:e} {:e}", p.mu, ls.eta, ls.eta_static)
                    }
                    other => println!("{alpha} {} {other:?}", p.mu),
                }
            }
            continue;
        }
        for f in [1.02, 1.3, 2.0, 4.0, 10.0] {
            let sol = solve(&arch, ms * f, s).expect("valid input");
            match sol.outcome {
                arch_enum::limit::Outcome::Limit(ls) => {
                    println!("{alpha} {f} {:e} {:e}", ls.eta, ls.eta_static)
                }
                other => println!("{alpha} {f} {other:?}"),
            }
        }
    }
}

fn main() {
    let a: Vec<String> = std::env::args().collect();
    let usage =
        "usage: profile_loop solve|limit|curve|modes|mix|chain ALPHA MU N [BLOCKS [centroid]]";
    let arg = |i: usize| a.get(i).expect(usage).as_str();
    let what = arg(1);
    let alpha: f64 = arg(2).parse().expect(usage);
    let mu: f64 = arg(3).parse().expect(usage);
    let n: u32 = arg(4).parse().expect(usage);
    let blocks: usize = a.get(5).map_or(0, |b| b.parse().expect(usage));
    let weight = match a.get(6).map(String::as_str) {
        None => WeightModel::Centreline,
        Some("centroid") => WeightModel::Centroid,
        Some(_) => panic!("{usage}"),
    };
    let s = Settings::default();
    let arch = Arch::symmetric(alpha, weight).expect("an opening");
    let arch = if blocks > 0 {
        arch.with_blocks(blocks).expect("a voussoir count")
    } else {
        arch
    };
    // `curve`: one curve of CURVE_POINTS friction coefficients from MU to MU + 0.2
    let mus: Vec<f64> = (0..CURVE_POINTS)
        .map(|i| mu + 0.2 * i as f64 / (CURVE_POINTS - 1) as f64)
        .collect();
    let t = std::time::Instant::now();
    for _ in 0..n {
        match what {
            "solve" => drop(survey(&arch, mu, &s).expect("valid input")),
            "modes" => drop(trace(&arch, &s)),
            "limit" => drop(solve(&arch, mu, &s).expect("valid input")),
            "curve" => drop(sample(&arch, &mus, &s, 1, &|_, _| {}).expect("valid input")),
            "mix" => mix(&s, blocks, false),
            "chain" => mix(&s, blocks, true),
            _ => panic!("{usage}"),
        }
    }
    eprintln!("{:?} per call", t.elapsed() / n.max(1));
}
