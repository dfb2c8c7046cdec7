//! An INDEPENDENT reference for the least admissible thickness η_s(μ) of a CONTINUOUS arch
//! (any springings β_R < β_L, centreline or true-centroid weight), written from
//! shared/spec/formulation.md §3 only. Nothing of the crate's statics, scan, refinement or
//! limit code is used by the reference; `arch_enum::solve` appears only as the thing under
//! test (and `arch_enum::least_friction` only to draw μ just above μ_ms).
//!
//! Method: the classical exchange (Remez-type constraint generation) for the semi-infinite
//! LP, and a root of its margin in η.
//! * Each activation function φ_k(x, β) = a_k(β)·x + c_k(β) (k = E, I, S+, S−; only E, I at
//!   μ = ∞) is affine in x = (h, v, w) at fixed (β, η, μ); rows are normalised by the
//!   gradient norm |a_k(β)| (≥ 1 for the hinges thanks to w, √(1 + μ²) for the slides), so
//!   g_k = φ_k/|a_k| is the signed distance of x to the plane, in units of x.
//! * **Margin LP** over a finite set of angles B: max s subject to g_k(x, β) + s ≤ 0 for
//!   β ∈ B, with the box |x_i| ≤ BOX, s ≤ BOX as rows (it binds only at η near 2, μ = ∞).
//!   HiGHS (simplex, presolve off, tolerances 1e-10) gives a near-optimal basis; HiGHS's
//!   answer itself is NOT used: its feasibility tolerance cannot be set below 1e-10, so a
//!   new row violated by 1e-11 counts as satisfied and the exchange would stall there. A
//!   small dense dual simplex in f64 (`dual_simplex`) restarts from HiGHS's basis (or from
//!   the box's vertex when HiGHS fails or its basis is not dual feasible) and pivots until
//!   no row is violated by more than 1e-15 of the state's size: the vertex and its margin
//!   are then exact to rounding.
//! * **Exchange**: at the LP's x, every local maximum of every g_k(x, ·) over the continuum
//!   [β_R, β_L] is located by a dense scan (SCAN cells) and refined by golden section on
//!   its two cells (the two end cells are searched too whenever g falls away from a
//!   springing: a tangency point a fraction of a cell inside the arch is no local maximum
//!   of the scan); the violated maximisers join B, and the LP is solved again until the
//!   continuum max of g is within ~1e-14 of −s (then s_lp ≥ s(η) ≥ −max g ≥ s_lp − tol:
//!   the continuum margin is known to rounding). B starts with INITIAL equally spaced
//!   angles (both springings included) and keeps growing across the η iterations.
//! * **Root**: s(η) changes sign once (admissibility is monotone in η); η_s is bracketed in
//!   [1e-9, 2(1 − 1e-9)] by geometric bisection and polished by Illinois regula falsi,
//!   until the bracket is 1e-13 relative or |s| is at its rounding floor. The state found
//!   there is checked once more on a dense grid with `model::phis` (an independent
//!   transcription of §3, not the rows used above).
//!
//! The tests: known values of the semicircle (Couplet–Heyman, Milankovitch, μ = 0.35),
//! and random continuous arches against `arch_enum::solve`'s `eta_static` to 1e-10.

use crate::model;
use crate::search_reference::Rng;
use arch_enum::{least_friction, solve, Arch, Outcome, Settings, WeightModel};
use good_lp::{highs, variable, Expression, ProblemVariables, Solution, SolverModel};
use nalgebra::{Matrix4, Vector4};
use std::f64::consts::PI;
use std::time::Instant;

/// Equally spaced angles the working set starts with (springings included).
const INITIAL: usize = 200;
/// Cells of the dense scan for the local maxima of each g_k over the continuum.
const SCAN: usize = 1024;
/// Box on x and on s in the margin LP.
const BOX: f64 = 1e3;
/// Thickness range searched (as the crate's: 0 < η < 2).
const ETA_MIN: f64 = 1e-9;
const ETA_TOP: f64 = 2.0 * (1.0 - 1e-9);
/// Exchange rounds at one η before giving up.
const MAX_ROUNDS: usize = 60;

/// A continuous arch at friction μ.
pub struct Cont {
    br: f64,
    bl: f64,
    centroid: bool,
    mu: f64,
    /// Scan grid and its sines and cosines (fixed per arch).
    grid: Vec<f64>,
    gsin: Vec<f64>,
    gcos: Vec<f64>,
}

