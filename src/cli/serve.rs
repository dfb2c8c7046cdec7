//! `arch-enum serve`: a local HTTP server with one page (the explorer, `assets/explorer/`)
//! and a JSON API that is the command line itself.
//!
//! A request `/api/solve?alpha=0&mu=0.35` becomes the argument list
//! `arch-enum solve --alpha=0 --mu=0.35 --json`, parsed by the same clap definitions and
//! run by the same command function as the binary ([`super::run`]), writing into buffers:
//! the body is byte for byte what the CLI prints on standard output. Exit 0 (answered) and
//! exit 1 (no answer for these inputs: no equilibrium, unresolved, ...; the document says
//! which) are `200`; exit 2 (bad input) is `400` with the CLI's error document
//! `{"version", "status": "error", "message"}`. Errors of the server's own (an unknown
//! parameter, a limit below, a malformed query) use the same document. Unknown path: `404`;
//! a method other than GET: `405`; a panic (none is known; each request is caught as a
//! last line of defence): `500`. Figures (`/api/plot/arch|load|eccentricity`) are the
//! `plot` command's SVG, `200 image/svg+xml`; "no figure" (the plot command's exit 1) is
//! `422` with the same error document.
//!
//! Bounded time: the commands whose cost grows with the number of joints are refused above
//! the limits in [`LIMITS`] (measured on the 2-core development machine, release build).
//! Requests are answered by [`WORKERS`] threads taking turns on one listening socket; the
//! server binds 127.0.0.1 only.

use super::app::{run_with, Cli, Command};
use super::io::{to_json, Exit, Io};
use super::serve_args::ServeArgs;
use crate::render::json::ErrorJson;
use clap::{CommandFactory, Parser};
use std::ffi::OsString;
use std::io::Write;
use std::sync::Arc;

/// The explorer page, its script and its style sheet, embedded (no build step, no CDN).
const INDEX_HTML: &str = include_str!("../../assets/explorer/index.html");
const EXPLORER_JS: &str = include_str!("../../assets/explorer/explorer.js");
const EXPLORER_CSS: &str = include_str!("../../assets/explorer/explorer.css");

/// Threads answering requests (the development machine has 2 cores).
pub const WORKERS: usize = 2;

/// The longest request target (path and query) answered, in bytes.
pub const MAX_URL: usize = 8192;

/// The commands the API runs, with the parameters each refuses (they write files or pick
/// the output format; the API always answers `--json` or SVG).
const COMMANDS: &[(&str, &[&str])] = &[
    ("solve", &["compas", "radius"]),
    ("modes", &[]),
    ("assess", &[]),
    ("load", &[]),
    ("certify", &["out"]),
    ("curve", &[]),
];

/// The figures the API draws (`plot <figure>`), as SVG.
const FIGURES: &[&str] = &["arch", "load", "eccentricity"];

/// The parameters that name a live load.
const LOAD_KEYS: &[&str] = &[
    "horizontal",
    "horizontal-left",
    "point-load",
    "point-load-deg",
    "point-load-joint",
];

/// Parameters no endpoint takes: `json` is implied, the rest pick files and formats.
const NEVER: &[&str] = &["json", "help", "version", "out", "png"];

/// Parameters the figures refuse: `width` is the PNG's there (the API draws SVG); the
/// commands take it as the barrel width.
const FIGURE_NEVER: &[&str] = &["width"];

/// A limit on a count-valued parameter of one endpoint.
pub struct Limit {
    /// The endpoint (`solve`, `plot/arch`, ...).
    pub endpoint: &'static str,
    /// `blocks` (also bounds the number of `joints` angles, N + 1) or `points`.
    pub param: &'static str,
    /// The largest value served.
    pub max: usize,
}

