//! `solve --compas FILE`: the COMPAS document (compas 2 JSON: `dtype` + `data`) of the
//! limit state, in the XZ plane with z up, scaled by `--radius`; bad input exits 2.
//! (python/tests/test_compas.py reads the same file back with `compas.json_load`.)

use assert_cmd::Command;
use serde_json::Value;

fn arch_enum() -> Command {
    Command::cargo_bin("arch-enum").unwrap()
}

fn points(v: &Value) -> Vec<[f64; 3]> {
    v["data"]["points"]
        .as_array()
        .unwrap()
        .iter()
        .map(|p| {
            let p = p.as_array().unwrap();
            [0, 1, 2].map(|k| p[k].as_f64().unwrap())
        })
        .collect()
}

#[test]
fn solve_writes_the_limit_state_as_compas_geometry() {
    let dir = std::env::temp_dir().join(format!("arch-enum-compas-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let file = dir.join("arch.json");
    let out = arch_enum()
        .args([
            "solve", "--alpha", "0", "--mu", "0.35", "--json", "--compas",
        ])
        .arg(&file)
        .args(["--radius", "4"])
        .output()
        .unwrap();
    assert_eq!(out.status.code(), Some(0));
    let solve: Value = serde_json::from_slice(&out.stdout).unwrap();
    let eta = solve["eta"].as_f64().unwrap();
    let doc: Value = serde_json::from_str(&std::fs::read_to_string(&file).unwrap()).unwrap();
    for key in ["outline", "thrust_line", "friction_line"] {
        assert_eq!(doc[key]["dtype"], "compas.geometry/Polyline", "{key}");
        assert_eq!(doc[key]["name"], key);
        // the XZ plane
        assert!(points(&doc[key]).iter().all(|p| p[1] == 0.0), "{key}");
    }
    // z up, lengths times the radius: the outline spans the extrados 4 (1 + eta/2)
    let outline = points(&doc["outline"]);
    let top = outline.iter().map(|p| p[2]).fold(f64::MIN, f64::max);
    assert!((top - 4.0 * (1.0 + eta / 2.0)).abs() < 1e-9, "{top}");
    assert_eq!(outline.first(), outline.last());
    // the line of thrust stays within the thickness
    for p in points(&doc["thrust_line"]) {
        let r = p[0].hypot(p[2]) / 4.0;
        assert!(
            r >= 1.0 - eta / 2.0 - 1e-9 && r <= 1.0 + eta / 2.0 + 1e-9,
            "{r}"
        );
    }
    // one point per contact of the pattern, named by kind, on the extrados or intrados
    let pattern = solve["pattern"].as_array().unwrap();
    let hinges = doc["hinges"].as_array().unwrap();
    let sliding = doc["sliding"].as_array().unwrap();
    assert_eq!(hinges.len() + sliding.len(), pattern.len());
    for h in hinges {
        assert_eq!(h["dtype"], "compas.geometry/Point");
        let p = h["data"].as_array().unwrap();
        let r = p[0].as_f64().unwrap().hypot(p[2].as_f64().unwrap()) / 4.0;
        let edge = match h["name"].as_str().unwrap() {
            "hinge_extrados" => 1.0 + eta / 2.0,
            "hinge_intrados" => 1.0 - eta / 2.0,
            other => panic!("{other}"),
        };
        assert!((r - edge).abs() < 1e-12, "{r} vs {edge}");
    }
    assert_eq!(doc["arch_enum"]["eta"].as_f64(), Some(eta));
    assert_eq!(doc["arch_enum"]["radius"].as_f64(), Some(4.0));
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn compas_bad_input_exits_2() {
    // a radius outside (0, inf), named
    let out = arch_enum()
        .args([
            "solve", "--alpha", "0", "--mu", "0.35", "--compas", "x.json", "--radius", "0",
        ])
        .output()
        .unwrap();
    assert_eq!(out.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&out.stderr).contains("invalid value for --radius: 0"));
    // --radius means nothing without --compas
    let out = arch_enum()
        .args(["solve", "--alpha", "0", "--mu", "0.35", "--radius", "2"])
        .output()
        .unwrap();
    assert_eq!(out.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&out.stderr).contains("--compas"));
    // a file that cannot be written
    let out = arch_enum()
        .args([
            "solve",
            "--alpha",
            "0",
            "--mu",
            "0.35",
            "--compas",
            "/nonexistent/dir/a.json",
        ])
        .output()
        .unwrap();
    assert_eq!(out.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&out.stderr).contains("cannot write --compas"));
    // no limit state to draw: the answer's exit code, and no file
    let out = arch_enum()
        .args([
            "solve",
            "--alpha",
            "0",
            "--mu",
            "0.2",
            "--compas",
            "/nonexistent/b.json",
        ])
        .output()
        .unwrap();
    assert_eq!(out.status.code(), Some(1));
    assert!(String::from_utf8_lossy(&out.stderr).contains("no COMPAS file written"));
}
