//! Live loads with a multiplier (issue 11, first piece): the live statics against an
//! independent quadrature, the virtual-work identity with the live power on random
//! compatible rates, and the static multiplier of a published discrete arch.

use crate::search_reference::{random_joints, Rng};
use arch_enum::bridge::Fill;
use arch_enum::contact::{Contact, ContactKind, Location};
use arch_enum::kinematics::{column, power};
use arch_enum::load::{live_activation, LiveLoad, Side};
use arch_enum::multiplier::{static_range, StaticRange};
use arch_enum::pressure::{Patch, PointLoad, Pressure};
use arch_enum::statics::actions;
use arch_enum::{Arch, Settings, WeightModel};
use nalgebra::DMatrix;
use std::f64::consts::PI;

/// M_L of the horizontal body force from a quadrature over the annular sector [β_R, β]
/// (composite Simpson in θ, two-point Gauss in r; weight density r/η per unit dr dθ, so
/// that the weight is Δ), with the centreline model's weight on r = 1: a force F towards
/// +x at height y gives M = F (sin β − y) at the joint's centre point.
fn quadrature_moment(beta_r: f64, beta: f64, eta: f64, centroid: bool) -> f64 {
    let nt = 2000; // even
    let h = (beta - beta_r) / nt as f64;
    let radii: Vec<(f64, f64)> = if centroid {
        let g = eta / (2.0 * 3f64.sqrt());
        vec![(1.0 - g, 0.5), (1.0 + g, 0.5)] // (r, weight of the mean over the radius)
    } else {
        vec![(1.0, 1.0)]
    };
    let f = |th: f64| -> f64 {
        radii
            .iter()
            .map(|&(r, w)| {
                // ∫ (r/η) dr over the thickness = 1: the mean of r·(sin β − r sin θ)
                w * r * (beta.sin() - r * th.sin())
            })
            .sum()
    };
    let mut sum = f(beta_r) + f(beta);
    for i in 1..nt {
        sum += if i % 2 == 1 { 4.0 } else { 2.0 } * f(beta_r + h * i as f64);
    }
    sum * h / 3.0
}

#[test]
fn horizontal_moment_matches_a_quadrature_of_the_sector() {
    for (br, bl, eta, centroid) in [
        (0.0, PI, 0.2, false),
        (0.0, PI, 0.2, true),
        (-0.6, PI + 0.3, 0.9, true),
        (0.4, 2.5, 1.5, true),
    ] {
        let w = if centroid {
            WeightModel::Centroid
        } else {
            WeightModel::Centreline
        };
        let arch = Arch::new(br, bl, w).unwrap();
        for f in [0.1, 0.37, 0.8, 1.0] {
            let beta = br + f * (bl - br);
            let load = LiveLoad::Horizontal {
                towards_right: true,
            };
            let [n, t, m] = load.actions(&arch, eta, beta, Side::After);
            let q = quadrature_moment(br, beta, eta, centroid);
            assert!(
                (m - q).abs() < 1e-11 * (1.0 + q.abs()),
                "M_L {m} vs quadrature {q}"
            );
            // the resultant λΔ towards +x, resolved on the joint (as the reaction h is,
            // with the opposite sign: N = h sin β + ..., T = h cos β − ...)
            let d = beta - br;
            assert!((n + d * beta.sin()).abs() < 1e-15 && (t + d * beta.cos()).abs() < 1e-15);
            let left = LiveLoad::Horizontal {
                towards_right: false,
            }
            .actions(&arch, eta, beta, Side::After);
            assert_eq!(left, [-n, -t, -m]);
        }
    }
}

