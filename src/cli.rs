//! The command-line interface: argument parsing, one library call, rendering, and
//! the single place where outcomes become exit codes (0 ok, 1 no answer, 2 bad input).

use crate::arch::{Arch, InputError, WeightModel};
use crate::friction::least_friction;
use crate::limit::{solve, Outcome};
use crate::limit_curve::{mu_grid, sample};
use crate::render::{json, table};
use crate::settings::Settings;
use clap::{Args, Parser, Subcommand, ValueEnum};
use std::ffi::OsString;
use std::io::Write;

/// Exit status: success.
pub const EXIT_OK: i32 = 0;
/// Exit status: the question has no answer for these inputs (no equilibrium, unresolved).
pub const EXIT_NO_ANSWER: i32 = 1;
/// Exit status: bad input.
pub const EXIT_BAD_INPUT: i32 = 2;

#[derive(Parser, Debug)]
#[command(
    name = "arch-enum",
    version,
    about = "Exact limit analysis of circular masonry arches with limited friction",
    long_about = "Exact limit analysis of circular masonry arches with limited friction.\n\n\
Lengths are divided by the mean radius r (eta = t/r); angles are radians measured \
counter-clockwise from the horizontal through the centre (a symmetric arch of opening \
alpha has beta_R = -alpha, beta_L = pi + alpha).",
    after_help = "Examples:\n  arch-enum solve --alpha 0 --mu inf          Couplet-Heyman semicircle\n  \
arch-enum solve --alpha-deg 30 --mu 0.8 --json\n  \
arch-enum solve --beta-right -0.2 --beta-left 3.0 --mu 0.5 --explain\n  \
arch-enum curve --alpha 0 --mu-min 0.31 --mu-max 1 --points 12"
)]
struct Cli {
    #[command(subcommand)]
    command: Command,
}

#[derive(Subcommand, Debug)]
enum Command {
    /// The least thickness eta*(mu), the collapse mode, the active pattern, the reactions and a mechanism.
    #[command(
        after_help = "Example:\n  arch-enum solve --alpha 0 --mu 0.35\n  arch-enum solve --alpha 0.5 --blocks 12 --mu inf --json"
    )]
    Solve {
        #[command(flatten)]
        arch: ArchArgs,
        /// Friction coefficient mu = tan(phi) > 0; `inf` for no sliding.
        #[arg(long, allow_negative_numbers = true)]
        mu: f64,
        /// List every pattern tried and why it was kept or rejected.
        #[arg(long)]
        explain: bool,
        /// Print one JSON document instead of tables.
        #[arg(long)]
        json: bool,
    },
    /// The whole eta-mu limit curve: branches with their collapse modes and exact corners.
    #[command(
        after_help = "Example:\n  arch-enum modes --alpha 1.0\n  arch-enum modes --alpha-deg 30 --json\n  arch-enum modes --alpha 0 --blocks 20"
    )]
    Modes {
        #[command(flatten)]
        arch: ArchArgs,
        /// Print one JSON document instead of tables.
        #[arg(long)]
        json: bool,
    },
    /// A certificate for eta*(mu): an admissible state at eta_hi (upper bound), a Farkas certificate at eta_lo (lower bound), the limit state.
    #[command(
        after_help = "Example:\n  arch-enum certify --alpha 0 --mu 0.35 --out cert.json\n  arch-enum verify cert.json"
    )]
    Certify {
        #[command(flatten)]
        arch: ArchArgs,
        /// Friction coefficient mu > 0; `inf` for no sliding.
        #[arg(long, allow_negative_numbers = true)]
        mu: f64,
        /// Target relative gap (eta_hi - eta_lo)/eta_hi, 1e-15 to 1e-4; widened tenfold until provable.
        #[arg(long, default_value_t = 1e-12, allow_negative_numbers = true)]
        gap: f64,
        /// Write the certificate here instead of standard output.
        #[arg(long)]
        out: Option<std::path::PathBuf>,
        /// Print a JSON summary instead of text (the certificate itself is always JSON).
        #[arg(long)]
        json: bool,
    },
    /// Re-checks a certificate independently (no LP, no solver); exit 0 only if it holds.
    Verify {
        /// The certificate file.
        file: std::path::PathBuf,
        /// Print one JSON document instead of text.
        #[arg(long)]
        json: bool,
    },
    /// Pictures: limit curves, the arch with its lines and mechanism, eccentricities, a margin map (SVG, or PNG with --png).
    Plot {
        #[command(subcommand)]
        figure: Figure,
    },
    /// eta*(mu) sampled at geometrically spaced mu, one row per mu, with the mode.
    #[command(
        after_help = "Example:\n  arch-enum curve --alpha 0 --points 10\n  arch-enum curve --alpha 1 --mu-min 1 --mu-max 100 --json"
    )]
    Curve {
        #[command(flatten)]
        arch: ArchArgs,
        /// Smallest mu (default: mu_ms (1 + 1e-6), just above the least friction admitting equilibrium).
        #[arg(long, allow_negative_numbers = true)]
        mu_min: Option<f64>,
        /// Largest mu (default: 10 * mu_min).
        #[arg(long, allow_negative_numbers = true)]
        mu_max: Option<f64>,
        /// Number of samples (1 to 100000).
        #[arg(long, default_value_t = 20, allow_negative_numbers = true)]
        points: usize,
        /// Print one JSON document instead of tables.
        #[arg(long)]
        json: bool,
    },
}

