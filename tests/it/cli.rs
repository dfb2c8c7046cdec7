//! The binary, driven as a user would: JSON contract, exit codes, error messages,
//! and a digit-stable snapshot of `solve --json`.

use arch_enum::contact::{Contact, Location};
use arch_enum::kinematics::{column, power};
use arch_enum::{Arch, WeightModel};
use assert_cmd::Command;
use nalgebra::{DMatrix, DVector};
use serde_json::{json, Value};

pub fn arch_enum() -> Command {
    Command::cargo_bin("arch-enum").unwrap()
}

pub fn json_of(args: &[&str]) -> (Value, i32) {
    let out = arch_enum().args(args).arg("--json").output().unwrap();
    let v: Value = serde_json::from_slice(&out.stdout).unwrap_or_else(|e| {
        panic!(
            "stdout is not one JSON document ({e}): {}",
            String::from_utf8_lossy(&out.stdout)
        )
    });
    (v, out.status.code().unwrap())
}

/// Rounds every float to 10 significant digits, so snapshots are machine-independent.
pub fn round(v: &Value) -> Value {
    match v {
        Value::Number(n) if n.is_f64() => {
            let x = n.as_f64().unwrap();
            let r: f64 = format!("{x:.9e}").parse().unwrap();
            // values that are zero up to rounding of O(1) quantities
            let r = if r.abs() < 1e-13 { 0.0 } else { r };
            serde_json::json!(r)
        }
        Value::Array(a) => Value::Array(a.iter().map(round).collect()),
        Value::Object(o) => Value::Object(o.iter().map(|(k, v)| (k.clone(), round(v))).collect()),
        other => other.clone(),
    }
}

#[test]
fn solve_json_contract() {
    let (v, code) = json_of(&["solve", "--alpha", "0", "--mu", "0.35"]);
    assert_eq!(code, 0);
    assert_eq!(v["status"], "ok");
    for key in [
        "arch",
        "mu",
        "eta",
        "mode",
        "pattern",
        "reactions",
        "mechanism",
    ] {
        assert!(v.get(key).is_some(), "missing {key}");
    }
    for key in ["beta_right", "beta_left", "weight", "joints"] {
        assert!(v["arch"].get(key).is_some(), "missing arch.{key}");
    }
    for j in v["pattern"].as_array().unwrap() {
        assert!(j["beta"].is_f64());
        let kind = j["kind"].as_str().unwrap();
        assert!([
            "hinge_extrados",
            "hinge_intrados",
            "slide_plus",
            "slide_minus"
        ]
        .contains(&kind));
        assert!(["springing", "interior"].contains(&j["at"].as_str().unwrap()));
    }
    for key in ["h", "v", "w"] {
        assert!(v["reactions"][key].is_f64());
    }
    for key in ["rates", "dof", "power"] {
        assert!(v["mechanism"].get(key).is_some());
    }
    // snapshot, without the machine-dependent LP bracket, and with each mechanism's cone
    // (unique) in place of its representative rates (one of many: the cone has 2 dof)
    let mut v = v;
    let arch = Arch::symmetric(0.0, WeightModel::Centreline).unwrap();
    // the top-level mechanism is the least limit state's
    let eta = v["limit_states"][0]["eta"].as_f64().unwrap();
    mechanism_cone(&mut v["mechanism"], &arch, eta);
    for ls in v["limit_states"].as_array_mut().unwrap() {
        let eta = ls["eta"].as_f64().unwrap();
        mechanism_cone(&mut ls["mechanism"], &arch, eta);
    }
    assert_eq!(v["mechanism"]["cone"]["dimension"], 2);
    let mut snap = round(&v);
    snap["checks"] = Value::Null;
    insta::with_settings!({ snapshot_path => "../../snapshots", prepend_module_to_snapshot => false }, {
        insta::assert_json_snapshot!("solve_alpha0_mu0.35", snap);
    });
}

