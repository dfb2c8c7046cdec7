//! Progress on standard error for commands that run longer than a second: a `\r` bar
//! when standard error is a terminal, else a plain line at most every ten percent.
//! Nothing is printed for work that finishes within the first second.

use std::io::{IsTerminal, Write};
use std::sync::Mutex;
use std::time::{Duration, Instant};

/// Quiet period before the first report.
const QUIET: Duration = Duration::from_secs(1);

/// The environment variable that silences progress: `ARCH_ENUM_PROGRESS=off` (set by
/// `serve` for the commands it runs, whose standard error it reads).
pub(crate) const PROGRESS_ENV: &str = "ARCH_ENUM_PROGRESS";

/// Whether progress is silenced for this process.
fn silenced() -> bool {
    static OFF: std::sync::OnceLock<bool> = std::sync::OnceLock::new();
    *OFF.get_or_init(|| std::env::var_os(PROGRESS_ENV).is_some_and(|v| v == "off"))
}

/// A progress reporter, safe to call from several threads.
pub(crate) struct Progress {
    label: &'static str,
    start: Instant,
    tty: bool,
    /// The last reported tenth (plain lines) and whether anything was printed.
    state: Mutex<(usize, bool)>,
}

impl Progress {
    /// A reporter for work named `label` (e.g. "curve"), started now.
    pub(crate) fn new(label: &'static str) -> Progress {
        Progress {
            label,
            start: Instant::now(),
            tty: std::io::stderr().is_terminal(),
            state: Mutex::new((0, false)),
        }
    }

    /// Reports that `done` of `total` units are finished.
    pub(crate) fn update(&self, done: usize, total: usize) {
        if silenced() || (self.start.elapsed() < QUIET && done < total) {
            return;
        }
        let mut st = self.state.lock().unwrap_or_else(|e| e.into_inner());
        let total = total.max(1);
        let mut err = std::io::stderr().lock();
        if self.tty {
            if !done.is_multiple_of(16) && done != total {
                return;
            }
            let bar = 30 * done / total;
            let _ = write!(
                err,
                "\r{} [{}{}] {done}/{total}",
                self.label,
                "#".repeat(bar),
                " ".repeat(30 - bar)
            );
            if done == total {
                let _ = writeln!(err);
            }
            st.1 = true;
        } else {
            let tenth = 10 * done / total;
            if tenth > st.0 || (done == total && st.1) {
                if !(done == total && st.0 == 10) {
                    let _ = writeln!(
                        err,
                        "{}: {done}/{total} ({:.1} s)",
                        self.label,
                        self.start.elapsed().as_secs_f64()
                    );
                }
                st.0 = tenth;
                st.1 = true;
            }
        }
    }
}
