//! The JSON Schema of every `--json` document, derived from the very types that print them
//! (so the schema cannot drift from the output); the Python package's result types are
//! generated from it.

use super::assess::AssessJson;
use super::atlas::AtlasJson;
use super::bridge::BridgeJson;
use super::certificate::{CertifyJson, VerifyJson};
use super::common::ErrorJson;
use super::curve::CurveJson;
use super::load::LoadDoc;
use super::load_curve::LoadCurveDoc;
use super::load_map::LoadMapJson;
use super::modes::ModesJson;
use super::modes_fill::FillModesJson;
use super::solve::SolveJson;
use schemars::generate::SchemaSettings;
use serde_json::{json, Map, Value};

/// One JSON Schema (draft 2020-12) for every document: `$defs` holds each type once,
/// `x-documents` names the type of each command's document (`modes_fill`: `modes` with
/// fill; `load_map`: `atlas` with a load; `critical`: `load` of a vehicle at its critical
/// position; `error`: bad input under `--json`), and the document is any one of them.
pub fn schema() -> Value {
    let mut g = SchemaSettings::draft2020_12().into_generator();
    let documents = [
        ("solve", g.subschema_for::<SolveJson>()),
        ("curve", g.subschema_for::<CurveJson>()),
        ("modes", g.subschema_for::<ModesJson>()),
        ("modes_fill", g.subschema_for::<FillModesJson>()),
        ("assess", g.subschema_for::<AssessJson>()),
        ("load", g.subschema_for::<LoadDoc>()),
        ("critical", g.subschema_for::<BridgeJson>()),
        ("load_curve", g.subschema_for::<LoadCurveDoc>()),
        ("atlas", g.subschema_for::<AtlasJson>()),
        ("load_map", g.subschema_for::<LoadMapJson>()),
        ("certify", g.subschema_for::<CertifyJson>()),
        ("verify", g.subschema_for::<VerifyJson>()),
        ("error", g.subschema_for::<ErrorJson>()),
    ];
    let name = |s: &schemars::Schema| {
        let r = s.get("$ref").and_then(Value::as_str).expect("a named type");
        r.trim_start_matches("#/$defs/").to_string()
    };
    let names: Map<String, Value> = documents
        .iter()
        .map(|(c, s)| (c.to_string(), Value::String(name(s))))
        .collect();
    let any: Vec<Value> = documents
        .iter()
        .map(|(_, s)| s.clone().to_value())
        .collect();
    let mut defs = Value::Object(g.take_definitions(false));
    numbers_may_be_null(&mut defs);
    json!({
        "$schema": "https://json-schema.org/draft/2020-12/schema",
        "title": "arch-enum --json documents",
        "anyOf": any,
        "x-documents": names,
        "$defs": defs,
    })
}

/// A float that is not finite prints as `null` (+∞ where the documents say so, as μ = ∞):
/// every `number` of the schema may be `null`, and one that the Rust type always has
/// (not an `Option`) is marked `x-null: infinity` unless its field says otherwise.
fn numbers_may_be_null(v: &mut Value) {
    match v {
        Value::Object(m) => {
            if m.get("type") == Some(&Value::from("number")) {
                m.insert("type".into(), json!(["number", "null"]));
                m.entry("x-null").or_insert_with(|| Value::from("infinity"));
            }
            m.values_mut().for_each(numbers_may_be_null);
        }
        Value::Array(a) => a.iter_mut().for_each(numbers_may_be_null),
        _ => {}
    }
}
