//! `arch-enum load`: the collapse multiplier of a live load (horizontal acceleration or a
//! point load) at a given thickness and friction, with every limit state; `load-curve`:
//! the same sampled over a range of friction coefficients.

use super::arch_args::ArchArgs;
use super::bridge_args::{FillArgs, Placed, VehicleArgs};
use super::dimension_args::{sized, DimensionArgs};
use super::io::{geometry_text, json_with_geometry, Exit, Io};
use crate::arch::{fmt_value, Arch, InputError, JointLayout};
use crate::bridge::critical::{critical, Critical};
use crate::friction::least_friction;
use crate::limit_curve::mu_grid;
use crate::load::LiveLoad;
use crate::multiplier::{check_load, survey_partial, trace, LoadCurve, LoadOutcome};
use crate::render::load::{curve_json, curve_table, json, table, LoadQuestion};
use crate::settings::Settings;
use clap::{ArgGroup, Args};

/// Which live load (exactly one).
#[derive(Args, Debug)]
#[command(group(ArgGroup::new("live").required(true).args(["horizontal", "horizontal_left", "point_load", "point_load_deg", "point_load_joint"])))]
pub(crate) struct LiveLoadArgs {
    /// A horizontal body force lambda x self-weight towards +x (the right springing):
    /// a constant horizontal acceleration lambda g.
    #[arg(long)]
    horizontal: bool,
    /// The same towards -x (the left springing).
    #[arg(long)]
    horizontal_left: bool,
    /// A vertical point load lambda (units of gamma t d r) at the extrados point of angle B
    /// (radians, between the springings; at a joint or inside a voussoir).
    #[arg(long, value_name = "B", allow_hyphen_values = true)]
    point_load: Option<f64>,
    /// The same with the angle in degrees. On a discrete arch an angle within 1e-9 rad of
    /// a joint is that joint.
    #[arg(long, value_name = "DEG", allow_hyphen_values = true)]
    point_load_deg: Option<f64>,
    /// A vertical point load at the extrados point of joint K of a discrete arch, counted
    /// from the right springing (0) to the left one.
    #[arg(long, value_name = "K")]
    point_load_joint: Option<usize>,
}

impl LiveLoadArgs {
    /// The load on `arch`, checked (a point load must lie on the arch; the error names the
    /// flag the angle came in).
    pub(crate) fn build(&self, arch: &Arch) -> Result<LiveLoad, InputError> {
        let joints: &[f64] = match arch.layout() {
            JointLayout::Discrete(j) => j,
            JointLayout::Continuous => &[],
        };
        let snap = |b: f64| arch.snap_to_joint(b);
        let load = if self.horizontal {
            LiveLoad::Horizontal {
                towards_right: true,
            }
        } else if self.horizontal_left {
            LiveLoad::Horizontal {
                towards_right: false,
            }
        } else if let Some(b) = self.point_load {
            LiveLoad::Point { beta: snap(b) }
        } else if let Some(d) = self.point_load_deg {
            let load = LiveLoad::Point {
                beta: snap(d.to_radians()),
            };
            return check_load(arch, &load)
                .map(|_| load)
                .map_err(|_| InputError::OutOfRange {
                    arg: "--point-load-deg",
                    value: fmt_value(d),
                    range: format!(
                        "between the springings, {} to {} degrees",
                        arch.beta_right().to_degrees(),
                        arch.beta_left().to_degrees()
                    ),
                });
        } else if let Some(k) = self.point_load_joint {
            match joints.get(k) {
                Some(&beta) => LiveLoad::Point { beta },
                None => {
                    return Err(InputError::OutOfRange {
                        arg: "--point-load-joint",
                        value: k.to_string(),
                        range: if joints.is_empty() {
                            "a joint index of a discrete arch (give --blocks or --joints)".into()
                        } else {
                            format!("0 <= K <= {}", joints.len() - 1)
                        },
                    })
                }
            }
        } else {
            return Err(no_live_load());
        };
        check_load(arch, &load).map(|_| load)
    }
}

