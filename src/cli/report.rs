//! `arch-enum report`: the assessment of one arch as a self-contained HTML page, made of the
//! commands themselves: `assess`, `load` (with `--critical` for a vehicle), `certify` and
//! `verify`, and the `plot` figures, each run on the flags it accepts with `--json` (or
//! `--out -` for a figure), so that the report's numbers are the command line's.

use super::io::{message_of, Exit, Io};
use crate::render::report::{html, Certified, ReportInput};
use serde_json::Value;
use std::ffi::OsString;
use std::path::PathBuf;

/// `arch-enum report`.
#[derive(clap::Args, Debug)]
pub(crate) struct ReportArgs {
    /// The HTML file written (`-`: standard output).
    #[arg(long, default_value = "report.html")]
    out: PathBuf,
    /// The report's title (default: "Assessment of an arch").
    #[arg(long)]
    title: Option<String>,
    /// The arch and the question, as for `assess` (the arch, --eta or --ring, --mu, a fill),
    /// and optionally a live load as for `load` (a vehicle, whose critical position is
    /// found unless --at is given, or a point load or horizontal acceleration).
    #[arg(
        trailing_var_arg = true,
        allow_hyphen_values = true,
        num_args = 0..,
        value_name = "FLAGS"
    )]
    flags: Vec<String>,
}

/// What a command run left: its exit code, standard output and standard error.
pub(crate) struct Ran {
    pub(super) code: i32,
    pub(super) out: Vec<u8>,
    pub(super) err: Vec<u8>,
}

/// How the report runs the commands: the parser's definitions and the command line itself,
/// handed in by the dispatcher (so that the two do not import each other).
pub(crate) struct Runner<'a> {
    pub(super) cli: clap::Command,
    pub(super) run: &'a dyn Fn(Vec<OsString>) -> Ran,
}

/// The flags naming a vehicle, and the other live loads.
const VEHICLE: &[&str] = &["axles", "patch"];
const LIVE: &[&str] = &[
    "axles",
    "patch",
    "horizontal",
    "horizontal-left",
    "point-load",
    "point-load-deg",
    "point-load-joint",
];

/// A flag as given: its long name and its value (none for a switch).
type Flag = (String, Option<String>);

pub(crate) fn run(mut a: ReportArgs, io: &mut Io, runner: &Runner) -> Exit {
    let flags = match tokens(&mut a, &runner.cli) {
        Ok(f) => f,
        Err(message) => return io.bad(message),
    };
    let has = |names: &[&str]| flags.iter().any(|(k, _)| names.contains(&k.as_str()));
    let exec =
        |path: &[&str], extra: &[&str], drop: &[&str]| command(runner, path, &flags, extra, drop);
    let assess = match document(exec(&["assess"], &["--json"], &[])) {
        Ok(v) => v,
        Err(message) => return io.bad(message),
    };
    let critical: &[&str] = if has(VEHICLE) && !has(&["at", "critical"]) {
        &["--critical"]
    } else {
        &[]
    };
    let load = if has(LIVE) {
        let extra = [critical, &["--json"]].concat();
        match document(exec(&["load"], &extra, &[])) {
            Ok(v) => Some(v),
            Err(message) => return io.bad(message),
        }
    } else {
        None
    };
    // the certificate of the vehicle at the X* just found (the same float)
    let at = load
        .as_ref()
        .and_then(|l| l["critical"]["at_m"].as_f64())
        .map(|x| format!("--at={x}"));
    let at_critical: Vec<&str> = at.iter().map(String::as_str).collect();
    let certified = certify(&exec, has(LIVE), &at_critical);
    let figures = figures(&exec, has(VEHICLE), has(LIVE), critical);
    let flags_text = flags
        .iter()
        .map(|(k, v)| match v {
            Some(v) => format!("--{k} {v}"),
            None => format!("--{k}"),
        })
        .collect::<Vec<_>>();
    let versions = format!(
        "arch-enum {} (LP: {}); {}",
        env!("CARGO_PKG_VERSION"),
        crate::lp::highs::SOLVER,
        "the report runs the command line's own commands on the flags above"
    );
    let certificate = match &certified {
        Ok((summary, file, verified)) => Ok(Certified {
            summary,
            file,
            verified: (&verified.0, verified.1),
        }),
        Err(why) => Err(why.clone()),
    };
    let page = html(&ReportInput {
        title: a.title.as_deref().unwrap_or("Assessment of an arch"),
        flags: &flags_text,
        assess: &assess,
        load: load.as_ref(),
        certificate,
        figures: &figures,
        versions: &versions,
    });
    if a.out.as_os_str() == "-" {
        io.out(&page);
        return Exit::Answered;
    }
    if let Err(e) = std::fs::write(&a.out, page) {
        return io.bad(format!("cannot write --out {}: {e}", a.out.display()));
    }
    io.out(&format!("wrote {}\n", a.out.display()));
    Exit::Answered
}

