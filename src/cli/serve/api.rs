//! What a request asks for: a page, or a command line for the CLI to run, or an error.
//!
//! A request `/api/solve?alpha=0&mu=0.35` becomes the argument list
//! `solve --alpha=0 --mu=0.35 --json`, checked against the same clap definitions as the
//! binary's (an unknown or refused parameter is named here, before anything runs), and
//! a figure `/api/plot/arch?...` becomes `plot arch ... --out -` (SVG on standard output),
//! and `/api/report?...` becomes `report --out - ...` (the HTML page).
//! Errors of the request itself (an unknown parameter, a limit below, a malformed query)
//! use the CLI's error document `{"version", "status": "error", "message"}`. Unknown path:
//! `404`; a method other than GET: `405`; a URL over [`MAX_URL`] bytes: `414`.
//!
//! Bounded work: the commands whose cost grows with the number of joints are refused above
//! the limits in [`LIMITS`] (measured on the 2-core development machine, release build);
//! what is left is bounded by the server's time budget.

use super::http::Reply;
use crate::cli::app::Cli;
use clap::CommandFactory;
use std::ffi::OsString;

/// The explorer page, its script and its style sheet, embedded (no build step, no CDN).
const INDEX_HTML: &str = include_str!("../../../assets/explorer/index.html");
const EXPLORER_JS: &str = include_str!("../../../assets/explorer/explorer.js");
const EXPLORER_CSS: &str = include_str!("../../../assets/explorer/explorer.css");

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
    ("report", &[]),
];

/// The figures the API draws (`plot <figure>`), as SVG, with the parameters each refuses:
/// `width` is the PNG's where the command takes no barrel width (the API draws SVG).
const FIGURES: &[(&str, &[&str])] = &[
    ("arch", &["width"]),
    ("load", &["width"]),
    ("eccentricity", &["width"]),
    ("influence", &["png-width"]),
];

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
/// - `load` at N = 1000 (α = 0, η = 0.3, μ = 0.6; above 511 voussoirs the face search,
///   whose work grows like N²): 0.13–0.15 s under a horizontal or a point load since
///   2026-12-08, 0.6–0.9 s before (N = 2000: 0.45 s; N = 4095: 1.8–1.9 s); `plot load`
///   likewise (0.12 s); `certify` with a load ("certify/load") 0.86–0.91 s, most of it
///   the proofs of the points the search checked (N = 2000: 2.9–3.4 s). Before the face
///   search, N = 5000 took 1.0–1.5 s with the search not done.
/// - `modes` (centreline weight) at N = 200: 0.4–1.1 s over α ∈ {0, ±0.5, 1, −1.2}
///   (N = 400: up to 3.6 s; N = 1000: up to 16 s); the continuous arch 0.05–0.08 s.
///   With the centroid weight ("modes/centroid") the limit states above η_s are swept
///   (no ridge walk): N = 70: 0.7–1.3 s (N = 100: up to 3.0 s, N = 200: up to 18.5 s);
///   the continuous arch 0.2–3.0 s (no N to limit).
/// - `curve` at N = 2000, 100 points: 0.8 s (centroid weight: 1.0 s).
/// - `plot/influence` and `report` run the critical position (tens of multiplier searches):
///   N ≤ 200; a continuous arch has no N, and the time budget bounds it (the README's
///   bridge: 1–7 s).
#[rustfmt::skip]
pub const LIMITS: &[Limit] = &[
    Limit { endpoint: "solve", param: "blocks", max: 100_000 },
    Limit { endpoint: "assess", param: "blocks", max: 100_000 },
    Limit { endpoint: "certify", param: "blocks", max: 100_000 },
    Limit { endpoint: "plot/arch", param: "blocks", max: 100_000 },
    Limit { endpoint: "plot/eccentricity", param: "blocks", max: 100_000 },
    Limit { endpoint: "load", param: "blocks", max: 1_000 },
    Limit { endpoint: "certify/load", param: "blocks", max: 1_000 },
    Limit { endpoint: "plot/load", param: "blocks", max: 1_000 },
    Limit { endpoint: "modes", param: "blocks", max: 200 },
    Limit { endpoint: "modes/centroid", param: "blocks", max: 70 },
    Limit { endpoint: "curve", param: "blocks", max: 2_000 },
    Limit { endpoint: "curve", param: "points", max: 100 },
    Limit { endpoint: "plot/influence", param: "blocks", max: 200 },
    Limit { endpoint: "report", param: "blocks", max: 200 },
];

