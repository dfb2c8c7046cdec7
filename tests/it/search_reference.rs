//! An INDEPENDENT brute-force reference for the limit states of a small DISCRETE arch at a
//! given friction μ, written from the formulas of shared/spec/formulation.md only (§2
//! geometry, §3 statics, §4 kinematics, §5 limit states, §6 virtual work). Nothing of the
//! crate's solver is used by the reference itself; `arch_enum::solve` appears only in the
//! comparison tests at the end of the file.
//!
//! Method (every step exact up to rounding, the LP only as a cross-check):
//! * contacts are (joint, kind) with kind 0 = E, 1 = I, 2 = S+, 3 = S− (only E, I at μ = ∞);
//!   each activation function is φ = a(η)·x + c(η) with x = (h, v, w);
//! * **static roots**: for every support S of 4 contacts (never S+ and S− at one joint),
//!   φ_S(x, η) = 0 is consistent iff det[A(η) | c(η)] = 0, a polynomial in η (degree ≤ 4
//!   for the centreline weight, ≤ 5 for the true centroid since ρ = 1 + η²/12 is a
//!   polynomial too). Its coefficients come from exact interpolation at 7 Chebyshev nodes
//!   of [0, 2]; its real roots from the monotone pieces between the roots of its
//!   derivatives (double roots: critical values that vanish); each root is polished by
//!   Newton on the square system (x, η), and kept when x is admissible at η;
//! * **kinematic roots**: a mechanism can also live on 3 contacts whose compatibility
//!   columns become dependent at an isolated η (e.g. two hinges and a slide parallel to
//!   the line through them): there det B_S(η) = 0 (degree ≤ 3) and x is fixed by the three
//!   equations φ_S = 0. Such a state has only 3 active contacts and no 4-support root
//!   sees it, so these supports are enumerated too;
//! * **recession roots**: the admissible states may be unbounded; the least η with a
//!   weightless admissible direction d (a_i(η)·d ≤ 0 for all i) is a root of a 3-row
//!   determinant of the a_i(η);
//! * η_s = min(least admissible static root, least recession root), cross-checked against
//!   a bisection on a homogenised margin LP (HiGHS): cone {(y, τ ≥ 0): a_i·y + c_i τ ≤ 0},
//!   slice Σ_j N_j(y, τ) + τ = 1, which stays bounded when the reactions blow up;
//! * supports whose determinant vanishes identically are families over a whole interval
//!   of η: mirror pairs of like contacts on a symmetric arch (e.g. {0E, 1I, 5I, 6E}: the
//!   antisymmetric part of the system is homogeneous), ≥ 3 sliding contacts, sliding joints
//!   π apart. Consistent ones with a unique x(η) are followed along η on a grid, and every
//!   run of admissible states carrying a mechanism on the support is reported by its lower
//!   end with `interval_end` = its upper end; those with x not unique (rank < 3, only at
//!   special μ or geometry) by LP, least η of the interval only;
//! * a candidate state carries a mechanism when its full active set contains an extreme
//!   ray of {λ ≥ 0, Bλ = 0, L_e ≥ 0}: a subset of ≤ 5 contacts on which B (or B with the
//!   L_e row) has a one-dimensional null space spanned by a strictly positive vector. (At
//!   an admissible x, λ on the active set gives L_e = μ Σ N (s⁺ + s⁻) ≥ 0 by §6, so L_e ≥ 0
//!   never binds there and supports of ≤ 4 contacts would do.)
//!
//! For the true centroid, the external power uses the sector centroids ρ·G_m (the centroid
//! of an annular sector is ρ = 1 + η²/12 times that of its centreline arc): with the
//! centreline G_m of §4 the identity of §6 fails for that weight model.

use arch_enum::{solve, Arch, JointLayout, Outcome, Settings, WeightModel};
use good_lp::{highs, variable, Expression, ProblemVariables, Solution, SolverModel};
use itertools::Itertools;
use nalgebra::{DMatrix, Matrix3, Matrix4, SMatrix, Vector4};
use std::f64::consts::PI;

/// One limit state found by the brute force.
#[derive(Debug, Clone)]
pub struct RefLimitState {
    /// Thickness ratio.
    pub eta: f64,
    /// Reactions (h, v, w) at the right springing.
    pub x: [f64; 3],
    /// The full active set at (x, η): (joint index, kind 0 = E, 1 = I, 2 = S+, 3 = S−), sorted.
    pub active: Vec<(usize, u8)>,
    /// One extreme mechanism on the active set, aligned with `active`, Σ = 1.
    pub rates: Vec<f64>,
    /// Whether that mechanism slides somewhere.
    pub slides: bool,
    /// `Some(η_end)` when this state starts a whole interval [η, η_end] of limit states (a
    /// support whose determinant vanishes for every η, followed along η).
    pub interval_end: Option<f64>,
}

/// Everything the brute force found for one arch and one μ.
#[derive(Debug, Clone)]
pub struct RefSearch {
    /// Least η with a statically admissible state (0 when every η admits one, ∞ when none
    /// below 2 does).
    pub eta_s: f64,
    /// Whether η_s is attained by a bounded state (false: the reactions grow without
    /// bound as η ↓ η_s).
    pub attained: bool,
    /// Whether a limit state exists at η_s itself.
    pub mechanism_at_eta_s: bool,
    /// Every limit state, sorted by η.
    pub states: Vec<RefLimitState>,
    /// Supports examined (4-contact static, 3-contact kinematic and recession, 2-contact).
    pub supports_checked: usize,
    /// η_s from the LP bisection alone (cross-check, HiGHS tolerance).
    pub eta_s_lp: f64,
    /// Supports whose determinant vanishes for all η and whose equations are consistent
    /// (families over an interval of η).
    pub interval_supports: usize,
    /// Roots at which the equations of the support had rank < 3 (x not unique there).
    pub degenerate_roots: usize,
    /// Least η with a weightless admissible direction (the admissible states are
    /// unbounded from there on); ∞ if none below 2.
    pub eta_recession: f64,
}

/// Kind names, for messages.
pub const KIND: [&str; 4] = ["E", "I", "S+", "S-"];

const TOL: f64 = 1e-10;
/// Thicknesses searched: [ETA_MIN, ETA_MAX] inside (0, 2).
const ETA_MIN: f64 = 1e-10;
const ETA_MAX: f64 = 2.0 * (1.0 - 1e-9);

pub(crate) struct Ctx {
    br: f64,
    sr: f64,
    cr: f64,
    beta: Vec<f64>,
    sn: Vec<f64>,
    cs: Vec<f64>,
    centroid: bool,
    mu: f64,
    contacts: Vec<(usize, u8)>,
    /// With fill (bridge spec §2): per joint, the coefficients (lowest first) of the cubics
    /// η F_j(η) and η S_j(η) of the fill's resultant and first moment on [β_R, β_j]
    /// (interpolated from Simpson quadratures at four thicknesses: exact for the spec's
    /// pressure, whose η F and η S are polynomials of degree 2 and 3). Every row φ is then
    /// replaced by η φ (a polynomial again, with the sign and zeros of φ for η > 0).
    fill: Option<Vec<([f64; 4], [f64; 4])>>,
}

/// The nodes of the fill's cubics.
const FILL_NODES: [f64; 4] = [0.5, 1.0, 1.5, 2.0];

/// The coefficients (lowest first) of the cubic through (FILL_NODES[i], v[i]).
fn cubic_through(v: [f64; 4]) -> [f64; 4] {
    let m = SMatrix::<f64, 4, 4>::from_fn(|r, c| FILL_NODES[r].powi(c as i32));
    let c = m.try_inverse().expect("Vandermonde") * SMatrix::<f64, 4, 1>::from_column_slice(&v);
    [c[0], c[1], c[2], c[3]]
}

fn dot(a: &[f64; 3], x: &[f64; 3]) -> f64 {
    a[0] * x[0] + a[1] * x[1] + a[2] * x[2]
}
fn norm3(a: &[f64; 3]) -> f64 {
    dot(a, a).sqrt()
}

impl Ctx {
    pub(crate) fn new(beta_r: f64, beta_l: f64, joints: &[f64], centroid: bool, mu: f64) -> Ctx {
        assert!(joints.len() >= 2, "at least the two springings");
        assert!(
            joints[0] == beta_r && *joints.last().unwrap() == beta_l,
            "joints must include both springings"
        );
        assert!(
            joints.windows(2).all(|w| w[1] > w[0]),
            "joints strictly increasing"
        );
        assert!(mu > 0.0, "mu > 0");
        let nk = if mu.is_finite() { 4 } else { 2 };
        let contacts = (0..joints.len())
            .flat_map(|j| (0..nk).map(move |k| (j, k)))
            .collect();
        Ctx {
            br: beta_r,
            sr: beta_r.sin(),
            cr: beta_r.cos(),
            beta: joints.to_vec(),
            sn: joints.iter().map(|b| b.sin()).collect(),
            cs: joints.iter().map(|b| b.cos()).collect(),
            centroid,
            mu,
            contacts,
            fill: None,
        }
    }