/// Σ_j φ_j(x, λ) r_j = L_dead + λ L_live − μ Σ_sliding N_j(x, λ) r_j for every compatible
/// rate vector r (B r = 0, any sign) and any state (x, λ): a direct test of the live
/// statics against the live kinematics (loads.md), on random discrete arches with every
/// contact of every joint, both weight models, every load (the point load at a joint,
/// with both sides of its section, or inside a voussoir; patches and point loads on the
/// extrados), a third of the arches under fill.
#[test]
fn virtual_work_identity_with_the_live_load() {
    let mut rng = Rng(0x11fe_10ad_0000_0001);
    for case in 0..300 {
        let n = 2 + (rng.next() * 7.0) as usize;
        let br = -0.8 + 1.6 * rng.next();
        let bl = PI + (-0.8 + 1.6 * rng.next());
        let joints = random_joints(&mut rng, br, bl, n);
        let weight = if case % 2 == 1 {
            WeightModel::Centroid
        } else {
            WeightModel::Centreline
        };
        let mut arch = Arch::new(br, bl, weight)
            .unwrap()
            .with_joints(&joints)
            .unwrap();
        // fill (bridge spec §2) on a third of the arches: its power block by block
        if case % 3 == 0 {
            arch = arch.with_fill(Fill::new(0.2 + rng.next(), 0.3 * rng.next()).unwrap());
        }
        let mu = 0.2 + 2.0 * rng.next();
        let eta = 0.01 + 1.9 * rng.next();
        let kappa = 1.0 + eta / 2.0;
        let load = match case % 6 {
            0 => LiveLoad::Horizontal {
                towards_right: true,
            },
            1 => LiveLoad::Horizontal {
                towards_right: false,
            },
            2 => LiveLoad::Point {
                beta: joints[(rng.next() * joints.len() as f64) as usize % joints.len()],
            },
            3 => LiveLoad::Point {
                beta: br + (bl - br) * rng.next(),
            },
            // patches on the extrados (some past its ends), and point loads at joints
            // and inside voussoirs (bridge spec §3)
            4 => LiveLoad::Pressure(
                Pressure::new(
                    &(0..3)
                        .map(|_| {
                            let x = kappa * (2.4 * rng.next() - 1.2);
                            let half = 0.4 * rng.next() + 1e-3;
                            Patch {
                                x_lo: x - half,
                                x_hi: x + half,
                                q: rng.next(),
                            }
                        })
                        .collect::<Vec<_>>(),
                    &[],
                )
                .unwrap(),
            ),
            _ => {
                let (a, b) = (br.max(0.0), bl.min(PI));
                let on = |beta: f64| beta >= a && beta <= b;
                let mut points = Vec::new();
                for &beta in &joints {
                    if on(beta) && rng.next() < 0.5 {
                        points.push(PointLoad {
                            beta,
                            q: rng.next(),
                        });
                    }
                }
                points.push(PointLoad {
                    beta: a + (b - a) * rng.next(),
                    q: 1.0,
                });
                LiveLoad::Pressure(Pressure::new(&[], &points).unwrap())
            }
        };
        // every contact at every joint (both sides of a loaded joint)
        let mut contacts: Vec<(Contact, Side)> = Vec::new();
        for (j, &beta) in joints.iter().enumerate() {
            let at = if j == 0 || j == joints.len() - 1 {
                Location::Springing
            } else {
                Location::Interior
            };
            let sides: &[Side] = if load.splits(beta) {
                &[Side::Before, Side::After]
            } else {
                &[Side::After]
            };
            for &side in sides {
                for kind in ContactKind::ALL {
                    contacts.push((
                        Contact {
                            beta,
                            kind,
                            at,
                            free: false,
                        },
                        side,
                    ));
                }
            }
        }
        let nc = contacts.len();
        let b = DMatrix::from_fn(3, nc, |r, c| {
            column(contacts[c].0.kind, contacts[c].0.beta, eta)[r]
        });
        let svd = b.clone().svd(false, true);
        let vt = svd.v_t.unwrap();
        let mut rates = DMatrix::from_fn(nc, 1, |_, _| rng.next() - 0.5);
        for r in 0..3 {
            let row = vt.row(r).transpose();
            let p = row.dot(&rates);
            rates -= row * p;
        }
        let x = [
            3.0 * (rng.next() - 0.5),
            3.0 * (rng.next() - 0.5),
            rng.next() - 0.5,
        ];
        let lambda = 2.0 * rng.next();
        let plain: Vec<Contact> = contacts.iter().map(|c| c.0).collect();
        let dead = power(&arch, eta, &plain);
        let live = load.power(&arch, eta, &contacts);
        let (mut lhs, mut rhs) = (0.0, 0.0);
        for (c, &(contact, side)) in contacts.iter().enumerate() {
            let a = actions(&arch, eta, contact.beta);
            let la = load.actions(&arch, eta, contact.beta, side);
            let phi = a.activation(contact.kind, 0, eta, mu).at(&x)
                + lambda * live_activation(contact.kind, eta, mu, la);
            lhs += rates[c] * phi;
            rhs += rates[c] * (dead[c] + lambda * live[c]);
            if !contact.kind.is_hinge() {
                let normal = a.n[0].at(&x) + lambda * la[0];
                rhs -= mu * normal * rates[c];
            }
        }
        assert!(
            (lhs - rhs).abs() < 1e-10 * (1.0 + lhs.abs()),
            "case {case} ({load:?}): phi . r = {lhs}, L_dead + lambda L_live - mu sum N s = {rhs}"
        );
    }
}

