//! The physical dimensions of a real arch, which the text and JSON forms use to print
//! results in metres and kilonewtons.

use crate::bridge::Intrados;

/// Dimensions of a real arch, for printing results in metres and kilonewtons.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Dimensions {
    /// Mean radius r (m).
    pub radius: f64,
    /// Depth d of the arch barrel, perpendicular to its plane (m).
    pub depth: f64,
    /// Density ρ (kg/m³).
    pub density: f64,
    /// Gravitational acceleration g (m/s²).
    pub g: f64,
    /// The intrados when the arch was given by its span and rise: the least thickness is
    /// then the least ring on it ([`Intrados::ring_of`]), rather than η* r at the fixed
    /// mean radius.
    pub intrados: Option<Intrados>,
}
