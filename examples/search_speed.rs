//! Speed of the limit-state search against the thickness solve alone, in one run: for each
//! workload the median wall time of `solve` (η_s and the least limit state) and of
//! `survey` (`solve` plus every limit state with η in [η_s, 2)), their ratio, and what
//! the search found. Run: `cargo run --release --example search_speed`.

use arch_enum::limit_states::survey;
use arch_enum::{solve, Arch, Settings, WeightModel};

#[path = "common/found.rs"]
mod summary;
#[path = "common/timing.rs"]
mod timing;
use timing::median;

fn main() {
    let s = Settings::default();
    let sym = |a: f64| Arch::symmetric(a, WeightModel::Centreline).unwrap();
    let cases: Vec<(&str, Arch, f64)> = vec![
        ("semicircle, mu = inf", sym(0.0), f64::INFINITY),
        ("semicircle, mu = 0.35", sym(0.0), 0.35),
        ("alpha = 1, mu = 2", sym(1.0), 2.0),
        ("alpha = 1.15, mu = inf", sym(1.15), f64::INFINITY),
        ("alpha = -1.2, mu = inf", sym(-1.2), f64::INFINITY),
        (
            "alpha = 0.8, mu = 1.154 (non-unique)",
            sym(0.8),
            1.1540692474221415,
        ),
        (
            "unsymmetric -0.67/2.72, mu = 0.96",
            Arch::new(-0.67, 2.72, WeightModel::Centreline).unwrap(),
            0.96,
        ),
        (
            "100 blocks, mu = 0.35",
            sym(0.0).with_blocks(100).unwrap(),
            0.35,
        ),
    ];
    println!(
        "| workload | solve [ms] | solve + search [ms] | ratio | limit states | method, events |"
    );
    println!("|---|---:|---:|---:|---:|---|");
    for (name, arch, mu) in cases {
        let reps = 7;
        let t_solve = median(|| drop(solve(&arch, mu, &s).unwrap()), reps);
        let t_all = median(|| drop(survey(&arch, mu, &s).unwrap()), reps);
        let sv = survey(&arch, mu, &s).unwrap();
        let (found, how) = summary::found(&sv);
        println!(
            "| {name} | {:.3} | {:.3} | {:.0} | {found} | {how} |",
            1e3 * t_solve,
            1e3 * t_all,
            t_all / t_solve
        );
    }
}
