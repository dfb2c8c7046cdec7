//! Output formatting: pure functions from results to text. No numerics here.

pub mod json;
pub mod plot;
pub mod plot_curve;
pub mod table;
