//! Exact identities of the formulation, checked on random data (proptest):
//! the exact β- and η-derivatives (first and second in η) of the activation functions,
//! with and without fill, against central finite
//! differences, and the virtual-work identity φᵀλ = L_e − μ Σ N (s⁺ + s⁻) for every
//! compatible λ (formulation §6), which ties the signs of statics, B and L_e together.

use arch_enum::contact::{Contact, Location};
use arch_enum::kinematics::{column, power};
use arch_enum::statics::{actions, eta_terms};
use arch_enum::{Arch, ContactKind, WeightModel};
use nalgebra::DMatrix;
use proptest::prelude::*;

fn weight(centroid: bool) -> WeightModel {
    if centroid {
        WeightModel::Centroid
    } else {
        WeightModel::Centreline
    }
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 64, ..ProptestConfig::default() })]

    #[test]
    fn derivatives_match_finite_differences(
        alpha in -1.2f64..1.2, t in 0.05f64..0.95, eta in 0.01f64..1.5, mu in 0.1f64..3.0,
        h in -2.0f64..2.0, v in -2.0f64..2.0, w in -1.0f64..1.0, centroid in any::<bool>(), k in 0usize..4,
        fill in proptest::option::of((0.1f64..2.0, 0.0f64..0.5)),
    ) {
        let mut arch = Arch::symmetric(alpha, weight(centroid)).unwrap();
        if let Some((g, depth)) = fill {
            arch = arch.with_fill(arch_enum::fill::Fill::new(g, depth).unwrap());
        }
        let beta = arch.beta_right() + t * arch.span();
        let x = [h, v, w];
        let mode = ContactKind::ALL[k];
        let phi = |b: f64, e: f64, order: usize| actions(&arch, e, b).activation(mode, order, e, mu).at(&x);
        let d = 1e-5;
        for order in 0..2 {
            let fd = (phi(beta + d, eta, order) - phi(beta - d, eta, order)) / (2.0 * d);
            let exact = phi(beta, eta, order + 1);
            prop_assert!((fd - exact).abs() < 1e-7 * (1.0 + exact.abs()), "d/dbeta of order {order}: fd {fd} vs {exact}");
            // a step relative to η: the fill's 1/η makes the differences of absolute steps
            // inaccurate near η → 0
            let de = 1e-4 * eta;
            let fd_eta = (phi(beta, eta + de, order) - phi(beta, eta - de, order)) / (2.0 * de);
            let d_eta = |e: f64| {
                let n = actions(&arch, e, beta).n[order].at(&x);
                eta_terms(&arch, e, beta).activation_d_eta(mode, order, (e, mu), n)
            };
            let exact_eta = d_eta(eta);
            prop_assert!((fd_eta - exact_eta).abs() < 1e-7 * (1.0 + exact_eta.abs()), "d/deta of order {order}: fd {fd_eta} vs {exact_eta}");
            let fd2 = (d_eta(eta + de) - d_eta(eta - de)) / (2.0 * de);
            let exact2 = eta_terms(&arch, eta, beta).activation_d2_eta(mode, order, (eta, mu));
            prop_assert!((fd2 - exact2).abs() < 1e-5 * (1.0 + exact2.abs()), "d2/deta2 of order {order}: fd {fd2} vs {exact2}");
        }
    }

    #[test]
    fn virtual_work_identity(
        alpha in -1.2f64..1.2, eta in 0.01f64..1.5, mu in 0.1f64..3.0,
        h in -2.0f64..2.0, v in -2.0f64..2.0, w in -1.0f64..1.0, centroid in any::<bool>(),
        ts in proptest::collection::vec(0.0f64..1.0, 4..7), ks in proptest::collection::vec(0usize..4, 7),
    ) {
        let arch = Arch::symmetric(alpha, weight(centroid)).unwrap();
        let x = [h, v, w];
        let contacts: Vec<Contact> = ts.iter().zip(&ks).map(|(&t, &k)| Contact {
            beta: arch.beta_right() + t * arch.span(),
            kind: ContactKind::ALL[k],
            at: Location::Interior,
            free: false,
        }).collect();
        // a compatible lambda: the null vector of the first four columns of B, by
        // cofactors (any sign: the identity is linear), zero on the other contacts
        let b = DMatrix::from_fn(3, contacts.len(), |r, c| column(contacts[c].kind, contacts[c].beta, eta)[r]);
        let mut lambda = vec![0.0; contacts.len()];
        for (i, l) in lambda.iter_mut().enumerate().take(4) {
            let cols: Vec<usize> = (0..4).filter(|&j| j != i).collect();
            let minor = nalgebra::Matrix3::from_fn(|r, c| b[(r, cols[c])]);
            *l = if i % 2 == 0 { 1.0 } else { -1.0 } * minor.determinant();
        }
        let bl = &b * nalgebra::DVector::from_vec(lambda.clone());
        prop_assert!(bl.norm() < 1e-12 * (1.0 + lambda.iter().map(|v| v.abs()).sum::<f64>()));
        let p = power(&arch, eta, &contacts);
        let le: f64 = p.iter().zip(&lambda).map(|(a, l)| a * l).sum();
        let mut phi_l = 0.0;
        let mut diss = 0.0;
        for (c, &l) in contacts.iter().zip(&lambda) {
            let a = actions(&arch, eta, c.beta);
            phi_l += a.activation(c.kind, 0, eta, mu).at(&x) * l;
            if !c.kind.is_hinge() {
                diss += mu * a.n[0].at(&x) * l;
            }
        }
        prop_assert!((phi_l - (le - diss)).abs() < 1e-10, "phi'lambda = {phi_l}, L_e - mu sum N s = {}", le - diss);
    }
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 200, ..ProptestConfig::default() })]

    /// The fast 4-variable LP and HiGHS agree on the margin LP of random arches, states
    /// and working sets (the optimum value; the optimal x need not be unique).
    #[test]
    fn dense_lp_matches_highs(
        alpha in -1.3f64..1.2, eta in 0.001f64..1.9, mu in 0.05f64..5.0, n in 3usize..60, seed in 0u64..1000,
    ) {
        use arch_enum::statics::actions;
        let arch = Arch::symmetric(alpha, WeightModel::Centreline).unwrap();
        let mut rng = seed;
        let mut rows = Vec::new();
        for _ in 0..n {
            rng = rng.wrapping_mul(6364136223846793005).wrapping_add(1442695040888963407);
            let t = (rng >> 11) as f64 / (1u64 << 53) as f64;
            let beta = arch.beta_right() + t * arch.span();
            let a = actions(&arch, eta, beta);
            for m in ContactKind::ALL {
                rows.push(a.activation(m, 0, eta, mu));
            }
        }
        let cap = arch.span();
        let fast = arch_enum::lp::dense::max_margin(&rows, cap, 1e-13);
        let reference = arch_enum::lp::highs::max_margin(&rows, cap, 1e-10).unwrap();
        if let Err(arch_enum::lp::LpOutcome::Failed(m)) = &fast {
            // the only admissible failure: a working set so small that the optimum is
            // unbounded in x (the dense solver's box binds); the caller then uses HiGHS
            prop_assert!(m.contains("box"), "dense LP failed: {m}");
        }
        if let Ok((x, s)) = fast {
            prop_assert!((s - reference.1).abs() <= 1e-8 * (1.0 + s.abs()), "dense {s} vs HiGHS {}", reference.1);
            // the dense optimum is feasible
            for r in &rows {
                let g = r.grad_norm();
                prop_assert!(r.at(&x) / g + s <= 1e-9 * (1.0 + x.iter().map(|v| v.abs()).sum::<f64>()));
            }
        }
    }
}