/// What a request asks for.
#[derive(Debug)]
pub(super) enum Route {
    /// An answer at once: a page, or an error of the request.
    Reply(Reply),
    /// A command line to run (without the program's name), and what it prints.
    Run { args: Vec<OsString>, prints: Prints },
}

/// What a command run for the API prints on standard output.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(super) enum Prints {
    /// A `--json` document (also on bad input).
    Json,
    /// A figure (SVG).
    Svg,
    /// The report (HTML).
    Html,
}

/// The route of `method url` (url: the request target, path and query).
pub(super) fn route(method: &str, url: &str) -> Route {
    match answer(method, url) {
        Ok(run) => run,
        Err(reply) => Route::Reply(reply),
    }
}

fn answer(method: &str, url: &str) -> Result<Route, Reply> {
    if url.len() > MAX_URL {
        return Err(Reply::error(
            414,
            format!(
                "the request URL is {} bytes long; at most {MAX_URL} are served",
                url.len()
            ),
        ));
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
                    .is_some_and(|f| FIGURES.iter().any(|(g, _)| *g == f))
        });
    if !known {
        return Err(Reply::error(
            404,
            format!("no such page or endpoint: {path}"),
        ));
    }
    if method != "GET" {
        return Err(Reply::error(
            405,
            format!("method {method} not allowed: only GET is served"),
        ));
    }
    if let Some((content_type, body)) = page {
        if path == "/explorer.js" {
            let script = body.replacen("/*MODE_COLOURS*/{}", &mode_colours(), 1);
            return Ok(Route::Reply(Reply::text(content_type, &script)));
        }
        return Ok(Route::Reply(Reply::text(content_type, body)));
    }
    let endpoint = endpoint.expect("a known API path");
    let params = parse_query(query).map_err(|message| Reply::error(400, message))?;
    let run = match endpoint.strip_prefix("plot/") {
        Some(figure) => {
            let refused = FIGURES
                .iter()
                .find(|(f, _)| *f == figure)
                .map_or(&[][..], |(_, r)| *r);
            let mut args = arguments(&["plot", figure], refused, &params)?;
            args.push("--out=-".into());
            Route::Run {
                args,
                prints: Prints::Svg,
            }
        }
        None if endpoint == "report" => {
            let mut args = arguments(&["report"], &[], &params)?;
            args.insert(1, "--out=-".into());
            Route::Run {
                args,
                prints: Prints::Html,
            }
        }
        None => {
            let refused = COMMANDS
                .iter()
                .find(|(c, _)| *c == endpoint)
                .map_or(&[][..], |(_, r)| *r);
            let mut args = arguments(&[endpoint], refused, &params)?;
            args.push("--json".into());
            Route::Run {
                args,
                prints: Prints::Json,
            }
        }
    };
    Ok(run)
}

/// The figures' mode colours as a JavaScript object (`{"purely_rotational": "#1f77b4", ...}`),
/// so that the page and the figures share one table.
fn mode_colours() -> String {
    use crate::collapse_mode::CollapseMode;
    let entries: Vec<String> = CollapseMode::ALL
        .iter()
        .map(|&m| {
            let c = crate::render::plot::mode_color(m);
            format!("\"{}\": \"#{:02x}{:02x}{:02x}\"", m.name(), c.0, c.1, c.2)
        })
        .collect();
    format!("{{{}}}", entries.join(", "))
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
fn arguments(path: &[&str], refused: &[&str], params: &[Param]) -> Result<Vec<OsString>, Reply> {
    arguments_of(path, refused, params).map_err(|message| Reply::error(400, message))
}

fn arguments_of(
    path: &[&str],
    refused: &[&str],
    params: &[Param],
) -> Result<Vec<OsString>, String> {
    let endpoint = path.join("/");
    // the report takes the flags of assess and load (and its title)
    let defined: Vec<clap::Command> = if path == ["report"] {
        vec![
            command_of(&["assess"]),
            command_of(&["load"]),
            command_of(path),
        ]
    } else {
        vec![command_of(path)]
    };
    let mut accepted: Vec<(String, bool)> = Vec::new();
    for a in defined.iter().flat_map(|c| c.get_arguments()) {
        let Some(long) = a.get_long() else { continue };
        let refused = NEVER.contains(&long) || refused.contains(&long) || long == "flags";
        if !refused && !accepted.iter().any(|(k, _)| k == long) {
            accepted.push((long.to_string(), a.get_action().takes_values()));
        }
    }
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
    let mut args: Vec<OsString> = path.iter().map(OsString::from).collect();
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
        if p.value.as_deref().is_some_and(|v| v.contains('\0')) {
            return Err(format!(
                "invalid value for --{key}: it contains a NUL character"
            ));
        }
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
