//! The load family: the self-weight at a fixed thickness η plus t = λ times a live load
//! (shared spec `loads.md`). Every row is affine in (x, λ) and in μ.

use super::traits::{Family, Param, ParamDerivative, Rows};
use crate::arch::{Arch, Radians};
use crate::contact::ContactKind;
use crate::load::{live_activation, LiveLoad, Side};
use crate::statics::{actions, Actions, Affine, Reactions};

/// An arch at thickness `eta` carrying its self-weight and λ × `load`; the parameter is λ.
/// A row is named by its contact and the side of the loaded section it belongs to.
#[derive(Debug, Clone, Copy)]
pub struct Load<'a> {
    /// The arch.
    pub arch: &'a Arch,
    /// Its thickness ratio η.
    pub eta: f64,
    /// The live load.
    pub load: &'a LiveLoad,
}

/// The rows of one contact of the load family at (λ, μ).
#[derive(Debug, Clone)]
pub struct LoadRows {
    dead: Actions,
    live: [[f64; 3]; 3],
    kind: ContactKind,
    eta: f64,
    lambda: f64,
    mu: f64,
}

impl<'a> Family for Load<'a> {
    type Tag = Side;
    type Local = LoadRows;

    fn arch(&self) -> &Arch {
        self.arch
    }

    fn local(
        &self,
        kind: ContactKind,
        beta: Radians,
        side: Side,
        lambda: f64,
        mu: f64,
    ) -> LoadRows {
        LoadRows {
            dead: actions(self.arch, self.eta, beta),
            live: self.load.actions_d(self.arch, self.eta, beta, side),
            kind,
            eta: self.eta,
            lambda,
            mu,
        }
    }

    /// λ may take any value along the way (the callers check λ ≥ 0 at the root).
    fn inside(&self, _lambda: f64, mu: f64) -> bool {
        mu > 0.0
    }
}

impl LoadRows {
    /// The live coefficient of λ in the row's β-derivative `order`.
    pub fn live(&self, order: usize) -> f64 {
        live_activation(self.kind, self.eta, self.mu, self.live[order])
    }

    /// The row's β-derivative `order` as coefficients of (h, v, w, λ) and a constant.
    pub fn coefficients(&self, order: usize) -> ([f64; 4], f64) {
        let dead = self.dead.activation(self.kind, order, self.eta, self.mu);
        ([dead.g[0], dead.g[1], dead.g[2], self.live(order)], dead.c)
    }
}

impl Rows for LoadRows {
    fn phi(&self, order: usize) -> Affine {
        let dead = self.dead.activation(self.kind, order, self.eta, self.mu);
        Affine {
            g: dead.g,
            c: dead.c + self.lambda * self.live(order),
        }
    }

    fn d_param(&self, order: usize, x: &Reactions, p: Param) -> ParamDerivative {
        match p {
            Param::T => ParamDerivative {
                value: self.live(order),
                grad: [0.0; 3],
                second: 0.0,
            },
            Param::Mu => {
                if self.kind.is_hinge() {
                    return ParamDerivative::ZERO;
                }
                ParamDerivative {
                    value: self.dead.activation_d_mu(self.kind, order, x)
                        - self.lambda * self.live[order][0],
                    grad: self.dead.n[order].g.map(|v| -v),
                    second: 0.0,
                }
            }
        }
    }
}
