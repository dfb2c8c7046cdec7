//! The thickness family: the self-weight of the arch at thickness t = η (formulation §3).

use super::traits::{Family, Param, ParamDerivative, Rows};
use crate::arch::{Arch, Radians};
use crate::contact::ContactKind;
use crate::statics::{actions_with, eta_terms_with, Actions, Affine, EtaTerms, Reactions};

/// The arch under its self-weight; the parameter is the thickness ratio η.
#[derive(Debug, Clone, Copy)]
pub struct Thickness<'a> {
    /// The arch.
    pub arch: &'a Arch,
}

/// The rows of one contact of the thickness family at (η, μ).
#[derive(Debug, Clone)]
pub struct ThicknessRows {
    actions: Actions,
    eta_terms: EtaTerms,
    kind: ContactKind,
    eta: f64,
    mu: f64,
}

impl<'a> Family for Thickness<'a> {
    type Tag = ();
    type Local = ThicknessRows;

    fn arch(&self) -> &Arch {
        self.arch
    }

    fn local(&self, kind: ContactKind, beta: Radians, _: (), eta: f64, mu: f64) -> ThicknessRows {
        let sc = self.arch.sin_cos(beta);
        ThicknessRows {
            actions: actions_with(self.arch, eta, beta, sc),
            eta_terms: eta_terms_with(self.arch, eta, beta, sc),
            kind,
            eta,
            mu,
        }
    }

    fn inside(&self, eta: f64, mu: f64) -> bool {
        eta > 0.0 && eta < 2.0 && mu > 0.0
    }
}

impl Rows for ThicknessRows {
    fn phi(&self, order: usize) -> Affine {
        self.actions.activation(self.kind, order, self.eta, self.mu)
    }

    /// η enters the hinge rows (M = ±ηN/2, and the weight through ρ(η)), and with fill every
    /// row (its 1/η); μ the sliding rows (T = ±μN).
    fn d_param(&self, order: usize, x: &Reactions, p: Param) -> ParamDerivative {
        let a = &self.actions;
        match p {
            Param::T => {
                let e = &self.eta_terms;
                if !self.kind.is_hinge() && !e.moves_sliding() {
                    return ParamDerivative::ZERO;
                }
                let grad = if self.kind.is_hinge() {
                    a.n[order].g.map(|v| -0.5 * v)
                } else {
                    [0.0; 3]
                };
                let at = (self.eta, self.mu);
                ParamDerivative {
                    value: e.activation_d_eta(self.kind, order, at, a.n[order].at(x)),
                    grad,
                    second: e.activation_d2_eta(self.kind, order, at),
                }
            }
            Param::Mu => {
                if self.kind.is_hinge() {
                    return ParamDerivative::ZERO;
                }
                ParamDerivative {
                    value: a.activation_d_mu(self.kind, order, x),
                    grad: a.n[order].g.map(|v| -v),
                    second: 0.0,
                }
            }
        }
    }
}