/// The default settings are valid; a field out of range is named in the error.
#[test]
fn settings_validate_names_the_field() {
    let s = arch_enum::Settings::default();
    assert!(s.validate().is_ok());
    let bad = arch_enum::Settings {
        root_slack: 0.0,
        ..s.clone()
    };
    let e = bad.validate().unwrap_err().to_string();
    assert!(e.contains("settings.root_slack"), "{e}");
    let bad = arch_enum::Settings {
        scan_points: 1,
        ..s
    };
    let e = bad.validate().unwrap_err().to_string();
    assert!(e.contains("settings.scan_points"), "{e}");
}

/// A 64-bit LCG in [0, 1) (a fixed stream: the cases below are reproducible).
struct Lcg(u64);

impl Lcg {
    fn next(&mut self) -> f64 {
        self.0 = self
            .0
            .wrapping_mul(6364136223846793005)
            .wrapping_add(1442695040888963407);
        (self.0 >> 11) as f64 / (1u64 << 53) as f64
    }
}

/// The dense multiplier LP (least and largest λ of `a · (h, v, w, λ) + c ≤ 0`, λ ≥ 0)
/// against HiGHS on 400 random row sets: the rows of loaded arches at random joints
/// (horizontal and point loads, hinges only and with friction, thick and thin) and rows
/// drawn at random in R⁴. Wherever the dense path answers (in either of its boxes), HiGHS
/// has an optimum with the same λ to 1e-9 relative and the dense z satisfies every row; where HiGHS finds λ
/// unbounded or no state, the dense path declines (the caller then uses HiGHS), and
/// `lp::multiplier_extreme_warm` with the dense back end gives HiGHS's answer. A warm start
/// from the optimum on half the rows gives the cold answer on all of them. Each kind of
/// outcome occurs, and the dense path decides every bounded largest λ and most least ones.
#[test]
fn dense_multiplier_lp_matches_highs() {
    use arch_enum::load::{rows, LiveLoad, LoadRow};
    use arch_enum::lp::{self, dense, highs, LpOutcome};
    use arch_enum::settings::LpBackend;
    let settings = arch_enum::Settings {
        lp_backend: LpBackend::Dense,
        ..arch_enum::Settings::default()
    };
    let mut rng = Lcg(0x5eed_1a3b_da00_0011);
    // bounded and decided: [least, largest]
    let (mut bounded, mut decided) = ([0; 2], [0; 2]);
    let (mut unbounded, mut infeasible) = (0, 0);
    let rel = |a: f64, b: f64| (a - b).abs() / b.abs().max(1.0);
    for case in 0..400 {
        let physical = case % 2 == 0;
        let maximise = (case / 2) % 2 == 0;
        let set: Vec<([f64; 4], f64)> = if physical {
            let alpha = -1.2 + 2.4 * rng.next();
            let weight = if rng.next() < 0.5 {
                WeightModel::Centreline
            } else {
                WeightModel::Centroid
            };
            let arch = Arch::symmetric(alpha, weight).unwrap();
            let eta = 0.02 + 0.8 * rng.next();
            let mu = if rng.next() < 0.4 {
                f64::INFINITY
            } else {
                0.2 + 2.0 * rng.next()
            };
            let n = 3 + (rng.next() * 40.0) as usize;
            let mut joints: Vec<f64> = (0..n)
                .map(|_| arch.beta_right() + rng.next() * arch.span())
                .collect();
            joints.push(arch.beta_right());
            joints.push(arch.beta_left());
            joints.sort_by(f64::total_cmp);
            let load = if rng.next() < 0.5 {
                LiveLoad::Horizontal {
                    towards_right: rng.next() < 0.5,
                }
            } else {
                LiveLoad::Point {
                    beta: joints[(rng.next() * joints.len() as f64) as usize],
                }
            };
            rows(&arch, &joints, eta, mu, &load)
                .iter()
                .map(LoadRow::pair)
                .collect()
        } else {
            let n = 3 + (rng.next() * 30.0) as usize;
            (0..n)
                .map(|_| {
                    let a = [0; 4].map(|_| 2.0 * rng.next() - 1.0);
                    (a, 2.0 * rng.next() - 1.0 - 0.3)
                })
                .collect()
        };
        let reference = highs::multiplier_extreme(&set, &[], maximise, 1e-10);
        // the dense path in its two boxes: that of the margin LP, and HiGHS's retry's
        let fast = dense::multiplier_extreme(&set, maximise, 1e-13, None, dense::BOX);
        let wide = dense::multiplier_extreme(&set, maximise, 1e-13, None, highs::REACTION_BOX);
        let combined =
            lp::multiplier_extreme_warm(&set, maximise, &settings, &mut lp::WarmStart::default());
        let label = format!("case {case} (physical {physical}, maximise {maximise})");
        match &reference {
            Ok(Some(z)) if !lp::on_box(z) => bounded[maximise as usize] += 1,
            Ok(_) => unbounded += 1,
            Err(LpOutcome::Infeasible) => infeasible += 1,
            Err(LpOutcome::Failed(e)) => panic!("{label}: HiGHS failed: {e}"),
        }
        if fast.is_ok() {
            decided[maximise as usize] += 1;
        }
        for answer in [&fast, &wide] {
            let Ok((z, _)) = answer else { continue };
            let Ok(Some(zr)) = reference else {
                panic!("{label}: dense optimum {z:?}, HiGHS {reference:?}");
            };
            assert!(
                !lp::on_box(&zr) && rel(z[3], zr[3]) <= 1e-9,
                "{label}: dense lambda {} vs HiGHS {}",
                z[3],
                zr[3]
            );
            assert!(z[3] >= 0.0, "{label}: lambda {} < 0", z[3]);
            let size = 1.0 + z.iter().map(|v| v.abs()).sum::<f64>();
            for (a, c) in &set {
                let norm = a.iter().map(|v| v * v).sum::<f64>().sqrt();
                let value = a.iter().zip(z).map(|(p, q)| p * q).sum::<f64>() + c;
                assert!(
                    value <= 1e-9 * norm * size,
                    "{label}: row violated by {value}"
                );
            }
        }
        // the dense back end's answer: the dense optimum in the first box, else (after an
        // optimum on that box) in the second, else HiGHS's
        let box_failure = |r: &Result<([f64; 4], [usize; 4]), LpOutcome>| matches!(r, Err(LpOutcome::Failed(e)) if e.contains("box"));
        match (&fast, &wide) {
            (Ok((z, _)), _) => assert_eq!(combined, Ok(Some(*z)), "{label}"),
            (f, Ok((z, _))) if box_failure(f) => assert_eq!(combined, Ok(Some(*z)), "{label}"),
            _ => assert_eq!(combined, reference, "{label}"),
        }
        // a warm start from the optimum on the first half of the rows
        let half = set.len() / 2;
        if let (Ok((_, basis)), Ok((cold, _))) = (
            dense::multiplier_extreme(&set[..half], maximise, 1e-13, None, dense::BOX),
            &fast,
        ) {
            match dense::multiplier_extreme(&set, maximise, 1e-13, Some(basis), dense::BOX) {
                Ok((warm, _)) => assert!(
                    rel(warm[3], cold[3]) <= 1e-9,
                    "{label}: warm {} vs cold {}",
                    warm[3],
                    cold[3]
                ),
                Err(e) => panic!("{label}: warm start failed where the cold one did not: {e:?}"),
            }
        }
    }
    println!(
        "dense multiplier LP: bounded {bounded:?} (least, largest), decided by the dense path {decided:?}, {unbounded} unbounded, {infeasible} infeasible"
    );
    assert!(bounded[0] >= 50 && bounded[1] >= 50 && unbounded >= 20 && infeasible >= 20);
    // every largest λ; the least λ = 0 is often attained on a face of states that
    // reaches the dense path's box, where it declines
    assert!(
        decided[1] == bounded[1],
        "largest: {decided:?} of {bounded:?}"
    );
    assert!(
        decided[0] * 4 >= bounded[0] * 3,
        "least: {decided:?} of {bounded:?}"
    );
}

