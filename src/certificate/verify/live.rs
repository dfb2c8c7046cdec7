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
use super::vertical::{actions, edge_angles, pressure_jets, At, PressureModel};
use crate::certificate::format::{ContactKind, LoadKind, LoadSpec, Side, Towards};
use crate::certificate::interval::Interval as I;

/// The live load of a certificate with its thickness.
#[derive(Debug, Clone)]
pub(super) struct Live {
    /// The thickness η of the load problem.
    pub(super) eta: f64,
    kind: LiveKind,
    /// The angles of its point loads, where a section has two sides (sorted).
    splits: Vec<f64>,
    /// The smooth pieces of the arch (and the slivers around a patch's edges).
    spans: Vec<Span>,
}

#[derive(Debug, Clone)]
enum LiveKind {
    /// Horizontal body force; `k` = +1 towards +x, −1 towards −x.
    Horizontal { k: f64 },
    /// Vertical point load at the extrados point of `beta`.
    Point { beta: f64 },
    /// Vertical pressure: patches and point loads.
    Pressure(PressureModel),
}

/// A piece [a, b] of the arch whose sections carry the point loads of the free body `at`;
/// `smooth` unless it is the enclosure of a patch's edge, where the actions have a corner
/// (proved there by the enclosure of φ itself, not by a Taylor form).
#[derive(Debug, Clone, Copy)]
pub(super) struct Span {
    pub(super) a: f64,
    pub(super) b: f64,
    pub(super) at: At,
    pub(super) smooth: bool,
}

impl Span {
    /// The whole arch as one smooth piece (no load).
    pub(super) fn whole(model: &Model) -> Span {
        Span {
            a: model.beta_r,
            b: model.beta_l,
            at: At {
                beta: model.beta_r,
                after: false,
            },
            smooth: true,
        }
    }
}

/// The free body of the section at `beta` on `side` (`after` only on the `after` side of a
/// point load's own section).
pub(super) fn section(beta: f64, side: Option<Side>) -> At {
    At {
        beta,
        after: side == Some(Side::After),
    }
}

/// A pressure of `spec`, checked: at least one load, patches finite with x_lo < x_hi and
/// q >= 0, point loads on the arch with q >= 0.
fn pressure_of(spec: &LoadSpec, model: &Model) -> Result<PressureModel, Rejection> {
    let patches: Vec<[f64; 3]> = spec
        .patches
        .iter()
        .flatten()
        .map(|p| [p.x_lo, p.x_hi, p.q])
        .collect();
    let points: Vec<[f64; 2]> = spec
        .points
        .iter()
        .flatten()
        .map(|p| [p.beta, p.q])
        .collect();
    if patches.is_empty() && points.is_empty() {
        return reject("load: a pressure needs at least one patch or point load");
    }
    if let Some(p) = patches.iter().find(|p| !(p[0] < p[1] && p[2] >= 0.0)) {
        return reject(format!(
            "load.patches: x_lo = {}, x_hi = {}, q = {}: need x_lo < x_hi and q >= 0",
            p[0], p[1], p[2]
        ));
    }
    let off = |b: f64| !(b >= model.beta_r && b <= model.beta_l);
    if let Some(p) = points
        .iter()
        .find(|p| off(p[0]) || p[1].is_nan() || p[1] < 0.0)
    {
        return reject(format!(
            "load.points: beta = {}, q = {}: the point must lie on the arch [{}, {}] and q >= 0",
            p[0], p[1], model.beta_r, model.beta_l
        ));
    }
    Ok(PressureModel { patches, points })
}

/// The pieces of the arch between the point loads `splits` (each a piece [a, b] whose
/// sections carry the loads before a, and the one at a), with the `edges` of patches cut
/// out as slivers that are not smooth; a point load inside a sliver is rejected.
fn spans_of(model: &Model, splits: &[f64], edges: &[(f64, f64)]) -> Result<Vec<Span>, Rejection> {
    let mut out = Vec::new();
    let mut cur = Span::whole(model);
    let mut events: Vec<(f64, f64)> = splits.iter().map(|&b| (b, b)).collect();
    events.extend(
        edges
            .iter()
            .map(|&(lo, hi)| (lo.max(model.beta_r), hi.min(model.beta_l))),
    );
    events.sort_by(|x, y| x.0.total_cmp(&y.0));
    for (lo, hi) in events {
        if lo < cur.a {
            return reject(format!(
                "load: a point load or a patch edge near beta = {lo} lies within the located edge of another patch"
            ));
        }
        out.push(Span { b: lo, ..cur });
        if lo == hi {
            cur = Span {
                a: lo,
                at: At {
                    beta: lo,
                    after: true,
                },
                ..cur
            };
        } else {
            out.push(Span {
                a: lo,
                b: hi,
                smooth: false,
                ..cur
            });
            cur.a = hi;
        }
    }
    out.push(Span {
        b: model.beta_l,
        ..cur
    });
    Ok(out)
}