#[derive(Args, Debug)]
#[command(mut_group("live", |g| g.required(false)))]
pub(crate) struct LoadArgs {
    #[command(flatten)]
    arch: ArchArgs,
    /// Thickness ratio eta = t/r of the arch, 0 < eta < 2 (or --ring with --span, --rise).
    #[arg(long, allow_hyphen_values = true)]
    eta: Option<f64>,
    /// Friction coefficient mu = tan(phi) > 0; `inf` for no sliding.
    #[arg(long, allow_hyphen_values = true)]
    mu: f64,
    #[command(flatten)]
    live: LiveLoadArgs,
    #[command(flatten)]
    bridge: BridgeFlags,
    /// Print one JSON document instead of text.
    #[arg(long)]
    pub(crate) json: bool,
}

/// The engineer's flags of a load question, shared by `load` and `certify`: the dimensions,
/// a vehicle and the fill.
#[derive(Args, Debug)]
pub(crate) struct BridgeFlags {
    #[command(flatten)]
    dims: DimensionArgs,
    #[command(flatten)]
    pub(crate) vehicle: VehicleArgs,
    #[command(flatten)]
    pub(crate) fill: FillArgs,
}

impl BridgeFlags {
    /// The fill of these flags on the arch of `arch_args`, without a thickness (`None`
    /// without fill flags): the ring's radius (with `--ring`) and the masonry's unit weight
    /// convert `--fill-weight --fill-depth`.
    pub(crate) fn fill_on(
        &self,
        arch_args: &ArchArgs,
    ) -> Result<Option<crate::bridge::Fill>, InputError> {
        let dims = self.dims.build(arch_args.geometry()?)?;
        let fill = self
            .fill
            .build(dims.as_ref().map(super::bridge_args::masonry))?;
        Ok(fill.map(|(f, _)| f))
    }
}

/// A load question as the flags give it: the engineer's geometry and dimensions, η, the
/// arch with its fill, the vehicle placed (at `--at` or its critical position) and the load.
pub(crate) struct Prepared {
    geometry: Option<crate::bridge::Geometry>,
    dims: Option<crate::render::table::Dimensions>,
    pub(crate) eta: f64,
    pub(crate) mu: f64,
    pub(crate) arch: Arch,
    fill: Option<crate::render::json::FillJson>,
    bridge: Option<Bridge>,
    pub(crate) load: LiveLoad,
}

impl Prepared {
    /// The critical position found with `--critical`, and the vehicle's total (kN).
    pub(crate) fn critical(&self) -> Option<(&Critical, f64)> {
        let b = self.bridge.as_ref()?;
        Some((b.critical.as_ref()?, b.placed.total_kn()))
    }

    /// Where the vehicle stands (m from the left intrados springing), if a vehicle is given.
    pub(crate) fn vehicle_at(&self) -> Option<f64> {
        self.bridge.as_ref().map(|b| b.at_m)
    }
}

/// The question of `a`, every input checked (the critical position searched with
/// `--critical`).
pub(crate) fn prepare(a: &LoadArgs, settings: &Settings) -> Result<Prepared, InputError> {
    prepare_parts((&a.arch, a.eta, a.mu), Some(&a.live), &a.bridge, settings)
}

/// The question of the arch flags with η and μ, a live load (`None`: a vehicle or none)
/// and the bridge flags, every input checked.
pub(crate) fn prepare_parts(
    (arch_args, eta, mu): (&ArchArgs, Option<f64>, f64),
    live: Option<&LiveLoadArgs>,
    flags: &BridgeFlags,
    settings: &Settings,
) -> Result<Prepared, InputError> {
    let (geometry, dims, eta) = sized(arch_args, &flags.dims, eta)?;
    let arch = arch_args.build()?;
    let fill = flags
        .fill
        .build(dims.as_ref().map(super::bridge_args::masonry))?;
    let arch = match &fill {
        Some((f, _)) => arch.with_fill(*f),
        None => arch,
    };
    let bridge = Bridge::build(&flags.vehicle, &arch, eta, mu, dims.as_ref(), settings)?;
    let load = match (&bridge, live) {
        (Some(b), _) => b.load,
        (None, Some(live)) => live.build(&arch)?,
        (None, None) => return Err(no_live_load()),
    };
    Ok(Prepared {
        geometry,
        dims,
        eta,
        mu,
        arch,
        fill: fill.map(|f| f.1),
        bridge,
        load,
    })
}