#[derive(Args, Debug)]
struct Output {
    /// Output file (default: <figure>.svg, or <figure>.png with --png, in the current folder).
    #[arg(long)]
    out: Option<std::path::PathBuf>,
    /// Render to PNG in-process (fonts embedded) instead of SVG.
    #[arg(long)]
    png: bool,
    /// PNG width in pixels (100 to 8000).
    #[arg(long, default_value_t = 1200)]
    width: u32,
}

/// The arch and the state a figure draws.
#[derive(Args, Debug)]
struct StateArgs {
    #[command(flatten)]
    arch: ArchArgs,
    /// Friction coefficient mu > 0; `inf` for no sliding.
    #[arg(long, allow_negative_numbers = true)]
    mu: f64,
    /// Thickness ratio to draw (default: eta*(mu)); above eta* the state of greatest margin is drawn.
    #[arg(long, allow_negative_numbers = true)]
    eta: Option<f64>,
}

#[derive(Subcommand, Debug)]
enum Figure {
    /// The eta-mu limit curves of one or more symmetric openings in one figure.
    #[command(
        after_help = "Example:\n  arch-enum plot curve --alpha 0 --alpha 0.5236 --alpha 1.0 --png"
    )]
    Curve {
        /// Opening(s) in radians, -pi/2 < alpha < pi/2; repeat for several arches.
        #[arg(long, required = true, allow_negative_numbers = true)]
        alpha: Vec<f64>,
        /// Where self-weight acts.
        #[arg(long, value_enum, default_value = "centreline")]
        weight: WeightArg,
        #[command(flatten)]
        output: Output,
    },
    /// The arch to scale at eta*(mu) (or at --eta) with its lines of thrust and friction, and the mechanism.
    #[command(
        after_help = "Example:\n  arch-enum plot arch --alpha 0 --mu 0.35 --png\n  arch-enum plot arch --alpha 1.0 --mu 2 --eta 0.9"
    )]
    Arch {
        #[command(flatten)]
        state: StateArgs,
        #[command(flatten)]
        output: Output,
    },
    /// The eccentricities e_M = M/N and e_T = (T/N)/mu eta/2 against beta.
    Eccentricity {
        #[command(flatten)]
        state: StateArgs,
        #[command(flatten)]
        output: Output,
    },
    /// A margin map over the eta-mu plane with the exact limit curve (computed in parallel).
    Map {
        #[command(flatten)]
        arch: ArchArgs,
        /// Grid cells along eta (4 to 400).
        #[arg(long, default_value_t = 36)]
        n_eta: usize,
        /// Grid cells along mu (4 to 400).
        #[arg(long, default_value_t = 48)]
        n_mu: usize,
        #[command(flatten)]
        output: Output,
    },
}

#[derive(ValueEnum, Clone, Copy, Debug)]
enum WeightArg {
    /// Self-weight along the centreline (Heyman).
    Centreline,
    /// Self-weight at the true centroid of each piece (Milankovitch).
    Centroid,
}

#[derive(Args, Debug)]
struct ArchArgs {
    /// Opening of a symmetric arch in radians, -pi/2 < alpha < pi/2 (0: semicircle).
    #[arg(long, allow_negative_numbers = true, group = "shape")]
    alpha: Option<f64>,
    /// Opening of a symmetric arch in degrees, -90 < alpha-deg < 90.
    #[arg(long, allow_negative_numbers = true, group = "shape")]
    alpha_deg: Option<f64>,
    /// Right springing angle of an unsymmetric arch (radians); needs --beta-left.
    #[arg(
        long,
        allow_negative_numbers = true,
        group = "shape",
        requires = "beta_left"
    )]
    beta_right: Option<f64>,
    /// Left springing angle (radians), beta_right < beta_left <= beta_right + 2 pi.
    #[arg(long, allow_negative_numbers = true, requires = "beta_right")]
    beta_left: Option<f64>,
    /// N equal voussoirs: joints only at the N + 1 equally spaced angles (1 to 100000).
    #[arg(long, conflicts_with = "joints", allow_negative_numbers = true)]
    blocks: Option<usize>,
    /// Explicit joint angles in radians, comma-separated, increasing, within the springings.
    #[arg(long, value_delimiter = ',', allow_negative_numbers = true)]
    joints: Option<Vec<f64>>,
    /// Where self-weight acts.
    #[arg(long, value_enum, default_value = "centreline")]
    weight: WeightArg,
}