    /// The same arch under fill of weight ratio `gf` up to a road `h` above the highest
    /// extrados point (its left springing `beta_l`).
    pub(crate) fn with_fill(mut self, beta_l: f64, (gf, h): (f64, f64)) -> Ctx {
        let springings = (self.br, beta_l);
        let fill = self
            .beta
            .iter()
            .map(|&b| {
                let at = FILL_NODES.map(|eta| {
                    let (f, s) = crate::load_reference::fill_by_simpson(
                        gf,
                        h,
                        eta,
                        springings,
                        (self.br, b),
                    );
                    (eta * f, eta * s)
                });
                (
                    cubic_through(at.map(|v| v.0)),
                    cubic_through(at.map(|v| v.1)),
                )
            })
            .collect();
        self.fill = Some(fill);
        self
    }

    /// The fill's (F, S) on [β_R, β_j] at η (zero without fill).
    fn fill_at(&self, j: usize, eta: f64) -> (f64, f64) {
        match &self.fill {
            Some(f) => (peval(&f[j].0, eta) / eta, peval(&f[j].1, eta) / eta),
            None => (0.0, 0.0),
        }
    }
    fn nj(&self) -> usize {
        self.beta.len()
    }
    fn rho(&self, eta: f64) -> f64 {
        if self.centroid {
            1.0 + eta * eta / 12.0
        } else {
            1.0
        }
    }
    fn drho(&self, eta: f64) -> f64 {
        if self.centroid {
            eta / 6.0
        } else {
            0.0
        }
    }
    /// N, T, M at joint j as (gradient in x, constant): formulation §3.
    fn ntm(&self, j: usize, eta: f64) -> [([f64; 3], f64); 3] {
        let (s, c, d) = (self.sn[j], self.cs[j], self.beta[j] - self.br);
        let (sr, cr) = (self.sr, self.cr);
        let mut out = [
            ([s, c, 0.0], -d * c),
            ([c, -s, 0.0], d * s),
            ([-(s - sr), cr - c, 1.0], d * c - self.rho(eta) * (s - sr)),
        ];
        if self.fill.is_some() {
            // the fill acts as a weight F at horizontal position S/F (bridge spec §2)
            let (f, m) = self.fill_at(j, eta);
            out[0].1 -= f * c;
            out[1].1 += f * s;
            out[2].1 += f * c - m;
        }
        out
    }
    /// φ = a·x + c of contact (j, k) at η (with fill, η φ).
    pub(crate) fn row(&self, j: usize, k: u8, eta: f64) -> ([f64; 3], f64) {
        let (a, c) = self.bare_row(j, k, eta);
        match self.fill {
            Some(_) => (a.map(|v| eta * v), eta * c),
            None => (a, c),
        }
    }
    fn bare_row(&self, j: usize, k: u8, eta: f64) -> ([f64; 3], f64) {
        let [(an, cn), (at, ct), (am, cm)] = self.ntm(j, eta);
        let comb = |p: f64, a1: [f64; 3], c1: f64, q: f64| {
            (
                [
                    p * a1[0] + q * an[0],
                    p * a1[1] + q * an[1],
                    p * a1[2] + q * an[2],
                ],
                p * c1 + q * cn,
            )
        };
        match k {
            0 => comb(1.0, am, cm, -eta / 2.0),
            1 => comb(-1.0, am, cm, -eta / 2.0),
            2 => comb(1.0, at, ct, -self.mu),
            3 => comb(-1.0, at, ct, -self.mu),
            _ => unreachable!(),
        }
    }
    pub(crate) fn phi(&self, j: usize, k: u8, eta: f64, x: &[f64; 3]) -> f64 {
        let (a, c) = self.row(j, k, eta);
        dot(&a, x) + c
    }
    pub(crate) fn normal(&self, j: usize, eta: f64, x: &[f64; 3]) -> f64 {
        let (a, c) = self.ntm(j, eta)[0];
        dot(&a, x) + c
    }
    pub(crate) fn tangential(&self, j: usize, eta: f64, x: &[f64; 3]) -> f64 {
        let (a, c) = self.ntm(j, eta)[1];
        dot(&a, x) + c
    }
    /// ∂φ/∂η at fixed x.
    fn dphi_deta(&self, j: usize, k: u8, eta: f64, x: &[f64; 3]) -> f64 {
        if self.fill.is_some() {
            // of η φ: a central difference (Newton's polish needs no more)
            let d = 1e-6 * eta;
            return (self.phi(j, k, eta + d, x) - self.phi(j, k, eta - d, x)) / (2.0 * d);
        }
        let n = self.normal(j, eta, x);
        let r = self.drho(eta) * (self.sn[j] - self.sr); // ∂M/∂η = −r
        match k {
            0 => -n / 2.0 - r,
            1 => -n / 2.0 + r,
            _ => 0.0,
        }
    }
    /// Tolerance on φ of (j, k) at x: relative to the magnitudes that make it up.
    fn tol(&self, j: usize, k: u8, eta: f64, x: &[f64; 3]) -> f64 {
        let (a, c) = self.row(j, k, eta);
        TOL * (norm3(&a) * (1.0 + norm3(x)) + c.abs())
    }
    pub(crate) fn admissible(&self, eta: f64, x: &[f64; 3]) -> bool {
        self.contacts
            .iter()
            .all(|&(j, k)| self.phi(j, k, eta, x) <= self.tol(j, k, eta, x))
    }
    /// Indices (into `contacts`) of the active contacts.
    fn active(&self, eta: f64, x: &[f64; 3]) -> Vec<usize> {
        (0..self.contacts.len())
            .filter(|&i| {
                let (j, k) = self.contacts[i];
                self.phi(j, k, eta, x).abs() <= self.tol(j, k, eta, x)
            })
            .collect()
    }
    /// Compatibility column of (j, k) at η: formulation §4.
    pub(crate) fn col(&self, j: usize, k: u8, eta: f64) -> [f64; 3] {
        let (s, c) = (self.sn[j], self.cs[j]);
        match k {
            0 => [-(1.0 + eta / 2.0) * s, (1.0 + eta / 2.0) * c, -1.0],
            1 => [(1.0 - eta / 2.0) * s, -(1.0 - eta / 2.0) * c, 1.0],
            2 => [c, s, 0.0],
            3 => [-c, -s, 0.0],
            _ => unreachable!(),
        }
    }
    /// Coefficient of the rate of (j, k) in the external power L_e: the joint moves every
    /// block after it; block m (between joints m and m+1) weighs W_m and its weight acts at
    /// G_m (scaled by ρ for the true centroid: the centroid of an annular sector lies at
    /// ρ times the centroid of its centreline arc).
    pub(crate) fn ell(&self, j: usize, k: u8, eta: f64) -> f64 {
        self.ell_with_size(j, k, eta).0
    }
    /// [`Ctx::ell`] and the size of the terms it sums (Σ_m W_m (|col_y| + |col_ψ G_m,x|)):
    /// the scale of its rounding error. L_e can vanish by cancellation (a rotation about a
    /// point directly below the centre of mass: an arch balanced on one edge of a
    /// springing), and a tolerance relative to the cancelled value itself is then
    /// meaningless.
    pub(crate) fn ell_with_size(&self, j: usize, k: u8, eta: f64) -> (f64, f64) {
        let col = self.col(j, k, eta);
        let g = if self.centroid { self.rho(eta) } else { 1.0 };
        let (mut l, mut size) = (0.0, 0.0);
        for m in j..self.nj() - 1 {
            let w = self.beta[m + 1] - self.beta[m];
            let gx = g * (self.sn[m + 1] - self.sn[m]) / w;
            l -= w * (col[1] + col[2] * gx);
            size += w * (col[1].abs() + (col[2] * gx).abs());
            if self.fill.is_some() {
                // the fill on block m: a weight F_m with first moment S_m about the centre
                let ((f0, s0), (f1, s1)) = (self.fill_at(m, eta), self.fill_at(m + 1, eta));
                let (f, sm) = (f1 - f0, s1 - s0);
                l -= f * col[1] + col[2] * sm;
                size += (f * col[1]).abs() + (col[2] * sm).abs();
            }
        }
        (l, size)
    }
    fn conflict(&self, sub: &[usize]) -> bool {
        sub.iter().tuple_combinations().any(|(&a, &b)| {
            let ((ja, ka), (jb, kb)) = (self.contacts[a], self.contacts[b]);
            ja == jb && ka >= 2 && kb >= 2 && ka != kb
        })
    }
}

// ---------------------------------------------------------------- polynomials

/// Nodes of the determinants' interpolation: degree ≤ 5 without fill, ≤ 6 with (rows of η φ
/// have gradients η × (affine) and constants of degree 3, so det[A|c] = η³ × a polynomial of
/// degree ≤ 6, interpolated divided by η³: the triple root at η = 0 would blur the small
/// roots).
const NODES: usize = 7;

fn cheb_nodes() -> [f64; NODES] {
    let mut t = [0.0; NODES];
    for (k, tk) in t.iter_mut().enumerate() {
        *tk = ((2 * k + 1) as f64 * PI / (2 * NODES) as f64).cos();
    }
    t
}

/// Inverse Vandermonde matrix of the nodes (monomials in t = η − 1 on [−1, 1]).
fn vandermonde_inverse(t: &[f64; NODES]) -> SMatrix<f64, NODES, NODES> {
    let v = SMatrix::<f64, NODES, NODES>::from_fn(|r, c| t[r].powi(c as i32));
    v.try_inverse().expect("Vandermonde")
}

fn peval(c: &[f64], t: f64) -> f64 {
    c.iter().rev().fold(0.0, |acc, &a| acc * t + a)
}

