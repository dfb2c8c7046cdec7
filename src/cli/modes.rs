//! `arch-enum modes`: the whole η–μ limit curve, branches and exact corners.

use super::arch_args::ArchArgs;
use super::bridge_args::ArchFillArgs;
use super::io::{geometry_text, json_with_geometry, to_json, Exit, Io};
use super::threads_arg::ThreadsArg;
use crate::limit_curve::{filled, trace_parallel, CurveStatus};
use crate::render::{json, table};
use crate::settings::Settings;
use clap::Args;

#[derive(Args, Debug)]
pub(crate) struct ModesArgs {
    #[command(flatten)]
    arch: ArchArgs,
    #[command(flatten)]
    fill: ArchFillArgs,
    #[command(flatten)]
    threads: ThreadsArg,
    /// Print one JSON document instead of tables.
    #[arg(long)]
    pub(crate) json: bool,
}

pub(crate) fn run(a: ModesArgs, settings: &Settings, io: &mut Io) -> Exit {
    let threads = match a.threads.count() {
        Ok(t) => t,
        Err(e) => return io.bad_input(&e),
    };
    if a.fill.given() {
        return with_fill(&a, settings, threads, io);
    }
    let arch = match a.arch.build_without_ring() {
        Ok(a) => a,
        Err(e) => return io.bad_input(&e),
    };
    let curve = trace_parallel(&arch, settings, threads);
    if a.json {
        io.out(&to_json(&json::modes(&arch, &curve)));
    } else {
        io.out(&table::modes(&arch, &curve));
    }
    match curve.status() {
        CurveStatus::Traced => Exit::Answered,
        _ => Exit::NoAnswer,
    }
}

/// `modes` of an arch with fill: the curve μ_min(η), traced in η.
fn with_fill(a: &ModesArgs, settings: &Settings, threads: usize, io: &mut Io) -> Exit {
    let (arch, fill) = match a.fill.build(&a.arch) {
        Ok(b) => b,
        Err(e) => return io.bad_input(&e),
    };
    let geometry = match a.arch.geometry() {
        Ok(g) => g,
        Err(e) => return io.bad_input(&e),
    };
    let intrados = geometry.map(|g| g.intrados);
    let curve = filled::trace(&arch, settings, threads);
    if a.json {
        let doc = json::modes_fill(&arch, fill, intrados.as_ref(), &curve);
        io.out(&json_with_geometry(&doc, geometry, None));
    } else {
        let head = geometry_text(geometry, None).replace(crate::render::geometry::RING_SCOPE, "");
        io.out(&(head + &table::modes_fill(&arch, fill.as_ref(), intrados.as_ref(), &curve)));
    }
    match curve.least {
        Some(_) => Exit::Answered,
        None => Exit::NoAnswer,
    }
}
