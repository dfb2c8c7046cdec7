//! Vehicles at the road (bridge spec §3): a train of axles placed at a road position,
//! spread through the fill onto the extrados, as the live load of the multiplier problem.
//!
//! Road positions X are metres from the left intrados springing, horizontally towards the
//! right springing; the vehicle travels left to right, its first axle at X and axle i at
//! X − a_i. An axle Q (kN) over the effective width w_e is a line load Q/w_e per metre of
//! barrel, non-dimensional over γ t r. Through fill of depth D above the extrados point below
//! it (from the road, y_s) it reaches the extrados as a uniform pressure over the horizontal
//! width 2 s D centred on it (s the dispersal, horizontal per vertical); beyond an extrados
//! end D is the end's, and the part of a patch beyond the loaded extrados is carried by the
//! abutment ([`crate::pressure::Pressure::resultant`] clips it). Without fill or with s = 0
//! each axle is a point load at the extrados point below it (one beyond the loaded extrados
//! bears on the abutment).

use crate::arch::{fmt_value, Arch, InputError};
use crate::input::check_non_negative;
use crate::load::LiveLoad;
use crate::pressure::{Patch, PointLoad, Pressure, MAX_PATCHES};
use std::f64::consts::PI;

/// A train of axles: loads (kN) and offsets behind the first axle (m, a_1 = 0), with a
/// uniform patch load that stays where it is on the road while the axles move (or a patch
/// alone, without axles).
#[derive(Debug, Clone, PartialEq)]
pub struct Vehicle {
    /// Axle loads Q_i (kN), first axle first.
    pub axles_kn: Vec<f64>,
    /// Offsets a_i ≥ 0 of each axle behind the first (m), non-decreasing, a_1 = 0.
    pub offsets_m: Vec<f64>,
    /// A uniform load on the road.
    pub patch: Option<RoadPatch>,
}

/// A uniform load `q_kn_m2` (kN/m²) on the road over [`from_m`, `to_m`] (m from the left
/// intrados springing).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct RoadPatch {
    /// Intensity (kN/m²).
    pub q_kn_m2: f64,
    /// Left end (m).
    pub from_m: f64,
    /// Right end (m).
    pub to_m: f64,
}

impl RoadPatch {
    /// The patch `q` (kN/m², > 0) over [`from`, `to`] (m, finite, from < to).
    pub fn new(q: f64, from: f64, to: f64) -> Result<RoadPatch, InputError> {
        crate::input::check_positive("--patch", q)?;
        if !(from.is_finite() && to.is_finite() && from < to) {
            return Err(InputError::OutOfRange {
                arg: "--patch",
                value: format!("{from} to {to}"),
                range: "Q,X1,X2 with finite road positions X1 < X2 (m)".into(),
            });
        }
        Ok(RoadPatch {
            q_kn_m2: q,
            from_m: from,
            to_m: to,
        })
    }
}

impl Vehicle {
    /// The vehicle of `axles` (kN, each > 0) with `spacing` (m, each > 0) between consecutive
    /// axles: one value for every gap, or one per gap.
    pub fn new(axles: &[f64], spacing: &[f64]) -> Result<Vehicle, InputError> {
        if axles.is_empty() || axles.len() > MAX_PATCHES {
            return Err(InputError::OutOfRange {
                arg: "--axles",
                value: axles.len().to_string(),
                range: format!("1 to {MAX_PATCHES} axle loads"),
            });
        }
        for &q in axles {
            crate::input::check_positive("--axles", q)?;
        }
        for &a in spacing {
            crate::input::check_positive("--spacing", a)?;
        }
        let gaps = axles.len() - 1;
        let gap = |i: usize| match spacing.len() {
            1 => Ok(spacing[0]),
            n if n == gaps => Ok(spacing[i]),
            n => Err(InputError::Inconsistent {
                arg: "--spacing",
                reason: format!(
                    "{n} spacings for {} axles: give one for every gap, or one per gap ({gaps})",
                    axles.len()
                ),
            }),
        };
        let mut offsets_m = vec![0.0];
        for i in 0..gaps {
            offsets_m.push(offsets_m[i] + gap(i)?);
        }
        Ok(Vehicle {
            axles_kn: axles.to_vec(),
            offsets_m,
            patch: None,
        })
    }

    /// A patch load alone.
    pub fn patch_only(patch: RoadPatch) -> Vehicle {
        Vehicle {
            axles_kn: Vec::new(),
            offsets_m: Vec::new(),
            patch: Some(patch),
        }
    }

    /// The same axles with `patch` on the road.
    pub fn with_patch(self, patch: RoadPatch) -> Vehicle {
        Vehicle {
            patch: Some(patch),
            ..self
        }
    }

