//! An INDEPENDENT reference for λ_static, the largest multiplier λ ≥ 0 of a live load
//! (shared/spec/loads.md) with a statically admissible state, on a CONTINUOUS arch at fixed
//! (η, μ): a horizontal body force λ·(self-weight) either way (centreline or true-centroid
//! weight), or a vertical point load λ at the extrados point β_P. Nothing of the crate's
//! statics or live load is used (`arch_enum::load::LiveLoad` only names the load): the
//! dead rows are those of
//! `continuum_reference` (formulation §3), the live terms are written again here and
//! checked against a quadrature of the free body [β_R, β]; `arch_enum::multiplier::
//! static_range` appears only as the thing under test (`limit::solve` and `least_friction`
//! only to draw the random cases).
//!
//! Method: every activation function φ_k(z, β) = a_k(β)·z + c_k(β) is affine in
//! z = (h, v, w, λ) at fixed (β, η, μ), so over a finite set of angles λ_static is an LP
//! (maximise λ). The arch splits into smooth pieces: the whole arch for the horizontal
//! force; [β_R, β_P] (free body without the load) and [β_P, β_L] (with it) for the point
//! load, both containing β_P (the two one-sided limits of the jumping actions).
//! * **Bounded?** First the recession problem: the rows without their constant terms at
//!   λ = 1, margin LP max s with φ_k(dx, 1)/|a_x| + s ≤ 0 (by exchange as below). s ≥ 0
//!   (to rounding) gives a direction (dx, 1) along which every state stays admissible:
//!   λ_static is unbounded (typically a point load carried straight down to a springing
//!   inside the arch, s = 0 exactly, or two straight thrust lines inside a thick arch).
//! * **LP** over the working set (angles per piece; rows normalised by the gradient norm
//!   in x, so φ/|a_x| is a distance in units of x), with the box |x_i| ≤ XBOX, λ ≤ LBOX:
//!   HiGHS, then the exact dense dual-simplex finish of `continuum_reference::max_last`.
//! * **Exchange**: at the LP's z, every local maximum of every family over every piece
//!   (scan of SCAN cells + golden section, end points included: `scan_peaks`); violated
//!   maximisers join the piece's set, until the continuum max is ≤ TOL·(1 + |z|). The LP
//!   over a subset is a relaxation, so its λ ≥ λ_static, and its z is admissible over the
//!   continuum to that tolerance. At a vertex optimum (four contacts) this takes ~3
//!   rounds; where the optimum rests on three contacts and the curvature of a family the
//!   convergence is linear (~15 rounds) and λ is good to a few 1e-13 relative.
//! * The final state is checked on a dense grid with `model::ntm` (another transcription
//!   of the dead statics) plus the live terms.
//!
//! Second route (`discrete_lambda`): the arch cut into N equal voussoirs (plus a joint at
//! β_P), λ_static of that discrete arch by one LP on its joints (both sides of the loaded
//! joint), rows built from `model::ntm`. It is a relaxation of the continuum problem, so
//! it lies above, by O(h²) where the maxima of φ are smooth (the grids 2000 ⊂ 4000 are
//! nested: the error is C δ², δ the distance of a contact to the nearest joint, and need
//! not fall by 4); with the reference's contact angles added as joints it must give the
//! same λ to rounding at a vertex optimum. On the 2000 voussoirs it is also compared with
//! the crate's discrete `static_range`, which answers today.

use crate::continuum_reference::{max_last, scan_peaks, Cont};
use crate::model;
use crate::search_reference::Rng;
use arch_enum::load::LiveLoad;
use arch_enum::multiplier::{static_range, StaticRange};
use arch_enum::{least_friction, solve, Arch, Outcome, Settings, WeightModel};
use std::f64::consts::PI;
use std::time::Instant;

/// Equally spaced angles the working set starts with (over the whole arch).
const INITIAL: usize = 200;
/// Cells of the dense scan of each piece.
const SCAN: usize = 1024;
/// Box on x and on λ in the LP for λ_static (decided bounded by the recession problem
/// first): λ reaching LBOX means λ_static ≥ LBOX, treated as unbounded in comparisons.
const XBOX: f64 = 1e12;
const LBOX: f64 = 1e9;
/// Box on the direction dx per unit λ and on the margin in the recession problem.
const RBOX: f64 = 1e3;
/// The exchange stops when the continuum max of φ/|a_x| is below TOL·(1 + |z|). Where
/// λ_static is fixed by three contacts and the curvature of a fourth family (no vertex of
/// four planes), the exchange converges only linearly (the violation falls by ~4, λ by ~2
/// a round), so the tolerance is set near the rounding of the rows (~1e-16·|z|).
const TOL: f64 = 2e-15;
/// Exchange rounds before giving up.
const MAX_ROUNDS: usize = 60;

const FAMILY: [&str; 4] = ["E", "I", "S+", "S-"];

/// Of the random loads drawn (two per arch, skipped arches included), the crate must answer
/// and be compared on at least this fraction...
const MIN_COMPARED_FRACTION: f64 = 0.8;
/// ... and on at least this many (the default 20 arches give 40 loads), so that a run that
/// draws or compares nothing fails.
const MIN_RANDOM_COMPARED: usize = 30;

/// The live actions (N_L, T_L, M_L) per unit λ at the section β (sin β = s, cos β = c)
/// of an arch with right springing `br`, from the free body [β_R, β] (loads.md):
/// horizontal body force towards ±x (its resultant on [β_R, β] is ±Δ at the centroid of
/// the piece, whose height times Δ is ρ (cos β_R − cos β)); point load at β_P when the
/// free body contains it (`loaded`).
#[allow(clippy::too_many_arguments)]
fn live_ntm(
    load: &LiveLoad,
    br: f64,
    eta: f64,
    rho: f64,
    beta: f64,
    s: f64,
    c: f64,
    loaded: bool,
) -> [f64; 3] {
    match *load {
        LiveLoad::Pressure(_) => unreachable!("this reference draws horizontal and point loads"),
        LiveLoad::Horizontal { towards_right } => {
            let k = if towards_right { 1.0 } else { -1.0 };
            let d = beta - br;
            // force (k Δ, 0) at G: N = F·n, T = −F·t, M = (G − P) × F
            [-k * d * s, -k * d * c, -k * (rho * (br.cos() - c) - d * s)]
        }
        LiveLoad::Point { beta: bp } => {
            if loaded {
                // force (0, −1) at E_P = (1 + η/2)(cos β_P, sin β_P)
                [-c, s, -((1.0 + 0.5 * eta) * bp.cos() - c)]
            } else {
                [0.0; 3]
            }
        }
    }
}

