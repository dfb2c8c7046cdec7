//! How often `limit_states::survey` decides the question of issue 10 ("every limit state
//! with η in [η_s, 2), decided") on random arches, in one run.
//!
//! Run: `cargo run --release --example decided_sweep -- [--count N] [--seed S]`
//! (defaults: 300 arches, seed 1).
//!
//! Arches are drawn (seeded xorshift64*, deterministic) round-robin from four strata:
//! continuous symmetric (α ∈ [−1.3, 1.15]); continuous unsymmetric (β_R ∈ [−0.6, 0.6],
//! π − β_L ∈ [−0.6, 0.6]); discrete with 3..=12 voussoirs at random sorted joint angles
//! (`with_joints`; no voussoir narrower than 5 % of the mean width); discrete with 3..=12
//! equal voussoirs (`with_blocks`). A discrete arch has symmetric or unsymmetric springings
//! (half each, same ranges). Weight model: centreline or centroid (half each). Friction:
//! μ = ∞ (15 %), μ_ms (1 + δ) with δ log-uniform in [1e-4, 1e-2] (42.5 %), or uniform in
//! (μ_ms, 3] (42.5 %), μ_ms from `least_friction`.
//!
//! Each survey (default settings) is classified as `json::solve` and the CLI do:
//! * decided: `states` is `Ok` and the outcome is `Limit` (η_s with a limit state found by
//!   `solve`) — or `Unresolved` with a least state (`solve` found η_s but no limit state;
//!   the search above η_s completed): the CLI reports both as status "ok". The second kind
//!   is counted apart ("gap-decided") so the stricter reading (only `Limit` counts) can be
//!   read off too;
//! * unresolved: `states` is `Err` (outcome `Limit` or `Unresolved`);
//! * no_equilibrium, no_collapse: the outcome (the latter split by whether the sweep from
//!   η = 0 completed).

use arch_enum::limit_states::{survey, Survey};
use arch_enum::{least_friction, Arch, JointLayout, Outcome, Settings, WeightModel};
use std::f64::consts::PI;
use std::time::Instant;

/// xorshift64* (Vigna): small, seeded, deterministic.
struct Rng(u64);

impl Rng {
    fn new(seed: u64) -> Rng {
        // splitmix64 of the seed, never zero
        let mut z = seed.wrapping_add(0x9E37_79B9_7F4A_7C15);
        z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
        Rng((z ^ (z >> 31)) | 1)
    }
    fn next_u64(&mut self) -> u64 {
        let mut x = self.0;
        x ^= x >> 12;
        x ^= x << 25;
        x ^= x >> 27;
        self.0 = x;
        x.wrapping_mul(0x2545_F491_4F6C_DD1D)
    }
    /// Uniform in [0, 1).
    fn unit(&mut self) -> f64 {
        (self.next_u64() >> 11) as f64 / (1u64 << 53) as f64
    }
    fn range(&mut self, lo: f64, hi: f64) -> f64 {
        lo + (hi - lo) * self.unit()
    }
    /// Uniform in lo..=hi.
    fn int(&mut self, lo: usize, hi: usize) -> usize {
        lo + (self.next_u64() % (hi - lo + 1) as u64) as usize
    }
}

const STRATA: [&str; 4] = [
    "continuous symmetric",
    "continuous unsymmetric",
    "discrete, random joints",
    "discrete, equal blocks",
];
const MU_CLASSES: [&str; 3] = ["mu = inf", "mu just above mu_ms", "mu in (mu_ms, 3]"];

#[derive(Clone, Copy, PartialEq)]
enum Class {
    Decided,
    /// `solve` Unresolved (with a least state), the search above η_s complete.
    GapDecided,
    Unresolved,
    NoEquilibrium,
    NoCollapse {
        searched: bool,
    },
}

struct Case {
    index: usize,
    stratum: usize,
    mu_class: usize,
    arch: Arch,
    /// `Some(n)` for `with_blocks(n)`.
    blocks: Option<usize>,
    mu: f64,
    mu_ms: Option<f64>,
    note: Option<String>,
    class: Class,
    unique: Option<bool>,
    count: usize,
    mechanism_at_eta_s: bool,
    attained: bool,
    reason: Option<String>,
    ms: f64,
}

