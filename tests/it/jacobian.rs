//! The Newton/KKT Jacobian of a pattern's system (`refine::residual_and_jacobian_in`)
//! against central differences of its residual, on seeded random arches (both weight
//! models, symmetric and not), patterns (hinges and sliding, springing and free interior
//! joints) and points z, for every kind of unknowns: η (plain with 4–5 contacts,
//! KKT-completed with 1–3), μ (plain with 3–4, KKT with 1–2) and both η and μ (corners).
//!
//! The same for the load family (t = λ at a fixed η; horizontal and point loads, both sides
//! of a loaded section, KKT-completed for the largest λ).
//!
//! Tolerance: with steps h_j = 1e-5 (1 + |z_j|) the truncation error is
//! O(h²·|F'''|) ≈ 1e-9 and the rounding error O(ε |F| / h) ≈ 1e-10 here, so
//! |J_fd − J| ≤ 1e-6 (1 + |J|) entry by entry; a wrong term is O(1) larger.

use arch_enum::family::{self, Family, Tagged};
use arch_enum::load::{LiveLoad, Side};
use arch_enum::refine::{residual_and_jacobian_in, Objective, Unknowns};
use arch_enum::{Arch, Contact, ContactKind, Location, WeightModel};
use proptest::prelude::*;
use proptest::test_runner::RngSeed;

const TOL: f64 = 1e-6;

fn kind(i: usize) -> ContactKind {
    ContactKind::ALL[i % 4]
}

/// One random contact: springing (right or left) or a free interior joint at a fraction
/// t of the span.
fn contact(arch: &Arch, k: usize, where_: usize, t: f64) -> Contact {
    let (lo, hi) = (arch.beta_right(), arch.beta_left());
    let (beta, at) = match where_ {
        0 => (lo, Location::Springing),
        1 => (hi, Location::Springing),
        _ => (lo + t * (hi - lo), Location::Interior),
    };
    Contact {
        beta,
        kind: kind(k),
        at,
        free: at == Location::Interior,
    }
}

/// The residual of `pattern` in `family` at (x, t, μ) (plus the free angles and, for a
/// KKT-completed system, the multipliers `ys`) against central differences, entry by entry.
#[allow(clippy::too_many_arguments)]
fn check<F: Family>(
    fam: &F,
    pattern: &[Tagged<F::Tag>],
    unknowns: Unknowns,
    objective: Objective,
    x: [f64; 3],
    t: f64,
    mu: f64,
    ys: &[f64],
) -> Result<(), TestCaseError> {
    let n = pattern.len();
    let kkt = unknowns != Unknowns::TMu && n < if unknowns == Unknowns::Mu { 3 } else { 4 };
    let mut z = x.to_vec();
    match unknowns {
        Unknowns::T => z.push(t),
        Unknowns::Mu => z.push(mu),
        Unknowns::TMu => z.extend([t, mu]),
    }
    z.extend(pattern.iter().filter(|c| c.0.free).map(|c| c.0.beta));
    if kkt {
        z.extend(&ys[..n]);
    }
    let eval = |z: &[f64]| residual_and_jacobian_in(fam, pattern, (t, mu), unknowns, objective, z);
    let (f, jac) = eval(&z).expect("z has the system's length");
    prop_assert!(eval(&z[1..]).is_none());
    let free = pattern.iter().filter(|c| c.0.free).count();
    let expected_rows = n + free + if kkt { 4 } else { 0 };
    prop_assert_eq!(f.len(), expected_rows);
    prop_assert_eq!(jac.len(), expected_rows);
    for j in 0..z.len() {
        let h = 1e-5 * (1.0 + z[j].abs());
        let (mut zp, mut zm) = (z.clone(), z.clone());
        zp[j] += h;
        zm[j] -= h;
        let (fp, fm) = (eval(&zp).unwrap().0, eval(&zm).unwrap().0);
        let step = zp[j] - zm[j];
        for r in 0..f.len() {
            let fd = (fp[r] - fm[r]) / step;
            let an = jac[r][j];
            prop_assert!(
                (fd - an).abs() <= TOL * (1.0 + an.abs()),
                "{unknowns:?} kkt {kkt}: d F[{r}] / d z[{j}] analytic {an:e}, central difference {fd:e}\npattern {pattern:?}\nz {z:?}"
            );
        }
    }
    Ok(())
}

