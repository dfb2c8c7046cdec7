//! The one state value passed between the parts of the solver: an arch at thickness η
//! and friction μ carrying the reactions x. Its scan over the joints lives in
//! [`crate::scan`].

use crate::arch::Arch;
use crate::statics::Reactions;

/// Reactions x = (h, v, w) at the right springing of `arch`, at thickness ratio η and
/// friction coefficient μ (units: formulation §3).
#[derive(Debug, Clone, Copy)]
pub struct State<'a> {
    /// The arch.
    pub arch: &'a Arch,
    /// Thickness ratio η = t/r.
    pub eta: f64,
    /// Friction coefficient μ (∞: no sliding).
    pub mu: f64,
    /// Reactions x = (h, v, w).
    pub x: Reactions,
}
