//! The Python package's result types are generated from the JSON Schema of the command
//! line's documents (`arch_enum::render::json::schema`, derived from the Rust types that
//! print them): one schema. This test regenerates `python/arch_enum/_types.py` and fails
//! when the file in the tree differs; `PYTHON_TYPES_UPDATE=1 cargo test --release --test it
//! python_types` rewrites it.
//!
//! Rules (the converters are `python/arch_enum/_convert.py`): a number is a `float` (a field
//! marked `x-null: infinity` in the schema, as every float the Rust type always has, reads
//! JSON `null` as +∞; any other reads it as `None`, and a field left out is `None`); a list of numbers is a read-only NumPy array (a list of lists
//! a 2-D one), a list of two numbers a tuple; any other list a tuple; an object of a named
//! type its dataclass; a map without a named type a `dict`. A field that is a Python
//! keyword gets a trailing `_` (`lambda_`). Behaviour beyond the data (figures, columns,
//! saving) comes from the hand-written mixins of `python/arch_enum/_extras.py` listed in
//! [`EXTRAS`].

use arch_enum::render::json::schema;
use serde_json::{Map, Value};
use std::collections::BTreeSet;
use std::fmt::Write;

/// The documents with typed results in Python (the others are `Document` dicts).
const TYPED: [&str; 7] = [
    "solve", "curve", "modes", "assess", "load", "certify", "verify",
];

/// Types with hand-written behaviour: (type, mixin in `_extras`, the list field whose items
/// are the rows of `to_pandas`).
const EXTRAS: [(&str, &str, Option<&str>); 8] = [
    ("SolveResult", "SolveExtras", Some("limit_states")),
    ("CurveResult", "CurveExtras", Some("points")),
    ("ModesResult", "ModesExtras", Some("corners")),
    ("AssessResult", "AssessExtras", None),
    ("LoadResult", "LoadExtras", Some("limit_states")),
    ("CertifyResult", "CertifyExtras", None),
    ("Mechanism", "MechanismExtras", None),
    ("ArchInfo", "ArchInfoExtras", None),
];

const KEYWORDS: [&str; 6] = ["lambda", "from", "in", "is", "class", "global"];

const PATH: &str = "python/arch_enum/_types.py";

fn defs(s: &Value) -> &Map<String, Value> {
    s["$defs"].as_object().expect("$defs")
}

fn ref_name(v: &Value) -> Option<&str> {
    v.get("$ref")?.as_str()?.strip_prefix("#/$defs/")
}

/// The named types a schema refers to, directly.
fn refs(v: &Value, out: &mut Vec<String>) {
    match v {
        Value::Object(m) => {
            if let Some(n) = ref_name(v) {
                out.push(n.to_string());
            }
            m.values().for_each(|x| refs(x, out));
        }
        Value::Array(a) => a.iter().for_each(|x| refs(x, out)),
        _ => {}
    }
}

/// Every named type reachable from the typed documents, in alphabetical order.
fn reachable(s: &Value) -> BTreeSet<String> {
    let docs = s["x-documents"].as_object().expect("x-documents");
    let mut todo: Vec<String> = TYPED
        .iter()
        .map(|c| docs[*c].as_str().expect("a type").to_string())
        .collect();
    let mut seen = BTreeSet::new();
    while let Some(n) = todo.pop() {
        if seen.insert(n.clone()) {
            refs(&defs(s)[&n], &mut todo);
        }
    }
    seen
}

/// The JSON types of a schema (`type` as a list), and whether `null` is one of them.
fn types(v: &Value) -> (Vec<String>, bool) {
    let mut t: Vec<String> = match v.get("type") {
        Some(Value::String(s)) => vec![s.clone()],
        Some(Value::Array(a)) => a
            .iter()
            .filter_map(|x| x.as_str().map(String::from))
            .collect(),
        _ => Vec::new(),
    };
    let mut null = t.iter().any(|x| x == "null");
    if let Some(Value::Array(alts)) = v.get("anyOf") {
        null |= alts
            .iter()
            .any(|a| a.get("type") == Some(&Value::from("null")));
        if let Some(a) = alts
            .iter()
            .find(|a| a.get("type") != Some(&Value::from("null")))
        {
            t.extend(types(a).0);
        }
    }
    t.retain(|x| x != "null");
    (t, null)
}

