//! The parts of a limit state in every document: its reactions and its mechanism.

use serde::Serialize;

#[derive(Debug, Serialize)]
pub(crate) struct Reactions {
    h: f64,
    v: f64,
    w: f64,
}

#[derive(Debug, Serialize)]
struct Rate {
    beta: f64,
    kind: &'static str,
    rate: f64,
}

#[derive(Debug, Serialize)]
pub(crate) struct MechanismJson {
    rates: Vec<Rate>,
    dof: usize,
    power: f64,
    dissipation: f64,
    symmetric: bool,
    compatibility_residual: f64,
    complementarity_residual: f64,
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
    }
}

pub(crate) fn reactions(x: &[f64; 3]) -> Reactions {
    Reactions {
        h: x[0],
        v: x[1],
        w: x[2],
    }
}