/// Stockdale et al. (2018, SoftwareX 7, 174–179): a 27-voussoir semicircle, intrados
/// radius 1.806 m, t = 0.1661 × the intrados radius, depth 0.25 m, density 1530 kg/m³,
/// true-centroid weight, μ = ∞, a vertical point load at the 8th joint from a springing
/// collapses at 2.751 kN (their kinematic calculator; 2.756 kN by their independent
/// check). At μ = ∞ the largest statically admissible multiplier is the collapse load.
#[test]
fn stockdale_point_load_on_a_27_voussoir_semicircle() {
    let (ri, g, rho_m, depth) = (1.806, 9.81, 1530.0, 0.25);
    let t = 0.1661 * ri;
    let r = ri + t / 2.0;
    let eta = t / r;
    let unit_kn = rho_m * g * t * depth * r / 1000.0; // γ t d r in kN
    let arch = Arch::symmetric(0.0, WeightModel::Centroid)
        .unwrap()
        .with_blocks(27)
        .unwrap();
    let beta = 8.0 * PI / 27.0;
    let range = static_range(
        &arch,
        eta,
        f64::INFINITY,
        &LiveLoad::Point { beta },
        &Settings::default(),
    )
    .unwrap()
    .unwrap();
    let StaticRange::Interval { min, max } = range else {
        panic!("{range:?}")
    };
    assert_eq!(min.0, 0.0, "the arch stands unloaded");
    let kn = max.unwrap().0 * unit_kn;
    println!(
        "Stockdale: lambda_static = {} (x {unit_kn} kN) = {kn} kN",
        max.unwrap().0
    );
    assert!((kn - 2.751).abs() < 0.0005, "{kn} kN against 2.751 kN");
}

