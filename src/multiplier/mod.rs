//! The load-multiplier problem at fixed η and μ: the range of multipliers
//! λ ≥ 0 of a [`LiveLoad`](crate::load::LiveLoad) at which a statically admissible state exists, and every limit
//! state in it (a state whose active contacts carry a mechanism with positive live power).
//!
//! Every activation function is affine in (x, λ) ([`crate::load`]), so the admissible
//! (x, λ) form a convex polyhedron and its λ-range [λ_min, λ_static] is two LPs. For a
//! discrete arch the rows are the four activation functions at every joint — at the
//! point load's own joint on both sides of the loaded section. λ_min > 0 means the arch
//! does not stand without the load (the load stabilises it up to λ_min); λ_static is the
//! largest statically admissible multiplier (unbounded: the load never breaks the arch).

pub mod continuum;
pub mod curve;
mod face;
mod limit_state;
mod outcome;
mod range;
mod survey;

pub use limit_state::follow;
pub use outcome::{
    LoadAnswer, LoadOutcome, LoadSurvey, LoadUnsettled, StaticRange, UNBOUNDED_SEARCH_TOP,
};
pub use range::{check_load, static_range};
pub use survey::{continua, survey, survey_partial};

pub use curve::{sample, trace, CurveSample, LoadCurve};