fn pderiv(c: &[f64]) -> Vec<f64> {
    (1..c.len()).map(|i| c[i] * i as f64).collect()
}

/// Real roots of the polynomial c in [lo, hi]: bisection on the monotone pieces between the
/// roots of the derivative; a critical point whose value is within `ztol` of 0 is a
/// (double) root.
fn real_roots(c: &[f64], lo: f64, hi: f64, ztol: f64) -> Vec<f64> {
    let mut d = c.len();
    while d > 0 && c[d - 1] == 0.0 {
        d -= 1;
    }
    let c = &c[..d];
    if d <= 1 {
        return vec![];
    }
    if d == 2 {
        let r = -c[0] / c[1];
        return if (lo..=hi).contains(&r) {
            vec![r]
        } else {
            vec![]
        };
    }
    let crit = real_roots(&pderiv(c), lo, hi, 0.0);
    let mut pts = vec![lo];
    pts.extend(crit.iter().copied().filter(|&x| x > lo && x < hi));
    pts.push(hi);
    let mut roots = Vec::new();
    for w in pts.windows(2) {
        let (mut a, mut b) = (w[0], w[1]);
        let (fa, fb) = (peval(c, a), peval(c, b));
        if fa == 0.0 {
            roots.push(a);
            continue;
        }
        if fb == 0.0 || fa.signum() == fb.signum() {
            continue;
        }
        for _ in 0..200 {
            let m = 0.5 * (a + b);
            if m <= a || m >= b {
                break;
            }
            let fm = peval(c, m);
            if fm == 0.0 {
                a = m;
                b = m;
                break;
            }
            if fm.signum() == fa.signum() {
                a = m;
            } else {
                b = m;
            }
        }
        roots.push(0.5 * (a + b));
    }
    if peval(c, hi) == 0.0 {
        roots.push(hi);
    }
    for &x in &crit {
        if x >= lo && x <= hi && peval(c, x).abs() <= ztol {
            roots.push(x);
        }
    }
    roots.sort_by(|a, b| a.partial_cmp(b).unwrap());
    roots.dedup_by(|a, b| (*a - *b).abs() <= 1e-12);
    roots
}

/// Samples f at the nodes (η = 1 + t), returns (monomial coefficients in t, whether f
/// vanishes identically relative to `scale`).
fn interpolate(
    f: impl Fn(f64) -> (f64, f64),
    t: &[f64; NODES],
    vinv: &SMatrix<f64, NODES, NODES>,
) -> (Vec<f64>, f64, bool) {
    let mut vals = SMatrix::<f64, NODES, 1>::zeros();
    let mut scale: f64 = 0.0;
    for q in 0..NODES {
        let (v, s) = f(1.0 + t[q]);
        vals[q] = v;
        scale = scale.max(s);
    }
    let zero = vals.iter().all(|v| v.abs() <= 1e-12 * scale);
    let c = vinv * vals;
    (c.iter().copied().collect(), scale, zero)
}

// ---------------------------------------------------------------- small linear algebra

/// Least-squares solution of rows·x = rhs (rows: m ≤ 4 rows of 3), with the ratio of the
/// least to the greatest singular value.
fn lstsq(rows: &[[f64; 3]], rhs: &[f64]) -> ([f64; 3], f64) {
    assert!(rows.len() <= 4);
    let m = rows.len();
    let a = SMatrix::<f64, 4, 3>::from_fn(|r, c| if r < m { rows[r][c] } else { 0.0 });
    let b = Vector4::from_fn(|r, _| if r < m { rhs[r] } else { 0.0 });
    let svd = a.svd(true, true);
    let smax = svd.singular_values.max();
    let smin = svd.singular_values.min();
    let x = svd.solve(&b, 1e-13 * smax.max(1e-300)).unwrap();
    (
        [x[0], x[1], x[2]],
        if smax > 0.0 { smin / smax } else { 0.0 },
    )
}

// ---------------------------------------------------------------- LPs (cross-checks, families)

/// Margin of the homogenised static LP at η (> 0: admissible states or weightless
/// admissible directions exist with room to spare; < 0: none).
fn lp_margin(ctx: &Ctx, eta: f64, only_sliding: bool) -> Option<f64> {
    let mut vars = ProblemVariables::new();
    let y: Vec<_> = (0..3).map(|_| vars.add(variable())).collect();
    let tau = vars.add(variable().min(0.0));
    let s = vars.add(variable().max(1.0));
    let mut p = vars
        .maximise(s)
        .using(highs)
        .set_option("output_flag", false);
    for &(j, k) in &ctx.contacts {
        if only_sliding && k < 2 {
            continue;
        }
        let (a, c) = ctx.row(j, k, eta);
        let n = (dot(&a, &a) + c * c).sqrt();
        let mut e = Expression::from(0.0);
        for i in 0..3 {
            e.add_mul(a[i] / n, y[i]);
        }
        e.add_mul(c / n, tau);
        e += s;
        p = p.with(e.leq(0.0));
    }
    let mut e = Expression::from(0.0);
    for j in 0..ctx.nj() {
        let (a, c) = ctx.ntm(j, eta)[0];
        for i in 0..3 {
            e.add_mul(a[i], y[i]);
        }
        e.add_mul(c, tau);
    }
    e += tau;
    p = p.with(e.eq(1.0));
    p.solve().ok().map(|sol| sol.value(s))
}

/// Least η in (0, 2) with a nonzero element of the homogenised cone, by bisection on the
/// sign of the LP margin (0 if every η works, ∞ if none below 2 does). Whether every η
/// works is decided by [`stands_at_vanishing_thickness`], not by the LP at η = ETA_MIN:
/// there the hinge slabs are 1e-10 wide and the margin's sign is HiGHS's rounding (a
/// two-voussoir arch at μ = ∞ whose only state at η = 0 is in tension got "0").
fn lp_least_thickness(ctx: &Ctx, stands: bool) -> f64 {
    let ok = |eta: f64| lp_margin(ctx, eta, false).is_some_and(|m| m >= 0.0);
    let (mut lo, mut hi) = (ETA_MIN, ETA_MAX);
    if !ok(hi) {
        return f64::INFINITY;
    }
    if stands {
        return 0.0;
    }
    while hi - lo > 1e-13 * hi {
        let m = 0.5 * (lo + hi);
        if ok(m) {
            hi = m;
        } else {
            lo = m;
        }
    }
    hi
}

/// Whether a state stands at every η > 0: as η → 0 the hinge conditions |M| ≤ ηN/2 become
/// M = 0 with N ≥ 0 (formulation §3: φ_E + φ_I ≤ 0 gives N ≥ 0 only while η > 0), so the
/// LP has the equalities M_j = 0 at every joint and maximises the margin of N_j ≥ 0 and
/// (finite μ) |T_j| ≤ μ N_j; such a state is admissible at every η > 0 (N ≥ 0 and M = 0
/// meet |M| ≤ ηN/2). The margin is O(1) away from the boundary case N = 0, so its sign is
/// no matter of tolerance.
fn stands_at_vanishing_thickness(ctx: &Ctx) -> bool {
    if ctx.fill.is_some() {
        // the fill's 1/η grows without bound as η → 0 (the arches compared have a least
        // thickness)
        return false;
    }
    let mut vars = ProblemVariables::new();
    let y: Vec<_> = (0..3).map(|_| vars.add(variable())).collect();
    let s = vars.add(variable().max(1.0));
    let mut p = vars
        .maximise(s)
        .using(highs)
        .set_option("output_flag", false);
    let affine = |(a, c): ([f64; 3], f64)| {
        let n = norm3(&a).max(1e-300);
        let mut e = Expression::from(c / n);
        for i in 0..3 {
            e.add_mul(a[i] / n, y[i]);
        }
        e
    };
    for j in 0..ctx.nj() {
        let [(an, cn), (at, ct), (am, cm)] = ctx.ntm(j, 0.0);
        p = p.with(affine((am, cm)).eq(0.0));
        let neg_n = ([-an[0], -an[1], -an[2]], -cn);
        p = p.with((affine(neg_n) + s).leq(0.0));
        if ctx.mu.is_finite() {
            for sign in [1.0, -1.0] {
                let row = (
                    [
                        sign * at[0] - ctx.mu * an[0],
                        sign * at[1] - ctx.mu * an[1],
                        sign * at[2] - ctx.mu * an[2],
                    ],
                    sign * ct - ctx.mu * cn,
                );
                p = p.with((affine(row) + s).leq(0.0));
            }
        }
    }
    p.solve().is_ok_and(|sol| sol.value(s) >= -1e-9)
}

/// The least friction coefficient admitting a nonzero friction-only state (μ_ms, with
/// the same homogenisation): bisection in μ.
pub fn least_friction(beta_r: f64, beta_l: f64, joints: &[f64]) -> f64 {
    let ok = |mu: f64| {
        let ctx = Ctx::new(beta_r, beta_l, joints, false, mu);
        lp_margin(&ctx, 1.0, true).is_some_and(|m| m >= 0.0)
    };
    let (mut lo, mut hi) = (1e-9, 100.0);
    if !ok(hi) {
        return f64::INFINITY;
    }
    while hi - lo > 1e-12 * hi {
        let m = 0.5 * (lo + hi);
        if ok(m) {
            hi = m;
        } else {
            lo = m;
        }
    }
    hi
}

