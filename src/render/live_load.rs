//! The question of `load` and `load-curve` (arch, η, μ, the live load, the dimensions) and
//! what their JSON and text forms share: the contacts with the side of the loaded section
//! each is on, the force unit, the tolerance that calls a corner continuous.

use crate::arch::Arch;
use crate::contact::Contact;
use crate::load::{LiveLoad, Side};
use crate::render::dimensions::Dimensions;

/// The question asked: arch, η, μ and the load.
pub struct LoadQuestion<'a> {
    /// The arch.
    pub arch: &'a Arch,
    /// Thickness ratio.
    pub eta: f64,
    /// Friction coefficient.
    pub mu: f64,
    /// The live load.
    pub load: LiveLoad,
    /// Physical dimensions, for loads in kN or accelerations in m/s².
    pub dims: Option<Dimensions>,
    /// A pressure's load at λ = 1 in kN, when it was given in kN (a vehicle: the sum of its
    /// axles; a patch load: q times its area).
    pub vehicle_kn: Option<f64>,
}

pub(super) fn at_joint(arch: &Arch, beta: f64) -> bool {
    match arch.layout() {
        crate::arch::JointLayout::Discrete(j) => j.contains(&beta),
        crate::arch::JointLayout::Continuous => false,
    }
}

fn side_name(load: &LiveLoad, c: &Contact, side: Side) -> Option<&'static str> {
    load.splits(c.beta).then_some(match side {
        Side::Before => "before",
        Side::After => "after",
    })
}

/// The contacts of a pattern with the side of a loaded section each is on (`None`: no
/// section split there; `Some("both")`: one hinge seen from both sides). The extrados hinge
/// rows on the two sides of a point load's section are one function — the load acts at the
/// extrados point, so its moment about it is nil — and appear once, as `both`.
pub(super) fn merged<'a>(
    load: &LiveLoad,
    pattern: impl Iterator<Item = (&'a Contact, Side)>,
) -> Vec<(Contact, Option<&'static str>)> {
    let mut out: Vec<(Contact, Option<&'static str>)> = Vec::new();
    for (c, side) in pattern {
        let name = side_name(load, c, side);
        if let Some(twin) = out.iter_mut().find(|(d, side)| {
            name.is_some()
                && side.is_some()
                && d.beta == c.beta
                && d.kind == c.kind
                && c.kind == crate::contact::ContactKind::HingeExtrados
        }) {
            twin.1 = Some("both");
            continue;
        }
        out.push((*c, name));
    }
    out
}

/// γ t d r in kN, and g in m/s², for the question's dimensions.
pub(super) fn force_unit_kn(q: &LoadQuestion, d: &Dimensions) -> f64 {
    d.density * d.g * q.eta * d.radius * d.depth * d.radius / 1000.0
}

/// λ equal on both sides of a corner to this relative tolerance: continuous.
pub(super) const CONTINUOUS_TOL: f64 = 1e-9;
