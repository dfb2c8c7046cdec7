//! The live load of a load certificate, for `verify`: its internal actions and its power
//! in interval arithmetic, written out again from the formulas of docs/loads.md (not the
//! solver's [`crate::load`]).
//!
//! Per unit λ, for the free body [β_R, β] (Δ = β − β_R, ρ as for the weight):
//! * horizontal body force towards +x (k = 1) or −x (k = −1):
//!   N_L = −k Δ sin β, T_L = −k Δ cos β, M_L = −k [ρ (cos β_R − cos β) − Δ sin β];
//! * vertical point load at the extrados point of β_P, for the sections that carry it
//!   (β > β_P, and the `after` side of β_P): N_L = −cos β, T_L = sin β,
//!   M_L = −[(1 + η/2) cos β_P − cos β]; zero for the others.
//!
//! Their β-derivatives (for the Taylor enclosures over a continuum) are derived here:
//! horizontal dN_L = −k (sin β + Δ cos β), d²N_L = −k (2 cos β − Δ sin β),
//! dT_L = −k (cos β − Δ sin β), d²T_L = k (2 sin β + Δ cos β),
//! dM_L = −k [(ρ − 1) sin β − Δ cos β], d²M_L = −k [(ρ − 2) cos β + Δ sin β];
//! point dN_L = sin β, d²N_L = cos β, dT_L = cos β, d²T_L = −sin β, dM_L = −sin β,
//! d²M_L = −cos β.

use super::report::{reject, Rejection};
use super::statics::{Model, Ntm};
use crate::certificate::format::{ContactKind, LoadKind, LoadSpec, Side, Towards};
use crate::certificate::interval::Interval as I;

/// The live load of a certificate with its thickness.
#[derive(Debug, Clone, Copy)]
pub(super) struct Live {
    /// The thickness η of the load problem.
    pub(super) eta: f64,
    kind: LiveKind,
}

#[derive(Debug, Clone, Copy)]
enum LiveKind {
    /// Horizontal body force; `k` = +1 towards +x, −1 towards −x.
    Horizontal { k: f64 },
    /// Vertical point load at the extrados point of `beta`.
    Point { beta: f64 },
}

impl Live {
    /// The load of `spec` on the certificate's arch, checked: η in (0, 2), `towards`
    /// exactly for a horizontal load, `beta` exactly for a point load and on the arch.
    pub(super) fn of(spec: &LoadSpec, model: &Model) -> Result<Live, Rejection> {
        if !(spec.eta.is_finite() && spec.eta > 0.0 && spec.eta < 2.0) {
            return reject(format!("load.eta = {}: must lie in (0, 2)", spec.eta));
        }
        let kind = match (spec.kind, spec.towards, spec.beta) {
            (LoadKind::Horizontal, Some(t), None) => LiveKind::Horizontal {
                k: if t == Towards::Right { 1.0 } else { -1.0 },
            },
            (LoadKind::Point, None, Some(beta)) => {
                if !(beta.is_finite() && beta >= model.beta_r && beta <= model.beta_l) {
                    return reject(format!(
                        "load.beta = {beta}: the loaded point must lie on the arch [beta_right, beta_left] = [{}, {}]",
                        model.beta_r, model.beta_l
                    ));
                }
                LiveKind::Point { beta }
            }
            (LoadKind::Horizontal, _, _) => {
                return reject(
                    "load: a horizontal load needs `towards` (right or left) and no `beta`",
                )
            }
            (LoadKind::Point, _, _) => {
                return reject("load: a point load needs `beta` and no `towards`")
            }
        };
        Ok(Live {
            eta: spec.eta,
            kind,
        })
    }

    /// The point load's angle, where a section has two sides.
    pub(super) fn split(&self) -> Option<f64> {
        match self.kind {
            LiveKind::Point { beta } => Some(beta),
            LiveKind::Horizontal { .. } => None,
        }
    }

    /// Whether the section at β (on `side`, at the point load's angle) carries the load.
    pub(super) fn carries(&self, beta: f64, side: Option<Side>) -> bool {
        match self.kind {
            LiveKind::Horizontal { .. } => true,
            LiveKind::Point { beta: bp } => beta > bp || (beta == bp && side == Some(Side::After)),
        }
    }