    /// The whole live load at λ = 1 (kN): the axles, and the patch over the effective width
    /// `width_m` of barrel.
    pub fn total_kn(&self, width_m: f64) -> f64 {
        let patch = self
            .patch
            .map_or(0.0, |p| p.q_kn_m2 * (p.to_m - p.from_m) * width_m);
        self.axles_kn.iter().sum::<f64>() + patch
    }

    /// The distance from the first axle to the last (m).
    pub fn length_m(&self) -> f64 {
        *self.offsets_m.last().unwrap_or(&0.0)
    }
}

/// How loads at the road reach the ring: the bridge's scale and the fill's dispersal.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Deck {
    /// Mean radius r (m).
    pub radius_m: f64,
    /// Unit weight γ of the masonry (kN/m³).
    pub unit_weight: f64,
    /// Effective width w_e over which an axle spreads across the barrel (m).
    pub effective_width_m: f64,
    /// Dispersal slope s through the fill (horizontal per vertical; 0: none).
    pub dispersal: f64,
}

impl Deck {
    /// A deck: each length and the unit weight finite and positive, the dispersal ≥ 0.
    pub fn new(
        radius_m: f64,
        unit_weight: f64,
        effective_width_m: f64,
        dispersal: f64,
    ) -> Result<Deck, InputError> {
        Ok(Deck {
            radius_m: crate::input::check_positive("--radius", radius_m)?,
            unit_weight: crate::input::check_positive("--unit-weight", unit_weight)?,
            effective_width_m: crate::input::check_positive(
                "--effective-width",
                effective_width_m,
            )?,
            dispersal: check_non_negative("--dispersal", dispersal)?,
        })
    }

    /// The non-dimensional x (from the centre, r = 1) of the road position `at_m`.
    fn x_of(&self, arch: &Arch, eta: f64, at_m: f64) -> f64 {
        (1.0 - 0.5 * eta) * arch.beta_left().cos() + at_m / self.radius_m
    }

    /// The road position (m) of the non-dimensional x.
    fn at_of(&self, arch: &Arch, eta: f64, x: f64) -> f64 {
        (x - (1.0 - 0.5 * eta) * arch.beta_left().cos()) * self.radius_m
    }

    /// An axle of `kn` kN as a line load over γ t r (t = η r).
    fn scaled(&self, eta: f64, kn: f64) -> f64 {
        kn / (self.effective_width_m * self.unit_weight * eta * self.radius_m * self.radius_m)
    }

    /// Whether loads spread: fill on the arch and a positive dispersal.
    fn spreads(&self, arch: &Arch) -> bool {
        arch.fill().is_some() && self.dispersal > 0.0
    }

    /// The half-width s D (non-dimensional) over which a load at x reaches the extrados.
    fn half_width(&self, arch: &Arch, eta: f64, x: f64) -> f64 {
        let Some(fill) = arch.fill() else {
            return 0.0;
        };
        let kappa = 1.0 + 0.5 * eta;
        let (lo, hi) = Pressure::extrados(arch, eta);
        let xc = x.clamp(lo, hi);
        let below = (kappa * kappa - xc * xc).max(0.0).sqrt();
        self.dispersal * (fill.road(arch.springings(), eta) - below)
    }

    /// The road positions (m) of the first axle over which the vehicle loads the arch: from
    /// its first axle's spread reaching the left end of the loaded extrados to its last
    /// axle's leaving the right end.
    pub fn crossing(&self, arch: &Arch, eta: f64, vehicle: &Vehicle) -> (f64, f64) {
        let (lo, hi) = Pressure::extrados(arch, eta);
        let first = lo - self.half_width(arch, eta, lo);
        let last = hi + self.half_width(arch, eta, hi);
        (
            self.at_of(arch, eta, first),
            self.at_of(arch, eta, last) + vehicle.length_m(),
        )
    }

    /// Whether some axle of `vehicle` at `at_m` loads the ring: its spread (or, not spread,
    /// the axle itself) meets the loaded extrados.
    pub fn on_arch(&self, arch: &Arch, eta: f64, vehicle: &Vehicle, at_m: f64) -> bool {
        let (lo, hi) = Pressure::extrados(arch, eta);
        let spreads = self.spreads(arch);
        if let Some(p) = &vehicle.patch {
            let patch = self.road_patch(arch, eta, p);
            if patch.x_lo < hi && patch.x_hi > lo {
                return true;
            }
        }
        vehicle.offsets_m.iter().any(|&a| {
            let x = self.x_of(arch, eta, at_m - a);
            if spreads {
                let half = self.half_width(arch, eta, x);
                x + half > lo && x - half < hi
            } else {
                (lo..=hi).contains(&x)
            }
        })
    }

