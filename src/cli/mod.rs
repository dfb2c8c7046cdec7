//! The command-line interface: argument parsing, one library call per command, rendering,
//! and the single place where what happened becomes an exit code ([`Exit::code`]):
//! 0 answered, 1 the question has no answer for these inputs, 2 bad input.
//!
//! One file per command, holding its arguments and its run function; `arch_args` holds
//! the description of the arch that every command shares, `io` the exit codes and where a
//! command writes, `app` the parser and the dispatch. The explorer's server (`serve`) runs
//! commands through `app` too; this file hands `app` the server's entry point, so that
//! neither imports the other.

mod app;
mod arch_args;
mod assess;
mod atlas;
mod bridge_args;
mod certify;
mod curve;
mod dimension_args;
mod io;
pub(crate) mod load;
mod modes;
mod mu_arg;
mod plot;
mod progress;
mod report;
pub mod serve;
mod serve_args;
mod solve;
mod threads_arg;

pub use io::{Exit, EXIT_BAD_INPUT, EXIT_NO_ANSWER, EXIT_OK};

use std::ffi::OsString;
use std::io::Write;

/// Runs the command line `args` (including the program name), writing results to
/// `out` and diagnostics to `err`; returns the exit status.
pub fn run<I, T>(args: I, out: &mut dyn Write, err: &mut dyn Write) -> i32
where
    I: IntoIterator<Item = T>,
    T: Into<OsString> + Clone,
{
    app::run_with(args, out, err, serve::run)
}