/// An admissible state at η with φ = 0 on `sup` (LP: equalities on `sup`, greatest margin on
/// the others), cleaned by a least-squares projection onto the equalities.
fn lp_state_on(ctx: &Ctx, eta: f64, sup: &[usize]) -> Option<[f64; 3]> {
    let mut vars = ProblemVariables::new();
    let y: Vec<_> = (0..3).map(|_| vars.add(variable())).collect();
    let s = vars.add(variable().max(1.0));
    let mut p = vars
        .maximise(s)
        .using(highs)
        .set_option("output_flag", false);
    for (i, &(j, k)) in ctx.contacts.iter().enumerate() {
        let (a, c) = ctx.row(j, k, eta);
        let n = (dot(&a, &a) + c * c).sqrt();
        let mut e = Expression::from(0.0);
        for q in 0..3 {
            e.add_mul(a[q] / n, y[q]);
        }
        if sup.contains(&i) {
            p = p.with(e.eq(-c / n));
        } else {
            e += s;
            p = p.with(e.leq(-c / n));
        }
    }
    let sol = p.solve().ok()?;
    if sol.value(s) < -1e-9 {
        return None;
    }
    let mut x = [sol.value(y[0]), sol.value(y[1]), sol.value(y[2])];
    let rows: Vec<[f64; 3]> = sup
        .iter()
        .map(|&i| ctx.row(ctx.contacts[i].0, ctx.contacts[i].1, eta).0)
        .collect();
    let res: Vec<f64> = sup
        .iter()
        .map(|&i| -ctx.phi(ctx.contacts[i].0, ctx.contacts[i].1, eta, &x))
        .collect();
    let (dx, _) = lstsq(&rows, &res);
    for q in 0..3 {
        x[q] += dx[q];
    }
    ctx.admissible(eta, &x).then_some(x)
}

// ---------------------------------------------------------------- mechanisms

/// An extreme mechanism on `active` (indices into contacts): a subset of at most 5
/// contacts (no S+ and S− at one joint) on which B, or B with the L_e row, has a
/// one-dimensional null space spanned by a strictly positive vector with L_e ≥ 0.
/// Returns the rates aligned with `active`.
fn find_mechanism(ctx: &Ctx, eta: f64, active: &[usize]) -> Option<Vec<f64>> {
    for size in 1..=active.len().min(5) {
        for sub in (0..active.len()).combinations(size) {
            let ids: Vec<usize> = sub.iter().map(|&q| active[q]).collect();
            if let Some(v) = ray(ctx, eta, &ids) {
                let mut rates = vec![0.0; active.len()];
                for (q, a) in sub.iter().zip(v) {
                    rates[*q] = a;
                }
                return Some(rates);
            }
        }
    }
    None
}

/// The extreme mechanism with support exactly `ids` (Σ = 1), if there is one: no S+ and S−
/// at one joint, and B (or B with the L_e row) restricted to `ids` has a one-dimensional
/// null space spanned by a strictly positive vector with L_e ≥ 0.
fn ray(ctx: &Ctx, eta: f64, ids: &[usize]) -> Option<Vec<f64>> {
    if ctx.conflict(ids) {
        return None;
    }
    let size = ids.len();
    let cols: Vec<[f64; 3]> = ids
        .iter()
        .map(|&i| ctx.col(ctx.contacts[i].0, ctx.contacts[i].1, eta))
        .collect();
    let (ell, ell_size): (Vec<f64>, Vec<f64>) = ids
        .iter()
        .map(|&i| ctx.ell_with_size(ctx.contacts[i].0, ctx.contacts[i].1, eta))
        .unzip();
    for with_ell in [false, true] {
        let rows = if with_ell { 4 } else { 3 };
        let n = rows.max(size);
        let m = DMatrix::from_fn(n, size, |r, c| {
            if r < 3 {
                cols[c][r]
            } else if r == 3 && with_ell {
                ell[c]
            } else {
                0.0
            }
        });
        let svd = m.svd(false, true);
        let sv = &svd.singular_values;
        let smax = sv.max().max(1.0);
        let nulls: Vec<usize> = (0..sv.len()).filter(|&q| sv[q] <= 1e-10 * smax).collect();
        if nulls.len() != 1 {
            continue;
        }
        let vt = svd.v_t.unwrap();
        let mut v: Vec<f64> = (0..size).map(|c| vt[(nulls[0], c)]).collect();
        if v.iter().sum::<f64>() < 0.0 {
            v.iter_mut().for_each(|a| *a = -*a);
        }
        let vmax = v.iter().fold(0.0f64, |a, b| a.max(b.abs()));
        if v.iter().any(|&a| a <= 1e-9 * vmax) {
            continue;
        }
        // L_e ≥ 0 up to its rounding: relative to the size of every term that makes it up
        // (not to Σ|v_i ℓ_i|, which is itself rounding noise when L_e cancels exactly:
        // that rejected arches balanced on one edge of a springing, the other detached)
        let le: f64 = v.iter().zip(&ell).map(|(a, b)| a * b).sum();
        let lscale: f64 = v.iter().zip(&ell_size).map(|(a, b)| a.abs() * b).sum();
        if le < -1e-10 * lscale.max(1e-300) {
            continue;
        }
        let total: f64 = v.iter().sum();
        return Some(v.iter().map(|a| a / total).collect());
    }
    None
}

// ---------------------------------------------------------------- the brute force

struct Candidate {
    eta: f64,
    x: [f64; 3],
    /// End of the interval of limit states this one starts (families only).
    until: Option<f64>,
}

/// Newton on φ_S(x, η) = 0 (4 equations, 4 unknowns) from a polynomial root.
fn polish4(ctx: &Ctx, sup: &[usize], eta0: f64) -> Option<(f64, [f64; 3], bool)> {
    let rows_at = |eta: f64| -> (Vec<[f64; 3]>, Vec<f64>) {
        sup.iter()
            .map(|&i| {
                let (a, c) = ctx.row(ctx.contacts[i].0, ctx.contacts[i].1, eta);
                (a, -c)
            })
            .unzip()
    };
    let (a0, b0) = rows_at(eta0);
    let (x0, ratio) = lstsq(&a0, &b0);
    if ratio < 1e-9 {
        return Some((eta0, x0, true));
    }
    // clearly inadmissible already: polishing moves x by rounding amounts only
    if ctx
        .contacts
        .iter()
        .any(|&(j, k)| ctx.phi(j, k, eta0, &x0) > 1e6 * ctx.tol(j, k, eta0, &x0))
    {
        return None;
    }
    let resid_ok = |eta: f64, x: &[f64; 3]| {
        sup.iter().all(|&i| {
            let (j, k) = ctx.contacts[i];
            ctx.phi(j, k, eta, x).abs() <= ctx.tol(j, k, eta, x)
        })
    };
    let (mut eta, mut x) = (eta0, x0);
    for _ in 0..12 {
        let mut jac = Matrix4::zeros();
        let mut f = Vector4::zeros();
        for (r, &i) in sup.iter().enumerate() {
            let (j, k) = ctx.contacts[i];
            let (a, c) = ctx.row(j, k, eta);
            f[r] = dot(&a, &x) + c;
            for q in 0..3 {
                jac[(r, q)] = a[q];
            }
            jac[(r, 3)] = ctx.dphi_deta(j, k, eta, &x);
        }
        let Some(d) = jac.lu().solve(&(-f)) else {
            break;
        };
        if !d.iter().all(|v| v.is_finite()) {
            break;
        }
        for q in 0..3 {
            x[q] += d[q];
        }
        eta += d[3];
        if d.norm() <= 1e-15 * (1.0 + norm3(&x)) {
            break;
        }
    }
    if eta.is_finite() && (eta - eta0).abs() <= 1e-6 * (1.0 + eta0) && resid_ok(eta, &x) {
        Some((eta, x, false))
    } else if resid_ok(eta0, &x0) {
        Some((eta0, x0, false))
    } else {
        None
    }
}

/// All limit states of the discrete arch with the given joints (both springings
/// included) at friction μ (∞: hinges only); see the module doc for the method.
pub fn brute_force(beta_r: f64, beta_l: f64, joints: &[f64], centroid: bool, mu: f64) -> RefSearch {
    brute_force_of(Ctx::new(beta_r, beta_l, joints, centroid, mu))
}

/// [`brute_force`] of the arch under fill `(g_f, h)` (bridge spec §2).
pub fn brute_force_filled(joints: &[f64], centroid: bool, mu: f64, fill: (f64, f64)) -> RefSearch {
    let (br, bl) = (joints[0], joints[joints.len() - 1]);
    brute_force_of(Ctx::new(br, bl, joints, centroid, mu).with_fill(bl, fill))
}

