//! Every tolerance and work limit of the solver, with documented defaults.
//!
//! Activation functions φ are measured in units of γ t d r² (moments) or γ t d r
//! (forces); all tolerances below are relative to the problem's own magnitude
//! `scale` = max(1, ‖x‖) · span, unless said otherwise, so that shallow arches
//! with η* ~ 1e-3 are treated as carefully as deep ones.

/// Which solver answers the static margin LP.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum LpBackend {
    /// The 4-variable revised simplex of [`crate::lp::dense`] (fast path), falling back to
    /// HiGHS if it reports a failure.
    Dense,
    /// HiGHS through good_lp (reference path).
    Highs,
}

/// Solver settings. `Settings::default()` is what the CLI uses.
#[derive(Debug, Clone, PartialEq)]
pub struct Settings {
    /// Static admissibility: a state is admissible when every φ ≤ `adm_tol` times
    /// its natural magnitude ([`crate::statics::magnitude`]) over the whole arch.
    /// Default 1e-12.
    pub adm_tol: f64,
    /// Smallest factor used by [`crate::statics::magnitude`]: below η (or μ) of this
    /// size tolerances stop shrinking with η, because the rounding error of M, N, T
    /// does not. Default 1e-3.
    pub magnitude_floor: f64,
    /// Constraint generation stops when the continuum violation exceeds the working
    /// set's by at most `sep_tol` · scale. Default 1e-13.
    pub sep_tol: f64,
    /// Number of equally spaced samples per activation function used to seed the
    /// 1-D maximisation over a continuous arch (each local maximum is then refined
    /// by Newton on dφ/dβ = 0). Default 96.
    pub scan_points: usize,
    /// Bracketing of η* stops when the bracket is narrower than `bracket_rel` · η.
    /// Default 1e-8.
    pub bracket_rel: f64,
    /// A local maximum of φ is a candidate active contact when its slack is below
    /// `candidate_rel` · scale at the upper end of the bracket. Default 1e-5.
    pub candidate_rel: f64,
    /// At most this many candidate contacts enter the enumeration. Default 8.
    pub max_candidates: usize,
    /// Newton on a pattern's square system stops when the scaled residual is below
    /// `newton_tol`. Default 1e-14.
    pub newton_tol: f64,
    /// Newton iteration limit. Default 40.
    pub newton_max_iter: usize,
    /// Two contacts at angles closer than this (radians) are the same joint. Default 1e-7.
    pub same_joint: f64,
    /// Feasibility and optimality tolerances passed to HiGHS. Default 1e-10.
    pub lp_tol: f64,
    /// Feasibility tolerance of the dense margin simplex, on rows normalised to unit
    /// gradient. Default 1e-13.
    pub dense_lp_tol: f64,
    /// Maximum constraint-generation rounds per LP. Default 60.
    pub max_rounds: usize,
    /// Solver of the static margin LP. Default [`LpBackend::Dense`].
    pub lp_backend: LpBackend,
    /// Number of μ samples used to discover the branches of the limit curve. Default 16.
    pub curve_samples: usize,
    /// A rate below `rate_tol` (rates sum to 1) counts as zero. Default 1e-10.
    pub rate_tol: f64,
}

impl Default for Settings {
    fn default() -> Self {
        Settings {
            adm_tol: 1e-12,
            magnitude_floor: 1e-3,
            sep_tol: 1e-13,
            scan_points: 96,
            bracket_rel: 1e-8,
            candidate_rel: 1e-5,
            max_candidates: 8,
            newton_tol: 1e-14,
            newton_max_iter: 40,
            same_joint: 1e-7,
            lp_tol: 1e-10,
            dense_lp_tol: 1e-13,
            max_rounds: 60,
            rate_tol: 1e-10,
            curve_samples: 16,
            lp_backend: LpBackend::Dense,
        }
    }
}
