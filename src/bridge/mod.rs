//! The arch as a bridge (bridge spec): engineering inputs in metres ([`geometry`]).

pub mod geometry;

pub use geometry::{Geometry, Intrados, Ring};
