//! The JSON shapes of the command-line contract (`shared/spec/cli.md`).
//! Angles in radians; `null` stands for +∞.

use crate::arch::{Arch, JointLayout};
use crate::contact::Contact;
use crate::limit::{Candidate, LimitState, Outcome, Solution};
use crate::limit_curve::{CurvePoint, CurveStatus};
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
struct Reactions {
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
struct MechanismJson {
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
        Reactions {
            h: ls.x[0],
            v: ls.x[1],
            w: ls.x[2],
        },
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
        },
        Checks {
            eta_static: ls.eta_static,
            newton_residual: ls.newton_residual,
            max_phi: ls.max_phi,
            eta_bracket: [ls.bracket.0, ls.bracket.1],
        },
    )
}

/// Builds the `solve --json` document; `explain` adds the enumeration log.
pub fn solve(sol: &Solution, explain: bool) -> SolveJson {
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
    pattern: Vec<Contact>,
    between: [&'static str; 2],
    mode: &'static str,
    exact: bool,
    residual: f64,
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
    corners: Vec<CornerJson>,
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
        branches: curve
            .branches
            .iter()
            .map(|b| BranchJson {
                mode: b.mode.name(),
                mode_standard: b.mode.is_standard(),
                mu_min: b.mu_min,
                mu_max: b.mu_max,
                eta_min: b.eta_min,
                eta_max: b.eta_max,
                pattern: b.pattern.clone(),
            })
            .collect(),
        corners: curve
            .corners
            .iter()
            .map(|c| CornerJson {
                mu: c.mu,
                friction_angle_deg: c.mu.atan().to_degrees(),
                eta: c.eta,
                pattern: c.joints.clone(),
                between: c.between.map(|m| m.name()),
                mode: c.mode.name(),
                exact: c.exact,
                residual: c.residual,
            })
            .collect(),
        mu_min: curve.mu_ms,
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
