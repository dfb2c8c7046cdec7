//! An independent brute force for the limit states of a loaded discrete arch (issue 11),
//! written from `loads.md` and the formulation alone (the dead statics of `model.rs`, the
//! live statics and every power written again here, block by block), compared with
//! `arch_enum::multiplier::survey` on random small arches.
//!
//! At fixed (η, μ) every activation function is affine in (x, λ) ∈ R⁴; a limit state needs
//! four active contacts at one point (generic case), i.e. four planes meeting: a 4 × 4
//! linear system. The brute force solves it for every 4-subset of planes, keeps the
//! admissible solutions with λ ≥ 0, and runs its own kinematic LP (compatible rates,
//! Σ = 1, total power ≥ 0, one sliding sense per joint, maximal live power) on every contact
//! active there: a limit state when the live power is positive.

use crate::model::{column, ntm};
use crate::search_reference::{random_joints, Rng};
use arch_enum::contact::ContactKind;
use arch_enum::load::LiveLoad;
use arch_enum::multiplier::{survey, LoadOutcome};
use arch_enum::{Arch, Settings, WeightModel};
use good_lp::{highs, variable, Expression, ProblemVariables, Solution, SolverModel};
use itertools::Itertools;
use std::f64::consts::PI;

const KINDS: [ContactKind; 4] = [
    ContactKind::HingeExtrados,
    ContactKind::HingeIntrados,
    ContactKind::SlidePlus,
    ContactKind::SlideMinus,
];

/// One section: its angle, whether it is the loaded side of a split joint, and its
/// index in the list of sections (for the block structure).
#[derive(Debug, Clone, Copy)]
struct Section {
    beta: f64,
    /// At a joint carrying the point load: `false` for the section just before the load,
    /// `true` just after (its free body [β_R, β] contains the load).
    loaded_side: bool,
}

struct Case {
    joints: Vec<f64>,
    centroid: bool,
    eta: f64,
    mu: f64,
    load: LiveLoad,
    sections: Vec<Section>,
    /// (section index, kind): every contact.
    contacts: Vec<(usize, ContactKind)>,
}

impl Case {
    fn new(joints: &[f64], centroid: bool, eta: f64, mu: f64, load: LiveLoad) -> Case {
        let mut sections = Vec::new();
        for &b in joints {
            match load {
                LiveLoad::Point { beta } if beta == b => {
                    sections.push(Section {
                        beta: b,
                        loaded_side: false,
                    });
                    sections.push(Section {
                        beta: b,
                        loaded_side: true,
                    });
                }
                _ => sections.push(Section {
                    beta: b,
                    loaded_side: false,
                }),
            }
        }
        let kinds: &[ContactKind] = if mu.is_finite() { &KINDS } else { &KINDS[..2] };
        let contacts = (0..sections.len())
            .flat_map(|s| kinds.iter().map(move |&k| (s, k)))
            .collect();
        Case {
            joints: joints.to_vec(),
            centroid,
            eta,
            mu,
            load,
            sections,
            contacts,
        }
    }

    fn rho(&self) -> f64 {
        if self.centroid {
            1.0 + self.eta * self.eta / 12.0
        } else {
            1.0
        }
    }

    /// (N, T, M) per unit λ of the live load at a section (loads.md, written again).
    fn live(&self, s: Section) -> [f64; 3] {
        let br = self.joints[0];
        let b = s.beta;
        match self.load {
            LiveLoad::Horizontal { towards_right } => {
                let k = if towards_right { 1.0 } else { -1.0 };
                let d = b - br;
                [
                    -k * d * b.sin(),
                    -k * d * b.cos(),
                    -k * (self.rho() * (br.cos() - b.cos()) - d * b.sin()),
                ]
            }
            LiveLoad::Point { beta } => {
                if b > beta || (b == beta && s.loaded_side) {
                    [
                        -b.cos(),
                        b.sin(),
                        -((1.0 + self.eta / 2.0) * beta.cos() - b.cos()),
                    ]
                } else {
                    [0.0; 3]
                }
            }
        }
    }

    /// The activation function of a contact as (a, c): a · (h, v, w, λ) + c.
    fn row(&self, (s, kind): (usize, ContactKind)) -> ([f64; 4], f64) {
        let sec = self.sections[s];
        let br = self.joints[0];
        let f = |x: [f64; 3]| {
            let (n, t, m) = ntm(br, self.rho(), x, sec.beta);
            self.combine(kind, n, t, m)
        };
        let c = f([0.0; 3]);
        let g = [
            f([1.0, 0.0, 0.0]) - c,
            f([0.0, 1.0, 0.0]) - c,
            f([0.0, 0.0, 1.0]) - c,
        ];
        let [nl, tl, ml] = self.live(sec);
        ([g[0], g[1], g[2], self.combine(kind, nl, tl, ml)], c)
    }