/// The error of a load question without a load.
fn no_live_load() -> InputError {
    InputError::Inconsistent {
        arg: "--horizontal/--point-load/--axles",
        reason: "give a live load: --horizontal, --horizontal-left, --point-load, \
                 --point-load-deg, --point-load-joint, or a vehicle with --axles"
            .into(),
    }
}

pub(crate) fn run(a: LoadArgs, settings: &Settings, io: &mut Io) -> Exit {
    let p = match prepare(&a, settings) {
        Ok(p) => p,
        Err(e) => return io.bad_input(&e),
    };
    // at the critical position its search has surveyed the load already
    let known = p
        .bridge
        .as_ref()
        .and_then(|b| b.critical.as_ref()?.at_critical.as_ref())
        .map(|(_, sv)| Ok(LoadOutcome::Limits(sv.clone())));
    let outcome = match known.map_or_else(
        || survey_partial(&p.arch, p.eta, p.mu, &p.load, settings),
        Ok,
    ) {
        Ok(o) => o,
        Err(e) => return io.bad_input(&e),
    };
    let q = p.question(p.mu);
    if a.json {
        io.out(&p.framed_json(&json(&q, &outcome)));
    } else {
        io.out(&(p.framed_head() + &table(&q, &outcome)));
    }
    match outcome {
        Ok(LoadOutcome::Limits(_)) => Exit::Answered,
        _ => Exit::NoAnswer,
    }
}

impl Prepared {
    /// The question as the renderers take it, at friction `mu`.
    fn question(&self, mu: f64) -> LoadQuestion<'_> {
        LoadQuestion {
            arch: &self.arch,
            eta: self.eta,
            mu,
            load: self.load,
            dims: self.dims,
            vehicle_kn: self.bridge.as_ref().map(|b| b.placed.total_kn()),
        }
    }

    /// The vehicle's document and the critical search, on a bridge (fill or a vehicle).
    fn bridged(&self) -> Option<(Option<crate::render::json::VehicleJson>, Option<&Critical>)> {
        (self.fill.is_some() || self.bridge.is_some()).then(|| {
            let vehicle = self
                .bridge
                .as_ref()
                .map(|b| b.placed.json(&self.arch, self.eta, b.at_m, &self.load));
            (
                vehicle,
                self.bridge.as_ref().and_then(|b| b.critical.as_ref()),
            )
        })
    }

    /// `doc` with the geometry's keys and, on a bridge, the scope, fill, vehicle and critical
    /// search after its own.
    fn framed_json<T: serde::Serialize>(&self, doc: &T) -> String {
        match self.bridged() {
            None => json_with_geometry(doc, self.geometry, None),
            Some((vehicle, critical)) => {
                let kn = self.bridge.as_ref().map(|b| b.placed.total_kn());
                let keys = crate::render::json::bridge(self.fill.clone(), vehicle, critical, kn);
                json_with_geometry(&WithBridge { doc, keys: &keys }, self.geometry, None)
            }
        }
    }

    /// The lines before the answer: the geometry and, on a bridge, its own scope (not the
    /// bare ring's), the fill, the vehicle and the critical search.
    fn framed_head(&self) -> String {
        let lines = self.bridged().map_or(String::new(), |(vehicle, critical)| {
            let kn = self.bridge.as_ref().map(|b| b.placed.total_kn());
            crate::render::table::bridge(self.fill.as_ref(), vehicle.as_ref(), critical, kn)
        });
        let head = geometry_text(self.geometry, None);
        match lines.is_empty() {
            false => head.replace(crate::render::geometry::RING_SCOPE, "") + &lines,
            true => head,
        }
    }
}

