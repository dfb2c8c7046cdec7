//! The command-line interface: argument parsing, one library call per command, rendering,
//! and the single place where what happened becomes an exit code ([`Exit::code`]):
//! 0 answered, 1 the question has no answer for these inputs, 2 bad input.
//!
//! One file per command, holding its arguments and its run function; `arch_args` holds
//! the description of the arch that every command shares.

mod arch_args;
mod assess;
mod certify;
mod curve;
mod dimension_args;
pub(crate) mod load;
mod modes;
mod plot;
mod progress;
pub mod serve;
mod solve;
mod threads_arg;

use crate::arch::InputError;
use crate::limit::Outcome;
use crate::render::json;
use crate::settings::Settings;
use clap::{Parser, Subcommand};
use std::ffi::OsString;
use std::io::Write;

/// Exit status: success.
pub const EXIT_OK: i32 = 0;
/// Exit status: the question has no answer for these inputs (no equilibrium, unresolved).
pub const EXIT_NO_ANSWER: i32 = 1;
/// Exit status: bad input.
pub const EXIT_BAD_INPUT: i32 = 2;

/// How a command ended.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Exit {
    /// The question was answered.
    Answered,
    /// The question has no answer for these inputs (no equilibrium, no collapse,
    /// unresolved, a certificate rejected or not produced, nothing to draw).
    NoAnswer,
    /// The input was bad (the message names the argument and the valid range).
    BadInput,
}

impl Exit {
    /// The process exit status: the only place where results become exit codes.
    pub fn code(self) -> i32 {
        match self {
            Exit::Answered => EXIT_OK,
            Exit::NoAnswer => EXIT_NO_ANSWER,
            Exit::BadInput => EXIT_BAD_INPUT,
        }
    }

    /// How a solver outcome ends a command.
    pub fn of(outcome: &Outcome) -> Exit {
        match outcome {
            Outcome::Limit(_) => Exit::Answered,
            Outcome::NoEquilibrium { .. }
            | Outcome::Unresolved { .. }
            | Outcome::NoCollapse { .. } => Exit::NoAnswer,
        }
    }
}

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
  mixed_sliding_rotational      hinges and sliding, a hinge nearer the crown (the middle of the arch) \
than every sliding joint: rotation at the crown, sliding further out
  mixed_rotational_sliding      hinges and sliding, every hinge farther from the crown than every \
sliding joint: rotation at the shoulders, sliding near the crown
  mixed_interleaved             hinges and sliding interleaved otherwise (a descriptive name outside \
the contract's list)"
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
struct Cli {
    #[command(subcommand)]
    command: Command,
}

#[derive(Subcommand, Debug)]
enum Command {
    /// The least thickness eta*(mu), the collapse mode, the active pattern, the reactions and a mechanism.
    #[command(
        after_help = "Example:\n  arch-enum solve --alpha 0 --mu 0.35\n  arch-enum solve --alpha 0.5 --blocks 12 --mu inf --json",
        after_long_help = concat!("Example:\n  arch-enum solve --alpha 0 --mu 0.35\n  arch-enum solve --alpha 0.5 --blocks 12 --mu inf --json\n\n", mode_names!())
    )]
    Solve(solve::SolveArgs),
    /// The whole eta-mu limit curve: branches with their collapse modes and exact corners.
    #[command(
        after_help = "Example:\n  arch-enum modes --alpha 1.0\n  arch-enum modes --alpha-deg 30 --json\n  arch-enum modes --alpha 0 --blocks 20",
        after_long_help = concat!("Example:\n  arch-enum modes --alpha 1.0\n  arch-enum modes --alpha-deg 30 --json\n  arch-enum modes --alpha 0 --blocks 20\n\n", mode_names!())
    )]
    Modes(modes::ModesArgs),
    /// A certificate for eta*(mu): an admissible state at eta_hi (upper bound), a Farkas certificate at eta_lo (lower bound), the limit state; with --eta and a live load, for lambda_static and the limit states under the load.
    #[command(
        after_help = "Example:\n  arch-enum certify --alpha 0 --mu 0.35 --out cert.json\n  arch-enum verify cert.json\n  arch-enum certify --alpha 0 --blocks 20 --eta 0.3 --mu 0.8 --horizontal --out load.json"
    )]
    Certify(certify::CertifyArgs),
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
    Assess(assess::AssessArgs),
    /// The collapse multiplier of a live load (horizontal acceleration or a point load) at a given thickness and friction: the static maximum, every limit state below it (non-associative friction can lower the collapse load), unique or not.
    #[command(
        after_help = "Example:\n  arch-enum load --alpha 0 --blocks 27 --weight centroid --eta 0.153361 --mu inf --point-load-deg 53.3333333333\n  arch-enum load --alpha 0 --blocks 20 --eta 0.3 --mu 0.8 --horizontal --json"
    )]
    Load(load::LoadArgs),
    /// The load multiplier against friction at a fixed thickness: lambda_static and the collapse multiplier lambda (the least limit state) sampled over mu, and at mu = inf.
    #[command(
        after_help = "Example:\n  arch-enum load-curve --alpha 0 --blocks 20 --eta 0.3 --horizontal\n  arch-enum load-curve --alpha 0 --eta 0.2 --point-load-deg 60 --mu-min 0.4 --mu-max 2 --json"
    )]
    LoadCurve(load::LoadCurveArgs),
    /// eta*(mu) sampled at geometrically spaced mu, one row per mu, with the mode.
    #[command(
        after_help = "Example:\n  arch-enum curve --alpha 0 --points 10\n  arch-enum curve --alpha 1 --mu-min 1 --mu-max 100 --json"
    )]
    Curve(curve::CurveArgs),
    /// The explorer: a local web page (sliders, the eta-mu diagram, the arch at its limit state) and a JSON API giving the same documents as --json, on 127.0.0.1.
    #[command(
        after_help = "Example:\n  arch-enum serve --open\n  arch-enum serve --port 0   (any free port; the URL is the first line printed)\n  curl 'http://127.0.0.1:8765/api/solve?alpha=0&mu=0.35'"
    )]
    Serve(serve::ServeArgs),
}