/// A hard case of the continuous exchange (found comparing the dense and HiGHS paths on
/// random arches): a point load on an unsymmetric arch, λ_static ≈ 433 with reactions
/// ≈ 400, where HiGHS's z (to its 1e-10 tolerance) pointed Newton at an admissible vertex
/// that is not the optimum (λ = 431.91, a multiplier of −418). The dense path's exact
/// vertex gives the optimum, which fine discretisations bound from above and attain (their
/// joints include every contact: the springings and the loaded section); the HiGHS path
/// now rejects the wrong vertex by its multipliers and answers no decision rather than a
/// wrong λ.
#[test]
fn continuous_lambda_static_is_the_optimum_not_an_admissible_vertex() {
    use arch_enum::load::LiveLoad;
    use arch_enum::multiplier::{static_range, StaticRange};
    use arch_enum::settings::LpBackend;
    let (br, bl, eta, mu, bp) = (
        -0.21973324701638386,
        2.4199860547471412,
        0.3472361077353397,
        0.828971296174701,
        1.026148395555269,
    );
    let arch = Arch::new(br, bl, WeightModel::Centreline).unwrap();
    let load = LiveLoad::Point { beta: bp };
    let largest = |arch: &Arch, settings: &arch_enum::Settings| match static_range(
        arch, eta, mu, &load, settings,
    )
    .unwrap()
    {
        Ok(StaticRange::Interval { max: Some(m), .. }) => Ok(m.0),
        other => Err(format!("{other:?}")),
    };
    let dense = arch_enum::Settings::default();
    let n = 4000;
    let mut joints: Vec<f64> = (0..=n)
        .map(|i| {
            if i == n {
                bl
            } else {
                br + (bl - br) * i as f64 / n as f64
            }
        })
        .collect();
    joints.push(bp);
    joints.sort_by(f64::total_cmp);
    let fine = largest(&arch.clone().with_joints(&joints).unwrap(), &dense).unwrap();
    let exact = largest(&arch, &dense).unwrap();
    assert!(
        (exact - fine).abs() <= 1e-9 * fine,
        "continuous {exact} vs {n} joints {fine}"
    );
    let reference = arch_enum::Settings {
        lp_backend: LpBackend::Highs,
        ..dense
    };
    if let Ok(l) = largest(&arch, &reference) {
        assert!((l - fine).abs() <= 1e-9 * fine, "HiGHS path {l} vs {fine}");
    }
}

