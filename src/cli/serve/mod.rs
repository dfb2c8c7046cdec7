//! `arch-enum serve`: a local HTTP server with one page (the explorer, `assets/explorer/`)
//! and a JSON API that is the command line itself.
//!
//! A request `/api/solve?alpha=0&mu=0.35` runs `arch-enum solve --alpha=0 --mu=0.35
//! --json` (this binary, as a child process): the body is byte for byte what the CLI
//! prints on standard output. Exit 0 (answered) and exit 1 (no answer for these inputs: no
//! equilibrium, unresolved, ...; the document says which) are `200`; exit 2 (bad input) is
//! `400` with the CLI's error document `{"version", "status": "error", "message"}`.
//! Figures (`/api/plot/arch|load|eccentricity`) are the `plot` command's SVG, `200
//! image/svg+xml`; "no figure" (the plot command's exit 1) is `422` with the error document.
//!
//! The files follow a request: `http` (the connection: its head read and checked, the
//! reply written), `api` (what the request asks for: a page, a command line, an error),
//! `jobs` (the workers, and each command run under the time budget). The server binds
//! 127.0.0.1 only; what bounds each resource is said in `http` and `jobs`.

mod api;
mod http;
mod jobs;

use super::io::{Exit, Io};
use super::serve_args::ServeArgs;
use std::sync::Arc;

pub(crate) fn run(a: ServeArgs, io: &mut Io) -> Exit {
    if !(0.1..=3600.0).contains(&a.budget) {
        return io.bad(format!(
            "invalid value '{}' for --budget: valid range 0.1 to 3600 seconds",
            a.budget
        ));
    }
    let exe = match std::env::current_exe() {
        Ok(e) => e,
        Err(e) => {
            return io.bad(format!(
                "serve: cannot find this program to run commands: {e}"
            ))
        }
    };
    let listener = match std::net::TcpListener::bind(("127.0.0.1", a.port)) {
        Ok(l) => l,
        Err(e) => {
            return io.bad(format!(
                "--port {}: cannot listen on 127.0.0.1: {e}",
                a.port
            ))
        }
    };
    let port = match listener.local_addr() {
        Ok(addr) => addr.port(),
        Err(e) => return io.bad(format!("--port: the server has no address: {e}")),
    };
    let url = format!("http://127.0.0.1:{port}/");
    io.out(&format!("{url}\n"));
    if a.open {
        // harmless when there is no xdg-open
        let _ = std::process::Command::new("xdg-open")
            .arg(&url)
            .stdout(std::process::Stdio::null())
            .stderr(std::process::Stdio::null())
            .spawn();
    }
    let budget = std::time::Duration::from_secs_f64(a.budget);
    let tx = jobs::start(Arc::new(jobs::Shared::new(exe, budget, a.verbose)));
    http::read_heads(&listener, port, |ready| jobs::hand_over(&tx, ready));
    Exit::Answered
}
