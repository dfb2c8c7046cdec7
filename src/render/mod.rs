//! Output formatting: pure functions from results to text. No numerics here.

#[cfg(feature = "svg")]
pub mod figures;
pub mod json;
#[cfg(feature = "svg")]
pub mod plot;
#[cfg(feature = "svg")]
pub mod plot_arch;
#[cfg(feature = "svg")]
pub mod plot_curve;
#[cfg(feature = "svg")]
pub mod plot_ecc;
#[cfg(feature = "svg")]
pub mod plot_map;
pub mod table;
