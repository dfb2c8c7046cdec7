//! The statics of a certificate's arch in interval arithmetic, for the verifier
//! (formulation §3, written out again from the formulas, not the solver's
//! [`crate::statics`]): N, T, M and their β-derivatives, the activation functions and their
//! affine form in x.

use super::report::{reject, Rejection};
use super::vertical::{actions, fill_jets, fill_jets_times_eta, FillModel};
use crate::certificate::format::ContactKind;
use crate::certificate::interval::Interval as I;

/// Tolerances of the floating-point consistency checks of the limit state.
pub const LIMIT_STATE_TOL: f64 = 1e-9;

/// The geometry and weight of the certificate's arch, for interval evaluation.
pub(super) struct Model {
    pub(super) beta_r: f64,
    /// sin β_R and cos β_R in intervals ([`springing_trig`]: every N, T, M takes them).
    pub(super) springing: (I, I),
    /// sin β and cos β in intervals at each of `joints` (empty without joints): the
    /// checks of a state visit every joint, and each of many states ([`joint_trig`]).
    pub(super) joint_trig: Vec<(I, I)>,
    pub(super) beta_l: f64,
    pub(super) centroid: bool,
    pub(super) joints: Option<Vec<f64>>,
    /// The fill above the extrados, a dead load beside the weight.
    pub(super) fill: Option<FillModel>,
}

/// sin β_R and cos β_R in intervals, for [`Model::springing`].
pub(super) fn springing_trig(beta_r: f64) -> (I, I) {
    let br = I::point(beta_r);
    (br.sin(), br.cos())
}

/// sin β and cos β in intervals at each joint angle, for [`Model::joint_trig`].
pub(super) fn joint_trig(joints: Option<&[f64]>) -> Vec<(I, I)> {
    joints.map_or_else(Vec::new, |j| {
        j.iter()
            .map(|&b| (I::point(b).sin(), I::point(b).cos()))
            .collect()
    })
}

/// Interval values of N, T, M and their first two β-derivatives at β ∈ `b`.
#[derive(Clone, Copy)]
pub(super) struct Ntm {
    pub(super) n: [I; 3],
    pub(super) t: [I; 3],
    pub(super) m: [I; 3],
}

impl Default for Ntm {
    /// All zero.
    fn default() -> Ntm {
        let z = I::point(0.0);
        Ntm {
            n: [z; 3],
            t: [z; 3],
            m: [z; 3],
        }
    }
}

impl Ntm {
    /// `self + k·o`, term by term (the dead actions plus λ times the live ones).
    pub(super) fn plus(&self, k: f64, o: &Ntm) -> Ntm {
        let k = I::point(k);
        let add = |a: [I; 3], b: [I; 3]| [0, 1, 2].map(|i| a[i] + k * b[i]);
        Ntm {
            n: add(self.n, o.n),
            t: add(self.t, o.t),
            m: add(self.m, o.m),
        }
    }
}

impl Model {
    /// A joint angle must be finite, inside [β_R, β_L], and for a discrete arch one of
    /// its listed joints.
    pub(super) fn check_joint(&self, beta: f64, what: &str) -> Result<(), Rejection> {
        if !(beta.is_finite() && beta >= self.beta_r && beta <= self.beta_l) {
            return reject(format!(
                "{what}: beta = {beta} lies outside the arch [beta_right, beta_left] = [{}, {}]",
                self.beta_r, self.beta_l
            ));
        }
        if let Some(js) = &self.joints {
            if !js.contains(&beta) {
                return reject(format!(
                    "{what}: beta = {beta} is not one of the joint_angles of this discrete arch"
                ));
            }
        }
        Ok(())
    }

    pub(super) fn rho(&self, eta: f64) -> I {
        self.rho_over(I::point(eta))
    }

    /// ρ over an interval of η (1, or 1 + η²/12 for the true centroid; η ≥ 0).
    pub(super) fn rho_over(&self, e: I) -> I {
        if self.centroid {
            I::point(1.0) + e * e * I::new((1.0f64 / 12.0).next_down(), (1.0f64 / 12.0).next_up())
        } else {
            I::point(1.0)
        }
    }

    /// sin b and cos b in intervals: from [`Model::joint_trig`] where b is a joint angle
    /// (a point), else evaluated (the same values either way).
    pub(super) fn trig(&self, b: I) -> (I, I) {
        let cached = (b.lo == b.hi)
            .then_some(self.joints.as_deref())
            .flatten()
            .and_then(|j| j.binary_search_by(|v| v.total_cmp(&b.lo)).ok())
            .and_then(|k| self.joint_trig.get(k));
        match cached {
            Some(&t) => t,
            None => (b.sin(), b.cos()),
        }
    }

