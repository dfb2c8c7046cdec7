//! The JSON shapes of the command-line contract (`shared/spec/cli.md`).
//! Angles in radians; `null` stands for +∞.

use crate::arch::{Arch, JointLayout};
use crate::contact::Contact;
use crate::limit::{Candidate, LimitState, Outcome};
use crate::limit_curve::{CurvePoint, CurveStatus};
use crate::limit_states::Survey;
use serde::Serialize;

/// The `version` of every JSON document the command line prints: bumped on a breaking
/// change of any shape (2: `version`/`status` everywhere, `pattern` for every joint list).
pub const JSON_VERSION: u32 = 2;

/// The arch as described in every JSON document.
#[derive(Debug, Serialize)]
pub struct ArchJson {
    beta_right: f64,
    beta_left: f64,
    weight: &'static str,
    joints: &'static str,
    #[serde(skip_serializing_if = "Option::is_none")]
    joint_angles: Option<Vec<f64>>,
    symmetric: bool,
}

impl ArchJson {
    /// Describes `arch`.
    pub fn new(arch: &Arch) -> ArchJson {
        let (joints, joint_angles) = match arch.layout() {
            JointLayout::Continuous => ("continuous", None),
            JointLayout::Discrete(j) => ("discrete", Some(j.clone())),
        };
        ArchJson {
            beta_right: arch.beta_right(),
            beta_left: arch.beta_left(),
            weight: arch.weight().name(),
            joints,
            joint_angles,
            symmetric: arch.is_symmetric(),
        }
    }
}

#[derive(Debug, Serialize)]
pub(crate) struct Reactions {
    h: f64,
    v: f64,
    w: f64,
}

#[derive(Debug, Serialize)]
struct Rate {
    beta: f64,
    kind: &'static str,
    rate: f64,
}

#[derive(Debug, Serialize)]
pub(crate) struct MechanismJson {
    rates: Vec<Rate>,
    dof: usize,
    power: f64,
    dissipation: f64,
    symmetric: bool,
    compatibility_residual: f64,
    complementarity_residual: f64,
}

#[derive(Debug, Serialize)]
struct Checks {
    eta_static: f64,
    newton_residual: f64,
    max_phi: f64,
    eta_bracket: [f64; 2],
}

#[derive(Debug, Serialize)]
struct CandidateJson {
    pattern: Vec<Contact>,
    tried: bool,
    eta: Option<f64>,
    verdict: String,
}

/// The `solve --json` document.
#[derive(Debug, Serialize)]
pub struct SolveJson {
    version: u32,
    status: &'static str,
    arch: ArchJson,
    mu: f64,
    friction_angle_deg: f64,
    #[serde(skip_serializing_if = "Option::is_none")]
    eta: Option<f64>,
    #[serde(skip_serializing_if = "Option::is_none")]
    mode: Option<&'static str>,
    /// false when the mode name is a descriptive one outside the contract's list
    #[serde(skip_serializing_if = "Option::is_none")]
    mode_standard: Option<bool>,
    #[serde(skip_serializing_if = "Option::is_none")]
    pattern: Option<Vec<Contact>>,
    #[serde(skip_serializing_if = "Option::is_none")]
    reactions: Option<Reactions>,
    #[serde(skip_serializing_if = "Option::is_none")]
    mechanism: Option<MechanismJson>,
    #[serde(skip_serializing_if = "Option::is_none")]
    checks: Option<Checks>,
    #[serde(skip_serializing_if = "Option::is_none")]
    mu_ms: Option<f64>,
    #[serde(skip_serializing_if = "Option::is_none")]
    eta_bracket: Option<[f64; 2]>,
    #[serde(skip_serializing_if = "Option::is_none")]
    message: Option<String>,
    #[serde(skip_serializing_if = "Option::is_none")]
    candidates: Option<Vec<CandidateJson>>,
    /// Whether η_s is attained by a bounded state.
    #[serde(skip_serializing_if = "Option::is_none")]
    attained: Option<bool>,
    /// Whether the least admissible state carries a non-associative mechanism.
    #[serde(skip_serializing_if = "Option::is_none")]
    mechanism_at_eta: Option<bool>,
    /// Whether exactly one limit state has η in [η_s, 2) (`null`: search not completed).
    #[serde(skip_serializing_if = "Option::is_none")]
    unique: Option<Option<bool>>,
    /// Every limit state with η in [η_s, 2), ascending.
    #[serde(skip_serializing_if = "Option::is_none")]
    limit_states: Option<Vec<LimitStateJson>>,
    /// How the limit states were searched.
    #[serde(skip_serializing_if = "Option::is_none")]
    search: Option<SearchJson>,
}