impl Live {
    /// The load of `spec` on the certificate's arch, checked: η in (0, 2), `towards`
    /// exactly for a horizontal load, `beta` exactly for a point load and on the arch,
    /// `patches` and `points` exactly for a pressure.
    pub(super) fn of(spec: &LoadSpec, model: &Model) -> Result<Live, Rejection> {
        if !(spec.eta.is_finite() && spec.eta > 0.0 && spec.eta < 2.0) {
            return reject(format!("load.eta = {}: must lie in (0, 2)", spec.eta));
        }
        let pressure = spec.patches.is_some() || spec.points.is_some();
        let kind = match (spec.kind, spec.towards, spec.beta, pressure) {
            (LoadKind::Horizontal, Some(t), None, false) => LiveKind::Horizontal {
                k: if t == Towards::Right { 1.0 } else { -1.0 },
            },
            (LoadKind::Point, None, Some(beta), false) => {
                if !(beta.is_finite() && beta >= model.beta_r && beta <= model.beta_l) {
                    return reject(format!(
                        "load.beta = {beta}: the loaded point must lie on the arch [beta_right, beta_left] = [{}, {}]",
                        model.beta_r, model.beta_l
                    ));
                }
                LiveKind::Point { beta }
            }
            (LoadKind::Pressure, None, None, true) => LiveKind::Pressure(pressure_of(spec, model)?),
            (LoadKind::Horizontal, ..) => {
                return reject(
                    "load: a horizontal load needs `towards` (right or left) and no `beta`, `patches` or `points`",
                )
            }
            (LoadKind::Point, ..) => {
                return reject("load: a point load needs `beta` and no `towards`, `patches` or `points`")
            }
            (LoadKind::Pressure, ..) => {
                return reject("load: a pressure needs `patches` or `points` and no `towards` or `beta`")
            }
        };
        let mut splits: Vec<f64> = match &kind {
            LiveKind::Horizontal { .. } => Vec::new(),
            LiveKind::Point { beta } => vec![*beta],
            LiveKind::Pressure(p) => p.points.iter().map(|p| p[0]).collect(),
        };
        splits.sort_by(f64::total_cmp);
        splits.dedup();
        let edges = match &kind {
            LiveKind::Pressure(p) if model.joints.is_none() => {
                edge_angles(p, (model.beta_r, model.beta_l), spec.eta)?
            }
            _ => Vec::new(),
        };
        let spans = spans_of(model, &splits, &edges)?;
        Ok(Live {
            eta: spec.eta,
            kind,
            splits,
            spans,
        })
    }

    /// The angles of the point loads, where a section has two sides.
    pub(super) fn splits(&self) -> &[f64] {
        &self.splits
    }

    /// The angle of a single point load (the load a transfer carries to a springing).
    pub(super) fn point(&self) -> Option<f64> {
        match self.kind {
            LiveKind::Point { beta } => Some(beta),
            _ => None,
        }
    }

    /// Whether λ may enter the rows of the section at β (on `side`, at a point load's
    /// angle): always for a horizontal load and a pressure, for a point load on the
    /// sections after it (and the `after` side of its own).
    pub(super) fn carries(&self, beta: f64, side: Option<Side>) -> bool {
        match self.kind {
            LiveKind::Point { beta: bp } => section(beta, side).carries(bp),
            _ => true,
        }
    }

    /// The smooth pieces of the arch: the whole arch for a horizontal load; between
    /// consecutive point loads (both sides of a loaded section covered), with a pressure's
    /// patch edges cut out as slivers on a continuous arch.
    pub(super) fn pieces(&self) -> &[Span] {
        &self.spans
    }

