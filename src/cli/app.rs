//! The command line itself: every command and its `--help`, parsed by clap, and the one
//! dispatch from a command to its run function.

use super::io::{emit, message_of, to_json, Exit, Io};
use super::report::{ReportArgs, Runner};
use super::serve_args::ServeArgs;
use super::{assess, atlas, certify, curve, load, modes, plot, report, solve};
use crate::render::json;
use crate::settings::Settings;
use clap::{Parser, Subcommand};
use std::ffi::OsString;
use std::io::Write;

/// The collapse-mode names, defined (shown by `--help` of the commands that print them).
macro_rules! mode_names {
    () => {
        "Collapse modes (named from the active pattern alone; E: hinge at the extrados, \
I: hinge at the intrados, S+/S-: sliding along the radial joint, the part beyond it (larger beta) \
moving outwards/inwards):
  purely_rotational             hinges only (Couplet-Heyman)
  overturning                   hinges only, with a detached joint (N = 0: E and I both active)
  purely_sliding                sliding only (the vertical branch mu = mu_ms)
  rotational_sliding_shoulders  a springing hinges and slides at once
  mixed_sliding_rotational      hinges and sliding, the contact farthest from the crown (the middle \
of the arch) a sliding joint: sliding at the shoulders, rotation nearer the crown
  mixed_rotational_sliding      hinges and sliding, the contact farthest from the crown a hinge: \
rotation at the shoulders, sliding nearer the crown (a crown hinge may lie inside)
  (when a hinge and a sliding joint are equally far out, e.g. at the two springings, the innermost \
contact decides: a hinge gives mixed_sliding_rotational, a sliding joint mixed_rotational_sliding)
  mixed_interleaved             a hinge and a sliding joint share both the outermost and the \
innermost place (a descriptive name outside the contract's list)"
    };
}

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
pub(super) struct Cli {
    #[command(subcommand)]
    pub(super) command: Command,
}

#[derive(Subcommand, Debug)]
pub(super) enum Command {
    /// The least thickness eta*(mu), the collapse mode, the active pattern, the reactions and a mechanism.
    #[command(
        after_help = "Example:\n  arch-enum solve --alpha 0 --mu 0.35\n  arch-enum solve --alpha 0.5 --blocks 12 --mu inf --json",
        after_long_help = concat!("Example:\n  arch-enum solve --alpha 0 --mu 0.35\n  arch-enum solve --alpha 0.5 --blocks 12 --mu inf --json\n\n", mode_names!())
    )]
    Solve(solve::SolveArgs),
    /// The whole eta-mu limit curve: branches with their collapse modes and exact corners. With fill, the least friction mu_min(eta) of every thickness, traced in eta, and the least friction at which the arch stands at all.
    #[command(
        after_help = "Example:\n  arch-enum modes --alpha 1.0\n  arch-enum modes --alpha-deg 30 --json\n  arch-enum modes --alpha 0 --blocks 20\n  arch-enum modes --span 10 --rise 5 --ring 0.6 --unit-weight 20 --fill-weight 18 --fill-depth 0.3",
        after_long_help = concat!("Example:\n  arch-enum modes --alpha 1.0\n  arch-enum modes --alpha-deg 30 --json\n  arch-enum modes --alpha 0 --blocks 20\n  arch-enum modes --span 10 --rise 5 --ring 0.6 --unit-weight 20 --fill-weight 18 --fill-depth 0.3\n\n", mode_names!())
    )]
    Modes(modes::ModesArgs),
    /// A certificate for eta*(mu): an admissible state at eta_hi (upper bound), a Farkas certificate at eta_lo (lower bound), the limit state; with --eta and a live load, for lambda_static and the limit states under the load.
    #[command(
        after_help = "Example:\n  arch-enum certify --alpha 0 --mu 0.35 --out cert.json\n  arch-enum verify cert.json\n  arch-enum certify --alpha 0 --blocks 20 --eta 0.3 --mu 0.8 --horizontal --out load.json"
    )]
    Certify(Box<certify::CertifyArgs>),
    /// Re-checks a certificate independently (no LP, no solver); exit 0 only if it holds.
    Verify(certify::VerifyArgs),
    /// Pictures: limit curves, the arch with its lines and mechanism, eccentricities, a margin map (SVG, or PNG with --png).
    Plot {
        #[command(subcommand)]
        figure: plot::Figure,
    },
    /// A given thickness at a given friction: does it stand, and with what margins (geometric and friction factors of safety, the safest line of thrust).
    #[command(
        after_help = "Example:\n  arch-enum assess --alpha 0 --eta 0.2 --mu 0.35\n  arch-enum assess --alpha-deg 30 --eta 0.5 --mu 0.9 --radius 5 --depth 1 --density 2000"
    )]
    Assess(Box<assess::AssessArgs>),
    /// The collapse multiplier of a live load (horizontal acceleration or a point load) at a given thickness and friction: the static maximum, every limit state below it (non-associative friction can lower the collapse load), unique or not.
    #[command(
        after_help = "Example:\n  arch-enum load --alpha 0 --blocks 27 --weight centroid --eta 0.153361 --mu inf --point-load-deg 53.3333333333\n  arch-enum load --alpha 0 --blocks 20 --eta 0.3 --mu 0.8 --horizontal --json"
    )]
    Load(Box<load::LoadArgs>),
    /// The load multiplier against friction at a fixed thickness: lambda_static and the collapse multiplier lambda (the least limit state) sampled over mu, and at mu = inf.
    #[command(
        after_help = "Example:\n  arch-enum load-curve --alpha 0 --blocks 20 --eta 0.3 --horizontal\n  arch-enum load-curve --alpha 0 --eta 0.2 --point-load-deg 60 --mu-min 0.4 --mu-max 2 --json"
    )]
    LoadCurve(Box<load::LoadCurveArgs>),
    /// eta*(mu) sampled at geometrically spaced mu, one row per mu, with the mode.
    #[command(
        after_help = "Example:\n  arch-enum curve --alpha 0 --points 10\n  arch-enum curve --alpha 1 --mu-min 1 --mu-max 100 --json"
    )]
    Curve(curve::CurveArgs),
    /// The atlas of uniqueness over symmetric arches: where the least thickness carries the only limit state, where others lie above it, where it carries none, and where no equilibrium exists, over openings alpha and friction mu from mu_ms(alpha); with --horizontal, the load map: where friction lowers the collapse acceleration below its static maximum.
    #[command(after_help = "Example:
  arch-enum atlas --alpha-min 0.5 --alpha-max 0.9 --mu-max-factor 1.5
  arch-enum atlas --blocks 24 --json
  arch-enum atlas --horizontal --mu 1 --alpha-min 0.45 --alpha-max 0.55 --columns 3")]
    Atlas(atlas::AtlasArgs),
    /// The explorer: a local web page (sliders, the eta-mu diagram, the arch at its limit state) and a JSON API giving the same documents as --json, on 127.0.0.1.
    #[command(
        after_help = "Example:\n  arch-enum serve --open\n  arch-enum serve --port 0   (any free port; the URL is the first line printed)\n  curl 'http://127.0.0.1:8765/api/solve?alpha=0&mu=0.35'"
    )]
    Serve(ServeArgs),
    /// An assessment report: one self-contained HTML page (inputs, answers, every limit state, the certificate and its verification, the figures, the scope) made by the commands themselves.
    #[command(
        after_help = "Example:\n  arch-enum report --out bridge.html --span 10 --rise 5 --ring 0.6 --width 1 --unit-weight 20 --mu 0.6 --fill-weight 18 --fill-depth 0.3 --axles 100\n  arch-enum report --out arch.html --alpha 0 --eta 0.2 --mu 0.6"
    )]
    Report(Box<ReportArgs>),
    /// The JSON Schema (draft 2020-12) of every --json document, derived from the types that print them; `x-documents` names each command's document type.
    #[command(after_help = "Example:\n  arch-enum schema > arch-enum.schema.json")]
    Schema,
}