#[derive(Debug, Serialize)]
struct LimitStateJson {
    eta: f64,
    mode: &'static str,
    pattern: Vec<Contact>,
    reactions: Reactions,
    mechanism: MechanismJson,
}

#[derive(Debug, Serialize)]
struct SearchJson {
    complete: bool,
    method: Option<String>,
    events: Option<usize>,
    #[serde(skip_serializing_if = "Option::is_none")]
    reason: Option<String>,
}

pub(crate) fn mechanism_json(m: &crate::mechanism::Mechanism) -> MechanismJson {
    MechanismJson {
        rates: m
            .contacts
            .iter()
            .zip(&m.rates)
            .map(|(c, &rate)| Rate {
                beta: c.beta,
                kind: c.kind.name(),
                rate,
            })
            .collect(),
        dof: m.dof,
        power: m.power,
        dissipation: m.dissipation,
        symmetric: m.symmetric,
        compatibility_residual: m.compatibility,
        complementarity_residual: m.complementarity,
    }
}

pub(crate) fn reactions(x: &[f64; 3]) -> Reactions {
    Reactions {
        h: x[0],
        v: x[1],
        w: x[2],
    }
}

/// The status word of an outcome.
pub fn status(outcome: &Outcome) -> &'static str {
    match outcome {
        Outcome::Limit(_) => "ok",
        Outcome::NoEquilibrium { .. } => "no_equilibrium",
        Outcome::Unresolved { .. } => "unresolved",
        Outcome::NoCollapse { .. } => "no_collapse",
    }
}

fn limit_parts(ls: &LimitState) -> (Vec<Contact>, Reactions, MechanismJson, Checks) {
    let m = &ls.mechanism;
    (
        ls.pattern.clone(),
        reactions(&ls.x),
        mechanism_json(m),
        Checks {
            eta_static: ls.eta_static,
            newton_residual: ls.newton_residual,
            max_phi: ls.max_phi,
            eta_bracket: [ls.bracket.0, ls.bracket.1],
        },
    )
}