/// `load --json`: the contract's keys, the Stockdale case through the command line (the
/// 8th joint by index, the load in kN), and exit codes.
#[test]
fn load_command_json_contract() {
    use crate::cli::json_of;
    let (ri, t) = (1.806, 0.1661 * 1.806);
    let r = ri + t / 2.0;
    let eta = format!("{}", t / r);
    let radius = format!("{r}");
    let (v, code) = json_of(&[
        "load",
        "--alpha",
        "0",
        "--blocks",
        "27",
        "--weight",
        "centroid",
        "--eta",
        &eta,
        "--mu",
        "inf",
        "--point-load-joint",
        "8",
        "--radius",
        &radius,
        "--depth",
        "0.25",
        "--density",
        "1530",
    ]);
    assert_eq!(code, 0, "{v}");
    assert_eq!(v["status"], "ok");
    for key in [
        "lambda",
        "lambda_static",
        "unique",
        "mechanism_at_static",
        "limit_states",
        "load",
        "reduction",
        "lambda_min",
    ] {
        assert!(v.get(key).is_some(), "missing {key}: {v}");
    }
    assert_eq!(v["load"]["kind"], "point");
    assert_eq!(v["load"]["at_joint"], true);
    assert!((v["load"]["beta"].as_f64().unwrap() - 8.0 * PI / 27.0).abs() < 1e-15);
    let kn = v["units"]["lambda_kn"].as_f64().unwrap();
    assert!((kn - 2.751).abs() < 0.0005, "{kn} kN");
    // mu = inf: the static maximum is the collapse multiplier
    assert_eq!(v["lambda"], v["lambda_static"]);
    assert_eq!(v["unique"], true);
    let states = v["limit_states"].as_array().unwrap();
    assert_eq!(states.len(), 1);
    for key in ["lambda", "mode", "pattern", "mechanism"] {
        assert!(states[0].get(key).is_some(), "missing {key}");
    }
    // a horizontal load on a discrete semicircle
    let (v, code) = json_of(&[
        "load",
        "--alpha",
        "0",
        "--blocks",
        "20",
        "--eta",
        "0.3",
        "--mu",
        "0.8",
        "--horizontal",
    ]);
    assert_eq!(code, 0);
    assert_eq!(v["load"]["kind"], "horizontal");
    assert_eq!(v["load"]["beta"], serde_json::Value::Null);
    assert!(v["lambda"].as_f64().unwrap() > 0.0);
}

#[test]
fn load_bad_input_names_the_argument() {
    let cases: &[(&[&str], &str)] = &[
        (
            &[
                "load",
                "--alpha",
                "0",
                "--eta",
                "-0.3",
                "--mu",
                "1",
                "--horizontal",
            ],
            "--eta",
        ),
        (
            &[
                "load",
                "--alpha",
                "0",
                "--blocks",
                "8",
                "--eta",
                "0.3",
                "--mu",
                "1",
                "--point-load",
                "4",
            ],
            "--point-load",
        ),
        (
            &[
                "load",
                "--alpha",
                "0",
                "--blocks",
                "8",
                "--eta",
                "0.3",
                "--mu",
                "1",
                "--point-load-deg",
                "200",
            ],
            "--point-load-deg",
        ),
        (
            &[
                "load",
                "--alpha",
                "0",
                "--blocks",
                "8",
                "--eta",
                "0.3",
                "--mu",
                "1",
                "--point-load-joint",
                "9",
            ],
            "--point-load-joint",
        ),
        (
            &[
                "load",
                "--alpha",
                "0",
                "--blocks",
                "8",
                "--eta",
                "2.5",
                "--mu",
                "1",
                "--horizontal",
            ],
            "--eta",
        ),
        (
            &[
                "load",
                "--alpha",
                "0",
                "--blocks",
                "8",
                "--eta",
                "0.3",
                "--mu",
                "0",
                "--horizontal",
            ],
            "--mu",
        ),
        (
            &[
                "load", "--alpha", "0", "--blocks", "8", "--eta", "0.3", "--mu", "1",
            ],
            "--horizontal",
        ),
    ];
    for (args, name) in cases {
        let out = assert_cmd::Command::cargo_bin("arch-enum")
            .unwrap()
            .args(*args)
            .output()
            .unwrap();
        let err = String::from_utf8_lossy(&out.stderr);
        assert_eq!(out.status.code(), Some(2), "{args:?}: {err}");
        assert!(err.contains(name), "{args:?}: {err}");
        assert!(!err.contains("panicked"), "{args:?}: {err}");
    }
}

