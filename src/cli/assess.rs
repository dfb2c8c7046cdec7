//! `arch-enum assess`: a given thickness at a given friction — does it stand, and with
//! what margins?

use super::arch_args::ArchArgs;
use super::bridge_args::{masonry, FillArgs};
use super::dimension_args::{sized, DimensionArgs};
use super::io::{geometry_text, json_with_geometry, Exit, Io};
use crate::assess::assess;
use crate::render::{json, table};
use crate::settings::Settings;
use clap::Args;

#[derive(Args, Debug)]
pub(crate) struct AssessArgs {
    #[command(flatten)]
    arch: ArchArgs,
    /// Thickness ratio eta = t/r of the arch, 0 < eta < 2 (or --ring with --span, --rise).
    #[arg(long, allow_hyphen_values = true)]
    eta: Option<f64>,
    /// Friction coefficient mu = tan(phi) > 0; `inf` for no sliding.
    #[arg(long, allow_hyphen_values = true)]
    mu: f64,
    #[command(flatten)]
    dims: DimensionArgs,
    #[command(flatten)]
    fill: FillArgs,
    /// Print one JSON document instead of text.
    #[arg(long)]
    pub(crate) json: bool,
}

pub(crate) fn run(a: AssessArgs, settings: &Settings, io: &mut Io) -> Exit {
    let (geometry, dims, eta) = match sized(&a.arch, &a.dims, a.eta) {
        Ok(v) => v,
        Err(e) => return io.bad_input(&e),
    };
    let fill = match a.fill.build(dims.as_ref().map(masonry)) {
        Ok(f) => f,
        Err(e) => return io.bad_input(&e),
    };
    let (arch, res) = match a.arch.build() {
        Ok(arch) => {
            let arch = match &fill {
                Some((f, _)) => arch.with_fill(*f),
                None => arch,
            };
            let r = assess(&arch, eta, a.mu, settings);
            (arch, r)
        }
        Err(e) => return io.bad_input(&e),
    };
    let fill = fill.map(|f| f.1);
    let res = match res {
        Ok(r) => r,
        Err(e) => return io.bad_input(&e),
    };
    let least = match &res.limit {
        crate::limit::Outcome::Limit(ls) => Some(ls.eta),
        _ => None,
    };
    if a.json {
        let mut doc = json::assess(&arch, &res);
        doc.fill = fill;
        io.out(&json_with_geometry(&doc, geometry, least));
    } else {
        // with fill the answer states its own scope (the bridge's, not the bare ring's)
        let head = geometry_text(geometry, least);
        let head = match &fill {
            Some(f) => {
                head.replace(crate::render::geometry::RING_SCOPE, "")
                    + &table::bridge(Some(f), None, None, None)
            }
            None => head,
        };
        io.out(&(head + &table::assess(&arch, &res, dims)));
    }
    match res.limit {
        crate::limit::Outcome::Unresolved { .. } => Exit::NoAnswer,
        _ => Exit::Answered,
    }
}
