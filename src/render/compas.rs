//! A drawn state as a COMPAS data document (compas 2 JSON, read by `compas.json_load`,
//! e.g. in Rhino/Grasshopper): the outline of the arch and its line of thrust as
//! `compas.geometry/Polyline`s, hinges and sliding joints as `compas.geometry/Point`s.
//! The plane of the arch is the XZ plane with z up (x towards the right springing,
//! y = 0), lengths multiplied by the mean radius given. A pure function of
//! [`ArchScene`]; `arch-enum solve --compas FILE` and the Python package's `to_compas()`
//! both use it.

use super::json::JSON_VERSION;
use crate::arch::{fmt_value, InputError};
use crate::contact::ContactKind;
use crate::figures::polylines::Point;
use crate::figures::ArchScene;
use serde_json::{json, Value};

/// Validates the mean radius the drawing is scaled by: finite, > 0 (any length unit).
pub fn check_radius(radius: f64) -> Result<f64, InputError> {
    if radius.is_finite() && radius > 0.0 {
        Ok(radius)
    } else {
        Err(InputError::OutOfRange {
            arg: "--radius",
            value: fmt_value(radius),
            range: "0 < radius < inf (the mean radius, in the length unit of the drawing)".into(),
        })
    }
}

fn xz(p: Point, radius: f64) -> Value {
    json!([radius * p.0, 0.0, radius * p.1])
}

fn polyline(name: &str, pts: &[Point], radius: f64) -> Value {
    json!({
        "dtype": "compas.geometry/Polyline",
        "data": { "points": pts.iter().map(|&p| xz(p, radius)).collect::<Vec<_>>() },
        "name": name,
    })
}

fn points(pts: &[(Point, ContactKind)], radius: f64) -> Value {
    pts.iter()
        .map(|&(p, kind)| {
            json!({
                "dtype": "compas.geometry/Point",
                "data": xz(p, radius),
                "name": kind.name(),
            })
        })
        .collect()
}

/// The document of `scene` scaled by `radius` (checked with [`check_radius`]): keys
/// `outline`, `thrust_line`, `friction_line` (`null` at μ = ∞), `hinges`, `sliding`, and
/// `arch_enum` (plain numbers: η, μ (`null` = ∞), the mode, the radius).
pub fn document(scene: &ArchScene, radius: f64) -> Value {
    let friction = scene.friction_line();
    json!({
        "arch_enum": {
            "version": JSON_VERSION,
            "eta": scene.eta,
            "mu": scene.mu,
            "mode": scene.mode.map(|m| m.name()),
            "radius": radius,
            "beta_right": scene.arch.beta_right(),
            "beta_left": scene.arch.beta_left(),
            "plane": "xz",
        },
        "outline": polyline("outline", &scene.outline(), radius),
        "thrust_line": polyline("thrust_line", &scene.thrust_line(), radius),
        "friction_line": if friction.is_empty() {
            Value::Null
        } else {
            polyline("friction_line", &friction, radius)
        },
        "hinges": points(&scene.hinges(), radius),
        "sliding": points(&scene.sliding(), radius),
    })
}