    /// The smooth pieces of the arch, each with whether its sections carry the load: the
    /// whole arch for a horizontal load; [β_R, β_P] (the `before` side at β_P) and
    /// [β_P, β_L] (the `after` side) for a point load, so that both sides of the loaded
    /// section are covered.
    pub(super) fn pieces(&self, model: &Model) -> Vec<(f64, f64, bool)> {
        match self.kind {
            LiveKind::Horizontal { .. } => vec![(model.beta_r, model.beta_l, true)],
            LiveKind::Point { beta } => {
                vec![(model.beta_r, beta, false), (beta, model.beta_l, true)]
            }
        }
    }

    /// N_L, T_L, M_L and their first two β-derivatives per unit λ over the angles `b` of
    /// sections that carry the load (`carries`); `None` for sections that do not (zero).
    pub(super) fn ntm(&self, model: &Model, b: I, carries: bool) -> Option<Ntm> {
        let (s, c) = (b.sin(), b.cos());
        let two = I::point(2.0);
        match self.kind {
            LiveKind::Horizontal { k } => {
                let br = I::point(model.beta_r);
                let d = b - br;
                let rho = model.rho(self.eta);
                let one = I::point(1.0);
                let n = [-(d * s), -(s + d * c), -(two * c - d * s)];
                let t = [-(d * c), -(c - d * s), two * s + d * c];
                let m = [
                    -(rho * (br.cos() - c) - d * s),
                    -((rho - one) * s - d * c),
                    -((rho - two) * c + d * s),
                ];
                let k3 = |v: [I; 3]| v.map(|e| e.scale(k));
                Some(Ntm {
                    n: k3(n),
                    t: k3(t),
                    m: k3(m),
                })
            }
            LiveKind::Point { beta } => {
                if !carries {
                    return None;
                }
                let re = I::point(1.0) + I::point(0.5) * I::point(self.eta);
                let m0 = -(re * I::point(beta).cos() - c);
                Some(Ntm {
                    n: [-c, s, c],
                    t: [s, c, -s],
                    m: [m0, -s, -c],
                })
            }
        }
    }

    /// The live power per unit λ of a unit rate of each contact of `kept` (angle, kind,
    /// side): everything after contact j moves with its compatibility column
    /// c_j = (V_x(O), V_y(O), ψ), so a point G moves with (V_x − ψ G_y, V_y + ψ G_x);
    /// the blocks are the pieces between consecutive distinct angles of `kept` (those
    /// beyond the last are at rest when B λ = 0).
    /// * horizontal: q_j = k Σ_{blocks m after j} [W_m c_j,x − c_j,ψ ρ (cos β_m − cos β_{m+1})],
    ///   W_m = β_{m+1} − β_m (the weight of block m and its centroid height times W_m);
    /// * point: q_j = −[c_j,y + c_j,ψ (1 + η/2) cos β_P] when the loaded point moves with
    ///   the blocks after j (β_P > β_j, or β_P = β_j and j on the `before` side), else 0.
    pub(super) fn power(
        &self,
        model: &Model,
        kept: &[(f64, ContactKind, Option<Side>)],
        columns: &[[I; 3]],
    ) -> Vec<I> {
        match self.kind {
            LiveKind::Horizontal { k } => {
                let mut angles: Vec<f64> = kept.iter().map(|j| j.0).collect();
                angles.sort_by(f64::total_cmp);
                angles.dedup();
                let rho = model.rho(self.eta);
                let blocks: Vec<(f64, I, I)> = angles
                    .windows(2)
                    .map(|w| {
                        let (a, b) = (I::point(w[0]), I::point(w[1]));
                        (w[0], b - a, rho * (a.cos() - b.cos()))
                    })
                    .collect();
                kept.iter()
                    .zip(columns)
                    .map(|(j, col)| {
                        blocks
                            .iter()
                            .filter(|(start, _, _)| *start >= j.0)
                            .fold(I::point(0.0), |acc, &(_, w, wgy)| {
                                acc + w * col[0] - col[2] * wgy
                            })
                            .scale(k)
                    })
                    .collect()
            }
            LiveKind::Point { beta } => {
                let re = I::point(1.0) + I::point(0.5) * I::point(self.eta);
                let xp = re * I::point(beta).cos();
                kept.iter()
                    .zip(columns)
                    .map(|(j, col)| {
                        if beta > j.0 || (beta == j.0 && j.2 == Some(Side::Before)) {
                            -(col[1] + col[2] * xp)
                        } else {
                            I::point(0.0)
                        }
                    })
                    .collect()
            }
        }
    }

