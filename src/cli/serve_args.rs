//! The arguments of `arch-enum serve`.

/// `arch-enum serve`.
#[derive(clap::Args, Debug)]
pub(crate) struct ServeArgs {
    /// Port on 127.0.0.1, 0 to 65535 (0: any free port). The URL is printed on the first
    /// line.
    #[arg(long, default_value_t = 8765, allow_negative_numbers = true)]
    pub(super) port: u16,
    /// Open the page in the browser (xdg-open, when present).
    #[arg(long)]
    pub(super) open: bool,
    /// Log each request with its status and time on standard error.
    #[arg(long)]
    pub(super) verbose: bool,
    /// Seconds a request's computation may take (0.1 to 3600); longer work is stopped and
    /// answered 503.
    #[arg(long, default_value_t = 30.0, allow_negative_numbers = true)]
    pub(super) budget: f64,
}