impl ArchArgs {
    fn build(&self) -> Result<Arch, InputError> {
        let weight = match self.weight {
            WeightArg::Centreline => WeightModel::Centreline,
            WeightArg::Centroid => WeightModel::Centroid,
        };
        let arch = match (self.alpha, self.alpha_deg, self.beta_right, self.beta_left) {
            (Some(a), _, _, _) => Arch::symmetric(a, weight)?,
            (_, Some(d), _, _) => Arch::symmetric(d.to_radians(), weight).map_err(|_| InputError::OutOfRange {
                arg: "--alpha-deg",
                value: crate::arch::fmt_value(d),
                range: "(-90, 90) degrees".into(),
            })?,
            (_, _, Some(r), Some(l)) => Arch::new(r, l, weight)?,
            _ => {
                return Err(InputError::Inconsistent {
                    arg: "--alpha/--alpha-deg/--beta-right/--beta-left",
                    reason: "describe the arch with --alpha A, --alpha-deg D, or --beta-right B1 --beta-left B2".into(),
                })
            }
        };
        match (&self.blocks, &self.joints) {
            (Some(n), _) => arch.with_blocks(*n),
            (_, Some(j)) => arch.with_joints(j),
            _ => Ok(arch),
        }
    }
}

fn emit(out: &mut dyn Write, text: &str) {
    // A closed pipe (e.g. `| head`) is not an error of ours.
    let _ = out.write_all(text.as_bytes());
    let _ = out.flush();
}

fn to_json<T: serde::Serialize>(value: &T) -> String {
    let mut s = serde_json::to_string_pretty(value).expect("results serialise to JSON");
    s.push('\n');
    s
}

fn bad_input(e: &InputError, json_out: bool, out: &mut dyn Write, err: &mut dyn Write) -> i32 {
    emit(err, &format!("error: {e}\n"));
    if json_out {
        emit(
            out,
            &to_json(&json::ErrorJson {
                status: "bad_input",
                message: e.to_string(),
            }),
        );
    }
    EXIT_BAD_INPUT
}

