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
mod thickness;

use crate::arch::{Arch, Radians};
use crate::contact::{Contact, ContactKind, Location};
use crate::statics::{Affine, Reactions};
use std::fmt::Debug;

pub use load::Load;
pub use thickness::Thickness;

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

/// A discrete pattern carried over to the continuum: contacts of one kind and tag at
/// adjacent joints (spacing `h`) become one contact — the group's first contact that stays
/// where it is (`fixed`: a springing, the section of a point load) or else an interior
/// tangency contact with a free angle at the group's mean angle. The groups come in the
/// order of (kind, tag, β).
pub fn merge_adjacent<T: Copy + Ord>(
    pattern: &[Tagged<T>],
    h: f64,
    fixed: impl Fn(&Tagged<T>) -> bool,
) -> Vec<Tagged<T>> {
    let mut sorted = pattern.to_vec();
    sorted.sort_by(|a, b| {
        (a.0.kind, a.1)
            .cmp(&(b.0.kind, b.1))
            .then(a.0.beta.total_cmp(&b.0.beta))
    });
    let mut merged: Vec<Tagged<T>> = Vec::new();
    let mut group: Vec<Tagged<T>> = Vec::new();
    let flush = |group: &mut Vec<Tagged<T>>, out: &mut Vec<Tagged<T>>| {
        let Some(first) = group.first() else {
            return;
        };
        out.push(group.iter().copied().find(&fixed).unwrap_or((
            Contact {
                beta: group.iter().map(|c| c.0.beta).sum::<f64>() / group.len() as f64,
                kind: first.0.kind,
                at: Location::Interior,
                free: true,
            },
            first.1,
        )));
        group.clear();
    };
    for c in sorted {
        let joins = group.last().is_some_and(|l| {
            l.0.kind == c.0.kind && l.1 == c.1 && (c.0.beta - l.0.beta).abs() <= ADJACENT * h
        });
        if !joins {
            flush(&mut group, &mut merged);
        }
        group.push(c);
    }
    flush(&mut group, &mut merged);
    merged
}

/// Two contacts of one kind are adjacent joints of a discretisation of spacing h when they
/// are at most this many spacings apart.
const ADJACENT: f64 = 1.5;
