//! `--threads`, shared by the commands that spread independent work over threads.

use crate::arch::InputError;
use clap::Args;

/// The most threads a command accepts.
const MAX_THREADS: usize = 1024;

#[derive(Args, Debug, Clone, Copy)]
pub(crate) struct ThreadsArg {
    /// Worker threads (1 to 1024; default: every core the machine offers). The answer does
    /// not depend on it.
    #[arg(long, allow_hyphen_values = true)]
    threads: Option<usize>,
}

impl ThreadsArg {
    /// The thread count asked for, or every core; out of range is an error naming
    /// `--threads`.
    pub(crate) fn count(&self) -> Result<usize, InputError> {
        match self.threads {
            None => Ok(crate::threads::available()),
            Some(t) if (1..=MAX_THREADS).contains(&t) => Ok(t),
            Some(t) => Err(InputError::OutOfRange {
                arg: "--threads",
                value: t.to_string(),
                range: format!("whole numbers 1 to {MAX_THREADS}"),
            }),
        }
    }
}
