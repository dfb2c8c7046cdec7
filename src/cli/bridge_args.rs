//! The bridge flags of `load`: fill above the extrados (`--fill-weight --fill-depth` in kN/m³
//! and m, or `--fill-ratio --fill-height` non-dimensional), and a vehicle at the road
//! (`--axles --spacing --at`, `--dispersal`, `--effective-width`), with `--critical` for the
//! position where it is worst.

use super::threads_arg::ThreadsArg;
use crate::arch::{Arch, InputError};
use crate::bridge::critical::Search;
use crate::bridge::vehicle::RoadPatch;
use crate::bridge::{Deck, Fill, Vehicle};
use crate::render::json::{FillJson, VehicleJson};
use crate::render::table::Dimensions;
use clap::Args;

#[derive(Args, Debug, Default)]
pub(crate) struct FillArgs {
    /// Unit weight of the fill in kN/m^3 (with --fill-depth; needs the masonry's unit
    /// weight: --width --unit-weight, or --radius --depth --density).
    #[arg(long, allow_hyphen_values = true, requires = "fill_depth", conflicts_with_all = ["fill_ratio", "fill_height"])]
    fill_weight: Option<f64>,
    /// Depth of the fill in metres above the highest extrados point (the road's level).
    #[arg(long, allow_hyphen_values = true, requires = "fill_weight")]
    fill_depth: Option<f64>,
    /// The fill's unit weight over the masonry's, g_f (non-dimensional; with --fill-height).
    #[arg(long, allow_hyphen_values = true, requires = "fill_height")]
    fill_ratio: Option<f64>,
    /// The road's height above the highest extrados point over the mean radius, h = h_c/r.
    #[arg(long, allow_hyphen_values = true, requires = "fill_ratio")]
    fill_height: Option<f64>,
}

impl FillArgs {
    /// Whether a fill was given.
    pub(crate) fn given(&self) -> bool {
        self.fill_weight.is_some() || self.fill_ratio.is_some()
    }

    /// The fill (`None` without fill flags) and its description; `masonry` is the ring's
    /// mean radius (m) and the masonry's unit weight (kN/m³), which convert `--fill-weight`
    /// and `--fill-depth`.
    pub(crate) fn build(
        &self,
        masonry: Option<(f64, f64)>,
    ) -> Result<Option<(Fill, FillJson)>, InputError> {
        if let (Some(g), Some(h)) = (self.fill_ratio, self.fill_height) {
            let g = crate::input::check_non_negative("--fill-ratio", g)?;
            let h = crate::input::check_non_negative("--fill-height", h)?;
            let fill = Fill::new(g, h)?;
            return Ok(Some((fill, fill_json(&fill, None, None))));
        }
        let (Some(w), Some(d)) = (self.fill_weight, self.fill_depth) else {
            return Ok(None);
        };
        let Some((radius, gamma)) = masonry else {
            return Err(InputError::Inconsistent {
                arg: "--fill-weight/--fill-depth",
                reason: "need the masonry's unit weight and the ring's radius: give --span \
                         --rise --ring with --unit-weight (and --width on load), or --radius \
                         --depth --density, or use --fill-ratio --fill-height"
                    .into(),
            });
        };
        let w = crate::input::check_non_negative("--fill-weight", w)?;
        let d = crate::input::check_non_negative("--fill-depth", d)?;
        let fill = Fill::new(w / gamma, d / radius)?;
        Ok(Some((fill, fill_json(&fill, Some(w), Some(d)))))
    }
}

/// The fill flags of a command that takes the arch without `load`'s dimensions (`solve`,
/// `plot arch`): `--unit-weight` and the ring of `--span --rise --ring` convert
/// `--fill-weight --fill-depth`.
#[derive(Args, Debug, Default)]
pub(crate) struct ArchFillArgs {
    #[command(flatten)]
    fill: FillArgs,
    /// Unit weight of the masonry in kN/m^3: with --span --rise --ring, converts
    /// --fill-weight and --fill-depth to g_f and h = h_c/r.
    #[arg(long, allow_hyphen_values = true, requires = "fill_weight")]
    unit_weight: Option<f64>,
}