fn brute_force_of(ctx: Ctx) -> RefSearch {
    let nc = ctx.contacts.len();
    let t = cheb_nodes();
    let vinv = vandermonde_inverse(&t);
    let mut supports_checked = 0;
    let mut degenerate_roots = 0;
    let mut statics: Vec<Candidate> = Vec::new();
    let mut zero4: Vec<Vec<usize>> = Vec::new();

    // static roots of the 4-supports over (0, 2); the rows at the nodes are computed once
    let node_rows: Vec<Vec<([f64; 4], f64)>> = t
        .iter()
        .map(|tq| {
            ctx.contacts
                .iter()
                .map(|&(j, k)| {
                    let (a, c) = ctx.row(j, k, 1.0 + tq);
                    ([a[0], a[1], a[2], c], (dot(&a, &a) + c * c).sqrt())
                })
                .collect()
        })
        .collect();
    for sup in (0..nc).combinations(4) {
        if ctx.conflict(&sup) {
            continue;
        }
        supports_checked += 1;
        let mut vals = SMatrix::<f64, NODES, 1>::zeros();
        let mut scale: f64 = 0.0;
        for q in 0..NODES {
            let rows = &node_rows[q];
            let m = Matrix4::from_fn(|r, c| rows[sup[r]].0[c]);
            let eta3 = if ctx.fill.is_some() {
                (1.0 + t[q]).powi(3)
            } else {
                1.0
            };
            vals[q] = m.determinant() / eta3;
            scale = scale.max(sup.iter().map(|&i| rows[i].1).product::<f64>() / eta3);
        }
        let zero = vals.iter().all(|v| v.abs() <= 1e-12 * scale);
        let coef: Vec<f64> = (vinv * vals).iter().copied().collect();
        if zero {
            zero4.push(sup);
            continue;
        }
        for r in real_roots(&coef, -1.0, 1.0, 1e-11 * scale) {
            let eta0 = 1.0 + r;
            // η = 0 (E and I at one joint: det ∝ η) and η = 2 (every intrados point at the
            // centre) are spurious roots of many supports
            if !(ETA_MIN..=ETA_MAX).contains(&eta0) {
                continue;
            }
            if let Some((eta, x, degenerate)) = polish4(&ctx, &sup, eta0) {
                if degenerate && !(1e-6..=2.0 - 1e-6).contains(&eta) {
                    // the spurious roots at η = 0 and η = 2 (see above), found only to
                    // ~1e-8 because they are multiple roots
                } else if degenerate {
                    degenerate_roots += 1;
                    if let Some(x) = lp_state_on(&ctx, eta, &sup) {
                        statics.push(Candidate {
                            eta,
                            x,
                            until: None,
                        });
                    }
                } else if (ETA_MIN..=ETA_MAX).contains(&eta) && ctx.admissible(eta, &x) {
                    statics.push(Candidate {
                        eta,
                        x,
                        until: None,
                    });
                }
            }
        }
    }

    // recession roots: least η with a weightless admissible direction
    let mut eta_rec = f64::INFINITY;
    for sup in (0..nc).combinations(3) {
        supports_checked += 1;
        let rows = |eta: f64| -> Vec<[f64; 3]> {
            sup.iter()
                .map(|&i| ctx.bare_row(ctx.contacts[i].0, ctx.contacts[i].1, eta).0)
                .collect()
        };
        let det = |eta: f64| {
            let r = rows(eta);
            let m = Matrix3::from_fn(|a, b| r[a][b]);
            (m.determinant(), r.iter().map(norm3).product::<f64>())
        };
        let (coef, scale, zero) = interpolate(det, &t, &vinv);
        if zero {
            continue;
        }
        for r in real_roots(&coef, -1.0, 1.0, 1e-11 * scale) {
            let eta = 1.0 + r;
            if !(ETA_MIN..=ETA_MAX).contains(&eta) || eta >= eta_rec {
                continue;
            }
            let rs = rows(eta);
            let m = Matrix3::from_fn(|a, b| rs[a][b]);
            let svd = m.svd(false, true);
            let sv = svd.singular_values;
            let (q, _) = sv.argmin();
            if sv[q] > 1e-9 * sv.max() {
                continue;
            }
            let vt = svd.v_t.unwrap();
            let d0 = [vt[(q, 0)], vt[(q, 1)], vt[(q, 2)]];
            for sign in [1.0, -1.0] {
                let d = [sign * d0[0], sign * d0[1], sign * d0[2]];
                let ok = ctx.contacts.iter().all(|&(j, k)| {
                    let (a, _) = ctx.row(j, k, eta);
                    dot(&a, &d) <= 1e-10 * norm3(&a)
                });
                if ok {
                    eta_rec = eta_rec.min(eta);
                }
            }
        }
    }

    let eta_b = statics.iter().map(|c| c.eta).fold(f64::INFINITY, f64::min);
    let stands = stands_at_vanishing_thickness(&ctx);
    let eta_s_lp = lp_least_thickness(&ctx, stands);
    let mut eta_s = eta_b.min(eta_rec);
    if !eta_s.is_finite() || stands {
        eta_s = eta_s_lp;
    }
    let attained = eta_b.is_finite() && eta_b <= eta_s * (1.0 + 1e-9);
    let eta_lo = eta_s * (1.0 - 1e-9);

    // kinematic roots of the 3-supports and identically singular 2- and 3-supports
    let mut kin: Vec<Candidate> = Vec::new();
    let mut families: Vec<Vec<usize>> = Vec::new();
    if eta_s.is_finite() {
        for size in [2usize, 3] {
            for sup in (0..nc).combinations(size) {
                if ctx.conflict(&sup) {
                    continue;
                }
                supports_checked += 1;
                let cols = |eta: f64| -> Vec<[f64; 3]> {
                    sup.iter()
                        .map(|&i| ctx.col(ctx.contacts[i].0, ctx.contacts[i].1, eta))
                        .collect()
                };
                if size == 2 {
                    let c = cols(1.0);
                    let cr = [
                        c[0][1] * c[1][2] - c[0][2] * c[1][1],
                        c[0][2] * c[1][0] - c[0][0] * c[1][2],
                        c[0][0] * c[1][1] - c[0][1] * c[1][0],
                    ];
                    if norm3(&cr) <= 1e-12 * norm3(&c[0]) * norm3(&c[1]) {
                        families.push(sup);
                    }
                    continue;
                }
                let det = |eta: f64| {
                    let c = cols(eta);
                    let m = Matrix3::from_fn(|a, b| c[b][a]);
                    (m.determinant(), c.iter().map(norm3).product::<f64>())
                };
                let (coef, scale, zero) = interpolate(det, &t, &vinv);
                if zero {
                    families.push(sup);
                    continue;
                }
                for r in real_roots(&coef, -1.0, 1.0, 1e-11 * scale) {
                    let mut eta = 1.0 + r;
                    // Newton polish on the determinant itself
                    let dc = pderiv(&coef);
                    for _ in 0..3 {
                        let d = peval(&dc, eta - 1.0);
                        if d == 0.0 {
                            break;
                        }
                        let step = det(eta).0 / d;
                        if step.abs() > 1e-8 {
                            break;
                        }
                        eta -= step;
                    }
                    if eta < eta_lo.max(ETA_MIN) || eta > ETA_MAX {
                        continue;
                    }
                    let (a, b): (Vec<[f64; 3]>, Vec<f64>) = sup
                        .iter()
                        .map(|&i| {
                            let (a, c) = ctx.row(ctx.contacts[i].0, ctx.contacts[i].1, eta);
                            (a, -c)
                        })
                        .unzip();
                    let (x, ratio) = lstsq(&a, &b);
                    if ratio < 1e-9 {
                        degenerate_roots += 1;
                        if let Some(x) = lp_state_on(&ctx, eta, &sup) {
                            kin.push(Candidate {
                                eta,
                                x,
                                until: None,
                            });
                        }
                        continue;
                    }
                    if ctx.admissible(eta, &x) {
                        kin.push(Candidate {
                            eta,
                            x,
                            until: None,
                        });
                    }
                }
            }
        }
    }

    // families over an interval of η: supports whose determinant vanishes for every η
    // (mirror pairs of like contacts on a symmetric arch, ≥ 3 sliding contacts, sliding
    // joints π apart). Consistent ones are followed along η: with x(η) unique, on a grid
    // with bisection at the ends of every run of admissible states carrying a mechanism on
    // the support; with x not unique, by LP (the least η of the interval only).
    let mut interval_supports = 0;
    let mut fam: Vec<Candidate> = Vec::new();
    if eta_s.is_finite() && eta_s > 0.0 {
        for sup in families.into_iter().chain(zero4) {
            let sys = |eta: f64| -> (Vec<[f64; 3]>, Vec<f64>) {
                sup.iter()
                    .map(|&i| {
                        let (a, c) = ctx.row(ctx.contacts[i].0, ctx.contacts[i].1, eta);
                        (a, -c)
                    })
                    .unzip()
            };
            let consistent = [0.5 * eta_s + 0.5, 1.0, 1.5].iter().all(|&eta| {
                let (a, b) = sys(eta);
                let (x, _) = lstsq(&a, &b);
                sup.iter().all(|&i| {
                    let (j, k) = ctx.contacts[i];
                    ctx.phi(j, k, eta, &x).abs() <= 1e3 * ctx.tol(j, k, eta, &x)
                })
            });
            if !consistent {
                continue;
            }
            interval_supports += 1;
            let (a1, b1) = sys(1.0);
            if lstsq(&a1, &b1).1 >= 1e-9 {
                let pass = |eta: f64| -> Option<[f64; 3]> {
                    let (a, b) = sys(eta);
                    let (x, r) = lstsq(&a, &b);
                    (r >= 1e-9 && ctx.admissible(eta, &x) && ray(&ctx, eta, &sup).is_some())
                        .then_some(x)
                };
                // the ok-side end of [fail, ok] (either order)
                let refine = |mut fail: f64, mut ok: f64| {
                    for _ in 0..60 {
                        let m = 0.5 * (fail + ok);
                        if pass(m).is_some() {
                            ok = m;
                        } else {
                            fail = m;
                        }
                    }
                    ok
                };
                let n = 200;
                let grid: Vec<f64> = (0..=n)
                    .map(|g| eta_lo + (ETA_MAX - eta_lo) * (g as f64 / n as f64).powi(2))
                    .collect();
                let ok: Vec<bool> = grid.iter().map(|&e| pass(e).is_some()).collect();
                let mut g = 0;
                while g <= n {
                    if !ok[g] {
                        g += 1;
                        continue;
                    }
                    let start = if g == 0 {
                        grid[0]
                    } else {
                        refine(grid[g - 1], grid[g])
                    };
                    let mut h = g;
                    while h < n && ok[h + 1] {
                        h += 1;
                    }
                    let end = if h == n {
                        grid[n]
                    } else {
                        refine(grid[h + 1], grid[h])
                    };
                    if let Some(x) = pass(start) {
                        fam.push(Candidate {
                            eta: start,
                            x,
                            until: Some(end),
                        });
                    }
                    g = h + 1;
                }
            } else {
                let grid: Vec<f64> = (0..=40)
                    .map(|g| eta_s + (ETA_MAX - eta_s) * (g as f64 / 40.0).powi(2))
                    .collect();
                let Some(first) = grid
                    .iter()
                    .position(|&e| lp_state_on(&ctx, e, &sup).is_some())
                else {
                    continue;
                };
                let (mut lo, mut hi) = (
                    if first == 0 { grid[0] } else { grid[first - 1] },
                    grid[first],
                );
                if first > 0 {
                    for _ in 0..40 {
                        let m = 0.5 * (lo + hi);
                        if lp_state_on(&ctx, m, &sup).is_some() {
                            hi = m;
                        } else {
                            lo = m;
                        }
                    }
                }
                if let Some(x) = lp_state_on(&ctx, hi, &sup) {
                    fam.push(Candidate {
                        eta: hi,
                        x,
                        until: None,
                    });
                }
            }
        }
    }

    // limit states: candidates at η ≥ η_s whose full active set carries a mechanism
    let mut states: Vec<RefLimitState> = Vec::new();
    let mut seen: Vec<(f64, Vec<usize>, usize)> = Vec::new();
    for c in fam
        .iter()
        .chain(statics.iter().filter(|c| c.eta >= eta_lo))
        .chain(kin.iter())
    {
        let act = ctx.active(c.eta, &c.x);
        if let Some((_, _, q)) = seen
            .iter()
            .find(|(e, a, _)| (e - c.eta).abs() <= 1e-9 * c.eta.max(1e-300) && *a == act)
        {
            if let (true, Some(until)) = (*q < usize::MAX, c.until) {
                let s = &mut states[*q];
                s.interval_end = Some(s.interval_end.unwrap_or(f64::NEG_INFINITY).max(until));
            }
            continue;
        }
        match find_mechanism(&ctx, c.eta, &act) {
            Some(rates) => {
                seen.push((c.eta, act.clone(), states.len()));
                let active: Vec<(usize, u8)> = act.iter().map(|&i| ctx.contacts[i]).collect();
                let slides = active
                    .iter()
                    .zip(&rates)
                    .any(|(&(_, k), &r)| k >= 2 && r > 1e-12);
                states.push(RefLimitState {
                    eta: c.eta,
                    x: c.x,
                    active,
                    rates,
                    slides,
                    interval_end: c.until,
                });
            }
            None => seen.push((c.eta, act, usize::MAX)),
        }
    }
    states.sort_by(|a, b| a.eta.partial_cmp(&b.eta).unwrap());
    let mechanism_at_eta_s = eta_s.is_finite()
        && states
            .iter()
            .any(|s| (s.eta - eta_s).abs() <= 1e-9 * eta_s.max(1e-300));
    RefSearch {
        eta_s,
        attained,
        mechanism_at_eta_s,
        states,
        supports_checked,
        eta_s_lp,
        interval_supports,
        degenerate_roots,
        eta_recession: eta_rec,
    }
}

