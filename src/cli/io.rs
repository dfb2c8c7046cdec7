//! Where a command writes, and how it ends: the vocabulary every command file shares
//! (the exit codes, [`Io`], the JSON writer).

use crate::arch::InputError;
use crate::limit::Outcome;
use crate::render::json;
use std::io::Write;

/// Exit status: success.
pub const EXIT_OK: i32 = 0;
/// Exit status: the question has no answer for these inputs (no equilibrium, unresolved).
pub const EXIT_NO_ANSWER: i32 = 1;
/// Exit status: bad input.
pub const EXIT_BAD_INPUT: i32 = 2;

/// How a command ended.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Exit {
    /// The question was answered.
    Answered,
    /// The question has no answer for these inputs (no equilibrium, no collapse,
    /// unresolved, a certificate rejected or not produced, nothing to draw).
    NoAnswer,
    /// The input was bad (the message names the argument and the valid range).
    BadInput,
}

impl Exit {
    /// The process exit status: the only place where results become exit codes.
    pub fn code(self) -> i32 {
        match self {
            Exit::Answered => EXIT_OK,
            Exit::NoAnswer => EXIT_NO_ANSWER,
            Exit::BadInput => EXIT_BAD_INPUT,
        }
    }

    /// How a solver outcome ends a command.
    pub fn of(outcome: &Outcome) -> Exit {
        match outcome {
            Outcome::Limit(_) => Exit::Answered,
            Outcome::NoEquilibrium { .. }
            | Outcome::Unresolved { .. }
            | Outcome::NoCollapse { .. } => Exit::NoAnswer,
        }
    }
}

/// Where a command writes: results to `out`, diagnostics to `err`; `json` when standard
/// output must be exactly one JSON document.
pub(crate) struct Io<'a> {
    pub(super) out: &'a mut dyn Write,
    pub(super) err: &'a mut dyn Write,
    pub(super) json: bool,
}

pub(super) fn emit(w: &mut dyn Write, text: &str) {
    // A closed pipe (e.g. `| head`) is not an error of ours.
    let _ = w.write_all(text.as_bytes());
    let _ = w.flush();
}

/// The message of an error report on standard error: its first paragraph (the "error: ..."
/// line and any indented continuation, as clap and the commands write it), on one line.
pub(crate) fn message_of(err: &[u8]) -> String {
    let text = String::from_utf8_lossy(err);
    let lines: Vec<&str> = text
        .lines()
        .take_while(|l| !l.trim().is_empty())
        .map(|l| l.trim().trim_start_matches("error: "))
        .collect();
    lines.join(" ")
}

pub(crate) fn to_json<T: serde::Serialize>(value: &T) -> String {
    let mut s = serde_json::to_string_pretty(value).expect("results serialise to JSON");
    s.push('\n');
    s
}

impl Io<'_> {
    /// Writes a result.
    pub(crate) fn out(&mut self, text: &str) {
        emit(self.out, text);
    }
    /// Writes a result that is not text (a PNG on standard output).
    pub(crate) fn out_bytes(&mut self, bytes: &[u8]) {
        let _ = self.out.write_all(bytes);
        let _ = self.out.flush();
    }
    /// Writes a diagnostic.
    pub(crate) fn err(&mut self, text: &str) {
        emit(self.err, text);
    }
    /// Reports bad input: the message on standard error, and with `--json` a JSON document
    /// on standard output.
    pub(crate) fn bad_input(&mut self, e: &InputError) -> Exit {
        self.bad(e.to_string())
    }
    /// Reports bad input described by `message` (a file that cannot be read or written).
    pub(crate) fn bad(&mut self, message: String) -> Exit {
        self.err(&format!("error: {message}\n"));
        if self.json {
            self.out(&to_json(&json::ErrorJson::new(message)));
        }
        Exit::BadInput
    }
}

/// A command's JSON document with the engineer's `geometry` added after its own keys (when
/// given; without it, the document byte for byte as before).
pub(crate) fn json_with_geometry<T: serde::Serialize>(
    doc: &T,
    geometry: Option<crate::bridge::Geometry>,
    least_eta: Option<f64>,
) -> String {
    #[derive(serde::Serialize)]
    struct With<'a, T> {
        #[serde(flatten)]
        doc: &'a T,
        geometry: serde_json::Value,
    }
    match geometry {
        None => to_json(doc),
        Some(g) => to_json(&With {
            doc,
            geometry: crate::render::geometry::json(&g, least_eta),
        }),
    }
}

/// The engineer's geometry as text lines above a command's answer ("" without it).
pub(crate) fn geometry_text(
    geometry: Option<crate::bridge::Geometry>,
    least_eta: Option<f64>,
) -> String {
    geometry.map_or(String::new(), |g| {
        crate::render::geometry::text(&g, least_eta)
    })
}
