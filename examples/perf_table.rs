//! The speed table, measured in one run: median library time of the default paths (`solve` =
//! the exact η* plus the complete limit-state search, as `arch-enum solve` runs it; `modes` =
//! the traced limit curve, as `arch-enum modes` runs it: on every core the machine offers,
//! with `--json` a key `threads` says how many), the complete search at 10³ and 10⁴
//! voussoirs, a live load on 10⁴ voussoirs, η*(μ) on a 200 × 200 (α, μ) grid, and the CPU
//! time of a one-shot `arch-enum solve` process beside a hello-world process.
//!
//! A time is printed only for a complete answer: where the search stops at a budget of this
//! version (`unique` not decided, a load `unresolved`) the key is null and the text row says
//! why, so that no figure stands for work not done.
//!
//! Run: `cargo run --release --example perf_table [-- --json] [--reps N]`. The process rows
//! need the release binaries `arch-enum` and the `hello` example next to this one (cargo
//! builds both with `cargo build --release --bin arch-enum --example hello`); without them
//! those two keys are null. Wall times on a shared machine are noisy: compare ratios taken
//! in one run.

use arch_enum::limit_curve::{mu_grid, sample, trace_parallel};
use arch_enum::limit_states::survey;
use arch_enum::load::LiveLoad;
use arch_enum::multiplier::{self, LoadOutcome};
use arch_enum::threads;
use arch_enum::{least_friction, Arch, Settings, WeightModel};
use std::path::{Path, PathBuf};
use std::process::Command;
use std::time::Instant;

#[path = "common/timing.rs"]
mod timing;
use timing::median;

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

/// A row of the table: a median, or why there is none.
type Row = (&'static str, Result<f64, String>);

/// Median ms of the complete survey (η* and every limit state) of `arch` at `mu`, or why the
/// search is not complete.
fn search_ms(arch: &Arch, mu: f64, s: &Settings, reps: usize) -> Result<f64, String> {
    let sv = survey(arch, mu, s).map_err(|e| e.to_string())?;
    if let Err(e) = &sv.states {
        return Err(format!("search not complete: {e}"));
    }
    Ok(1e3 * median(|| drop(survey(arch, mu, s)), reps))
}

/// Median ms of a point load at β = π/3 on a semicircle of 10⁴ voussoirs (η = 0.2, μ = 0.6),
/// or why it is not answered.
fn load_b1e4_ms(s: &Settings, reps: usize) -> Result<f64, String> {
    let arch = Arch::symmetric(0.0, WeightModel::Centreline)
        .and_then(|a| a.with_blocks(10_000))
        .map_err(|e| e.to_string())?;
    let load = LiveLoad::Point {
        beta: std::f64::consts::FRAC_PI_3,
    };
    let run = || multiplier::survey(&arch, 0.2, 0.6, &load, s);
    match run().map_err(|e| e.to_string())? {
        Ok(LoadOutcome::Limits(_)) => Ok(1e3 * median(|| drop(run()), reps)),
        Ok(other) => Err(format!("unexpected outcome {other:?}")),
        Err(e) => Err(format!("unresolved: {e}")),
    }
}

/// Seconds for η*(μ) on a 200 × 200 grid: 200 openings α in [−1.2, 1.2], at each 200 μ from
/// μ_ms (1 + 10⁻⁶) to 10 μ_ms (geometric, as `curve`'s default), on `cores` threads.
fn grid_s(s: &Settings, cores: usize) -> Result<f64, String> {
    let start = Instant::now();
    for k in 0..200 {
        let alpha = -1.2 + 2.4 * k as f64 / 199.0;
        let arch = Arch::symmetric(alpha, WeightModel::Centreline).map_err(|e| e.to_string())?;
        let ms = least_friction(&arch, s)
            .map_err(|e| e.to_string())?
            .ok_or("no mu_ms")?;
        let lo = ms * (1.0 + 1e-6);
        let grid = mu_grid(lo, 10.0 * lo, 200).map_err(|e| e.to_string())?;
        sample(&arch, &grid, s, cores, &|_, _| {}).map_err(|e| e.to_string())?;
    }
    Ok(start.elapsed().as_secs_f64())
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
    let b20 = |w| {
        Arch::symmetric(0.0, w)
            .and_then(|a| a.with_blocks(20))
            .expect("arch")
    };
    let blocks = |n| sym(0.0).with_blocks(n).expect("arch");
    let (bin, hello) = binaries();
    let missing = || "binary missing".to_string();
    let rows: Vec<Row> = vec![
        ("solve_a0_mu035_us", Ok(solve_us(&sym(0.0), 0.35))),
        ("solve_a1_mu2_us", Ok(solve_us(&sym(1.0), 2.0))),
        ("solve_a0_inf_us", Ok(solve_us(&sym(0.0), f64::INFINITY))),
        (
            "solve_b20_centroid_us",
            Ok(solve_us(&b20(WeightModel::Centroid), 0.6)),
        ),
        ("modes_a0_ms", Ok(modes_ms(&sym(0.0)))),
        ("modes_a1_ms", Ok(modes_ms(&sym(1.0)))),
        (
            "modes_b20_centroid_ms",
            Ok(modes_ms(&b20(WeightModel::Centroid))),
        ),
        ("solve_b1e4_ms", Ok(solve_us(&blocks(10_000), 0.35) / 1e3)),
        ("solve_b1e5_ms", Ok(solve_us(&blocks(100_000), 0.35) / 1e3)),
        (
            "solve_b1e3_search_ms",
            search_ms(&blocks(1_000), 0.6, &s, reps.min(5)),
        ),
        (
            "solve_b1e4_search_ms",
            search_ms(&blocks(10_000), 0.6, &s, reps.min(3)),
        ),
        ("load_b1e4_ms", load_b1e4_ms(&s, reps.min(3))),
        ("grid_200x200_s", grid_s(&s, cores)),
        (
            "process_solve_ms",
            process_cpu_ms(
                &bin,
                &["solve", "--alpha", "0", "--mu", "0.35", "--json"],
                50,
            )
            .ok_or_else(missing),
        ),
        (
            "process_hello_ms",
            process_cpu_ms(&hello, &[], 50).ok_or_else(missing),
        ),
        ("threads", Ok(cores as f64)),
    ];
    if json {
        let doc: serde_json::Map<String, serde_json::Value> = rows
            .iter()
            .map(|(k, v)| ((*k).to_string(), serde_json::json!(v.as_ref().ok())))
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
                v.map_or_else(|e| format!("n/a ({e})"), |v| format!("{v:.3}"))
            );
        }
    }
}
