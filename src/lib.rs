//! # arch-enum
//!
//! Exact limit analysis of circular masonry arches with **limited friction** by
//! active-set enumeration.
//!
//! An arch of mean radius r (all lengths divided by r), thickness ratio η = t/r and
//! springings β_R < β_L (radians, counter-clockwise from the horizontal through the
//! centre) carries its self-weight. Joints are radial; they may hinge at the
//! extrados or intrados (no tension) or slide (Coulomb friction μ, non-associative:
//! no dilatancy). The least thickness η*(μ) is the least η for which a statically
//! admissible state of the redundant reactions x = (h, v, w) exists and carries a
//! compatible mechanism on its active contacts.
//!
//! | module | formulation (`shared/spec/formulation.md`) |
//! |---|---|
//! | [`arch`] | §2 geometry, input validation |
//! | [`statics`] | §3 N, T, M, activation functions and exact derivatives |
//! | [`state`] | the state value (arch, η, μ, x) passed between the parts |
//! | [`scan`] | §3 maxima of φ over the continuum |
//! | [`admissibility`] | §5 static LP by constraint generation |
//! | [`lp`] | the static and kinematic LPs; back ends `lp::dense` (fast path) and `lp::highs` (reference) |
//! | [`kinematics`] | §4 compatibility B and external power L_e |
//! | [`mechanism`] | §4–5 kinematic LP, mechanism cone |
//! | [`refine`] | §5 Newton on a pattern's square system |
//! | [`search`] | §5 bracketing the continuum margin, candidate contacts |
//! | [`limit`] | §5 η*(μ): bracket, enumerate, verify; the solution types |
//! | [`friction`] | §6 the friction-only problem, μ_ms |
//! | [`limit_states`] | §5 every limit state at one μ: the sweep of the admissible polytope in η |
//! | [`limit_curve`] | §5 the η–μ curve: branches and exact corners; η*(μ) sampled over μ |
//! | [`assess`] | a given thickness: factors of safety, μ_min(η), the safest state |
//! | [`bridge`] | bridge spec §1: span, rise and ring in metres ↔ (α, η, r) |
//! | [`collapse_mode`] | §5 collapse-mode names from the pattern |
//! | [`certificate`] | certificates (format, certify) and their independent re-check (verify, interval arithmetic) |
//! | [`figures`] | §3–4 the data of the pictures: sampled curves, lines of thrust and friction, block motions, margin map |
//! | [`contact`], [`settings`] | vocabulary (contacts, locations) and every tolerance |
//! | [`render`], [`cli`] | text, JSON and SVG/PNG drawing of [`figures`] data, the command line (thin layers, no numerics) |
//!
//! ```
//! use arch_enum::{Arch, WeightModel, Settings, solve, Outcome};
//! // Couplet–Heyman: semicircle, infinite friction.
//! let arch = Arch::symmetric(0.0, WeightModel::Centreline).unwrap();
//! let sol = solve(&arch, f64::INFINITY, &Settings::default()).unwrap();
//! let Outcome::Limit(ls) = sol.outcome else { panic!("no limit state") };
//! assert!((ls.eta - 0.1074).abs() < 1e-4);
//! ```
#![deny(missing_docs)]
#![forbid(unsafe_code)]

pub mod admissibility;
pub mod arch;
pub mod assess;
pub mod atlas;
pub mod bridge;
pub mod certificate;
#[cfg(feature = "cli")]
pub mod cli;
pub mod collapse_mode;
pub mod contact;
pub mod family;
pub mod figures;
pub mod fill;
pub mod friction;
pub mod input;
pub mod kinematics;
pub mod limit;
pub mod limit_curve;
pub mod limit_states;
pub mod load;
pub mod lp;
pub mod mechanism;
pub mod multiplier;
pub mod pressure;
pub mod refine;
pub mod render;
pub mod scan;
pub mod search;
pub mod settings;
pub mod state;
pub mod statics;
pub mod threads;
pub mod tracer;
pub mod undecided;

pub use arch::{Arch, InputError, JointLayout, Radians, WeightModel};
pub use collapse_mode::CollapseMode;
pub use contact::ContactKind;
pub use contact::{Contact, Location};
pub use friction::{friction_limit, least_friction, FrictionLimit};
pub use limit::{solve, LeastLimitState, Outcome, Solution};
pub use settings::{LpBackend, Settings};