/// One `arch-enum solve` line reproducing the case.
fn cli_line(c: &Case) -> String {
    let a = &c.arch;
    let mut s = format!(
        "arch-enum solve --beta-right {} --beta-left {}",
        a.beta_right(),
        a.beta_left()
    );
    match (c.blocks, a.layout()) {
        (Some(n), _) => s += &format!(" --blocks {n}"),
        (None, JointLayout::Discrete(j)) => {
            let inner: Vec<String> = j[1..j.len() - 1].iter().map(|b| b.to_string()).collect();
            s += &format!(" --joints {}", inner.join(","));
        }
        (None, JointLayout::Continuous) => {}
    }
    if a.weight() == WeightModel::Centroid {
        s += " --weight centroid";
    }
    s + &format!(
        " --mu {}",
        if c.mu.is_finite() {
            c.mu.to_string()
        } else {
            "inf".into()
        }
    )
}

/// Springings: symmetric (α) or unsymmetric.
fn springings(rng: &mut Rng, symmetric: bool) -> (f64, f64) {
    if symmetric {
        let alpha = rng.range(-1.3, 1.15);
        (-alpha + 0.0, PI + alpha)
    } else {
        let r = rng.range(-0.6, 0.6);
        let l = PI - rng.range(-0.6, 0.6);
        (r, l)
    }
}

/// The arch of case `i` (stratum `i mod 4`) and, for equal blocks, their number.
fn draw_arch(rng: &mut Rng, stratum: usize) -> (Arch, Option<usize>) {
    let weight = if rng.unit() < 0.5 {
        WeightModel::Centreline
    } else {
        WeightModel::Centroid
    };
    let symmetric = match stratum {
        0 => true,
        1 => false,
        _ => rng.unit() < 0.5,
    };
    let (r, l) = springings(rng, symmetric);
    let arch = Arch::new(r, l, weight).expect("valid springings");
    match stratum {
        2 => {
            let n = rng.int(3, 12);
            let min_gap = 0.05 * (l - r) / n as f64;
            loop {
                let mut j: Vec<f64> = (0..n - 1).map(|_| rng.range(r, l)).collect();
                j.sort_by(f64::total_cmp);
                let mut all = vec![r];
                all.extend(&j);
                all.push(l);
                if all.windows(2).all(|w| w[1] - w[0] >= min_gap) {
                    return (arch.with_joints(&j).expect("valid joints"), None);
                }
            }
        }
        3 => {
            let n = rng.int(3, 12);
            (arch.with_blocks(n).expect("valid blocks"), Some(n))
        }
        _ => (arch, None),
    }
}

fn classify(sv: &Survey) -> Class {
    match (&sv.solution.outcome, &sv.states) {
        (Outcome::NoEquilibrium { .. }, _) => Class::NoEquilibrium,
        (Outcome::NoCollapse { .. }, s) => Class::NoCollapse {
            searched: s.is_ok(),
        },
        (Outcome::Limit(_), Ok(_)) => Class::Decided,
        (Outcome::Unresolved { .. }, Ok(_)) => Class::GapDecided,
        (_, Err(_)) => Class::Unresolved,
    }
}

fn reason_of(sv: &Survey) -> Option<String> {
    let solve_reason = match &sv.solution.outcome {
        Outcome::Unresolved { reason, .. }
        | Outcome::NoEquilibrium { reason, .. }
        | Outcome::NoCollapse { reason } => Some(format!("solve: {reason}")),
        Outcome::Limit(_) => None,
    };
    let search_reason = sv.states.as_ref().err().map(|e| format!("search: {e}"));
    match (solve_reason, search_reason) {
        (None, None) => None,
        (Some(a), None) | (None, Some(a)) => Some(a),
        (Some(a), Some(b)) => Some(format!("{a}; {b}")),
    }
}