/// Builds the `solve --json` document from the solution and the search for every limit
/// state; `explain` adds the enumeration log.
pub fn solve(survey: &Survey, explain: bool) -> SolveJson {
    let sol = &survey.solution;
    let mut doc = SolveJson {
        version: JSON_VERSION,
        status: status(&sol.outcome),
        arch: ArchJson::new(&sol.arch),
        mu: sol.mu,
        friction_angle_deg: sol.mu.atan().to_degrees(),
        eta: None,
        mode: None,
        mode_standard: None,
        pattern: None,
        reactions: None,
        mechanism: None,
        checks: None,
        mu_ms: None,
        eta_bracket: None,
        message: None,
        candidates: explain.then(|| candidates(&sol.candidates)),
        attained: None,
        mechanism_at_eta: None,
        unique: None,
        limit_states: None,
        search: None,
    };
    match &sol.outcome {
        Outcome::Limit(ls) => {
            let (p, r, m, c) = limit_parts(ls);
            doc.eta = Some(ls.eta);
            doc.mode = Some(ls.mode.name());
            doc.mode_standard = Some(ls.mode.is_standard());
            doc.pattern = Some(p);
            doc.reactions = Some(r);
            doc.mechanism = Some(m);
            doc.checks = Some(c);
        }
        Outcome::NoCollapse { reason } => {
            doc.message = Some(reason.clone());
        }
        Outcome::NoEquilibrium { mu_ms, reason } => {
            doc.mu_ms = *mu_ms;
            doc.message = Some(reason.clone());
        }
        Outcome::Unresolved {
            eta_lo,
            eta_hi,
            reason,
            ..
        } => {
            doc.eta_bracket = Some([*eta_lo, *eta_hi]);
            doc.message = Some(reason.clone());
        }
    }
    match &survey.states {
        Ok(s) => {
            // η_s is known exactly and every limit state above it was searched: a decided
            // answer even when the least state carries no mechanism. An arch that stands at
            // every η > 0 keeps its status (there is no least thickness; η_s = 0 is an
            // infimum) and its message, with the limit states above listed all the same.
            if !matches!(sol.outcome, Outcome::NoCollapse { .. }) {
                doc.status = "ok";
                doc.message = None;
            }
            doc.eta_bracket = None;
            doc.eta = Some(s.eta_s);
            doc.attained = Some(s.attained);
            doc.mechanism_at_eta = Some(s.mechanism_at_eta_s);
            doc.unique = Some(survey.unique());
            let mut all = Vec::new();
            if let (true, Outcome::Limit(ls)) = (s.mechanism_at_eta_s, &sol.outcome) {
                all.push(LimitStateJson {
                    eta: ls.eta,
                    mode: ls.mode.name(),
                    pattern: ls.pattern.clone(),
                    reactions: reactions(&ls.x),
                    mechanism: mechanism_json(&ls.mechanism),
                });
            }
            all.extend(s.above.iter().map(|a| LimitStateJson {
                eta: a.eta,
                mode: a.mode.name(),
                pattern: a.pattern.clone(),
                reactions: reactions(&a.x),
                mechanism: mechanism_json(&a.mechanism),
            }));
            // the top-level mode, pattern, reactions and mechanism are the least limit
            // state's (none when there is none)
            if !s.mechanism_at_eta_s {
                let least = s.above.first();
                doc.mode = least.map(|a| a.mode.name());
                doc.mode_standard = least.map(|a| a.mode.is_standard());
                doc.pattern = least.map(|a| a.pattern.clone());
                doc.reactions = least.map(|a| reactions(&a.x));
                doc.mechanism = least.map(|a| mechanism_json(&a.mechanism));
                doc.checks = None;
            }
            doc.limit_states = Some(all);
            doc.search = Some(SearchJson {
                complete: true,
                method: Some(s.method.clone()),
                events: Some(s.events),
                reason: None,
            });
        }
        Err(reason) => {
            doc.search = Some(SearchJson {
                complete: false,
                method: None,
                events: None,
                reason: Some(reason.clone()),
            });
            if let Outcome::Limit(_) = &sol.outcome {
                doc.unique = Some(None);
            }
        }
    }
    doc
}

fn candidates(c: &[Candidate]) -> Vec<CandidateJson> {
    c.iter()
        .map(|c| CandidateJson {
            pattern: c.contacts.clone(),
            tried: c.tried,
            eta: c.eta,
            verdict: c.verdict.clone(),
        })
        .collect()
}

#[derive(Debug, Serialize)]
struct CurveRow {
    mu: f64,
    friction_angle_deg: f64,
    status: &'static str,
    eta: Option<f64>,
    mode: Option<&'static str>,
    pattern: Option<Vec<Contact>>,
    #[serde(skip_serializing_if = "Option::is_none")]
    message: Option<String>,
}

/// The `curve --json` document.
#[derive(Debug, Serialize)]
pub struct CurveJson {
    version: u32,
    status: &'static str,
    arch: ArchJson,
    /// μ_ms, the least friction at which some thickness stands.
    mu_ms: Option<f64>,
    points: Vec<CurveRow>,
}

/// Builds the `curve --json` document. `mu_ms` is the least friction admitting
/// equilibrium (`None` when no finite μ does).
pub fn curve(arch: &Arch, mu_ms: Option<f64>, points: &[CurvePoint]) -> CurveJson {
    CurveJson {
        version: JSON_VERSION,
        status: "ok",
        arch: ArchJson::new(arch),
        mu_ms,
        points: points
            .iter()
            .map(|p| {
                let (eta, mode, pattern, message) = match &p.outcome {
                    Outcome::Limit(ls) => (
                        Some(ls.eta),
                        Some(ls.mode.name()),
                        Some(ls.pattern.clone()),
                        None,
                    ),
                    Outcome::NoEquilibrium { reason, .. }
                    | Outcome::Unresolved { reason, .. }
                    | Outcome::NoCollapse { reason } => (None, None, None, Some(reason.clone())),
                };
                CurveRow {
                    mu: p.mu,
                    friction_angle_deg: p.mu.atan().to_degrees(),
                    status: status(&p.outcome),
                    eta,
                    mode,
                    pattern,
                    message,
                }
            })
            .collect(),
    }
}