/// Replaces the representative of a `mechanism` document (at thickness `eta`) by its cone
/// {λ ≥ 0 : B λ = 0} on the contacts: where the cone has more than one dimension every
/// point of it is a valid mechanism, so the representative's rates, power and dissipation
/// (linear in the rates) are one choice, not a result. The cone is unique: its dimension
/// and its extreme rays, the rates of minimal support (the columns of B on the support
/// dependent, their null vector of one sign), each with Σ λ = 1 and its power L_e, sorted.
/// Before it is dropped, the representative is checked to lie in the relative interior of
/// the cone (λ ≥ 0, Σ λ = 1, B λ = 0, the support of the cone), and the cone's dimension to
/// be the document's `dof`.
fn mechanism_cone(m: &mut Value, arch: &Arch, eta: f64) {
    let listed = m["rates"].as_array().unwrap().clone();
    let contacts: Vec<Contact> = listed
        .iter()
        .map(|r| Contact {
            beta: r["beta"].as_f64().unwrap(),
            kind: serde_json::from_value(r["kind"].clone()).unwrap(),
            at: Location::Interior,
            free: false,
        })
        .collect();
    let rates: Vec<f64> = listed.iter().map(|r| r["rate"].as_f64().unwrap()).collect();
    let n = contacts.len();
    let b = DMatrix::from_fn(3, n, |i, j| {
        column(contacts[j].kind, contacts[j].beta, eta)[i]
    });
    // circuits of B: at most 4 columns (rank ≤ 3)
    let mut rays: Vec<Vec<f64>> = Vec::new();
    for subset in 1usize..1 << n {
        let s: Vec<usize> = (0..n).filter(|&j| subset >> j & 1 == 1).collect();
        if s.len() > 4 {
            continue;
        }
        let bs = b.select_columns(&s);
        let eig = (bs.transpose() * &bs).symmetric_eigen();
        // null directions: eigenvalues of BᵀB at the rounding of the largest
        let top = eig.eigenvalues.amax();
        let null: Vec<usize> = (0..s.len())
            .filter(|&k| eig.eigenvalues[k].abs() <= 1e-12 * top)
            .collect();
        if null.len() != 1 {
            continue;
        }
        let v = eig.eigenvectors.column(null[0]);
        let sign = v.sum().signum();
        if v.iter().any(|x| x * sign <= 1e-9) {
            continue;
        }
        let mut ray = vec![0.0; n];
        for (k, &j) in s.iter().enumerate() {
            ray[j] = v[k] / v.sum();
        }
        rays.push(ray);
    }
    rays.sort_by(|x, y| {
        x.iter()
            .zip(y)
            .map(|(a, b)| b.total_cmp(a))
            .find(|o| o.is_ne())
            .unwrap_or(std::cmp::Ordering::Equal)
    });
    let dimension = DMatrix::from_fn(n, rays.len(), |i, j| rays[j][i])
        .singular_values()
        .iter()
        .filter(|&&sv| sv > 1e-9)
        .count();
    assert_eq!(
        m["dof"].as_u64().unwrap() as usize,
        dimension,
        "dof and the cone"
    );
    // the representative: in the cone, with the cone's support
    let residual = (&b * DVector::from_column_slice(&rates)).amax();
    assert!(
        rates.iter().all(|&r| r >= 0.0) && residual < 1e-12,
        "the representative {rates:?} is not in the cone: |B lambda| = {residual:e}"
    );
    assert!((rates.iter().sum::<f64>() - 1.0).abs() < 1e-12, "{rates:?}");
    for j in 0..n {
        let in_support = rays.iter().any(|r| r[j] > 0.0);
        assert_eq!(
            rates[j] > 1e-12,
            in_support,
            "contact {j}: rate {}",
            rates[j]
        );
    }
    let p = power(arch, eta, &contacts);
    let dot = |r: &[f64]| p.iter().zip(r).map(|(a, b)| a * b).sum::<f64>();
    assert!((dot(&rates) - m["power"].as_f64().unwrap()).abs() < 1e-12);
    let cone_rays: Vec<Value> = rays
        .iter()
        .map(|ray| {
            let rates: Vec<Value> = listed
                .iter()
                .zip(ray)
                .map(|(c, &rate)| json!({"beta": c["beta"], "kind": c["kind"], "rate": rate}))
                .collect();
            json!({"rates": rates, "power": dot(ray)})
        })
        .collect();
    check_listed_rays(m, &rays, &b, &p);
    let o = m.as_object_mut().unwrap();
    for key in ["rates", "power", "dissipation", "rays"] {
        o.remove(key);
    }
    o.insert(
        "cone".into(),
        json!({"dimension": dimension, "extreme_rays": cone_rays}),
    );
}

