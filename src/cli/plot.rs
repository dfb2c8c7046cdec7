//! `arch-enum plot`: the figures (limit curves, the arch with its lines and mechanism,
//! eccentricities, a margin map), as SVG or PNG.

use super::arch_args::{ArchArgs, WeightArg};
use super::io::{Exit, Io};
use super::mu_arg::MuArg;
use super::threads_arg::ThreadsArg;
use crate::arch::{check_mu, Arch, InputError};
use crate::settings::Settings;
use clap::{Args, Subcommand};

#[derive(Args, Debug)]
pub(crate) struct Output {
    /// Output file; its extension picks the format: .svg or .png (default: <figure>.svg, or
    /// <figure>.png with --png, in the current folder); `-` writes to standard output (SVG,
    /// or PNG with --png).
    #[arg(long)]
    out: Option<std::path::PathBuf>,
    /// PNG output (rendered in-process, fonts embedded); with --out the path must end in .png.
    #[arg(long)]
    png: bool,
    /// PNG width in pixels (100 to 8000).
    #[arg(long, default_value_t = 1200)]
    width: u32,
}

/// The format of the file written.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum Format {
    Svg,
    Png,
}

impl Output {
    /// The path written and its format: from the extension of --out (.svg or .png, any
    /// case), else `<name>.svg` or `<name>.png` with --png; `-` is standard output. Checked
    /// before any work.
    fn target(&self, name: &str) -> Result<(std::path::PathBuf, Format), InputError> {
        if !(100..=8000).contains(&self.width) {
            return Err(InputError::OutOfRange {
                arg: "--width",
                value: self.width.to_string(),
                range: "100 to 8000 pixels".into(),
            });
        }
        if self.out.as_deref() == Some(std::path::Path::new("-")) {
            let f = if self.png { Format::Png } else { Format::Svg };
            return Ok(("-".into(), f));
        }
        let Some(path) = &self.out else {
            let (ext, f) = if self.png {
                ("png", Format::Png)
            } else {
                ("svg", Format::Svg)
            };
            return Ok((format!("{name}.{ext}").into(), f));
        };
        let ext = path
            .extension()
            .and_then(|e| e.to_str())
            .map(str::to_ascii_lowercase);
        match (ext.as_deref(), self.png) {
            (Some("png"), _) => Ok((path.clone(), Format::Png)),
            (Some("svg"), false) => Ok((path.clone(), Format::Svg)),
            (Some("svg"), true) => Err(InputError::Inconsistent {
                arg: "--out",
                reason: format!(
                    "{} ends in .svg but --png asks for a PNG; valid extensions: .png (or .svg without --png)",
                    path.display()
                ),
            }),
            _ => Err(InputError::OutOfRange {
                arg: "--out",
                value: path.display().to_string(),
                range: "a file name ending in .svg or .png".into(),
            }),
        }
    }
}

/// The output flags of a figure whose command also takes the barrel's `--width` (metres):
/// the PNG width is `--png-width` there.
#[derive(Args, Debug)]
pub(crate) struct BridgeOutput {
    /// Output file; its extension picks the format: .svg or .png (default: <figure>.svg, or
    /// <figure>.png with --png, in the current folder); `-` writes to standard output (SVG,
    /// or PNG with --png).
    #[arg(long)]
    out: Option<std::path::PathBuf>,
    /// PNG output (rendered in-process, fonts embedded); with --out the path must end in .png.
    #[arg(long)]
    png: bool,
    /// PNG width in pixels (100 to 8000).
    #[arg(long, default_value_t = 1200)]
    png_width: u32,
}

impl BridgeOutput {
    fn output(&self) -> Output {
        Output {
            out: self.out.clone(),
            png: self.png,
            width: self.png_width,
        }
    }
}

/// The arch and the state a figure draws.
#[derive(Args, Debug)]
pub(crate) struct StateArgs {
    #[command(flatten)]
    arch: ArchArgs,
    #[command(flatten)]
    fill: super::bridge_args::ArchFillArgs,
    /// Friction coefficient mu > 0; `inf` for no sliding; `ms` for the arch's own mu_ms (with
    /// --eta above eta_ms: a purely sliding limit state of the vertical branch).
    #[arg(long, allow_negative_numbers = true)]
    mu: MuArg,
    /// Thickness ratio to draw (default: eta*(mu)); above eta* the state of greatest margin is drawn.
    #[arg(long, allow_negative_numbers = true)]
    eta: Option<f64>,
}

