//! The ridge's vocabulary: each joint's N, T and M − w as affine functions of (h, v); the
//! hinge rows along a line of the (h, v) plane, which bound w above (extrados) or below
//! (intrados); the candidate points the walk hands over to the check.

use crate::arch::{Arch, JointLayout, WeightModel};
use crate::contact::ContactKind;
use crate::statics::{actions, Reactions};

/// Relative tolerance of the walk's own tests (band membership, rows through a vertex);
/// the verdict on a candidate is `Settings::adm_tol`'s.
pub(super) const TOL: f64 = 1e-9;

/// Whether the ridge search applies: a discrete arch with the centreline weight at finite μ
/// (the true centroid puts η² into the hinge rows; μ = ∞ has no sliding rows, and
/// `limit_states` answers it by the interior alone).
pub fn applies(arch: &Arch, mu: f64) -> bool {
    mu.is_finite()
        && matches!(arch.layout(), JointLayout::Discrete(_))
        && matches!(arch.weight(), WeightModel::Centreline)
}

/// N, T and m = M − w at one joint as affine functions of (h, v): [∂/∂h, ∂/∂v, constant].
pub(super) struct JointRows {
    pub(super) beta: f64,
    pub(super) n: [f64; 3],
    pub(super) t: [f64; 3],
    pub(super) m: [f64; 3],
}

impl JointRows {
    /// The rows of the joint at `beta` (the centreline weight: independent of η).
    pub(super) fn at(arch: &Arch, beta: f64) -> JointRows {
        let a = actions(arch, 1.0, beta);
        JointRows {
            beta,
            n: [a.n[0].g[0], a.n[0].g[1], a.n[0].c],
            t: [a.t[0].g[0], a.t[0].g[1], a.t[0].c],
            m: [a.m[0].g[0], a.m[0].g[1], a.m[0].c],
        }
    }
}

/// The value of an affine row at p = (h, v).
pub(super) fn ev(a: &[f64; 3], p: [f64; 2]) -> f64 {
    a[0] * p[0] + a[1] * p[1] + a[2]
}

/// A hinge row along the line p = p0 + t d of the (h, v) plane: the row is active where
/// w = c0 + c1 t + η (c2 + c3 t); an upper bound on w (extrados) or a lower one (intrados).
#[derive(Clone, Copy)]
pub(super) struct HingeRow {
    pub(super) j: usize,
    pub(super) upper: bool,
    pub(super) c: [f64; 4],
}

impl HingeRow {
    pub(super) fn at(&self, t: f64, eta: f64) -> f64 {
        self.c[0] + self.c[1] * t + eta * (self.c[2] + self.c[3] * t)
    }
    pub(super) fn kind(&self) -> ContactKind {
        if self.upper {
            ContactKind::HingeExtrados
        } else {
            ContactKind::HingeIntrados
        }
    }
}

/// The hinge rows of every joint along the line p = p0 + t d.
pub(super) fn hinge_rows(js: &[JointRows], p0: [f64; 2], d: [f64; 2]) -> Vec<HingeRow> {
    hinge_rows_of(js, 0..js.len(), p0, d)
}

/// The hinge rows of the joints `joints` (indices into `js`, ascending) along the line
/// p = p0 + t d.
pub(super) fn hinge_rows_of(
    js: &[JointRows],
    joints: impl ExactSizeIterator<Item = usize>,
    p0: [f64; 2],
    d: [f64; 2],
) -> Vec<HingeRow> {
    let mut out = Vec::with_capacity(2 * joints.len());
    for j in joints {
        let jr = &js[j];
        let (m0, m1) = (ev(&jr.m, p0), jr.m[0] * d[0] + jr.m[1] * d[1]);
        let (n0, n1) = (ev(&jr.n, p0), jr.n[0] * d[0] + jr.n[1] * d[1]);
        for (upper, sg) in [(true, 0.5), (false, -0.5)] {
            out.push(HingeRow {
                j,
                upper,
                c: [-m0, -m1, sg * n0, sg * n1],
            });
        }
    }
    out
}

/// Whether w lies in the band [max l, min u] of the hinge rows at (t, η), up to `tol`.
pub(super) fn in_band(rows: &[HingeRow], t: f64, eta: f64, w: f64, tol: f64) -> bool {
    rows.iter().all(|r| {
        let v = r.at(t, eta);
        if r.upper {
            w <= v + tol
        } else {
            w >= v - tol
        }
    })
}

/// A point of the ridge to check: (h, v, w) and η.
#[derive(Clone, Copy, Debug)]
pub(super) struct Candidate {
    pub(super) x: Reactions,
    pub(super) eta: f64,
    /// The joints that may be near active there (an index into the walk's subsets), or
    /// `None`: every joint.
    pub(super) near: Option<usize>,
}

/// The determinant of the 3 × 3 matrix of columns a, b, c.
pub(super) fn det3(a: [f64; 3], b: [f64; 3], c: [f64; 3]) -> f64 {
    a[0] * (b[1] * c[2] - b[2] * c[1]) - a[1] * (b[0] * c[2] - b[2] * c[0])
        + a[2] * (b[0] * c[1] - b[1] * c[0])
}
