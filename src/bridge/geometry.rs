//! Engineering inputs (bridge spec §1): a circular arch described by what an engineer
//! measures — the clear span L and rise f of the intrados, the ring thickness t — and its
//! non-dimensional description (opening α, springings β, thickness ratio η = t/r, mean
//! radius r), both ways.
//!
//! The intrados circle through the springings and the crown has radius
//! R_i = (L²/4 + f²)/(2f) and subtends the half-angle θ ∈ (0, π) at the centre, with
//! tan(θ/2) = 2f/L (a segment for f < L/2, the semicircle at f = L/2, a horseshoe above);
//! β_R = π/2 − θ, β_L = π/2 + θ, α = θ − π/2. With a ring t, r = R_i + t/2 and η = t/r.

use crate::arch::{check_positive as positive, InputError};
use schemars::JsonSchema;
use serde::Serialize;
use std::f64::consts::FRAC_PI_2;

/// The intrados of a symmetric circular arch, from its clear span and rise (metres).
#[derive(Debug, Clone, Copy, PartialEq, Serialize, JsonSchema)]
pub struct Intrados {
    /// Clear span L between the intrados springings (m).
    pub span: f64,
    /// Rise f of the intrados above its springings (m).
    pub rise: f64,
    /// Intrados radius R_i (m).
    pub radius: f64,
    /// Half-angle θ the intrados chord subtends at the centre (radians, in (0, π)).
    pub half_angle: f64,
}

/// A ring of thickness t on an intrados: its mean radius and thickness ratio.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, JsonSchema)]
pub struct Ring {
    /// Ring thickness t (m).
    pub thickness: f64,
    /// Mean radius r = R_i + t/2 (m).
    pub radius: f64,
    /// Thickness ratio η = t/r (always in (0, 2)).
    pub eta: f64,
}

impl Intrados {
    /// The intrados of clear span `span` and rise `rise` (both finite and positive).
    pub fn new(span: f64, rise: f64) -> Result<Intrados, InputError> {
        let (span, rise) = (positive("--span", span)?, positive("--rise", rise)?);
        let half_angle = 2.0 * (2.0 * rise / span).atan();
        let radius = (0.25 * span * span + rise * rise) / (2.0 * rise);
        Ok(Intrados {
            span,
            rise,
            radius,
            half_angle,
        })
    }

    /// The intrados of a symmetric arch of opening `alpha` (radians, in (−π/2, π/2)) and
    /// intrados radius `radius` (m): the inverse of [`Intrados::new`].
    pub fn of_opening(alpha: f64, radius: f64) -> Intrados {
        let half_angle = alpha + FRAC_PI_2;
        let half = 0.5 * half_angle;
        Intrados {
            span: 2.0 * radius * half_angle.sin(),
            // 1 − cos θ = 2 sin²(θ/2), without the cancellation near θ = 0
            rise: 2.0 * radius * half.sin() * half.sin(),
            radius,
            half_angle,
        }
    }

    /// The opening α = θ − π/2 of the symmetric arch (`--alpha`).
    pub fn alpha(&self) -> f64 {
        self.half_angle - FRAC_PI_2
    }

    /// A ring of thickness `thickness` (m, finite and positive) on this intrados.
    pub fn ring(&self, thickness: f64) -> Result<Ring, InputError> {
        let t = positive("--ring", thickness)?;
        let radius = self.radius + 0.5 * t;
        Ok(Ring {
            thickness: t,
            radius,
            eta: t / radius,
        })
    }

    /// The ring whose thickness ratio is `eta` (0 < η < 2) on this intrados:
    /// t = η R_i/(1 − η/2) (the least ring t* of a least thickness η*).
    pub fn ring_of(&self, eta: f64) -> Ring {
        let radius = self.radius / (1.0 - 0.5 * eta);
        Ring {
            thickness: eta * radius,
            radius,
            eta,
        }
    }
}

/// An arch as an engineer gave it: the intrados and, when given, the ring.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, JsonSchema)]
pub struct Geometry {
    /// The intrados (span, rise).
    pub intrados: Intrados,
    /// The ring on it (thickness, mean radius, η).
    pub ring: Option<Ring>,
}