/// The activation function of family k from (N, T, M).
fn combine(k: usize, eta: f64, mu: f64, [n, t, m]: [f64; 3]) -> f64 {
    match k {
        0 => m - 0.5 * eta * n,
        1 => -m - 0.5 * eta * n,
        2 => t - mu * n,
        3 => -t - mu * n,
        _ => unreachable!(),
    }
}

/// A smooth piece of the arch: its scan grid and whether its free bodies carry the
/// point load (always true for the horizontal force).
struct Piece {
    loaded: bool,
    grid: Vec<f64>,
    gsin: Vec<f64>,
    gcos: Vec<f64>,
}

impl Piece {
    fn new(a: f64, b: f64, loaded: bool) -> Piece {
        let grid: Vec<f64> = (0..=SCAN)
            .map(|i| {
                if i == SCAN {
                    b
                } else {
                    a + (b - a) * i as f64 / SCAN as f64
                }
            })
            .collect();
        Piece {
            loaded,
            gsin: grid.iter().map(|t| t.sin()).collect(),
            gcos: grid.iter().map(|t| t.cos()).collect(),
            grid,
        }
    }
    fn lo(&self) -> f64 {
        self.grid[0]
    }
    fn hi(&self) -> f64 {
        self.grid[SCAN]
    }
}

/// A loaded continuous arch at (η, μ).
pub struct LoadedCont {
    dead: Cont,
    br: f64,
    bl: f64,
    centroid: bool,
    eta: f64,
    mu: f64,
    rho: f64,
    load: LiveLoad,
    pieces: Vec<Piece>,
    /// Rows without constant terms (the recession problem).
    homogeneous: bool,
}

/// A converged exchange.
struct Exchanged {
    z: [f64; 4],
    boxed: bool,
    /// The local maxima of every family at z: (family, piece, β, φ/|a_x|).
    peaks: Vec<(usize, usize, f64, f64)>,
    rounds: usize,
    angles: usize,
}

/// What the reference found.
#[derive(Debug, Clone)]
pub enum RefLambda {
    /// λ_static and a state there.
    Static {
        lambda: f64,
        x: [f64; 3],
        /// Contacts within 1e-9 of active: (family, piece, β).
        touching: Vec<(usize, usize, f64)>,
        /// Exchange rounds and final size of the working set.
        rounds: usize,
        angles: usize,
        /// The recession problem's margin (< 0: bounded).
        recession_margin: f64,
    },
    /// λ_static is unbounded: the recession problem (no dead load) admits (dx, 1), with
    /// `margin` (≥ −1e-13: 0 when some contact stays exactly active, e.g. a load carried
    /// straight down to a springing).
    Unbounded { direction: [f64; 3], margin: f64 },
    /// λ reaches the box LBOX but the recession problem does not admit λ: λ_static is
    /// finite and at least LBOX (not compared).
    AtLeast(f64),
}

impl RefLambda {
    /// λ_static, `None` when unbounded (or at least LBOX).
    fn value(&self) -> Option<f64> {
        match self {
            RefLambda::Static { lambda, .. } => Some(*lambda),
            RefLambda::Unbounded { .. } | RefLambda::AtLeast(_) => None,
        }
    }
}

impl LoadedCont {
    pub fn new(br: f64, bl: f64, centroid: bool, eta: f64, mu: f64, load: LiveLoad) -> Self {
        let pieces = match load {
            LiveLoad::Pressure(_) => {
                unreachable!("this reference draws horizontal and point loads")
            }
            LiveLoad::Horizontal { .. } => vec![Piece::new(br, bl, true)],
            LiveLoad::Point { beta } => {
                assert!(br < beta && beta < bl, "point load inside the arch");
                vec![Piece::new(br, beta, false), Piece::new(beta, bl, true)]
            }
        };
        LoadedCont {
            dead: Cont::new(br, bl, centroid, mu),
            br,
            bl,
            centroid,
            eta,
            mu,
            rho: if centroid {
                1.0 + eta * eta / 12.0
            } else {
                1.0
            },
            load,
            pieces,
            homogeneous: false,
        }
    }

    pub fn of(arch: &Arch, eta: f64, mu: f64, load: LiveLoad) -> Self {
        Self::new(
            arch.beta_right(),
            arch.beta_left(),
            arch.weight() == WeightModel::Centroid,
            eta,
            mu,
            load,
        )
    }

    fn families(&self) -> usize {
        self.dead.families()
    }

    /// φ_k = a·(h, v, w, λ) + c at β on piece p, normalised by |a_x| (sin, cos given).
    fn row(&self, k: usize, p: usize, beta: f64, s: f64, c: f64) -> ([f64; 4], f64) {
        let (a, c0) = self.dead.row_raw(k, self.eta, beta, s, c);
        let live = live_ntm(
            &self.load,
            self.br,
            self.eta,
            self.rho,
            beta,
            s,
            c,
            self.pieces[p].loaded,
        );
        let l = combine(k, self.eta, self.mu, live);
        let n = (a[0] * a[0] + a[1] * a[1] + a[2] * a[2]).sqrt();
        let c0 = if self.homogeneous { 0.0 } else { c0 };
        ([a[0] / n, a[1] / n, a[2] / n, l / n], c0 / n)
    }

    fn g(&self, k: usize, p: usize, z: &[f64; 4], beta: f64) -> f64 {
        let (a, c) = self.row(k, p, beta, beta.sin(), beta.cos());
        a[0] * z[0] + a[1] * z[1] + a[2] * z[2] + a[3] * z[3] + c
    }

    /// Every local maximum of every family on every piece at z: (family, piece, β, g).
    fn peaks(&self, z: &[f64; 4]) -> Vec<(usize, usize, f64, f64)> {
        let mut out = Vec::new();
        let mut vals = vec![0.0; SCAN + 1];
        for (p, piece) in self.pieces.iter().enumerate() {
            for k in 0..self.families() {
                for (i, v) in vals.iter_mut().enumerate() {
                    let (a, c) = self.row(k, p, piece.grid[i], piece.gsin[i], piece.gcos[i]);
                    *v = a[0] * z[0] + a[1] * z[1] + a[2] * z[2] + a[3] * z[3] + c;
                }
                // golden section must stay on the piece (the one-sided limits at β_P)
                let (lo, hi) = (piece.lo(), piece.hi());
                let f = |t: f64| self.g(k, p, z, t.clamp(lo, hi));
                out.extend(
                    scan_peaks(&piece.grid, &vals, f)
                        .into_iter()
                        .map(|(b, v)| (k, p, b, v)),
                );
            }
        }
        out
    }