/// How `serve` runs: the server's own entry point, passed in so that the server (which runs
/// commands through [`run_with`]) and this dispatcher do not import each other.
pub(super) type Serve = fn(ServeArgs, &mut Io) -> Exit;

/// Runs the command line `args` (including the program name), writing results to
/// `out` and diagnostics to `err`, `serve` running the explorer; returns the exit status.
pub(super) fn run_with<I, T>(args: I, out: &mut dyn Write, err: &mut dyn Write, serve: Serve) -> i32
where
    I: IntoIterator<Item = T>,
    T: Into<OsString> + Clone,
{
    let args: Vec<OsString> = args.into_iter().map(Into::into).collect();
    let cli = match Cli::try_parse_from(&args) {
        Ok(c) => c,
        Err(e) => {
            let text = e.render().to_string();
            return if e.use_stderr() {
                emit(err, &text);
                if args.iter().any(|a| a == "--json") {
                    let message = message_of(text.as_bytes());
                    emit(out, &to_json(&json::ErrorJson::new(message)));
                }
                Exit::BadInput.code()
            } else {
                emit(out, &text);
                Exit::Answered.code()
            };
        }
    };
    let settings = Settings::default();
    let json = match &cli.command {
        Command::Solve(a) => a.json,
        Command::Modes(a) => a.json,
        Command::Certify(a) => a.json,
        Command::Verify(a) => a.json,
        Command::Curve(a) => a.json,
        Command::Atlas(a) => a.json,
        Command::Assess(a) => a.json,
        Command::Load(a) => a.json,
        Command::LoadCurve(a) => a.json,
        Command::Plot { .. } | Command::Serve(_) | Command::Report(_) | Command::Schema => false,
    };
    let mut io = Io { out, err, json };
    let exit = match cli.command {
        Command::Solve(a) => solve::run(a, &settings, &mut io),
        Command::Modes(a) => modes::run(a, &settings, &mut io),
        Command::Certify(a) => certify::run_certify(*a, &settings, &mut io),
        Command::Verify(a) => certify::run_verify(a, &mut io),
        Command::Plot { figure } => plot::run(figure, &settings, &mut io),
        Command::Curve(a) => curve::run(a, &settings, &mut io),
        Command::Atlas(a) => atlas::run(a, &settings, &mut io),
        Command::Assess(a) => assess::run(*a, &settings, &mut io),
        Command::Load(a) => load::run(*a, &settings, &mut io),
        Command::LoadCurve(a) => load::run_curve(*a, &settings, &mut io),
        Command::Serve(a) => serve(a, &mut io),
        Command::Schema => {
            io.out(&to_json(&json::schema()));
            Exit::Answered
        }
        Command::Report(a) => {
            let run = |args: Vec<OsString>| {
                let (mut out, mut err) = (Vec::new(), Vec::new());
                let code = run_with(args, &mut out, &mut err, serve);
                report::Ran { code, out, err }
            };
            let runner = Runner {
                cli: <Cli as clap::CommandFactory>::command(),
                run: &run,
            };
            report::run(*a, &mut io, &runner)
        }
    };
    exit.code()
}
