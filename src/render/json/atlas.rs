//! The `atlas --json` document.

use super::common::JSON_VERSION;
use crate::atlas::{Atlas, Column, Kind};
use schemars::JsonSchema;
use serde::Serialize;
use std::collections::BTreeMap;

#[derive(Debug, Serialize, JsonSchema)]
struct RectangleJson {
    alpha_min: f64,
    alpha_max: f64,
    mu_max_factor: f64,
    columns: usize,
    samples: usize,
}

#[derive(Debug, Serialize, JsonSchema)]
struct RegionJson {
    kind: &'static str,
    polygon: Vec<[f64; 2]>,
}

#[derive(Debug, Serialize, JsonSchema)]
struct PointJson {
    alpha: f64,
    mu: f64,
    /// The last μ of the lower kind and the first of the upper one.
    bracket: [f64; 2],
    /// Whether the bracket's ends are neighbouring floats.
    tight: bool,
    /// Why the bisection stopped short of neighbouring floats.
    #[serde(skip_serializing_if = "Option::is_none")]
    stopped: Option<String>,
    /// Between `non_unique` and `unique`: why the non-unique end's limit states above η_s
    /// are none at the other end (each followed there by Newton on its pattern).
    #[serde(skip_serializing_if = "Option::is_none")]
    why: Option<String>,
    /// Whether `mu` is solved from the condition that ends the branch (else the middle of
    /// the bracket, or μ_ms as `friction_limit` gives it).
    exact: bool,
    /// Solved from its defining condition: η of the branch's last limit state.
    #[serde(skip_serializing_if = "Option::is_none")]
    eta: Option<f64>,
    /// Solved from its defining condition: what ends the branch there.
    #[serde(skip_serializing_if = "Option::is_none")]
    condition: Option<String>,
    /// Solved from its defining condition: the condition's residual there.
    #[serde(skip_serializing_if = "Option::is_none")]
    residual: Option<f64>,
    /// Between `non_unique` and `unique`: why the point is not solved from its defining
    /// condition.
    #[serde(skip_serializing_if = "Option::is_none")]
    not_exact: Option<String>,
    /// Verified certificates at both ends of the bracket state its two kinds.
    certified: bool,
    /// With `--certify`, why the bracket is not certified.
    #[serde(skip_serializing_if = "Option::is_none")]
    not_certified: Option<String>,
    /// The bracket whose two ends verified certificates state as the two kinds (for μ_ms:
    /// μ_ms (1 ± 1e-6)).
    #[serde(skip_serializing_if = "Option::is_none")]
    certified_bracket: Option<[f64; 2]>,
    /// With a certified bracket: whether the verifier proved both certificates' lists of
    /// limit states complete (voussoir arches, ridge evidence), so that the kinds are proved;
    /// false where it only checked each listed state (continuous arches).
    #[serde(skip_serializing_if = "Option::is_none")]
    list_proved_complete: Option<bool>,
}