    /// The load in words.
    pub(super) fn text(&self) -> String {
        match self.kind {
            LiveKind::Horizontal { k } => format!(
                "horizontal body force lambda x self-weight towards the {} springing, eta = {}",
                if k > 0.0 { "right" } else { "left" },
                self.eta
            ),
            LiveKind::Point { beta } => format!(
                "vertical point load lambda at the extrados point beta = {beta}, eta = {}",
                self.eta
            ),
        }
    }
}

/// A state of either problem, for the checks of a listed or proved state: reactions x at
/// thickness η and, under a live load, its multiplier λ.
#[derive(Clone, Copy)]
pub(super) struct StateAt<'a> {
    /// Reactions.
    pub(super) x: [f64; 3],
    /// Thickness.
    pub(super) eta: f64,
    /// The live load and λ (load certificates).
    pub(super) load: Option<(&'a Live, f64)>,
}

impl<'a> StateAt<'a> {
    /// A state of the thickness problem: x at η, no load.
    pub(super) fn bare(x: [f64; 3], eta: f64) -> StateAt<'a> {
        StateAt { x, eta, load: None }
    }

    /// The state (x, λ) under the live load, at the load's thickness.
    pub(super) fn loaded(live: &'a Live, lambda: f64, x: [f64; 3]) -> StateAt<'a> {
        StateAt {
            x,
            eta: live.eta,
            load: Some((live, lambda)),
        }
    }

    /// N, T, M (with β-derivatives) at the joint β on `side`: the dead actions of x,
    /// plus λ times the live ones where the section carries the load.
    pub(super) fn ntm(&self, model: &Model, beta: f64, side: Option<Side>) -> Ntm {
        let b = I::point(beta);
        let dead = model.ntm(b, self.x, self.eta);
        match self.load {
            Some((live, lambda)) => match live.ntm(model, b, live.carries(beta, side)) {
                Some(l) => dead.plus(lambda, &l),
                None => dead,
            },
            None => dead,
        }
    }

    /// The live load, if any.
    pub(super) fn live(&self) -> Option<&'a Live> {
        self.load.map(|(live, _)| live)
    }

    /// The point load's angle (two sections there).
    pub(super) fn split(&self) -> Option<f64> {
        self.live().and_then(|live| live.split())
    }

    /// 1 + ‖x‖₁, the scale of the floating-point tolerances.
    pub(super) fn scale(&self) -> f64 {
        1.0 + self.x.iter().map(|v| v.abs()).sum::<f64>()
    }
}

/// Where a proof over the arch holds, in words.
pub(super) fn everywhere(model: &Model, live: &Live) -> &'static str {
    match (&model.joints, live.split()) {
        (Some(j), Some(bp)) if j.contains(&bp) => {
            "at every joint (both sides of the loaded section)"
        }
        (Some(_), _) => "at every joint",
        (None, Some(_)) => "over the whole arch (both sides of the loaded section)",
        (None, None) => "over the whole arch",
    }
}

/// The sections at a joint: two (`before`, `after`) at the point load's angle, else one.
pub(super) fn sections(beta: f64, split: Option<f64>) -> Vec<Option<Side>> {
    if split == Some(beta) {
        vec![Some(Side::Before), Some(Side::After)]
    } else {
        vec![None]
    }
}

/// " (before)" / " (after)" / "".
pub(super) fn side_text(side: Option<Side>) -> &'static str {
    match side {
        Some(Side::Before) => " (before the loaded point)",
        Some(Side::After) => " (after the loaded point)",
        None => "",
    }
}

#[cfg(test)]
mod tests {
    //! The verifier's live actions against the solver's (`crate::load`, whose β-derivatives
    //! are checked against differences in `tests/it/loads.rs`): two implementations of the
    //! spec, every order, both loads, both weight models, both sides.
    use super::super::mechanism::column;
    use super::super::statics::Model;
    use super::Live;
    use crate::certificate::format::{LoadKind, LoadSpec, Side, Towards};
    use crate::certificate::interval::Interval as I;
    use crate::load::{LiveLoad, Side as SolverSide};
    use crate::{Arch, WeightModel};

    /// The verifier's model of the continuous `arch`.
    fn model_of(arch: &Arch) -> Model {
        Model {
            beta_r: arch.beta_right(),
            beta_l: arch.beta_left(),
            centroid: arch.weight() == WeightModel::Centroid,
            joints: None,
        }
    }