#[derive(Subcommand, Debug)]
pub(crate) enum Figure {
    /// The eta-mu limit curves of one or more symmetric openings in one figure.
    #[command(
        after_help = "Example:\n  arch-enum plot curve --alpha 0 --alpha 0.5236 --alpha 1.0 --out curves.png\n  arch-enum plot curve --alpha -1.2 --log-eta"
    )]
    Curve {
        /// Opening(s) in radians, -pi/2 < alpha < pi/2; repeat for several arches.
        #[arg(long, required = true, allow_negative_numbers = true)]
        alpha: Vec<f64>,
        /// Where self-weight acts.
        #[arg(long, value_enum, default_value = "centreline")]
        weight: WeightArg,
        /// Log-scale eta axis (for shallow arches, e.g. --alpha -1.2).
        #[arg(long)]
        log_eta: bool,
        /// With fill (one opening): the curve mu_min(eta), traced in eta, as `modes` gives it.
        #[command(flatten)]
        fill: super::bridge_args::FillArgs,
        #[command(flatten)]
        output: Output,
    },
    /// The arch to scale at eta*(mu) (or at --eta) with its lines of thrust and friction, and the mechanism.
    #[command(
        after_help = "Example:\n  arch-enum plot arch --alpha 0 --mu 0.35 --out arch.png\n  arch-enum plot arch --alpha 1.0 --mu 2 --eta 0.9\n  arch-enum plot arch --alpha 0.8 --mu 1.1540692474 --limit-states --out states.png"
    )]
    Arch {
        #[command(flatten)]
        state: StateArgs,
        /// Draw every limit state at this mu with eta in [eta_s, 2), one panel each (the one
        /// at eta_s when it carries a mechanism, then each above it: non-unique cases).
        #[arg(long, conflicts_with = "eta")]
        limit_states: bool,
        /// Draw extreme mechanism K (1, 2, ...) of the limit state's mechanism cone instead of
        /// its representative (the mean of the extreme rays, made symmetric on a symmetric
        /// pattern); the caption says "extreme K of N". An out-of-range K names the range.
        #[arg(long, conflicts_with = "limit_states", value_name = "K")]
        mechanism: Option<usize>,
        #[command(flatten)]
        output: Output,
    },
    /// Every limit state of a live load at (eta, mu), the collapse first: the arch with the load, its lines of thrust and friction under the load, and the mechanism.
    #[command(
        after_help = "Example:\n  arch-enum plot load --alpha 0 --blocks 27 --weight centroid --eta 0.1534 --mu inf --point-load-joint 8 --out load.png\n  arch-enum plot load --alpha 0 --eta 0.2 --mu 0.6 --horizontal"
    )]
    Load {
        #[command(flatten)]
        arch: ArchArgs,
        /// Thickness ratio eta = t/r, 0 < eta < 2 (or --ring with --span, --rise).
        #[arg(long, allow_negative_numbers = true)]
        eta: Option<f64>,
        /// Friction coefficient mu > 0; `inf` for no sliding.
        #[arg(long, allow_negative_numbers = true)]
        mu: f64,
        #[command(flatten)]
        live: super::load::LiveLoadArgs,
        #[command(flatten)]
        output: Output,
    },
    /// The load multiplier against friction at a fixed thickness: lambda_static and the collapse multiplier lambda (coloured by mode), the gap between them shaded. A vehicle stays at --at; PNG width is --png-width (--width is the barrel).
    #[command(
        after_help = "Example:\n  arch-enum plot load-curve --alpha 0 --blocks 20 --eta 0.3 --horizontal --out lambda_mu.png"
    )]
    LoadCurve {
        #[command(flatten)]
        curve: Box<super::load::LoadCurveArgs>,
        #[command(flatten)]
        output: BridgeOutput,
    },
    /// The influence line of a vehicle: its collapse multiplier against its road position, the local minima and the critical position X* marked, and the arch with the mechanism at X*.
    #[command(
        after_help = "Example:\n  arch-enum plot influence --span 10 --rise 5 --ring 0.6 --width 1 --unit-weight 20 --mu 0.6 --fill-weight 18 --fill-depth 0.3 --axles 100,100 --spacing 1.2 --critical --out influence.png"
    )]
    Influence {
        #[command(flatten)]
        load: Box<super::load::LoadArgs>,
        #[command(flatten)]
        output: BridgeOutput,
    },
    /// The eccentricities e_M = M/N and e_T = (T/N)/mu eta/2 against beta.
    Eccentricity {
        #[command(flatten)]
        state: StateArgs,
        #[command(flatten)]
        output: Output,
    },
    /// The atlas of uniqueness: over openings alpha and mu/mu_ms - 1, where the least thickness carries the only limit state, where others lie above it, where it carries none.
    #[command(
        after_help = "Example:\n  arch-enum plot atlas --out atlas.png\n  arch-enum plot atlas --blocks 24 --alpha-min 0.4 --alpha-max 1.1 --mu-max-factor 1.5"
    )]
    Atlas {
        #[command(flatten)]
        rect: super::atlas::RectArgs,
        #[command(flatten)]
        loads: super::atlas::LoadMapArgs,
        /// With --horizontal: the thickness eta up the map instead of eta/eta*(alpha, mu) (the
        /// cells of an opening at f eta*; a change at one eta across openings lies level).
        #[arg(long, requires = "horizontal")]
        eta_axis: bool,
        #[command(flatten)]
        output: Output,
    },
    /// A margin map over the eta-mu plane with the exact limit curve (computed on all cores).
    #[command(
        after_help = "Example:\n  arch-enum plot map --alpha 0 --out map.png\n  arch-enum plot map --alpha -1.2 --log-eta --threads 4"
    )]
    Map {
        #[command(flatten)]
        arch: ArchArgs,
        /// Grid cells along eta (4 to 400).
        #[arg(long, default_value_t = 36)]
        n_eta: usize,
        /// Grid cells along mu (4 to 400).
        #[arg(long, default_value_t = 48)]
        n_mu: usize,
        /// Log-scale eta axis, cells spaced geometrically (for shallow arches).
        #[arg(long)]
        log_eta: bool,
        #[command(flatten)]
        threads: ThreadsArg,
        #[command(flatten)]
        output: Output,
    },
}