    /// max λ over the working set (one sorted angle list per piece): (z, box binds).
    /// The LP over the working set (one sorted angle list per piece): (z, box binds).
    /// λ_static: max λ over z = (x, λ). Recession (homogeneous rows): the margin LP
    /// max s over z = (dx, s) with g(dx, λ = 1) + s ≤ 0.
    fn lp(&self, set: &[Vec<f64>]) -> Result<([f64; 4], bool), String> {
        let nf = self.families();
        let homogeneous = self.homogeneous;
        let rows: Vec<([f64; 4], f64)> = set
            .iter()
            .enumerate()
            .flat_map(|(p, angles)| {
                angles.iter().flat_map(move |&b| {
                    let (sb, cb) = (b.sin(), b.cos());
                    (0..nf).map(move |k| {
                        let (a, c) = self.row(k, p, b, sb, cb);
                        if homogeneous {
                            ([a[0], a[1], a[2], 1.0], -a[3])
                        } else {
                            (a, -c)
                        }
                    })
                })
            })
            .collect();
        if homogeneous {
            max_last(rows, [RBOX; 4])
        } else {
            max_last(rows, [XBOX, XBOX, XBOX, LBOX])
        }
    }

    fn initial_set(&self) -> Vec<Vec<f64>> {
        let all: Vec<f64> = (0..=INITIAL)
            .map(|i| {
                if i == INITIAL {
                    self.bl
                } else {
                    self.br + (self.bl - self.br) * i as f64 / INITIAL as f64
                }
            })
            .collect();
        self.pieces
            .iter()
            .map(|pc| {
                let (lo, hi) = (pc.lo(), pc.hi());
                let mut v: Vec<f64> = all.iter().copied().filter(|&b| b > lo && b < hi).collect();
                v.insert(0, lo);
                v.push(hi);
                v
            })
            .collect()
    }

    /// The recession problem: the same rows without their constant terms (no dead
    /// load). A direction (dx, 1) admissible there makes λ_static unbounded.
    fn recession(&self) -> LoadedCont {
        let mut r = LoadedCont::new(
            self.br,
            self.bl,
            self.centroid,
            self.eta,
            self.mu,
            self.load,
        );
        r.homogeneous = true;
        r
    }

    /// The exchange: the LP over a growing working set until its z is admissible over
    /// the continuum to 1e-14·(1 + |z|).
    fn exchange(&self) -> Result<Exchanged, String> {
        let mut set = self.initial_set();
        for round in 1..=MAX_ROUNDS {
            let (z, boxed) = self.lp(&set)?;
            // the recession problem's rows are checked at (dx, λ = 1) against −s
            let (at, shift) = if self.homogeneous {
                ([z[0], z[1], z[2], 1.0], z[3])
            } else {
                (z, 0.0)
            };
            let peaks = self.peaks(&at);
            let worst = peaks.iter().map(|p| p.3).fold(f64::NEG_INFINITY, f64::max) + shift;
            let zs = at.iter().map(|v| v.abs()).fold(0.0, f64::max);
            let tol = TOL * (1.0 + zs);
            if std::env::var("LOADCONT_DEBUG").is_ok() {
                let viol: Vec<String> = peaks
                    .iter()
                    .filter(|p| p.3 + shift > tol)
                    .map(|p| format!("{}{}@{:.15}:{:.1e}", FAMILY[p.0], ["", "'"][p.1], p.2, p.3))
                    .collect();
                println!(
                    "round {round}: z = {z:?} boxed {boxed} worst {worst:e} violated {}",
                    viol.join(" ")
                );
            }
            if worst <= tol {
                return Ok(Exchanged {
                    z,
                    boxed,
                    peaks,
                    rounds: round,
                    angles: set.iter().map(Vec::len).sum(),
                });
            }
            let mut added = 0;
            for &(_, p, b, g) in &peaks {
                if g + shift > tol {
                    let s = &mut set[p];
                    let i = s.partition_point(|&t| t < b);
                    let near = (i < s.len() && (s[i] - b).abs() <= 1e-15 * (1.0 + b.abs()))
                        || (i > 0 && (b - s[i - 1]).abs() <= 1e-15 * (1.0 + b.abs()));
                    if !near {
                        s.insert(i, b);
                        added += 1;
                    }
                }
            }
            if added == 0 {
                return Err(format!(
                    "exchange stalled: continuum max {worst:e} > {tol:e} at angles already in the working set (z = {z:?})"
                ));
            }
        }
        Err(format!("exchange did not converge in {MAX_ROUNDS} rounds"))
    }

    /// λ_static by exchange, after the recession problem has decided whether it is
    /// bounded: a direction dx with every homogeneous row ≤ 0 at (dx, λ = 1) (margin
    /// s ≥ −1e-13, i.e. admissible to rounding) makes it unbounded.
    pub fn lambda_static(&self) -> Result<RefLambda, String> {
        let rec = self.recession().exchange()?;
        let (dx, margin) = ([rec.z[0], rec.z[1], rec.z[2]], rec.z[3]);
        if margin >= -1e-13 * (1.0 + dx.iter().map(|v| v.abs()).fold(0.0, f64::max)) {
            if rec.boxed {
                return Err(format!(
                    "the box binds in the recession problem: dx = {dx:?}, margin {margin:e}"
                ));
            }
            return Ok(RefLambda::Unbounded {
                direction: dx,
                margin,
            });
        }
        let ex = self.exchange()?;
        let z = ex.z;
        if ex.boxed {
            if z[3] >= LBOX * (1.0 - 1e-12) {
                return Ok(RefLambda::AtLeast(z[3]));
            }
            return Err(format!(
                "the box on x binds at lambda = {}: z = {z:?}",
                z[3]
            ));
        }
        self.dense_check(&z)?;
        let touching = ex
            .peaks
            .iter()
            .filter(|p| p.3 > -1e-9)
            .map(|p| (p.0, p.1, p.2))
            .collect();
        Ok(RefLambda::Static {
            lambda: z[3],
            x: [z[0], z[1], z[2]],
            touching,
            rounds: ex.rounds,
            angles: ex.angles,
            recession_margin: margin,
        })
    }