/// The margin at one η.
#[derive(Debug, Clone)]
pub struct Margin {
    /// The LP's margin over the working set; the continuum margin lies within ~1e-14 below.
    pub s_lp: f64,
    /// The LP's state.
    pub x: [f64; 3],
    /// Whether the box on (x, s) binds at the LP's vertex.
    pub boxed: bool,
}

/// What the reference found.
#[derive(Debug, Clone)]
pub enum RefEta {
    /// η_s and the state there.
    Least {
        eta: f64,
        x: [f64; 3],
        /// The contacts within 1e-9 of the margin at η_s: (family, β).
        touching: Vec<(usize, f64)>,
        /// Margin evaluations (each an exchange).
        evaluations: usize,
    },
    /// No η < 2 admits a state (s(ETA_TOP) < 0).
    NoEquilibrium {
        /// The margin at η = 2(1 − 1e-9) (read through `Debug` in messages).
        #[allow(dead_code)]
        s_top: f64,
    },
    /// Every η ≥ ETA_MIN admits a state.
    StandsEverywhere,
}

const FAMILY: [&str; 4] = ["E", "I", "S+", "S-"];

impl Cont {
    pub fn new(br: f64, bl: f64, centroid: bool, mu: f64) -> Cont {
        assert!(br < bl && mu > 0.0);
        let grid: Vec<f64> = (0..=SCAN)
            .map(|i| {
                if i == SCAN {
                    bl
                } else {
                    br + (bl - br) * i as f64 / SCAN as f64
                }
            })
            .collect();
        Cont {
            br,
            bl,
            centroid,
            mu,
            gsin: grid.iter().map(|b| b.sin()).collect(),
            gcos: grid.iter().map(|b| b.cos()).collect(),
            grid,
        }
    }

    pub fn of(arch: &Arch, mu: f64) -> Cont {
        Cont::new(
            arch.beta_right(),
            arch.beta_left(),
            arch.weight() == WeightModel::Centroid,
            mu,
        )
    }

    pub(crate) fn families(&self) -> usize {
        if self.mu.is_finite() {
            4
        } else {
            2
        }
    }

    /// ρ(η): 1 for the centreline weight; 1 + η²/12 for the true centroid (the centroid of an
    /// annular sector of half-thicknesses 1 ± η/2 lies ρ times farther from the centre than
    /// that of its centreline arc: (2/3)((1+η/2)³ − (1−η/2)³)/((1+η/2)² − (1−η/2)²) = 1 + η²/12).
    fn rho(&self, eta: f64) -> f64 {
        if self.centroid {
            1.0 + eta * eta / 12.0
        } else {
            1.0
        }
    }

    /// The row of family k at β (given sin β, cos β): φ_k = a·x + c (formulation §3).
    pub(crate) fn row_raw(&self, k: usize, eta: f64, beta: f64, s: f64, c: f64) -> ([f64; 3], f64) {
        let (sr, cr) = (self.br.sin(), self.br.cos());
        let d = beta - self.br;
        // N = gn·x + cn, T = gt·x + ct, M = gm·x + cm
        let (gn, cn) = ([s, c, 0.0], -d * c);
        let (gt, ct) = ([c, -s, 0.0], d * s);
        let (gm, cm) = ([-(s - sr), cr - c, 1.0], d * c - self.rho(eta) * (s - sr));
        let (p, q, g1, c1) = match k {
            0 => (1.0, -eta / 2.0, gm, cm),
            1 => (-1.0, -eta / 2.0, gm, cm),
            2 => (1.0, -self.mu, gt, ct),
            3 => (-1.0, -self.mu, gt, ct),
            _ => unreachable!(),
        };
        (
            [
                p * g1[0] + q * gn[0],
                p * g1[1] + q * gn[1],
                p * g1[2] + q * gn[2],
            ],
            p * c1 + q * cn,
        )
    }

    /// The row normalised to unit gradient: (a/|a|, c/|a|).
    fn row_sc(&self, k: usize, eta: f64, beta: f64, s: f64, c: f64) -> ([f64; 3], f64) {
        let (a, c0) = self.row_raw(k, eta, beta, s, c);
        let n = (a[0] * a[0] + a[1] * a[1] + a[2] * a[2]).sqrt();
        ([a[0] / n, a[1] / n, a[2] / n], c0 / n)
    }

    fn row(&self, k: usize, eta: f64, beta: f64) -> ([f64; 3], f64) {
        self.row_sc(k, eta, beta, beta.sin(), beta.cos())
    }

    /// g_k(x, β) = φ_k / |a_k|.
    pub fn g(&self, k: usize, eta: f64, x: &[f64; 3], beta: f64) -> f64 {
        let (a, c) = self.row(k, eta, beta);
        a[0] * x[0] + a[1] * x[1] + a[2] * x[2] + c
    }

