//! The engineer's description of an arch (`--span --rise [--ring]`) beside the
//! non-dimensional one it gives, as text lines and as the JSON `geometry` object.

use crate::bridge::Geometry;
use crate::render::table::sig;
use serde_json::{json, Value};

/// `geometry` in JSON: `span_m`, `rise_m`, `intrados_radius_m`, `ring_m`, `radius_m`, `eta`
/// (null without a ring), `alpha`, `beta_right`, `beta_left`; with a least thickness η*
/// (`least_eta`), `least_ring_m` = η* R_i/(1 − η*/2), and with a ring too `ring_over_least`.
pub fn json(g: &Geometry, least_eta: Option<f64>) -> Value {
    let i = &g.intrados;
    let alpha = i.alpha();
    let least = least_eta.map(|e| i.ring_of(e).thickness);
    json!({
        "span_m": i.span,
        "rise_m": i.rise,
        "intrados_radius_m": i.radius,
        "ring_m": g.ring.map(|r| r.thickness),
        "radius_m": g.ring.map(|r| r.radius),
        "eta": g.ring.map(|r| r.eta),
        "alpha": alpha,
        "beta_right": 0.0 - alpha,
        "beta_left": std::f64::consts::PI + alpha,
        "least_ring_m": least,
        "ring_over_least": least.and_then(|t| g.ring.map(|r| r.thickness / t)),
    })
}

/// The same as text: a line for the intrados, one for the ring, one for the least ring.
pub fn text(g: &Geometry, least_eta: Option<f64>) -> String {
    let i = &g.intrados;
    let mut out = format!(
        "geometry            span {} m, rise {} m: intrados radius {} m, alpha = {} rad ({} deg)\n",
        sig(i.span, 6),
        sig(i.rise, 6),
        sig(i.radius, 6),
        sig(i.alpha(), 10),
        sig(i.alpha().to_degrees(), 6)
    );
    if let Some(r) = g.ring {
        out += &format!(
            "ring                t = {} m: mean radius r = {} m, eta = t/r = {}\n",
            sig(r.thickness, 6),
            sig(r.radius, 6),
            sig(r.eta, 12)
        );
    }
    if let Some(e) = least_eta {
        let t = i.ring_of(e).thickness;
        out += &format!(
            "least ring          t* = {} m with the span and rise held",
            sig(t, 6)
        );
        if let Some(r) = g.ring {
            out += &format!(
                " (the ring given is t/t* = {} times it)",
                sig(r.thickness / t, 4)
            );
        }
        out += "\n";
    }
    out + RING_SCOPE
}

/// The scope line of an arch without fill or vehicle (a bridge answer prints its own).
pub const RING_SCOPE: &str =
    "scope               single ring, radial joints, no crushing, no fill (the ring's own weight)\n";