    /// The state is admissible on a dense grid of every piece, with the dead statics of
    /// `model::ntm` (not the rows above) plus the live terms.
    pub(crate) fn dense_check(&self, z: &[f64; 4]) -> Result<(), String> {
        let x = [z[0], z[1], z[2]];
        let zs = z.iter().map(|v| v.abs()).fold(0.0, f64::max);
        let scale = (1.0 + zs) * (1.0 + if self.mu.is_finite() { self.mu } else { 0.0 });
        let n = 10_000;
        for piece in &self.pieces {
            for i in 0..=n {
                let b = piece.lo() + (piece.hi() - piece.lo()) * i as f64 / n as f64;
                let (nn, t, m) = model::ntm(self.br, self.rho, x, b);
                let l = live_ntm(
                    &self.load,
                    self.br,
                    self.eta,
                    self.rho,
                    b,
                    b.sin(),
                    b.cos(),
                    piece.loaded,
                );
                let a = [nn + z[3] * l[0], t + z[3] * l[1], m + z[3] * l[2]];
                for (k, name) in FAMILY.iter().enumerate().take(self.families()) {
                    let phi = combine(k, self.eta, self.mu, a);
                    if phi > 2e-13 * scale {
                        return Err(format!(
                            "the state z = {z:?} violates {name} at {b} by {phi:e} (dense check)"
                        ));
                    }
                }
            }
        }
        Ok(())
    }
}

/// The second route: λ_static of the arch cut into `n` equal voussoirs (plus a joint at
/// the point load's β_P when it is not one, and at the angles `extra`), one LP on every joint's activation
/// functions, both sides of the loaded joint (HiGHS with the exact finish of `max_last`:
/// HiGHS alone is off by up to ~1e-7 in λ here); the dead statics from `model::ntm`
/// (rows built from its values, not from `continuum_reference`'s rows). `None` when λ
/// reaches LBOX.
#[allow(clippy::too_many_arguments)]
fn discrete_lambda(
    br: f64,
    bl: f64,
    centroid: bool,
    eta: f64,
    mu: f64,
    load: LiveLoad,
    n: usize,
    extra: &[f64],
) -> Option<f64> {
    let joints = discrete_joints(br, bl, n, load, extra);
    discrete_lambda_at(&joints, centroid, eta, mu, load)
}

/// The joints of the second route: `n` equal voussoirs, plus β_P and `extra`.
fn discrete_joints(br: f64, bl: f64, n: usize, load: LiveLoad, extra: &[f64]) -> Vec<f64> {
    let mut joints: Vec<f64> = (0..=n)
        .map(|i| {
            if i == n {
                bl
            } else {
                br + (bl - br) * i as f64 / n as f64
            }
        })
        .collect();
    let bp = match load {
        LiveLoad::Pressure(_) => unreachable!("this reference draws horizontal and point loads"),
        LiveLoad::Point { beta } => Some(beta),
        LiveLoad::Horizontal { .. } => None,
    };
    for &b in bp.iter().chain(extra) {
        let i = joints.partition_point(|&t| t < b);
        if i < joints.len() && (joints[i] - b).abs() <= 1e-12 {
            joints[i] = b;
        } else if i > 0 && (b - joints[i - 1]).abs() <= 1e-12 {
            joints[i - 1] = b;
        } else {
            joints.insert(i, b);
        }
    }
    if let Some(q) = bp {
        // the load's own angle wins over a reference angle within 1e-12 of it
        let i = joints
            .iter()
            .position(|&t| (t - q).abs() <= 1e-12)
            .expect("the load's joint");
        joints[i] = q;
    }
    joints
}

/// λ_static of the discrete arch with these joints (the springings first and last).
fn discrete_lambda_at(
    joints: &[f64],
    centroid: bool,
    eta: f64,
    mu: f64,
    load: LiveLoad,
) -> Option<f64> {
    let br = joints[0];
    let rho = if centroid {
        1.0 + eta * eta / 12.0
    } else {
        1.0
    };
    let bp = match load {
        LiveLoad::Pressure(_) => unreachable!("this reference draws horizontal and point loads"),
        LiveLoad::Point { beta } => Some(beta),
        LiveLoad::Horizontal { .. } => None,
    };
    let nf = if mu.is_finite() { 4 } else { 2 };
    let mut rows = Vec::with_capacity(nf * (joints.len() + 1));
    for &b in joints {
        let sides: &[bool] = match bp {
            Some(q) if q == b => &[false, true],
            Some(q) => {
                if b > q {
                    &[true]
                } else {
                    &[false]
                }
            }
            None => &[true],
        };
        let dead = |x: [f64; 3]| {
            let (nn, t, m) = model::ntm(br, rho, x, b);
            [nn, t, m]
        };
        let d0 = dead([0.0; 3]);
        let du = [
            dead([1.0, 0.0, 0.0]),
            dead([0.0, 1.0, 0.0]),
            dead([0.0, 0.0, 1.0]),
        ];
        for &loaded in sides {
            let l = live_ntm(&load, br, eta, rho, b, b.sin(), b.cos(), loaded);
            for k in 0..nf {
                let c = combine(k, eta, mu, d0);
                let a: Vec<f64> = du.iter().map(|u| combine(k, eta, mu, *u) - c).collect();
                let norm = (a[0] * a[0] + a[1] * a[1] + a[2] * a[2]).sqrt();
                let al = combine(k, eta, mu, l);
                rows.push((
                    [a[0] / norm, a[1] / norm, a[2] / norm, al / norm],
                    -c / norm,
                ));
            }
        }
    }
    let (z, _) = max_last(rows, [XBOX, XBOX, XBOX, LBOX]).expect("discrete LP");
    (z[3] < LBOX * (1.0 - 1e-9)).then_some(z[3])
}