    fn combine(&self, kind: ContactKind, n: f64, t: f64, m: f64) -> f64 {
        match kind {
            ContactKind::HingeExtrados => m - self.eta * n / 2.0,
            ContactKind::HingeIntrados => -m - self.eta * n / 2.0,
            ContactKind::SlidePlus => t - self.mu * n,
            ContactKind::SlideMinus => -t - self.mu * n,
        }
    }

    /// Dead and live power of unit rates of each contact in `active`, block by block: the
    /// pieces between consecutive sections move with the sum of the columns of the active
    /// contacts at or before their start; the zero-width piece between the two sections of
    /// a loaded joint carries the point load.
    fn powers(&self, active: &[(usize, ContactKind)]) -> (Vec<f64>, Vec<f64>) {
        let rho = self.rho();
        let n = active.len();
        let (mut dead, mut live) = (vec![0.0; n], vec![0.0; n]);
        for (i, &(s, kind)) in active.iter().enumerate() {
            let col = column(kind, self.sections[s].beta, self.eta);
            // every piece after section s: between sections k and k+1 for k >= s
            for k in s..self.sections.len() - 1 {
                let (a, b) = (self.sections[k].beta, self.sections[k + 1].beta);
                let w = b - a;
                let wgx = rho * (b.sin() - a.sin());
                let wgy = rho * (a.cos() - b.cos());
                dead[i] -= w * col[1] + col[2] * wgx;
                match self.load {
                    LiveLoad::Horizontal { towards_right } => {
                        let k = if towards_right { 1.0 } else { -1.0 };
                        live[i] += k * (w * col[0] - col[2] * wgy);
                    }
                    LiveLoad::Point { beta } => {
                        // the load sits on this piece: strictly inside it, or it is the
                        // zero-width piece of the loaded joint
                        if (a < beta && beta < b) || (a == beta && b == beta) {
                            let px = (1.0 + self.eta / 2.0) * beta.cos();
                            live[i] -= col[1] + col[2] * px;
                        }
                    }
                }
            }
        }
        (dead, live)
    }

    /// The largest live power of compatible rates on `active` (Σ = 1, total power ≥ 0,
    /// one sliding sense per section), or `None` if no such rates exist.
    fn mechanism(&self, active: &[(usize, ContactKind)], lambda: f64) -> Option<f64> {
        let both: Vec<usize> = active
            .iter()
            .filter(|&&(s, k)| {
                k == ContactKind::SlidePlus && active.contains(&(s, ContactKind::SlideMinus))
            })
            .map(|&(s, _)| s)
            .collect();
        let mut best: Option<f64> = None;
        for choice in 0..(1usize << both.len()) {
            let keep: Vec<(usize, ContactKind)> = active
                .iter()
                .copied()
                .filter(|&(s, k)| match both.iter().position(|&b| b == s) {
                    None => true,
                    Some(p) => match k {
                        ContactKind::SlidePlus => choice >> p & 1 == 0,
                        ContactKind::SlideMinus => choice >> p & 1 == 1,
                        _ => true,
                    },
                })
                .collect();
            let (dead, live) = self.powers(&keep);
            let mut vars = ProblemVariables::new();
            let r: Vec<_> = keep.iter().map(|_| vars.add(variable().min(0.0))).collect();
            let mut obj = Expression::from(0.0);
            for (i, &ri) in r.iter().enumerate() {
                obj += live[i] * ri;
            }
            let mut p = vars
                .maximise(obj)
                .using(highs)
                .set_option("output_flag", false)
                .set_option("primal_feasibility_tolerance", 1e-10);
            for row in 0..3 {
                let mut e = Expression::from(0.0);
                for (i, &(s, k)) in keep.iter().enumerate() {
                    e += column(k, self.sections[s].beta, self.eta)[row] * r[i];
                }
                p = p.with(e.eq(0.0));
            }
            let mut total = Expression::from(0.0);
            let mut sum = Expression::from(0.0);
            for (i, &ri) in r.iter().enumerate() {
                total += (dead[i] + lambda * live[i]) * ri;
                sum += ri;
            }
            p = p.with(total.geq(0.0)).with(sum.eq(1.0));
            if let Ok(sol) = p.solve() {
                let lp: f64 = r
                    .iter()
                    .enumerate()
                    .map(|(i, &ri)| live[i] * sol.value(ri))
                    .sum();
                if lp > 1e-9 && best.is_none_or(|b| lp > b) {
                    best = Some(lp);
                }
            }
        }
        best
    }