/// Runs the command line `args` (including the program name), writing results to
/// `out` and diagnostics to `err`; returns the exit status.
pub fn run<I, T>(args: I, out: &mut dyn Write, err: &mut dyn Write) -> i32
where
    I: IntoIterator<Item = T>,
    T: Into<OsString> + Clone,
{
    let cli = match Cli::try_parse_from(args) {
        Ok(c) => c,
        Err(e) => {
            let code = if e.use_stderr() {
                EXIT_BAD_INPUT
            } else {
                EXIT_OK
            };
            let text = e.render().to_string();
            if e.use_stderr() {
                emit(err, &text);
            } else {
                emit(out, &text);
            }
            return code;
        }
    };
    let settings = Settings::default();
    match cli.command {
        Command::Solve {
            arch,
            mu,
            explain,
            json: json_out,
        } => {
            let sol = match arch.build().and_then(|a| solve(&a, mu, &settings)) {
                Ok(s) => s,
                Err(e) => return bad_input(&e, json_out, out, err),
            };
            if json_out {
                emit(out, &to_json(&json::solve(&sol, explain)));
            } else {
                emit(out, &table::solve(&sol, explain));
            }
            match &sol.outcome {
                Outcome::Limit(_) => EXIT_OK,
                Outcome::NoEquilibrium { reason, .. }
                | Outcome::Unresolved { reason, .. }
                | Outcome::NoCollapse { reason } => {
                    if json_out {
                        emit(err, &format!("{}: {reason}\n", json::status(&sol.outcome)));
                    }
                    EXIT_NO_ANSWER
                }
            }
        }
        Command::Modes {
            arch,
            json: json_out,
        } => {
            let arch = match arch.build() {
                Ok(a) => a,
                Err(e) => return bad_input(&e, json_out, out, err),
            };
            let curve = crate::limit_curve::trace(&arch, &settings);
            if json_out {
                emit(out, &to_json(&json::modes(&arch, &curve)));
            } else {
                emit(out, &table::modes(&arch, &curve));
            }
            if !curve.branches.is_empty() {
                EXIT_OK
            } else {
                EXIT_NO_ANSWER
            }
        }
        Command::Certify {
            arch,
            mu,
            gap,
            out: out_file,
            json: json_out,
        } => {
            let arch = match arch
                .build()
                .and_then(|a| crate::arch::check_mu(mu).map(|_| a))
            {
                Ok(a) => a,
                Err(e) => return bad_input(&e, json_out, out, err),
            };
            if !(gap.is_finite() && (1e-15..=1e-4).contains(&gap)) {
                let e = InputError::OutOfRange {
                    arg: "--gap",
                    value: crate::arch::fmt_value(gap),
                    range: "1e-15 <= gap <= 1e-4".into(),
                };
                return bad_input(&e, json_out, out, err);
            }
            match crate::certificate::certify(&arch, mu, gap, &settings) {
                Ok(cert) => {
                    let text = to_json(&cert);
                    match out_file {
                        Some(path) => {
                            if let Err(e) = std::fs::write(&path, &text) {
                                emit(
                                    err,
                                    &format!("error: cannot write {}: {e}\n", path.display()),
                                );
                                return EXIT_BAD_INPUT;
                            }
                            let summary = serde_json::json!({"status": "ok", "file": path.display().to_string(), "claim": cert.claim, "gap_relative": cert.gap_relative});
                            if json_out {
                                emit(out, &to_json(&summary));
                            } else {
                                emit(
                                    out,
                                    &format!(
                                        "wrote {} ({:?}, relative gap {:?})\n",
                                        path.display(),
                                        cert.claim,
                                        cert.gap_relative
                                    ),
                                );
                            }
                        }
                        None => emit(out, &text),
                    }
                    EXIT_OK
                }
                Err(crate::certificate::NotCertified(reason)) => {
                    if json_out {
                        emit(
                            out,
                            &to_json(
                                &serde_json::json!({"status": "not_certified", "message": reason}),
                            ),
                        );
                    }
                    emit(err, &format!("not certified: {reason}\n"));
                    EXIT_NO_ANSWER
                }
            }
        }
        Command::Verify {
            file,
            json: json_out,
        } => {
            let text = match std::fs::read_to_string(&file) {
                Ok(t) => t,
                Err(e) => {
                    emit(
                        err,
                        &format!("error: cannot read FILE {}: {e}\n", file.display()),
                    );
                    return EXIT_BAD_INPUT;
                }
            };
            let cert: crate::certificate::Certificate = match serde_json::from_str(&text) {
                Ok(c) => c,
                Err(e) => {
                    emit(
                        err,
                        &format!("error: FILE {} is not a certificate: {e}\n", file.display()),
                    );
                    return EXIT_BAD_INPUT;
                }
            };
            match crate::certificate::verify(&cert) {
                Ok(report) => {
                    if json_out {
                        emit(
                            out,
                            &to_json(
                                &serde_json::json!({"status": "holds", "checks": report.checks}),
                            ),
                        );
                    } else {
                        emit(
                            out,
                            &format!("certificate holds\n  {}\n", report.checks.join("\n  ")),
                        );
                    }
                    EXIT_OK
                }
                Err(crate::certificate::Rejection(reason)) => {
                    if json_out {
                        emit(
                            out,
                            &to_json(&serde_json::json!({"status": "rejected", "reason": reason})),
                        );
                    } else {
                        emit(out, &format!("certificate REJECTED: {reason}\n"));
                    }
                    EXIT_NO_ANSWER
                }
            }
        }
        Command::Plot { figure } => run_plot(figure, &settings, out, err),
        Command::Curve {
            arch,
            mu_min,
            mu_max,
            points,
            json: json_out,
        } => {
            let arch = match arch.build() {
                Ok(a) => a,
                Err(e) => return bad_input(&e, json_out, out, err),
            };
            for (name, v) in [("--mu-min", mu_min), ("--mu-max", mu_max)] {
                if let Some(v) = v {
                    if !(v.is_finite() && v > 0.0) {
                        let e = InputError::OutOfRange {
                            arg: name,
                            value: crate::arch::fmt_value(v),
                            range: "0 < mu < inf".into(),
                        };
                        return bad_input(&e, json_out, out, err);
                    }
                }
            }
            let mu_ms = least_friction(&arch, &settings).ok().flatten();
            let lo = mu_min.unwrap_or_else(|| mu_ms.map_or(0.01, |m| (m * (1.0 + 1e-6)).max(1e-6)));
            let hi = mu_max.unwrap_or(10.0 * lo);
            let grid = match mu_grid(lo, hi, points) {
                Ok(g) => g,
                Err(e) => return bad_input(&e, json_out, out, err),
            };
            let pts = match sample(&arch, &grid, &settings) {
                Ok(p) => p,
                Err(e) => return bad_input(&e, json_out, out, err),
            };
            if json_out {
                emit(out, &to_json(&json::curve(&arch, mu_ms, &pts)));
            } else {
                emit(out, &table::curve(&arch, mu_ms, &pts));
            }
            EXIT_OK
        }
    }
}

