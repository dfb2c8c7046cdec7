//! Wall time of one exact `solve`, by workload, and of a whole `modes` trace.
//! Run: `cargo bench --bench solve`.

use arch_enum::{solve, Arch, Settings, WeightModel};
use criterion::{criterion_group, criterion_main, Criterion};
use std::hint::black_box;

fn bench_solve(c: &mut Criterion) {
    let s = Settings::default();
    let cases: Vec<(&str, Arch, f64)> = vec![
        (
            "semicircle_mu_inf",
            Arch::symmetric(0.0, WeightModel::Centreline).unwrap(),
            f64::INFINITY,
        ),
        (
            "semicircle_mu_0.35_mixed",
            Arch::symmetric(0.0, WeightModel::Centreline).unwrap(),
            0.35,
        ),
        (
            "alpha1_mu_2_mixed",
            Arch::symmetric(1.0, WeightModel::Centreline).unwrap(),
            2.0,
        ),
        (
            "alpha1.15_mu_inf_overturning",
            Arch::symmetric(1.15, WeightModel::Centreline).unwrap(),
            f64::INFINITY,
        ),
        (
            "shallow_alpha-1.2_mu_inf",
            Arch::symmetric(-1.2, WeightModel::Centreline).unwrap(),
            f64::INFINITY,
        ),
        (
            "discrete_100_blocks_mu_0.35",
            Arch::symmetric(0.0, WeightModel::Centreline)
                .unwrap()
                .with_blocks(100)
                .unwrap(),
            0.35,
        ),
        (
            "below_mu_ms_no_equilibrium",
            Arch::symmetric(0.0, WeightModel::Centreline).unwrap(),
            0.3,
        ),
    ];
    let mut g = c.benchmark_group("solve");
    g.sample_size(20);
    for (name, arch, mu) in &cases {
        g.bench_function(*name, |b| {
            b.iter(|| solve(black_box(arch), black_box(*mu), &s).unwrap())
        });
    }
    g.finish();
}

fn bench_modes(c: &mut Criterion) {
    let s = Settings::default();
    let mut g = c.benchmark_group("modes");
    g.sample_size(10);
    for alpha in [0.0, 1.0, 1.15] {
        let arch = Arch::symmetric(alpha, WeightModel::Centreline).unwrap();
        g.bench_function(format!("alpha_{alpha}"), |b| {
            b.iter(|| arch_enum::limit_curve::trace(black_box(&arch), &s))
        });
    }
    g.finish();
}

fn bench_certify(c: &mut Criterion) {
    let s = Settings::default();
    let arch = Arch::symmetric(0.0, WeightModel::Centreline).unwrap();
    let cert = arch_enum::certificate::certify(&arch, 0.35, 1e-12, &s).unwrap();
    let mut g = c.benchmark_group("certificate");
    g.sample_size(20);
    g.bench_function("certify_semicircle_mu_0.35", |b| {
        b.iter(|| arch_enum::certificate::certify(black_box(&arch), 0.35, 1e-12, &s).unwrap())
    });
    g.bench_function("verify_semicircle_mu_0.35", |b| {
        b.iter(|| arch_enum::certificate::verify(black_box(&cert)).unwrap())
    });
    g.finish();
}

criterion_group!(benches, bench_solve, bench_modes, bench_certify);
criterion_main!(benches);