/// The limits that keep one request within about 2 s. Measured (release build, 2 cores,
/// wall time of the CLI call):
/// - `solve` at N = 100000: 0.4–0.9 s (α = 0 and −1.2, μ from μ_ms to ∞, both weights);
///   `assess` 0.9–1.3 s; `certify` 0.7–0.8 s; the `arch`/`eccentricity` figures 0.5–1.0 s.
/// - `load` at N = 5000 (horizontal acceleration, α = 0, η = 0.3, μ = 0.8): 1.0–1.4 s
///   (N = 10000: 3.9 s); `plot load` 1.4 s; `certify` with that load ("certify/load")
///   1.5 s (N = 10000: 4.7 s).
/// - `modes` (centreline weight) at N = 200: 0.4–1.1 s over α ∈ {0, ±0.5, 1, −1.2}
///   (N = 400: up to 3.6 s; N = 1000: up to 16 s); the continuous arch 0.05–0.08 s.
///   With the centroid weight ("modes/centroid") the limit states above η_s are swept
///   (no ridge walk): N = 70: 0.7–1.3 s (N = 100: up to 3.0 s, N = 200: up to 18.5 s);
///   the continuous arch 0.2–3.0 s (no N to limit).
/// - `curve` at N = 2000, 100 points: 0.8 s (centroid weight: 1.0 s).
#[rustfmt::skip]
pub const LIMITS: &[Limit] = &[
    Limit { endpoint: "solve", param: "blocks", max: 100_000 },
    Limit { endpoint: "assess", param: "blocks", max: 100_000 },
    Limit { endpoint: "certify", param: "blocks", max: 100_000 },
    Limit { endpoint: "plot/arch", param: "blocks", max: 100_000 },
    Limit { endpoint: "plot/eccentricity", param: "blocks", max: 100_000 },
    Limit { endpoint: "load", param: "blocks", max: 5_000 },
    Limit { endpoint: "certify/load", param: "blocks", max: 5_000 },
    Limit { endpoint: "plot/load", param: "blocks", max: 5_000 },
    Limit { endpoint: "modes", param: "blocks", max: 200 },
    Limit { endpoint: "modes/centroid", param: "blocks", max: 70 },
    Limit { endpoint: "curve", param: "blocks", max: 2_000 },
    Limit { endpoint: "curve", param: "points", max: 100 },
];

/// One HTTP answer.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Reply {
    /// HTTP status code.
    pub status: u16,
    /// The Content-Type header.
    pub content_type: &'static str,
    /// The body.
    pub body: Vec<u8>,
}

const JSON: &str = "application/json";

impl Reply {
    fn error(status: u16, message: String) -> Reply {
        Reply {
            status,
            content_type: JSON,
            body: to_json(&ErrorJson::new(message)).into_bytes(),
        }
    }
    fn text(content_type: &'static str, body: &str) -> Reply {
        Reply {
            status: 200,
            content_type,
            body: body.as_bytes().to_vec(),
        }
    }
}

/// The answer to `method url` (url: the request target, path and query). Never panics
/// (a panic inside a command is caught and answered `500`).
pub fn respond(method: &str, url: &str) -> Reply {
    match std::panic::catch_unwind(|| answer(method, url)) {
        Ok(r) => r,
        Err(_) => Reply::error(500, "internal error: the request panicked".into()),
    }
}

fn answer(method: &str, url: &str) -> Reply {
    if url.len() > MAX_URL {
        return Reply::error(
            400,
            format!(
                "the request URL is {} bytes long; at most {MAX_URL} are served",
                url.len()
            ),
        );
    }
    let (path, query) = url.split_once('?').unwrap_or((url, ""));
    let page = match path {
        "/" | "/index.html" => Some(("text/html; charset=utf-8", INDEX_HTML)),
        "/explorer.js" => Some(("text/javascript; charset=utf-8", EXPLORER_JS)),
        "/explorer.css" => Some(("text/css; charset=utf-8", EXPLORER_CSS)),
        _ => None,
    };
    let endpoint = path.strip_prefix("/api/");
    let known = page.is_some()
        || endpoint.is_some_and(|e| {
            COMMANDS.iter().any(|(c, _)| *c == e)
                || e.strip_prefix("plot/")
                    .is_some_and(|f| FIGURES.contains(&f))
        });
    if !known {
        return Reply::error(404, format!("no such page or endpoint: {path}"));
    }
    if method != "GET" {
        return Reply::error(
            405,
            format!("method {method} not allowed: only GET is served"),
        );
    }
    if let Some((content_type, body)) = page {
        return Reply::text(content_type, body);
    }
    let endpoint = endpoint.expect("a known API path");
    let params = match parse_query(query) {
        Ok(p) => p,
        Err(message) => return Reply::error(400, message),
    };
    match endpoint.strip_prefix("plot/") {
        Some(figure) => run_figure(figure, &params),
        None => run_command(endpoint, &params),
    }
}

/// A query parameter, percent-decoded; `value` is `None` for a bare key (`?horizontal`).
struct Param {
    key: String,
    value: Option<String>,
}

/// `%XX` and `+` decoding; the text must be UTF-8 once decoded.
fn percent_decode(s: &str, what: &str) -> Result<String, String> {
    let b = s.as_bytes();
    let mut out = Vec::with_capacity(b.len());
    let mut i = 0;
    while i < b.len() {
        match b[i] {
            b'%' => {
                let hex = b
                    .get(i + 1..i + 3)
                    .and_then(|h| std::str::from_utf8(h).ok())
                    .and_then(|h| u8::from_str_radix(h, 16).ok());
                match hex {
                    Some(byte) if b[i + 1].is_ascii_hexdigit() => out.push(byte),
                    _ => {
                        return Err(format!(
                            "malformed percent-encoding in {what}: '%' must be followed by two hex digits"
                        ))
                    }
                }
                i += 3;
            }
            b'+' => {
                out.push(b' ');
                i += 1;
            }
            c => {
                out.push(c);
                i += 1;
            }
        }
    }
    String::from_utf8(out).map_err(|_| format!("{what} is not valid UTF-8 once percent-decoded"))
}

