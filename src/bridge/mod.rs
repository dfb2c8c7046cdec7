//! The arch as a bridge (bridge spec): engineering inputs in metres ([`geometry`]), the
//! fill's statics in closed form ([`fill`]).

pub mod fill;
pub mod geometry;

pub use fill::{Fill, FillActions, FillLoad};
pub use geometry::{Geometry, Intrados, Ring};