fn config() -> ProptestConfig {
    ProptestConfig {
        cases: 200,
        rng_seed: RngSeed::Fixed(7_140_303),
        ..ProptestConfig::default()
    }
}

proptest! {
    #![proptest_config(config())]

    #[test]
    fn jacobian_matches_central_differences(
        beta_r in -1.2f64..0.3,
        beta_l_off in -0.3f64..1.2,
        centroid in any::<bool>(),
        specs in proptest::collection::vec((0usize..4, 0usize..4, 0.05f64..0.95), 6),
        n in 1usize..=6,
        which in 0usize..3,
        x in proptest::array::uniform3(-2.0f64..2.0),
        eta in 0.05f64..1.0,
        mu in 0.2f64..2.0,
        ys in proptest::collection::vec(-1.0f64..1.0, 6),
    ) {
        let weight = if centroid { WeightModel::Centroid } else { WeightModel::Centreline };
        let arch = Arch::new(beta_r, std::f64::consts::PI + beta_l_off, weight).unwrap();
        let unknowns = [Unknowns::T, Unknowns::Mu, Unknowns::TMu][which];
        // plain and KKT sizes for each kind of unknowns
        let n = match unknowns {
            Unknowns::T => n.min(5),
            Unknowns::Mu => n.min(4),
            Unknowns::TMu => n.max(5),
        };
        let contacts: Vec<Contact> = specs[..n]
            .iter()
            .map(|&(k, w, t)| contact(&arch, k, w, t))
            .collect();
        let thickness = family::Thickness { arch: &arch };
        let pattern: Vec<Tagged<()>> = contacts.iter().map(|&c| (c, ())).collect();
        check(&thickness, &pattern, unknowns, Objective::Least, x, eta, mu, &ys)?;
    }
}

proptest! {
    #![proptest_config(config())]

    #[test]
    fn load_family_jacobian_matches_central_differences(
        beta_r in -1.2f64..0.3,
        beta_l_off in -0.3f64..1.2,
        centroid in any::<bool>(),
        load_kind in 0usize..3,
        load_at in 0.1f64..0.9,
        specs in proptest::collection::vec((0usize..4, 0usize..4, 0.05f64..0.95, any::<bool>()), 6),
        n in 1usize..=6,
        which in 0usize..3,
        x in proptest::array::uniform3(-2.0f64..2.0),
        lambda in 0.0f64..3.0,
        eta in 0.05f64..1.0,
        mu in 0.2f64..2.0,
        ys in proptest::collection::vec(-1.0f64..1.0, 6),
    ) {
        let weight = if centroid { WeightModel::Centroid } else { WeightModel::Centreline };
        let arch = Arch::new(beta_r, std::f64::consts::PI + beta_l_off, weight).unwrap();
        let (lo, hi) = (arch.beta_right(), arch.beta_left());
        let load = match load_kind {
            0 => LiveLoad::Horizontal { towards_right: true },
            1 => LiveLoad::Horizontal { towards_right: false },
            _ => LiveLoad::Point { beta: lo + load_at * (hi - lo) },
        };
        let fam = family::Load { arch: &arch, eta, load: &load };
        let unknowns = [Unknowns::T, Unknowns::Mu, Unknowns::TMu][which];
        let n = match unknowns {
            Unknowns::T => n.min(5),
            Unknowns::Mu => n.min(4),
            Unknowns::TMu => n.max(5),
        };
        let pattern: Vec<Tagged<Side>> = specs[..n]
            .iter()
            .map(|&(k, w, t, after)| {
                (contact(&arch, k, w, t), if after { Side::After } else { Side::Before })
            })
            .collect();
        check(&fam, &pattern, unknowns, Objective::Largest, x, lambda, mu, &ys)?;
    }
}
