//! Every tolerance and work limit of the solver, with documented defaults.
//!
//! Activation functions φ are measured in units of γ t d r² (moments) or γ t d r
//! (forces), and the reactions x = (h, v, w) in units of γ t d r. Each field says what
//! its tolerance is relative to; the scales used are
//!
//! * the size of a state, 1 + ‖x‖₁ ([`crate::statics::reaction_scale`]);
//! * the natural magnitude of an activation function, that size times max(η,
//!   `magnitude_floor`) for a hinge or max(min(μ, 1), `magnitude_floor`) for sliding
//!   ([`crate::statics::magnitude`]), so that shallow arches with η* ~ 1e-3 are treated as
//!   carefully as deep ones;
//! * η, μ or λ itself for a relative tolerance on a root;
//! * radians for angles.
//!
//! Each default is written in its field's documentation and in `Default`; a unit test
//! checks that the two agree.

use crate::arch::{fmt_value, InputError};

/// Which solver answers the static margin LP.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum LpBackend {
    /// The 4-variable revised simplex of [`crate::lp::dense`] (fast path), falling back to
    /// HiGHS if it reports a failure.
    Dense,
    /// HiGHS through good_lp (reference path).
    Highs,
}

/// How the limit states above η_s are searched where both methods apply (a discrete arch,
/// or a continuous arch's discretisations, with the centreline weight at finite μ).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum LimitStateSearch {
    /// The walk along the ridge over the friction polygon ([`crate::limit_states::ridge`])
    /// where P(η) has an interior point just above η_s; the sweep otherwise.
    Ridge,
    /// The sweep of P(η) in η ([`crate::limit_states::sweep`]) always: the reference, and
    /// the method whose checked points a certificate carries.
    Sweep,
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
    /// set's by at most `sep_tol` × (1 + ‖x‖₁). Default 1e-13.
    pub sep_tol: f64,
    /// Number of equally spaced samples per activation function used to seed the
    /// 1-D maximisation over a continuous arch (each local maximum is then refined
    /// by Newton on dφ/dβ = 0). Default 96.
    pub scan_points: usize,
    /// Bracketing of η* stops when the bracket is narrower than `bracket_rel` · η.
    /// Default 1e-8.
    pub bracket_rel: f64,
    /// A local maximum of φ is a candidate active contact when its normalised slack
    /// (distance to the plane) is within `candidate_rel` × (1 + ‖x‖₁) of the LP margin at
    /// the upper end of the bracket. Default 1e-5.
    pub candidate_rel: f64,
    /// At most this many candidate contacts enter the enumeration. Default 8.
    pub max_candidates: usize,
    /// Newton on a pattern's square system stops when the residual ‖F‖∞ scaled by
    /// 1 + ‖x‖₁ is below `newton_tol`. Default 1e-14.
    pub newton_tol: f64,
    /// Newton iteration limit. Default 40.
    pub newton_max_iter: usize,
    /// The one "same joint" threshold: within one state, two contacts at angles closer
    /// than this (radians) are at the same joint (a detached joint with both hinges
    /// active, a springing that hinges and slides, mirror images of a symmetric pattern).
    /// Default 1e-7.
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
    /// Relative singular-value threshold for the rank of a compatibility matrix B (the
    /// dimension of the mechanism cone, rank-deficient kinematic LPs). Default 1e-10.
    pub rank_tol: f64,
    /// Singular values of the Newton Jacobian below `svd_cutoff` × the largest are treated
    /// as zero in the least-squares step. Default 1e-13.
    pub svd_cutoff: f64,
    /// The same, for the least-squares estimate of KKT multipliers. Default 1e-12.
    pub multiplier_cutoff: f64,
    /// Newton that stagnates at a residual below `newton_accept` (scaled, like
    /// `newton_tol`) has converged to the rounding level. Default 1e-11.
    pub newton_accept: f64,
    /// A refined root (η or μ) may lie this far (relative) beyond the end of its LP
    /// bracket that carries a verified admissible state: the LP decides only to its
    /// tolerance. Farther out it is another root. Default 1e-9.
    pub root_slack: f64,
    /// Two refined values of η or μ closer than this (relative) are the same root; the
    /// resolution of the limit-state sweep's roots in η or λ (relative to 1 + |t|), and of
    /// the order of limit states (mirror images share η to this). Default 1e-12.
    pub same_root: f64,
    /// Within this relative distance above μ_ms the LP cannot decide admissibility and
    /// the solver says so instead of answering. Default 1e-6.
    pub mu_ms_resolution: f64,
    /// A joint whose N is below `detach_rel` × (1 + ‖x‖₁) is detached (N = 0): it can
    /// carry no friction. Default 1e-9.
    pub detach_rel: f64,
    /// The limit curve is sampled from μ_ms (1 + `curve_start_rel`). Default 1e-5.
    pub curve_start_rel: f64,
    /// Two contacts of the same kind and location in neighbouring samples of the limit
    /// curve whose angles differ by less than this (radians) are the same contact moving
    /// along the branch (patterns are tracked, not compared exactly: interior joints move
    /// with μ). Not a "same joint" test within one state: that is `same_joint`.
    /// Default 0.05.
    pub track_angle: f64,
    /// The limit-state sweep is not run below this η_s (its roots in η are resolved to
    /// about 1e-12 absolute). Default 1e-6.
    pub sweep_min_eta: f64,
    /// A least admissible state whose reactions exceed this multiple of 1 + span (the
    /// arch's weight) is taken as unbounded: η_s is then an infimum, not attained.
    /// Default 1e6.
    pub unbounded_reactions: f64,
    /// A continuous arch's limit states are searched on discretisations of this many and
    /// twice as many equal pieces (then refined on the continuum). Default 48.
    pub sweep_pieces: usize,
    /// The pieces are doubled at most this many times: where two consecutive
    /// discretisations' refined limit states differ (a branch of limit states that the
    /// coarser one misses, near where the branch is born or dies), the next is tried until
    /// two agree. 1: `sweep_pieces` and twice as many only. Default 3 (up to 8 ×
    /// `sweep_pieces`; a discretisation the ridge does not walk stops at the sweep's
    /// budget, `sweep_max_joints`).
    pub sweep_doublings: usize,
    /// A discretisation of J pieces misses a continuous arch's limit state where μ lies
    /// within its discretisation error of where the state's branch is born or dies (its
    /// own branch ends a little before or after, by O(1/J²) relative): the coarsest
    /// discretisation (and a finer one where its list does not settle without it, or where
    /// the previous shifted search was narrowed or failed, near μ_ms) is therefore also searched at μ (1 ∓ `carry_shift` / J²) (the lower shift quartered, at most
    /// twice, where that search fails), and every state found there is carried to μ
    /// (Newton on the continuum at μ, then checked there). 0: only at μ. Default 8
    /// (0.35 % at 48 pieces, 0.087 % at 96; on the 22 branch ends of the 46-column atlas
    /// where a contact reaches its limit, 1 already finds every state missed at μ).
    pub carry_shift: f64,
    /// A discretisation's branch of limit states can also end by losing its mechanism a
    /// little before the continuum's does (where a contact lies between joints, by an
    /// erratic amount): a point of the ridge with four active contacts whose rates have
    /// one of the other sign, of at most this fraction of the largest, is carried to the
    /// continuum as well (Newton, then checked there). 0: none. Default 0.2.
    pub carry_almost_rate: f64,
    /// The complete limit-state sweep of a discrete arch (work growing faster than the
    /// square of the number of joints) is run up to this many joints; beyond, the search
    /// is reported as not done (η_s and λ_static stay exact). Default 256 (a 255-voussoir
    /// arch takes about a second at finite friction).
    pub sweep_max_joints: usize,
    /// The same budget for the sweep in λ of a live load at fixed η, whose vertices move
    /// along straight lines (degree 1 in λ, against up to 5 in η), so that it costs about
    /// what the sweep in η costs at half the joints. Default 512 (511 voussoirs under a
    /// horizontal load take about 1.6 s, under a point load 0.3 s).
    pub load_sweep_max_joints: usize,
    /// Beyond `load_sweep_max_joints`, the limit states of a live load are searched by the
    /// vertices of the admissible (x, λ) on which a sliding row is active (the face search,
    /// docs/design/load-limit-states-on-the-seam.md §5: work about the square of the
    /// number of joints) up to this many joints; beyond, not at all. Default 4096.
    pub load_face_max_joints: usize,
    /// The ridge walk over the friction polygon (in chunks, each with the joints proved
    /// near it: work about linear in the number of joints) is run up to this many joints;
    /// beyond, the sweep's budget decides. Default 16384 (10⁴ joints take about 0.3 s).
    pub ridge_max_joints: usize,
    /// A contact is active at an event of the limit-state sweep when |φ| is below
    /// `event_tol` × its natural magnitude; a point of the sweep lies on a plane, or
    /// inside it, to `event_tol` × (1 + ‖x‖₁), and two vertices meet at one point when
    /// their coordinates agree to that or to `event_tol` × (1 + |x_k|). Default 1e-9.
    pub event_tol: f64,
    /// Joints added to the constraint-generation working set closer than this (radians)
    /// to one already there are not added again. Default 1e-10.
    pub working_set_gap: f64,
    /// The one-sided slopes dη_s/dμ at a pattern change of the limit curve are taken from
    /// η_s at μ(1 ± δ) and μ(1 ± 2δ) (second-order differences) with δ this. Default 1e-6.
    pub slope_step: f64,
    /// A pattern change is a corner (a kink of η_s(μ)) when its one-sided slopes differ by
    /// more than this fraction of max(|slopes|, η/μ); else a smooth transition.
    /// Default 1e-3 (smooth changes agree to ~1e-6 with the default `slope_step`; corners
    /// differ by O(1)).
    pub kink_slope_rel: f64,
    /// A located pattern change of the limit curve stands only where its η equals, to
    /// this relative difference, η_s extrapolated to its μ from either side (see
    /// `slope_step`; the extrapolation is second order, so ~δ² ≈ 1e-12 on a smooth side).
    /// Default 1e-9.
    pub boundary_match: f64,
    /// How limit states above η_s are searched. Default `Ridge`.
    pub limit_state_search: LimitStateSearch,
    /// Where the least admissible state is degenerate (P(η_s) not a point) or P has an
    /// interior at the start, the limit-state sweep starts from every vertex of P at
    /// η_s (1 + `sweep_walk_offset`) (a load sweep: at λ_min + `sweep_walk_offset` ×
    /// min(λ_static − λ_min, 1 + λ_min)), found by a walk: limit states between the least
    /// state and that start are not searched. Default 1e-6.
    pub sweep_walk_offset: f64,
    /// Two limit states found by different routes (the refined states of a continuous
    /// arch's two discretisations, the candidates of the ridge walk) are the same only when
    /// their η agree to this (relative). Default 1e-9.
    pub same_state_eta: f64,
    /// Two refined limit states of a continuous arch's two discretisations are the same
    /// only when their contacts have the same kinds at angles that agree to this
    /// (radians), and their η to `same_state_eta`. Default 1e-6.
    pub same_state_angle: f64,
    /// Two candidates of the ridge walk are the same limit state only when their
    /// reactions agree to this × (1 + ‖x‖₁), and their η to `same_state_eta`.
    /// Default 1e-7.
    pub same_state_x: f64,
    /// Where η_s is an infimum (the least admissible state unbounded), the exact least η of
    /// a weightless admissible direction ([`crate::limit::recession`]) replaces the η_s
    /// found when it lies within this (relative) of it. Default 1e-6.
    pub infimum_rel: f64,
    /// A contact admits a weightless direction d when g·d ≤ `recession_tol` |g| |d|
    /// (g the gradient of its activation function). Default 1e-10.
    pub recession_tol: f64,
    /// The contacts from which the exact least η of a weightless direction d is solved are
    /// those tight at d: g·d ≥ −`recession_candidate_rel` |g| |d| (|d|∞ for a discrete
    /// arch). Default 1e-6.
    pub recession_candidate_rel: f64,
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
            rank_tol: 1e-10,
            svd_cutoff: 1e-13,
            multiplier_cutoff: 1e-12,
            newton_accept: 1e-11,
            root_slack: 1e-9,
            same_root: 1e-12,
            mu_ms_resolution: 1e-6,
            detach_rel: 1e-9,
            curve_start_rel: 1e-5,
            track_angle: 0.05,
            working_set_gap: 1e-10,
            slope_step: 1e-6,
            kink_slope_rel: 1e-3,
            boundary_match: 1e-9,
            event_tol: 1e-9,
            sweep_pieces: 48,
            sweep_doublings: 3,
            carry_shift: 8.0,
            carry_almost_rate: 0.2,
            sweep_max_joints: 256,
            load_sweep_max_joints: 512,
            load_face_max_joints: 4096,
            ridge_max_joints: 16384,
            unbounded_reactions: 1e6,
            sweep_min_eta: 1e-6,
            curve_samples: 16,
            lp_backend: LpBackend::Dense,
            limit_state_search: LimitStateSearch::Ridge,
            sweep_walk_offset: 1e-6,
            same_state_eta: 1e-9,
            same_state_angle: 1e-6,
            same_state_x: 1e-7,
            infimum_rel: 1e-6,
            recession_tol: 1e-10,
            recession_candidate_rel: 1e-6,
        }
    }
}

