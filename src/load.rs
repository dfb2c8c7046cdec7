//! Live loads with a multiplier λ (`../shared/spec/loads.md`): a uniform horizontal body
//! force λ·(self-weight), or a vertical point load λ at an extrados point. Self-weight
//! stays the dead load ([`crate::statics`]); the live load adds terms **linear in λ** to
//! N, T and M, so at fixed η and μ every activation function is affine in (x, λ).
//!
//! Units as in [`crate::statics`]: forces in γ t d r, moments in γ t d r², r = 1; the
//! horizontal multiplier is in units of the self-weight (λ g is the acceleration), the
//! point load in γ t d r. Angles β are radians, counter-clockwise from the horizontal
//! through the centre; +x points towards the right springing.

use crate::arch::{Arch, Radians};
use crate::contact::{Contact, ContactKind, Location};
use crate::fill::vertical_actions;
use crate::kinematics::column;
use crate::pressure::Pressure;
use crate::statics::{actions, Reactions};
use serde::{Deserialize, Serialize};

/// A live load with a multiplier λ ≥ 0. A value (`Copy`), as every question passes its load
/// by value: a pressure's fixed arrays (at most 640 bytes) cost nothing beside the LPs it
/// feeds, and keep it free of allocation.
#[derive(Debug, Clone, Copy, PartialEq)]
#[allow(clippy::large_enum_variant)]
pub enum LiveLoad {
    /// A uniform horizontal body force λ·(weight), applied where the weight is applied
    /// (centreline or true centroid); `towards_right`: towards +x (the right springing),
    /// else towards −x.
    Horizontal {
        /// Sense of the force.
        towards_right: bool,
    },
    /// A vertical (downward) point load λ at the extrados point of angle `beta`
    /// (radians), (1 + η/2)(cos β, sin β). On a discrete arch a load at a joint must carry
    /// that joint's angle exactly (sections at the load's angle are compared with `==`; the
    /// command line snaps angles within 1e-9 rad of a joint); else it sits inside a voussoir.
    Point {
        /// Angle of the loaded extrados point.
        beta: Radians,
    },
    /// A vertical pressure λ·q on patches of the extrados (a vehicle or a patch load
    /// spread through the fill, bridge spec §3), built for the thickness it is used at.
    Pressure(Pressure),
}

/// Which side of a section at the point load's own angle: the free body [β_R, β] of a
/// section just before β_P does not contain the load, just after it does. Elsewhere the
/// side makes no difference. In JSON and certificates: `before`, `after`.
#[derive(
    Debug, Clone, Copy, PartialEq, Eq, PartialOrd, Ord, Serialize, Deserialize, schemars::JsonSchema,
)]
#[serde(rename_all = "snake_case")]
pub enum Side {
    /// The section just before (smaller β) the loaded point.
    Before,
    /// The section just after it.
    After,
}

impl LiveLoad {
    /// The live parts (N_L, T_L, M_L) of the internal actions at the joint `beta` per unit
    /// λ, from the free body [β_R, β] (loads.md):
    ///
    /// * horizontal (towards +x): N_L = −Δ sin β, T_L = −Δ cos β,
    ///   M_L = −[ρ (cos β_R − cos β) − Δ sin β], Δ = β − β_R, ρ as for the weight
    ///   (the resultant of the body force on an annular sector acts at its centroid);
    ///   towards −x the opposite;
    /// * point load at β_P, for β > β_P (or β = β_P on the [`Side::After`] side):
    ///   N_L = −cos β, T_L = sin β, M_L = −[(1 + η/2) cos β_P − cos β]; zero before.
    pub fn actions(&self, arch: &Arch, eta: f64, beta: Radians, side: Side) -> [f64; 3] {
        self.actions_d(arch, eta, beta, side)[0]
    }