    /// The largest g_k(x, β) over the four contact families and 20 001 equally spaced
    /// angles of the arch: the state (η, x) is admissible to within it.
    pub fn worst(&self, eta: f64, x: &[f64; 3]) -> f64 {
        (0..=20_000)
            .map(|i| self.br + (self.bl - self.br) * i as f64 / 20_000.0)
            .flat_map(|b| (0..4).map(move |k| (k, b)))
            .map(|(k, b)| self.g(k, eta, x, b))
            .fold(f64::NEG_INFINITY, f64::max)
    }

    /// φ_k itself (unnormalised), for the cross-check against `model::phis`.
    pub fn phi(&self, k: usize, eta: f64, x: &[f64; 3], beta: f64) -> f64 {
        let (a, c) = self.row_raw(k, eta, beta, beta.sin(), beta.cos());
        a[0] * x[0] + a[1] * x[1] + a[2] * x[2] + c
    }

    /// Every local maximum of g_k(x, ·) over [β_R, β_L], for every family: (k, β, g).
    /// Interior maxima of the scan are refined by golden section on their two cells;
    /// a springing counts when g decreases away from it.
    #[allow(clippy::needless_range_loop)]
    fn peaks(&self, eta: f64, x: &[f64; 3]) -> Vec<(usize, f64, f64)> {
        let mut out = Vec::new();
        let mut vals = vec![0.0; self.grid.len()];
        for k in 0..self.families() {
            for (i, v) in vals.iter_mut().enumerate() {
                let (a, c) = self.row_sc(k, eta, self.grid[i], self.gsin[i], self.gcos[i]);
                *v = a[0] * x[0] + a[1] * x[1] + a[2] * x[2] + c;
            }
            let f = |t: f64| self.g(k, eta, x, t);
            out.extend(
                scan_peaks(&self.grid, &vals, f)
                    .into_iter()
                    .map(|(b, v)| (k, b, v)),
            );
        }
        out
    }

    /// The margin LP over the working set `set` at η: (x, s, whether the box binds), by
    /// [`max_last`] (HiGHS, then [`dual_simplex`] in f64 from HiGHS's basis; HiGHS alone
    /// is accurate to 1e-10 at best: a new row violated by 1e-11 counts as satisfied, and
    /// the exchange would stall). The box |x_i| ≤ BOX, s ≤ BOX is part of the rows.
    fn lp(&self, eta: f64, set: &[f64]) -> Result<([f64; 3], f64, bool), String> {
        let nf = self.families();
        let rows: Vec<([f64; 4], f64)> = set
            .iter()
            .flat_map(|&b| {
                let (sb, cb) = (b.sin(), b.cos());
                (0..nf).map(move |k| {
                    let (a, c) = self.row_sc(k, eta, b, sb, cb);
                    ([a[0], a[1], a[2], 1.0], -c)
                })
            })
            .collect();
        let (zz, boxed) =
            max_last(rows, [BOX; 4]).map_err(|e| format!("margin LP at eta = {eta}: {e}"))?;
        Ok(([zz[0], zz[1], zz[2]], zz[3], boxed))
    }

    /// The continuum margin at η by exchange, growing the working set `set` (sorted).
    pub fn margin(&self, eta: f64, set: &mut Vec<f64>) -> Result<Margin, String> {
        for _ in 0..MAX_ROUNDS {
            let (x, s_lp, boxed) = self.lp(eta, set)?;
            let peaks = self.peaks(eta, &x);
            let worst = peaks.iter().map(|p| p.2).fold(f64::NEG_INFINITY, f64::max);
            let xs = x.iter().map(|v| v.abs()).fold(0.0, f64::max);
            let tol = 1e-14 * (1.0 + xs);
            if worst + s_lp <= tol {
                return Ok(Margin { s_lp, x, boxed });
            }
            let mut added = 0;
            for &(_, b, g) in &peaks {
                if g + s_lp > tol {
                    let i = set.partition_point(|&t| t < b);
                    let near = (i < set.len() && (set[i] - b).abs() <= 1e-15 * (1.0 + b.abs()))
                        || (i > 0 && (b - set[i - 1]).abs() <= 1e-15 * (1.0 + b.abs()));
                    if !near {
                        set.insert(i, b);
                        added += 1;
                    }
                }
            }
            if added == 0 {
                return Err(format!(
                    "exchange stalled at eta = {eta}: continuum max {worst:e} + LP margin {s_lp:e} > {tol:e} at angles already in the working set (x = {x:?})"
                ));
            }
        }
        Err(format!(
            "exchange did not converge at eta = {eta} in {MAX_ROUNDS} rounds"
        ))
    }

