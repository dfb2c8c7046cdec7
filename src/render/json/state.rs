//! The parts of a limit state in every document: its reactions and its mechanism.

use schemars::JsonSchema;
use serde::Serialize;

#[derive(Debug, Serialize, JsonSchema)]
#[schemars(rename = "Reactions")]
pub(crate) struct Reactions {
    h: f64,
    v: f64,
    w: f64,
}

#[derive(Debug, Serialize, JsonSchema)]
#[schemars(rename = "Rate")]
struct Rate {
    beta: f64,
    kind: &'static str,
    rate: f64,
}

#[derive(Debug, Serialize, JsonSchema)]
#[schemars(rename = "Mechanism")]
pub(crate) struct MechanismJson {
    rates: Vec<Rate>,
    dof: usize,
    power: f64,
    dissipation: f64,
    symmetric: bool,
    compatibility_residual: f64,
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