/// The document's `rays` (the solver's extreme mechanisms: the vertices of
/// {λ ≥ 0 : B λ = 0, Σ λ = 1, L_e ≥ 0}) against the cone's circuits found above: where every
/// circuit has L_e ≥ 0 the two lists are the same set; otherwise each listed ray is in the
/// cone with L_e ≥ 0, and the circuits with L_e ≥ 0 are all listed. Every ray sums to 1.
fn check_listed_rays(m: &Value, circuits: &[Vec<f64>], b: &DMatrix<f64>, p: &[f64]) {
    let listed: Vec<Vec<f64>> = serde_json::from_value(m["rays"].clone()).expect("mechanism.rays");
    let dot = |r: &[f64]| p.iter().zip(r).map(|(a, b)| a * b).sum::<f64>();
    let same = |x: &[f64], y: &[f64]| x.iter().zip(y).all(|(a, b)| (a - b).abs() < 1e-9);
    assert!(
        listed.len() >= m["dof"].as_u64().unwrap() as usize,
        "{listed:?}"
    );
    for r in &listed {
        assert!((r.iter().sum::<f64>() - 1.0).abs() < 1e-12, "{r:?}");
        assert!(r.iter().all(|&v| v >= 0.0), "{r:?}");
        assert!((b * DVector::from_column_slice(r)).amax() < 1e-12, "{r:?}");
        assert!(dot(r) >= -1e-12, "a listed ray of negative power: {r:?}");
    }
    let admissible: Vec<&Vec<f64>> = circuits.iter().filter(|c| dot(c) >= -1e-12).collect();
    for c in &admissible {
        assert!(
            listed.iter().any(|r| same(r, c)),
            "circuit {c:?} not listed in {listed:?}"
        );
    }
    if admissible.len() == circuits.len() {
        assert_eq!(
            listed.len(),
            circuits.len(),
            "{listed:?} against {circuits:?}"
        );
    }
}

/// The arch a `solve --json` document describes (`arch`).
fn arch_of(a: &Value) -> Arch {
    let weight = match a["weight"].as_str().unwrap() {
        "centroid" => WeightModel::Centroid,
        _ => WeightModel::Centreline,
    };
    let arch = Arch::new(
        a["beta_right"].as_f64().unwrap(),
        a["beta_left"].as_f64().unwrap(),
        weight,
    )
    .unwrap();
    match a["joint_angles"].as_array() {
        Some(j) => {
            let angles: Vec<f64> = j.iter().map(|x| x.as_f64().unwrap()).collect();
            arch.with_joints(&angles).unwrap()
        }
        None => arch,
    }
}

