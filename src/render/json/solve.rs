//! The `solve --json` document.

use super::common::{status, ArchJson, JSON_VERSION};
use super::state::{mechanism_with_rays, reactions, MechanismJson, Reactions};
use crate::contact::Contact;
use crate::limit::{Candidate, LeastLimitState, Outcome, Solution};
use crate::limit_states::{LimitState, LimitStates, Rays, Survey};
use schemars::JsonSchema;
use serde::Serialize;

/// The checks of the limit state at η_s: the static η of the LP, Newton's residual, the largest
/// activation over the arch, the LP's bracket of η_s.
#[derive(Debug, Serialize, JsonSchema)]
#[schemars(rename = "Checks")]
struct Checks {
    /// η_s of the static LPs (before Newton).
    eta_static: f64,
    /// The residual of the pattern's equations after Newton.
    newton_residual: f64,
    /// The largest activation φ over the arch (≤ 0 up to rounding: admissible).
    max_phi: f64,
    /// The LPs' bracket of η_s.
    eta_bracket: [f64; 2],
}

/// A pattern the enumeration tried (`--explain`).
#[derive(Debug, Serialize, JsonSchema)]
#[schemars(rename = "Candidate")]
struct CandidateJson {
    /// Its active contacts.
    pattern: Vec<Contact>,
    /// Whether its equations were solved.
    tried: bool,
    /// Its thickness, when solved.
    eta: Option<f64>,
    /// What became of it.
    verdict: String,
}

/// The least thickness η*(μ) and every limit state with η in [η_s, 2) (`solve`). `status` is
/// `ok` (answered), `no_equilibrium` (no thickness stands at this μ), `unresolved`
/// (`eta_bracket` holds what is known) or `no_collapse`; `message` says why when not ok.
/// `mode`, `pattern`, `reactions` and `mechanism` describe the least limit state.
#[derive(Debug, Serialize, JsonSchema)]
#[schemars(rename = "SolveResult")]
pub struct SolveJson {
    /// The document format's version (2).
    version: u32,
    /// `ok`, `no_equilibrium`, `unresolved` or `no_collapse`.
    status: &'static str,
    /// The arch.
    arch: ArchJson,
    /// The friction coefficient μ (`null`: ∞, no sliding).
    mu: f64,
    /// atan μ in degrees.
    friction_angle_deg: f64,
    /// η*(μ) = η_s, the least thickness ratio t/r at which the arch stands.
    #[serde(skip_serializing_if = "Option::is_none")]
    eta: Option<f64>,
    /// The collapse mode of the least limit state.
    #[serde(skip_serializing_if = "Option::is_none")]
    mode: Option<&'static str>,
    /// false when the mode name is a descriptive one outside the contract's list
    #[serde(skip_serializing_if = "Option::is_none")]
    mode_standard: Option<bool>,
    /// The active contacts of the least limit state.
    #[serde(skip_serializing_if = "Option::is_none")]
    pattern: Option<Vec<Contact>>,
    /// The reactions of the least limit state.
    #[serde(skip_serializing_if = "Option::is_none")]
    reactions: Option<Reactions>,
    /// The mechanism of the least limit state, with the extreme rays of its cone.
    #[serde(skip_serializing_if = "Option::is_none")]
    mechanism: Option<MechanismJson>,
    /// The checks of the least limit state.
    #[serde(skip_serializing_if = "Option::is_none")]
    checks: Option<Checks>,
    /// μ_ms, the least friction at which some thickness stands (with `no_equilibrium`).
    #[serde(skip_serializing_if = "Option::is_none")]
    mu_ms: Option<f64>,
    /// What is known of η_s when it is `unresolved`: [lower, upper].
    #[serde(skip_serializing_if = "Option::is_none")]
    eta_bracket: Option<[f64; 2]>,
    /// Why there is no answer (status not `ok`).
    #[serde(skip_serializing_if = "Option::is_none")]
    message: Option<String>,
    /// With `--explain`: the patterns the enumeration tried.
    #[serde(skip_serializing_if = "Option::is_none")]
    candidates: Option<Vec<CandidateJson>>,
    /// Whether η_s is attained by a bounded state.
    #[serde(skip_serializing_if = "Option::is_none")]
    attained: Option<bool>,
    /// Whether the least admissible state carries a non-associative mechanism.
    #[serde(skip_serializing_if = "Option::is_none")]
    mechanism_at_eta: Option<bool>,
    /// Whether exactly one limit state has η in [η_s, 2) (`null`: search not completed;
    /// `false` also when it was not completed but two limit states were found).
    #[serde(skip_serializing_if = "Option::is_none")]
    unique: Option<Option<bool>>,
    /// Every limit state with η in [η_s, 2), ascending (with `search.complete` false: the
    /// ones found, each verified; others may exist).
    #[serde(skip_serializing_if = "Option::is_none")]
    limit_states: Option<Vec<LimitStateJson>>,
    /// How the limit states were searched.
    #[serde(skip_serializing_if = "Option::is_none")]
    search: Option<SearchJson>,
    /// At μ = μ_ms: the purely sliding limit states of every η ≥ η_s.
    #[serde(skip_serializing_if = "Option::is_none")]
    vertical_branch: Option<VerticalJson>,
    /// The fill (an arch with fill only).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub fill: Option<super::bridge::FillJson>,
    /// With fill: the scan of the thickness range ([`crate::limit::filled`]).
    #[serde(skip_serializing_if = "Option::is_none")]
    thickness_scan: Option<ScanJson>,
}