/// Where a command writes: results to `out`, diagnostics to `err`; `json` when standard
/// output must be exactly one JSON document.
pub(crate) struct Io<'a> {
    out: &'a mut dyn Write,
    err: &'a mut dyn Write,
    json: bool,
}

fn emit(w: &mut dyn Write, text: &str) {
    // A closed pipe (e.g. `| head`) is not an error of ours.
    let _ = w.write_all(text.as_bytes());
    let _ = w.flush();
}

pub(crate) fn to_json<T: serde::Serialize>(value: &T) -> String {
    let mut s = serde_json::to_string_pretty(value).expect("results serialise to JSON");
    s.push('\n');
    s
}

impl Io<'_> {
    /// Writes a result.
    pub(crate) fn out(&mut self, text: &str) {
        emit(self.out, text);
    }
    /// Writes a diagnostic.
    pub(crate) fn err(&mut self, text: &str) {
        emit(self.err, text);
    }
    /// Reports bad input: the message on standard error, and with `--json` a JSON document
    /// on standard output.
    pub(crate) fn bad_input(&mut self, e: &InputError) -> Exit {
        self.bad(e.to_string())
    }
    /// Reports bad input described by `message` (a file that cannot be read or written).
    pub(crate) fn bad(&mut self, message: String) -> Exit {
        self.err(&format!("error: {message}\n"));
        if self.json {
            self.out(&to_json(&json::ErrorJson::new(message)));
        }
        Exit::BadInput
    }
}

/// Runs the command line `args` (including the program name), writing results to
/// `out` and diagnostics to `err`; returns the exit status.
pub fn run<I, T>(args: I, out: &mut dyn Write, err: &mut dyn Write) -> i32
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
                    // clap's first paragraph: "error: ..." and any indented continuation
                    let message: Vec<&str> = text
                        .lines()
                        .take_while(|l| !l.trim().is_empty())
                        .map(|l| l.trim().trim_start_matches("error: "))
                        .collect();
                    emit(out, &to_json(&json::ErrorJson::new(message.join(" "))));
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
        Command::Assess(a) => a.json,
        Command::Load(a) => a.json,
        Command::LoadCurve(a) => a.json,
        Command::Plot { .. } | Command::Serve(_) => false,
    };
    let mut io = Io { out, err, json };
    let exit = match cli.command {
        Command::Solve(a) => solve::run(a, &settings, &mut io),
        Command::Modes(a) => modes::run(a, &settings, &mut io),
        Command::Certify(a) => certify::run_certify(a, &settings, &mut io),
        Command::Verify(a) => certify::run_verify(a, &mut io),
        Command::Plot { figure } => plot::run(figure, &settings, &mut io),
        Command::Curve(a) => curve::run(a, &settings, &mut io),
        Command::Assess(a) => assess::run(a, &settings, &mut io),
        Command::Load(a) => load::run(a, &settings, &mut io),
        Command::LoadCurve(a) => load::run_curve(a, &settings, &mut io),
        Command::Serve(a) => serve::run(a, &mut io),
    };
    exit.code()
}