/// N, T, M at the section β by quadrature of the free body [β_R, β]: the reaction (−h, v)
/// at the right springing's centre point with moment w, the weight (density 1 per unit
/// centreline angle, or 1/η per unit area of the annular sector), the body force λ·k per
/// unit weight towards +x, the point load (0, −λ) at the extrados of β_P when `loaded`.
/// Gauss–Legendre, 8 panels of 12 points in θ, 3 points in r.
#[allow(clippy::too_many_arguments)]
fn quadrature_ntm(
    br: f64,
    centroid: bool,
    eta: f64,
    load: &LiveLoad,
    x: [f64; 3],
    lambda: f64,
    beta: f64,
    loaded: bool,
) -> [f64; 3] {
    let (p_x, p_y) = (beta.cos(), beta.sin());
    // total force (fx, fy) and moment about P
    let mut f = [-x[0], x[1]];
    let mut m = x[2] + (br.cos() - p_x) * x[1] - (br.sin() - p_y) * (-x[0]);
    let kx = match *load {
        LiveLoad::Pressure(_) => unreachable!("this reference draws horizontal and point loads"),
        LiveLoad::Horizontal { towards_right } => lambda * if towards_right { 1.0 } else { -1.0 },
        LiveLoad::Point { .. } => 0.0,
    };
    let mut add = |q: (f64, f64), force: (f64, f64)| {
        f[0] += force.0;
        f[1] += force.1;
        m += (q.0 - p_x) * force.1 - (q.1 - p_y) * force.0;
    };
    let (gt, wt) = gauss_legendre(12);
    let (gr, wr) = gauss_legendre(3);
    let panels = 8;
    let h = (beta - br) / panels as f64;
    for j in 0..panels {
        let (a, b) = (br + j as f64 * h, br + (j + 1) as f64 * h);
        for (ti, tw) in gt.iter().zip(&wt) {
            let th = 0.5 * (a + b) + 0.5 * (b - a) * ti;
            let dth = 0.5 * (b - a) * tw;
            if centroid {
                for (ri, rw) in gr.iter().zip(&wr) {
                    let r = 1.0 + 0.5 * eta * ri;
                    // dm = (1/η) r dr dθ, dr = (η/2) rw
                    let dm = r * 0.5 * rw * dth;
                    add((r * th.cos(), r * th.sin()), (kx * dm, -dm));
                }
            } else {
                add((th.cos(), th.sin()), (kx * dth, -dth));
            }
        }
    }
    if let LiveLoad::Point { beta: bp } = *load {
        if loaded {
            let e = 1.0 + 0.5 * eta;
            add((e * bp.cos(), e * bp.sin()), (0.0, -lambda));
        }
    }
    let (s, c) = (beta.sin(), beta.cos());
    [-f[0] * s + f[1] * c, -(f[0] * c + f[1] * s), m]
}

/// Nodes and weights of n-point Gauss–Legendre on [−1, 1] (Newton on P_n).
fn gauss_legendre(n: usize) -> (Vec<f64>, Vec<f64>) {
    let (mut xs, mut ws) = (Vec::new(), Vec::new());
    for i in 0..n {
        let mut t = (PI * (i as f64 + 0.75) / (n as f64 + 0.5)).cos();
        let mut dp = 0.0;
        for _ in 0..100 {
            let (mut p0, mut p1) = (1.0, t);
            for k in 2..=n {
                let p2 = ((2 * k - 1) as f64 * t * p1 - (k - 1) as f64 * p0) / k as f64;
                p0 = p1;
                p1 = p2;
            }
            dp = n as f64 * (t * p1 - p0) / (t * t - 1.0);
            let dt = p1 / dp;
            t -= dt;
            if dt.abs() < 1e-16 {
                break;
            }
        }
        xs.push(t);
        ws.push(2.0 / ((1.0 - t * t) * dp * dp));
    }
    (xs, ws)
}

fn rel(a: f64, b: f64) -> f64 {
    (a - b).abs() / a.abs().max(b.abs()).max(1e-300)
}

fn describe(r: &RefLambda) -> String {
    match r {
        RefLambda::Static {
            x,
            touching,
            rounds,
            angles,
            recession_margin,
            ..
        } => {
            let t: Vec<String> = touching
                .iter()
                .map(|(k, p, b)| format!("{}{}@{:.6}", FAMILY[*k], ["", "'"][*p], b))
                .collect();
            format!(
                "x = {x:?}, touching {} ({rounds} rounds, {angles} angles; recession margin {recession_margin:.2e})",
                t.join(" ")
            )
        }
        RefLambda::Unbounded { direction, margin } => format!(
            "unbounded: recession direction dx = {direction:?} per unit lambda, margin {margin:.1e}"
        ),
        RefLambda::AtLeast(l) => format!("lambda >= {l}, bounded"),
    }
}

fn load_name(load: &LiveLoad) -> String {
    match load {
        LiveLoad::Pressure(_) => unreachable!("this reference draws horizontal and point loads"),
        LiveLoad::Horizontal { towards_right } => {
            format!("horizontal {}", if *towards_right { "+x" } else { "-x" })
        }
        LiveLoad::Point { beta } => format!("point at {beta:.6}"),
    }
}

/// The crate's λ_static: Ok(Some(λ)), Ok(None) unbounded, Err(text) no answer yet.
fn crate_lambda(arch: &Arch, eta: f64, mu: f64, load: &LiveLoad) -> Result<Option<f64>, String> {
    match static_range(arch, eta, mu, load, &Settings::default()).expect("valid input") {
        Ok(StaticRange::Interval { min, max }) => {
            if min.0 > 1e-12 {
                return Err(format!("lambda_min = {} > 0 on an arch that stands", min.0));
            }
            Ok(max.map(|m| m.0))
        }
        Ok(StaticRange::NoEquilibrium) => Err("no_equilibrium on an arch that stands".into()),
        Err(e) => Err(format!("no answer: {e}")),
    }
}

/// Whether the crate's answer agrees with the reference: λ_static to 1e-9 relative;
/// unbounded (or bounded beyond LBOX = 1e9) with `None` or a value beyond LBOX.
fn agrees(reference: &RefLambda, crate_value: Option<f64>) -> bool {
    match (reference, crate_value) {
        (RefLambda::Static { lambda, .. }, Some(c)) => rel(*lambda, c) <= 1e-9,
        (RefLambda::Static { .. }, None) => false,
        // beyond LBOX: either answer
        (RefLambda::Unbounded { .. } | RefLambda::AtLeast(_), None) => true,
        (RefLambda::Unbounded { .. } | RefLambda::AtLeast(_), Some(c)) => c >= LBOX * (1.0 - 1e-9),
    }
}