/// `mechanism.rays` on arches whose cones have one to four dimensions: discrete symmetric
/// arches (two mirror rays), the vertical branch at μ_ms (cone of dimension 4), a
/// non-unique case, segmental and horseshoe openings at finite and infinite μ; each limit
/// state's rays checked against the cone's circuits ([`check_listed_rays`]).
#[test]
fn solve_lists_the_extreme_rays_of_every_cone() {
    let cases: &[&[&str]] = &[
        &["--alpha", "0", "--blocks", "20", "--mu", "0.6"],
        &["--alpha", "0", "--mu", "ms"],
        &["--alpha", "0.8", "--mu", "1.1540692474221415"],
        &["--alpha", "-0.6", "--blocks", "9", "--mu", "0.5"],
        &["--alpha", "1", "--blocks", "30", "--mu", "inf"],
        &[
            "--alpha", "0.3", "--blocks", "15", "--weight", "centroid", "--mu", "0.9",
        ],
        &[
            "--beta-right",
            "-0.3",
            "--beta-left",
            "3.2",
            "--blocks",
            "12",
            "--mu",
            "0.7",
        ],
    ];
    let mut dims = std::collections::BTreeSet::new();
    for flags in cases {
        let mut args = vec!["solve"];
        args.extend_from_slice(flags);
        let (mut v, code) = json_of(&args);
        assert_eq!(code, 0, "{flags:?}");
        let arch = arch_of(&v["arch"]);
        for ls in v["limit_states"].as_array_mut().unwrap() {
            let eta = ls["eta"].as_f64().unwrap();
            dims.insert(ls["mechanism"]["dof"].as_u64().unwrap());
            mechanism_cone(&mut ls["mechanism"], &arch, eta);
        }
    }
    assert!(
        dims.contains(&1) && dims.contains(&2) && dims.contains(&4),
        "{dims:?}"
    );
}

#[test]
fn infinite_mu_is_null_in_json() {
    let (v, code) = json_of(&["solve", "--alpha", "0", "--mu", "inf"]);
    assert_eq!(code, 0);
    assert!(v["mu"].is_null());
    assert_eq!(v["mode"], "purely_rotational");
}

#[test]
fn no_equilibrium_exit_1() {
    let (v, code) = json_of(&["solve", "--alpha", "0", "--mu", "0.3"]);
    assert_eq!(code, 1);
    assert_eq!(v["status"], "no_equilibrium");
    assert!(v["message"].as_str().unwrap().contains("mu_ms = 0.309215"));
    let out = arch_enum()
        .args(["solve", "--alpha", "0", "--mu", "0.3"])
        .output()
        .unwrap();
    assert_eq!(out.status.code(), Some(1));
    assert!(String::from_utf8_lossy(&out.stdout).contains("mu_ms = 0.309215"));
}

/// Without --mu-min, `curve` starts where its help says: at mu_ms (1 + 1e-6).
#[test]
fn curve_starts_just_above_mu_ms() {
    for alpha in ["0", "1.0", "-0.5"] {
        let (v, code) = json_of(&["curve", "--alpha", alpha, "--points", "3"]);
        assert_eq!(code, 0);
        let ms = v["mu_ms"].as_f64().unwrap();
        let first = v["points"][0]["mu"].as_f64().unwrap();
        assert!(
            (first - ms * (1.0 + 1e-6)).abs() <= 1e-15 * ms,
            "{first} vs {ms}"
        );
        assert_eq!(
            v["points"][0]["status"], "ok",
            "alpha {alpha}: {}",
            v["points"][0]
        );
    }
}

#[test]
fn curve_rows() {
    let (v, code) = json_of(&[
        "curve", "--alpha", "0", "--mu-min", "0.32", "--mu-max", "0.5", "--points", "4",
    ]);
    assert_eq!(code, 0);
    let pts = v["points"].as_array().unwrap();
    assert_eq!(pts.len(), 4);
    let etas: Vec<f64> = pts.iter().map(|p| p["eta"].as_f64().unwrap()).collect();
    assert!(etas.windows(2).all(|w| w[0] >= w[1]), "{etas:?}");
    assert_eq!(pts[3]["mode"], "purely_rotational");
    assert!((v["mu_ms"].as_f64().unwrap() - 0.30921544).abs() < 5e-9);
    assert_eq!(v["status"], "ok");
}