/// The scan of the thickness range of an arch with fill: `interval` when every scanned η
/// above the lowest admissible one is admissible too, else the inadmissible ones (`gaps`).
#[derive(Debug, Serialize, JsonSchema)]
#[schemars(rename = "ThicknessScan")]
struct ScanJson {
    /// The thicknesses scanned.
    nodes: usize,
    /// The least η scanned.
    eta_from: f64,
    /// The largest η scanned.
    eta_to: f64,
    /// The least admissible η scanned (absent: none).
    lowest_admissible: Option<f64>,
    /// Whether every scanned η above the lowest admissible one is admissible too.
    interval: bool,
    /// The inadmissible η above the lowest admissible one.
    gaps: Vec<f64>,
}

fn scan_json(s: &crate::limit::filled::ThicknessScan) -> ScanJson {
    let gaps = s.gaps();
    ScanJson {
        nodes: s.etas.len(),
        eta_from: s.etas[0],
        eta_to: s.etas[s.etas.len() - 1],
        lowest_admissible: s.lowest().map(|i| s.etas[i]),
        interval: gaps.is_empty(),
        gaps,
    }
}

/// The vertical branch at μ = μ_ms: from `eta_min` up, every admissible state is a limit
/// state with the purely sliding mechanism on `pattern`.
#[derive(Debug, Serialize, JsonSchema)]
#[schemars(rename = "VerticalBranch")]
struct VerticalJson {
    /// The least thickness of the branch (η_s).
    eta_min: f64,
    /// Its mode (purely sliding).
    mode: &'static str,
    /// The sliding contacts.
    pattern: Vec<Contact>,
}

/// A limit state: an admissible state whose active contacts carry a mechanism.
#[derive(Debug, Serialize, JsonSchema)]
#[schemars(rename = "LimitState")]
struct LimitStateJson {
    /// Its thickness ratio η.
    eta: f64,
    /// Its collapse mode.
    mode: &'static str,
    /// Its active contacts.
    pattern: Vec<Contact>,
    /// Its reactions.
    reactions: Reactions,
    /// Its mechanism.
    mechanism: MechanismJson,
}

/// How every limit state above η_s was searched (`complete`: all were found).
#[derive(Debug, Serialize, JsonSchema)]
#[schemars(rename = "Search")]
struct SearchJson {
    /// Whether the search is complete: every limit state in [η_s, 2) is listed.
    complete: bool,
    /// `ridge`, `sweep` or the like.
    method: Option<String>,
    /// The points the search checked.
    events: Option<usize>,
    /// Why the search could not be completed.
    #[serde(skip_serializing_if = "Option::is_none")]
    reason: Option<String>,
}

fn limit_parts(
    ls: &LeastLimitState,
    rays: &[Vec<f64>],
) -> (Vec<Contact>, Reactions, MechanismJson, Checks) {
    (
        ls.pattern.clone(),
        reactions(&ls.x),
        mechanism_with_rays(&ls.mechanism, rays),
        Checks {
            eta_static: ls.eta_static,
            newton_residual: ls.newton_residual,
            max_phi: ls.max_phi,
            eta_bracket: [ls.bracket.0, ls.bracket.1],
        },
    )
}

