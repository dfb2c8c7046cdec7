//! README.md and the pages under docs/ stay true. In each of them:
//! * every ```console transcript (`$ arch-enum ...` and its output) is run and its standard
//!   output compared line by line (trailing blanks ignored; a line `...` stands for any
//!   number of lines, so a short transcript may leave out what a page elsewhere shows);
//! * every `arch-enum ...` line of a ```sh block must run with exit 0;
//! * every row of the corners table (on whichever page holds it) is recomputed;
//! * every relative link points to an existing file, and an anchor to a heading of it.
//!
//! So that a transcript dropped when text moves between pages is noticed, the pages together
//! must hold at least `CONSOLE_TRANSCRIPTS` distinct console transcripts (never fewer than
//! README.md held before its long sections moved to docs/), and README.md at least one.
//!
//! `README_UPDATE=1 cargo test --release readme` rewrites, on every page, the transcripts that
//! no longer match with the binary's whole output (a transcript that matches, `...` lines
//! included, is left as it is); then read the diff before committing. CI never sets it.

use arch_enum::limit_curve::trace;
use arch_enum::render::table::corner_rows;
use arch_enum::{Arch, Settings, WeightModel};
use assert_cmd::Command;
use std::collections::BTreeSet;
use std::path::{Path, PathBuf};

/// `grep -c '^```console' README.md` before the long sections moved to docs/.
const README_CONSOLE_BEFORE_MOVE: usize = 14;

/// Distinct console transcripts (by their commands) of README.md and docs/ together: the 14
/// of the old README, now in docs/, the atlas of docs/uniqueness.md, the α = 1.15 `solve` of
/// docs/paper.md, the `curve` with fill of docs/bridge.md and the undecided `load` of
/// docs/live-loads.md. Raise it when a page gains one, so that a transcript dropped later is
/// noticed.
const CONSOLE_TRANSCRIPTS: usize = 18;
const _: () = assert!(CONSOLE_TRANSCRIPTS >= README_CONSOLE_BEFORE_MOVE);

fn root() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR"))
}

/// README.md first, then every `.md` file under docs/ (sub-folders included), sorted.
fn pages() -> Vec<PathBuf> {
    fn walk(dir: &Path, out: &mut Vec<PathBuf>) {
        let mut entries: Vec<PathBuf> = std::fs::read_dir(dir)
            .unwrap()
            .map(|e| e.unwrap().path())
            .collect();
        entries.sort();
        for p in entries {
            if p.is_dir() {
                walk(&p, out);
            } else if p.extension().is_some_and(|e| e == "md") {
                out.push(p);
            }
        }
    }
    let mut out = vec![root().join("README.md")];
    walk(&root().join("docs"), &mut out);
    out
}