/// Every argument's bad values: exit 2 and a message naming the argument and the range.
#[test]
fn bad_input_table() {
    let cases: &[(&[&str], &str)] = &[
        (&["solve", "--alpha", "0", "--mu", "nan"], "--mu"),
        (&["solve", "--alpha", "0", "--mu", "0"], "--mu"),
        (&["solve", "--alpha", "0", "--mu", "-1"], "--mu"),
        (&["solve", "--alpha", "0", "--mu", "abc"], "--mu"),
        (&["solve", "--alpha", "nan", "--mu", "1"], "--alpha"),
        (&["solve", "--alpha", "2", "--mu", "1"], "--alpha"),
        (&["solve", "--alpha", "-1.6", "--mu", "1"], "--alpha"),
        (&["solve", "--alpha", "inf", "--mu", "1"], "--alpha"),
        (&["solve", "--alpha-deg", "95", "--mu", "1"], "--alpha-deg"),
        (
            &[
                "solve",
                "--beta-right",
                "1",
                "--beta-left",
                "0.5",
                "--mu",
                "1",
            ],
            "--beta-right",
        ),
        (
            &[
                "solve",
                "--beta-right",
                "0",
                "--beta-left",
                "7",
                "--mu",
                "1",
            ],
            "--beta-right",
        ),
        (&["solve", "--beta-right", "0", "--mu", "1"], "--beta-left"),
        (
            &["solve", "--alpha", "0", "--blocks", "0", "--mu", "1"],
            "--blocks",
        ),
        (
            &["solve", "--alpha", "0", "--blocks", "-3", "--mu", "1"],
            "--blocks",
        ),
        (
            &["solve", "--alpha", "0", "--joints", "0.5,0.4", "--mu", "1"],
            "--joints",
        ),
        (
            &["solve", "--alpha", "0", "--joints", "4.0", "--mu", "1"],
            "--joints",
        ),
        (
            &["solve", "--alpha", "0", "--weight", "heavy", "--mu", "1"],
            "--weight",
        ),
        (&["solve", "--mu", "1"], "--alpha"),
        (
            &["solve", "--alpha", "0", "--mu", "1", "--frobnicate"],
            "--frobnicate",
        ),
        (&["curve", "--alpha", "0", "--mu-min", "-1"], "--mu-min"),
        (
            &["curve", "--alpha", "0", "--mu-min", "1", "--mu-max", "0.5"],
            "--mu-max",
        ),
        (&["curve", "--alpha", "0", "--points", "0"], "--points"),
        (
            &["certify", "--alpha", "0", "--mu", "0.5", "--gap", "0.1"],
            "--gap",
        ),
        (&["certify", "--alpha", "0", "--mu", "nan"], "--mu"),
        (&["verify", "/nonexistent/certificate.json"], "FILE"),
        (&["modes", "--alpha", "1.6"], "--alpha"),
        (&["curve", "--alpha", "0", "--mu-max", "1e201"], "--mu-max"),
        (&["curve", "--alpha", "0", "--mu-min", "0"], "--mu-min"),
        (
            &[
                "load-curve",
                "--alpha",
                "0",
                "--eta",
                "0.3",
                "--horizontal",
                "--mu-max",
                "1e201",
            ],
            "--mu-max",
        ),
        (&["serve", "--port", "-1"], "--port"),
        (&["serve", "--budget", "0"], "--budget"),
        (
            &[
                "report", "--alpha", "0", "--eta", "0.3", "--mu", "1", "--bogus", "2",
            ],
            "--bogus",
        ),
        (
            &["report", "--alpha", "0", "--eta", "0.3", "--mu", "abc"],
            "--mu",
        ),
        (
            &["report", "--alpha", "0", "--eta", "3", "--mu", "1"],
            "--eta",
        ),
        // a mistyped option gets clap's suggestion
        (&["solve", "--alpha", "0", "--mu", "1", "--jsn"], "'--json'"),
    ];
    for (args, name) in cases {
        let out = arch_enum().args(*args).output().unwrap();
        let err = String::from_utf8_lossy(&out.stderr);
        assert_eq!(out.status.code(), Some(2), "{args:?}: {err}");
        assert!(
            err.contains(name),
            "{args:?}: message does not name {name}: {err}"
        );
        assert!(!err.contains("panicked"), "{args:?}: {err}");
    }
}