fn run_case(rng: &mut Rng, index: usize, settings: &Settings) -> Case {
    let stratum = index % STRATA.len();
    let (arch, blocks) = draw_arch(rng, stratum);
    let (u_class, u_mu) = (rng.unit(), rng.unit());
    let mut note = None;
    let mu_ms = match least_friction(&arch, settings) {
        Ok(m) => m,
        Err(e) => {
            note = Some(format!("least_friction failed: {e}"));
            None
        }
    };
    let mut mu_class = if u_class < 0.15 {
        0
    } else if u_class < 0.575 {
        1
    } else {
        2
    };
    let mu = match (mu_class, mu_ms) {
        (0, _) => f64::INFINITY,
        (_, None) => {
            note.get_or_insert_with(|| "no finite mu_ms: mu = inf".into());
            mu_class = 0;
            f64::INFINITY
        }
        (1, Some(m)) => {
            let delta = 10f64.powf(-4.0 + 2.0 * u_mu);
            if m > 0.0 {
                m * (1.0 + delta)
            } else {
                note = Some("mu_ms = 0: mu = delta".into());
                delta
            }
        }
        (_, Some(m)) => {
            let hi = if m < 3.0 {
                3.0
            } else {
                note = Some("mu_ms >= 3: mu in (mu_ms, 2 mu_ms]".into());
                2.0 * m
            };
            // (mu_ms, hi]: 1 - u in (0, 1]
            m + (hi - m) * (1.0 - u_mu)
        }
    };
    let t = Instant::now();
    let sv = survey(&arch, mu, settings).expect("valid input");
    let ms = 1e3 * t.elapsed().as_secs_f64();
    let class = classify(&sv);
    let (count, mechanism_at_eta_s, attained) = match &sv.states {
        Ok(s) => (
            usize::from(s.mechanism_at_eta_s) + s.above.len(),
            s.mechanism_at_eta_s,
            s.attained,
        ),
        Err(_) => (0, false, false),
    };
    Case {
        index,
        stratum,
        mu_class,
        arch,
        blocks,
        mu,
        mu_ms,
        note,
        class,
        unique: sv.unique(),
        count,
        mechanism_at_eta_s,
        attained,
        reason: reason_of(&sv),
        ms,
    }
}

fn median(v: &mut [f64]) -> f64 {
    if v.is_empty() {
        return f64::NAN;
    }
    v.sort_by(f64::total_cmp);
    let n = v.len();
    if n % 2 == 1 {
        v[n / 2]
    } else {
        0.5 * (v[n / 2 - 1] + v[n / 2])
    }
}

fn header() {
    println!(
        "| group | count | decided | gap-decided | unresolved | non-unique (none / several) | no mechanism at eta_s | not attained | no_equilibrium | no_collapse (searched) | median ms | max ms |"
    );
    println!("|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|");
}

fn row(name: &str, cases: &[&Case]) {
    let n = |f: &dyn Fn(&Case) -> bool| cases.iter().filter(|c| f(c)).count();
    let decided = |c: &Case| matches!(c.class, Class::Decided | Class::GapDecided);
    let mut times: Vec<f64> = cases.iter().map(|c| c.ms).collect();
    let max = times.iter().copied().fold(0.0, f64::max);
    println!(
        "| {name} | {} | {} | {} | {} | {} ({} / {}) | {} | {} | {} | {} ({}) | {:.1} | {:.0} |",
        cases.len(),
        n(&|c| c.class == Class::Decided),
        n(&|c| c.class == Class::GapDecided),
        n(&|c| c.class == Class::Unresolved),
        n(&|c| decided(c) && c.unique == Some(false)),
        n(&|c| decided(c) && c.count == 0),
        n(&|c| decided(c) && c.count >= 2),
        n(&|c| decided(c) && !c.mechanism_at_eta_s),
        n(&|c| decided(c) && !c.attained),
        n(&|c| c.class == Class::NoEquilibrium),
        n(&|c| matches!(c.class, Class::NoCollapse { .. })),
        n(&|c| c.class == Class::NoCollapse { searched: true }),
        median(&mut times),
        max,
    );
}