/// The live statics of the reference (rows and `live_ntm`, with the dead terms of
/// `continuum_reference` and `model`) against a quadrature of the free body, both loads,
/// both weight models, both sides of the point load.
#[test]
fn loaded_continuum_statics_match_a_quadrature() {
    let mut rng = Rng(0x10ad_c047_0000_0001);
    let mut worst = 0.0f64;
    for case in 0..40 {
        let br = -0.6 + 1.2 * rng.next();
        let bl = PI - 0.6 + 1.2 * rng.next();
        let centroid = case % 2 == 1;
        let eta = 0.05 + 1.2 * rng.next();
        let mu = 0.2 + 1.5 * rng.next();
        let load = match case % 4 {
            0 => LiveLoad::Horizontal {
                towards_right: true,
            },
            1 => LiveLoad::Horizontal {
                towards_right: false,
            },
            _ => LiveLoad::Point {
                beta: br + (bl - br) * (0.1 + 0.8 * rng.next()),
            },
        };
        let lc = LoadedCont::new(br, bl, centroid, eta, mu, load);
        let z = [
            rng.next() * 2.0 - 1.0,
            rng.next() * 3.0,
            rng.next() - 0.5,
            rng.next() * 2.0,
        ];
        for (p, piece) in lc.pieces.iter().enumerate() {
            for f in [0.0, 0.21, 0.5, 0.77, 1.0] {
                let b = piece.lo() + f * (piece.hi() - piece.lo());
                let q = quadrature_ntm(
                    br,
                    centroid,
                    eta,
                    &load,
                    [z[0], z[1], z[2]],
                    z[3],
                    b,
                    piece.loaded,
                );
                for (k, name) in FAMILY.iter().enumerate() {
                    let (a, _) = lc.dead.row_raw(k, eta, b, b.sin(), b.cos());
                    let n = (a[0] * a[0] + a[1] * a[1] + a[2] * a[2]).sqrt();
                    let (r, rc) = lc.row(k, p, b, b.sin(), b.cos());
                    let phi = n * (r[0] * z[0] + r[1] * z[1] + r[2] * z[2] + r[3] * z[3] + rc);
                    let expected = combine(k, eta, mu, q);
                    let d = (phi - expected).abs();
                    worst = worst.max(d);
                    assert!(
                        d < 1e-12,
                        "case {case} {} {name} at {b} (piece {p}): rows {phi} vs quadrature {expected}",
                        load_name(&load)
                    );
                }
            }
        }
    }
    println!("live statics vs free-body quadrature: max |difference| {worst:.2e}");
}

/// One random case of the comparison.
struct Case {
    arch: Arch,
    eta: f64,
    mu: f64,
    label: String,
}

/// A random continuous arch that stands: springings within ±0.5 of the semicircle's,
/// either weight, μ = ∞ or in (1.1 μ_ms, 2], η in [1.05 η_s, 0.8]. `Err` (the reason)
/// when it does not qualify.
fn draw(rng: &mut Rng, settings: &Settings) -> Result<Case, String> {
    let br = -0.5 + rng.next();
    let bl = PI - 0.5 + rng.next();
    let centroid = rng.next() < 0.5;
    let weight = if centroid {
        WeightModel::Centroid
    } else {
        WeightModel::Centreline
    };
    let arch = Arch::new(br, bl, weight).unwrap();
    let (r, r2, r3) = (rng.next(), rng.next(), rng.next());
    let mu = if r < 0.4 {
        f64::INFINITY
    } else {
        let ms = least_friction(&arch, settings)
            .map_err(|e| format!("least_friction: {e}"))?
            .unwrap_or(f64::INFINITY);
        if 1.1 * ms >= 2.0 {
            return Err(format!("mu_ms = {ms} too large"));
        }
        1.1 * ms + (2.0 - 1.1 * ms) * r2.max(1e-3)
    };
    let sol = solve(&arch, mu, settings).expect("valid input");
    let eta_s = match &sol.outcome {
        Outcome::Limit(ls) => ls.eta_static,
        Outcome::Unresolved {
            least_static: Some((e, _)),
            ..
        } => *e,
        o => return Err(format!("no least thickness: {o:?}")),
    };
    if 1.05 * eta_s >= 0.8 {
        return Err(format!("eta_s = {eta_s} too thick"));
    }
    // skewed towards the thin end: thick arches carry most point loads unboundedly
    let eta = 1.05 * eta_s + (0.8 - 1.05 * eta_s) * r3 * r3;
    let label = format!(
        "--beta-right {br:?} --beta-left {bl:?} --eta {eta:?} --mu {}{}",
        if mu.is_finite() {
            format!("{mu:?}")
        } else {
            "inf".into()
        },
        if centroid { " --weight centroid" } else { "" }
    );
    Ok(Case {
        arch,
        eta,
        mu,
        label,
    })
}