fn parse_query(query: &str) -> Result<Vec<Param>, String> {
    let mut params = Vec::new();
    for piece in query.split('&').filter(|p| !p.is_empty()) {
        let (k, v) = match piece.split_once('=') {
            Some((k, v)) => (k, Some(v)),
            None => (piece, None),
        };
        let key = percent_decode(k, "a parameter name")?;
        let value = match v {
            Some(v) => Some(percent_decode(v, &format!("the value of '{key}'"))?),
            None => None,
        };
        params.push(Param { key, value });
    }
    Ok(params)
}

/// The clap definition of `path` (`["solve"]`, `["plot", "arch"]`).
fn command_of(path: &[&str]) -> clap::Command {
    let mut cmd = Cli::command();
    for p in path {
        cmd = cmd
            .find_subcommand(p)
            .expect("a whitelisted command exists")
            .clone();
    }
    cmd
}

/// The CLI argument list of `path` and `params`: `--key=value` for a value, `--key` for a
/// flag; a key must be a long option of the command (underscores read as hyphens) and
/// not refused.
fn arguments(path: &[&str], refused: &[&str], params: &[Param]) -> Result<Vec<OsString>, String> {
    let cmd = command_of(path);
    let endpoint = path.join("/");
    let accepted: Vec<(String, bool)> = cmd
        .get_arguments()
        .filter_map(|a| {
            let long = a.get_long()?;
            let refused = NEVER.contains(&long) || refused.contains(&long);
            (!refused).then(|| (long.to_string(), a.get_action().takes_values()))
        })
        .collect();
    // certify with a live load costs what load does; modes with the centroid weight more
    let loaded = params
        .iter()
        .any(|p| LOAD_KEYS.contains(&p.key.replace('_', "-").as_str()));
    let centroid = params
        .iter()
        .any(|p| p.key == "weight" && p.value.as_deref() == Some("centroid"));
    let limited = match endpoint.as_str() {
        "certify" if loaded => "certify/load".to_string(),
        "modes" if centroid => "modes/centroid".to_string(),
        _ => endpoint.clone(),
    };
    let mut args: Vec<OsString> = vec!["arch-enum".into()];
    args.extend(path.iter().map(OsString::from));
    for p in params {
        let key = p.key.replace('_', "-");
        let Some((_, takes_value)) = accepted.iter().find(|(k, _)| *k == key) else {
            let names: Vec<&str> = accepted.iter().map(|(k, _)| k.as_str()).collect();
            return Err(format!(
                "unknown parameter '{}' for /api/{endpoint}; valid parameters: {}",
                p.key,
                names.join(", ")
            ));
        };
        match (takes_value, p.value.as_deref()) {
            (true, Some(v)) => args.push(format!("--{key}={v}").into()),
            (true, None) => {
                return Err(format!(
                    "parameter '{key}' needs a value ({key}=...); see `arch-enum {} --help`",
                    path.join(" ")
                ))
            }
            (false, None | Some("" | "true" | "1")) => args.push(format!("--{key}").into()),
            (false, Some("false" | "0")) => {}
            (false, Some(v)) => {
                return Err(format!(
                    "parameter '{key}' is a flag: give it without a value, or =true / =false (got '{v}')"
                ))
            }
        }
        check_limit(&limited, &key, p.value.as_deref())?;
    }
    Ok(args)
}

/// Refuses a count above the endpoint's [`LIMITS`] (a value that is not a count is left
/// to clap, which names it).
fn check_limit(endpoint: &str, key: &str, value: Option<&str>) -> Result<(), String> {
    let Some(value) = value else { return Ok(()) };
    let (param, count) = match key {
        "joints" => ("blocks", value.split(',').count().saturating_sub(1)),
        "blocks" | "points" => match value.parse::<usize>() {
            Ok(n) => (key, n),
            Err(_) => return Ok(()),
        },
        _ => return Ok(()),
    };
    let shown = match endpoint {
        "certify/load" => "/api/certify with a live load".to_string(),
        "modes/centroid" => "/api/modes with --weight centroid".to_string(),
        e => format!("/api/{e}"),
    };
    match LIMITS
        .iter()
        .find(|l| l.endpoint == endpoint && l.param == param)
    {
        Some(l) if count > l.max => Err(if key == "joints" {
            format!(
                "--joints gives {} joints; {shown} serves at most {} (N <= {} voussoirs, to answer within about 2 s; the command line has no such limit)",
                count + 1,
                l.max + 1,
                l.max
            )
        } else {
            format!(
                "invalid value for --{key}: {count} (valid range for {shown}: 1 to {}, to answer within about 2 s; the command line has no such limit)",
                l.max
            )
        }),
        _ => Ok(()),
    }
}

