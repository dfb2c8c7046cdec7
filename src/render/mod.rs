//! Output formatting: pure functions from results to text. No numerics here.

pub mod json;
pub mod table;
