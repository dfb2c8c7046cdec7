//! `arch-enum solve`: the least thickness at one friction coefficient.

use super::arch_args::ArchArgs;
use super::{to_json, Exit, Io};
use crate::limit::Outcome;
use crate::limit_states::survey;
use crate::render::{json, table};
use crate::settings::Settings;
use clap::Args;

#[derive(Args, Debug)]
pub(crate) struct SolveArgs {
    #[command(flatten)]
    arch: ArchArgs,
    /// Friction coefficient mu = tan(phi) > 0; `inf` for no sliding.
    #[arg(long, allow_hyphen_values = true)]
    mu: f64,
    /// List every pattern tried and why it was kept or rejected.
    #[arg(long)]
    explain: bool,
    /// Print one JSON document instead of tables.
    #[arg(long)]
    pub(crate) json: bool,
}

pub(crate) fn run(a: SolveArgs, settings: &Settings, io: &mut Io) -> Exit {
    let survey = match a
        .arch
        .build()
        .and_then(|arch| survey(&arch, a.mu, settings))
    {
        Ok(s) => s,
        Err(e) => return io.bad_input(&e),
    };
    let sol = &survey.solution;
    if a.json {
        io.out(&to_json(&json::solve(&survey, a.explain)));
    } else {
        io.out(&table::solve(&survey, a.explain));
    }
    // decided: η_s exact and every limit state above it searched (an arch that stands at
    // every η > 0 has no least thickness: exit 1 with status no_collapse, as `modes` says)
    if survey.states.is_ok() && !matches!(sol.outcome, Outcome::NoCollapse { .. }) {
        return Exit::Answered;
    }
    match &sol.outcome {
        Outcome::Limit(_) => {}
        Outcome::NoEquilibrium { reason, .. }
        | Outcome::Unresolved { reason, .. }
        | Outcome::NoCollapse { reason } => {
            if a.json {
                io.err(&format!("{}: {reason}\n", json::status(&sol.outcome)));
            }
        }
    }
    Exit::of(&sol.outcome)
}