impl Settings {
    /// Checks every field against its valid range; the error names the field
    /// (`settings.<name>`), the range and the value.
    pub fn validate(&self) -> Result<(), InputError> {
        let unit = |name: &'static str, v: f64| -> Result<(), InputError> {
            if v.is_finite() && v > 0.0 && v < 1.0 {
                Ok(())
            } else {
                Err(InputError::OutOfRange {
                    arg: name,
                    value: fmt_value(v),
                    range: "0 < value < 1".into(),
                })
            }
        };
        let count = |name: &'static str, v: usize, lo: usize, hi: usize| {
            if (lo..=hi).contains(&v) {
                Ok(())
            } else {
                Err(InputError::OutOfRange {
                    arg: name,
                    value: v.to_string(),
                    range: format!("whole numbers {lo} to {hi}"),
                })
            }
        };
        for (name, v) in [
            ("settings.adm_tol", self.adm_tol),
            ("settings.magnitude_floor", self.magnitude_floor),
            ("settings.sep_tol", self.sep_tol),
            ("settings.bracket_rel", self.bracket_rel),
            ("settings.candidate_rel", self.candidate_rel),
            ("settings.newton_tol", self.newton_tol),
            ("settings.newton_accept", self.newton_accept),
            ("settings.same_joint", self.same_joint),
            ("settings.lp_tol", self.lp_tol),
            ("settings.dense_lp_tol", self.dense_lp_tol),
            ("settings.rate_tol", self.rate_tol),
            ("settings.rank_tol", self.rank_tol),
            ("settings.svd_cutoff", self.svd_cutoff),
            ("settings.multiplier_cutoff", self.multiplier_cutoff),
            ("settings.root_slack", self.root_slack),
            ("settings.same_root", self.same_root),
            ("settings.mu_ms_resolution", self.mu_ms_resolution),
            ("settings.detach_rel", self.detach_rel),
            ("settings.curve_start_rel", self.curve_start_rel),
            ("settings.track_angle", self.track_angle),
            ("settings.working_set_gap", self.working_set_gap),
            ("settings.event_tol", self.event_tol),
            ("settings.sweep_min_eta", self.sweep_min_eta),
            ("settings.slope_step", self.slope_step),
            ("settings.kink_slope_rel", self.kink_slope_rel),
            ("settings.boundary_match", self.boundary_match),
            ("settings.sweep_walk_offset", self.sweep_walk_offset),
            ("settings.same_state_eta", self.same_state_eta),
            ("settings.same_state_angle", self.same_state_angle),
            ("settings.same_state_x", self.same_state_x),
            ("settings.infimum_rel", self.infimum_rel),
            ("settings.recession_tol", self.recession_tol),
            (
                "settings.recession_candidate_rel",
                self.recession_candidate_rel,
            ),
        ] {
            unit(name, v)?;
        }
        if self.newton_accept < self.newton_tol {
            return Err(InputError::Inconsistent {
                arg: "settings.newton_accept",
                reason: "must be at least settings.newton_tol".into(),
            });
        }
        if !(0.0..1.0).contains(&self.carry_almost_rate) {
            return Err(InputError::OutOfRange {
                arg: "settings.carry_almost_rate",
                value: fmt_value(self.carry_almost_rate),
                range: "0 <= value < 1".into(),
            });
        }
        if !(self.carry_shift.is_finite() && (0.0..=1e4).contains(&self.carry_shift)) {
            return Err(InputError::OutOfRange {
                arg: "settings.carry_shift",
                value: fmt_value(self.carry_shift),
                range: "a finite number in [0, 1e4]".into(),
            });
        }
        if !(self.unbounded_reactions.is_finite() && self.unbounded_reactions >= 1.0) {
            return Err(InputError::OutOfRange {
                arg: "settings.unbounded_reactions",
                value: fmt_value(self.unbounded_reactions),
                range: "a finite number >= 1".into(),
            });
        }
        count("settings.scan_points", self.scan_points, 8, 100_000)?;
        count("settings.max_candidates", self.max_candidates, 2, 16)?;
        count("settings.newton_max_iter", self.newton_max_iter, 1, 10_000)?;
        count("settings.max_rounds", self.max_rounds, 1, 10_000)?;
        count("settings.curve_samples", self.curve_samples, 2, 10_000)?;
        count("settings.sweep_pieces", self.sweep_pieces, 4, 10_000)?;
        count("settings.sweep_doublings", self.sweep_doublings, 1, 8)?;
        for (name, v) in [
            ("settings.sweep_max_joints", self.sweep_max_joints),
            ("settings.load_sweep_max_joints", self.load_sweep_max_joints),
            ("settings.load_face_max_joints", self.load_face_max_joints),
            ("settings.ridge_max_joints", self.ridge_max_joints),
        ] {
            count(name, v, 2, 1_000_000)?;
        }
        Ok(())
    }
}