/// The dense kinematic LP (`lp::Kinematic` with the dense back end: the basic solutions of
/// the independent equality rows) against HiGHS on 600 random patterns of 1 to 12 rates:
/// compatibility columns of rank 1 to 3, repeated columns, powers zero or of either sign.
/// Both say "no mechanism", or both find rates with the same objective to 1e-9, and the
/// dense rates satisfy every row. Rows of full rank and rows of lower rank (every pattern
/// of three rates or fewer) are both met many times, and so are both answers.
#[test]
fn dense_kinematic_lp_matches_highs() {
    use arch_enum::lp::{dense, highs, Kinematic, LpOutcome};
    use arch_enum::settings::LpBackend;
    let settings = arch_enum::Settings {
        lp_backend: LpBackend::Dense,
        ..arch_enum::Settings::default()
    };
    let mut rng = Lcg(0x5eed_c0de_4b1e_0007);
    let (mut full, mut deficient, mut found, mut none) = (0, 0, 0, 0);
    for case in 0..600 {
        let n = 1 + case % 12;
        let rank = 1 + (case / 12) % 3;
        let basis: Vec<[f64; 3]> = (0..rank)
            .map(|_| [0; 3].map(|_| 2.0 * rng.next() - 1.0))
            .collect();
        let mut columns: Vec<[f64; 3]> = (0..n)
            .map(|_| {
                let w: Vec<f64> = basis.iter().map(|_| 2.0 * rng.next() - 1.0).collect();
                [0, 1, 2].map(|i| basis.iter().zip(&w).map(|(b, w)| b[i] * w).sum())
            })
            .collect();
        if n > 1 && case % 5 == 0 {
            columns[n - 1] = columns[0]; // a repeated contact
        }
        let power: Vec<f64> = (0..n)
            .map(|_| match case % 4 {
                0 => 0.0,
                _ => 2.0 * rng.next() - 1.0,
            })
            .collect();
        let objective: Vec<f64> = (0..n).map(|_| rng.next()).collect();
        match dense::kinematic_rows(&columns, &power) {
            dense::KinematicRows::Independent(0b11111) => full += 1,
            dense::KinematicRows::Independent(_) => deficient += 1,
            _ => {}
        }
        let d = Kinematic::new(&columns, &power, &settings).solve(&objective);
        let h = highs::kinematic(&columns, &power, &objective, settings.lp_tol);
        let value = |l: &[f64]| l.iter().zip(&objective).map(|(a, b)| a * b).sum::<f64>();
        match (d, h) {
            (Err(LpOutcome::Infeasible), Err(LpOutcome::Infeasible)) => none += 1,
            (Ok(l), Ok(r)) => {
                found += 1;
                assert!(
                    (value(&l) - value(&r)).abs() <= 1e-9,
                    "case {case}: dense {} vs HiGHS {}",
                    value(&l),
                    value(&r)
                );
                let sum = |f: &dyn Fn(usize) -> f64| (0..n).map(|j| l[j] * f(j)).sum::<f64>();
                let rows = (0..n).fold([0.0; 3], |acc, j| {
                    [0, 1, 2].map(|i| acc[i] + l[j] * columns[j][i])
                });
                assert!(
                    rows.iter().all(|r| r.abs() <= 1e-9),
                    "case {case}: {rows:?}"
                );
                assert!(sum(&|j| power[j]) >= -1e-9, "case {case}: power");
                assert!((sum(&|_| 1.0) - 1.0).abs() <= 1e-9, "case {case}: sum");
                assert!(l.iter().all(|&v| v >= 0.0), "case {case}: sign");
            }
            (d, h) => panic!("case {case}: dense {d:?} vs HiGHS {h:?}"),
        }
    }
    assert!(
        full >= 100 && deficient >= 100,
        "full {full}, deficient {deficient}"
    );
    assert!(found >= 100 && none >= 100, "found {found}, none {none}");
}