/// The document printed for bad input under `--json`.
#[derive(Debug, Serialize)]
pub struct ErrorJson {
    version: u32,
    /// Always `"error"`.
    status: &'static str,
    /// The message naming the argument and its valid range.
    message: String,
}

impl ErrorJson {
    /// The error document for `message`.
    pub fn new(message: String) -> ErrorJson {
        ErrorJson {
            version: JSON_VERSION,
            status: "error",
            message,
        }
    }
}

#[derive(Debug, Serialize)]
struct BranchJson {
    mode: &'static str,
    mode_standard: bool,
    mu_min: f64,
    mu_max: f64,
    eta_min: f64,
    eta_max: f64,
    pattern: Vec<Contact>,
}

#[derive(Debug, Serialize)]
struct CornerJson {
    mu: f64,
    friction_angle_deg: f64,
    eta: f64,
    /// True for a corner (the slopes differ), false for a smooth transition.
    kink: bool,
    /// dη_s/dμ on the side of smaller μ (`null`: the vertical purely-sliding branch at
    /// μ_ms, or undefined at μ = ∞).
    slope_left: f64,
    /// dη_s/dμ on the side of larger μ (`null` at μ = ∞).
    slope_right: f64,
    pattern: Vec<Contact>,
    between: [&'static str; 2],
    mode: &'static str,
    exact: bool,
    residual: f64,
}

#[derive(Debug, Serialize)]
struct LimitBranchJson {
    #[serde(flatten)]
    branch: BranchJson,
    samples: usize,
}

fn branch(b: &crate::limit_curve::Branch) -> BranchJson {
    BranchJson {
        mode: b.mode.name(),
        mode_standard: b.mode.is_standard(),
        mu_min: b.mu_min,
        mu_max: b.mu_max,
        eta_min: b.eta_min,
        eta_max: b.eta_max,
        pattern: b.pattern.clone(),
    }
}

#[derive(Debug, Serialize)]
struct ThicknessLimitJson {
    mu: f64,
    eta: f64,
    pattern: Vec<Contact>,
    exact: bool,
}

#[derive(Debug, Serialize)]
struct UnresolvedJson {
    mu: f64,
    message: String,
}

/// The `modes --json` document (`null` stands for +∞).
#[derive(Debug, Serialize)]
pub struct ModesJson {
    version: u32,
    status: &'static str,
    arch: ArchJson,
    branches: Vec<BranchJson>,
    /// Kinks of η_s(μ).
    corners: Vec<CornerJson>,
    /// Smooth pattern changes of η_s(μ).
    transitions: Vec<CornerJson>,
    /// Limit states above the boundary, by samples.
    limit_branches: Vec<LimitBranchJson>,
    /// Where the boundary reaches the thickness limit η → 2 above μ_ms (then no
    /// purely-sliding corner, and `mu_min` is this μ), else `null`.
    thickness_limit: Option<ThicknessLimitJson>,
    /// The least friction at which the arch stands at some thickness (μ_ms); the same
    /// value as `mu_ms`, under the name the contract gives it.
    mu_min: Option<f64>,
    /// μ_ms.
    mu_ms: Option<f64>,
    unresolved: Vec<UnresolvedJson>,
    /// Sampled μ at which the arch stands at every thickness (no collapse).
    no_collapse: Vec<f64>,
    /// Sampled μ at which no thickness stands.
    no_equilibrium: Vec<f64>,
}

fn corner(c: &crate::limit_curve::Corner) -> CornerJson {
    CornerJson {
        mu: c.mu,
        friction_angle_deg: c.mu.atan().to_degrees(),
        eta: c.eta,
        kink: c.kink,
        slope_left: c.slope_left,
        slope_right: c.slope_right,
        pattern: c.joints.clone(),
        between: c.between.map(|m| m.name()),
        mode: c.mode.name(),
        exact: c.exact,
        residual: c.residual,
    }
}

/// Builds the `modes --json` document.
pub fn modes(arch: &Arch, curve: &crate::limit_curve::LimitCurve) -> ModesJson {
    ModesJson {
        version: JSON_VERSION,
        status: match curve.status() {
            CurveStatus::Traced => "ok",
            CurveStatus::NoEquilibrium => "no_equilibrium",
            CurveStatus::NoCollapse => "no_collapse",
            CurveStatus::Unresolved => "unresolved",
        },
        arch: ArchJson::new(arch),
        branches: curve.branches.iter().map(branch).collect(),
        corners: curve.corners.iter().map(corner).collect(),
        transitions: curve.transitions.iter().map(corner).collect(),
        limit_branches: curve
            .limit_branches
            .iter()
            .map(|b| LimitBranchJson {
                branch: branch(&b.branch),
                samples: b.samples,
            })
            .collect(),
        thickness_limit: curve.thickness_limit.as_ref().map(|t| ThicknessLimitJson {
            mu: t.mu,
            eta: t.eta,
            pattern: t.pattern.clone(),
            exact: t.exact,
        }),
        mu_min: curve.thickness_limit.as_ref().map(|t| t.mu).or(curve.mu_ms),
        mu_ms: curve.mu_ms,
        no_collapse: curve.no_collapse.clone(),
        no_equilibrium: curve.no_equilibrium.clone(),
        unresolved: curve
            .unresolved
            .iter()
            .map(|(mu, m)| UnresolvedJson {
                mu: *mu,
                message: m.clone(),
            })
            .collect(),
    }
}

#[derive(Debug, Serialize)]
struct SafestJson {
    h: f64,
    v: f64,
    w: f64,
    margin: f64,
}

/// The `assess --json` document (`null` stands for +∞ where noted).
#[derive(Debug, Serialize)]
pub struct AssessJson {
    version: u32,
    status: &'static str,
    arch: ArchJson,
    /// The thickness ratio assessed.
    eta: f64,
    /// η*(μ) (`null` when nothing stands at μ or η* is unresolved; 0 when every η stands).
    eta_min: Option<f64>,
    /// Whether the arch stands at (η, μ).
    stands: bool,
    /// η / η*(μ) (`null`: none, or infinite when every η stands).
    geometric_factor: Option<f64>,
    /// μ (`null` = ∞).
    mu: Option<f64>,
    /// μ_min(η), the least friction at which η stands (`null` when none does).
    mu_min: Option<f64>,
    /// Whether `mu_min` is exact (Newton on the active pattern, verified) or an LP bound.
    mu_min_exact: Option<bool>,
    /// The active pattern of the state at μ_min.
    mu_min_pattern: Vec<Contact>,
    /// μ / μ_min (`null` when μ_min does not exist or the factor is infinite).
    friction_factor: Option<f64>,
    /// The collapse mode of η*(μ).
    mode: Option<&'static str>,
    /// The admissible state of largest margin, when the arch stands.
    safest_state: Option<SafestJson>,
    /// Why η*(μ) is missing, when it is.
    #[serde(skip_serializing_if = "Option::is_none")]
    message: Option<String>,
}

fn finite(v: f64) -> Option<f64> {
    v.is_finite().then_some(v)
}

/// Builds the `assess --json` document.
pub fn assess(arch: &Arch, a: &crate::assess::Assessment) -> AssessJson {
    use crate::assess::LeastFriction;
    let (mu_min, mu_min_exact, mu_min_pattern) = match &a.least_friction {
        LeastFriction::Finite { mu, pattern, exact } => {
            (finite(*mu), Some(*exact), pattern.clone())
        }
        LeastFriction::Never => (None, None, Vec::new()),
    };
    let (eta_min, message) = match &a.limit {
        Outcome::Limit(ls) => (Some(ls.eta), None),
        Outcome::NoCollapse { reason } => (Some(0.0), Some(reason.clone())),
        Outcome::NoEquilibrium { reason, .. } | Outcome::Unresolved { reason, .. } => {
            (None, Some(reason.clone()))
        }
    };
    AssessJson {
        version: JSON_VERSION,
        status: match &a.limit {
            Outcome::Unresolved { .. } => "unresolved",
            _ => "ok",
        },
        arch: ArchJson::new(arch),
        eta: a.eta,
        eta_min,
        stands: a.stands,
        geometric_factor: a.geometric_factor.and_then(finite),
        mu: finite(a.mu),
        mu_min,
        mu_min_exact,
        mu_min_pattern,
        friction_factor: a.friction_factor.and_then(finite),
        mode: a.mode.map(|m| m.name()),
        safest_state: a.safest.as_ref().map(|s| SafestJson {
            h: s.x[0],
            v: s.x[1],
            w: s.x[2],
            margin: s.margin,
        }),
        message,
    }
}