    /// N, T, M of the reactions x alone (no weight): the linear part of the statics,
    /// N = h sin β + v cos β, T = h cos β − v sin β, M = −h (sin β − sin β_R) +
    /// v (cos β_R − cos β) + w, with dN = T, dT = −N, dM = −T.
    pub(super) fn ntm_weightless(&self, b: I, x: [f64; 3]) -> Ntm {
        let (h, v, w) = (I::point(x[0]), I::point(x[1]), I::point(x[2]));
        let (s, c) = self.trig(b);
        let (sr, cr) = self.springing;
        let n0 = h * s + v * c;
        let t0 = h * c - v * s;
        let m0 = -(h * (s - sr)) + v * (cr - c) + w;
        Ntm {
            n: [n0, t0, -n0],
            t: [t0, -n0, -t0],
            m: [m0, -t0, n0],
        }
    }

    pub(super) fn ntm(&self, b: I, x: [f64; 3], eta: f64) -> Ntm {
        let (h, v, w) = (I::point(x[0]), I::point(x[1]), I::point(x[2]));
        let (s, c) = self.trig(b);
        let br = I::point(self.beta_r);
        let (sr, cr) = self.springing;
        let d = b - br;
        let rho = self.rho(eta);
        let one = I::point(1.0);
        let two = I::point(2.0);
        let n0 = h * s + v * c - d * c;
        let t0 = h * c - v * s + d * s;
        let m0 = -(h * (s - sr)) + v * (cr - c) + w + d * c - rho * (s - sr);
        let n1 = t0 - c;
        let t1 = -n0 + s;
        let m1 = -t0 + (one - rho) * c;
        let n2 = two * s - n0;
        let t2 = two * c - t0;
        let m2 = n0 - (two - rho) * s;
        let ring = Ntm {
            n: [n0, n1, n2],
            t: [t0, t1, t2],
            m: [m0, m1, m2],
        };
        match self.fill_actions(b, I::point(eta)) {
            Some(fill) => ring.plus(1.0, &fill),
            None => ring,
        }
    }

    /// The fill's N, T, M (with β-derivatives) over the angles `b` and thicknesses `eta`.
    pub(super) fn fill_actions(&self, b: I, eta: I) -> Option<Ntm> {
        let fill = self.fill.as_ref()?;
        let (f, s) = fill_jets(fill, (self.beta_r, self.beta_l), b, eta);
        let [n, t, m] = actions(f, s, b);
        Some(Ntm { n, t, m })
    }

    /// η times the fill's N, T, M (bounded as η → 0; see [`ntm_rows_times_eta`]).
    fn fill_actions_times_eta(&self, b: I, eta: I) -> Option<Ntm> {
        let fill = self.fill.as_ref()?;
        let (f, s) = fill_jets_times_eta(fill, (self.beta_r, self.beta_l), b, eta);
        let [n, t, m] = actions(f, s, b);
        Some(Ntm { n, t, m })
    }
}

/// Whether the activation function `kind` exists at friction `mu` (`None` = ∞: hinges only).
pub(super) fn exists(kind: ContactKind, mu: Option<f64>) -> bool {
    kind.is_hinge() || mu.is_some()
}

/// φ of `kind` (β-derivative `k`). Sliding rows need a finite μ: callers check
/// [`exists`] first, and a sliding row at μ = ∞ evaluates to an unbounded interval.
pub(super) fn phi(kind: ContactKind, k: usize, a: &Ntm, eta: f64, mu: Option<f64>) -> I {
    let he = I::point(eta) * I::point(0.5);
    let slide = |sign: f64| match mu {
        Some(mu) => a.t[k].scale(sign) - I::point(mu) * a.n[k],
        None => I::new(f64::NEG_INFINITY, f64::INFINITY),
    };
    match kind {
        ContactKind::HingeExtrados => a.m[k] - he * a.n[k],
        ContactKind::HingeIntrados => -a.m[k] - he * a.n[k],
        ContactKind::SlidePlus => slide(1.0),
        ContactKind::SlideMinus => slide(-1.0),
    }
}