pub(crate) fn run(figure: Figure, settings: &Settings, io: &mut Io) -> Exit {
    let bridge_output;
    let (name, output) = match &figure {
        Figure::Curve { output, .. } => ("curve", output),
        Figure::Arch { output, .. } => ("arch", output),
        Figure::Eccentricity { output, .. } => ("eccentricity", output),
        Figure::Load { output, .. } => ("load", output),
        Figure::LoadCurve { output, .. } => {
            bridge_output = output.output();
            ("load_curve", &bridge_output)
        }
        Figure::Influence { output, .. } => {
            bridge_output = output.output();
            ("influence", &bridge_output)
        }
        Figure::Map { output, .. } => ("map", output),
        Figure::Atlas { output, .. } => ("atlas", output),
    };
    let (path, format, width) = match output.target(name) {
        Ok((p, f)) => (p, f, output.width),
        Err(e) => return io.bad_input(&e),
    };
    let svg = match draw(figure, settings, io) {
        Ok(s) => s,
        Err(exit) => return exit,
    };
    let bytes = match format {
        Format::Svg => svg.into_bytes(),
        Format::Png => match crate::render::plot::svg_to_png(&svg, width) {
            Ok(b) => b,
            Err(e) => {
                io.err(&format!("no figure: {e}\n"));
                return Exit::NoAnswer;
            }
        },
    };
    if path.as_os_str() == "-" {
        io.out_bytes(&bytes);
        return Exit::Answered;
    }
    if let Err(e) = std::fs::write(&path, bytes) {
        io.err(&format!(
            "error: cannot write --out {}: {e}\n",
            path.display()
        ));
        return Exit::BadInput;
    }
    io.out(&format!("wrote {}\n", path.display()));
    Exit::Answered
}