/// The named type of a schema (directly or as the non-null branch of an `anyOf`).
fn named(v: &Value) -> Option<String> {
    ref_name(v).map(String::from).or_else(|| {
        v.get("anyOf")?
            .as_array()?
            .iter()
            .find_map(|a| ref_name(a).map(String::from))
    })
}

/// Whether a named type is a string enum (a `str` in Python).
fn is_enum(s: &Value, name: &str) -> bool {
    defs(s)[name].get("enum").is_some() || defs(s)[name].get("oneOf").is_some()
}

/// (Python annotation, converter template: `@` stands for the JSON value) of a value of
/// schema `v`; `null_inf`: a JSON null number is +∞.
fn value(s: &Value, v: &Value, null_inf: bool) -> (String, String) {
    if let Some(n) = named(v) {
        if is_enum(s, &n) {
            return ("str".into(), "@".into());
        }
        return (n.clone(), format!("{n}._of(@)"));
    }
    let (t, _) = types(v);
    match t.first().map(String::as_str) {
        Some("number") if null_inf => ("float".into(), "_c.number(@)".into()),
        Some("number") => ("float".into(), "float(@)".into()),
        Some("integer") => ("int".into(), "int(@)".into()),
        Some("boolean") => ("bool".into(), "bool(@)".into()),
        Some("string") => ("str".into(), "@".into()),
        Some("array") => array(s, &v["items"], v),
        Some("object") => ("Dict[str, Any]".into(), "dict(@)".into()),
        _ => ("Any".into(), "@".into()),
    }
}

fn array(s: &Value, items: &Value, v: &Value) -> (String, String) {
    let (it, _) = types(items);
    let fixed = v.get("minItems").is_some() && v.get("minItems") == v.get("maxItems");
    match it.first().map(String::as_str) {
        Some("number") if fixed => ("Tuple[float, ...]".into(), "_c.pair(@)".into()),
        Some("number") => ("np.ndarray".into(), "_c.numbers(@)".into()),
        Some("array") => ("np.ndarray".into(), "_c.matrix(@)".into()),
        _ => {
            let (a, c) = value(s, items, true);
            let c = if c == "@" {
                "tuple(@)".to_string()
            } else {
                format!("tuple({} for y in @)", c.replace('@', "y"))
            };
            (format!("Tuple[{a}, ...]"), c)
        }
    }
}

/// The description of a schema on one line, rustdoc's links (`` [`x`] ``) as plain code.
fn doc(v: &Value) -> Option<String> {
    let d = v.get("description")?.as_str()?.replace('\n', " ");
    Some(d.replace("[`", "`").replace("`]", "`"))
}

/// Wraps `text` at 88 columns, the first line indented by `first`, the others by `more`.
fn wrap(text: &str, (first, more): (&str, &str), out: &mut String) {
    let mut line = String::from(first);
    let mut indent = first.len();
    for w in text.split_whitespace() {
        if line.len() > indent && line.chars().count() + 1 + w.chars().count() > 88 {
            out.push_str(line.trim_end());
            out.push('\n');
            line = String::from(more);
            indent = more.len();
        }
        if line.len() > indent {
            line.push(' ');
        }
        line.push_str(w);
    }
    if line.len() > indent {
        out.push_str(&line);
        out.push('\n');
    }
}

struct Field {
    key: String,
    name: String,
    annotation: String,
    convert: String,
    required: bool,
    doc: Option<String>,
}

