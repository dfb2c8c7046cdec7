//! What [`verify()`](super::verify) returns: the [`Report`] of what was proved and checked,
//! or the [`Rejection`] that names the first thing that does not hold.

use crate::certificate::format::{ArchSpec, Claim};

/// What `verify` proved or checked, for which arch and friction.
#[derive(Debug, Clone)]
pub struct Report {
    /// The claim that was proved.
    pub claim: Claim,
    /// μ (`None` = ∞).
    pub mu: Option<f64>,
    /// (η_lo, η_hi) of a least-thickness claim; `None` for no equilibrium.
    pub bracket: Option<(f64, f64)>,
    /// The arch the proof is about.
    pub arch: ArchSpec,
    /// One line per check that passed, each saying whether it was *proved* (interval
    /// arithmetic) or *checked* (floating point, evidence only).
    pub checks: Vec<String>,
    /// What the limit-state search lists (certificates with a `search` section).
    pub limit_states: Option<String>,
    /// Load certificates: the load in words.
    pub load: Option<String>,
    /// (λ_lo, λ_hi) of a largest-multiplier claim; for an unbounded multiplier, the λ from
    /// which states are proved admissible at every larger λ, and `None`.
    pub lambda_bracket: Option<(f64, Option<f64>)>,
}

impl Report {
    /// The arch in words: layout, springings, weight model.
    pub fn arch_text(&self) -> String {
        let a = &self.arch;
        let layout = match &a.joint_angles {
            None => "continuous".to_string(),
            Some(j) => format!("discrete ({} joints)", j.len()),
        };
        let fill = a.fill.map_or(String::new(), |f| {
            format!(
                ", with fill (weight ratio g_f = {}, road h = {} above the highest extrados point)",
                f.weight_ratio, f.depth
            )
        });
        format!(
            "{layout} arch, beta_right = {}, beta_left = {}, weight {}{fill}",
            a.beta_right,
            a.beta_left,
            a.weight.name()
        )
    }

    /// The proved statement, in one line.
    pub fn statement(&self) -> String {
        let mu = mu_text(self.mu);
        if let Some(load) = &self.load {
            return match (self.claim, self.lambda_bracket) {
                (Claim::LargestMultiplier, Some((lo, Some(hi)))) => format!(
                    "proved: for this arch at mu = {mu} under the {load}, lambda_static lies in [{lo}, {hi}] (relative gap {:.3e}; lambda_static = the largest multiplier with a statically admissible state)",
                    (hi - lo) / hi
                ),
                (Claim::UnboundedMultiplier, Some((lo, None))) => format!(
                    "proved: for this arch at mu = {mu} under the {load}, statically admissible states exist at every lambda >= {lo}: lambda_static is unbounded"
                ),
                _ => format!(
                    "proved: for this arch at mu = {mu} under the {load}, no state is statically admissible at any lambda >= 0"
                ),
            };
        }
        if self.claim == Claim::StandsAtEveryThickness {
            return format!(
                "proved: for this arch at mu = {mu}, a state is statically admissible at every thickness eta in (0, 2): eta* = 0, not attained (no least thickness)"
            );
        }
        match self.bracket {
            Some((lo, hi)) => format!(
                "proved: for this arch at mu = {mu}, eta* lies in [{lo}, {hi}] (relative gap {:.3e}; eta* = the least thickness with a statically admissible state)",
                (hi - lo) / hi
            ),
            None => format!(
                "proved: for this arch at mu = {mu}, no thickness stands (no statically admissible state at any eta)"
            ),
        }
    }
}

/// Why a certificate does not hold.
#[derive(Debug, Clone, PartialEq)]
pub struct Rejection(pub String);

pub(super) fn reject<T>(msg: impl Into<String>) -> Result<T, Rejection> {
    Err(Rejection(msg.into()))
}

/// "inf" for `None`, else the number.
pub(super) fn mu_text(mu: Option<f64>) -> String {
    mu.map_or("inf".into(), |m| m.to_string())
}
