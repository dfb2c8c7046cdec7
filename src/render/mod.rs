//! Output formatting: pure functions from results to text. No numerics here.

pub mod figures;
pub mod json;
pub mod plot;
pub mod plot_arch;
pub mod plot_curve;
pub mod plot_ecc;
pub mod plot_map;
pub mod table;
