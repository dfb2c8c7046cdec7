//! `arch-enum modes`: the whole η–μ limit curve, branches and exact corners.

use super::arch_args::ArchArgs;
use super::io::{to_json, Exit, Io};
use super::threads_arg::ThreadsArg;
use crate::limit_curve::{trace_parallel, CurveStatus};
use crate::render::{json, table};
use crate::settings::Settings;
use clap::Args;

#[derive(Args, Debug)]
pub(crate) struct ModesArgs {
    #[command(flatten)]
    arch: ArchArgs,
    #[command(flatten)]
    threads: ThreadsArg,
    /// Print one JSON document instead of tables.
    #[arg(long)]
    pub(crate) json: bool,
}

pub(crate) fn run(a: ModesArgs, settings: &Settings, io: &mut Io) -> Exit {
    let arch = match a.arch.build_without_ring() {
        Ok(a) => a,
        Err(e) => return io.bad_input(&e),
    };
    let threads = match a.threads.count() {
        Ok(t) => t,
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