    /// N_L, T_L, M_L and their first two β-derivatives per unit λ over the angles `b` of
    /// sections with the free body `at`; `None` where they are zero (a point load not on
    /// it).
    pub(super) fn ntm(&self, model: &Model, b: I, at: At) -> Option<Ntm> {
        let (s, c) = model.trig(b);
        let two = I::point(2.0);
        match &self.kind {
            LiveKind::Horizontal { k } => {
                let br = I::point(model.beta_r);
                let d = b - br;
                let rho = model.rho(self.eta);
                let one = I::point(1.0);
                let n = [-(d * s), -(s + d * c), -(two * c - d * s)];
                let t = [-(d * c), -(c - d * s), two * s + d * c];
                let m = [
                    -(rho * (model.springing.1 - c) - d * s),
                    -((rho - one) * s - d * c),
                    -((rho - two) * c + d * s),
                ];
                let k3 = |v: [I; 3]| v.map(|e| e.scale(*k));
                Some(Ntm {
                    n: k3(n),
                    t: k3(t),
                    m: k3(m),
                })
            }
            LiveKind::Point { beta } => {
                if !at.carries(*beta) {
                    return None;
                }
                let re = I::point(1.0) + I::point(0.5) * I::point(self.eta);
                let m0 = -(re * I::point(*beta).cos() - c);
                Some(Ntm {
                    n: [-c, s, c],
                    t: [s, c, -s],
                    m: [m0, -s, -c],
                })
            }
            LiveKind::Pressure(p) => {
                let (f, sm) = pressure_jets(p, (model.beta_r, model.beta_l), b, self.eta, at);
                let [n, t, m] = actions(f, sm, b);
                Some(Ntm { n, t, m })
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
        match &self.kind {
            LiveKind::Horizontal { k } => {
                let k = *k;
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
                let beta = *beta;
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
            // the pressure beyond each contact: the whole less its free body's
            LiveKind::Pressure(p) => {
                let arch = (model.beta_r, model.beta_l);
                let whole = At {
                    beta: model.beta_l,
                    after: true,
                };
                let fs = |beta: f64, at: At| {
                    let (f, s) = pressure_jets(p, arch, I::point(beta), self.eta, at);
                    (f[0], s[0])
                };
                let (total_f, total_s) = fs(model.beta_l, whole);
                kept.iter()
                    .zip(columns)
                    .map(|(&(beta, _, side), col)| {
                        let (f, s) = fs(beta, section(beta, side));
                        -(col[1] * (total_f - f) + col[2] * (total_s - s))
                    })
                    .collect()
            }
        }
    }

    /// The load in words.
    pub(super) fn text(&self) -> String {
        match &self.kind {
            LiveKind::Horizontal { k } => format!(
                "horizontal body force lambda x self-weight towards the {} springing, eta = {}",
                if *k > 0.0 { "right" } else { "left" },
                self.eta
            ),
            LiveKind::Point { beta } => format!(
                "vertical point load lambda at the extrados point beta = {beta}, eta = {}",
                self.eta
            ),
            LiveKind::Pressure(p) => format!(
                "vertical pressure lambda x q on the extrados: {} patch(es) and {} point load(s), eta = {}",
                p.patches.len(),
                p.points.len(),
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
            Some((live, lambda)) => match live.ntm(model, b, section(beta, side)) {
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

    /// The point loads' angles (two sections at each).
    pub(super) fn splits(&self) -> &'a [f64] {
        self.live().map_or(&[], |live| live.splits())
    }

    /// 1 + ‖x‖₁, the scale of the floating-point tolerances.
    pub(super) fn scale(&self) -> f64 {
        1.0 + self.x.iter().map(|v| v.abs()).sum::<f64>()
    }
}

/// Where a proof over the arch holds, in words.
pub(super) fn everywhere(model: &Model, live: &Live) -> &'static str {
    let (one, many) = (live.splits().len() == 1, live.splits().len() > 1);
    match &model.joints {
        Some(j) if live.splits().iter().any(|b| j.contains(b)) => match one {
            true => "at every joint (both sides of the loaded section)",
            false => "at every joint (both sides of each loaded section)",
        },
        Some(_) => "at every joint",
        None if one => "over the whole arch (both sides of the loaded section)",
        None if many => "over the whole arch (both sides of each loaded section)",
        None => "over the whole arch",
    }
}

/// The sections at a joint: two (`before`, `after`) at a point load's angle, else one.
pub(super) fn sections(beta: f64, splits: &[f64]) -> Vec<Option<Side>> {
    if splits.contains(&beta) {
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
            springing: super::super::statics::springing_trig(arch.beta_right()),
            joint_trig: Vec::new(),
            beta_l: arch.beta_left(),
            centroid: arch.weight() == WeightModel::Centroid,
            joints: None,
            fill: arch.fill().map(|f| super::super::vertical::FillModel {
                weight_ratio: f.weight_ratio,
                depth: f.depth,
            }),
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
                patches: None,
                points: None,
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
                        let side = live.splits().contains(&beta).then_some(side).flatten();
                        let at = super::section(beta, side.or(Some(Side::After)));
                        let want = load.actions_d(&arch, eta, beta, solver_side);
                        let got = live.ntm(&model, I::point(beta), at);
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

    /// The pressure of the checks below: three patches (one off a segmental arch's
    /// extrados) and two point loads.
    fn pressure() -> crate::pressure::Pressure {
        use crate::pressure::{Patch, PointLoad, Pressure};
        let patch = |x_lo, x_hi, q| Patch { x_lo, x_hi, q };
        let point = |beta, q| PointLoad { beta, q };
        Pressure::new(
            &[
                patch(-0.5, 0.1, 2.0),
                patch(0.3, 0.9, 1.5),
                patch(-1.25, -0.9, 0.7),
            ],
            &[point(1.0, 0.8), point(2.0, 0.3)],
        )
        .unwrap()
    }

    /// The verifier's pressure of the solver's `p` at thickness `eta`.
    fn live_pressure(model: &Model, eta: f64, p: &crate::pressure::Pressure) -> Live {
        use crate::certificate::format::{PatchSpec, PointSpec};
        let patches = p.patches().iter();
        let points = p.points().iter();
        Live::of(
            &LoadSpec {
                eta,
                kind: LoadKind::Pressure,
                towards: None,
                beta: None,
                patches: Some(
                    patches
                        .map(|q| PatchSpec {
                            x_lo: q.x_lo,
                            x_hi: q.x_hi,
                            q: q.q,
                        })
                        .collect(),
                ),
                points: Some(
                    points
                        .map(|q| PointSpec {
                            beta: q.beta,
                            q: q.q,
                        })
                        .collect(),
                ),
            },
            model,
        )
        .unwrap()
    }

    /// The fill (dead) and a pressure (live) as the verifier writes them against the solver's
    /// `fill.rs`, `pressure.rs` and statics: values and two β-derivatives at 60 angles of a
    /// semicircle, a horseshoe and a segmental arch; over small intervals of angles (also
    /// across a patch's edge, π and 0) the enclosures hold the solver's values at points
    /// inside them.
    #[test]
    #[allow(clippy::needless_range_loop)] // the order indexes six arrays alike
    fn fill_and_pressure_match_the_solver() {
        use crate::fill::Fill;
        let fill = Fill::new(0.9, 0.07).unwrap();
        let p = pressure();
        let load = LiveLoad::Pressure(p);
        let x = [0.8, 1.1, -0.2];
        for (br, bl, weight) in [
            (0.0, std::f64::consts::PI, WeightModel::Centreline),
            (-0.3, 3.45, WeightModel::Centroid),
            (0.6, 2.5, WeightModel::Centreline),
        ] {
            let arch = Arch::new(br, bl, weight).unwrap().with_fill(fill);
            let model = model_of(&arch);
            let eta = 0.23;
            let live = live_pressure(&model, eta, &p);
            let angles: Vec<f64> = (0..60)
                .map(|i| br + (bl - br) * (i as f64 + 0.37) / 60.0)
                .collect();
            for &beta in &angles {
                let dead = model.ntm(I::point(beta), x, eta);
                let want = crate::statics::actions(&arch, eta, beta);
                let live_want = load.actions_d(&arch, eta, beta, SolverSide::After);
                let at = super::section(beta, Some(Side::After));
                let live_got = live.ntm(&model, I::point(beta), at).unwrap();
                for o in 0..3 {
                    let pairs = [
                        (dead.n[o], want.n[o].at(&x)),
                        (dead.t[o], want.t[o].at(&x)),
                        (dead.m[o], want.m[o].at(&x)),
                        (live_got.n[o], live_want[o][0]),
                        (live_got.t[o], live_want[o][1]),
                        (live_got.m[o], live_want[o][2]),
                    ];
                    for (k, (g, w)) in pairs.iter().enumerate() {
                        assert!(
                            (g.mid() - w).abs() <= 1e-12 * (1.0 + w.abs()) && g.width() < 1e-12,
                            "arch [{br}, {bl}] beta {beta} order {o} term {k}: {g:?} vs {w}"
                        );
                    }
                }
            }
            // enclosures over intervals, some across the corners of the actions
            let mut centres = angles.clone();
            centres.extend(p.breaks(&arch, eta));
            centres.extend(
                [0.0, std::f64::consts::PI]
                    .iter()
                    .filter(|&&b| b > br && b < bl),
            );
            for &c in &centres {
                let (a, b) = ((c - 1e-3).max(br), (c + 1e-3).min(bl));
                let span = live
                    .pieces()
                    .iter()
                    .find(|s| s.a <= c && c <= s.b)
                    .expect("a piece holds every angle");
                let over_live = live.ntm(&model, I::new(a, b), span.at).unwrap();
                let over_dead = model.ntm(I::new(a, b), x, eta);
                for i in 0..=8 {
                    let beta = a + (b - a) * i as f64 / 8.0;
                    let want = crate::statics::actions(&arch, eta, beta);
                    for side in [SolverSide::Before, SolverSide::After] {
                        // a point load inside the interval is carried by one side only
                        if p.points().iter().any(|q| q.beta > a && q.beta <= b) {
                            continue;
                        }
                        let lw = load.actions_d(&arch, eta, beta, side);
                        for o in 0..3 {
                            let inside = |g: I, w: f64| g.lo - 1e-12 <= w && w <= g.hi + 1e-12;
                            assert!(
                                inside(over_dead.n[o], want.n[o].at(&x)),
                                "dead N{o} at {beta} in [{a}, {b}]"
                            );
                            assert!(
                                inside(over_dead.t[o], want.t[o].at(&x)),
                                "dead T{o} at {beta}"
                            );
                            assert!(
                                inside(over_dead.m[o], want.m[o].at(&x)),
                                "dead M{o} at {beta}"
                            );
                            assert!(
                                inside(over_live.n[o], lw[o][0]),
                                "live N{o} at {beta} in [{a}, {b}]"
                            );
                            assert!(inside(over_live.t[o], lw[o][1]), "live T{o} at {beta}");
                            assert!(inside(over_live.m[o], lw[o][2]), "live M{o} at {beta}");
                        }
                    }
                }
            }
        }
    }

    /// The power of the fill (in the dead load's) and of a pressure as the verifier writes
    /// them against the solver's `kinematics::power` and `LiveLoad::power`.
    #[test]
    fn fill_and_pressure_power_match_the_solver() {
        use super::super::mechanism::weight_work;
        use crate::contact::{Contact, ContactKind, Location};
        let p = pressure();
        let load = LiveLoad::Pressure(p);
        let arch = Arch::new(-0.3, 3.4, WeightModel::Centroid)
            .unwrap()
            .with_fill(crate::fill::Fill::new(1.1, 0.2).unwrap());
        let model = model_of(&arch);
        let eta = 0.42;
        let live = live_pressure(&model, eta, &p);
        // contacts at five joints, two sides at a point load's
        let kept: Vec<(f64, ContactKind, Option<Side>)> = vec![
            (-0.3, ContactKind::HingeExtrados, None),
            (0.5, ContactKind::SlidePlus, None),
            (1.0, ContactKind::HingeIntrados, Some(Side::Before)),
            (1.0, ContactKind::SlideMinus, Some(Side::After)),
            (2.4, ContactKind::HingeIntrados, None),
            (3.4, ContactKind::HingeExtrados, None),
        ];
        let columns: Vec<[I; 3]> = kept.iter().map(|&(b, k, _)| column(k, b, eta)).collect();
        let contact = |beta, kind| Contact {
            beta,
            kind,
            at: Location::Interior,
            free: false,
        };
        let pairs: Vec<(Contact, SolverSide)> = kept
            .iter()
            .map(|&(beta, kind, side)| {
                let side = match side {
                    Some(Side::Before) => SolverSide::Before,
                    _ => SolverSide::After,
                };
                (contact(beta, kind), side)
            })
            .collect();
        let got = live.power(&model, &kept, &columns);
        let want = load.power(&arch, eta, &pairs);
        let dead_got = weight_work(&model, I::point(eta), &kept, &columns);
        let contacts: Vec<Contact> = pairs.iter().map(|p| p.0).collect();
        let dead_want = crate::kinematics::power(&arch, eta, &contacts);
        for i in 0..kept.len() {
            let close = |g: I, w: f64| g.lo <= w + 1e-12 && w - 1e-12 <= g.hi && g.width() < 1e-12;
            assert!(
                close(got[i], want[i]),
                "live {i}: {:?} vs {}",
                got[i],
                want[i]
            );
            // the verifier's work of the dead load is minus the solver's power
            assert!(
                close(-dead_got[i], dead_want[i]),
                "dead {i}: {:?} vs {}",
                dead_got[i],
                dead_want[i]
            );
        }
    }
}