    fn initial_set(&self) -> Vec<f64> {
        (0..=INITIAL)
            .map(|i| {
                if i == INITIAL {
                    self.bl
                } else {
                    self.br + (self.bl - self.br) * i as f64 / INITIAL as f64
                }
            })
            .collect()
    }

    /// η_s: the root of the continuum margin s(η).
    pub fn least_thickness(&self) -> Result<RefEta, String> {
        let mut set = self.initial_set();
        let mut evaluations = 0;
        let mut f = |eta: f64, set: &mut Vec<f64>| -> Result<Margin, String> {
            evaluations += 1;
            self.margin(eta, set)
        };
        let top = f(ETA_TOP, &mut set)?;
        if top.s_lp < 0.0 {
            return Ok(RefEta::NoEquilibrium { s_top: top.s_lp });
        }
        let bottom = f(ETA_MIN, &mut set)?;
        if bottom.s_lp >= 0.0 {
            return Ok(RefEta::StandsEverywhere);
        }
        let (mut a, mut fa) = (ETA_MIN, bottom.s_lp);
        let (mut b, mut fb) = (ETA_TOP, top.s_lp);
        let mut best = (ETA_TOP, top);
        // geometric bisection down to a ratio of 2
        while b > 2.0 * a {
            let m = (a * b).sqrt();
            let r = f(m, &mut set)?;
            if r.s_lp < 0.0 {
                (a, fa) = (m, r.s_lp);
            } else {
                (b, fb) = (m, r.s_lp);
                best = (m, r);
            }
        }
        // Illinois regula falsi, bisection when the bracket does not halve in 3 steps
        let (mut side, mut stale, mut width) = (0, 0, b - a);
        for _ in 0..200 {
            if b - a <= 1e-13 * b {
                break;
            }
            let mut c = (a * fb - b * fa) / (fb - fa);
            if stale >= 3 || !(c > a && c < b) {
                c = 0.5 * (a + b);
                stale = 0;
                width = b - a;
            }
            let r = f(c, &mut set)?;
            // at the rounding floor of the margin: c is the root to the margin's precision
            let xs = r.x.iter().map(|v| v.abs()).fold(0.0, f64::max);
            let floor = r.s_lp.abs() <= 4e-15 * (1.0 + xs);
            let s = r.s_lp;
            if floor || s.abs() < best.1.s_lp.abs() {
                best = (c, r);
            }
            if floor {
                break;
            }
            if s < 0.0 {
                (a, fa) = (c, s);
                if side == -1 {
                    fb *= 0.5;
                }
                side = -1;
            } else {
                (b, fb) = (c, s);
                if side == 1 {
                    fa *= 0.5;
                }
                side = 1;
            }
            if b - a > 0.5 * width {
                stale += 1;
            } else {
                stale = 0;
                width = b - a;
            }
        }
        let (eta, m) = best;
        let x = m.x;
        if m.boxed {
            return Err(format!("the box binds at eta_s = {eta}: x = {x:?}"));
        }
        // independent of the peak finder: φ of `model` (another transcription of §3) on a
        // dense grid, each relative to its gradient norm as the margin is
        let rho = self.rho(eta);
        let n = 20_000;
        let dense = (0..=n)
            .flat_map(|i| {
                let b = self.br + (self.bl - self.br) * i as f64 / n as f64;
                let p = model::phis(self.br, rho, eta, self.mu, x, b);
                (0..self.families()).map(move |k| (k, b, p[k]))
            })
            .map(|(k, b, p)| {
                let (a, _) = self.row_raw(k, eta, b, b.sin(), b.cos());
                p / (a[0] * a[0] + a[1] * a[1] + a[2] * a[2]).sqrt()
            })
            .fold(f64::NEG_INFINITY, f64::max);
        let xs = x.iter().map(|v| v.abs()).fold(0.0, f64::max);
        if dense > 1e-13 * (1.0 + xs) {
            return Err(format!(
                "the state at eta_s = {eta} violates a dense check by {dense:e}: x = {x:?}"
            ));
        }
        let touching = self
            .peaks(eta, &x)
            .into_iter()
            .filter(|p| p.2 > -1e-9)
            .map(|p| (p.0, p.1))
            .collect();
        Ok(RefEta::Least {
            eta,
            x,
            touching,
            evaluations,
        })
    }
}