// ---------------------------------------------------------------- self-checks

/// Re-checks a returned limit state from scratch: admissibility, active set,
/// complementarity, compatibility, normalisation, no S+ and S− at one joint, L_e ≥ 0 and
/// the virtual-work identity (§6) at x and at a perturbed x. Returns a message on failure.
pub fn check_state(
    beta_r: f64,
    beta_l: f64,
    joints: &[f64],
    centroid: bool,
    mu: f64,
    s: &RefLimitState,
) -> Result<(), String> {
    let ctx = Ctx::new(beta_r, beta_l, joints, centroid, mu);
    let eta = s.eta;
    if !ctx.admissible(eta, &s.x) {
        return Err(format!("not admissible at eta = {eta}"));
    }
    for &(j, k) in &s.active {
        let p = ctx.phi(j, k, eta, &s.x);
        if p.abs() > ctx.tol(j, k, eta, &s.x) {
            return Err(format!(
                "contact ({j}, {}) listed active with phi = {p:e}",
                KIND[k as usize]
            ));
        }
    }
    if s.rates.len() != s.active.len() || s.rates.iter().any(|&r| r < 0.0) {
        return Err("rates must be non-negative and aligned with the active set".into());
    }
    let total: f64 = s.rates.iter().sum();
    if (total - 1.0).abs() > 1e-12 {
        return Err(format!("rates sum to {total}"));
    }
    for (a, b) in s.active.iter().zip(&s.rates).tuple_combinations() {
        if a.0 .0 == b.0 .0 && a.0 .1 >= 2 && b.0 .1 >= 2 && *a.1 > 0.0 && *b.1 > 0.0 {
            return Err(format!("S+ and S- both slide at joint {}", a.0 .0));
        }
    }
    let mut bl = [0.0; 3];
    for (&(j, k), &r) in s.active.iter().zip(&s.rates) {
        let c = ctx.col(j, k, eta);
        for q in 0..3 {
            bl[q] += r * c[q];
        }
    }
    if norm3(&bl) > 1e-11 {
        return Err(format!("B lambda = {bl:?}"));
    }
    let le: f64 = s
        .active
        .iter()
        .zip(&s.rates)
        .map(|(&(j, k), &r)| r * ctx.ell(j, k, eta))
        .sum();
    if le < -1e-11 {
        return Err(format!("L_e = {le:e} < 0"));
    }
    let slides = s
        .active
        .iter()
        .zip(&s.rates)
        .any(|(&(_, k), &r)| k >= 2 && r > 1e-12);
    if slides != s.slides {
        return Err("slides flag".into());
    }
    // virtual work: φᵀλ = L_e − μ Σ N (s+ + s−), for this x and for another x
    for dx in [[0.0, 0.0, 0.0], [0.3, -0.7, 0.45]] {
        let x = [s.x[0] + dx[0], s.x[1] + dx[1], s.x[2] + dx[2]];
        let mut lhs = 0.0;
        let mut fric = 0.0;
        let mut mag = 0.0;
        for (&(j, k), &r) in s.active.iter().zip(&s.rates) {
            let p = ctx.phi(j, k, eta, &x);
            lhs += r * p;
            mag += (r * p).abs() + (r * ctx.ell(j, k, eta)).abs();
            if k >= 2 {
                fric += mu * ctx.normal(j, eta, &x) * r;
                mag += (mu * ctx.normal(j, eta, &x) * r).abs();
            }
        }
        let rhs = le - fric;
        if (lhs - rhs).abs() > 1e-10 * (1.0 + mag) {
            return Err(format!(
                "virtual work: phi.lambda = {lhs}, L_e - mu sum N s = {rhs}"
            ));
        }
    }
    Ok(())
}

// ---------------------------------------------------------------- tests

fn joints_of(arch: &Arch) -> Vec<f64> {
    match arch.layout() {
        JointLayout::Discrete(j) => j.clone(),
        JointLayout::Continuous => panic!("discrete arch expected"),
    }
}

fn rel(a: f64, b: f64) -> f64 {
    (a - b).abs() / a.abs().max(b.abs()).max(1e-300)
}

/// μ_rm of the arch: max |T|/N over the joints at the μ = ∞ limit state (∞ when N
/// vanishes somewhere).
fn mu_rm(br: f64, bl: f64, joints: &[f64], centroid: bool) -> f64 {
    let r = brute_force(br, bl, joints, centroid, f64::INFINITY);
    let s = &r.states[0];
    let ctx = Ctx::new(br, bl, joints, centroid, f64::INFINITY);
    (0..joints.len())
        .map(|j| {
            let n = ctx.normal(j, s.eta, &s.x);
            let t = ctx.tangential(j, s.eta, &s.x);
            if n <= 1e-9 * (1.0 + norm3(&s.x)) {
                f64::INFINITY
            } else {
                t.abs() / n
            }
        })
        .fold(0.0, f64::max)
}