fn fields(s: &Value, def: &Value) -> Vec<Field> {
    let props = def["properties"].as_object().expect("properties");
    let required: Vec<&str> = def
        .get("required")
        .and_then(Value::as_array)
        .map_or(Vec::new(), |r| r.iter().filter_map(Value::as_str).collect());
    // the required fields in the order the Rust type declares them, then the others
    let mut keys: Vec<&str> = required.clone();
    keys.extend(
        props
            .keys()
            .map(String::as_str)
            .filter(|k| !required.contains(k)),
    );
    keys.iter()
        .map(|&key| {
            let v = &props[key];
            let (_, nullable) = types(v);
            let req = required.contains(&key);
            let mark = v.get("x-null").and_then(Value::as_str);
            // a number marked so reads null as +∞ (every float the Rust type always has);
            // one that may be null (an `Option`), as None
            let null_inf = mark == Some("infinity");
            let (ann, conv) = value(s, v, null_inf);
            let access = if req {
                format!("d[{key:?}]")
            } else {
                format!("d.get({key:?})")
            };
            let may_be_none = !req || (nullable && !null_inf) || mark == Some("none");
            let optional = may_be_none && !(nullable && null_inf);
            let convert = if conv == "@" {
                access
            } else if !req && nullable && null_inf {
                // absent: None; null: +∞
                let v = format!("(v := d.get({key:?}, _c.ABSENT))");
                format!("None if {v} is _c.ABSENT else {}", conv.replace('@', "v"))
            } else if optional {
                format!(
                    "None if (v := {access}) is None else {}",
                    conv.replace('@', "v")
                )
            } else {
                conv.replace('@', &access)
            };
            let annotation = if optional || (!req && nullable && null_inf) {
                format!("Optional[{ann}]")
            } else {
                ann
            };
            let name = if KEYWORDS.contains(&key) {
                format!("{key}_")
            } else {
                key.to_string()
            };
            Field {
                key: key.to_string(),
                name,
                annotation,
                convert,
                required: req,
                doc: doc(v),
            }
        })
        .collect()
}

fn class(s: &Value, name: &str, out: &mut String) {
    let def = &defs(s)[name];
    let extras = EXTRAS.iter().find(|e| e.0 == name);
    let bases = extras.map_or("_c.Result".to_string(), |e| {
        format!("_x.{}, _c.Result", e.1)
    });
    let fs = fields(s, def);
    writeln!(
        out,
        "\n\n@dataclass(frozen=True, eq=False)\nclass {name}({bases}):"
    )
    .unwrap();
    out.push_str("    \"\"\"");
    let mut text = String::new();
    let what = doc(def).unwrap_or_else(|| format!("The `{name}` of a document."));
    wrap(&what, ("", ""), &mut text);
    out.push_str(&text.trim_end().replace('\n', "\n    "));
    out.push_str("\n\n    Attributes:\n");
    for f in &fs {
        let d = f.doc.clone().unwrap_or_default();
        let t = if f.key == f.name {
            d
        } else {
            format!("(JSON `{}`) {d}", f.key)
        };
        wrap(
            &format!("{}: {t}", f.name),
            ("        ", "            "),
            out,
        );
    }
    out.push_str("    \"\"\"\n\n");
    if let Some(rows) = extras.and_then(|e| e.2) {
        writeln!(out, "    _rows = {rows:?}\n").unwrap();
    }
    for f in &fs {
        let default = if f.required { "" } else { " = None" };
        writeln!(out, "    {}: {}{default}", f.name, f.annotation).unwrap();
    }
    writeln!(
        out,
        "\n    @classmethod\n    def _of(cls, d: Dict[str, Any]) -> \"{name}\":"
    )
    .unwrap();
    out.push_str("        return cls(\n");
    for f in &fs {
        writeln!(out, "            {}={},", f.name, f.convert).unwrap();
    }
    out.push_str("        )\n");
}

fn generate() -> String {
    let s = schema();
    let mut out = String::from(HEADER);
    for name in reachable(&s) {
        if !is_enum(&s, &name) {
            class(&s, &name, &mut out);
        }
    }
    out
}

const HEADER: &str = r#""""The result types: frozen dataclasses, one per type of the command line's JSON documents.

GENERATED from the Rust types that print those documents (``arch-enum schema``) by
``tests/it/python_types.rs``: do not edit. Regenerate with
``PYTHON_TYPES_UPDATE=1 cargo test --release --test it python_types``.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any, Dict, Optional, Tuple

import numpy as np

from . import _convert as _c
from . import _extras as _x
"#;

#[test]
fn python_types_are_generated_from_the_schema() {
    let text = generate();
    let path = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join(PATH);
    if std::env::var("PYTHON_TYPES_UPDATE").is_ok_and(|v| v == "1") {
        std::fs::write(&path, &text).expect("writable");
    }
    let tree = std::fs::read_to_string(&path).unwrap_or_default();
    assert!(
        tree == text,
        "{PATH} is not what the schema generates: run PYTHON_TYPES_UPDATE=1 cargo test --release --test it python_types"
    );
}