fn main() {
    let mut count = 300usize;
    let mut seed = 1u64;
    let args: Vec<String> = std::env::args().skip(1).collect();
    let mut it = args.iter();
    while let Some(a) = it.next() {
        let v = it.next().unwrap_or_else(|| panic!("{a} needs a value"));
        match a.as_str() {
            "--count" => count = v.parse().expect("--count N"),
            "--seed" => seed = v.parse().expect("--seed S"),
            _ => panic!("unknown argument {a} (use --count N, --seed S)"),
        }
    }
    let settings = Settings::default();
    let mut rng = Rng::new(seed);
    let start = Instant::now();
    let mut cases = Vec::with_capacity(count);
    for i in 0..count {
        cases.push(run_case(&mut rng, i, &settings));
        if (i + 1) % 50 == 0 {
            eprintln!(
                "{} / {count} surveys, {:.0} s",
                i + 1,
                start.elapsed().as_secs_f64()
            );
        }
    }
    let total = start.elapsed().as_secs_f64();

    println!("# decided_sweep: --count {count} --seed {seed} ({total:.0} s in all)\n");
    println!(
        "decided: states Ok and solve found a limit state; gap-decided: states Ok, solve \
         Unresolved with a least state (the CLI's status \"ok\" for both); unresolved: states \
         Err. non-unique, no mechanism, not attained: among the decided and gap-decided. \
         Times: the survey alone (not least_friction).\n"
    );
    let mut notes: Vec<&str> = cases.iter().filter_map(|c| c.note.as_deref()).collect();
    notes.sort_unstable();
    notes.dedup();
    println!(
        "friction draws adjusted: {} ({})\n",
        cases.iter().filter(|c| c.note.is_some()).count(),
        if notes.is_empty() {
            "none".to_string()
        } else {
            notes.join("; ")
        }
    );
    println!("## By stratum\n");
    header();
    for (s, name) in STRATA.iter().enumerate() {
        row(
            name,
            &cases.iter().filter(|c| c.stratum == s).collect::<Vec<_>>(),
        );
    }
    row("**all**", &cases.iter().collect::<Vec<_>>());
    println!("\n## By friction class\n");
    header();
    for (m, name) in MU_CLASSES.iter().enumerate() {
        row(
            name,
            &cases.iter().filter(|c| c.mu_class == m).collect::<Vec<_>>(),
        );
    }
    println!("\n## By weight model\n");
    header();
    for w in [WeightModel::Centreline, WeightModel::Centroid] {
        row(
            w.name(),
            &cases
                .iter()
                .filter(|c| c.arch.weight() == w)
                .collect::<Vec<_>>(),
        );
    }

    let describe = |c: &Case| {
        format!(
            "#{} [{}, {}] mu_ms = {}{}",
            c.index,
            STRATA[c.stratum],
            MU_CLASSES[c.mu_class],
            c.mu_ms.map_or("none".into(), |m| m.to_string()),
            c.note.as_ref().map_or(String::new(), |n| format!(" ({n})"))
        )
    };
    let unresolved: Vec<&Case> = cases
        .iter()
        .filter(|c| c.class == Class::Unresolved)
        .collect();
    println!("\n## Unresolved ({})\n", unresolved.len());
    for c in &unresolved {
        println!("- {}, {:.0} ms", describe(c), c.ms);
        println!("  `{}`", cli_line(c));
        println!("  reason: {}", c.reason.as_deref().unwrap_or("?"));
    }
    let odd: Vec<&Case> = cases
        .iter()
        .filter(|c| {
            matches!(
                c.class,
                Class::NoEquilibrium | Class::NoCollapse { searched: false } | Class::GapDecided
            )
        })
        .collect();
    println!(
        "\n## Gap-decided, no_equilibrium, no_collapse without a search ({})\n",
        odd.len()
    );
    for c in &odd {
        let what = match c.class {
            Class::GapDecided => format!("gap-decided, {} limit state(s)", c.count),
            Class::NoEquilibrium => "no_equilibrium".into(),
            _ => "no_collapse, search not completed".into(),
        };
        println!("- {} — {what}, {:.0} ms", describe(c), c.ms);
        println!("  `{}`", cli_line(c));
        println!("  {}", c.reason.as_deref().unwrap_or(""));
    }
    let standing: Vec<&Case> = cases
        .iter()
        .filter(|c| c.class == (Class::NoCollapse { searched: true }) && c.count > 0)
        .collect();
    println!(
        "\n## no_collapse with limit states above eta = 0 ({})\n",
        standing.len()
    );
    for c in &standing {
        println!("- {}: {} limit state(s)", describe(c), c.count);
        println!("  `{}`", cli_line(c));
    }
    let nonunique: Vec<&Case> = cases
        .iter()
        .filter(|c| {
            matches!(c.class, Class::Decided | Class::GapDecided) && c.unique == Some(false)
        })
        .collect();
    println!(
        "\n## Non-unique among the decided ({}, first 20)\n",
        nonunique.len()
    );
    for c in nonunique.iter().take(20) {
        println!(
            "- {}: {} limit state(s), mechanism at eta_s: {}, attained: {}",
            describe(c),
            c.count,
            c.mechanism_at_eta_s,
            c.attained
        );
        println!("  `{}`", cli_line(c));
    }
    let mut slow: Vec<&Case> = cases.iter().collect();
    slow.sort_by(|p, q| q.ms.total_cmp(&p.ms));
    println!("\n## Slowest 5\n");
    for c in slow.iter().take(5) {
        println!("- {:.0} ms: {}", c.ms, describe(c));
        println!("  `{}`", cli_line(c));
    }
}