fn describe(r: &RefSearch) -> String {
    let mut out = format!(
        "eta_s = {:.12} (LP {:.12}), attained = {}, mechanism at eta_s = {}, supports = {}, intervals = {}, degenerate = {}\n",
        r.eta_s, r.eta_s_lp, r.attained, r.mechanism_at_eta_s, r.supports_checked, r.interval_supports, r.degenerate_roots
    );
    for s in &r.states {
        let act: Vec<String> = s
            .active
            .iter()
            .zip(&s.rates)
            .map(|(&(j, k), &l)| {
                format!("{j}{}{}", KIND[k as usize], if l > 0.0 { "*" } else { "" })
            })
            .collect();
        out += &format!(
            "   eta = {:.12}  x = [{:.9}, {:.9}, {:.9}]  active [{}]{}",
            s.eta,
            s.x[0],
            s.x[1],
            s.x[2],
            act.join(" "),
            if s.slides { "  slides" } else { "" }
        );
        out += &s
            .interval_end
            .map(|e| format!("  (a whole interval of limit states, up to eta = {e:.12})"))
            .unwrap_or_default();
        out += "\n";
    }
    out
}

/// Symmetric discrete arches (α ∈ {−0.5, 0, 0.5, 1}, 6 and 8 voussoirs, μ ∈ {∞, 10, halfway
/// between μ_ms and μ_rm}): η_s equals the solver's `eta_static` and the least limit state its
/// `eta` (1e-9 relative); the set of limit states is mirror-invariant; the limit state is
/// unique except on the mixed branch of the horseshoe α = 1, where a mirror pair of
/// unsymmetric sliding limit states lies above η_s.
#[test]
fn symmetric_discrete_arches_match_solver() {
    let mut failures = Vec::new();
    let mut checked = 0;
    for alpha in [-0.5, 0.0, 0.5, 1.0] {
        for n in [6usize, 8] {
            let arch = Arch::symmetric(alpha, WeightModel::Centreline)
                .unwrap()
                .with_blocks(n)
                .unwrap();
            let joints = joints_of(&arch);
            let (br, bl) = (arch.beta_right(), arch.beta_left());
            let m_rm = mu_rm(br, bl, &joints, false);
            let m_ms = least_friction(br, bl, &joints);
            assert!(
                m_ms < m_rm,
                "alpha {alpha}, blocks {n}: mu_ms = {m_ms}, mu_rm = {m_rm}"
            );
            // on the mixed branch: halfway between mu_ms and mu_rm
            let mixed = if m_rm.is_finite() {
                0.5 * (m_ms + m_rm)
            } else {
                1.5 * m_ms
            };
            let eta_inf = brute_force(br, bl, &joints, false, f64::INFINITY).eta_s;
            for mu in [f64::INFINITY, 10.0, mixed] {
                let r = brute_force(br, bl, &joints, false, mu);
                for s in &r.states {
                    if let Err(e) = check_state(br, bl, &joints, false, mu, s) {
                        failures.push(format!("alpha {alpha} n {n} mu {mu}: {e}"));
                    }
                }
                // the limit states of a symmetric arch are mirror-invariant as a set
                let last = joints.len() - 1;
                for s in &r.states {
                    let mut m: Vec<(usize, u8)> = s
                        .active
                        .iter()
                        .map(|&(j, k)| (last - j, [0u8, 1, 3, 2][k as usize]))
                        .collect();
                    m.sort();
                    if !r
                        .states
                        .iter()
                        .any(|t| rel(t.eta, s.eta) <= 1e-9 && t.active == m)
                    {
                        failures.push(format!(
                            "alpha {alpha} n {n} mu {mu}: no mirror image of {:?}\n{}",
                            s.active,
                            describe(&r)
                        ));
                    }
                }
                let sol = solve(&arch, mu, &Settings::default()).unwrap();
                checked += 1;
                println!(
                    "alpha = {alpha:4}, blocks = {n}, mu = {mu:.6}: eta_s = {:.12}, states: {}",
                    r.eta_s,
                    r.states
                        .iter()
                        .map(|s| format!(
                            "{:.12} [{}]",
                            s.eta,
                            s.active
                                .iter()
                                .map(|&(j, k)| format!("{j}{}", KIND[k as usize]))
                                .join(" ")
                        ))
                        .join("; ")
                );
                let tag = format!("alpha = {alpha}, blocks = {n}, mu = {mu}");
                if mu == mixed && (r.eta_s.is_nan() || r.eta_s <= eta_inf * (1.0 + 1e-6)) {
                    failures.push(format!(
                        "{tag}: not on the mixed branch (eta_s = {}, at mu = inf {eta_inf})",
                        r.eta_s
                    ));
                }
                match sol.outcome {
                    Outcome::Limit(ls) => {
                        if rel(ls.eta_static, r.eta_s) > 1e-9 {
                            failures.push(format!(
                                "{tag}: solver eta_static = {:.15}, reference eta_s = {:.15}\n{}",
                                ls.eta_static,
                                r.eta_s,
                                describe(&r)
                            ));
                        }
                        let first = &r.states[0];
                        if rel(first.eta, r.eta_s) > 1e-9 {
                            failures.push(format!(
                                "{tag}: the least limit state is not at eta_s\n{}",
                                describe(&r)
                            ));
                        } else if rel(ls.eta, first.eta) > 1e-9 {
                            failures.push(format!(
                                "{tag}: solver eta = {:.15}, reference {:.15}",
                                ls.eta, first.eta
                            ));
                        }
                        // uniqueness holds for alpha <= 0.5 at every mu, and for the rotational
                        // branch; on the mixed branch of the horseshoe alpha = 1 a mirror pair
                        // of sliding limit states lies above eta_s (non-associative friction)
                        let above: Vec<&RefLimitState> = r
                            .states
                            .iter()
                            .filter(|s| {
                                s.eta.max(s.interval_end.unwrap_or(0.0)) > r.eta_s * (1.0 + 1e-9)
                            })
                            .collect();
                        let at = r.states.len() - above.len();
                        let expect_above = alpha == 1.0 && mu == mixed;
                        if at != 1 || above.is_empty() == expect_above {
                            failures.push(format!(
                                "{tag}: expected one limit state at eta_s and {} above it\n{}",
                                if expect_above {
                                    "a mirror pair"
                                } else {
                                    "none"
                                },
                                describe(&r)
                            ));
                        }
                        if expect_above
                            && !above.iter().all(|s| s.slides && s.interval_end.is_none())
                        {
                            failures.push(format!("{tag}: the states above eta_s should be isolated sliding states\n{}", describe(&r)));
                        }
                    }
                    Outcome::NoEquilibrium { .. } => {
                        if r.eta_s.is_finite() {
                            failures.push(format!(
                                "{tag}: solver says no equilibrium\n{}",
                                describe(&r)
                            ));
                        }
                    }
                    other => failures.push(format!(
                        "{tag}: solver returned {other:?}\n{}",
                        describe(&r)
                    )),
                }
                if r.eta_s.is_finite() && r.eta_s > 0.0 && rel(r.eta_s, r.eta_s_lp) > 1e-7 {
                    failures.push(format!("{tag}: roots and LP disagree\n{}", describe(&r)));
                }
            }
        }
    }
    assert_eq!(checked, 24);
    assert!(failures.is_empty(), "{}", failures.join("\n"));
}

/// The identity of §6 for arbitrary compatible λ (any sign) and arbitrary x, on every
/// kind of contact: a direct test of the kinematic columns and of L_e.
#[test]
fn virtual_work_identity_for_any_compatible_rates() {
    let mut rng = Rng(0x5eed_1234_abcd_0001);
    for case in 0..200 {
        let n = 2 + (rng.next() * 7.0) as usize;
        let br = -0.8 + 1.6 * rng.next();
        let bl = PI + (-0.8 + 1.6 * rng.next());
        let joints = random_joints(&mut rng, br, bl, n);
        let centroid = case % 2 == 1;
        let mu = 0.2 + 2.0 * rng.next();
        let eta = 0.01 + 1.9 * rng.next();
        let ctx = Ctx::new(br, bl, &joints, centroid, mu);
        let nc = ctx.contacts.len();
        let b = DMatrix::from_fn(3, nc, |r, c| {
            ctx.col(ctx.contacts[c].0, ctx.contacts[c].1, eta)[r]
        });
        // a random element of the null space of B
        let svd = b.clone().svd(false, true);
        let vt = svd.v_t.unwrap(); // 3 × nc: the row space; project a random vector off it
        let mut lam = DMatrix::from_fn(nc, 1, |_, _| rng.next() - 0.5);
        for r in 0..3 {
            let row = vt.row(r).transpose();
            let p = row.dot(&lam);
            lam -= row * p;
        }
        assert!((&b * &lam).norm() < 1e-12);
        let x = [
            3.0 * (rng.next() - 0.5),
            3.0 * (rng.next() - 0.5),
            rng.next() - 0.5,
        ];
        let mut lhs = 0.0;
        let mut le = 0.0;
        let mut fric = 0.0;
        for (c, &(j, k)) in ctx.contacts.iter().enumerate() {
            lhs += lam[c] * ctx.phi(j, k, eta, &x);
            le += lam[c] * ctx.ell(j, k, eta);
            if k >= 2 {
                fric += mu * ctx.normal(j, eta, &x) * lam[c];
            }
        }
        assert!(
            (lhs - (le - fric)).abs() < 1e-11 * (1.0 + lhs.abs()),
            "case {case}: phi.lambda = {lhs}, L_e - mu sum N s = {}",
            le - fric
        );
    }
}

