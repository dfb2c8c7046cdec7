//! What the thickness search returns: the verified limit state, the outcome at one μ,
//! and the log of every pattern tried.

use crate::arch::Arch;
use crate::collapse_mode::CollapseMode;
use crate::contact::Contact;
use crate::mechanism::Mechanism;
use crate::statics::Reactions;

/// A verified limit state (incipient collapse) at friction μ.
#[derive(Debug, Clone)]
pub struct LeastLimitState {
    /// Friction coefficient μ (∞ allowed).
    pub mu: f64,
    /// The least thickness ratio η*(μ).
    pub eta: f64,
    /// The least η with a statically admissible state. Equal to `eta` unless that
    /// state carries no mechanism without dilatancy (non-associative gap), in which
    /// case the limit state lies above it.
    pub eta_static: f64,
    /// The least admissible state at `eta_static` (equal to `x` when there is no gap).
    pub x_static: Reactions,
    /// Reactions x = (h, v, w) at the right springing.
    pub x: Reactions,
    /// The active pattern: every contact with φ = 0 at this state, by increasing β.
    pub pattern: Vec<Contact>,
    /// The collapse mode named from the pattern.
    pub mode: CollapseMode,
    /// A mechanism on the pattern.
    pub mechanism: Mechanism,
    /// Newton residual of the pattern's system (scaled).
    pub newton_residual: f64,
    /// Greatest φ over the whole arch relative to its magnitude (≤ `adm_tol`).
    pub max_phi: f64,
    /// The relative rounding error to expect in `eta` and `eta_static` from evaluating the
    /// hinge conditions in double precision ([`crate::statics::eta_rounding`]): about
    /// 1e-15 on ordinary arches, 1e-6 on a segment of 2° (η ~ 2e-9).
    pub eta_rounding: f64,
    /// Whether η_s is attained by a bounded state (`x_static` within
    /// `settings.unbounded_reactions` × (1 + span)). When false η_s is an infimum
    /// approached as the reactions grow without bound, and the state at η_s (reactions of
    /// 1e6 and more, with its "mechanism") is no limit state: none exists at η_s.
    pub attained: bool,
    /// The bracket [η_lo, η_hi] found before refinement: at η_hi a state was verified
    /// admissible over the whole arch; η_lo was judged infeasible by the LP (to
    /// HiGHS's tolerance, so for very shallow arches η* may lie slightly below it).
    pub bracket: (f64, f64),
}

/// What the solver found at one μ.
#[derive(Debug, Clone)]
pub enum Outcome {
    /// A verified limit state.
    Limit(LeastLimitState),
    /// No thickness η < 2 admits equilibrium.
    NoEquilibrium {
        /// The least friction coefficient that admits equilibrium at some
        /// (unbounded) thickness, when μ is below it.
        mu_ms: Option<f64>,
        /// Why, in words.
        reason: String,
    },
    /// Every thickness η > 0 admits equilibrium: there is no collapse to find (e.g. a
    /// discrete arch with at most three joints, which is statically determinate).
    NoCollapse {
        /// Why, in words.
        reason: String,
    },
    /// The solver could not verify a limit state; η* lies in the bracket.
    Unresolved {
        /// Lower end of the bracket (no admissible state).
        eta_lo: f64,
        /// Upper end of the bracket (admissible state).
        eta_hi: f64,
        /// What failed.
        reason: String,
        /// The least admissible state (η_s, x_s), when it was found (refined and verified)
        /// but no limit state was.
        least_static: Option<(f64, Reactions)>,
    },
}

/// One enumerated pattern and what became of it (for `solve --explain`).
#[derive(Debug, Clone)]
pub struct Candidate {
    /// The contacts of the pattern, as started.
    pub contacts: Vec<Contact>,
    /// Refined η, when Newton converged.
    pub eta: Option<f64>,
    /// False when the pattern was skipped (a limit state at the static least thickness
    /// had already been verified); true when Newton was run on it.
    pub tried: bool,
    /// Kept or rejected, and why.
    pub verdict: String,
}

/// The answer of [`solve`](crate::limit::solve): the outcome and the enumeration log.
#[derive(Debug, Clone)]
pub struct Solution {
    /// The arch solved.
    pub arch: Arch,
    /// Friction coefficient μ.
    pub mu: f64,
    /// The outcome.
    pub outcome: Outcome,
    /// Every pattern tried, in the order verified.
    pub candidates: Vec<Candidate>,
    /// At μ = μ_ms (to its rounding, [`crate::limit::MU_MS_ROUNDING`]) with a limit state:
    /// the sliding contacts of the friction limit, whose purely sliding mechanism (checked
    /// by the limit-state search) makes every admissible state a limit state: the vertical
    /// branch, for every η ≥ η_s.
    pub vertical: Option<Vec<Contact>>,
    /// With fill: the scan of the thickness range that bracketed η_s, and whether its
    /// admissible thicknesses form an interval ([`crate::limit::filled`]).
    pub scan: Option<crate::limit::filled::ThicknessScan>,
}
