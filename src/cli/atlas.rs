//! `arch-enum atlas`: where the least thickness carries the only limit state, over a
//! rectangle of openings and friction coefficients.

use super::arch_args::WeightArg;
use super::io::{to_json, Exit, Io};
use super::threads_arg::ThreadsArg;
use crate::arch::InputError;
use crate::atlas::loads::{load_map, LoadGrid, LoadMap};
use crate::atlas::{atlas, Atlas, Rectangle};
use crate::render::{json, table};
use crate::settings::Settings;
use clap::Args;

/// The rectangle of an atlas (shared with `plot atlas`).
#[derive(Args, Debug)]
pub(crate) struct RectArgs {
    /// The least opening alpha of the symmetric arches (radians, -pi/2 < alpha < pi/2).
    #[arg(long, default_value_t = -1.4, allow_hyphen_values = true)]
    alpha_min: f64,
    /// The largest opening (radians, above --alpha-min).
    #[arg(long, default_value_t = 1.2, allow_hyphen_values = true)]
    alpha_max: f64,
    /// mu runs from mu_ms(alpha) to this times mu_ms(alpha) (1.00001 to 1e6).
    #[arg(long, default_value_t = 10.0, allow_hyphen_values = true)]
    mu_max_factor: f64,
    /// Where self-weight acts.
    #[arg(long, value_enum, default_value = "centreline")]
    weight: WeightArg,
    /// N equal voussoirs (1 to 100000; default: continuous joints).
    #[arg(long, allow_hyphen_values = true)]
    blocks: Option<usize>,
    /// Openings sampled, evenly spaced (2 to 2000).
    #[arg(long, default_value_t = 53, allow_hyphen_values = true)]
    columns: usize,
    /// Friction coefficients sampled per opening, geometric in mu/mu_ms - 1 from 1e-6 (2 to 2000).
    #[arg(long, default_value_t = 40, allow_hyphen_values = true)]
    samples: usize,
    /// Certify the ends of every located bracket and one sample of every run (`certify`),
    /// each re-proved by the verifier (`verify`); with --horizontal, every reduced cell.
    #[arg(long)]
    certify: bool,
    #[command(flatten)]
    threads: ThreadsArg,
}

impl RectArgs {
    /// The load map these flags and `loads` ask for (a bad range is named by its flag).
    pub(crate) fn load_map(
        &self,
        loads: &LoadMapArgs,
        settings: &Settings,
    ) -> Result<LoadMap, InputError> {
        let grid = LoadGrid {
            rect: self.rectangle(),
            mus: loads.mu.clone(),
            factors: loads.factors.unwrap_or(12),
            factor_max: loads.factor_max.unwrap_or(4.0),
        };
        let threads = self.threads.count()?;
        let bar = super::progress::Progress::new("atlas");
        load_map(&grid, settings, threads, &|done, total| {
            bar.update(done, total)
        })
    }

    /// The rectangle of these flags.
    fn rectangle(&self) -> Rectangle {
        Rectangle {
            alpha_min: self.alpha_min,
            alpha_max: self.alpha_max,
            mu_max_factor: self.mu_max_factor,
            weight: self.weight.into(),
            blocks: self.blocks,
            columns: self.columns,
            samples: self.samples,
            certify: self.certify,
        }
    }

    /// The atlas these flags ask for (a bad range is named by its flag).
    pub(crate) fn atlas(&self, settings: &Settings) -> Result<Atlas, InputError> {
        let rect = self.rectangle();
        let threads = self.threads.count()?;
        let bar = super::progress::Progress::new("atlas");
        atlas(&rect, settings, threads, &|done, total| {
            bar.update(done, total)
        })
    }
}

/// The load map's flags (shared with `plot atlas`).
#[derive(Args, Debug)]
pub(crate) struct LoadMapArgs {
    /// Map the collapse multiplier of a horizontal acceleration (towards the right
    /// springing) instead: lambda_c/lambda_static over the openings and the thicknesses
    /// eta = f eta*(alpha, mu), at each --mu. Each cell is a complete load search (tens of
    /// ms on a continuous arch): mind --columns.
    #[arg(long, requires = "mu", conflicts_with_all = ["samples", "mu_max_factor"])]
    pub(crate) horizontal: bool,
    /// With --horizontal: the friction coefficients, comma-separated (0 < mu < inf).
    #[arg(
        long,
        value_delimiter = ',',
        allow_hyphen_values = true,
        requires = "horizontal"
    )]
    mu: Vec<f64>,
    /// With --horizontal: thicknesses per opening, f geometric from 1.02 to --factor-max
    /// (2 to 200; default 12).
    #[arg(long, allow_hyphen_values = true, requires = "horizontal")]
    factors: Option<usize>,
    /// With --horizontal: the thickest ring as a factor over eta* (1.02 < F <= 100; default 4).
    #[arg(long, allow_hyphen_values = true, requires = "horizontal")]
    factor_max: Option<f64>,
}

#[derive(Args, Debug)]
pub(crate) struct AtlasArgs {
    #[command(flatten)]
    rect: RectArgs,
    #[command(flatten)]
    loads: LoadMapArgs,
    /// Print one JSON document instead of tables.
    #[arg(long)]
    pub(crate) json: bool,
}

/// `atlas --horizontal`: the load map.
fn run_load_map(a: &AtlasArgs, settings: &Settings, io: &mut Io) -> Exit {
    let map = match a.rect.load_map(&a.loads, settings) {
        Ok(m) => m,
        Err(e) => return io.bad_input(&e),
    };
    if a.json {
        io.out(&to_json(&json::load_map(&map)));
    } else {
        io.out(&table::load_map(&map));
    }
    Exit::Answered
}

pub(crate) fn run(a: AtlasArgs, settings: &Settings, io: &mut Io) -> Exit {
    if a.loads.horizontal {
        return run_load_map(&a, settings, io);
    }
    let at = match a.rect.atlas(settings) {
        Ok(at) => at,
        Err(e) => return io.bad_input(&e),
    };
    if a.json {
        io.out(&to_json(&json::atlas(&at)));
    } else {
        io.out(&table::atlas(&at));
    }
    Exit::Answered
}
