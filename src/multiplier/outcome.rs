//! What the load question answers: the static range, every limit state in it, and the
//! outcome at one (η, μ).

use crate::limit_states::sweep::CheckedPoint;
use crate::limit_states::LimitState;
use crate::statics::Reactions;
use crate::undecided::Undecided;

/// The admissible multipliers λ ≥ 0 at (η, μ).
#[derive(Debug, Clone, PartialEq)]
pub enum StaticRange {
    /// No state is admissible at any λ ≥ 0.
    NoEquilibrium,
    /// Admissible states exist for λ in [`min`, `max`] (`max` `None`: unbounded), each end
    /// with a state that attains it.
    Interval {
        /// The least admissible λ (0 when the arch stands unloaded) and a state there.
        min: (f64, Reactions),
        /// The largest admissible λ, λ_static, and a state there; `None` when unbounded.
        max: Option<(f64, Reactions)>,
    },
}

/// Where admissible states exist at every λ (λ_static unbounded) the sweep runs up to
/// this multiplier; states there have reactions far beyond the box of the sweep
/// (|x_k| ≤ 1e7), which bounds every state it follows.
pub const UNBOUNDED_SEARCH_TOP: f64 = 1e9;

/// Every limit state of a loaded discrete arch at (η, μ) with λ in [λ_min, λ_static].
#[derive(Debug, Clone)]
pub struct LoadSurvey {
    /// The least admissible multiplier (0 when the arch stands unloaded) and a state.
    pub lambda_min: (f64, Reactions),
    /// The largest admissible multiplier and a state there; `None` when admissible states
    /// exist at every λ ≥ λ_min (the search then runs up to [`UNBOUNDED_SEARCH_TOP`]).
    pub lambda_static: Option<(f64, Reactions)>,
    /// Whether some state at λ_static carries a mechanism with positive live power (the
    /// whole optimal face is decided, in the private module `multiplier::face`).
    pub mechanism_at_static: bool,
    /// Every limit state, ascending in λ (those at λ_static included when they exist); a
    /// continuum of limit states appears once, by its least state; a face of limit states
    /// at λ_static (all at one λ) once, by the centroid of its vertices with the contacts
    /// active on the whole face, `continuum_to` = λ_static.
    pub limit_states: Vec<LimitState>,
    /// Events of the sweep.
    pub events: usize,
    /// How the list was established: `sweep` (discrete arch: every event of P(λ)), `faces`
    /// (a discrete arch beyond the sweep's budget: every vertex of the admissible (x, λ) on
    /// which a sliding row is active) or `associative` (μ = ∞: the static maximum is the
    /// only limit state).
    pub method: &'static str,
    /// `sweep` only: every point the sweep checked whose active contacts carry no
    /// mechanism with positive live power (the evidence a certificate carries); empty
    /// otherwise.
    pub no_mechanism: Vec<CheckedPoint>,
}

impl LoadSurvey {
    /// The collapse multiplier: the least limit state's λ (`None`: no limit state at all,
    /// which the static maximum without a mechanism can leave).
    pub fn lambda(&self) -> Option<f64> {
        self.limit_states.first().map(|s| s.t)
    }
    /// Whether exactly one limit state exists (a continuum is not unique).
    pub fn unique(&self) -> bool {
        self.limit_states.len() == 1
            && self.limit_states[0]
                .continuum_to
                .is_none_or(|to| to <= self.limit_states[0].t)
    }
    /// 1 − λ/λ_static: how far non-associative friction lowers the collapse multiplier
    /// (1 when λ_static is unbounded and a limit state exists).
    pub fn reduction(&self) -> Option<f64> {
        let l = self.lambda()?;
        Some(self.lambda_static.map_or(1.0, |s| 1.0 - l / s.0))
    }
}

/// The answer to the load question at (η, μ).
#[derive(Debug, Clone)]
pub enum LoadOutcome {
    /// No state is admissible at any λ ≥ 0.
    NoEquilibrium,
    /// λ is unbounded and no limit state exists up to [`UNBOUNDED_SEARCH_TOP`]: the load
    /// never breaks the arch (the least admissible multiplier and a state there).
    NoCollapse {
        /// λ_min and a state there.
        lambda_min: (f64, Reactions),
        /// Events of the sweep.
        events: usize,
    },
    /// The static range and every limit state in it.
    Limits(LoadSurvey),
}

/// A load survey that reached no decision on its list of limit states, with what it decided
/// all the same: the ends of the static range where they were computed (each exact), and
/// the limit states found — on a continuous arch whose discretisations do not settle, each
/// carried over from one of them, refined and verified on the continuum (a limit state:
/// admissible over the arch, a mechanism with positive live power), and the states at
/// λ_static where they carry a mechanism (on a discrete arch whose sweep is beyond its
/// budget, those alone). Others may lie below them, so the collapse
/// multiplier is not decided: it is at most the least λ found.
#[derive(Debug, Clone)]
pub struct LoadUnsettled {
    /// Why the list of limit states is not established.
    pub why: Undecided,
    /// λ_min, where it was computed.
    pub lambda_min: Option<f64>,
    /// λ_static, where it was computed and is finite.
    pub lambda_static: Option<f64>,
    /// Whether the state at λ_static carries a mechanism with positive live power, where
    /// that was decided.
    pub mechanism_at_static: Option<bool>,
    /// The limit states found, ascending in λ (empty where none was, or where the survey
    /// stopped before its list).
    pub found: Vec<LimitState>,
    /// How many of `found`, the first ones, lie below λ_static by more than the resolution
    /// at which λ is decided (the rest are states at λ_static).
    pub below_static: usize,
}

/// A load survey's answer: decided, or what an undecided survey decided all the same.
pub type LoadAnswer = Result<LoadOutcome, LoadUnsettled>;

impl From<Undecided> for LoadUnsettled {
    fn from(why: Undecided) -> LoadUnsettled {
        LoadUnsettled {
            why,
            lambda_min: None,
            lambda_static: None,
            mechanism_at_static: None,
            found: Vec::new(),
            below_static: 0,
        }
    }
}

impl LoadUnsettled {
    /// The least λ found: the collapse multiplier is at most this.
    pub fn lambda_at_most(&self) -> Option<f64> {
        self.found.first().map(|s| s.t)
    }

    /// `Some(false)` where two distinct limit states were found (not unique, whatever the
    /// list misses); `None` otherwise (not decided).
    pub fn unique(&self) -> Option<bool> {
        (crate::limit_states::distinct(&self.found).len() >= 2).then_some(false)
    }

    /// 1 − λ/λ_static for the least λ found below λ_static: the collapse multiplier lies at
    /// least this far below the static maximum (`None`: none was found below it).
    pub fn reduction_at_least(&self) -> Option<f64> {
        let s = self.lambda_static?;
        (self.below_static > 0).then(|| 1.0 - self.found[0].t / s)
    }
}