/// The flags as (name, value) pairs, each a long option of `assess` or `load`; `--out` and
/// `--title` given among them are the report's own.
fn tokens(a: &mut ReportArgs, cli: &clap::Command) -> Result<Vec<Flag>, String> {
    let known: Vec<(String, bool)> = ["assess", "load"]
        .iter()
        .filter_map(|c| cli.find_subcommand(c))
        .flat_map(|c| c.get_arguments())
        .filter_map(|arg| Some((arg.get_long()?.to_string(), arg.get_action().takes_values())))
        .filter(|(k, _)| !matches!(k.as_str(), "json" | "help"))
        .collect();
    let mut flags = Vec::new();
    let mut it = a.flags.clone().into_iter();
    while let Some(t) = it.next() {
        let Some(body) = t.strip_prefix("--") else {
            return Err(format!(
                "unexpected argument '{t}' for report: give flags (--name value) as for assess and load"
            ));
        };
        let (name, inline) = match body.split_once('=') {
            Some((n, v)) => (n.to_string(), Some(v.to_string())),
            None => (body.to_string(), None),
        };
        let own = matches!(name.as_str(), "out" | "title");
        let takes = own || known.iter().any(|(k, v)| *k == name && *v);
        if !own && !known.iter().any(|(k, _)| *k == name) {
            return Err(format!(
                "unknown flag --{name} for report: it takes the flags of assess and load (see arch-enum assess --help, arch-enum load --help), and --out, --title"
            ));
        }
        let value = match (takes, inline) {
            (true, Some(v)) => Some(v),
            (true, None) => Some(it.next().ok_or(format!("--{name} needs a value"))?),
            (false, Some(_)) => return Err(format!("--{name} takes no value")),
            (false, None) => None,
        };
        match (name.as_str(), value) {
            ("out", Some(v)) => a.out = v.into(),
            ("title", Some(v)) => a.title = Some(v),
            (_, value) => flags.push((name, value)),
        }
    }
    Ok(flags)
}

/// Runs `path` on the flags it accepts (and not in `drop`), with `extra` after them.
fn command(runner: &Runner, path: &[&str], flags: &[Flag], extra: &[&str], drop: &[&str]) -> Ran {
    let mut cmd = runner.cli.clone();
    for p in path {
        cmd = cmd.find_subcommand(p).cloned().unwrap_or_default();
    }
    let accepted: Vec<&str> = cmd.get_arguments().filter_map(|a| a.get_long()).collect();
    let mut args: Vec<OsString> = vec!["arch-enum".into()];
    args.extend(path.iter().map(OsString::from));
    for (k, v) in flags {
        if accepted.contains(&k.as_str()) && !drop.contains(&k.as_str()) {
            args.push(match v {
                Some(v) => format!("--{k}={v}").into(),
                None => format!("--{k}").into(),
            });
        }
    }
    args.extend(extra.iter().map(OsString::from));
    (runner.run)(args)
}

/// A command's JSON document (exit 0 or 1), or its error message (exit 2, or no document).
fn document(ran: Ran) -> Result<Value, String> {
    let first_error = || message_of(&ran.err);
    if ran.code == 2 {
        return Err(first_error());
    }
    serde_json::from_slice(&ran.out).map_err(|_| first_error())
}

type Exec<'a> = dyn Fn(&[&str], &[&str], &[&str]) -> Ran + 'a;

/// `certify` (the live load's multiplier, or η* without one), written to a temporary file
/// and checked by `verify`; or why there is no certificate.
fn certify(exec: &Exec, live: bool, at: &[&str]) -> Result<(Value, String, (Value, bool)), String> {
    let path = std::env::temp_dir().join(format!(
        "arch-enum-report-{}-{}.json",
        std::process::id(),
        std::time::SystemTime::now()
            .duration_since(std::time::UNIX_EPOCH)
            .map_or(0, |d| d.as_nanos())
    ));
    let out = format!("--out={}", path.display());
    // the report's certificate is proved to a relative gap of 1e-9 (ample for the digits
    // shown; a continuous arch's load certificate may not reach the default 1e-12)
    let (extra, drop): (Vec<&str>, &[&str]) = if live {
        let drop: &[&str] = if at.is_empty() { &[] } else { &["critical"] };
        ([at, &["--gap=1e-9", &out, "--json"]].concat(), drop)
    } else {
        (vec![&out, "--json"], &["eta", "ring"])
    };
    let summary = document(exec(&["certify"], &extra, drop));
    let file = std::fs::read_to_string(&path);
    let shown = path.display().to_string();
    let verified = exec(&["verify"], &[&shown, "--json"], &[]);
    let _ = std::fs::remove_file(&path);
    let summary = summary?;
    let file = file.map_err(|_| {
        format!(
            "certify wrote none (status {})",
            summary["status"].as_str().unwrap_or("?")
        )
    })?;
    let accepted = verified.code == 0;
    let v = document(verified)?;
    Ok((summary, file, (v, accepted)))
}

/// The figures: the arch at its thickness, and the live load's (the influence line for a
/// vehicle, the mechanism for another load); a figure that cannot be drawn is left out.
fn figures(exec: &Exec, vehicle: bool, live: bool, critical: &[&str]) -> Vec<(String, String)> {
    let mut figs = Vec::new();
    let mut draw = |path: &[&str], extra: &[&str], drop: &[&str], caption: &str| {
        let ran = exec(path, &[extra, &["--out=-"]].concat(), drop);
        if ran.code == 0 {
            figs.push((
                caption.to_string(),
                String::from_utf8_lossy(&ran.out).into_owned(),
            ));
        }
    };
    draw(
        &["plot", "arch"],
        &[],
        &["width"],
        "The arch at its thickness, with its fill if any, and the line of thrust of its safest state (the admissible state farthest from the limits).",
    );
    if vehicle {
        draw(
            &["plot", "influence"],
            critical,
            &["png-width"],
            "The influence line: the collapse multiplier λ_c as the vehicle crosses, its local minima marked, and the mechanism at the critical position X*.",
        );
    } else if live {
        draw(
            &["plot", "load"],
            &[],
            &["width"],
            "The live load at collapse: the line of thrust of the limit state and its mechanism.",
        );
    }
    figs
}