/// The figure as an SVG document; bad input and "no figure" are reported on `io` and
/// come back as the command's exit.
pub(crate) fn draw(figure: Figure, settings: &Settings, io: &mut Io) -> Result<String, Exit> {
    use crate::figures;
    use crate::render::{plot_arch, plot_curve, plot_ecc, plot_map};
    let bar = super::progress::Progress::new("map");
    let progress = |done: usize, total: usize| bar.update(done, total);
    let drawn: Result<Result<String, String>, figures::NoFigure> = match figure {
        Figure::Curve {
            alpha,
            weight,
            fill,
            ..
        } if fill.given() => match fill_arch(&alpha, weight.into(), &fill) {
            Ok(a) => figures::fill_curve::fill_curve(&a, settings, crate::threads::available())
                .map(|d| crate::render::plot_fill_curve::svg(&d)),
            Err(e) => return Err(io.bad_input(&e)),
        },
        Figure::Curve {
            alpha,
            weight,
            log_eta,
            ..
        } => {
            let arches: Result<Vec<Arch>, InputError> = alpha
                .iter()
                .map(|&a| Arch::symmetric(a, weight.into()))
                .collect();
            match arches {
                Ok(a) => figures::curves(&a, settings).map(|d| plot_curve::svg(&d, log_eta)),
                Err(e) => return Err(io.bad_input(&e)),
            }
        }
        Figure::Arch {
            state: st,
            limit_states,
            mechanism,
            ..
        } => arch_figure(&st, limit_states, mechanism, settings, io)?,
        Figure::Load {
            arch,
            eta,
            mu,
            live,
            ..
        } => match arch.build().and_then(|a| {
            let eta = arch.eta(eta)?;
            check_mu(mu)?;
            let load = live.build(&a)?;
            Ok((a, eta, load))
        }) {
            Ok((a, eta, load)) => figures::load_scenes(&a, eta, mu, &load, settings)
                .map(|s| plot_arch::svg_panels(&s)),
            Err(e) => return Err(io.bad_input(&e)),
        },
        Figure::LoadCurve { curve, .. } if curve.json => {
            return Err(io.bad_input(&InputError::Inconsistent {
                arg: "--json",
                reason: "plot load-curve draws a figure; `arch-enum load-curve --json` prints the numbers".into(),
            }))
        }
        Figure::LoadCurve { curve, .. } => match curve.trace(settings) {
            Ok((title, traced)) => Ok(crate::render::plot_load_curve::svg(&title, &traced)),
            Err(e) => return Err(io.bad_input(&e)),
        },
        Figure::Influence { load, .. } => match influence(&load, settings) {
            Ok(drawn) => drawn,
            Err(e) => return Err(io.bad_input(&e)),
        },
        Figure::Eccentricity { state: st, .. } => match plot_inputs(&st, settings) {
            Ok((a, mu, eta)) => figures::scene(&a, mu, eta, settings).map(|s| plot_ecc::svg(&s)),
            Err(e) => return Err(io.bad_input(&e)),
        },
        Figure::Atlas { rect, loads, eta_axis, .. } => {
            Ok(atlas_figure(&rect, &loads, eta_axis, settings).map_err(|e| io.bad_input(&e))?)
        }
        Figure::Map {
            arch,
            n_eta,
            n_mu,
            log_eta,
            threads,
            ..
        } => {
            for (name, n) in [("--n-eta", n_eta), ("--n-mu", n_mu)] {
                if !(4..=400).contains(&n) {
                    let e = InputError::OutOfRange {
                        arg: name,
                        value: n.to_string(),
                        range: "whole numbers 4 to 400".into(),
                    };
                    return Err(io.bad_input(&e));
                }
            }
            let threads = match threads.count() {
                Ok(t) => t,
                Err(e) => return Err(io.bad_input(&e)),
            };
            let grid = figures::MapGrid {
                n_eta,
                n_mu,
                log_eta,
            };
            match arch.build_without_ring() {
                Ok(a) => figures::map(&a, grid, threads, settings, &progress)
                    .map(|m| plot_map::svg(&m, log_eta)),
                Err(e) => return Err(io.bad_input(&e)),
            }
        }
    };
    match drawn {
        Ok(Ok(s)) => Ok(s),
        Ok(Err(reason)) | Err(figures::NoFigure(reason)) => {
            io.err(&format!("no figure: {reason}\n"));
            Err(Exit::NoAnswer)
        }
    }
}

/// `plot atlas`: the atlas of uniqueness, or with `--horizontal` the load map (up its
/// thickness factor, or its thickness with `--eta-axis`).
fn atlas_figure(
    rect: &super::atlas::RectArgs,
    loads: &super::atlas::LoadMapArgs,
    eta_axis: bool,
    settings: &Settings,
) -> Result<Result<String, String>, InputError> {
    if loads.horizontal {
        let m = rect.load_map(loads, settings)?;
        return Ok(crate::render::plot_load_map::svg(&m, eta_axis));
    }
    Ok(crate::render::plot_atlas::svg(&rect.atlas(settings)?))
}

