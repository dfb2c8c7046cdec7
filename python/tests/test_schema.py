"""`arch-enum schema` describes the documents the command line prints: each document of a
set of commands (finite and infinite friction, corners with undefined slopes, a load,
certificates, bad input) validates against its command's type in the schema, and the
typed Python results are generated from that very schema (`_types.py`)."""

import json

import jsonschema
import pytest

CASES = [
    ("solve", ["solve", "--alpha", "0", "--mu", "0.35", "--json"]),
    ("solve", ["solve", "--alpha", "0", "--mu", "inf", "--blocks", "20", "--json"]),
    ("solve", ["solve", "--alpha", "1", "--mu", "0.5", "--json"]),
    ("curve", ["curve", "--alpha", "0", "--mu-min", "0.2", "--mu-max", "2", "--points", "6",
               "--json"]),
    ("modes", ["modes", "--alpha", "1.0", "--json"]),
    ("assess", ["assess", "--alpha", "0", "--eta", "0.2", "--mu", "inf", "--json"]),
    ("load", ["load", "--alpha", "0", "--blocks", "20", "--eta", "0.3", "--mu", "0.8",
              "--horizontal", "--json"]),
    ("certify", ["certify", "--alpha", "0", "--mu", "0.6", "--json"]),
    ("error", ["solve", "--alpha", "0", "--mu", "-1", "--json"]),
]


@pytest.fixture(scope="module")
def schema(cli):
    code, doc = cli("schema")
    assert code == 0 and doc["$schema"].endswith("2020-12/schema")
    return doc


def check(schema, command, doc):
    name = schema["x-documents"][command]
    sub = {"$defs": schema["$defs"], "$ref": f"#/$defs/{name}"}
    jsonschema.validate(doc, sub, cls=jsonschema.Draft202012Validator)


@pytest.mark.parametrize("command,args", CASES)
def test_documents_validate(cli, schema, command, args):
    code, doc = cli(*args)
    check(schema, command, doc)


def test_verify_document_validates(cli, schema, tmp_path):
    path = tmp_path / "c.json"
    assert cli("certify", "--alpha", "0", "--mu", "0.6", "--out", str(path), "--json")[0] == 0
    code, doc = cli("verify", str(path), "--json")
    assert code == 0
    check(schema, "verify", doc)


def test_a_document_that_breaks_the_schema_is_caught(cli, schema):
    """The check can fail: a document with a wrong type or a missing key does not validate."""
    code, doc = cli("solve", "--alpha", "0", "--mu", "0.35", "--json")
    for broken in ({**doc, "status": 3}, {k: v for k, v in doc.items() if k != "arch"}):
        with pytest.raises(jsonschema.ValidationError):
            check(schema, "solve", broken)
    json.dumps(schema)
