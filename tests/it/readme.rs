//! README.md stays true: every ```console transcript (`$ arch-enum ...` and its output) is
//! run and its standard output compared line by line (trailing blanks ignored; a line
//! `...` stands for any number of lines); every `arch-enum ...` line of a ```sh block must
//! run with exit 0; every row of the corners table is recomputed.
//!
//! `README_UPDATE=1 cargo test --release readme` rewrites the transcripts from the binary's
//! output (then read the diff before committing); CI never sets it.

use arch_enum::limit_curve::trace;
use arch_enum::render::table::corner_rows;
use arch_enum::{Arch, Settings, WeightModel};
use assert_cmd::Command;
use std::path::{Path, PathBuf};

fn readme_path() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("README.md")
}

/// A fresh empty folder for the files a block writes.
fn scratch(name: &str) -> PathBuf {
    let dir = std::env::temp_dir().join(format!("arch-enum-readme-{}-{name}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).unwrap();
    dir
}

fn run(cmd: &str, dir: &Path) -> (String, i32) {
    let args: Vec<&str> = cmd.split_whitespace().skip(1).collect();
    let out = Command::cargo_bin("arch-enum")
        .unwrap()
        .args(&args)
        .current_dir(dir)
        .output()
        .unwrap();
    (
        String::from_utf8_lossy(&out.stdout).into_owned(),
        out.status.code().unwrap_or(-1),
    )
}

/// Expected lines (with `...` wildcards) against actual lines, trailing blanks ignored.
fn matches(expected: &[&str], actual: &[&str]) -> bool {
    match expected.split_first() {
        None => actual.is_empty(),
        Some((&"...", rest)) => (0..=actual.len()).any(|k| matches(rest, &actual[k..])),
        Some((e, rest)) => actual
            .split_first()
            .is_some_and(|(a, more)| a.trim_end() == e.trim_end() && matches(rest, more)),
    }
}

#[test]
fn console_transcripts_are_true() {
    let text = std::fs::read_to_string(readme_path()).unwrap();
    let update = std::env::var("README_UPDATE").is_ok_and(|v| v == "1");
    let mut out: Vec<String> = Vec::new();
    let mut failures = Vec::new();
    let mut lines = text.lines().peekable();
    let mut transcripts = 0;
    while let Some(line) = lines.next() {
        out.push(line.to_string());
        if line.trim() != "```console" {
            continue;
        }
        let dir = scratch(&format!("console{transcripts}"));
        while let Some(&l) = lines.peek() {
            if l.trim() == "```" {
                break;
            }
            lines.next();
            out.push(l.to_string());
            let Some(cmd) = l.strip_prefix("$ ") else {
                failures.push(format!("a console block line outside a command: {l}"));
                continue;
            };
            let mut expected = Vec::new();
            while let Some(&e) = lines.peek() {
                if e.starts_with("$ ") || e.trim() == "```" {
                    break;
                }
                expected.push(e);
                lines.next();
            }
            let (stdout, _) = run(cmd, &dir);
            let actual: Vec<&str> = stdout.lines().collect();
            transcripts += 1;
            if update {
                out.extend(actual.iter().map(|a| a.trim_end().to_string()));
            } else {
                out.extend(expected.iter().map(|e| e.to_string()));
                if !matches(&expected, &actual) {
                    failures.push(format!(
                        "$ {cmd}\n--- README says:\n{}\n--- the binary prints:\n{}",
                        expected.join("\n"),
                        stdout
                    ));
                }
            }
        }
        let _ = std::fs::remove_dir_all(&dir);
    }
    if update {
        let mut new = out.join("\n");
        new.push('\n');
        std::fs::write(readme_path(), new).unwrap();
    }
    assert!(transcripts >= 8, "only {transcripts} transcripts found");
    assert!(failures.is_empty(), "{}", failures.join("\n\n"));
}

#[test]
fn sh_commands_run() {
    let text = std::fs::read_to_string(readme_path()).unwrap();
    let dir = scratch("sh");
    let mut inside = false;
    let mut ran = 0;
    for line in text.lines() {
        match line.trim() {
            "```sh" => inside = true,
            "```" => inside = false,
            l if inside && l.starts_with("arch-enum ") => {
                let cmd = l.split('#').next().unwrap().trim();
                let (_, code) = run(cmd, &dir);
                assert_eq!(code, 0, "README command failed: {cmd}");
                ran += 1;
            }
            _ => {}
        }
    }
    let _ = std::fs::remove_dir_all(&dir);
    assert!(ran >= 5, "{ran}");
}

#[test]
fn corners_table_is_recomputed() {
    let text = std::fs::read_to_string(readme_path()).unwrap();
    let rows: Vec<&str> = text
        .lines()
        .skip_while(|l| !l.starts_with("| α_s |"))
        .skip(2)
        .take_while(|l| l.starts_with("| "))
        .collect();
    assert!(rows.len() >= 10, "{rows:?}");
    let mut alphas: Vec<&str> = rows
        .iter()
        .map(|r| r.split('|').nth(1).unwrap().trim())
        .collect();
    alphas.dedup();
    let mut computed = Vec::new();
    for a in alphas {
        // the table prints α to 6 decimals: ±0.523599 is ±π/6, as the example runs it
        let a: f64 = a.parse().unwrap();
        let k = (a / (std::f64::consts::PI / 6.0)).round();
        let a = if (a - k * std::f64::consts::PI / 6.0).abs() < 1e-6 {
            k * std::f64::consts::PI / 6.0
        } else {
            a
        };
        let arch = Arch::symmetric(a, WeightModel::Centreline).unwrap();
        computed.extend(corner_rows(&arch, &trace(&arch, &Settings::default())));
    }
    assert_eq!(rows, computed);
}