impl ArchFillArgs {
    /// Whether a fill was given.
    pub(crate) fn given(&self) -> bool {
        self.fill.given()
    }

    /// The arch of `arch` with its fill, and the fill's description (`None` without fill).
    pub(crate) fn build(
        &self,
        arch: &super::arch_args::ArchArgs,
    ) -> Result<(Arch, Option<FillJson>), InputError> {
        let built = arch.build()?;
        let ring = arch.geometry()?.and_then(|g| g.ring);
        let masonry = match (ring, self.unit_weight) {
            (Some(r), Some(g)) => {
                Some((r.radius, crate::input::check_positive("--unit-weight", g)?))
            }
            _ => None,
        };
        Ok(match self.fill.build(masonry)? {
            Some((f, j)) => (built.with_fill(f), Some(j)),
            None => (built, None),
        })
    }
}

fn fill_json(f: &Fill, weight: Option<f64>, depth: Option<f64>) -> FillJson {
    FillJson {
        weight_kn_m3: weight,
        depth_m: depth,
        weight_ratio: f.weight_ratio,
        depth_ratio: f.depth,
        depth_at_least_ring_m: None,
    }
}

/// The masonry's unit weight γ (kN/m³) of the dimensions.
fn unit_weight(d: &Dimensions) -> f64 {
    d.density * d.g / 1000.0
}

/// The ring's mean radius (m) and the masonry's unit weight (kN/m³) of the dimensions.
pub(crate) fn masonry(d: &Dimensions) -> (f64, f64) {
    (d.radius, unit_weight(d))
}

#[derive(Args, Debug)]
pub(crate) struct VehicleArgs {
    /// A vehicle: its axle loads in kN, first axle first (e.g. 100,100). Needs the
    /// dimensions (--span --rise --ring --width --unit-weight, or --radius --depth --density).
    #[arg(
        long,
        value_delimiter = ',',
        allow_hyphen_values = true,
        conflicts_with = "live"
    )]
    pub(crate) axles: Vec<f64>,
    /// A uniform load on the road: Q,X1,X2 (kN/m^2 over X1 < X2, m from the left intrados
    /// springing), spread through the fill at each end; it stays put while axles move.
    #[arg(
        long,
        value_delimiter = ',',
        allow_hyphen_values = true,
        num_args = 1,
        conflicts_with = "live"
    )]
    patch: Vec<f64>,
    /// Metres between consecutive axles: one value for every gap, or one per gap.
    #[arg(
        long,
        value_delimiter = ',',
        allow_hyphen_values = true,
        requires = "axles"
    )]
    spacing: Vec<f64>,
    /// Road position of the first axle in metres from the left intrados springing
    /// (horizontally, towards the right springing); the vehicle travels left to right.
    #[arg(long, allow_hyphen_values = true, requires = "axles")]
    at: Option<f64>,
    /// Dispersal through the fill, horizontal per vertical (0: point loads).
    #[arg(long, default_value_t = 0.5, allow_hyphen_values = true)]
    dispersal: f64,
    /// Width of barrel one axle spreads over, in metres (default: the barrel width).
    #[arg(long, allow_hyphen_values = true, requires = "axles")]
    effective_width: Option<f64>,
    /// Find the critical position X* of the vehicle (the least collapse multiplier as it
    /// crosses) instead of taking --at.
    #[arg(long, requires = "axles", conflicts_with = "at")]
    pub(crate) critical: bool,
    /// Samples of the influence line with --critical (3 to 100000).
    #[arg(long, default_value_t = 41, allow_hyphen_values = true)]
    samples: usize,
    /// Width (m) to which each local minimum of the influence line is bracketed.
    #[arg(long, default_value_t = 1e-6, allow_hyphen_values = true)]
    bracket: f64,
    #[command(flatten)]
    threads: ThreadsArg,
}

