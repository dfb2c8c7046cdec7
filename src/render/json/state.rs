//! The parts of a limit state in every document: its reactions and its mechanism.

use schemars::JsonSchema;
use serde::Serialize;

/// The redundant reactions at the right springing: h, v (forces) and w (moment), in units of γ
/// t d r (and r).
#[derive(Debug, Serialize, JsonSchema)]
#[schemars(rename = "Reactions")]
pub(crate) struct Reactions {
    /// Horizontal force.
    h: f64,
    /// Vertical force.
    v: f64,
    /// Moment.
    w: f64,
}

/// One contact's rate in a mechanism.
#[derive(Debug, Serialize, JsonSchema)]
#[schemars(rename = "Rate")]
struct Rate {
    /// The joint angle (radians).
    beta: f64,
    /// The contact (`hinge_extrados`, `hinge_intrados`, `slide_plus`, `slide_minus`).
    kind: &'static str,
    /// Its rate (the rates of a mechanism sum to 1).
    rate: f64,
}

/// A mechanism on the active contacts: the rates, the dimension of the mechanism cone, the
/// external power and the frictional dissipation, the residuals of compatibility and
/// complementarity, and (`solve` only) the cone's extreme rays.
#[derive(Debug, Serialize, JsonSchema)]
#[schemars(rename = "Mechanism")]
pub(crate) struct MechanismJson {
    /// The rate at each active contact (summing to 1).
    rates: Vec<Rate>,
    /// The dimension of the mechanism cone (1: a unique mechanism up to scale).
    dof: usize,
    /// The power of the weight (and of the live load) on the mechanism.
    power: f64,
    /// The power dissipated by friction.
    dissipation: f64,
    /// Whether the mechanism is its own mirror image.
    symmetric: bool,
    /// |B λ|: how far the rates are from compatible.
    compatibility_residual: f64,
    /// How far the rates are from complementary to the active contacts.
    complementarity_residual: f64,
    /// The extreme rays of the mechanism cone (rates on the contacts of `rates`, in their
    /// order, each summing to 1): one when `dof` is 1, every vertex of the cone's section
    /// otherwise (`solve` only; absent elsewhere).
    #[serde(skip_serializing_if = "Option::is_none")]
    rays: Option<Vec<Vec<f64>>>,
}

pub(crate) fn mechanism_json(m: &crate::mechanism::Mechanism) -> MechanismJson {
    MechanismJson {
        rates: m
            .contacts
            .iter()
            .zip(&m.rates)
            .map(|(c, &rate)| Rate {
                beta: c.beta,
                kind: c.kind.name(),
                rate,
            })
            .collect(),
        dof: m.dof,
        power: m.power,
        dissipation: m.dissipation,
        symmetric: m.symmetric,
        compatibility_residual: m.compatibility,
        complementarity_residual: m.complementarity,
        rays: None,
    }
}

/// [`mechanism_json`] with the extreme rays of the mechanism's cone
/// ([`crate::limit_states::Rays`]).
pub(crate) fn mechanism_with_rays(
    m: &crate::mechanism::Mechanism,
    rays: &[Vec<f64>],
) -> MechanismJson {
    MechanismJson {
        rays: Some(rays.to_vec()),
        ..mechanism_json(m)
    }
}

pub(crate) fn reactions(x: &[f64; 3]) -> Reactions {
    Reactions {
        h: x[0],
        v: x[1],
        w: x[2],
    }
}