/// On random symmetric discrete arches: the horizontal load towards either springing
/// gives the same multipliers (mirror symmetry); at μ = ∞ the collapse multiplier is the
/// static maximum (associative case, no reduction); at every limit state the total
/// external power equals the frictional dissipation (virtual work) and the live power is
/// positive.
#[test]
fn load_symmetry_infinite_friction_and_virtual_work() {
    use arch_enum::multiplier::{survey, LoadOutcome};
    let mut rng = Rng(0x5ee5_0000_0000_0011);
    let settings = Settings::default();
    let mut checked = 0;
    for case in 0..30 {
        let alpha = -0.4 + 1.2 * rng.next();
        let blocks = 3 + (rng.next() * 12.0) as usize;
        let weight = if case % 2 == 0 {
            WeightModel::Centreline
        } else {
            WeightModel::Centroid
        };
        let arch = Arch::symmetric(alpha, weight)
            .unwrap()
            .with_blocks(blocks)
            .unwrap();
        let eta = 0.2 + 0.6 * rng.next();
        let mu = if case % 3 == 0 {
            f64::INFINITY
        } else {
            0.4 + 1.2 * rng.next()
        };
        let run = |towards_right| {
            survey(
                &arch,
                eta,
                mu,
                &LiveLoad::Horizontal { towards_right },
                &settings,
            )
            .unwrap()
            .unwrap()
        };
        match (run(true), run(false)) {
            (LoadOutcome::Limits(r), LoadOutcome::Limits(l)) => {
                let (a, b) = (r.lambda_static.unwrap().0, l.lambda_static.unwrap().0);
                assert!((a - b).abs() < 1e-9 * (1.0 + a), "case {case}: {a} vs {b}");
                let la: Vec<f64> = r.limit_states.iter().map(|s| s.t).collect();
                let lb: Vec<f64> = l.limit_states.iter().map(|s| s.t).collect();
                assert_eq!(la.len(), lb.len(), "case {case}: {la:?} vs {lb:?}");
                for (x, y) in la.iter().zip(&lb) {
                    assert!(
                        (x - y).abs() < 1e-9 * (1.0 + x),
                        "case {case}: {la:?} vs {lb:?}"
                    );
                }
                if mu.is_infinite() {
                    assert_eq!(r.lambda(), Some(a), "case {case}: mu = inf must not reduce");
                }
                for s in r.limit_states.iter().chain(&l.limit_states) {
                    assert!(s.live_power > 0.0);
                    let m = &s.mechanism;
                    assert!(
                        (m.power - m.dissipation).abs() < 1e-8 * (1.0 + m.power.abs()),
                        "case {case}: power {} vs dissipation {}",
                        m.power,
                        m.dissipation
                    );
                }
                checked += 1;
            }
            (a, b) => assert_eq!(
                std::mem::discriminant(&a),
                std::mem::discriminant(&b),
                "case {case}"
            ),
        }
    }
    assert!(checked >= 20, "{checked}");
}

/// The β-derivatives of the live actions against central differences of the values.
#[test]
#[allow(clippy::needless_range_loop)]
fn live_action_derivatives_match_differences() {
    let arch = Arch::new(-0.3, PI + 0.2, WeightModel::Centroid).unwrap();
    let eta = 0.4;
    for load in [
        LiveLoad::Horizontal {
            towards_right: true,
        },
        LiveLoad::Horizontal {
            towards_right: false,
        },
        LiveLoad::Point { beta: 1.1 },
    ] {
        for beta in [0.2, 0.9, 1.6, 2.9] {
            let d = load.actions_d(&arch, eta, beta, Side::After);
            assert_eq!(d[0], load.actions(&arch, eta, beta, Side::After));
            let h = 1e-5;
            for order in 1..3 {
                for k in 0..3 {
                    let f = |b: f64| load.actions_d(&arch, eta, b, Side::After)[order - 1][k];
                    let fd = (f(beta + h) - f(beta - h)) / (2.0 * h);
                    assert!(
                        (fd - d[order][k]).abs() < 1e-8,
                        "{load:?} beta {beta} order {order} component {k}: {} vs {fd}",
                        d[order][k]
                    );
                }
            }
        }
    }
}

