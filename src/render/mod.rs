//! Output formatting: pure functions from results to text. No numerics here: the figures
//! draw the data that [`crate::figures`] computed and call no solver.

pub mod compas;
pub mod dimensions;
#[cfg(feature = "svg")]
pub mod fine;
pub mod geometry;
pub mod json;
mod live_load;
pub mod load;
#[cfg(feature = "svg")]
pub mod plot;
#[cfg(feature = "svg")]
pub mod plot_arch;
pub mod plot_atlas;
#[cfg(feature = "svg")]
pub mod plot_curve;
#[cfg(feature = "svg")]
pub mod plot_ecc;
#[cfg(feature = "svg")]
pub mod plot_fill_curve;
pub mod plot_influence;
#[cfg(feature = "svg")]
pub mod plot_load_curve;
#[cfg(feature = "svg")]
pub mod plot_load_map;
#[cfg(feature = "svg")]
pub mod plot_map;
pub mod report;
pub mod table;
