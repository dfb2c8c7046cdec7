//! The arch as a bridge (bridge spec): engineering inputs in metres ([`geometry`]), the
//! fill's statics in closed form ([`crate::fill`]), vehicles spread through the fill onto the
//! extrados ([`vehicle`]) and the position where a vehicle is worst ([`mod@critical`]).

pub mod critical;
pub mod geometry;
pub mod vehicle;

pub use crate::fill::{Fill, FillActions, FillLoad};
pub use critical::{critical, Collapse, Critical, Search};
pub use geometry::{Geometry, Intrados, Ring};
pub use vehicle::{Deck, Vehicle};
