//! Problem families: the one place where a parametric question meets the method.
//!
//! Every question the solver answers has the same shape: rows φ_i(β; x, t, μ) ≤ 0, one per
//! contact (an activation function at a joint angle β), affine in the reactions
//! x = (h, v, w) and smooth in the family's parameter t and in the friction μ. The method —
//! Newton with KKT completion ([`crate::refine`]), and the parts built on it — is written
//! once over this trait; a family only says how to evaluate its rows:
//!
//! | family | t | rows |
//! |---|---|---|
//! | [`Thickness`] | η (least admissible) | self-weight at thickness η |
//! | [`Load`] | λ (largest admissible) | self-weight at a fixed η plus λ × a live load |
//!
//! A new load or parameter is a new implementation of [`Family`] (its rows and their first
//! derivatives in t and μ), not a copy of the method: see `docs/architecture.md`.

mod load;
mod pattern;
mod thickness;
mod traits;

pub use load::{Load, LoadRows};
pub use pattern::merge_adjacent;
pub use thickness::{Thickness, ThicknessRows};
pub use traits::{Family, Param, ParamDerivative, Rows, Tagged};