/// The kinematic LP's equality rows with its power slack, as the dense path builds them:
/// rate j → (c_j, p_j, 1), the slack → (0, 0, 0, −1, 0).
fn kinematic_matrix(columns: &[[f64; 3]], power: &[f64]) -> DMatrix<f64> {
    let n = columns.len();
    DMatrix::from_fn(5, n + 1, |r, c| {
        if c < n {
            [columns[c][0], columns[c][1], columns[c][2], power[c], 1.0][r]
        } else {
            [0.0, 0.0, 0.0, -1.0, 0.0][r]
        }
    })
}

/// The kinematic rows are classified as of full rank exactly where their SVD says rank 5
/// at the dense path's threshold (1e-10), including rows a small perturbation away from
/// rank 4 on either side of it: the shortcut that skips the SVD (a determinant bound)
/// never claims full rank that the SVD would deny, and it decides most full-rank rows.
#[test]
fn kinematic_rows_full_rank_as_the_svd_says() {
    use arch_enum::lp::dense::{kinematic_rows, KinematicRows};
    let mut rng = Lcg(0x5eed_fa11_4a4c_0001);
    let (mut full, mut not_full, mut shortcut) = (0, 0, 0);
    for case in 0..2000 {
        let n = 4 + case % 9;
        // rank-2 columns of the compatibility rows, then a perturbation of 1e-7 to 1e-14
        let basis: Vec<[f64; 3]> = (0..2)
            .map(|_| [0; 3].map(|_| 2.0 * rng.next() - 1.0))
            .collect();
        let size = 10f64.powi(-7 - (case / 9) % 8);
        let columns: Vec<[f64; 3]> = (0..n)
            .map(|_| {
                let w: Vec<f64> = basis.iter().map(|_| 2.0 * rng.next() - 1.0).collect();
                [0, 1, 2].map(|i| {
                    basis.iter().zip(&w).map(|(b, w)| b[i] * w).sum::<f64>()
                        + size * (2.0 * rng.next() - 1.0)
                })
            })
            .collect();
        let power: Vec<f64> = (0..n).map(|_| 2.0 * rng.next() - 1.0).collect();
        let m = kinematic_matrix(&columns, &power);
        let svd_full = m.rank(1e-10) >= 5;
        if arch_enum::lp::dense::surely_full_rank(&m, 1e-10) {
            assert!(
                svd_full,
                "case {case}: the bound claims full rank, the SVD does not"
            );
            shortcut += 1;
        }
        let classified_full =
            kinematic_rows(&columns, &power) == KinematicRows::Independent(0b11111);
        assert_eq!(classified_full, svd_full, "case {case}: size {size:e}");
        if svd_full {
            full += 1;
        } else {
            not_full += 1;
        }
    }
    assert!(
        full >= 300 && not_full >= 300,
        "full {full}, not full {not_full}"
    );
    // near rank 4 the bound (loose by up to ‖M‖_F⁴) often leaves the decision to the SVD
    assert!(
        4 * shortcut >= full,
        "the bound decided {shortcut} of {full} full-rank rows"
    );
    // the rows the solver meets most (generic columns of rank 3): the bound decides them
    let mut decided = 0;
    for case in 0..200 {
        let n = 4 + case % 9;
        let columns: Vec<[f64; 3]> = (0..n)
            .map(|_| [0; 3].map(|_| 2.0 * rng.next() - 1.0))
            .collect();
        let power: Vec<f64> = (0..n).map(|_| 2.0 * rng.next() - 1.0).collect();
        let m = kinematic_matrix(&columns, &power);
        if arch_enum::lp::dense::surely_full_rank(&m, 1e-10) {
            assert!(m.rank(1e-10) >= 5, "generic case {case}");
            decided += 1;
        }
    }
    assert!(
        decided >= 190,
        "the bound decided {decided} of 200 generic rows"
    );
}