    /// [`Self::actions`] with its first two β-derivatives: `[N_L, T_L, M_L][order]`
    /// (order 0, 1, 2), for the scans of a continuous arch (each smooth piece; at the point
    /// load's angle the side says which).
    pub fn actions_d(&self, arch: &Arch, eta: f64, beta: Radians, side: Side) -> [[f64; 3]; 3] {
        let (s, c) = beta.sin_cos();
        match *self {
            LiveLoad::Horizontal { towards_right } => {
                let br = arch.beta_right();
                let d = beta - br;
                let rho = arch.weight().rho(eta);
                let k = if towards_right { 1.0 } else { -1.0 };
                [
                    [
                        -k * d * s,
                        -k * d * c,
                        -k * (rho * (arch.right_sin_cos().1 - c) - d * s),
                    ],
                    [
                        -k * (s + d * c),
                        -k * (c - d * s),
                        -k * ((rho - 1.0) * s - d * c),
                    ],
                    [
                        -k * (2.0 * c - d * s),
                        k * (2.0 * s + d * c),
                        -k * ((rho - 2.0) * c + d * s),
                    ],
                ]
            }
            LiveLoad::Point { beta: bp } => {
                let loaded = beta > bp || (beta == bp && side == Side::After);
                if loaded {
                    [
                        [-c, s, -((1.0 + 0.5 * eta) * bp.cos() - c)],
                        [s, c, -s],
                        [c, -s, -c],
                    ]
                } else {
                    [[0.0; 3]; 3]
                }
            }
            LiveLoad::Pressure(p) => {
                let (f, m) = p.resultant(arch, eta, beta, side == Side::After);
                let [n, t, m] = vertical_actions(f, m, beta);
                [0, 1, 2].map(|k| [n[k], t[k], m[k]])
            }
        }
    }

    /// The angles strictly inside the arch where the live actions are not smooth: a point
    /// load's (a jump) or a pressure patch's edges (a corner). A continuous arch is scanned
    /// piece by piece between them, and discretisations keep them as joints.
    pub fn breaks(&self, arch: &Arch, eta: f64) -> Vec<Radians> {
        match *self {
            LiveLoad::Horizontal { .. } => Vec::new(),
            LiveLoad::Point { beta } => vec![beta],
            LiveLoad::Pressure(p) => p.breaks(arch, eta),
        }
    }

    /// Whether a section at `beta` has two sides that differ (the point load's angle).
    pub fn splits(&self, beta: Radians) -> bool {
        match self {
            LiveLoad::Point { beta: bp } => *bp == beta,
            LiveLoad::Pressure(p) => p.splits(beta),
            LiveLoad::Horizontal { .. } => false,
        }
    }

    /// The coefficients q with L_live = λ q · rates for `contacts` (any order; a contact
    /// at the point load's angle counts on its `side`): the power of the live load per
    /// unit λ in the rigid motions of the blocks between consecutive distinct active
    /// joints (the pieces beyond the first and last active joint are at rest). A unit
    /// rate of contact j moves everything after it with (V_x(O), V_y(O), ψ) = its
    /// compatibility column c_j, so a point G moves with (V_x − ψ G_y, V_y + ψ G_x):
    ///
    /// * horizontal: q_j = ±Σ_{blocks m after j} [W_m c_j,x − c_j,ψ (W G_y)_m], with
    ///   W_m = β_{m+1} − β_m and (W G_y)_m = ρ (cos β_m − cos β_{m+1});
    /// * point load: q_j = −[c_j,y + c_j,ψ (1 + η/2) cos β_P] when the loaded point lies
    ///   after j (β_P > β_j, or β_P = β_j with j on the Before side), else 0. A load beyond
    ///   the last active joint is at rest: compatible rates (B λ = 0) give it no power;
    /// * pressure: q_j = −[c_j,y (F_total − F(β_j)) + c_j,ψ (S_total − S(β_j))], the
    ///   pressure's resultant and first moment beyond joint j (on its side).
    pub fn power(&self, arch: &Arch, eta: f64, contacts: &[(Contact, Side)]) -> Vec<f64> {
        match *self {
            LiveLoad::Horizontal { towards_right } => {
                let rho = arch.weight().rho(eta);
                let k = if towards_right { 1.0 } else { -1.0 };
                let mut joints: Vec<Radians> = contacts.iter().map(|(c, _)| c.beta).collect();
                joints.sort_by(f64::total_cmp);
                joints.dedup();
                let blocks: Vec<(Radians, f64, f64)> = joints
                    .windows(2)
                    .map(|w| (w[0], w[1] - w[0], rho * (w[0].cos() - w[1].cos())))
                    .collect();
                contacts
                    .iter()
                    .map(|(c, _)| {
                        let col = column(c.kind, c.beta, eta);
                        k * blocks
                            .iter()
                            .filter(|(start, _, _)| *start >= c.beta)
                            .map(|(_, w, wgy)| w * col[0] - col[2] * wgy)
                            .sum::<f64>()
                    })
                    .collect()
            }
            LiveLoad::Point { beta: bp } => contacts
                .iter()
                .map(|(c, side)| {
                    // the section just before the loaded point has it on its far side
                    let after = bp > c.beta || (bp == c.beta && *side == Side::Before);
                    if !after {
                        return 0.0;
                    }
                    let col = column(c.kind, c.beta, eta);
                    -(col[1] + col[2] * (1.0 + 0.5 * eta) * bp.cos())
                })
                .collect(),
            // the pressure beyond each joint: the whole less the free body's
            LiveLoad::Pressure(p) => {
                let (total_f, total_s) = p.resultant(arch, eta, arch.beta_left(), true);
                contacts
                    .iter()
                    .map(|(c, side)| {
                        let (f, s) = p.resultant(arch, eta, c.beta, *side == Side::After);
                        let col = column(c.kind, c.beta, eta);
                        -(col[1] * (total_f[0] - f[0]) + col[2] * (total_s[0] - s[0]))
                    })
                    .collect()
            }
        }
    }
}