/// A `--compas` path that cannot be written is bad input, and the only document printed.
#[test]
fn unwritable_compas_path_prints_one_document() {
    let out = arch_enum()
        .args(["solve", "--alpha", "0", "--mu", "0.35", "--json"])
        .args(["--compas", "/nonexistent/folder/x.json"])
        .output()
        .unwrap();
    assert_eq!(out.status.code(), Some(2));
    let v: serde_json::Value = serde_json::from_slice(&out.stdout).expect("one JSON document");
    assert_eq!(v["status"], "error");
    assert!(v["message"].as_str().unwrap().contains("--compas"), "{v}");
}

/// Errors found while parsing the arguments also give a JSON document under `--json`.
#[test]
fn parse_error_json_document() {
    let (v, code) = json_of(&["solve", "--alpha", "0", "--mu", "abc"]);
    assert_eq!(code, 2);
    assert_eq!(v["status"], "error");
    assert!(v["message"].as_str().unwrap().contains("--mu"), "{v}");
    let (v, code) = json_of(&["solve", "--alpha", "0"]);
    assert_eq!(code, 2);
    assert!(v["message"].as_str().unwrap().contains("--mu"), "{v}");
}

/// Negative values are values, not flags.
#[test]
fn negative_values_accepted() {
    let (v, code) = json_of(&[
        "solve",
        "--beta-right",
        "-0.4",
        "--beta-left",
        "3.64",
        "--joints",
        "-0.4,0,1,2,3.64",
        "--mu",
        "inf",
    ]);
    assert_eq!(code, 0, "{v}");
    let (v, code) = json_of(&["solve", "--alpha", "0", "--mu", "-inf"]);
    assert_eq!(code, 2);
    assert!(v["message"].as_str().unwrap().contains("--mu"), "{v}");
}

#[test]
fn bad_input_json_document() {
    let (v, code) = json_of(&["solve", "--alpha", "0", "--mu", "-2"]);
    assert_eq!(code, 2);
    assert_eq!(v["status"], "error");
    assert_eq!(v["version"], 2);
    assert!(v["message"].as_str().unwrap().contains("--mu"));
}

#[test]
fn explain_lists_candidates() {
    let out = arch_enum()
        .args(["solve", "--alpha", "0", "--mu", "0.35", "--explain"])
        .output()
        .unwrap();
    let s = String::from_utf8_lossy(&out.stdout);
    assert!(s.contains("patterns tried"));
    assert!(s.contains("kept: admissible"));
}

/// README's test command is what CI runs.
#[test]
fn readme_commands_match_ci() {
    let root = env!("CARGO_MANIFEST_DIR");
    let readme = std::fs::read_to_string(format!("{root}/README.md")).unwrap();
    let ci = std::fs::read_to_string(format!("{root}/.ci/run")).unwrap();
    let block: Vec<&str> = readme
        .split("```sh\n")
        .nth(1)
        .unwrap()
        .lines()
        .take(2)
        .collect();
    let test_cmd = block[1].split('#').next().unwrap().trim();
    assert_eq!(test_cmd, "bash scripts/test.sh");
    assert!(
        ci.lines().any(|l| l.trim() == test_cmd),
        ".ci/run does not run `{test_cmd}`"
    );
}

/// `curve --threads`: the samples are independent, so any thread count gives the same
/// document, byte for byte; 0 threads is bad input naming the argument.
#[test]
fn curve_threads_do_not_change_the_answer() {
    let run = |threads: &str| {
        arch_enum()
            .args([
                "curve",
                "--alpha",
                "0.3",
                "--mu-min",
                "0.3",
                "--mu-max",
                "3",
                "--points",
                "40",
                "--json",
                "--threads",
                threads,
            ])
            .output()
            .unwrap()
    };
    let (one, two, three) = (run("1"), run("2"), run("3"));
    assert_eq!(one.status.code(), Some(0));
    assert_eq!(one.stdout, two.stdout);
    assert_eq!(one.stdout, three.stdout);
    let zero = run("0");
    assert_eq!(zero.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&zero.stdout).contains("--threads"));
}