/// λ_static of continuous arches: the reference's values on the semicircle (printed,
/// cross-checked against fine discretisations), and random continuous arches against
/// `arch_enum::multiplier::static_range` to 1e-9 relative. Every case must be compared and
/// agree: an `Ok` that disagrees fails, and so does a crate `Err` (no answer where the
/// reference has one). Every semicircle case is compared, and at least
/// [`MIN_COMPARED_FRACTION`] of the random loads and at least [`MIN_RANDOM_COMPARED`] of
/// them, so that a run that skips its draws or compares nothing fails.
/// `LOADCONT_CASES=N` for more than 20 arches (two loads each; fewer than 15 cannot reach
/// the floor), `LOADCONT_SEED` for another draw.
#[test]
fn continuous_lambda_static_matches_the_reference() {
    let started = Instant::now();
    let settings = Settings::default();
    let mut failures = Vec::new();
    let mut crate_errors = Vec::new();
    let mut compared = 0;
    // the semicircle: table of reference values, the second route, and the crate
    let mut table = Vec::new();
    for centroid in [false, true] {
        for eta in [0.12, 0.15, 0.2, 0.3] {
            table.push((
                centroid,
                eta,
                f64::INFINITY,
                LiveLoad::Horizontal {
                    towards_right: true,
                },
            ));
        }
    }
    for centroid in [false, true] {
        for mu in [f64::INFINITY, 0.6] {
            for bp in [PI / 3.0, PI / 2.0] {
                table.push((centroid, 0.2, mu, LiveLoad::Point { beta: bp }));
            }
        }
    }
    let mut t_disc = 0.0;
    let mut worst_disc = [0.0f64; 3];
    let mut worst_crate_discrete = 0.0f64;
    println!(
        "semicircle (alpha = 0): lambda_static of the reference; the second route minus it: N = 2000 and 4000 equal voussoirs, and 4000 plus the reference's contact angles"
    );
    for &(centroid, eta, mu, load) in &table {
        let weight = if centroid {
            WeightModel::Centroid
        } else {
            WeightModel::Centreline
        };
        let arch = Arch::symmetric(0.0, weight).unwrap();
        let reference = LoadedCont::of(&arch, eta, mu, load)
            .lambda_static()
            .unwrap_or_else(|e| panic!("reference failed: {e}"));
        let RefLambda::Static {
            lambda: lr,
            touching,
            ..
        } = &reference
        else {
            panic!("semicircle: lambda_static unbounded? {reference:?}")
        };
        let lr = *lr;
        let contacts: Vec<f64> = touching.iter().map(|t| t.2).collect();
        let t0 = Instant::now();
        let d: Vec<f64> = [(2000, &[][..]), (4000, &[][..]), (4000, &contacts[..])]
            .iter()
            .map(|&(n, extra)| {
                discrete_lambda(0.0, PI, centroid, eta, mu, load, n, extra)
                    .expect("discrete bounded")
            })
            .collect();
        t_disc += t0.elapsed().as_secs_f64();
        // the crate already answers for discrete arches: the second route's 2000 voussoirs
        // against `static_range` (its live statics in src/load.rs, and the Ok path of the
        // comparison)
        let joints = discrete_joints(0.0, PI, 2000, load, &[]);
        let discrete = Arch::new(0.0, PI, weight)
            .unwrap()
            .with_joints(&joints)
            .unwrap();
        match crate_lambda(&discrete, eta, mu, &load) {
            Ok(c) => {
                let r = RefLambda::Static {
                    lambda: d[0],
                    x: [0.0; 3],
                    touching: Vec::new(),
                    rounds: 0,
                    angles: 0,
                    recession_margin: -1.0,
                };
                worst_crate_discrete = worst_crate_discrete.max(rel(d[0], c.unwrap_or(f64::NAN)));
                if !agrees(&r, c) {
                    failures.push(format!(
                        "2000 voussoirs: crate {c:?}, second route {:.15e}",
                        d[0]
                    ));
                }
            }
            Err(e) => failures.push(format!("2000 voussoirs: crate {e}")),
        }
        let name = format!(
            "{:<10} eta {eta:<4} mu {:<4} {:<16}",
            if centroid { "centroid" } else { "centreline" },
            if mu.is_finite() {
                format!("{mu}")
            } else {
                "inf".into()
            },
            load_name(&load)
        );
        println!(
            "  {name} {lr:.13e}  N=2000 {:+.2e}  N=4000 {:+.2e}  4000+contacts {:+.1e}   {}",
            d[0] - lr,
            d[1] - lr,
            d[2] - lr,
            describe(&reference)
        );
        // a relaxation: from above; O(h²) (the grids are nested, so the error is
        // C δ² with δ the distance of a contact to the nearest joint, ≤ h/2, and need not
        // fall by 4 from 2000 to 4000); exact once the contacts are joints
        let scale = lr.max(1.0);
        for (i, (what, tol)) in [
            ("N = 2000", 4e-6),
            ("N = 4000", 1e-6),
            ("N = 4000 and the contact angles", 1e-12),
        ]
        .into_iter()
        .enumerate()
        {
            let diff = (d[i] - lr) / scale;
            worst_disc[i] = worst_disc[i].max(diff.abs());
            if diff < -1e-12 || diff > tol {
                failures.push(format!(
                    "{name}: {what} voussoirs give {:.13e}, reference {lr:.13e}",
                    d[i]
                ));
            }
        }
        match crate_lambda(&arch, eta, mu, &load) {
            Ok(c) => {
                compared += 1;
                if !agrees(&reference, c) {
                    failures.push(format!("{name}: crate {c:?}, reference {lr:.15e}"));
                }
            }
            Err(e) => crate_errors.push(format!("{name}: reference {lr:.15e}, crate {e}")),
        }
    }
    println!(
        "  second route: max |difference|/max(1, lambda): N = 2000 {:.2e}, N = 4000 {:.2e}, 4000 + contacts {:.2e} ({t_disc:.1} s); the crate on the 2000 voussoirs: max rel diff {worst_crate_discrete:.1e}",
        worst_disc[0], worst_disc[1], worst_disc[2]
    );
    let semicircle_compared = compared;
    // random continuous arches
    let count = crate::cases_from_env("LOADCONT_CASES", 20);
    let seed: u64 = std::env::var("LOADCONT_SEED")
        .ok()
        .and_then(|v| v.parse().ok())
        .unwrap_or(0x10ad_c047_5eed_0001);
    let mut rng = Rng(seed);
    let (mut skipped, mut t_ref, mut t_crate, mut at_least) = (0, 0.0, 0.0, 0);
    let mut worst_random_disc = 0.0f64;
    let mut worst_random_label = String::new();
    // (vertex optima, optima with fewer than four contacts, their largest gap)
    let mut smooth_optima = (0, 0, 0.0f64);
    t_disc = 0.0;
    let mut max_rel = 0.0f64;
    for case in 0..count {
        let c = match draw(&mut rng, &settings) {
            Ok(c) => c,
            Err(why) => {
                skipped += 1;
                println!("  case {case} skipped: {why}");
                continue;
            }
        };
        let (br, bl) = (c.arch.beta_right(), c.arch.beta_left());
        let loads = [
            LiveLoad::Horizontal {
                towards_right: rng.next() < 0.5,
            },
            LiveLoad::Point {
                beta: br + (bl - br) * (0.15 + 0.7 * rng.next()),
            },
        ];
        for load in loads {
            let label = format!("case {case}: {} {load:?}", c.label);
            let t0 = Instant::now();
            let reference = match LoadedCont::of(&c.arch, c.eta, c.mu, load).lambda_static() {
                Ok(r) => r,
                Err(e) => {
                    failures.push(format!("{label}: reference failed: {e}"));
                    continue;
                }
            };
            t_ref += t0.elapsed().as_secs_f64();
            if reference.value().is_none() {
                at_least += 1;
                println!("  {label}: {}", describe(&reference));
            }
            // the second route on 500 voussoirs plus the reference's contact angles: the
            // same λ_static (or also beyond LBOX)
            let t2 = Instant::now();
            let contacts: Vec<f64> = match &reference {
                RefLambda::Static { touching, .. } => touching.iter().map(|t| t.2).collect(),
                _ => Vec::new(),
            };
            let centroid = c.arch.weight() == WeightModel::Centroid;
            let d = discrete_lambda(br, bl, centroid, c.eta, c.mu, load, 500, &contacts);
            t_disc += t2.elapsed().as_secs_f64();
            // four contacts: a vertex, which the contact rows pin exactly; fewer: the optimum
            // also rests on the curvature of a family, and the voussoirs next to its contact
            // leave an O(h²) gap (from above)
            let vertex = match &reference {
                RefLambda::Static { touching, .. } => touching.len() >= 4,
                _ => false,
            };
            let same = match (reference.value(), d) {
                (Some(r), Some(v)) => {
                    let diff = (v - r) / r.abs().max(1e-300);
                    if vertex {
                        if diff.abs() > worst_random_disc {
                            worst_random_disc = diff.abs();
                            worst_random_label = format!("{label}: {}", describe(&reference));
                        }
                        smooth_optima.0 += 1;
                        diff.abs() <= 1e-11
                    } else {
                        smooth_optima.1 += 1;
                        smooth_optima.2 = smooth_optima.2.max(diff);
                        (-1e-12..=1e-6).contains(&diff)
                    }
                }
                (None, None) => true,
                _ => false,
            };
            if !same {
                failures.push(format!(
                    "{label}: 500 voussoirs and the contact angles give {d:?}, reference {:?} ({})",
                    reference.value(),
                    describe(&reference)
                ));
            }
            let t1 = Instant::now();
            let answer = crate_lambda(&c.arch, c.eta, c.mu, &load);
            t_crate += t1.elapsed().as_secs_f64();
            match answer {
                Ok(cv) => {
                    compared += 1;
                    if let (Some(r), Some(v)) = (reference.value(), cv) {
                        max_rel = max_rel.max(rel(r, v));
                    }
                    if !agrees(&reference, cv) {
                        failures.push(format!(
                            "{label}: crate {cv:?}, reference {:?} ({})",
                            reference.value(),
                            describe(&reference)
                        ));
                    }
                }
                Err(e) => crate_errors.push(format!(
                    "{label}: reference {:?}: crate {e}",
                    reference.value()
                )),
            }
        }
    }
    println!(
        "continuous lambda_static: {count} random arches ({skipped} skipped, {at_least} loads with lambda_static unbounded or beyond {LBOX:e}), {compared} answers of the crate compared (max rel diff {max_rel:.2e}), {} crate errors, {} disagreements; second route (500 voussoirs + contact angles): {} vertex optima to {worst_random_disc:.1e}, {} with fewer than 4 contacts (gap up to {:.1e}); reference {t_ref:.2} s, second route {t_disc:.2} s, crate {t_crate:.2} s, total {:.1} s",
        crate_errors.len(),
        failures.len(),
        smooth_optima.0,
        smooth_optima.1,
        smooth_optima.2,
        started.elapsed().as_secs_f64()
    );
    println!("  largest second-route difference at a vertex: {worst_random_label}");
    // no answer where the reference has one is a disagreement
    failures.extend(crate_errors.iter().map(|e| format!("crate error: {e}")));
    if semicircle_compared != table.len() {
        failures.push(format!(
            "the crate answered {semicircle_compared} of the {} semicircle cases",
            table.len()
        ));
    }
    // two loads per drawn arch, skipped draws included: skipping counts against the run
    let drawn = 2 * count;
    let random_compared = compared - semicircle_compared;
    let needed = ((MIN_COMPARED_FRACTION * drawn as f64).ceil() as usize).max(MIN_RANDOM_COMPARED);
    if random_compared < needed {
        failures.push(format!(
            "only {random_compared} of the {drawn} random loads compared with the crate ({skipped} arches skipped, {} crate errors); at least {needed} needed ({MIN_COMPARED_FRACTION} of them and at least {MIN_RANDOM_COMPARED})",
            crate_errors.len()
        ));
    }
    for f in &failures {
        println!("  FAIL {f}");
    }
    assert!(failures.is_empty(), "{}", failures.join("\n"));
}