/// The scan's cheaper slopes (`statics::ring_slopes`, N and T at x combined by the
/// derivative identities) agree with the full evaluation (the affine forms of
/// `actions(..).activation(mode, 1, ..)` at x) within 32 ε (2 + |h| + |v| + |β − β_R|)
/// (1 + η + μ) on 20 000 random states of both weight models, half the bound the scan uses
/// to trust a slope's sign (`SLOPE_SIGN_ULPS` = 64 in src/scan.rs): a sign it trusts is the
/// full evaluation's. (The largest gap seen is about 1.7 ε times that size: the test fails
/// with 1 in place of 32.)
#[test]
fn ring_slopes_agree_with_the_full_evaluation_within_the_scan_bound() {
    use arch_enum::statics::ring_slopes;
    let mut rng = Lcg(0x5eed_5107_e500_0001);
    let modes = ContactKind::ALL;
    let mut worst = 0.0f64;
    for case in 0..20_000 {
        let alpha = -1.4 + 2.6 * rng.next();
        let arch = Arch::symmetric(alpha, weight(case % 2 == 0)).expect("an opening");
        let eta = 10f64.powf(-4.0 + 4.3 * rng.next());
        let mu = 10f64.powf(-1.0 + 4.0 * rng.next());
        let scale = 10f64.powf(-2.0 + 6.0 * rng.next());
        let x = [0; 3].map(|_| scale * (2.0 * rng.next() - 1.0));
        let (a, b) = (arch.beta_right(), arch.beta_left());
        let beta = a + (b - a) * rng.next();
        let fast = ring_slopes(&arch, (eta, mu), beta, beta.sin_cos(), &x, &modes);
        let full = actions(&arch, eta, beta);
        let terms = 2.0 + x[0].abs() + x[1].abs() + (beta - a).abs();
        let bound = 32.0 * f64::EPSILON * terms * (1.0 + eta + mu);
        for (k, &mode) in modes.iter().enumerate() {
            let exact = full.activation(mode, 1, eta, mu).at(&x);
            let gap = (fast[k] - exact).abs();
            worst = worst.max(gap / bound);
            assert!(
                gap <= bound,
                "case {case}: {mode:?} at beta {beta}: {} vs {exact} (bound {bound:e})",
                fast[k]
            );
        }
    }
    // the bound is not vacuous: the forms do differ by rounding
    assert!(worst > 0.0, "no rounding difference seen");
    assert!(worst <= 1.0, "the largest gap is {worst} of the bound");
}
