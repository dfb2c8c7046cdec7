//! The answer of `arch-enum load` and `load-curve` as JSON and as text, under the names the
//! command line and the Python module use: pure functions of
//! [`crate::multiplier::LoadOutcome`] and [`crate::multiplier::LoadCurve`].

pub use super::json::{
    load as json, load_curve as curve_json, LoadCurveDoc, LoadCurveRow, LoadDoc,
};
pub use super::live_load::LoadQuestion;
pub use super::table::{load as table, load_curve as curve_table};