    /// Pairs of contacts (indices into `contacts`) whose columns cancel, with positive
    /// live power of the rates (½, ½): wherever both are active they carry that mechanism,
    /// so the limit states with both active form a continuum; its least λ (own LP: rows
    /// ≤ 0, the pair = 0, total power ≥ 0, λ ≥ 0).
    fn continua(&self, rows: &[([f64; 4], f64)]) -> Vec<((usize, usize), f64)> {
        let mut out = Vec::new();
        for i in 0..self.contacts.len() {
            for j in i + 1..self.contacts.len() {
                let ((si, ki), (sj, kj)) = (self.contacts[i], self.contacts[j]);
                if si == sj {
                    continue;
                }
                let (ci, cj) = (
                    column(ki, self.sections[si].beta, self.eta),
                    column(kj, self.sections[sj].beta, self.eta),
                );
                if (0..3).any(|k| (ci[k] + cj[k]).abs() > 1e-12) {
                    continue;
                }
                let (dead, live) = self.powers(&[self.contacts[i], self.contacts[j]]);
                let (d, l) = (0.5 * (dead[0] + dead[1]), 0.5 * (live[0] + live[1]));
                if l <= 1e-9 {
                    continue;
                }
                let mut vars = ProblemVariables::new();
                let z: Vec<_> = (0..4)
                    .map(|k| {
                        vars.add(if k == 3 {
                            variable().min(0.0)
                        } else {
                            variable()
                        })
                    })
                    .collect();
                let mut p = vars
                    .minimise(z[3])
                    .using(highs)
                    .set_option("output_flag", false)
                    .set_option("primal_feasibility_tolerance", 1e-10);
                let expr = |a: &[f64; 4]| {
                    let mut e = Expression::from(0.0);
                    for k in 0..4 {
                        e += a[k] * z[k];
                    }
                    e
                };
                for (r, (a, c)) in rows.iter().enumerate() {
                    p = if r == i || r == j {
                        p.with(expr(a).eq(-c))
                    } else {
                        p.with(expr(a).leq(-c))
                    };
                }
                p = p.with((l * z[3]).geq(-d));
                if let Ok(sol) = p.solve() {
                    out.push(((i, j), sol.value(z[3])));
                }
            }
        }
        out
    }

    /// Every limit state's λ (distinct to 1e-9 relative), ascending; a continuum by its
    /// least λ.
    fn brute_force(&self) -> Vec<f64> {
        let rows: Vec<([f64; 4], f64)> = self.contacts.iter().map(|&c| self.row(c)).collect();
        let scale = |z: &[f64; 4]| 1.0 + z.iter().map(|v| v.abs()).sum::<f64>();
        let continua = self.continua(&rows);
        let mut found: Vec<f64> = continua.iter().map(|c| c.1).collect();
        // the least admissible λ: where it is positive the arch fails there by unloading,
        // and no state at it counts as a collapse under the load (issue 11)
        let lambda_min = {
            let mut vars = ProblemVariables::new();
            let z: Vec<_> = (0..4)
                .map(|k| {
                    vars.add(if k == 3 {
                        variable().min(0.0)
                    } else {
                        variable()
                    })
                })
                .collect();
            let mut p = vars
                .minimise(z[3])
                .using(highs)
                .set_option("output_flag", false)
                .set_option("primal_feasibility_tolerance", 1e-10);
            for (a, c) in &rows {
                let mut e = Expression::from(0.0);
                for k in 0..4 {
                    e += a[k] * z[k];
                }
                p = p.with(e.leq(-c));
            }
            p.solve().map_or(0.0, |sol| sol.value(z[3]))
        };
        for quad in (0..rows.len()).combinations(4) {
            let a = nalgebra::Matrix4::from_fn(|r, c| rows[quad[r]].0[c]);
            let b = nalgebra::Vector4::from_fn(|r, _| -rows[quad[r]].1);
            let Some(z) = a.lu().solve(&b) else { continue };
            let z = [z[0], z[1], z[2], z[3]];
            if !z.iter().all(|v| v.is_finite()) || z[3] < -1e-12 || scale(&z) > 1e6 {
                continue;
            }
            let tol = 1e-9 * scale(&z);
            let values: Vec<f64> = rows
                .iter()
                .map(|(a, c)| a[0] * z[0] + a[1] * z[1] + a[2] * z[2] + a[3] * z[3] + c)
                .collect();
            if values.iter().any(|&v| v > tol) {
                continue;
            }
            let lambda = z[3].max(0.0);
            if lambda_min > 1e-12 && lambda <= lambda_min * (1.0 + 1e-9) {
                continue;
            }
            if found
                .iter()
                .any(|&f| (f - lambda).abs() <= 1e-9 * (1.0 + lambda))
            {
                continue;
            }
            let active_rows: Vec<usize> = (0..rows.len())
                .filter(|&i| values[i].abs() <= tol)
                .collect();
            if continua
                .iter()
                .any(|((i, j), _)| active_rows.contains(i) && active_rows.contains(j))
            {
                continue; // a state of a continuum, listed by its least state
            }
            let active: Vec<(usize, ContactKind)> =
                active_rows.iter().map(|&i| self.contacts[i]).collect();
            if let Some(lp) = self.mechanism(&active, lambda) {
                if std::env::var("LOAD_DEBUG").is_ok() {
                    let desc: Vec<String> = active
                        .iter()
                        .map(|&(s, k)| {
                            format!(
                                "{}{}{:?}",
                                s,
                                if self.sections[s].loaded_side {
                                    "+"
                                } else {
                                    ""
                                },
                                k
                            )
                        })
                        .collect();
                    println!(
                        "brute force: lambda {lambda} z {z:?} live power {lp:e} active {desc:?}"
                    );
                }
                found.push(lambda);
            }
        }
        found.sort_by(f64::total_cmp);
        found
    }
}

