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

pub(crate) struct Case {
    joints: Vec<f64>,
    centroid: bool,
    eta: f64,
    mu: f64,
    load: LiveLoad,
    sections: Vec<Section>,
    /// (section index, kind): every contact.
    contacts: Vec<(usize, ContactKind)>,
    /// Fill above the extrados (g_f = γ_f/γ, depth h above its highest point over r): a
    /// dead load integrated here by Simpson's rule (bridge spec §2, written again).
    fill: Option<(f64, f64)>,
}

impl Case {
    pub(crate) fn new(joints: &[f64], centroid: bool, eta: f64, mu: f64, load: LiveLoad) -> Case {
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
            fill: None,
        }
    }

    /// The fill's resultant and first moment (F, S) on the extrados of the angles [lo, hi].
    fn fill_force(&self, lo: f64, hi: f64) -> (f64, f64) {
        let Some((gf, h)) = self.fill else {
            return (0.0, 0.0);
        };
        let springings = (self.joints[0], *self.joints.last().unwrap());
        fill_by_simpson(gf, h, self.eta, springings, (lo, hi))
    }

    /// A pressure's resultant and first moment on the extrados of the angles [lo, hi]:
    /// each patch's part over the horizontal extent of those extrados points, and the point
    /// loads in (lo, hi].
    fn pressure_force(&self, lo: f64, hi: f64) -> (f64, f64) {
        let LiveLoad::Pressure(p) = self.load else {
            return (0.0, 0.0);
        };
        let (br, bl) = (self.joints[0], *self.joints.last().unwrap());
        let (a, b) = (lo.max(br).max(0.0), hi.min(bl).min(PI));
        if b <= a {
            return (0.0, 0.0);
        }
        let kappa = 1.0 + self.eta / 2.0;
        let (x_lo, x_hi) = (kappa * b.cos(), kappa * a.cos());
        let (mut f, mut m) = (0.0, 0.0);
        for patch in p.patches() {
            let (u, v) = (patch.x_lo.max(x_lo), patch.x_hi.min(x_hi));
            if u < v {
                f += patch.q * (v - u);
                m += patch.q * (v * v - u * u) / 2.0;
            }
        }
        // point loads inside voussoirs (the generator puts none at a joint)
        for point in p.points() {
            if lo < point.beta && point.beta <= hi {
                f += point.q;
                m += point.q * kappa * point.beta.cos();
            }
        }
        (f, m)
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
            LiveLoad::Pressure(_) => {
                let (f, m) = self.pressure_force(br, b);
                [-f * b.cos(), f * b.sin(), f * b.cos() - m]
            }
        }
    }

    /// Every contact: (section index, kind).
    pub(crate) fn contacts(&self) -> &[(usize, ContactKind)] {
        &self.contacts
    }

    /// The activation function of a contact as (a, c): a · (h, v, w, λ) + c.
    pub(crate) fn row(&self, (s, kind): (usize, ContactKind)) -> ([f64; 4], f64) {
        let sec = self.sections[s];
        let br = self.joints[0];
        // a vertical dead load F at the horizontal position S/F on the free body [β_R, β]
        let (ff, fs) = self.fill_force(br, sec.beta);
        let (cb, sb) = (sec.beta.cos(), sec.beta.sin());
        let f = |x: [f64; 3]| {
            let (n, t, m) = ntm(br, self.rho(), x, sec.beta);
            self.combine(kind, n - ff * cb, t + ff * sb, m + ff * cb - fs)
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
                let (ff, fs) = self.fill_force(a, b);
                dead[i] -= ff * col[1] + col[2] * fs;
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
                    LiveLoad::Pressure(_) => {
                        let (f, m) = self.pressure_force(a, b);
                        live[i] -= col[1] * f + col[2] * m;
                    }
                }
            }
        }
        (dead, live)
    }

    /// The largest live power of compatible rates on `active` (Σ = 1, total power ≥ 0,
    /// one sliding sense per section), or `None` if no such rates exist.
    pub(crate) fn mechanism(&self, active: &[(usize, ContactKind)], lambda: f64) -> Option<f64> {
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
    pub(crate) fn brute_force(&self) -> Vec<f64> {
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
        for (z, values) in meeting_points(&rows) {
            let tol = 1e-9 * scale(&z);
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

/// Every point where four of `rows` (a · (h, v, w, λ) + c ≤ 0) meet with every row holding
/// to 1e-9 of 1 + ‖z‖₁, λ ≥ 0 and ‖z‖₁ < 10⁶: the point and every row's value there (once
/// per four rows: a point where more rows meet comes once for each four of them).
pub(crate) fn meeting_points(rows: &[([f64; 4], f64)]) -> Vec<([f64; 4], Vec<f64>)> {
    let scale = |z: &[f64; 4]| 1.0 + z.iter().map(|v| v.abs()).sum::<f64>();
    let mut out = Vec::new();
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
        if values.iter().all(|&v| v <= tol) {
            out.push((z, values));
        }
    }
    out
}

/// The fill's resultant and first moment about the centre's vertical, (F, S), on the extrados
/// of the angles [lo, hi] of the arch with springings (β_R, β_L) at thickness η: the weight of
/// the column above each point of the upward-facing extrados up to the road, h above the
/// highest extrados point, by composite Simpson (4000 intervals; bridge spec §2 written
/// again, with no use of `arch_enum::fill`).
pub(crate) fn fill_by_simpson(
    gf: f64,
    h: f64,
    eta: f64,
    (br, bl): (f64, f64),
    (lo, hi): (f64, f64),
) -> (f64, f64) {
    let kappa = 1.0 + eta / 2.0;
    let top = if br <= PI / 2.0 && bl >= PI / 2.0 {
        1.0
    } else {
        br.sin().max(bl.sin())
    };
    let road = kappa * top + h;
    let (a, b) = (lo.max(br).max(0.0), hi.min(PI));
    if b <= a {
        return (0.0, 0.0);
    }
    // the column's height times its horizontal width per dθ, d(κ cos θ) = κ sin θ dθ
    let p = |t: f64| gf / eta * (road - kappa * t.sin()) * kappa * t.sin();
    let n = 4000;
    let step = (b - a) / n as f64;
    let (mut f, mut m) = (0.0, 0.0);
    for i in 0..=n {
        let t = a + step * i as f64;
        let w = if i == 0 || i == n {
            1.0
        } else if i % 2 == 1 {
            4.0
        } else {
            2.0
        };
        f += w * p(t);
        m += w * p(t) * kappa * t.cos();
    }
    (f * step / 3.0, m * step / 3.0)
}

/// The crate's answer as the brute force gives it.
enum Answer {
    /// The λ of every limit state (ascending, distinct to 1e-9), and whether the least lies
    /// below λ_static.
    Limits {
        lambdas: Vec<f64>,
        reduced: bool,
    },
    NoEquilibrium,
    NoCollapse,
}

/// The crate's survey as an [`Answer`]; `Err` the reason it decided nothing.
fn crate_answer(
    outcome: Result<LoadOutcome, arch_enum::undecided::Undecided>,
) -> Result<Answer, String> {
    match outcome {
        Ok(LoadOutcome::Limits(s)) => {
            let mut lambdas: Vec<f64> = s.limit_states.iter().map(|l| l.t).collect();
            lambdas.dedup_by(|a, b| (*a - *b).abs() <= 1e-9 * (1.0 + b.abs()));
            let reduced = s.reduction().is_some_and(|r| r > 1e-9);
            Ok(Answer::Limits { lambdas, reduced })
        }
        Ok(LoadOutcome::NoEquilibrium) => Ok(Answer::NoEquilibrium),
        Ok(LoadOutcome::NoCollapse { .. }) => Ok(Answer::NoCollapse),
        Err(e) => Err(e.to_string()),
    }
}

/// The crate's limit states' λ (ascending, distinct to 1e-9) against the brute force's, to
/// 1e-8 relative: the same list.
fn same_lambdas(crate_states: &[f64], reference: &[f64]) -> bool {
    crate_states.len() == reference.len()
        && crate_states
            .iter()
            .zip(reference)
            .all(|(a, b)| (a - b).abs() <= 1e-8 * (1.0 + b.abs()))
}

/// A random small loaded discrete arch: 3–6 voussoirs, springings within ±0.5 rad of the
/// semicircle's, 30 % true-centroid weight, 20 % μ = ∞ else μ in [0.3, 1.8], η in
/// [0.15, 0.65], a horizontal load either way or a point load at a joint or inside a voussoir.
pub(crate) struct RandomLoaded {
    pub joints: Vec<f64>,
    pub weight: WeightModel,
    pub arch: Arch,
    pub mu: f64,
    pub eta: f64,
    pub load: LiveLoad,
}

/// Draws a [`RandomLoaded`] case.
pub(crate) fn random_loaded(rng: &mut Rng) -> RandomLoaded {
    let n = 3 + (rng.next() * 4.0) as usize;
    let br = -0.5 + 1.0 * rng.next();
    let bl = PI - 0.5 + 1.0 * rng.next();
    let joints = random_joints(rng, br, bl, n);
    let weight = if rng.next() < 0.3 {
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
    RandomLoaded {
        joints,
        weight,
        arch,
        mu,
        eta,
        load,
    }
}

/// The crate's limit states against the brute force on random small discrete arches:
/// horizontal loads either way and point loads at a joint or inside a voussoir, both
/// weight models, finite and infinite friction, thicknesses around the unloaded least
/// thickness. `LOAD_CASES=N` runs more (the CI runs 40).
#[test]
fn loaded_arches_match_the_brute_force() {
    let count = crate::cases_from_env("LOAD_CASES", 40);
    let mut rng = Rng(0x10ad_b47e_0000_0001);
    let settings = Settings::default();
    let (mut compared, mut reduced, mut nonunique, mut skipped) = (0, 0, 0, 0);
    let mut failures = Vec::new();
    for case in 0..count {
        let RandomLoaded {
            joints,
            weight,
            arch,
            mu,
            eta,
            load,
        } = random_loaded(&mut rng);
        let centroid = weight == WeightModel::Centroid;
        let reference = Case::new(&joints, centroid, eta, mu, load).brute_force();
        let crate_states = match crate_answer(survey(&arch, eta, mu, &load, &settings).unwrap()) {
            Ok(Answer::Limits {
                lambdas,
                reduced: r,
            }) => {
                reduced += usize::from(r);
                nonunique += usize::from(lambdas.len() > 1);
                lambdas
            }
            Ok(Answer::NoEquilibrium | Answer::NoCollapse) => {
                skipped += 1;
                Vec::new()
            }
            Err(e) => {
                failures.push(format!("case {case}: no decision: {e}"));
                continue;
            }
        };
        compared += 1;
        if !same_lambdas(&crate_states, &reference) {
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

/// The corners of the λ–μ curve (`multiplier::trace`) against the brute force on random
/// small arches at finite friction: 1e-7 (relative) to either side of every corner the
/// crate's branch is the corner's and the brute force's least limit state has the crate's
/// λ; at an exact corner the reference's own activation
/// functions of the five contacts vanish at (x, λ, μ) and every other one is ≤ 0 there;
/// a bracketed corner's ends are neighbouring floats. Where the arch starts to stand
/// (λ → 0) a state at λ = 0 to rounding may be a limit state at 0 on one side and none on
/// the other: both count as "about 0". `CORNER_CASES=N` runs more.
#[test]
fn load_curve_corners_match_the_brute_force() {
    use arch_enum::load::Side;
    use arch_enum::multiplier::curve::branch_key;
    use arch_enum::multiplier::trace;
    let count = crate::cases_from_env("CORNER_CASES", 6);
    let mut rng = Rng(0xc0_4e45_0000_0002);
    let settings = Settings::default();
    let (mut exact, mut bracketed, mut jumps, mut far, mut clustered, mut chatter) =
        (0, 0, 0, 0, 0, 0);
    let mut failures = Vec::new();
    let least = |r: &[f64]| r.first().copied();
    for case in 0..count {
        let n = 3 + (rng.next() * 3.0) as usize;
        let br = -0.4 + 0.8 * rng.next();
        let bl = PI - 0.4 + 0.8 * rng.next();
        let joints = random_joints(&mut rng, br, bl, n);
        let arch = Arch::new(br, bl, WeightModel::Centreline)
            .unwrap()
            .with_joints(&joints)
            .unwrap();
        let eta = 0.2 + 0.45 * rng.next();
        let load = match (rng.next() * 3.0) as usize {
            0 => LiveLoad::Horizontal {
                towards_right: true,
            },
            1 => LiveLoad::Horizontal {
                towards_right: false,
            },
            _ => LiveLoad::Point {
                beta: joints[1 + (rng.next() * (joints.len() - 2) as f64) as usize],
            },
        };
        let mus: Vec<f64> = (0..8).map(|i| 0.3 * 1.3f64.powi(i)).collect();
        let curve = trace(&arch, eta, &load, &mus, &settings, &|_, _| {}).unwrap();
        let lambda_of = |o: &arch_enum::multiplier::LoadAnswer| match o {
            Ok(LoadOutcome::Limits(s)) => s.lambda(),
            _ => None,
        };
        let at_of = |c: &arch_enum::multiplier::curve::Corner| c.mu;
        for (ci, c) in curve.corners.iter().enumerate() {
            if !c.above().0.is_finite() {
                continue;
            }
            // near-unbounded multipliers (reactions ~λ) are beyond the brute force's box
            let big = |o: &arch_enum::multiplier::LoadAnswer| match o {
                Ok(LoadOutcome::Limits(s)) => {
                    s.lambda_static.is_none_or(|m| m.0 > 1e3) || s.lambda().is_some_and(|l| l > 1e3)
                }
                _ => false,
            };
            if big(&c.below().1) || big(&c.above().1) {
                far += 1;
                continue;
            }
            // 1e-7 (relative) away; a corner with a neighbour closer than 1e-4 (a cluster of
            // branch changes that is not one five-contact point) is counted, not compared
            let mu_c = at_of(c);
            let delta = 1e-7 * mu_c;
            let near = |n: Option<&arch_enum::multiplier::curve::Corner>| {
                n.is_some_and(|n| (at_of(n) - mu_c).abs() < 1e-4 * mu_c)
            };
            if near(ci.checked_sub(1).and_then(|i| curve.corners.get(i)))
                || near(curve.corners.get(ci + 1))
            {
                clustered += 1;
                continue;
            }
            // on each side, 1e-6 away (the corner itself is degenerate by construction):
            // the crate's branch is the corner's, and its λ is the brute force's
            let key =
                |o: &arch_enum::multiplier::LoadAnswer| branch_key(&arch, &load, o, &settings);
            let mut reference_sides = Vec::new();
            for (mu, side) in [
                (c.below().0 - delta, c.below()),
                (c.above().0 + delta, c.above()),
            ] {
                let o = arch_enum::multiplier::survey_partial(&arch, eta, mu, &load, &settings)
                    .unwrap();
                if o.is_err() || side.1.is_err() {
                    continue;
                }
                if key(&o) != key(&side.1) {
                    // another change of branch within 1e-7 that the bisection did not
                    // bracket: counted and printed (the note reports it); λ still compared
                    chatter += 1;
                }
                let ours = lambda_of(&o);
                let reference = least(&Case::new(&joints, false, eta, mu, load).brute_force());
                reference_sides.push(reference);
                // where the arch starts to stand (λ_static → 0) a state at λ = 0 to rounding
                // is a limit state at 0 or none, by the last bits: both say "about 0"
                let nil = |l: Option<f64>| l.is_none_or(|l| l.abs() <= 1e-9);
                let agree = match (ours, reference) {
                    (Some(a), Some(b)) => (a - b).abs() <= 1e-8 * (1.0 + b.abs()),
                    (None, None) => true,
                    (a, b) => nil(a) && nil(b),
                };
                if !agree {
                    failures.push(format!(
                        "case {case} ({joints:?}, eta {eta}, {load:?}): at mu {mu} crate {ours:?} vs brute force {reference:?}"
                    ));
                }
            }
            // continuity, by the brute force: λ 1e-6 away on both sides within what the
            // branches' slopes allow (continuous), or apart by more (a jump)
            if let [Some(a), Some(b)] = reference_sides[..] {
                let close = (a - b).abs() <= 1e-4 * (1.0 + a.abs());
                if close != c.continuous(1e-9) {
                    failures.push(format!(
                        "case {case}: corner at mu {mu_c}: continuous {} (lambda {:?}, bracket {} .. {}, exact {}) but the brute force gives {a} and {b} either side",
                        c.continuous(1e-9), c.lambdas(), c.below().0, c.above().0, c.exact
                    ));
                }
            }
            if !c.continuous(1e-9) {
                jumps += 1;
            }
            match c.exact.then_some(c) {
                None => {
                    bracketed += 1;
                    if c.above().0 != c.below().0.next_up()
                        && c.detail.bracketed
                        && c.detail.changes == 1
                    {
                        failures.push(format!(
                            "case {case}: bracket [{}, {}] is not two neighbouring floats",
                            c.below().0,
                            c.above().0
                        ));
                    }
                }
                Some(e) => {
                    exact += 1;
                    let reference = Case::new(&joints, false, eta, e.mu, load);
                    let z = [e.x[0], e.x[1], e.x[2], e.t];
                    let scale = 1.0 + z.iter().map(|v| v.abs()).sum::<f64>();
                    let value = |(a, c): ([f64; 4], f64)| {
                        a[0] * z[0] + a[1] * z[1] + a[2] * z[2] + a[3] * z[3] + c
                    };
                    for (contact, side) in &e.pattern {
                        let s = reference
                            .sections
                            .iter()
                            .position(|s| {
                                s.beta == contact.beta
                                    && (s.loaded_side
                                        == (*side == Side::After && load.splits(s.beta)))
                            })
                            .expect("a section of the reference");
                        let v = value(reference.row((s, contact.kind)));
                        if v.abs() > 1e-12 * scale {
                            failures.push(format!(
                                "case {case}: corner mu {}: {contact:?} {side:?} = {v:e}, not 0",
                                e.mu
                            ));
                        }
                    }
                    let worst = reference
                        .contacts
                        .iter()
                        .map(|&c| value(reference.row(c)))
                        .fold(f64::NEG_INFINITY, f64::max);
                    if worst > 1e-10 * scale {
                        failures.push(format!(
                            "case {case}: corner mu {}: not admissible ({worst:e})",
                            e.mu
                        ));
                    }
                }
            }
        }
    }
    println!(
        "{count} curves: {exact} exact corners, {bracketed} bracketed to neighbouring floats, {jumps} where lambda jumps, {far} with lambda or lambda_static > 1e3 and {clustered} in clusters not compared; {chatter} sides where another change of branch lies within 1e-7; {} disagreements",
        failures.len()
    );
    assert!(
        exact + bracketed > 0,
        "no corner met: the test checks nothing"
    );
    assert!(failures.is_empty(), "{}", failures.join("\n"));
}

/// The vertices of the optimal face {x : admissible at λ_static} by the reference's own
/// rows and LPs (HiGHS): λ held within 1e-12 (relative) of `lambda`, each of ±h, ±v, ±w
/// optimised; each vertex as its active contacts (within 1e-9), distinct.
fn face_vertices(case: &Case, lambda: f64) -> Vec<Vec<(usize, ContactKind)>> {
    let rows: Vec<([f64; 4], f64)> = case.contacts.iter().map(|&c| case.row(c)).collect();
    let mut out: Vec<Vec<(usize, ContactKind)>> = Vec::new();
    for k in 0..3 {
        for sign in [1.0, -1.0] {
            let mut vars = ProblemVariables::new();
            let z: Vec<_> = (0..4).map(|_| vars.add(variable())).collect();
            let mut p = vars
                .minimise(sign * z[k])
                .using(highs)
                .set_option("output_flag", false)
                .set_option("primal_feasibility_tolerance", 1e-10);
            p = p.with((1.0 * z[3]).geq(lambda - 1e-12 * (1.0 + lambda)));
            for (a, c) in &rows {
                let mut e = Expression::from(0.0);
                for q in 0..4 {
                    e += a[q] * z[q];
                }
                p = p.with(e.leq(-c));
            }
            let Ok(sol) = p.solve() else { continue };
            let x = [0, 1, 2, 3].map(|q| sol.value(z[q]));
            let scale = 1.0 + x.iter().map(|v| v.abs()).sum::<f64>();
            let active: Vec<(usize, ContactKind)> = (0..rows.len())
                .filter(|&i| {
                    let (a, c) = rows[i];
                    (a[0] * x[0] + a[1] * x[1] + a[2] * x[2] + a[3] * x[3] + c).abs()
                        <= 1e-9 * scale
                })
                .map(|i| case.contacts[i])
                .collect();
            if !out.contains(&active) {
                out.push(active);
            }
        }
    }
    out
}

/// The state at λ_static does not depend on which optimal vertex the LP returns (a
/// degenerate maximum: the optimal face an edge, e.g. λ_static set by sliding rows, which
/// do not involve w, with w free between two hinge rows). The reference finds the face's
/// vertices itself and decides: where the contacts active on the whole face carry a
/// mechanism with positive live power, the survey must report exactly those contacts at
/// λ_static (a continuum of states when the face is not a point), not the contacts of one
/// vertex; a mechanism at λ_static must exist iff one exists at some vertex. The six-voussoir
/// arch of docs/live-loads.md (its face an edge in w) and random small arches.
#[test]
fn the_state_at_lambda_static_is_the_faces() {
    let settings = Settings::default();
    let readme = (
        vec![0.2442, 0.8409, 1.2686, 2.0653, 2.3805, 2.7970, 3.1489],
        WeightModel::Centreline,
        1.0246,
        0.6364,
        LiveLoad::Horizontal {
            towards_right: false,
        },
    );
    let mut rng = Rng(0xface_0000_0000_0003);
    let mut cases = vec![readme];
    for _ in 0..30 {
        let r = random_loaded(&mut rng);
        cases.push((r.joints, r.weight, r.mu, r.eta, r.load));
    }
    let (mut edges, mut failures) = (0, Vec::new());
    for (n, (joints, weight, mu, eta, load)) in cases.into_iter().enumerate() {
        let arch = Arch::new(joints[0], *joints.last().unwrap(), weight)
            .unwrap()
            .with_joints(&joints)
            .unwrap();
        let Ok(LoadOutcome::Limits(sv)) = survey(&arch, eta, mu, &load, &settings).unwrap() else {
            continue;
        };
        let Some((lambda_s, _)) = sv.lambda_static else {
            continue;
        };
        let case = Case::new(&joints, weight == WeightModel::Centroid, eta, mu, load);
        let vertices = face_vertices(&case, lambda_s);
        if vertices.len() > 1 {
            edges += 1;
        }
        let common: Vec<(usize, ContactKind)> = vertices
            .first()
            .map(|v| {
                v.iter()
                    .copied()
                    .filter(|c| vertices.iter().all(|w| w.contains(c)))
                    .collect()
            })
            .unwrap_or_default();
        let at_static: Vec<_> = sv
            .limit_states
            .iter()
            .filter(|s| s.t >= lambda_s * (1.0 - 1e-9))
            .collect();
        let any = vertices
            .iter()
            .any(|v| case.mechanism(v, lambda_s).is_some());
        if any != sv.mechanism_at_static {
            failures.push(format!(
                "case {n}: mechanism_at_static {} but the face's vertices say {any}",
                sv.mechanism_at_static
            ));
        }
        // a continuum of limit states in λ that reaches λ_static (two contacts whose
        // columns cancel) holds the states there that have both its contacts active
        let in_lambda_continuum = sv.limit_states.iter().any(|s| {
            s.t < lambda_s * (1.0 - 1e-9)
                && s.continuum_to
                    .is_some_and(|to| to >= lambda_s * (1.0 - 1e-9))
        });
        if mu.is_finite() && !in_lambda_continuum && case.mechanism(&common, lambda_s).is_some() {
            // the crate's pattern as the reference's (section, kind)
            let section = |c: &arch_enum::Contact, side: arch_enum::load::Side| {
                case.sections
                    .iter()
                    .position(|s| {
                        s.beta == c.beta
                            && s.loaded_side
                                == (side == arch_enum::load::Side::After && load.splits(s.beta))
                    })
                    .map(|s| (s, c.kind))
            };
            let ok = at_static.len() == 1 && {
                let s = at_static[0];
                let mut ours: Vec<_> = s
                    .pattern
                    .iter()
                    .zip(&s.sides)
                    .filter_map(|(c, side)| section(c, *side))
                    .collect();
                let mut theirs = common.clone();
                ours.sort_by_key(|p| (p.0, p.1 as usize));
                theirs.sort_by_key(|p| (p.0, p.1 as usize));
                // the extrados hinge at a split joint is one plane on both sides: the
                // reference lists it once per side as well
                ours == theirs && (vertices.len() == 1) == s.continuum_to.is_none()
            };
            if !ok {
                failures.push(format!(
                    "case {n}: the face ({} vertices) has the contacts {common:?} in common, carrying a mechanism; the survey reports {:?}",
                    vertices.len(),
                    at_static
                        .iter()
                        .map(|s| (s.t, s.pattern.iter().map(|c| (c.beta, c.kind)).collect::<Vec<_>>(), s.continuum_to))
                        .collect::<Vec<_>>()
                ));
            }
        }
    }
    println!(
        "{edges} optimal faces with more than one vertex; {} disagreements",
        failures.len()
    );
    assert!(
        edges >= 1,
        "no degenerate maximum met: the test checks nothing"
    );
    assert!(failures.is_empty(), "{}", failures.join("\n"));
}

/// The crate against the brute force on random small discrete arches under fill (bridge
/// spec §2, §5): the fill a dead load (integrated by the reference's own quadrature), the
/// live load a point load or a pressure of one to three patches on the extrados (some
/// reaching past its ends, which the abutments carry), both weight models, finite and
/// infinite friction; a tenth of the cases without fill (a pressure alone).
/// `FILL_CASES=N` runs more.
#[test]
fn filled_arches_under_pressure_match_the_brute_force() {
    use arch_enum::bridge::Fill;
    use arch_enum::pressure::{Patch, PointLoad, Pressure};
    let count = crate::cases_from_env("FILL_CASES", 30);
    let mut rng = Rng(0xf111_0000_0000_0023);
    let settings = Settings::default();
    let (mut compared, mut skipped, mut never, mut pressures, mut several) = (0, 0, 0, 0, 0);
    let mut failures = Vec::new();
    for case in 0..count {
        let n = 3 + (rng.next() * 4.0) as usize;
        let br = -0.2 + 0.6 * rng.next();
        let bl = PI - 0.4 + 0.6 * rng.next();
        let joints = random_joints(&mut rng, br, bl, n);
        let centroid = rng.next() < 0.3;
        let weight = if centroid {
            WeightModel::Centroid
        } else {
            WeightModel::Centreline
        };
        let mu = if rng.next() < 0.2 {
            f64::INFINITY
        } else {
            0.3 + 1.5 * rng.next()
        };
        let eta = 0.1 + 0.15 * rng.next();
        let fill = (rng.next() > 0.1).then(|| (0.05 + 0.2 * rng.next(), 0.02 + 0.2 * rng.next()));
        let kappa = 1.0 + eta / 2.0;
        let on_extrados = |u: f64| br.max(0.0) + (bl.min(PI) - br.max(0.0)) * (0.05 + 0.9 * u);
        let draw = rng.next();
        let load = if draw < 0.25 {
            LiveLoad::Point {
                beta: on_extrados(rng.next()),
            }
        } else if draw < 0.45 {
            pressures += 1;
            let points: Vec<PointLoad> = (0..1 + (rng.next() * 3.0) as usize)
                .map(|_| PointLoad {
                    beta: on_extrados(rng.next()),
                    q: 0.2 + rng.next(),
                })
                .collect();
            LiveLoad::Pressure(Pressure::new(&[], &points).unwrap())
        } else {
            pressures += 1;
            let k = 1 + (rng.next() * 3.0) as usize;
            let patches: Vec<Patch> = (0..k)
                .map(|_| {
                    let x = kappa * (-1.1 + 2.2 * rng.next());
                    let half = 0.02 + 0.3 * rng.next();
                    Patch {
                        x_lo: x - half,
                        x_hi: x + half,
                        q: (0.2 + rng.next()) / half,
                    }
                })
                .collect();
            LiveLoad::Pressure(Pressure::new(&patches, &[]).unwrap())
        };
        let mut arch = Arch::new(br, bl, weight)
            .unwrap()
            .with_joints(&joints)
            .unwrap();
        if let Some((g, h)) = fill {
            arch = arch.with_fill(Fill::new(g, h).unwrap());
        }
        let mut reference = Case::new(&joints, centroid, eta, mu, load);
        reference.fill = fill;
        let reference = reference.brute_force();
        let crate_states = match crate_answer(survey(&arch, eta, mu, &load, &settings).unwrap()) {
            Ok(Answer::Limits { lambdas, .. }) => {
                several += usize::from(lambdas.len() > 1);
                lambdas
            }
            Ok(Answer::NoEquilibrium) => {
                skipped += 1;
                Vec::new()
            }
            Ok(Answer::NoCollapse) => {
                never += 1;
                Vec::new()
            }
            Err(e) => {
                failures.push(format!("case {case}: no decision: {e}"));
                continue;
            }
        };
        compared += 1;
        // the reference's quadrature of the fill is good to about 1e-12
        if !same_lambdas(&crate_states, &reference) {
            failures.push(format!(
                "case {case}: joints {joints:?} centroid {centroid} eta {eta} mu {mu} fill {fill:?} {load:?}: crate {crate_states:?} vs brute force {reference:?}"
            ));
        }
    }
    println!(
        "{compared} filled or pressed arches compared ({pressures} pressures, {skipped} no_equilibrium, {never} no_collapse, {several} with several limit states), {} disagreements",
        failures.len()
    );
    assert!(
        compared >= count * 9 / 10,
        "too few cases compared: {compared} of {count}"
    );
    assert!(
        compared - skipped - never >= count / 2,
        "too few cases with limit states"
    );
    assert!(failures.is_empty(), "{}", failures.join("\n"));
}

/// The ridge's theorem read in λ (docs/design/limit-states-on-boundary.md §2–3 at fixed η,
/// λ the parameter): where P(λ) has an interior point, a limit state's mechanism has a
/// sliding rate (a hinge-only one would be active over all of P(λ)), and a mechanism with
/// hinge rates has an extrados and an intrados rate (rotation balance). Checked on the
/// sweep's limit states strictly between λ_min and λ_static of random loaded arches. The
/// premise of a search in (h, v, λ), not built (docs/performance.md): the states with hinge
/// rates lie where the sliding polyhedron's boundary meets the boundary of the set where
/// the band of w is not empty, and the purely sliding ones (many here) where three sliding
/// planes meet, at vertices of the sliding polyhedron.
#[test]
fn load_limit_states_below_the_static_maximum_slide_and_hinge_both_ways() {
    let mut rng = Rng(0x1a5d_0ad5);
    let (mut below, mut pure_sliding) = (0, 0);
    let mut odd: Vec<String> = Vec::new();
    for case in 0..1500 {
        let c = random_loaded(&mut rng);
        if c.mu.is_infinite() {
            continue;
        }
        let Ok(Ok(LoadOutcome::Limits(s))) =
            survey(&c.arch, c.eta, c.mu, &c.load, &Settings::default())
        else {
            continue;
        };
        let (lo, hi) = (
            s.lambda_min.0,
            s.lambda_static.map_or(f64::INFINITY, |m| m.0),
        );
        let inside = |t: f64| t > lo + 1e-9 * (1.0 + lo.abs()) && t < hi - 1e-9 * (1.0 + hi.abs());
        for st in s.limit_states.iter().filter(|st| inside(st.t)) {
            below += 1;
            let m = &st.mechanism;
            let rate = |k: ContactKind| {
                m.contacts
                    .iter()
                    .zip(&m.rates)
                    .any(|(c, &r)| c.kind == k && r > 1e-9)
            };
            let slides = rate(ContactKind::SlidePlus) || rate(ContactKind::SlideMinus);
            let (e, i) = (
                rate(ContactKind::HingeExtrados),
                rate(ContactKind::HingeIntrados),
            );
            if slides && !e && !i {
                pure_sliding += 1;
            } else if !(slides && e && i) {
                odd.push(format!(
                    "case {case}: lambda {} in ({lo}, {hi}): {:?} rates {:?}",
                    st.t, m.contacts, m.rates
                ));
            }
        }
    }
    println!(
        "{below} limit states below lambda_static, {pure_sliding} purely sliding, {} otherwise",
        odd.len()
    );
    assert!(odd.is_empty(), "{}", odd.join("\n"));
    assert!(below >= 50, "only {below} limit states below lambda_static");
    assert!(
        pure_sliding >= 10 && pure_sliding < below,
        "{pure_sliding} of {below} purely sliding"
    );
}
