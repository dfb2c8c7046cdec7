//! The contacts of either problem and how a certificate records them: the load, the side of
//! a loaded section, the rows in (h, v, w, λ), the order of the lists.

use crate::arch::Arch;
use crate::certificate::format::{
    CertJoint, LoadKind, LoadSpec, PatchSpec, PatternJoint, PointSpec, Side, Towards,
};
use crate::contact::Contact;
use crate::load::{live_activation, LiveLoad};
use crate::statics::{actions, Affine};

/// A contact of either problem: the activation function and the side of the loaded section
/// it belongs to (`After` away from a point load, and in the thickness problem).
pub(super) type Loaded = (Contact, Side);

/// The load as the certificate records it.
pub(super) fn load_spec(eta: f64, load: &LiveLoad) -> LoadSpec {
    match *load {
        LiveLoad::Horizontal { towards_right } => LoadSpec {
            eta,
            kind: LoadKind::Horizontal,
            towards: Some(if towards_right {
                Towards::Right
            } else {
                Towards::Left
            }),
            beta: None,
            patches: None,
            points: None,
        },
        LiveLoad::Point { beta } => LoadSpec {
            eta,
            kind: LoadKind::Point,
            towards: None,
            beta: Some(beta),
            patches: None,
            points: None,
        },
        LiveLoad::Pressure(p) => LoadSpec {
            eta,
            kind: LoadKind::Pressure,
            towards: None,
            beta: None,
            patches: Some(
                p.patches()
                    .iter()
                    .map(|q| PatchSpec {
                        x_lo: q.x_lo,
                        x_hi: q.x_hi,
                        q: q.q,
                    })
                    .collect(),
            ),
            points: Some(
                p.points()
                    .iter()
                    .map(|q| PointSpec {
                        beta: q.beta,
                        q: q.q,
                    })
                    .collect(),
            ),
        },
    }
}

/// The side as the certificate records it: only at the point load's own angle (never
/// without a load: `None` for the thickness problem).
fn cert_side(load: Option<&LiveLoad>, beta: f64, side: Side) -> Option<Side> {
    load.is_some_and(|l| l.splits(beta)).then_some(side)
}

/// The activation function of a loaded contact as a row in (h, v, w, λ): `(a, c)`.
pub(super) fn row_at(
    arch: &Arch,
    eta: f64,
    mu: f64,
    load: &LiveLoad,
    (c, side): Loaded,
) -> ([f64; 4], f64) {
    let dead = actions(arch, eta, c.beta).activation(c.kind, 0, eta, mu);
    let live = live_activation(c.kind, eta, mu, load.actions(arch, eta, c.beta, side));
    ([dead.g[0], dead.g[1], dead.g[2], live], dead.c)
}

/// The row at a fixed λ, affine in x.
pub(super) fn at_lambda((a, c): ([f64; 4], f64), lambda: f64) -> Affine {
    Affine {
        g: [a[0], a[1], a[2]],
        c: c + a[3] * lambda,
    }
}

/// Sorts loaded contacts by (β, side, kind), `Before` first: the order of certificates.
pub(super) fn sorted(mut p: Vec<Loaded>) -> Vec<Loaded> {
    p.sort_by(|a, b| {
        a.0.beta
            .total_cmp(&b.0.beta)
            .then((a.1 == Side::After).cmp(&(b.1 == Side::After)))
            .then(a.0.kind.cmp(&b.0.kind))
    });
    p
}

/// A contact as a joint of a pattern (`load` `None` for the thickness problem).
pub(super) fn joint(load: Option<&LiveLoad>, (c, side): Loaded) -> PatternJoint {
    PatternJoint {
        beta: c.beta,
        kind: c.kind,
        at: c.at,
        side: cert_side(load, c.beta, side),
    }
}

/// Whether the section of a loaded contact carries the live load (every section for a
/// horizontal load and a pressure; for a point load those after it, and the `After` side
/// of its own).
pub(super) fn carries(load: &LiveLoad, (c, side): Loaded) -> bool {
    match *load {
        LiveLoad::Horizontal { .. } => true,
        LiveLoad::Point { beta } => c.beta > beta || (c.beta == beta && side == Side::After),
        // λ enters every section's rows (its patches and point loads are not split out)
        LiveLoad::Pressure(_) => true,
    }
}

/// The contacts of a Farkas certificate with their multipliers (`load` `None` for the
/// thickness problem).
pub(super) fn cert_joints(load: Option<&LiveLoad>, labelled: &[(Loaded, f64)]) -> Vec<CertJoint> {
    labelled
        .iter()
        .map(|&((c, side), y)| CertJoint {
            beta: c.beta,
            kind: c.kind,
            side: cert_side(load, c.beta, side),
            y,
        })
        .collect()
}