#[derive(Debug, Serialize, JsonSchema)]
struct BoundaryJson {
    between: [&'static str; 2],
    points: Vec<PointJson>,
}

#[derive(Debug, Serialize, JsonSchema)]
struct RunJson {
    kind: &'static str,
    mu_from: f64,
    mu_to: f64,
    /// With `--certify`: the sample certified inside the run and whether its verified
    /// certificate states the run's kind.
    #[serde(skip_serializing_if = "Option::is_none")]
    certified: Option<RunCertificate>,
}

#[derive(Debug, Serialize, JsonSchema)]
struct RunCertificate {
    mu: f64,
    holds: bool,
    /// Whether the verifier proved the certificate's list of limit states complete.
    list_proved_complete: bool,
    #[serde(skip_serializing_if = "Option::is_none")]
    why_not: Option<String>,
}

#[derive(Debug, Serialize, JsonSchema)]
struct SampleJson {
    mu: f64,
    kind: &'static str,
    /// The η of every limit state (η_s first where it carries one).
    #[serde(skip_serializing_if = "Option::is_none")]
    etas: Option<Vec<f64>>,
    #[serde(skip_serializing_if = "Option::is_none")]
    reason: Option<String>,
}

#[derive(Debug, Serialize, JsonSchema)]
struct ColumnJson {
    alpha: f64,
    mu_ms: Option<f64>,
    mu_ms_exact: bool,
    runs: Vec<RunJson>,
    samples: Vec<SampleJson>,
}

#[derive(Debug, Serialize, JsonSchema)]
struct TipJson {
    between: [&'static str; 2],
    /// The last opening of the first kind and the first of the second, just above μ_ms.
    alpha_bracket: [f64; 2],
    alpha: f64,
    mu_ms: f64,
    #[serde(skip_serializing_if = "Option::is_none")]
    stopped: Option<String>,
}

#[derive(Debug, Serialize, JsonSchema)]
struct TopJson {
    /// The opening of the largest μ/μ_ms on the `non_unique`/`unique` boundary.
    alpha: f64,
    /// Its bracket when the golden section stopped.
    alpha_bracket: [f64; 2],
    /// The boundary point's μ there (solved from what ends its branch; on a voussoir arch
    /// the non-unique end of its bracket, bisected to neighbouring floats).
    mu: f64,
    mu_ms: f64,
    /// μ/μ_ms.
    ratio: f64,
    /// What ends the branch at the solved openings nearest the top on either side
    /// (different: a corner where the last branch to end changes).
    conditions: [String; 2],
    /// "a smooth peak", "a corner", "at the edge of the openings evaluated" (a side without
    /// a solved opening), or on a voussoir arch "the largest of bisected points".
    shape: &'static str,
    /// Openings evaluated.
    evaluations: usize,
}

#[derive(Debug, Serialize, JsonSchema)]
struct TracedPointJson {
    alpha: f64,
    /// Where the branch ends, solved from its defining condition.
    mu: f64,
    mu_ms: f64,
    /// η of the branch's last limit state.
    eta: f64,
    /// What ends the branch there.
    condition: String,
    /// The condition's residual there.
    residual: f64,
    /// Verified certificates at `mu` (the branch's last limit state listed) and at
    /// mu (1 + 1e-8) state `non_unique` and `unique`; where there is a notch, its lower
    /// end and its birth's bracket are certified the same way too.
    certified: bool,
    /// With `--certify`, why the point is not certified.
    #[serde(skip_serializing_if = "Option::is_none")]
    not_certified: Option<String>,
    /// A notch of uniqueness below `mu`: a lower branch ends (`non_unique` below, `unique`
    /// above) before the upper branch is born (`unique` below, `non_unique` above).
    #[serde(skip_serializing_if = "Option::is_none")]
    notch: Option<NotchJson>,
}

#[derive(Debug, Serialize, JsonSchema)]
struct NotchJson {
    /// Where the lower branch ends, solved from its defining condition.
    mu_end: f64,
    /// η of its last limit state.
    eta_end: f64,
    /// What ends it.
    condition: String,
    /// The birth of the upper branch: its μ, bisected (solved where `birth_exact`).
    mu_birth: f64,
    birth_bracket: [f64; 2],
    birth_exact: bool,
}

/// The `non_unique`/`unique` boundary between two columns, traced by continuation in α.
#[derive(Debug, Serialize, JsonSchema)]
struct TracedJson {
    between: [&'static str; 2],
    /// The curve's ends in α: the two columns' openings, or a column's and the tip's.
    alpha_from: f64,
    alpha_to: f64,
    /// The μ of the curve's ends: the columns' boundary points, or μ_ms at a tip.
    mu_from: f64,
    mu_to: f64,
    /// Where the band meets the μ_ms curve inside the strip, [alpha, mu_ms]: the curve runs
    /// from a column's point to this tip (or from it to the next column's point).
    #[serde(skip_serializing_if = "Option::is_none")]
    tip: Option<[f64; 2]>,
    /// The largest departure of the points from the straight segment between the curve's
    /// ends, relative to μ (null: no points).
    chord_departure: Option<f64>,
    points: Vec<TracedPointJson>,
}

/// The `atlas --json` document.
#[derive(Debug, Serialize, JsonSchema)]
pub struct AtlasJson {
    version: u32,
    status: &'static str,
    weight: &'static str,
    blocks: Option<usize>,
    rectangle: RectangleJson,
    regions: Vec<RegionJson>,
    boundaries: Vec<BoundaryJson>,
    /// The `non_unique`/`unique` boundary inside each strip between two columns that both
    /// solve one, traced by continuation in α (the polygons pass through these points).
    traced: Vec<TracedJson>,
    /// Where a kind begins or ends along the μ_ms curve (at μ_ms (1 + 1e-6)).
    tips: Vec<TipJson>,
    /// The top of the non-unique band (null: no solved `non_unique`/`unique` point).
    top: Option<TopJson>,
    /// Samples the search did not decide (their runs are in no region).
    undecided: usize,
    columns: Vec<ColumnJson>,
}

/// The name of a run's or a sample's kind (`undecided` where the search did not decide).
fn name(k: Option<Kind>) -> &'static str {
    k.map_or("undecided", Kind::name)
}

/// The changes of kind of every column, grouped by the pair of kinds (in the order met,
/// lower μ first), the μ_ms curve (no equilibrium below) first.
fn boundaries(columns: &[Column]) -> Vec<BoundaryJson> {
    let mut by_pair: BTreeMap<[Kind; 2], Vec<PointJson>> = BTreeMap::new();
    for c in columns {
        if let (Some(mu_ms), Some(first)) = (c.mu_ms, c.runs.first().and_then(|r| r.0)) {
            by_pair
                .entry([Kind::NoEquilibrium, first])
                .or_default()
                .push(PointJson {
                    alpha: c.alpha,
                    mu: mu_ms,
                    bracket: [mu_ms, mu_ms],
                    tight: true,
                    stopped: None,
                    why: None,
                    exact: c.mu_ms_exact,
                    eta: None,
                    condition: None,
                    residual: None,
                    not_exact: None,
                    certified: matches!(c.mu_ms_certified, Some(Ok(_))),
                    not_certified: c.mu_ms_certified.clone().and_then(Result::err),
                    certified_bracket: c
                        .mu_ms_certified
                        .clone()
                        .and_then(Result::ok)
                        .map(|m| [m.bracket.0, m.bracket.1]),
                    list_proved_complete: c
                        .mu_ms_certified
                        .clone()
                        .and_then(Result::ok)
                        .map(|m| m.complete),
                });
        }
        for p in &c.boundaries {
            let end = p.end.clone().and_then(Result::ok);
            by_pair.entry(p.between).or_default().push(PointJson {
                alpha: p.alpha,
                mu: p.mu(),
                bracket: [p.bracket.0, p.bracket.1],
                tight: p.tight,
                stopped: p.stopped.clone(),
                why: p.why.clone(),
                exact: p.exact(),
                eta: end.as_ref().map(|e| e.state.t),
                condition: end.as_ref().map(|e| e.condition.describe()),
                residual: end.as_ref().map(|e| e.residual),
                not_exact: p.end.clone().and_then(Result::err),
                certified: matches!(p.certified, Some(Ok(_))),
                not_certified: p.certified.clone().and_then(Result::err),
                certified_bracket: matches!(p.certified, Some(Ok(_))).then(|| {
                    let (lo, hi) = p.certified_bracket();
                    [lo, hi]
                }),
                list_proved_complete: p.certified.clone().and_then(Result::ok),
            });
        }
    }
    by_pair
        .into_iter()
        .map(|(k, points)| BoundaryJson {
            between: [k[0].name(), k[1].name()],
            points,
        })
        .collect()
}

/// The traced boundary of every strip that has one.
fn traced(a: &Atlas) -> Vec<TracedJson> {
    a.columns
        .iter()
        .zip(a.columns.iter().skip(1))
        .zip(&a.traced)
        .filter_map(|((c, d), t)| {
            let t = t.as_ref()?;
            // a tip strip's curve ends at the tip on one side
            let (alpha_from, alpha_to) = match t.tip {
                Some(tip) if t.from_mu == tip[1] => (tip[0], d.alpha),
                Some(tip) => (c.alpha, tip[0]),
                None => (c.alpha, d.alpha),
            };
            Some(TracedJson {
                between: [Kind::NonUnique.name(), Kind::Unique.name()],
                alpha_from,
                alpha_to,
                mu_from: t.from_mu,
                mu_to: t.to_mu,
                tip: t.tip,
                chord_departure: t.chord_departure((c.alpha, d.alpha)).map(|d| d.0),
                points: t
                    .points
                    .iter()
                    .map(|p| TracedPointJson {
                        alpha: p.alpha,
                        mu: p.end.mu,
                        mu_ms: p.mu_ms,
                        eta: p.end.state.t,
                        condition: p.end.condition.describe(),
                        residual: p.end.residual,
                        certified: matches!(p.certified, Some(Ok(_))),
                        not_certified: p.certified.clone().and_then(Result::err),
                        notch: p.notch.as_ref().map(|n| NotchJson {
                            mu_end: n.below.mu,
                            eta_end: n.below.state.t,
                            condition: n.below.condition.describe(),
                            mu_birth: n.birth.mu(),
                            birth_bracket: [n.birth.bracket.0, n.birth.bracket.1],
                            birth_exact: n.birth.exact(),
                        }),
                    })
                    .collect(),
            })
        })
        .collect()
}

fn column(c: &Column) -> ColumnJson {
    ColumnJson {
        alpha: c.alpha,
        mu_ms: c.mu_ms,
        mu_ms_exact: c.mu_ms_exact,
        runs: c
            .runs
            .iter()
            .map(|r| RunJson {
                kind: name(r.0),
                mu_from: r.1,
                mu_to: r.2,
                certified: c
                    .runs_certified
                    .iter()
                    .find(|(mu, _)| *mu > r.1 && *mu < r.2)
                    .map(|(mu, res)| RunCertificate {
                        mu: *mu,
                        holds: res.is_ok(),
                        list_proved_complete: res.as_ref().is_ok_and(|c| *c),
                        why_not: res.clone().err(),
                    }),
            })
            .collect(),
        samples: c
            .samples
            .iter()
            .map(|s| match &s.kind {
                Ok((k, etas)) => SampleJson {
                    mu: s.mu,
                    kind: k.name(),
                    etas: Some(etas.clone()),
                    reason: None,
                },
                Err(e) => SampleJson {
                    mu: s.mu,
                    kind: "undecided",
                    etas: None,
                    reason: Some(e.to_string()),
                },
            })
            .collect(),
    }
}

/// Builds the `atlas --json` document.
pub fn atlas(a: &Atlas) -> AtlasJson {
    let r = &a.rectangle;
    AtlasJson {
        version: JSON_VERSION,
        status: "ok",
        weight: r.weight.name(),
        blocks: r.blocks,
        rectangle: RectangleJson {
            alpha_min: r.alpha_min,
            alpha_max: r.alpha_max,
            mu_max_factor: r.mu_max_factor,
            columns: r.columns,
            samples: r.samples,
        },
        regions: a
            .regions
            .iter()
            .map(|(k, p)| RegionJson {
                kind: k.name(),
                polygon: p.clone(),
            })
            .collect(),
        boundaries: boundaries(&a.columns),
        traced: traced(a),
        tips: a
            .tips
            .iter()
            .map(|t| TipJson {
                between: [t.between[0].name(), t.between[1].name()],
                alpha_bracket: [t.alpha.0, t.alpha.1],
                alpha: 0.5 * (t.alpha.0 + t.alpha.1),
                mu_ms: t.mu_ms,
                stopped: t.stopped.clone(),
            })
            .collect(),
        top: a.top.as_ref().map(|t| TopJson {
            alpha: t.alpha,
            alpha_bracket: [t.alpha_bracket.0, t.alpha_bracket.1],
            mu: t.mu,
            mu_ms: t.mu_ms,
            ratio: t.ratio,
            conditions: [t.conditions.0.clone(), t.conditions.1.clone()],
            shape: t.shape(),
            evaluations: t.evaluations,
        }),
        undecided: a
            .columns
            .iter()
            .flat_map(|c| &c.samples)
            .filter(|s| s.kind.is_err())
            .count(),
        columns: a.columns.iter().map(column).collect(),
    }
}