/// Bad input reported by a command on its standard error ("error: ..." lines, clap's
/// first paragraph) as one message.
fn message_of(err: &[u8]) -> String {
    let text = String::from_utf8_lossy(err);
    let lines: Vec<&str> = text
        .lines()
        .take_while(|l| !l.trim().is_empty())
        .map(|l| l.trim().trim_start_matches("error: "))
        .collect();
    lines.join(" ")
}

fn run_command(command: &str, params: &[Param]) -> Reply {
    let refused = COMMANDS
        .iter()
        .find(|(c, _)| *c == command)
        .map_or(&[][..], |(_, r)| *r);
    let mut args = match arguments(&[command], refused, params) {
        Ok(a) => a,
        Err(message) => return Reply::error(400, message),
    };
    args.push("--json".into());
    let (mut out, mut err) = (Vec::new(), Vec::new());
    let code = run_with(args, &mut out, &mut err, run);
    if code == Exit::BadInput.code() {
        if out.is_empty() {
            return Reply::error(400, message_of(&err));
        }
        return Reply {
            status: 400,
            content_type: JSON,
            body: out,
        };
    }
    Reply {
        status: 200,
        content_type: JSON,
        body: out,
    }
}

fn run_figure(figure: &str, params: &[Param]) -> Reply {
    let args = match arguments(&["plot", figure], FIGURE_NEVER, params) {
        Ok(a) => a,
        Err(message) => return Reply::error(400, message),
    };
    let (mut out, mut err) = (Vec::new(), Vec::new());
    let parsed = match Cli::try_parse_from(&args) {
        Ok(Cli {
            command: Command::Plot { figure },
        }) => figure,
        Ok(_) => return Reply::error(500, "internal error: not a figure".into()),
        Err(e) => return Reply::error(400, message_of(e.render().to_string().as_bytes())),
    };
    let mut io = Io {
        out: &mut out,
        err: &mut err,
        json: false,
    };
    match super::plot::draw(parsed, &crate::settings::Settings::default(), &mut io) {
        Ok(svg) => Reply {
            status: 200,
            content_type: "image/svg+xml",
            body: svg.into_bytes(),
        },
        Err(Exit::BadInput) => Reply::error(400, message_of(&err)),
        Err(_) => Reply::error(422, message_of(&err)),
    }
}

pub(crate) fn run(a: ServeArgs, io: &mut Io) -> Exit {
    let server = match tiny_http::Server::http(("127.0.0.1", a.port)) {
        Ok(s) => Arc::new(s),
        Err(e) => {
            return io.bad(format!(
                "--port {}: cannot listen on 127.0.0.1: {e}",
                a.port
            ))
        }
    };
    let url = match server.server_addr().to_ip() {
        Some(addr) => format!("http://{addr}/"),
        None => return io.bad("--port: the server has no IP address".into()),
    };
    io.out(&format!("{url}\n"));
    if a.open {
        // harmless when there is no xdg-open
        let _ = std::process::Command::new("xdg-open")
            .arg(&url)
            .stdout(std::process::Stdio::null())
            .stderr(std::process::Stdio::null())
            .spawn();
    }
    super::progress::quiet();
    let workers: Vec<_> = (0..WORKERS)
        .map(|_| {
            let server = Arc::clone(&server);
            let verbose = a.verbose;
            std::thread::spawn(move || {
                for request in server.incoming_requests() {
                    serve_one(request, verbose);
                }
            })
        })
        .collect();
    for w in workers {
        let _ = w.join();
    }
    Exit::Answered
}

fn serve_one(request: tiny_http::Request, verbose: bool) {
    let start = std::time::Instant::now();
    let method = request.method().as_str().to_string();
    let reply = respond(&method, request.url());
    let status = reply.status;
    let mut response = tiny_http::Response::from_data(reply.body)
        .with_status_code(status)
        .with_header(header("Content-Type", reply.content_type))
        .with_header(header("Cache-Control", "no-store"));
    if status == 405 {
        response = response.with_header(header("Allow", "GET"));
    }
    if verbose {
        let _ = writeln!(
            std::io::stderr(),
            "{method} {} {status} {:.1} ms",
            request.url(),
            start.elapsed().as_secs_f64() * 1e3
        );
    }
    // a client that went away is not an error of ours
    let _ = request.respond(response);
}

fn header(name: &str, value: &str) -> tiny_http::Header {
    tiny_http::Header::from_bytes(name.as_bytes(), value.as_bytes())
        .expect("ASCII header names and values")
}