/// The crate's limit states against the brute force on random small discrete arches:
/// horizontal loads either way and point loads at a joint or inside a voussoir, both
/// weight models, finite and infinite friction, thicknesses around the unloaded least
/// thickness. `LOAD_CASES=N` runs more (the CI runs 40).
#[test]
fn loaded_arches_match_the_brute_force() {
    let count: usize = std::env::var("LOAD_CASES")
        .ok()
        .and_then(|v| v.parse().ok())
        .unwrap_or(40);
    let mut rng = Rng(0x10ad_b47e_0000_0001);
    let settings = Settings::default();
    let (mut compared, mut reduced, mut nonunique, mut skipped) = (0, 0, 0, 0);
    let mut failures = Vec::new();
    for case in 0..count {
        let n = 3 + (rng.next() * 4.0) as usize;
        let br = -0.5 + 1.0 * rng.next();
        let bl = PI - 0.5 + 1.0 * rng.next();
        let joints = random_joints(&mut rng, br, bl, n);
        let centroid = rng.next() < 0.3;
        let weight = if centroid {
            WeightModel::Centroid
        } else {
            WeightModel::Centreline
        };
        let arch = Arch::new(br, bl, weight)
            .unwrap()
            .with_joints(&joints)
            .unwrap();
        let mu = if rng.next() < 0.2 {
            f64::INFINITY
        } else {
            0.3 + 1.5 * rng.next()
        };
        let eta = 0.15 + 0.5 * rng.next();
        let load = match (rng.next() * 4.0) as usize {
            0 => LiveLoad::Horizontal {
                towards_right: true,
            },
            1 => LiveLoad::Horizontal {
                towards_right: false,
            },
            2 => LiveLoad::Point {
                beta: joints[1 + (rng.next() * (joints.len() - 2) as f64) as usize],
            },
            _ => LiveLoad::Point {
                beta: br + (bl - br) * (0.05 + 0.9 * rng.next()),
            },
        };
        let reference = Case::new(&joints, centroid, eta, mu, load).brute_force();
        let crate_states: Vec<f64> = match survey(&arch, eta, mu, &load, &settings).unwrap() {
            Ok(LoadOutcome::Limits(s)) => {
                let mut v: Vec<f64> = s.limit_states.iter().map(|l| l.lambda).collect();
                v.dedup_by(|a, b| (*a - *b).abs() <= 1e-9 * (1.0 + b.abs()));
                if s.reduction().is_some_and(|r| r > 1e-9) {
                    reduced += 1;
                }
                if v.len() > 1 {
                    nonunique += 1;
                }
                v
            }
            Ok(LoadOutcome::NoEquilibrium) | Ok(LoadOutcome::NoCollapse { .. }) => {
                skipped += 1;
                Vec::new()
            }
            Err(e) => {
                failures.push(format!("case {case}: no decision: {e}"));
                continue;
            }
        };
        compared += 1;
        let same = crate_states.len() == reference.len()
            && crate_states
                .iter()
                .zip(&reference)
                .all(|(a, b)| (a - b).abs() <= 1e-8 * (1.0 + b.abs()));
        if !same {
            failures.push(format!(
                "case {case}: joints {joints:?} centroid {centroid} eta {eta} mu {mu} {load:?}: crate {crate_states:?} vs brute force {reference:?}"
            ));
        }
    }
    println!(
        "{compared} loaded arches compared ({skipped} no_equilibrium or no_collapse), {reduced} with the collapse multiplier below lambda_static, {nonunique} with several limit states, {} disagreements",
        failures.len()
    );
    assert!(failures.is_empty(), "{}", failures.join("\n"));
}