/// The continuous arch's λ_static (exchange + Newton on the pattern) against fine
/// discretisations: N equal voussoirs give λ_static(N) ≥ λ_static(∞) (fewer joints, fewer
/// conditions), converging as N doubles; the semicircle under a horizontal acceleration,
/// both weight models, μ = ∞ and 0.6, and a point load. (The 10-digit comparison is with
/// the independent exchange reference of `load_continuum_reference.rs`.)
#[test]
fn continuous_lambda_static_against_fine_discretisations() {
    let settings = Settings::default();
    let lam = |arch: &Arch, eta: f64, mu: f64, load: &LiveLoad| match static_range(
        arch, eta, mu, load, &settings,
    )
    .unwrap()
    .unwrap()
    {
        StaticRange::Interval { max: Some(m), .. } => m.0,
        other => panic!("{other:?}"),
    };
    for (weight, eta, mu, load) in [
        (
            WeightModel::Centreline,
            0.2,
            f64::INFINITY,
            LiveLoad::Horizontal {
                towards_right: true,
            },
        ),
        (
            WeightModel::Centroid,
            0.3,
            f64::INFINITY,
            LiveLoad::Horizontal {
                towards_right: false,
            },
        ),
        (
            WeightModel::Centreline,
            0.2,
            0.6,
            LiveLoad::Horizontal {
                towards_right: true,
            },
        ),
        (
            WeightModel::Centreline,
            0.2,
            f64::INFINITY,
            LiveLoad::Point { beta: PI / 3.0 },
        ),
    ] {
        let arch = Arch::symmetric(0.0, weight).unwrap();
        let exact = lam(&arch, eta, mu, &load);
        // nested grids (N multiple of 6: pi/3 is a joint): more joints, more conditions, so
        // lambda_static(N) does not increase with N and stays at or above the continuum's;
        // it converges irregularly (the hinges fall between joints anywhere)
        let seq: Vec<f64> = [600, 1200, 2400]
            .iter()
            .map(|&n| lam(&arch.clone().with_blocks(n).unwrap(), eta, mu, &load))
            .collect();
        println!(
            "{weight:?} eta {eta} mu {mu} {load:?}: exact {exact:.13} N=600/1200/2400 {seq:.13?}"
        );
        for w in seq.windows(2) {
            assert!(w[1] <= w[0] * (1.0 + 1e-12), "not monotone: {seq:?}");
        }
        assert!(
            seq[2] >= exact * (1.0 - 1e-12),
            "discrete below the continuum: {seq:?} vs {exact}"
        );
        assert!((seq[2] - exact) / exact < 2e-6, "{seq:?} vs {exact}");
    }
}

/// Continuous arches at finite friction: the limit states below λ_static come from two
/// discretisations carried over to the continuum. On random continuous arches under a
/// horizontal acceleration: decided in most cases (the rest say why), the collapse
/// multiplier never above λ_static, and at every limit state positive live power and the
/// virtual-work balance (total external power = frictional dissipation).
#[test]
fn continuous_arches_at_finite_friction() {
    use arch_enum::multiplier::{survey, LoadOutcome};
    let mut rng = Rng(0xc0de_0000_0000_0021);
    let settings = Settings::default();
    let (mut decided, mut total, mut reduced) = (0, 0, 0);
    let mut undecided = Vec::new();
    for case in 0..8 {
        let br = -0.4 + 0.8 * rng.next();
        let bl = PI - 0.4 + 0.8 * rng.next();
        let arch = Arch::new(br, bl, WeightModel::Centreline).unwrap();
        let eta = 0.25 + 0.4 * rng.next();
        let mu = 0.5 + 1.0 * rng.next();
        let load = LiveLoad::Horizontal {
            towards_right: rng.next() < 0.5,
        };
        total += 1;
        match survey(&arch, eta, mu, &load, &settings).unwrap() {
            Ok(LoadOutcome::Limits(s)) => {
                decided += 1;
                let stat = s.lambda_static.unwrap().0;
                if let Some(l) = s.lambda() {
                    assert!(l <= stat * (1.0 + 1e-12), "case {case}: {l} above {stat}");
                    reduced += usize::from(l < stat * (1.0 - 1e-9));
                }
                for st in &s.limit_states {
                    let m = &st.mechanism;
                    assert!(st.live_power > 0.0);
                    assert!(
                        (m.power - m.dissipation).abs() < 1e-8 * (1.0 + m.power.abs()),
                        "case {case}: power {} dissipation {}",
                        m.power,
                        m.dissipation
                    );
                }
            }
            Ok(_) => decided += 1,
            Err(e) => undecided.push(format!("case {case} ({br}, {bl}, eta {eta}, mu {mu}): {e}")),
        }
    }
    println!("{total} continuous arches: {decided} decided, {reduced} with lambda below lambda_static; undecided: {undecided:#?}");
    assert!(decided * 4 >= total * 3, "{undecided:#?}");
}