/// Every local maximum over [grid₀, grid_last] of a smooth function `f` sampled on `grid`
/// (`vals[i] = f(grid[i])`): (β, f). Interior maxima of the scan are refined by golden
/// section on their two cells; an end point counts when f decreases away from it (and a
/// maximum a fraction of a cell inside it, found by golden section on the end cells,
/// counts too: it is no interior local maximum of the scan).
pub(crate) fn scan_peaks(grid: &[f64], vals: &[f64], f: impl Fn(f64) -> f64) -> Vec<(f64, f64)> {
    let mut out = Vec::new();
    let n = grid.len();
    assert!(n >= 3 && vals.len() == n);
    for (e, inner) in [(0, 1), (n - 1, n - 2)] {
        if vals[e] >= vals[inner] {
            out.push((grid[e], vals[e]));
            let (lo, hi) = if e == 0 {
                (grid[0], grid[2])
            } else {
                (grid[n - 3], grid[n - 1])
            };
            let (b, v) = golden(&f, lo, hi);
            if v > vals[e] && (b - grid[e]).abs() > 1e-9 {
                out.push((b, v));
            }
        }
    }
    for i in 1..n - 1 {
        if vals[i] >= vals[i - 1] && vals[i] > vals[i + 1] {
            let (b, v) = golden(&f, grid[i - 1], grid[i + 1]);
            // never worse than the grid point itself
            if v >= vals[i] {
                out.push((b, v));
            } else {
                out.push((grid[i], vals[i]));
            }
        }
    }
    out
}

/// Golden-section maximisation of `f` on [a, b] (unimodal there): (argmax, max).
pub(crate) fn golden(f: impl Fn(f64) -> f64, mut a: f64, mut b: f64) -> (f64, f64) {
    let r = 0.5 * (5f64.sqrt() - 1.0);
    let mut c = b - r * (b - a);
    let mut d = a + r * (b - a);
    let (mut fc, mut fd) = (f(c), f(d));
    while b - a > 1e-11 * (1.0 + a.abs()) {
        if fc >= fd {
            b = d;
            d = c;
            fd = fc;
            c = b - r * (b - a);
            fc = f(c);
        } else {
            a = c;
            c = d;
            fc = fd;
            d = a + r * (b - a);
            fd = f(d);
        }
    }
    if fc >= fd {
        (c, fc)
    } else {
        (d, fd)
    }
}

/// max z₄ subject to A z ≤ b (`rows` (A_k, b_k)) and the box |z_i| ≤ `bx[i]` (i < 3),
/// z₄ ≤ `bx[3]` (appended as rows). HiGHS (simplex, presolve off, tolerances 1e-10) gives
/// a near-optimal basis; [`dual_simplex`] restarts from it (or from the box's vertex when
/// HiGHS fails or its basis is not dual feasible) and pivots until no row is violated by
/// more than 1e-15 of the state's size. Returns the vertex and whether a box row is in its
/// basis.
pub(crate) fn max_last(
    mut rows: Vec<([f64; 4], f64)>,
    bx: [f64; 4],
) -> Result<([f64; 4], bool), String> {
    let boxed = rows.len();
    for (i, &bound) in bx.iter().enumerate() {
        for sign in [1.0, -1.0] {
            if i == 3 && sign < 0.0 {
                continue;
            }
            let mut a = [0.0; 4];
            a[i] = sign;
            rows.push((a, bound));
        }
    }
    let mut vars = ProblemVariables::new();
    let z: Vec<_> = (0..4).map(|_| vars.add(variable())).collect();
    let mut p = vars
        .maximise(z[3])
        .using(highs)
        .set_option("output_flag", false)
        .set_option("presolve", "off")
        .set_option("solver", "simplex")
        .set_option("primal_feasibility_tolerance", 1e-10)
        .set_option("dual_feasibility_tolerance", 1e-10);
    for (a, b) in &rows {
        let mut e = Expression::from(0.0);
        for i in 0..4 {
            if a[i] != 0.0 {
                e.add_mul(a[i], z[i]);
            }
        }
        p = p.with(e.leq(*b));
    }
    // the box's vertex: a dual feasible basis (y = 1 on z₄ ≤ bx[3]) to start from
    // when HiGHS fails or its basis is not dual feasible
    let box_basis = [boxed, boxed + 2, boxed + 4, boxed + 6];
    let (zz, basis) = match p.solve() {
        Ok(sol) => {
            let z0 = [
                sol.value(z[0]),
                sol.value(z[1]),
                sol.value(z[2]),
                sol.value(z[3]),
            ];
            let duals = sol.into_inner().dual_rows().to_vec();
            start_basis(&rows, &z0, &duals)
                .and_then(|b| dual_simplex(&rows, b))
                .or_else(|_| dual_simplex(&rows, box_basis))
        }
        Err(_) => dual_simplex(&rows, box_basis),
    }?;
    Ok((zz, basis.iter().any(|&k| k >= boxed)))
}