/// The page's path relative to the repository, for messages.
fn name(page: &Path) -> String {
    page.strip_prefix(root()).unwrap().display().to_string()
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

/// One page's console blocks: each block's commands (joined, as its key), and the failures.
/// With `update`, a transcript that does not match is replaced by the binary's output and
/// the page is written back if anything changed.
fn console_blocks(page: &Path, update: bool) -> (Vec<String>, Vec<String>) {
    let text = std::fs::read_to_string(page).unwrap();
    let mut out: Vec<String> = Vec::new();
    let mut failures = Vec::new();
    let mut blocks = Vec::new();
    let mut lines = text.lines().peekable();
    while let Some(line) = lines.next() {
        out.push(line.to_string());
        if line.trim() != "```console" {
            continue;
        }
        let dir = scratch(&format!("console{}", blocks.len()));
        let mut commands = Vec::new();
        while let Some(&l) = lines.peek() {
            if l.trim() == "```" {
                break;
            }
            lines.next();
            out.push(l.to_string());
            let Some(cmd) = l.strip_prefix("$ ") else {
                failures.push(format!(
                    "{}: a console block line outside a command: {l}",
                    name(page)
                ));
                continue;
            };
            commands.push(cmd.to_string());
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
            if matches(&expected, &actual) {
                out.extend(expected.iter().map(|e| e.to_string()));
            } else if update {
                out.extend(actual.iter().map(|a| a.trim_end().to_string()));
            } else {
                out.extend(expected.iter().map(|e| e.to_string()));
                failures.push(format!(
                    "{}: $ {cmd}\n--- the page says:\n{}\n--- the binary prints:\n{}",
                    name(page),
                    expected.join("\n"),
                    stdout
                ));
            }
        }
        blocks.push(commands.join("\n"));
        let _ = std::fs::remove_dir_all(&dir);
    }
    if update {
        let mut new = out.join("\n");
        new.push('\n');
        if new != text {
            std::fs::write(page, new).unwrap();
        }
    }
    (blocks, failures)
}

#[test]
fn console_transcripts_are_true() {
    let update = std::env::var("README_UPDATE").is_ok_and(|v| v == "1");
    let mut failures = Vec::new();
    let mut all = 0;
    let mut distinct = BTreeSet::new();
    let mut in_readme = 0;
    for page in pages() {
        let (blocks, f) = console_blocks(&page, update);
        if page.ends_with("README.md") && page.parent() == Some(root().as_path()) {
            in_readme = blocks.len();
        }
        all += blocks.len();
        distinct.extend(blocks);
        failures.extend(f);
    }
    assert!(in_readme >= 1, "README.md has no console transcript");
    assert!(
        distinct.len() >= CONSOLE_TRANSCRIPTS,
        "README.md and docs/ hold {} distinct console transcripts ({all} in all), fewer than \
         {CONSOLE_TRANSCRIPTS}: was one dropped on a move?",
        distinct.len()
    );
    assert!(failures.is_empty(), "{}", failures.join("\n\n"));
}

#[test]
fn sh_commands_run() {
    let dir = scratch("sh");
    let mut ran = 0;
    for page in pages() {
        let text = std::fs::read_to_string(&page).unwrap();
        let mut inside = false;
        for line in text.lines() {
            match line.trim() {
                "```sh" => inside = true,
                "```" => inside = false,
                l if inside && l.starts_with("arch-enum ") => {
                    let cmd = l.split('#').next().unwrap().trim();
                    let (_, code) = run(cmd, &dir);
                    assert_eq!(code, 0, "{}: command failed: {cmd}", name(&page));
                    ran += 1;
                }
                _ => {}
            }
        }
    }
    let _ = std::fs::remove_dir_all(&dir);
    assert!(ran >= 5, "{ran}");
}

#[test]
fn corners_table_is_recomputed() {
    let texts: Vec<(PathBuf, String)> = pages()
        .into_iter()
        .map(|p| {
            let t = std::fs::read_to_string(&p).unwrap();
            (p, t)
        })
        .filter(|(_, t)| t.lines().any(|l| l.starts_with("| α_s |")))
        .collect();
    assert_eq!(
        texts.len(),
        1,
        "the corners table should be on exactly one page: {:?}",
        texts.iter().map(|(p, _)| name(p)).collect::<Vec<_>>()
    );
    let text = &texts[0].1;
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

/// GitHub's anchor of a heading: lower case, letters, digits, `-` and `_` kept, spaces to `-`,
/// everything else (backticks, `\*`, punctuation) dropped.
fn anchor(heading: &str) -> String {
    heading
        .trim()
        .to_lowercase()
        .chars()
        .filter_map(|c| match c {
            ' ' => Some('-'),
            c if c.is_alphanumeric() || c == '-' || c == '_' => Some(c),
            _ => None,
        })
        .collect()
}

/// The anchors of a page's headings (outside code blocks).
fn anchors(text: &str) -> BTreeSet<String> {
    let mut fenced = false;
    let mut out = BTreeSet::new();
    for line in text.lines() {
        if line.starts_with("```") {
            fenced = !fenced;
        } else if !fenced && line.starts_with('#') {
            out.insert(anchor(line.trim_start_matches('#')));
        }
    }
    out
}

#[test]
fn links_point_to_files_and_headings() {
    let mut broken = Vec::new();
    let mut checked = 0;
    for page in pages() {
        let text = std::fs::read_to_string(&page).unwrap();
        let mut fenced = false;
        for line in text.lines() {
            if line.starts_with("```") {
                fenced = !fenced;
                continue;
            }
            if fenced {
                continue;
            }
            for piece in line.split("](").skip(1) {
                let Some(target) = piece.split(')').next() else {
                    continue;
                };
                if target.contains("://") || target.starts_with("mailto:") {
                    continue;
                }
                // mathematics such as det[g_a g_b](η) is not a link: a link names a file
                // (with a dot or a slash) or a heading (#)
                if target.contains(char::is_whitespace) || !target.contains(['.', '/', '#']) {
                    continue;
                }
                checked += 1;
                let (file, hash) = match target.split_once('#') {
                    Some((f, h)) => (f, Some(h)),
                    None => (target, None),
                };
                let path = if file.is_empty() {
                    page.clone()
                } else {
                    page.parent().unwrap().join(file)
                };
                if !path.exists() {
                    broken.push(format!("{}: {target} (no such file)", name(&page)));
                    continue;
                }
                if let Some(h) = hash {
                    let t = std::fs::read_to_string(&path).unwrap();
                    if !anchors(&t).contains(h) {
                        broken.push(format!("{}: {target} (no such heading)", name(&page)));
                    }
                }
            }
        }
    }
    assert!(checked >= 20, "only {checked} links found");
    assert!(broken.is_empty(), "{}", broken.join("\n"));
}
