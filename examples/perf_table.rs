//! The speed table of issue 12, measured in one run: median library time of the default
//! paths (`solve` = the exact η* plus the complete limit-state search, as `arch-enum solve`
//! runs it; `modes` = the traced limit curve, as `arch-enum modes` runs it: on every core
//! the machine offers, with `--json` a key `threads` says how many), and the CPU time
//! of a one-shot `arch-enum solve` process beside a hello-world process.
//!
//! Run: `cargo run --release --example perf_table [-- --json] [--reps N]`. The process rows
//! need the release binaries `arch-enum` and the `hello` example next to this one (cargo
//! builds both with `cargo build --release --bin arch-enum --example hello`); without them
//! those two keys are null. Wall times on a shared machine are noisy: compare ratios taken
//! in one run.

use arch_enum::limit_curve::trace_parallel;
use arch_enum::limit_states::survey;
use arch_enum::threads;
use arch_enum::{Arch, Settings, WeightModel};
use std::path::{Path, PathBuf};
use std::process::Command;
use std::time::Instant;

/// Median of `reps` timings of `f`, in seconds.
fn median<F: FnMut()>(mut f: F, reps: usize) -> f64 {
    let mut t: Vec<f64> = (0..reps.max(1))
        .map(|_| {
            let s = Instant::now();
            f();
            s.elapsed().as_secs_f64()
        })
        .collect();
    t.sort_by(f64::total_cmp);
    t[t.len() / 2]
}

/// CPU time (user + system) of the finished children of this process, in seconds, from
/// /proc/self/stat (cutime, cstime: fields 16 and 17, in clock ticks of 1/100 s).
fn children_cpu() -> Option<f64> {
    let stat = std::fs::read_to_string("/proc/self/stat").ok()?;
    let after = &stat[stat.rfind(')')? + 2..];
    let f: Vec<&str> = after.split_whitespace().collect();
    // after the command name, fields start at 3 (state): cutime is field 16 → index 13
    let cu: f64 = f.get(13)?.parse().ok()?;
    let cs: f64 = f.get(14)?.parse().ok()?;
    Some((cu + cs) / 100.0)
}

/// Mean CPU time of one run of `program args`, over `runs` runs, in ms.
fn process_cpu_ms(program: &Path, args: &[&str], runs: usize) -> Option<f64> {
    let before = children_cpu()?;
    for _ in 0..runs {
        let out = Command::new(program).args(args).output().ok()?;
        if !out.status.success() {
            return None;
        }
    }
    Some((children_cpu()? - before) * 1e3 / runs as f64)
}

/// The release binaries beside this example: target/release/{arch-enum, examples/hello}.
fn binaries() -> (PathBuf, PathBuf) {
    let me = std::env::current_exe().expect("the example's path");
    let examples = me.parent().expect("examples dir").to_path_buf();
    let release = examples.parent().expect("release dir").to_path_buf();
    (release.join("arch-enum"), examples.join("hello"))
}

fn main() {
    let args: Vec<String> = std::env::args().collect();
    let json = args.iter().any(|a| a == "--json");
    let reps: usize = args
        .iter()
        .position(|a| a == "--reps")
        .and_then(|i| args.get(i + 1))
        .and_then(|v| v.parse().ok())
        .unwrap_or(9);
    let s = Settings::default();
    let sym = |a: f64| Arch::symmetric(a, WeightModel::Centreline).expect("arch");
    let solve_us = |arch: &Arch, mu: f64| {
        1e6 * median(|| drop(survey(arch, mu, &s).expect("valid input")), reps)
    };
    let cores = threads::available();
    let modes_ms =
        |arch: &Arch| 1e3 * median(|| drop(trace_parallel(arch, &s, cores)), reps.min(5));
    let b20 = Arch::symmetric(0.0, WeightModel::Centroid)
        .and_then(|a| a.with_blocks(20))
        .expect("arch");
    let rows: Vec<(&str, Option<f64>)> = vec![
        ("solve_a0_mu035_us", Some(solve_us(&sym(0.0), 0.35))),
        ("solve_a1_mu2_us", Some(solve_us(&sym(1.0), 2.0))),
        ("solve_a0_inf_us", Some(solve_us(&sym(0.0), f64::INFINITY))),
        ("solve_b20_centroid_us", Some(solve_us(&b20, 0.6))),
        ("modes_a0_ms", Some(modes_ms(&sym(0.0)))),
        ("modes_a1_ms", Some(modes_ms(&sym(1.0)))),
        (
            "solve_b1e4_ms",
            Some(solve_us(&sym(0.0).with_blocks(10_000).expect("arch"), 0.35) / 1e3),
        ),
        (
            "solve_b1e5_ms",
            Some(solve_us(&sym(0.0).with_blocks(100_000).expect("arch"), 0.35) / 1e3),
        ),
        ("process_solve_ms", {
            let (bin, _) = binaries();
            process_cpu_ms(
                &bin,
                &["solve", "--alpha", "0", "--mu", "0.35", "--json"],
                50,
            )
        }),
        ("process_hello_ms", {
            let (_, hello) = binaries();
            process_cpu_ms(&hello, &[], 50)
        }),
        ("threads", Some(cores as f64)),
    ];
    if json {
        let doc: serde_json::Map<String, serde_json::Value> = rows
            .iter()
            .map(|(k, v)| ((*k).to_string(), serde_json::json!(v)))
            .collect();
        println!(
            "{}",
            serde_json::to_string_pretty(&doc).expect("a JSON document")
        );
    } else {
        println!("| quantity | median |");
        println!("|---|---:|");
        for (k, v) in rows {
            println!(
                "| {k} | {} |",
                v.map_or("n/a (binary missing)".to_string(), |v| format!("{v:.3}"))
            );
        }
    }
}