/// A first basis for [`dual_simplex`] from HiGHS's answer `z0`: the rows with a nonzero
/// HiGHS dual, completed by the tightest rows that keep it nonsingular.
fn start_basis(
    rows: &[([f64; 4], f64)],
    z0: &[f64; 4],
    duals: &[f64],
) -> Result<[usize; 4], String> {
    let slack = |k: usize| {
        let (a, b) = &rows[k];
        b - (a[0] * z0[0] + a[1] * z0[1] + a[2] * z0[2] + a[3] * z0[3])
    };
    let mut order: Vec<usize> = (0..rows.len()).collect();
    order.sort_by(|&i, &j| {
        let key = |k: usize| (duals[k].abs() <= 1e-12, slack(k));
        key(i).partial_cmp(&key(j)).unwrap()
    });
    let mut basis = [usize::MAX; 4];
    let mut ortho: Vec<Vector4<f64>> = Vec::new();
    for &k in &order {
        let mut u = Vector4::from(rows[k].0);
        let n0 = u.norm();
        for q in &ortho {
            u -= q * q.dot(&u);
        }
        if u.norm() > 1e-6 * n0 {
            basis[ortho.len()] = k;
            ortho.push(u.normalize());
            if ortho.len() == 4 {
                return Ok(basis);
            }
        }
    }
    Err("no nonsingular starting basis".into())
}

/// max z₄ subject to A z ≤ b (rows (A_k, b_k), z = (h, v, w, s)) by the dual simplex in
/// f64 from a dual feasible `basis` (its multipliers y, A_Bᵀ y = e₄, are ≥ 0): the most
/// violated row enters (violation above 1e-15 of the state's size: rounding is no reason
/// to pivot), the ratio test picks the row that leaves. The vertex A_B⁻¹ b_B is exact to
/// rounding. Returns it and its basis.
fn dual_simplex(
    rows: &[([f64; 4], f64)],
    mut basis: [usize; 4],
) -> Result<([f64; 4], [usize; 4]), String> {
    let slack = |k: usize, z: &[f64; 4]| {
        let (a, b) = &rows[k];
        b - (a[0] * z[0] + a[1] * z[1] + a[2] * z[2] + a[3] * z[3])
    };
    let e4 = Vector4::new(0.0, 0.0, 0.0, 1.0);
    for _ in 0..2000 {
        let ab = Matrix4::from_fn(|i, j| rows[basis[i]].0[j]);
        let lu = ab.full_piv_lu();
        let lut = ab.transpose().full_piv_lu();
        let bb = Vector4::from_fn(|i, _| rows[basis[i]].1);
        let zv = lu.solve(&bb).ok_or("singular basis")?;
        let y = lut.solve(&e4).ok_or("singular basis")?;
        if y.iter().any(|&v| v < -1e-9) {
            return Err(format!(
                "basis {basis:?} is not dual feasible: y = {:?}",
                y.as_slice()
            ));
        }
        let z = [zv[0], zv[1], zv[2], zv[3]];
        let size = 1.0 + z.iter().map(|v| v.abs()).fold(0.0, f64::max);
        let (r, _) =
            (0..rows.len())
                .map(|k| (k, -slack(k, &z)))
                .fold(
                    (usize::MAX, 1e-15 * size),
                    |a, b| if b.1 > a.1 { b } else { a },
                );
        if r == usize::MAX {
            return Ok((z, basis));
        }
        // A_r = Σ u_i A_{B_i}
        let u = lut
            .solve(&Vector4::from(rows[r].0))
            .ok_or("singular basis")?;
        let leave = (0..4)
            .filter(|&i| u[i] > 1e-12)
            .min_by(|&i, &j| {
                (y[i].max(0.0) / u[i])
                    .partial_cmp(&(y[j].max(0.0) / u[j]))
                    .unwrap()
                    .then(u[j].partial_cmp(&u[i]).unwrap())
            })
            .ok_or("primal infeasible (no z satisfies the rows)")?;
        basis[leave] = r;
    }
    Err("dual simplex did not finish in 2000 pivots".into())
}

fn rel(a: f64, b: f64) -> f64 {
    (a - b).abs() / a.abs().max(b.abs()).max(1e-300)
}