/// A load document with the bridge keys after its own.
#[derive(serde::Serialize)]
struct WithBridge<'a, T> {
    #[serde(flatten)]
    doc: &'a T,
    #[serde(flatten)]
    keys: &'a crate::render::json::BridgeJson,
}

/// The last critical-position search of this process, with its inputs written out in
/// full: `report` runs `load --critical` and `plot influence` on the same flags in one
/// process, and the second takes the first's answer (a pure function of these inputs)
/// instead of searching again.
static LAST_CRITICAL: std::sync::Mutex<Option<(String, Critical)>> = std::sync::Mutex::new(None);

/// [`critical`], or the last answer of this process for the very same inputs.
#[allow(clippy::too_many_arguments)]
fn critical_once(
    arch: &Arch,
    eta: f64,
    mu: f64,
    deck: &crate::bridge::Deck,
    vehicle: &crate::bridge::Vehicle,
    search: crate::bridge::Search,
    settings: &Settings,
) -> Result<Critical, InputError> {
    let key = format!("{arch:?} {eta:?} {mu:?} {deck:?} {vehicle:?} {search:?} {settings:?}");
    let last = LAST_CRITICAL.lock().ok().and_then(|g| g.clone());
    if let Some((_, c)) = last.filter(|(k, _)| *k == key) {
        return Ok(c);
    }
    let c = critical(arch, eta, mu, deck, vehicle, search, settings)?;
    if let Ok(mut g) = LAST_CRITICAL.lock() {
        *g = Some((key, c.clone()));
    }
    Ok(c)
}

/// A vehicle placed at `--at`, or at its critical position with `--critical`.
struct Bridge {
    placed: Placed,
    at_m: f64,
    load: LiveLoad,
    critical: Option<Critical>,
}

impl Bridge {
    fn build(
        vehicle: &VehicleArgs,
        arch: &Arch,
        eta: f64,
        mu: f64,
        dims: Option<&crate::render::table::Dimensions>,
        settings: &Settings,
    ) -> Result<Option<Bridge>, InputError> {
        if !vehicle.given() {
            return Ok(None);
        }
        let placed = vehicle.build(dims)?;
        let (at_m, critical) = match vehicle.at() {
            Some(at) => (at, None),
            None => {
                let c = critical_once(
                    arch,
                    eta,
                    mu,
                    &placed.deck,
                    &placed.vehicle,
                    vehicle.search()?,
                    settings,
                )?;
                let at = c.minima.first().map_or_else(
                    || placed.deck.crossing(arch, eta, &placed.vehicle).0,
                    |m| m.at_m,
                );
                (at, Some(c))
            }
        };
        let load = placed.deck.place(arch, eta, &placed.vehicle, at_m)?;
        Ok(Some(Bridge {
            placed,
            at_m,
            load,
            critical,
        }))
    }
}

#[derive(Args, Debug)]
#[command(mut_group("live", |g| g.required(false)))]
pub(crate) struct LoadCurveArgs {
    #[command(flatten)]
    pub(crate) arch: ArchArgs,
    /// Thickness ratio eta = t/r of the arch, 0 < eta < 2 (or --ring with --span, --rise).
    #[arg(long, allow_hyphen_values = true)]
    eta: Option<f64>,
    #[command(flatten)]
    live: LiveLoadArgs,
    /// The dimensions, a vehicle at --at (it stays there as mu varies) and the fill, as for
    /// `load`.
    #[command(flatten)]
    bridge: BridgeFlags,
    /// Smallest mu (default: mu_ms (1 + 1e-6), the least friction at which the arch can
    /// stand at all).
    #[arg(long, allow_hyphen_values = true)]
    mu_min: Option<f64>,
    /// Largest finite mu (default: 10 * mu_min); a last row at mu = inf follows.
    #[arg(long, allow_hyphen_values = true)]
    mu_max: Option<f64>,
    /// Number of finite samples (1 to 100000).
    #[arg(long, default_value_t = 12, allow_hyphen_values = true)]
    points: usize,
    /// Print one JSON document instead of a table.
    #[arg(long)]
    pub(crate) json: bool,
}