#[test]
fn modes_threads_do_not_change_the_answer() {
    // continuous and discrete, symmetric and not, with corners located on several threads
    for arch in [
        &["--alpha", "0"][..],
        &["--alpha", "1.0"],
        &["--beta-right", "-0.2", "--beta-left", "3.0"],
        &["--alpha", "0", "--blocks", "20"],
    ] {
        let run = |threads: &str| {
            arch_enum()
                .arg("modes")
                .args(arch)
                .args(["--json", "--threads", threads])
                .output()
                .unwrap()
        };
        let (one, two, three) = (run("1"), run("2"), run("3"));
        assert_eq!(one.status.code(), Some(0), "{arch:?}");
        assert_eq!(one.stdout, two.stdout, "{arch:?}");
        assert_eq!(one.stdout, three.stdout, "{arch:?}");
    }
    let out = arch_enum()
        .args(["modes", "--alpha", "0", "--threads", "1025"])
        .output()
        .unwrap();
    assert_eq!(out.status.code(), Some(2));
    let text = String::from_utf8_lossy(&out.stderr);
    assert!(
        text.contains("--threads") && text.contains("1 to 1024"),
        "{text}"
    );
}

/// η printed by `solve` is right to its last printed digit where the hinge conditions
/// lose digits to cancellation: the printed value against η of the same five-hinge
/// pattern solved in 60-digit arithmetic (mpmath findroot on M = ±ηN/2 at the springing,
/// the crown and a tangent intrados hinge, v = span/2 by symmetry), and the digits
/// printed no more than the rounding leaves.
#[test]
fn printed_eta_digits_are_right_on_shallow_segments() {
    // (alpha in degrees, eta from 60-digit arithmetic, digits printed at most)
    for (alpha_deg, reference, at_most) in [
        ("-89", 1.933_103_042_088_463e-9_f64, 7),
        ("-68.75493541569878", 3.885_614_604_439_682e-4, 12),
    ] {
        let out = arch_enum()
            .args(["solve", "--alpha-deg", alpha_deg, "--mu", "inf"])
            .output()
            .unwrap();
        let text = String::from_utf8_lossy(&out.stdout);
        let printed = text
            .lines()
            .find_map(|l| l.strip_prefix("least thickness     eta_s = t/r = "))
            .unwrap_or_else(|| panic!("{text}"))
            .trim();
        let mantissa = printed.split('e').next().unwrap();
        let digits = mantissa.chars().filter(|c| c.is_ascii_digit()).count()
            - mantissa
                .chars()
                .take_while(|&c| c == '0' || c == '.')
                .filter(|c| c.is_ascii_digit())
                .count();
        let value: f64 = printed.parse().unwrap();
        // half a unit in the last printed digit
        let ulp = 10f64.powi(reference.abs().log10().floor() as i32 - digits as i32 + 1);
        assert!(
            (value - reference).abs() <= 0.5 * ulp * (1.0 + 1e-9),
            "alpha {alpha_deg}: printed {printed} ({digits} digits), reference {reference:e}"
        );
        assert!(
            digits <= at_most,
            "alpha {alpha_deg}: {digits} digits printed: {printed}"
        );
    }
    // the curve table prints each sample's eta the same way
    let out = arch_enum()
        .args([
            "curve",
            "--alpha-deg",
            "-89",
            "--mu-min",
            "1",
            "--mu-max",
            "2",
            "--points",
            "2",
        ])
        .output()
        .unwrap();
    let text = String::from_utf8_lossy(&out.stdout);
    let etas: Vec<&str> = text
        .lines()
        .filter(|l| l.contains("purely_rotational"))
        .filter_map(|l| l.split_whitespace().nth(2))
        .collect();
    assert_eq!(etas.len(), 2, "{text}");
    for e in etas {
        let v: f64 = e.parse().unwrap();
        assert!(e.len() <= "1.933103e-9".len(), "curve prints {e}");
        assert!(
            (v - 1.933_103_042_088_463e-9).abs() <= 0.5e-14,
            "curve prints {e}"
        );
    }
}