/// An exact corner of `load-curve` on a continuous arch, checked with this file's own
/// statics: the semicircle at η = 0.3 under a point load at 60°, between μ = 0.88 and 0.90
/// (purely rotational above, rotation at the shoulders with sliding at the loaded section
/// below). At the corner's (x, λ, μ) every contact of its pattern is active (|φ| ≤ 1e-9 of
/// its scale), and no activation function exceeds that anywhere on a grid of 20 001 sections
/// on both sides of the load; `load` at that μ has the corner's λ.
#[test]
fn continuous_load_curve_corner_is_exact() {
    use arch_enum::load::Side;
    use arch_enum::multiplier::trace;
    let s = Settings::default();
    let arch = Arch::symmetric(0.0, WeightModel::Centreline).unwrap();
    let (eta, bp) = (0.3, PI / 3.0);
    let load = LiveLoad::Point { beta: bp };
    let curve = trace(&arch, eta, &load, &[0.88, 0.90], &s, &|_, _| {}).unwrap();
    let finite: Vec<_> = curve.corners.iter().filter(|c| c.mu < 0.9).collect();
    assert_eq!(finite.len(), 1, "{:?}", curve.corners);
    let c = finite[0];
    assert!(c.exact && c.mu > 0.88 && c.mu < 0.90, "{c:?}");
    let (x, lambda, mu) = (c.x, c.t, c.mu);
    let phi = |k: usize, beta: f64, loaded: bool| {
        let (n, t, m) = model::ntm(0.0, 1.0, x, beta);
        let l = live_ntm(&load, 0.0, eta, 1.0, beta, beta.sin(), beta.cos(), loaded);
        let scale = 1.0 + x.iter().map(|v| v.abs()).sum::<f64>() + lambda;
        combine(
            k,
            eta,
            mu,
            [n + lambda * l[0], t + lambda * l[1], m + lambda * l[2]],
        ) / scale
    };
    let family = |kind: arch_enum::ContactKind| {
        arch_enum::ContactKind::active_at(mu)
            .iter()
            .position(|&k| k == kind)
            .unwrap()
    };
    for (contact, side) in &c.pattern {
        let loaded = if contact.beta == bp {
            *side == Side::After
        } else {
            contact.beta > bp
        };
        let v = phi(family(contact.kind), contact.beta, loaded);
        assert!(v.abs() <= 1e-9, "{contact:?} {side:?}: phi = {v:e}");
    }
    let worst = (0..=20_000)
        .map(|i| PI * i as f64 / 20_000.0)
        .flat_map(|b| [(b, b > bp), (b, b >= bp)])
        .flat_map(|(b, loaded)| (0..4).map(move |k| (b, loaded, k)))
        .map(|(b, loaded, k)| phi(k, b, loaded))
        .fold(f64::NEG_INFINITY, f64::max);
    assert!(worst <= 1e-9, "worst activation {worst:e}");
    let at = arch_enum::multiplier::survey(&arch, eta, mu, &load, &s).unwrap();
    let Ok(arch_enum::multiplier::LoadOutcome::Limits(sv)) = at else {
        panic!("load at the corner: {at:?}");
    };
    let l = sv.lambda().unwrap();
    assert!(
        (l - lambda).abs() <= 1e-12 * lambda,
        "load at the corner: {l} vs {lambda}"
    );
}