    /// The verifier's live load of `spec` = (kind, towards, β) at thickness `eta`.
    fn live_of(model: &Model, eta: f64, spec: (LoadKind, Option<Towards>, Option<f64>)) -> Live {
        Live::of(
            &LoadSpec {
                eta,
                kind: spec.0,
                towards: spec.1,
                beta: spec.2,
            },
            model,
        )
        .unwrap()
    }

    #[test]
    fn live_actions_and_their_derivatives_match_the_solver() {
        for weight in [WeightModel::Centreline, WeightModel::Centroid] {
            let arch = Arch::new(-0.4, 3.3, weight).unwrap();
            let model = model_of(&arch);
            let eta = 0.37;
            for (spec, load) in [
                (
                    (LoadKind::Horizontal, Some(Towards::Right), None),
                    LiveLoad::Horizontal {
                        towards_right: true,
                    },
                ),
                (
                    (LoadKind::Horizontal, Some(Towards::Left), None),
                    LiveLoad::Horizontal {
                        towards_right: false,
                    },
                ),
                (
                    (LoadKind::Point, None, Some(1.2)),
                    LiveLoad::Point { beta: 1.2 },
                ),
            ] {
                let live = live_of(&model, eta, spec);
                // 41 angles and the point load's own (both sides there)
                let angles = (0..=40).map(|i| -0.4 + 3.7 * i as f64 / 40.0).chain([1.2]);
                for beta in angles {
                    for (side, solver_side) in [
                        (Some(Side::Before), SolverSide::Before),
                        (Some(Side::After), SolverSide::After),
                    ] {
                        let side = live.split().filter(|&b| b == beta).and(side);
                        let carries = live.carries(beta, side.or(Some(Side::After)));
                        let want = load.actions_d(&arch, eta, beta, solver_side);
                        let got = live.ntm(&model, I::point(beta), carries);
                        for (order, w) in want.iter().enumerate() {
                            let g = got.map_or([0.0; 3], |n| {
                                [n.n[order].mid(), n.t[order].mid(), n.m[order].mid()]
                            });
                            for k in 0..3 {
                                assert!(
                                    (g[k] - w[k]).abs() <= 1e-13,
                                    "{weight:?} {load:?} beta {beta} order {order} component {k}: {} vs {}",
                                    g[k],
                                    w[k]
                                );
                            }
                        }
                    }
                }
            }
        }
    }

    #[test]
    fn live_power_matches_the_solver() {
        use crate::contact::{Contact, ContactKind, Location};
        for weight in [WeightModel::Centreline, WeightModel::Centroid] {
            let arch = Arch::new(-0.3, 3.4, weight).unwrap();
            let model = model_of(&arch);
            let eta = 0.42;
            let bp = 1.1;
            // contacts at four joints, two sides at the loaded one
            let kept: Vec<(f64, ContactKind, Option<Side>)> = vec![
                (-0.3, ContactKind::HingeExtrados, None),
                (0.5, ContactKind::SlidePlus, None),
                (bp, ContactKind::HingeIntrados, Some(Side::Before)),
                (bp, ContactKind::SlideMinus, Some(Side::After)),
                (2.4, ContactKind::HingeIntrados, None),
                (3.4, ContactKind::HingeExtrados, None),
            ];
            let columns: Vec<[I; 3]> = kept.iter().map(|&(b, k, _)| column(k, b, eta)).collect();
            let pairs: Vec<(Contact, SolverSide)> = kept
                .iter()
                .map(|&(beta, kind, side)| {
                    (
                        Contact {
                            beta,
                            kind,
                            at: Location::Interior,
                            free: false,
                        },
                        if side == Some(Side::Before) {
                            SolverSide::Before
                        } else {
                            SolverSide::After
                        },
                    )
                })
                .collect();
            for (spec, load) in [
                (
                    (LoadKind::Horizontal, Some(Towards::Left), None),
                    LiveLoad::Horizontal {
                        towards_right: false,
                    },
                ),
                (
                    (LoadKind::Point, None, Some(bp)),
                    LiveLoad::Point { beta: bp },
                ),
            ] {
                let live = live_of(&model, eta, spec);
                let got = live.power(&model, &kept, &columns);
                let want = load.power(&arch, eta, &pairs);
                for (g, w) in got.iter().zip(&want) {
                    assert!(
                        g.lo <= *w + 1e-13 && *w - 1e-13 <= g.hi,
                        "{load:?}: {g:?} vs {w}"
                    );
                }
            }
        }
    }
}