fn describe_touching(t: &[(usize, f64)]) -> String {
    t.iter()
        .map(|(k, b)| format!("{}@{:.6}", FAMILY[*k], b))
        .collect::<Vec<_>>()
        .join(" ")
}

/// The reference's η_s of an arch (panics when the reference itself fails).
fn reference_eta(arch: &Arch, mu: f64) -> f64 {
    match Cont::of(arch, mu).least_thickness() {
        Ok(RefEta::Least { eta, .. }) => eta,
        other => panic!("reference failed: {other:?}"),
    }
}

/// The reference reproduces the classical values of the semicircle, and its activation
/// functions agree with `model::phis` (an independent transcription of formulation §3).
#[test]
fn continuum_reference_reproduces_known_values() {
    // the rows against model.rs, both weight models, finite μ
    for centroid in [false, true] {
        let c = Cont::new(-0.3, PI + 0.1, centroid, 0.7);
        let eta = 0.23;
        let rho = if centroid {
            1.0 + eta * eta / 12.0
        } else {
            1.0
        };
        for (i, beta) in [-0.3, 0.4, 1.7, 2.9, PI + 0.1].into_iter().enumerate() {
            let x = [0.3 + 0.1 * i as f64, 1.2 - 0.2 * i as f64, -0.05 * i as f64];
            let m = model::phis(-0.3, rho, eta, 0.7, x, beta);
            for k in 0..4 {
                let p = c.phi(k, eta, &x, beta);
                assert!(
                    (p - m[k]).abs() < 1e-14,
                    "phi_{} at {beta}: {p} vs model {}",
                    FAMILY[k],
                    m[k]
                );
            }
        }
    }
    let semi = Arch::symmetric(0.0, WeightModel::Centreline).unwrap();
    let ch = reference_eta(&semi, f64::INFINITY);
    println!("reference: Couplet-Heyman {ch:.15}");
    // 12 digits: 0.107426452755 (the crate's 0.10742645275542488 rounded)
    assert!(
        (ch - 0.107426452755).abs() < 1e-12,
        "Couplet-Heyman: {ch:.15} vs 0.107426452755"
    );
    let semi_c = Arch::symmetric(0.0, WeightModel::Centroid).unwrap();
    let mk = reference_eta(&semi_c, f64::INFINITY);
    println!("reference: Milankovitch (true centroid) {mk:.15}");
    assert!((mk - 0.1075).abs() < 5e-5, "Milankovitch: {mk} vs 0.1075");
    let mixed = reference_eta(&semi, 0.35);
    println!("reference: semicircle at mu = 0.35 {mixed:.15}");
    assert!(
        (mixed - 0.15291973385).abs() < 1e-11,
        "semicircle at mu = 0.35: {mixed:.15} vs 0.15291973385"
    );
}

/// One random continuous arch and friction.
struct Case {
    arch: Arch,
    mu: f64,
    label: String,
    /// Category index: 4·(friction class: 0 ∞, 1 just above μ_ms, 2 in (μ_ms, 3]) +
    /// 2·symmetric + centroid.
    kind: usize,
}

fn draw(rng: &mut Rng, settings: &Settings) -> Case {
    let centroid = rng.next() < 0.5;
    let weight = if centroid {
        WeightModel::Centroid
    } else {
        WeightModel::Centreline
    };
    let symmetric = rng.next() >= 0.5;
    let (arch, geo) = if !symmetric {
        let br = -0.6 + 1.2 * rng.next();
        let bl = PI - (-0.6 + 1.2 * rng.next());
        (
            Arch::new(br, bl, weight).unwrap(),
            format!("--beta-right {br:?} --beta-left {bl:?}"),
        )
    } else {
        let alpha = -1.2 + 2.3 * rng.next();
        let a = Arch::symmetric(alpha, weight).unwrap();
        let g = format!(
            "--beta-right {:?} --beta-left {:?}",
            a.beta_right(),
            a.beta_left()
        );
        (a, g)
    };
    let r = rng.next();
    let r2 = rng.next();
    let mut class = if r < 0.15 {
        0
    } else if r < 0.5 {
        1
    } else {
        2
    };
    let mu = if r < 0.15 {
        f64::INFINITY
    } else {
        let ms = least_friction(&arch, settings)
            .expect("least_friction")
            .unwrap_or(f64::INFINITY);
        if !ms.is_finite() {
            class = 0;
            f64::INFINITY
        } else if r < 0.5 {
            // just above μ_ms: 1e-3 .. 1e-2 relative
            ms * (1.0 + 10f64.powf(-3.0 + r2))
        } else if ms < 3.0 {
            ms + (3.0 - ms) * r2.max(1e-3)
        } else {
            ms * (1.0 + r2.max(1e-3))
        }
    };
    let label = format!(
        "arch-enum solve {geo} --mu {}{} --json",
        if mu.is_finite() {
            format!("{mu:?}")
        } else {
            "inf".to_string()
        },
        if centroid { " --weight centroid" } else { "" }
    );
    Case {
        arch,
        mu,
        label,
        kind: 4 * class + 2 * usize::from(symmetric) + usize::from(centroid),
    }
}