#[cfg(test)]
mod tests {
    //! The defaults written in the fields' documentation are those of `Default`, and the
    //! fields added for the limit-state search are validated by name.
    use super::Settings;

    /// Each field of `Settings` with the value after "Default " in its documentation.
    fn documented_defaults() -> Vec<(String, String)> {
        let text = include_str!("settings.rs");
        let body = &text[text.find("pub struct Settings {").expect("the struct")..];
        let body = &body[..body.find("\n}\n").expect("its end")];
        let mut out = Vec::new();
        let mut doc = String::new();
        for line in body.lines().skip(1).map(str::trim) {
            if let Some(d) = line.strip_prefix("///") {
                doc.push_str(d);
                doc.push(' ');
            } else if let Some(field) = line.strip_prefix("pub ") {
                let name = field.split(':').next().expect("a field").to_string();
                let value = doc
                    .split("Default ")
                    .nth(1)
                    .unwrap_or_else(|| panic!("settings.{name} documents no default"))
                    .split_whitespace()
                    .next()
                    .expect("a value")
                    .trim_end_matches('.')
                    .trim_matches(|c| "[]`".contains(c))
                    .rsplit("::")
                    .next()
                    .expect("a name")
                    .to_string();
                out.push((name, value));
                doc.clear();
            }
        }
        out
    }

