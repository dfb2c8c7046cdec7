//! `arch-enum plot`: the figures (limit curves, the arch with its lines and mechanism,
//! eccentricities, a margin map), as SVG or PNG.

use super::arch_args::{ArchArgs, WeightArg};
use super::{Exit, Io};
use crate::arch::{check_eta, check_mu, Arch, InputError};
use crate::settings::Settings;
use clap::{Args, Subcommand};

#[derive(Args, Debug)]
pub(crate) struct Output {
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
pub(crate) struct StateArgs {
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
pub(crate) enum Figure {
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

pub(crate) fn run(figure: Figure, settings: &Settings, io: &mut Io) -> Exit {
    use crate::render::figures;
    let bar = super::progress::Progress::new("map");
    let progress = |done: usize, total: usize| bar.update(done, total);
    let (name, output, result) = match figure {
        Figure::Curve {
            alpha,
            weight,
            output,
        } => {
            let arches: Result<Vec<Arch>, InputError> = alpha
                .iter()
                .map(|&a| Arch::symmetric(a, weight.into()))
                .collect();
            match arches {
                Ok(a) => ("curve", output, figures::curve(&a, settings)),
                Err(e) => return io.bad_input(&e),
            }
        }
        Figure::Arch { state: st, output } => match plot_inputs(&st) {
            Ok(a) => ("arch", output, figures::arch(&a, st.mu, st.eta, settings)),
            Err(e) => return io.bad_input(&e),
        },
        Figure::Eccentricity { state: st, output } => match plot_inputs(&st) {
            Ok(a) => (
                "eccentricity",
                output,
                figures::eccentricity(&a, st.mu, st.eta, settings),
            ),
            Err(e) => return io.bad_input(&e),
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
                    return io.bad_input(&e);
                }
            }
            match arch.build() {
                Ok(a) => (
                    "map",
                    output,
                    figures::map(&a, n_eta, n_mu, settings, &progress),
                ),
                Err(e) => return io.bad_input(&e),
            }
        }
    };
    if !(100..=8000).contains(&output.width) {
        let e = InputError::OutOfRange {
            arg: "--width",
            value: output.width.to_string(),
            range: "100 to 8000 pixels".into(),
        };
        return io.bad_input(&e);
    }
    let svg = match result {
        Ok(s) => s,
        Err(figures::NoFigure(reason)) => {
            io.err(&format!("no figure: {reason}\n"));
            return Exit::NoAnswer;
        }
    };
    let path = output
        .out
        .unwrap_or_else(|| format!("{name}.{}", if output.png { "png" } else { "svg" }).into());
    let bytes = if output.png {
        match crate::render::plot::svg_to_png(&svg, output.width) {
            Ok(b) => b,
            Err(e) => {
                io.err(&format!("no figure: {e}\n"));
                return Exit::NoAnswer;
            }
        }
    } else {
        svg.into_bytes()
    };
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

fn plot_inputs(st: &StateArgs) -> Result<Arch, InputError> {
    let a = st.arch.build()?;
    check_mu(st.mu)?;
    if let Some(e) = st.eta {
        check_eta(e)?;
    }
    Ok(a)
}