/// The friction coefficients of a λ–μ curve at thickness `eta`: `points` geometrically
/// spaced from `mu_min` (default μ_ms (1 + 1e-6); with fill, where μ_ms moves with η, the
/// least friction at which this thickness stands) to `mu_max` (default 10 μ_min), then μ = ∞.
pub(crate) fn mu_samples(
    (arch, eta): (&Arch, f64),
    mu_min: Option<f64>,
    mu_max: Option<f64>,
    points: usize,
    settings: &Settings,
) -> Result<Vec<f64>, InputError> {
    crate::limit_curve::check_mu_range(mu_min, mu_max)?;
    let mu_ms = match arch.fill() {
        Some(_) => match crate::assess::least_friction_for(arch, eta, settings) {
            crate::assess::LeastFriction::Finite { mu, .. } if mu.is_finite() => Some(mu),
            _ => None,
        },
        None => least_friction(arch, settings).ok().flatten(),
    };
    let lo = mu_min.unwrap_or_else(|| mu_ms.map_or(0.01, |m| (m * (1.0 + 1e-6)).max(1e-6)));
    let hi = mu_max.unwrap_or(10.0 * lo);
    let mut grid = mu_grid(lo, hi, points)?;
    grid.push(f64::INFINITY);
    Ok(grid)
}

pub(crate) fn run_curve(a: LoadCurveArgs, settings: &Settings, io: &mut Io) -> Exit {
    let p = match a.question(settings) {
        Ok(p) => p,
        Err(e) => return io.bad_input(&e),
    };
    let bar = super::progress::Progress::new("load-curve");
    let (arch, eta, load) = (&p.arch, p.eta, &p.load);
    let curve = match mu_samples((arch, eta), a.mu_min, a.mu_max, a.points, settings)
        .and_then(|grid| trace(arch, eta, load, &grid, settings, &|d, t| bar.update(d, t)))
    {
        Ok(s) => s,
        Err(e) => return io.bad_input(&e),
    };
    let q = LoadQuestion {
        dims: None,
        vehicle_kn: None,
        ..p.question(f64::INFINITY)
    };
    if a.json {
        io.out(&p.framed_json(&curve_json(&q, &curve)));
    } else {
        io.out(&(p.framed_head() + &curve_table(&q, &curve)));
    }
    Exit::Answered
}

impl LoadCurveArgs {
    /// The question: the arch with its fill, η and the load (a vehicle stays at `--at`: its
    /// critical position moves with μ).
    fn question(&self, settings: &Settings) -> Result<Prepared, InputError> {
        if self.bridge.vehicle.critical {
            return Err(InputError::Inconsistent {
                arg: "--critical",
                reason: "load-curve keeps the vehicle at --at (its critical position moves \
                         with mu): give --at, or run load --critical at each mu"
                    .into(),
            });
        }
        prepare_parts(
            (&self.arch, self.eta, f64::INFINITY),
            Some(&self.live),
            &self.bridge,
            settings,
        )
    }

    /// The figure's title and the traced curve (the `plot load-curve` figure).
    pub(crate) fn trace(&self, settings: &Settings) -> Result<(String, LoadCurve), InputError> {
        let Prepared {
            arch, eta, load, ..
        } = self.question(settings)?;
        let grid = mu_samples(
            (&arch, eta),
            self.mu_min,
            self.mu_max,
            self.points,
            settings,
        )?;
        let samples = trace(&arch, eta, &load, &grid, settings, &|_, _| {})?;
        let what = match load {
            LiveLoad::Horizontal { .. } => "horizontal acceleration".to_string(),
            LiveLoad::Point { beta } => format!("point load at {:.2}°", beta.to_degrees()),
            LiveLoad::Pressure(_) => "vehicle".to_string(),
        };
        Ok((
            format!(
                "{}{} — {what}, η = {}: λ against μ",
                crate::render::plot::arch_label(&arch),
                if arch.fill().is_some() {
                    " with fill"
                } else {
                    ""
                },
                eta
            ),
            samples,
        ))
    }
}