/// The activation functions that exist at friction `mu` (`None` = ∞).
pub(super) fn kinds(mu: Option<f64>) -> &'static [ContactKind] {
    match mu {
        Some(_) => &ContactKind::ALL,
        None => &ContactKind::HINGES,
    }
}

/// The thickness limit t = 2r: every arch has η < 2, and proofs over η cover [0, 2].
pub(super) const ETA_LIMIT: f64 = 2.0;

/// N, T and M at β as affine functions of x over the thicknesses `eta`: each (gradient,
/// constant), in interval arithmetic.
pub(super) fn ntm_rows(model: &Model, beta: f64, eta: I) -> [([I; 3], I); 3] {
    let ring = ring_rows(model, beta, eta);
    // the fill adds to the constant terms (without fill nothing is added: the same bounds)
    match model.fill_actions(I::point(beta), eta) {
        Some(f) => add_constants(ring, &f),
        None => ring,
    }
}

/// [`ntm_rows`] times η, in the reactions x̃ = η x (units of γ r² d): the gradients are the
/// same, the constants η times the ring's plus η times the fill's. Every row is multiplied
/// by the same η > 0, so a state admissible at η is one here and a Farkas proof over a cell
/// of these rows holds for the rows themselves; the fill's load, 1/η times the ring's weight,
/// stays bounded, so a cell may reach down to η = 0.
pub(super) fn ntm_rows_times_eta(model: &Model, beta: f64, eta: I) -> [([I; 3], I); 3] {
    let ring = ring_rows(model, beta, eta).map(|(g, c)| (g, c * eta));
    match model.fill_actions_times_eta(I::point(beta), eta) {
        Some(f) => add_constants(ring, &f),
        None => ring,
    }
}

/// The rows with N, T and M of `f` added to their constants.
fn add_constants(rows: [([I; 3], I); 3], f: &Ntm) -> [([I; 3], I); 3] {
    let [(gn, n), (gt, t), (gm, m)] = rows;
    [(gn, n + f.n[0]), (gt, t + f.t[0]), (gm, m + f.m[0])]
}

/// N, T and M at β of the ring's weight and the reactions alone.
fn ring_rows(model: &Model, beta: f64, eta: I) -> [([I; 3], I); 3] {
    let b = I::point(beta);
    let (s, c) = model.trig(b);
    let br = I::point(model.beta_r);
    let (sr, cr) = model.springing;
    let d = b - br;
    let rho = model.rho_over(eta);
    let z = I::point(0.0);
    [
        ([s, c, z], -(d * c)),
        ([c, -s, z], d * s),
        ([-(s - sr), cr - c, I::point(1.0)], d * c - rho * (s - sr)),
    ]
}

/// Interval gradient (w.r.t. x) and constant term of an activation function at β, over
/// the thicknesses `eta` (a point, or a cell of a proof over η).
pub(super) fn affine(model: &Model, kind: ContactKind, beta: f64, eta: I, mu: f64) -> ([I; 3], I) {
    combine(ntm_rows(model, beta, eta), kind, eta, mu)
}

/// [`affine`] times η, from [`ntm_rows_times_eta`] (the rows of a Farkas cell with fill).
pub(super) fn affine_times_eta(
    model: &Model,
    kind: ContactKind,
    beta: f64,
    eta: I,
    mu: f64,
) -> ([I; 3], I) {
    combine(ntm_rows_times_eta(model, beta, eta), kind, eta, mu)
}

/// The activation function `kind` from the rows of N, T and M.
fn combine(rows: [([I; 3], I); 3], kind: ContactKind, eta: I, mu: f64) -> ([I; 3], I) {
    let [(gn, n0), (gt, t0), (gm, m0)] = rows;
    let he = I::point(0.5) * eta;
    let m = I::point(mu);
    let comb = |a: I, g1: [I; 3], c1: I, k: I, g2: [I; 3], c2: I| {
        (
            [
                a * g1[0] + k * g2[0],
                a * g1[1] + k * g2[1],
                a * g1[2] + k * g2[2],
            ],
            a * c1 + k * c2,
        )
    };
    match kind {
        ContactKind::HingeExtrados => comb(I::point(1.0), gm, m0, -he, gn, n0),
        ContactKind::HingeIntrados => comb(I::point(-1.0), gm, m0, -he, gn, n0),
        ContactKind::SlidePlus => comb(I::point(1.0), gt, t0, -m, gn, n0),
        ContactKind::SlideMinus => comb(I::point(-1.0), gt, t0, -m, gn, n0),
    }
}