/// Every limit state returned, on symmetric and unsymmetric arches, both weight
/// models, satisfies the identity of §6 (and the other checks of `check_state`).
#[test]
fn virtual_work_identity_at_every_limit_state() {
    let mut rng = Rng(0x0bad_cafe_0000_0042);
    let mut count = 0;
    let mut sliding = 0;
    for case in 0..10 {
        let n = 3 + case % 5;
        let (br, bl) = if case < 4 {
            (-0.3 * case as f64, PI + 0.3 * case as f64)
        } else {
            (-0.6 + 1.2 * rng.next(), PI - 0.6 + 1.2 * rng.next())
        };
        let joints = if case < 4 {
            equal_joints(br, bl, n)
        } else {
            random_joints(&mut rng, br, bl, n)
        };
        let centroid = case % 2 == 0;
        let ms = least_friction(br, bl, &joints);
        for mu in [f64::INFINITY, ms * 1.05, ms * 1.3, 2.0] {
            if mu.is_nan() || mu <= ms {
                continue;
            }
            let r = brute_force(br, bl, &joints, centroid, mu);
            for s in &r.states {
                count += 1;
                sliding += s.slides as usize;
                if let Err(e) = check_state(br, bl, &joints, centroid, mu, s) {
                    panic!("case {case}, mu {mu}: {e}\n{}", describe(&r));
                }
                // L_e equals the frictional dissipation (§6, φᵀλ = 0)
                let ctx = Ctx::new(br, bl, &joints, centroid, mu);
                let le: f64 = s
                    .active
                    .iter()
                    .zip(&s.rates)
                    .map(|(&(j, k), &l)| l * ctx.ell(j, k, s.eta))
                    .sum();
                let diss: f64 = s
                    .active
                    .iter()
                    .zip(&s.rates)
                    .filter(|((_, k), _)| *k >= 2)
                    .map(|(&(j, _), &l)| mu * ctx.normal(j, s.eta, &s.x) * l)
                    .sum();
                assert!(
                    (le - diss).abs() < 1e-9 * (1.0 + le.abs()),
                    "L_e = {le}, dissipation = {diss}"
                );
                if !s.slides {
                    assert!(le.abs() < 1e-10, "rotational mechanism with L_e = {le}");
                }
            }
        }
    }
    assert!(count >= 20, "only {count} limit states");
    assert!(sliding >= 1, "no sliding limit state exercised");
}

pub struct Rng(pub u64);
impl Rng {
    pub fn next(&mut self) -> f64 {
        // xorshift64*
        self.0 ^= self.0 >> 12;
        self.0 ^= self.0 << 25;
        self.0 ^= self.0 >> 27;
        let v = self.0.wrapping_mul(0x2545_f491_4f6c_dd1d);
        (v >> 11) as f64 / (1u64 << 53) as f64
    }
}

/// The joints of `n` equal voussoirs, the last exactly the left springing.
pub fn equal_joints(br: f64, bl: f64, n: usize) -> Vec<f64> {
    (0..=n)
        .map(|i| {
            if i == n {
                bl
            } else {
                br + (bl - br) * i as f64 / n as f64
            }
        })
        .collect()
}

pub fn random_joints(rng: &mut Rng, br: f64, bl: f64, blocks: usize) -> Vec<f64> {
    let w: Vec<f64> = (0..blocks).map(|_| 0.4 + rng.next()).collect();
    let tot: f64 = w.iter().sum();
    let mut j = vec![br];
    let mut acc = 0.0;
    for wi in &w[..blocks - 1] {
        acc += wi;
        j.push(br + (bl - br) * acc / tot);
    }
    j.push(bl);
    j
}

/// Random unsymmetric discrete arches: internal consistency only (every state re-checked,
/// roots and LP agree on η_s); prints how often a limit state lies above η_s, η_s carries
/// no mechanism, or η_s is not attained, with one example each, and the crate's answer.
/// Part A: arch-like springings (β_R, π − β_L in [−0.6, 0.6]), 3–8 voussoirs, μ in
/// (μ_ms, 3]. Part B: arbitrary springings (spans 0.3–3.8 rad anywhere on the circle),
/// 3–4 voussoirs, μ random or ∞ — where unbounded (not attained) η_s shows up.
#[test]
fn unsymmetric_sweep() {
    let started = std::time::Instant::now();
    let (mut counts, mut noeq, mut total) = ([0usize; 3], 0, 0);
    let mut examples: [Vec<String>; 3] = Default::default();
    let (mut solver_agree, mut solver_differ) = (0, Vec::new());
    let mut rng = Rng(0x1234_5678_9abc_def1);
    let mut rng_b = Rng(7);
    for case in 0..40 {
        let wild = case >= 24;
        let (n, br, bl, joints, centroid, mu, ms);
        if !wild {
            n = 3 + (rng.next() * 6.0) as usize; // 3..=8 voussoirs
            br = -0.6 + 1.2 * rng.next();
            bl = PI - 0.6 + 1.2 * rng.next();
            joints = random_joints(&mut rng, br, bl, n);
            centroid = rng.next() < 0.5;
            ms = least_friction(br, bl, &joints);
            let u = rng.next();
            mu = if ms < 3.0 {
                ms + (3.0 - ms) * u * u + 1e-3 * ms
            } else {
                ms * (1.0 + u)
            };
        } else {
            n = 3 + (rng_b.next() * 2.0) as usize;
            br = -1.2 + 2.6 * rng_b.next();
            bl = br + 0.3 + 3.5 * rng_b.next();
            joints = random_joints(&mut rng_b, br, bl, n);
            centroid = rng_b.next() < 0.3;
            ms = least_friction(br, bl, &joints);
            mu = if rng_b.next() < 0.5 {
                f64::INFINITY
            } else {
                ms * (1.0 + 2.0 * rng_b.next())
            };
        }
        let _ = n;
        let r = brute_force(br, bl, &joints, centroid, mu);
        total += 1;
        for s in &r.states {
            if let Err(e) = check_state(br, bl, &joints, centroid, mu, s) {
                panic!("case {case}: {e}\n{}", describe(&r));
            }
            assert!(s.eta >= r.eta_s * (1.0 - 1e-9), "state below eta_s");
        }
        if r.eta_s.is_finite() && r.eta_s > 0.0 {
            assert!(
                rel(r.eta_s, r.eta_s_lp) < 1e-8,
                "case {case}: roots and LP disagree\n{}",
                describe(&r)
            );
        }
        if r.eta_s.is_finite() && r.eta_s > 0.0 && !r.attained {
            assert!(
                r.eta_recession <= r.eta_s * (1.0 + 1e-9),
                "case {case}: not attained without recession"
            );
        }
        let text = format!(
            "case {case}: beta_r = {br:?}, beta_l = {bl:?}, joints = {joints:?}, weight = {}, mu = {mu:?} (mu_ms = {ms:.9})\n  {}",
            if centroid { "centroid" } else { "centreline" },
            describe(&r)
        );
        if !r.eta_s.is_finite() {
            noeq += 1;
            continue;
        }
        for (q, hit) in [
            r.states
                .iter()
                .any(|s| s.eta.max(s.interval_end.unwrap_or(0.0)) > r.eta_s * (1.0 + 1e-9)),
            !r.mechanism_at_eta_s,
            !r.attained,
        ]
        .into_iter()
        .enumerate()
        {
            if hit {
                counts[q] += 1;
                if examples[q].len() < 2 {
                    examples[q].push(text.clone());
                }
            }
        }
        // the crate's answer, for information only
        let w = if centroid {
            WeightModel::Centroid
        } else {
            WeightModel::Centreline
        };
        let arch = Arch::new(br, bl, w).unwrap().with_joints(&joints).unwrap();
        let least = r.states.first().map(|s| s.eta).unwrap_or(f64::NAN);
        match solve(&arch, mu, &Settings::default()).map(|s| s.outcome) {
            Ok(Outcome::Limit(ls))
                if rel(ls.eta_static, r.eta_s) <= 1e-9 && rel(ls.eta, least) <= 1e-9 =>
            {
                solver_agree += 1
            }
            Ok(Outcome::Limit(ls)) => solver_differ.push(format!(
                "solver eta_static = {:.15}, eta = {:.15}, x = {:?}, pattern {:?}\n  {text}",
                ls.eta_static,
                ls.eta,
                ls.x,
                ls.pattern
                    .iter()
                    .map(|c| (c.beta, c.kind))
                    .collect::<Vec<_>>()
            )),
            other => solver_differ.push(format!("solver {other:?}\n  {text}")),
        }
    }
    println!("=== search_reference sweep: {total} random unsymmetric discrete arches (24 arch-like, 16 arbitrary) ===");
    println!("no equilibrium below eta = 2: {noeq}");
    println!("limit state above eta_s (non-uniqueness): {}", counts[0]);
    println!("no mechanism at eta_s: {}", counts[1]);
    println!("eta_s not attained (unbounded): {}", counts[2]);
    for (what, ex) in ["above eta_s", "no mechanism at eta_s", "unbounded"]
        .iter()
        .zip(&examples)
    {
        for t in ex {
            println!("--- example, {what}:\n{t}");
        }
    }
    println!("solver agrees (eta_static and least limit state to 1e-9): {solver_agree}");
    for d in &solver_differ {
        println!("  {d}");
    }
    println!("sweep time: {:.2} s", started.elapsed().as_secs_f64());
}