    /// The live load of `vehicle` with its first axle at `at_m`: a pressure of one patch per
    /// axle when loads spread, else of one point load per axle over the extrados.
    pub fn place(
        &self,
        arch: &Arch,
        eta: f64,
        vehicle: &Vehicle,
        at_m: f64,
    ) -> Result<LiveLoad, InputError> {
        if !at_m.is_finite() {
            return Err(InputError::OutOfRange {
                arg: "--at",
                value: fmt_value(at_m),
                range: "a finite road position in metres".into(),
            });
        }
        if !self.on_arch(arch, eta, vehicle, at_m) {
            let (from, to) = self.crossing(arch, eta, vehicle);
            return Err(InputError::OutOfRange {
                arg: "--at",
                value: fmt_value(at_m),
                range: format!("positions where the vehicle loads the ring, {from} to {to} m"),
            });
        }
        let road: Vec<Patch> = vehicle
            .patch
            .iter()
            .map(|p| self.road_patch(arch, eta, p))
            .collect();
        if !self.spreads(arch) {
            return Pressure::new(&road, &self.points(arch, eta, vehicle, at_m))
                .map(LiveLoad::Pressure);
        }
        let mut patches: Vec<Patch> = vehicle
            .axles_kn
            .iter()
            .zip(&vehicle.offsets_m)
            .map(|(&kn, &a)| {
                let x = self.x_of(arch, eta, at_m - a);
                let half = self.half_width(arch, eta, x);
                Patch {
                    x_lo: x - half,
                    x_hi: x + half,
                    q: self.scaled(eta, kn) / (2.0 * half),
                }
            })
            .collect();
        patches.extend(road);
        if patches.iter().any(|p| p.x_lo >= p.x_hi || p.x_lo.is_nan()) {
            return Err(InputError::Inconsistent {
                arg: "--fill-depth",
                reason: "an axle reaches the extrados without spreading (the road touches it): \
                         give a fill depth > 0, or --dispersal 0 for point loads"
                    .into(),
            });
        }
        Pressure::new(&patches, &[]).map(LiveLoad::Pressure)
    }

    /// A patch load on the road as it reaches the extrados: spread by s D at each end (D the
    /// fill's depth there), its whole load uniform over the widened interval.
    fn road_patch(&self, arch: &Arch, eta: f64, p: &RoadPatch) -> Patch {
        let (x1, x2) = (self.x_of(arch, eta, p.from_m), self.x_of(arch, eta, p.to_m));
        let (lo, hi) = if self.spreads(arch) {
            (
                x1 - self.half_width(arch, eta, x1),
                x2 + self.half_width(arch, eta, x2),
            )
        } else {
            (x1, x2)
        };
        // the line load per metre of barrel, q (X2 − X1), over γ t r (t = η r)
        let total = p.q_kn_m2 * (p.to_m - p.from_m)
            / (self.unit_weight * eta * self.radius_m * self.radius_m);
        Patch {
            x_lo: lo,
            x_hi: hi,
            q: total / (hi - lo),
        }
    }

    /// Axles that do not spread: point loads at the extrados points below them (an axle
    /// beyond the loaded extrados bears on the abutment, not on the ring). On a discrete
    /// arch an angle within 1e-9 rad of a joint is that joint.
    fn points(&self, arch: &Arch, eta: f64, vehicle: &Vehicle, at_m: f64) -> Vec<PointLoad> {
        let kappa = 1.0 + 0.5 * eta;
        let (lo, hi) = Pressure::extrados(arch, eta);
        let (br, bl) = arch.springings();
        vehicle
            .axles_kn
            .iter()
            .zip(&vehicle.offsets_m)
            .filter_map(|(&kn, &a)| {
                let x = self.x_of(arch, eta, at_m - a);
                (lo..=hi).contains(&x).then(|| PointLoad {
                    beta: arch.snap_to_joint(
                        (x / kappa)
                            .clamp(-1.0, 1.0)
                            .acos()
                            .clamp(br.max(0.0), bl.min(PI)),
                    ),
                    q: self.scaled(eta, kn),
                })
            })
            .collect()
    }

    /// The vehicle's load at λ = 1 that reaches the arch, and the part the abutments carry
    /// (kN); `None` for a load that is not a pressure.
    pub fn carried_kn(
        &self,
        arch: &Arch,
        eta: f64,
        vehicle: &Vehicle,
        load: &LiveLoad,
    ) -> Option<(f64, f64)> {
        let LiveLoad::Pressure(p) = load else {
            return None;
        };
        let (f, _) = p.resultant(arch, eta, arch.beta_left(), true);
        let kn = f[0] / self.scaled(eta, 1.0);
        let total = vehicle.total_kn(self.effective_width_m);
        // the whole load to rounding is the whole load
        let kn = if (total - kn).abs() <= 1e-12 * total {
            total
        } else {
            kn
        };
        Some((kn, total - kn))
    }
}