/// Random continuous arches (unsymmetric and symmetric, both weight models, μ = ∞, just
/// above μ_ms, or in (μ_ms, 3]): the crate's η_s (`eta_static`) equals the exchange
/// reference to 1e-10 relative. `CONT_CASES=N` for more than the default 20.
#[test]
fn continuous_arches_match_the_exchange_reference() {
    let count = crate::cases_from_env("CONT_CASES", 20);
    let started = Instant::now();
    let settings = Settings::default();
    let seed: u64 = std::env::var("CONT_SEED")
        .ok()
        .and_then(|v| v.parse().ok())
        .unwrap_or(0xc0a7_1a0e_5eed_0001);
    let mut rng = Rng(seed);
    let mut by_kind = [(0usize, 0.0f64); 12];
    let mut worst = String::new();
    let (mut max_rel, mut skipped, mut compared) = (0.0f64, 0usize, 0usize);
    let (mut t_ref, mut t_crate, mut evals) = (0.0, 0.0, 0usize);
    let mut disagreements = Vec::new();
    for _ in 0..count {
        let case = draw(&mut rng, &settings);
        let t0 = Instant::now();
        let reference = Cont::of(&case.arch, case.mu).least_thickness();
        t_ref += t0.elapsed().as_secs_f64();
        let t1 = Instant::now();
        let sol = solve(&case.arch, case.mu, &settings).expect("valid input");
        t_crate += t1.elapsed().as_secs_f64();
        let crate_eta = match &sol.outcome {
            Outcome::Limit(ls) => Some(ls.eta_static),
            Outcome::Unresolved {
                least_static: Some((eta, _)),
                ..
            } => Some(*eta),
            Outcome::NoCollapse { .. } => Some(0.0),
            _ => None,
        };
        match (&reference, crate_eta) {
            (Ok(RefEta::NoEquilibrium { .. }), None)
                if matches!(sol.outcome, Outcome::NoEquilibrium { .. }) =>
            {
                skipped += 1;
            }
            (
                Ok(RefEta::Least {
                    eta,
                    x,
                    touching,
                    evaluations,
                }),
                Some(c),
            ) => {
                evals += evaluations;
                compared += 1;
                let d = rel(*eta, c);
                if d > max_rel {
                    max_rel = d;
                    worst = format!("{}: reference {eta:.15}, crate {c:.15}", case.label);
                }
                by_kind[case.kind].0 += 1;
                by_kind[case.kind].1 = by_kind[case.kind].1.max(d);
                if d > 1e-10 {
                    disagreements.push(format!(
                        "{}: reference {eta:.15} (x = {x:?}, touching {}), crate {c:.15}, rel {d:.2e}",
                        case.label,
                        describe_touching(touching)
                    ));
                }
            }
            (r, _) => disagreements.push(format!(
                "{}: reference {r:?}, crate {:?}",
                case.label, sol.outcome
            )),
        }
    }
    println!(
        "continuum reference: {count} arches ({compared} compared, {skipped} no_equilibrium on both sides), max relative difference {max_rel:.2e}, {} disagreements; reference {t_ref:.1} s ({evals} margin evaluations), crate {t_crate:.1} s, total {:.1} s",
        disagreements.len(),
        started.elapsed().as_secs_f64()
    );
    println!("  largest difference: {worst}");
    let names = ["mu=inf", "mu just above mu_ms", "mu in (mu_ms, 3]"];
    for (i, (n, d)) in by_kind.iter().enumerate() {
        if *n > 0 {
            println!(
                "  {:<20} {:<11} {:<10}: {n:4} arches, max rel diff {d:.2e}",
                names[i / 4],
                if i & 2 != 0 {
                    "symmetric"
                } else {
                    "unsymmetric"
                },
                if i & 1 != 0 { "centroid" } else { "centreline" }
            );
        }
    }
    for d in &disagreements {
        println!("  {d}");
    }
    assert!(
        disagreements.is_empty(),
        "{} disagreements",
        disagreements.len()
    );
}
