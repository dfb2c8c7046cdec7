//! The arguments of `arch-enum serve`.

/// `arch-enum serve`.
#[derive(clap::Args, Debug)]
pub(crate) struct ServeArgs {
    /// Port on 127.0.0.1 (0: any free port). The URL is printed on the first line.
    #[arg(long, default_value_t = 8765)]
    pub(super) port: u16,
    /// Open the page in the browser (xdg-open, when present).
    #[arg(long)]
    pub(super) open: bool,
    /// Log each request with its status and time on standard error.
    #[arg(long)]
    pub(super) verbose: bool,
}