    #[test]
    fn documented_defaults_are_the_defaults() {
        let debug = format!("{:#?}", Settings::default());
        let fields = documented_defaults();
        assert_eq!(
            fields.len(),
            debug.lines().count() - 2,
            "a field without a doc"
        );
        for (name, documented) in fields {
            let actual = debug
                .lines()
                .find_map(|l| l.trim().strip_prefix(&format!("{name}: ")))
                .unwrap_or_else(|| panic!("settings.{name} not in Debug"))
                .trim_end_matches(',');
            let same = match (documented.parse::<f64>(), actual.parse::<f64>()) {
                (Ok(d), Ok(a)) => d == a,
                _ => documented == actual,
            };
            assert!(
                same,
                "settings.{name}: documented default {documented}, Default gives {actual}"
            );
        }
    }

    #[test]
    fn limit_state_settings_are_validated_by_name() {
        let ok = Settings::default();
        assert!(ok.validate().is_ok());
        type Spoil = fn(&mut Settings);
        let cases: [(&str, Spoil); 7] = [
            ("sweep_walk_offset", |s| s.sweep_walk_offset = 0.0),
            ("same_state_eta", |s| s.same_state_eta = 1.0),
            ("same_state_angle", |s| s.same_state_angle = f64::NAN),
            ("same_state_x", |s| s.same_state_x = -1e-7),
            ("infimum_rel", |s| s.infimum_rel = 0.0),
            ("recession_tol", |s| s.recession_tol = f64::INFINITY),
            ("recession_candidate_rel", |s| {
                s.recession_candidate_rel = 2.0
            }),
        ];
        for (name, spoil) in cases {
            let mut bad = ok.clone();
            spoil(&mut bad);
            let e = bad.validate().expect_err(name).to_string();
            assert!(e.contains(&format!("settings.{name}")), "{e}");
            assert!(e.contains("0 < value < 1"), "{e}");
        }
    }
}