/// Builds the `solve --json` document from the solution and the search for every limit
/// state (`rays`: the extreme rays of each mechanism, [`Survey::rays`]); `explain` adds the
/// enumeration log.
pub fn solve(survey: &Survey, explain: bool, rays: &Rays) -> SolveJson {
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
        vertical_branch: None,
        fill: None,
        thickness_scan: sol.scan.as_ref().map(scan_json),
    };
    with_outcome(&mut doc, &sol.outcome, rays);
    match &survey.states {
        Ok(s) => with_limit_states(&mut doc, survey, s, rays),
        Err(reason) => {
            doc.search = Some(SearchJson {
                complete: false,
                method: None,
                events: None,
                reason: Some(reason.to_string()),
            });
            if let Outcome::Limit(ls) = &sol.outcome {
                // not complete, but two limit states found decide `false`: the ones found
                // are listed (`search.complete` stays false)
                doc.unique = Some(survey.unique());
                if survey.unique() == Some(false) {
                    let at_eta_s = survey.limit_at_eta_s().is_some();
                    doc.mechanism_at_eta = Some(at_eta_s);
                    doc.limit_states = Some(listed(at_eta_s, sol, &survey.found, rays));
                }
                // `eta` is η_s, decided whatever the search above it says; where the
                // least admissible state carries no mechanism (a non-associative gap), the
                // limit state described is the least one found above it
                doc.eta = Some(ls.eta_static);
                if ls.eta_static < ls.eta {
                    doc.mechanism_at_eta = Some(false);
                }
                // an infimum: the state found at η_s has unbounded reactions and is no
                // limit state (its "mechanism" balances no finite thrust)
                if !ls.attained {
                    doc.attained = Some(false);
                    doc.mechanism_at_eta = Some(false);
                    doc.mode = None;
                    doc.mode_standard = None;
                    doc.pattern = None;
                    doc.reactions = None;
                    doc.mechanism = None;
                }
            }
        }
    }
    doc
}

/// What the solver found at η_s: the limit state, or the message and the numbers that say
/// why there is none.
fn with_outcome(doc: &mut SolveJson, outcome: &Outcome, rays: &Rays) {
    match outcome {
        Outcome::Limit(ls) => {
            let (p, r, m, c) = limit_parts(ls, rays.least.as_deref().unwrap_or_default());
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
}

/// Every limit state with η in [η_s, 2), found by a completed search: the decided answer.
fn with_limit_states(doc: &mut SolveJson, survey: &Survey, s: &LimitStates, rays: &Rays) {
    let sol = &survey.solution;
    let above_rays = |k: usize| rays.above.get(k).map_or(&[][..], Vec::as_slice);
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
    let all = listed(s.mechanism_at_eta_s, sol, &s.above, rays);
    // the top-level mode, pattern, reactions and mechanism are the least limit
    // state's (none when there is none)
    if !s.mechanism_at_eta_s {
        let least = s.above.first();
        doc.mode = least.map(|a| a.mode.name());
        doc.mode_standard = least.map(|a| a.mode.is_standard());
        doc.pattern = least.map(|a| a.pattern.clone());
        doc.reactions = least.map(|a| reactions(&a.x));
        doc.mechanism = least.map(|a| mechanism_with_rays(&a.mechanism, above_rays(0)));
        doc.checks = None;
    }
    doc.limit_states = Some(all);
    doc.vertical_branch = s.vertical.as_ref().map(|p| VerticalJson {
        eta_min: s.eta_s,
        mode: crate::collapse_mode::CollapseMode::PurelySliding.name(),
        pattern: p.clone(),
    });
    doc.search = Some(SearchJson {
        complete: true,
        method: Some(s.method.clone()),
        events: Some(s.events),
        reason: None,
    });
}

/// The limit states listed: the least state's where it carries a mechanism, then those
/// above η_s.
fn listed(
    mechanism_at_eta_s: bool,
    sol: &Solution,
    above: &[LimitState],
    rays: &Rays,
) -> Vec<LimitStateJson> {
    let least_rays = rays.least.as_deref().unwrap_or_default();
    let above_rays = |k: usize| rays.above.get(k).map_or(&[][..], Vec::as_slice);
    let mut all = Vec::new();
    if let (true, Outcome::Limit(ls)) = (mechanism_at_eta_s, &sol.outcome) {
        all.push(LimitStateJson {
            eta: ls.eta,
            mode: ls.mode.name(),
            pattern: ls.pattern.clone(),
            reactions: reactions(&ls.x),
            mechanism: mechanism_with_rays(&ls.mechanism, least_rays),
        });
    }
    all.extend(above.iter().enumerate().map(|(k, a)| LimitStateJson {
        eta: a.t,
        mode: a.mode.name(),
        pattern: a.pattern.clone(),
        reactions: reactions(&a.x),
        mechanism: mechanism_with_rays(&a.mechanism, above_rays(k)),
    }));
    all
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