/// `load-curve --json`: one row per μ and a last row at μ = ∞ (no reduction there), the
/// collapse multiplier never above λ_static.
#[test]
fn load_curve_json() {
    let (v, code) = crate::cli::json_of(&[
        "load-curve",
        "--beta-right",
        "0.2442",
        "--beta-left",
        "3.1489",
        "--joints",
        "0.2442,0.8409,1.2686,2.0653,2.3805,2.7970,3.1489",
        "--eta",
        "0.6364",
        "--horizontal-left",
        "--mu-min",
        "0.6",
        "--mu-max",
        "2",
        "--points",
        "10",
    ]);
    assert_eq!(code, 0);
    let pts = v["points"].as_array().unwrap();
    assert_eq!(pts.len(), 11);
    assert_eq!(pts[10]["mu"], serde_json::Value::Null);
    assert_eq!(pts[10]["reduction"].as_f64(), Some(0.0));
    let mut reduced = 0;
    for p in pts {
        assert_eq!(p["status"], "ok");
        let (l, s) = (
            p["lambda"].as_f64().unwrap(),
            p["lambda_static"].as_f64().unwrap(),
        );
        assert!(l <= s * (1.0 + 1e-12));
        reduced += usize::from(l < s * (1.0 - 1e-9));
    }
    assert!(reduced >= 1, "{v}");
    // the corners, by increasing μ: each between its two sides, an exact one with its
    // five contacts; the reduction window opens and closes with a jump of λ
    let corners = v["corners"].as_array().unwrap();
    assert!(corners.len() >= 5, "{v}");
    let mut last = 0.0;
    let mut jumps = 0;
    for c in corners {
        let (lo, hi) = (
            c["mu_below"].as_f64().unwrap(),
            c["mu_above"].as_f64().unwrap(),
        );
        assert!(lo > last && hi > lo, "{c}");
        last = hi;
        if c["exact"].as_bool().unwrap() {
            let mu = c["mu"].as_f64().unwrap();
            assert!(mu >= lo * (1.0 - 1e-6) && mu <= hi * (1.0 + 1e-6), "{c}");
            assert!(c["lambda"].as_f64().unwrap() > 0.0);
        } else if c["changes"] == 1 {
            assert_eq!(hi, lo.next_up(), "bracket of neighbouring floats: {c}");
        }
        if !c["continuous"].as_bool().unwrap() {
            jumps += 1;
            assert_ne!(c["below"]["pattern"], c["above"]["pattern"]);
        }
    }
    assert!(jumps >= 2, "{v}");
}

/// `plot load-curve` draws; `--json` there is refused, naming the flag.
#[test]
fn plot_load_curve_refuses_json() {
    let out = assert_cmd::Command::cargo_bin("arch-enum")
        .unwrap()
        .args([
            "plot",
            "load-curve",
            "--alpha",
            "0",
            "--blocks",
            "6",
            "--eta",
            "0.3",
            "--horizontal",
            "--json",
        ])
        .output()
        .unwrap();
    assert_eq!(out.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&out.stderr).contains("--json"));
}