fn weight_of(w: WeightArg) -> WeightModel {
    match w {
        WeightArg::Centreline => WeightModel::Centreline,
        WeightArg::Centroid => WeightModel::Centroid,
    }
}

fn run_plot(figure: Figure, settings: &Settings, out: &mut dyn Write, err: &mut dyn Write) -> i32 {
    use crate::render::figures;
    let progress = |done: usize, total: usize| {
        if done.is_multiple_of(16) || done == total {
            let bar = 30 * done / total.max(1);
            eprint!(
                "\r[{}{}] {done}/{total}",
                "#".repeat(bar),
                " ".repeat(30 - bar)
            );
            if done == total {
                eprintln!();
            }
        }
    };
    let (name, output, result) = match figure {
        Figure::Curve {
            alpha,
            weight,
            output,
        } => {
            let arches: Result<Vec<Arch>, InputError> = alpha
                .iter()
                .map(|&a| Arch::symmetric(a, weight_of(weight)))
                .collect();
            match arches {
                Ok(a) => ("curve", output, figures::curve(&a, settings)),
                Err(e) => return bad_input(&e, false, out, err),
            }
        }
        Figure::Arch { state: st, output } => match plot_inputs(&st) {
            Ok(a) => ("arch", output, figures::arch(&a, st.mu, st.eta, settings)),
            Err(e) => return bad_input(&e, false, out, err),
        },
        Figure::Eccentricity { state: st, output } => match plot_inputs(&st) {
            Ok(a) => (
                "eccentricity",
                output,
                figures::eccentricity(&a, st.mu, st.eta, settings),
            ),
            Err(e) => return bad_input(&e, false, out, err),
        },
        Figure::Map {
            arch,
            n_eta,
            n_mu,
            output,
        } => {
            for (name, n) in [("--n-eta", n_eta), ("--n-mu", n_mu)] {
                if !(4..=400).contains(&n) {
                    let e = InputError::OutOfRange {
                        arg: name,
                        value: n.to_string(),
                        range: "whole numbers 4 to 400".into(),
                    };
                    return bad_input(&e, false, out, err);
                }
            }
            match arch.build() {
                Ok(a) => (
                    "map",
                    output,
                    figures::map(&a, n_eta, n_mu, settings, &progress),
                ),
                Err(e) => return bad_input(&e, false, out, err),
            }
        }
    };
    if !(100..=8000).contains(&output.width) {
        let e = InputError::OutOfRange {
            arg: "--width",
            value: output.width.to_string(),
            range: "100 to 8000 pixels".into(),
        };
        return bad_input(&e, false, out, err);
    }
    let svg = match result {
        Ok(s) => s,
        Err(figures::NoFigure(reason)) => {
            emit(err, &format!("no figure: {reason}\n"));
            return EXIT_NO_ANSWER;
        }
    };
    let path = output
        .out
        .unwrap_or_else(|| format!("{name}.{}", if output.png { "png" } else { "svg" }).into());
    let bytes = if output.png {
        match crate::render::plot::svg_to_png(&svg, output.width) {
            Ok(b) => b,
            Err(e) => {
                emit(err, &format!("no figure: {e}\n"));
                return EXIT_NO_ANSWER;
            }
        }
    } else {
        svg.into_bytes()
    };
    if let Err(e) = std::fs::write(&path, bytes) {
        emit(
            err,
            &format!("error: cannot write --out {}: {e}\n", path.display()),
        );
        return EXIT_BAD_INPUT;
    }
    emit(out, &format!("wrote {}\n", path.display()));
    EXIT_OK
}

fn plot_inputs(st: &StateArgs) -> Result<Arch, InputError> {
    let a = st.arch.build()?;
    crate::arch::check_mu(st.mu)?;
    if let Some(e) = st.eta {
        crate::arch::check_eta(e)?;
    }
    Ok(a)
}
