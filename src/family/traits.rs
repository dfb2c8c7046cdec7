//! The vocabulary of a problem family: its parameters, the derivatives of a row in them,
//! the evaluated rows of one contact, and the [`Family`] trait itself.

use crate::arch::{Arch, Radians};
use crate::contact::{Contact, ContactKind};
use crate::statics::{Affine, Reactions};
use std::fmt::Debug;

/// A parameter of a family's rows: the family's own t, or the friction μ.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Param {
    /// The family's parameter t (η for the thickness, λ for a load multiplier).
    T,
    /// The friction coefficient μ.
    Mu,
}

/// The partial derivatives of one row (β-derivative of some order) in a parameter p at x:
/// ∂φ/∂p, its x-gradient ∂(∇ₓφ)/∂p, and ∂²φ/∂p².
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ParamDerivative {
    /// ∂φ/∂p at x.
    pub value: f64,
    /// ∂(∇ₓφ)/∂p.
    pub grad: [f64; 3],
    /// ∂²φ/∂p² at x.
    pub second: f64,
}

impl ParamDerivative {
    /// A row that does not depend on the parameter.
    pub const ZERO: ParamDerivative = ParamDerivative {
        value: 0.0,
        grad: [0.0; 3],
        second: 0.0,
    };
}

/// The rows of one contact at one angle and one (t, μ): what Newton needs of them.
pub trait Rows {
    /// The β-derivative of order `order` (0, 1 or 2) of the row, as an affine function of x.
    fn phi(&self, order: usize) -> Affine;
    /// Its derivatives in the parameter `p` at x.
    fn d_param(&self, order: usize, x: &Reactions, p: Param) -> ParamDerivative;
}

/// A parametric family of activation rows φ(β; x, t, μ).
pub trait Family {
    /// What names a row besides its contact: the side of a loaded section (`()` where a
    /// contact names its row alone).
    type Tag: Copy + Ord + Debug;
    /// The evaluated rows of one contact.
    type Local: Rows;
    /// The arch.
    fn arch(&self) -> &Arch;
    /// The rows of the activation function `kind` at angle `beta` (with `tag`) at
    /// parameter t and friction μ.
    fn local(
        &self,
        kind: ContactKind,
        beta: Radians,
        tag: Self::Tag,
        t: f64,
        mu: f64,
    ) -> Self::Local;
    /// Whether (t, μ) lies in the family's domain (Newton's iterates must stay in it).
    fn inside(&self, t: f64, mu: f64) -> bool;
}

/// A contact of a family's pattern: the contact and its row's tag.
pub type Tagged<T> = (Contact, T);
