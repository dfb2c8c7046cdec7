//! Human-readable answers: pure functions returning text, one file per command, over the
//! formats of numbers and patterns they share (`format`).

mod assess;
mod atlas;
mod bridge;
mod corners;
mod curve;
mod format;
mod load;
mod load_curve;
mod load_map;
mod modes;
mod modes_fill;
mod solve;

pub use assess::assess;
pub use atlas::atlas;
pub use bridge::bridge;
pub use corners::{corner_rows, CORNER_HEADER};
pub use curve::curve;
pub use format::{describe_arch, fmt_mu, pattern_table, right_half_angle, sig, Dimensions, LEGEND};
pub use load::load;
pub use load_curve::load_curve;
pub use load_map::load_map;
pub use modes::modes;
pub use modes_fill::modes_fill;
pub use solve::solve;