/// A vehicle on its deck, ready to be placed.
pub(crate) struct Placed {
    pub(crate) vehicle: Vehicle,
    pub(crate) deck: Deck,
    pub(crate) spacing: Vec<f64>,
}

impl VehicleArgs {
    /// Whether a vehicle was given.
    pub(crate) fn given(&self) -> bool {
        !self.axles.is_empty() || !self.patch.is_empty()
    }

    /// The vehicle and its deck (with the dimensions the loads in kN need).
    pub(crate) fn build(&self, dims: Option<&Dimensions>) -> Result<Placed, InputError> {
        let Some(d) = dims else {
            return Err(InputError::Inconsistent {
                arg: "--axles",
                reason: "axle loads in kN need the dimensions: give --span --rise --ring \
                         --width --unit-weight (or --radius --depth --density)"
                    .into(),
            });
        };
        if !self.axles.is_empty() && self.at.is_none() && !self.critical {
            return Err(InputError::Inconsistent {
                arg: "--axles",
                reason: "place the vehicle with --at X (metres), or find its worst place with \
                         --critical"
                    .into(),
            });
        }
        let patch = match self.patch[..] {
            [] => None,
            [q, from, to] => Some(RoadPatch::new(q, from, to)?),
            _ => {
                return Err(InputError::Inconsistent {
                    arg: "--patch",
                    reason: format!("give Q,X1,X2 (three numbers), got {}", self.patch.len()),
                })
            }
        };
        let vehicle = match (self.axles.is_empty(), patch) {
            (true, Some(p)) => Vehicle::patch_only(p),
            (_, p) => {
                let v = Vehicle::new(&self.axles, &self.spacing)?;
                match p {
                    Some(p) => v.with_patch(p),
                    None => v,
                }
            }
        };
        let deck = Deck::new(
            d.radius,
            unit_weight(d),
            self.effective_width.unwrap_or(d.depth),
            self.dispersal,
        )?;
        let spacing = vehicle.offsets_m.windows(2).map(|w| w[1] - w[0]).collect();
        Ok(Placed {
            vehicle,
            deck,
            spacing,
        })
    }

    /// The road position given (with `--at`; 0 for a patch alone, which does not move).
    pub(crate) fn at(&self) -> Option<f64> {
        match self.axles.is_empty() {
            true => Some(0.0),
            false => self.at,
        }
    }

    /// How finely `--critical` looks, and on how many threads.
    pub(crate) fn search(&self) -> Result<Search, InputError> {
        Ok(Search {
            samples: self.samples,
            bracket_m: self.bracket,
            threads: self.threads.count()?,
        })
    }
}

impl Placed {
    /// The live load at λ = 1 in kN.
    pub(crate) fn total_kn(&self) -> f64 {
        self.vehicle.total_kn(self.deck.effective_width_m)
    }

    /// The vehicle's description at `at_m`, with what reaches the ring.
    pub(crate) fn json(
        &self,
        arch: &Arch,
        eta: f64,
        at_m: f64,
        load: &crate::load::LiveLoad,
    ) -> VehicleJson {
        let total = self.total_kn();
        let (carried, abutments) = self
            .deck
            .carried_kn(arch, eta, &self.vehicle, load)
            .unwrap_or((total, 0.0));
        VehicleJson {
            axles_kn: self.vehicle.axles_kn.clone(),
            patch: self.vehicle.patch.map(|p| [p.q_kn_m2, p.from_m, p.to_m]),
            spacing_m: self.spacing.clone(),
            at_m,
            dispersal: self.deck.dispersal,
            effective_width_m: self.deck.effective_width_m,
            carried_kn: carried,
            abutments_kn: abutments,
        }
    }
}