/// The arch, μ and thickness of a state figure (`--mu ms` resolved; `--eta` or `--ring`,
/// default η*), the inputs checked.
fn plot_inputs(
    st: &StateArgs,
    settings: &Settings,
) -> Result<(Arch, f64, Option<f64>), InputError> {
    let a = st.fill.build(&st.arch)?.0;
    let mu = st.mu.resolve(&a, settings)?;
    check_mu(mu)?;
    let eta = match (st.eta, st.arch.ring) {
        (None, None) => None,
        _ => Some(st.arch.eta(st.eta)?),
    };
    Ok((a, mu, eta))
}

/// The influence figure of a vehicle with `--critical`: the line, and the arch at X* with
/// the collapse mechanism there.
fn influence(
    a: &super::load::LoadArgs,
    settings: &Settings,
) -> Result<Result<Result<String, String>, crate::figures::NoFigure>, InputError> {
    if a.json {
        return Err(InputError::Inconsistent {
            arg: "--json",
            reason: "plot influence draws a figure; `arch-enum load --critical --json` prints the numbers".into(),
        });
    }
    let p = super::load::prepare(a, settings)?;
    let Some((c, vehicle_kn)) = p.critical() else {
        return Err(InputError::Inconsistent {
            arg: "--critical",
            reason: "plot influence draws a vehicle crossing: give --axles and --critical".into(),
        });
    };
    let scenes = match crate::figures::load_scenes(&p.arch, p.eta, p.mu, &p.load, settings) {
        Ok(s) => s,
        Err(e) => return Ok(Err(e)),
    };
    let title = format!(
        "{} — η = {}, μ = {}: influence line of the vehicle",
        crate::render::plot::arch_label(&p.arch),
        short(p.eta),
        short(p.mu)
    );
    let at = c.minima.first().map_or(0.0, |m| m.at_m);
    let scene = scenes
        .first()
        .map(|(label, s)| (format!("the vehicle at X* = {} m: {label}", short(at)), s));
    Ok(Ok(crate::render::plot_influence::svg(
        &title,
        c,
        Some(vehicle_kn),
        scene,
    )))
}

fn short(v: f64) -> String {
    crate::render::plot::short_num(v)
}

/// `plot arch`: the limit state at η*(μ) (with extreme mechanism `mechanism`, if given),
/// the state of greatest margin at --eta, or every limit state (`limit_states`).
fn arch_figure(
    st: &StateArgs,
    limit_states: bool,
    mechanism: Option<usize>,
    settings: &Settings,
    io: &mut Io,
) -> Result<Result<Result<String, String>, crate::figures::NoFigure>, Exit> {
    use crate::figures;
    use crate::render::plot_arch;
    Ok(match plot_inputs(st, settings) {
        Ok((a, mu, _)) if limit_states => {
            figures::limit_scenes(&a, mu, settings).map(|s| plot_arch::svg_panels(&s))
        }
        Ok((a, mu, eta)) => match figures::scene(&a, mu, eta, settings) {
            Ok(s) => match mechanism {
                None => Ok(plot_arch::svg(&s)),
                Some(k) => match figures::extreme_scene(s, k, settings) {
                    Ok(s) => Ok(plot_arch::svg(&s)),
                    Err(figures::ExtremeChoice::NoMechanism) => Err(figures::NoFigure(
                        "--mechanism: the state drawn is safe and has no mechanism".into(),
                    )),
                    Err(figures::ExtremeChoice::OutOfRange(n)) => {
                        return Err(io.bad_input(&InputError::OutOfRange {
                            arg: "--mechanism",
                            value: k.to_string(),
                            range: format!("1 to {n} (the extreme mechanisms of this limit state)"),
                        }))
                    }
                },
            },
            Err(e) => Err(e),
        },
        Err(e) => return Err(io.bad_input(&e)),
    })
}

/// The one arch of `plot curve` with fill (the fill in ratios: `--fill-ratio --fill-height`).
fn fill_arch(
    alpha: &[f64],
    weight: crate::arch::WeightModel,
    fill: &super::bridge_args::FillArgs,
) -> Result<Arch, InputError> {
    let [a] = alpha else {
        return Err(InputError::Inconsistent {
            arg: "--alpha",
            reason: "with fill, plot curve draws one opening (give --alpha once)".into(),
        });
    };
    let arch = Arch::symmetric(*a, weight)?;
    match fill.build(None)? {
        Some((f, _)) => Ok(arch.with_fill(f)),
        None => Ok(arch),
    }
}