/// The live part of the activation function of `kind` per unit λ, from the live actions
/// (N_L, T_L, M_L) or any of their β-derivatives: E: M_L − η N_L/2; I: −M_L − η N_L/2;
/// S±: ±T_L − μ N_L (the sliding rows exist for finite μ only).
pub fn live_activation(kind: ContactKind, eta: f64, mu: f64, a: [f64; 3]) -> f64 {
    let [n, t, m] = a;
    match kind {
        ContactKind::HingeExtrados => m - 0.5 * eta * n,
        ContactKind::HingeIntrados => -m - 0.5 * eta * n,
        ContactKind::SlidePlus => t - mu * n,
        ContactKind::SlideMinus => -t - mu * n,
    }
}

/// One activation function of a loaded discrete arch: `a · (h, v, w, λ) + c ≤ 0`.
#[derive(Debug, Clone, Copy)]
pub struct LoadRow {
    /// The contact.
    pub contact: Contact,
    /// The side of the loaded section (`After` away from the point load).
    pub side: Side,
    /// Coefficients of (h, v, w, λ).
    pub a: [f64; 4],
    /// Constant term.
    pub c: f64,
}

impl LoadRow {
    /// The value at (x, λ).
    pub fn at(&self, x: &Reactions, lambda: f64) -> f64 {
        self.a[0] * x[0] + self.a[1] * x[1] + self.a[2] * x[2] + self.a[3] * lambda + self.c
    }
    /// (a, c).
    pub fn pair(&self) -> ([f64; 4], f64) {
        (self.a, self.c)
    }
}

/// The rows of a discrete arch: every activation function that exists at μ, at every
/// joint, on both sides of a joint carrying the point load.
pub fn rows(arch: &Arch, joints: &[Radians], eta: f64, mu: f64, load: &LiveLoad) -> Vec<LoadRow> {
    let mut out = Vec::with_capacity(4 * joints.len() + 4);
    for (j, &beta) in joints.iter().enumerate() {
        let at = Location::of_joint(j, joints.len());
        let sides: &[Side] = if load.splits(beta) {
            &[Side::Before, Side::After]
        } else {
            &[Side::After]
        };
        let dead = actions(arch, eta, beta);
        for &side in sides {
            let live = load.actions(arch, eta, beta, side);
            for &kind in ContactKind::active_at(mu) {
                let a = dead.activation(kind, 0, eta, mu);
                let l = live_activation(kind, eta, mu, live);
                out.push(LoadRow {
                    contact: Contact {
                        beta,
                        kind,
                        at,
                        free: false,
                    },
                    side,
                    a: [a.g[0], a.g[1], a.g[2], l],
                    c: a.c,
                });
            }
        }
    }
    out
}