/// A horizontal acceleration λ g towards +x added to self-weight is self-weight turned by
/// ψ = atan λ, and every condition is homogeneous in the load's size: the arch under λ at
/// thickness η admits exactly the states (turned) of the arch turned by −ψ, springings
/// (β_R − ψ, β_L − ψ), under self-weight alone. So at ψ = atan λ_static(η) the turned arch
/// stands at η, and its least thickness η_s is where λ_static reaches λ_static(η): η itself
/// where λ_static rises with η, the start of the plateau where it does not (a sliding limit,
/// the same at every thicker ring): λ_static(η_s (1 + 1e-7)) = λ_static(η) and
/// λ_static(η_s (1 − 1e-6)) < λ_static(η). Two implementations of the statics checked
/// against each other (the load's live terms and rows, `multiplier::static_range`; the
/// thickness problem's, `solve`), on random openings, thicknesses, friction, both weight
/// models, continuous and voussoir arches.
#[test]
fn the_load_is_gravity_turned() {
    let settings = Settings::default();
    let load = LiveLoad::Horizontal {
        towards_right: true,
    };
    let mut rng = Rng(0x7117_5eed);
    let (mut equal, mut plateau, mut worst) = (0, 0, 0.0f64);
    for case in 0..60 {
        let alpha = -0.8 + 1.8 * rng.next();
        let weight = if case % 2 == 0 {
            WeightModel::Centreline
        } else {
            WeightModel::Centroid
        };
        let blocks = (case % 3 == 0).then(|| 6 + (30.0 * rng.next()) as usize);
        let shape = |br: f64, bl: f64| {
            let a = Arch::new(br, bl, weight).unwrap();
            match blocks {
                Some(n) => a.with_blocks(n).unwrap(),
                None => a,
            }
        };
        let arch = shape(-alpha, PI + alpha);
        let Some(ms) = arch_enum::least_friction(&arch, &settings).unwrap() else {
            continue;
        };
        let mu = ms * (1.1 + 2.0 * rng.next());
        let arch_enum::Outcome::Limit(ls) = arch_enum::solve(&arch, mu, &settings).unwrap().outcome
        else {
            continue;
        };
        let eta = ls.eta_static * (1.05 + 1.5 * rng.next());
        let top = |eta: f64| match static_range(&arch, eta, mu, &load, &settings).unwrap() {
            Ok(StaticRange::Interval { max: Some(m), .. }) => Some(m.0),
            _ => None,
        };
        let Some(lambda) = top(eta).filter(|_| eta < 1.9) else {
            continue;
        };
        let psi = lambda.atan();
        let turned = shape(-alpha - psi, PI + alpha - psi);
        let eta_s = match arch_enum::solve(&turned, mu, &settings).unwrap().outcome {
            arch_enum::Outcome::Limit(t) => t.eta_static,
            arch_enum::Outcome::Unresolved {
                least_static: Some((e, _)),
                ..
            } => e,
            other => panic!("case {case}: the turned arch: {other:?}"),
        };
        let what = format!("case {case}: alpha {alpha}, {weight:?}, {blocks:?}, mu {mu}, eta {eta}: lambda_static {lambda} turns it to eta_s {eta_s}");
        let rel = (eta_s - eta).abs() / eta;
        if rel < 1e-8 {
            worst = worst.max(rel);
            equal += 1;
            continue;
        }
        assert!(eta_s < eta, "{what}");
        let on = top(eta_s * (1.0 + 1e-7)).unwrap();
        let below = top(eta_s * (1.0 - 1e-6)).unwrap();
        assert!(
            (on - lambda).abs() <= 1e-8 * lambda && below < lambda * (1.0 - 1e-9),
            "{what}: lambda_static {on} just above eta_s, {below} just below"
        );
        plateau += 1;
    }
    eprintln!("gravity turned: eta_s = eta on {equal} cases (worst relative difference {worst:e}), the start of a plateau of lambda_static on {plateau}");
    assert!(
        equal >= 30 && plateau >= 2,
        "only {equal} and {plateau} cases compared"
    );
}
