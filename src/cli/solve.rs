//! `arch-enum solve`: the least thickness at one friction coefficient.

use super::arch_args::ArchArgs;
use super::bridge_args::ArchFillArgs;
use super::io::{geometry_text, json_with_geometry, to_json, Exit, Io};
use super::mu_arg::MuArg;
use crate::figures::survey_scene;
use crate::limit::Outcome;
use crate::limit_states::survey;
use crate::render::{compas, json, table};
use crate::settings::Settings;
use clap::Args;
use std::path::PathBuf;

#[derive(Args, Debug)]
pub(crate) struct SolveArgs {
    #[command(flatten)]
    arch: ArchArgs,
    #[command(flatten)]
    fill: ArchFillArgs,
    /// Friction coefficient mu = tan(phi) > 0; `inf` for no sliding; `ms` for the arch's own
    /// mu_ms (the vertical branch: the corner eta_ms and the purely sliding limit states).
    #[arg(long, allow_hyphen_values = true)]
    mu: MuArg,
    /// List every pattern tried and why it was kept or rejected.
    #[arg(long)]
    explain: bool,
    /// Print one JSON document instead of tables.
    #[arg(long)]
    pub(crate) json: bool,
    /// Also write the limit state as a COMPAS JSON file (compas 2, `compas.json_load`):
    /// the outline and the line of thrust as Polylines, hinges and sliding joints as
    /// Points, in the XZ plane with z up.
    #[arg(long, value_name = "FILE")]
    compas: Option<PathBuf>,
    /// Mean radius the COMPAS drawing is scaled by (default 1: lengths in units of r).
    #[arg(
        long,
        requires = "compas",
        allow_hyphen_values = true,
        default_value_t = 1.0
    )]
    radius: f64,
}

pub(crate) fn run(a: SolveArgs, settings: &Settings, io: &mut Io) -> Exit {
    let (survey, fill) = match compas::check_radius(a.radius)
        .and_then(|_| a.fill.build(&a.arch))
        .and_then(|(arch, fill)| {
            Ok((
                survey(&arch, a.mu.resolve(&arch, settings)?, settings)?,
                fill,
            ))
        }) {
        Ok(s) => s,
        Err(e) => return io.bad_input(&e),
    };
    let sol = &survey.solution;
    let geometry = match a.arch.geometry() {
        Ok(g) => g,
        Err(e) => return io.bad_input(&e),
    };
    let least = match &sol.outcome {
        Outcome::Limit(ls) => Some(ls.eta),
        _ => None,
    };
    // the road's depth above the least ring's extrados (h held as the ring varies)
    let fill = fill.map(|mut f| {
        f.depth_at_least_ring_m = geometry
            .zip(least)
            .map(|(g, e)| f.depth_ratio * g.intrados.ring_of(e).radius);
        f
    });
    // the COMPAS file first: a path that cannot be written is bad input, reported alone
    let mut no_scene = None;
    if let Some(path) = &a.compas {
        match survey_scene(&survey, settings) {
            Ok(scene) => {
                let doc = compas::document(&scene, a.radius);
                if let Err(e) = std::fs::write(path, to_json(&doc)) {
                    return io.bad(format!("cannot write --compas {}: {e}", path.display()));
                }
            }
            Err(why) => no_scene = Some(why),
        }
    }
    if a.json {
        let mut doc = json::solve(&survey, a.explain, &survey.rays(settings));
        doc.fill = fill;
        io.out(&json_with_geometry(&doc, geometry, least));
    } else {
        let mut head = geometry_text(geometry, least);
        if let Some(f) = &fill {
            head = head.replace(crate::render::geometry::RING_SCOPE, "")
                + &table::bridge(Some(f), None, None, None);
        }
        io.out(&(head + &table::solve(&survey, a.explain, &survey.rays(settings))));
    }
    if let Some(why) = no_scene {
        io.err(&format!("no COMPAS file written: {why}\n"));
        return Exit::NoAnswer;
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
