//! The tree is the architecture: the modules of `src/` import each other without cycles, and
//! so do the files inside every folder of `src/` (a folder's `mod.rs` among them: a
//! dispatcher that imports its files, so they must not import it back); the certificate
//! verifier imports no solver; `render/` draws and formats without calling the solver, and
//! only the HiGHS back end imports good_lp. Read from the sources, so a new import that
//! breaks a rule fails here.

use std::collections::{BTreeMap, BTreeSet};
use std::path::Path;

/// The text without comment lines (doc links are not imports).
fn code_of(text: &str) -> String {
    text.lines()
        .filter(|l| !l.trim_start().starts_with("//"))
        .collect::<Vec<_>>()
        .join("\n")
}

/// Every `.rs` file under `root`, recursively.
fn rs_files(root: &Path) -> Vec<std::path::PathBuf> {
    let mut files = Vec::new();
    let mut stack = vec![root.to_path_buf()];
    while let Some(dir) = stack.pop() {
        for entry in std::fs::read_dir(&dir).unwrap() {
            let path = entry.unwrap().path();
            if path.is_dir() {
                stack.push(path);
            } else if path.extension().is_some_and(|e| e == "rs") {
                files.push(path);
            }
        }
    }
    files
}

/// Top-level module of every file under src/ → the top-level modules it names through
/// `crate::` (in `use` lines and paths alike).
fn imports() -> BTreeMap<String, BTreeSet<String>> {
    let mut graph: BTreeMap<String, BTreeSet<String>> = BTreeMap::new();
    let root = Path::new(env!("CARGO_MANIFEST_DIR")).join("src");
    {
        for path in rs_files(&root) {
            let rel = path
                .strip_prefix(&root)
                .unwrap()
                .to_string_lossy()
                .to_string();
            if rel == "lib.rs" || rel == "main.rs" {
                continue;
            }
            let module = rel
                .split('/')
                .next()
                .unwrap()
                .trim_end_matches(".rs")
                .to_string();
            let text = code_of(&std::fs::read_to_string(&path).unwrap());
            let deps = graph.entry(module.clone()).or_default();
            for (i, _) in text.match_indices("crate::") {
                let name: String = text[i + 7..]
                    .chars()
                    .take_while(|c| c.is_ascii_alphanumeric() || *c == '_')
                    .collect();
                if !name.is_empty() && name != module {
                    deps.insert(name);
                }
            }
        }
    }
    graph
}

/// A cycle of `g` (its nodes in order, the first one again at the end), if it has one:
/// depth-first search with colours, a grey node reached again closes it.
fn find_cycle(g: &BTreeMap<String, BTreeSet<String>>) -> Option<Vec<String>> {
    fn visit<'a>(
        n: &'a str,
        g: &'a BTreeMap<String, BTreeSet<String>>,
        colour: &mut BTreeMap<&'a str, u8>,
        path: &mut Vec<&'a str>,
    ) -> Option<Vec<String>> {
        match colour.get(n) {
            Some(2) => return None,
            Some(1) => {
                let start = path.iter().position(|&p| p == n).unwrap();
                let mut cycle: Vec<String> = path[start..].iter().map(|p| p.to_string()).collect();
                cycle.push(n.to_string());
                return Some(cycle);
            }
            _ => {}
        }
        colour.insert(n, 1);
        path.push(n);
        for d in g.get(n).into_iter().flatten() {
            if let Some(cycle) = visit(d, g, colour, path) {
                return Some(cycle);
            }
        }
        path.pop();
        colour.insert(n, 2);
        None
    }
    let mut colour = BTreeMap::new();
    g.keys()
        .find_map(|n| visit(n, g, &mut colour, &mut Vec::new()))
}

#[test]
fn module_imports_have_no_cycle() {
    let graph = imports();
    if let Some(cycle) = find_cycle(&graph) {
        panic!("import cycle: {}", cycle.join(" -> "));
    }
    assert!(graph.len() > 15, "{graph:?}");
}

/// render/ may name the result *types* of the solver (`Solution`, `LimitCurve`, ...) but
/// no function of a numerical module: every name it takes from outside the vocabulary
/// modules (arch, contact, collapse_mode) and itself starts with a capital letter.
#[test]
fn render_calls_no_solver() {
    let root = Path::new(env!("CARGO_MANIFEST_DIR")).join("src/render");
    let vocabulary = ["render", "arch", "contact", "collapse_mode"];
    let mut checked = 0;
    for path in rs_files(&root) {
        let text = code_of(&std::fs::read_to_string(&path).unwrap());
        for (i, _) in text.match_indices("crate::") {
            let rest = &text[i + 7..];
            let end = rest
                .find(|c: char| {
                    !(c.is_ascii_alphanumeric()
                        || c == '_'
                        || c == ':'
                        || c == '{'
                        || c == '}'
                        || c == ','
                        || c == ' ')
                })
                .unwrap_or(rest.len());
            let path_text = &rest[..end];
            let module = path_text.split("::").next().unwrap();
            if vocabulary.contains(&module) {
                continue;
            }
            let names: Vec<&str> = match path_text.find('{') {
                Some(b) => path_text[b + 1..path_text.find('}').unwrap()]
                    .split(',')
                    .map(str::trim)
                    .filter(|s| !s.is_empty())
                    .collect(),
                None => vec![path_text.trim().rsplit("::").next().unwrap()],
            };
            for n in names {
                let last = n.rsplit("::").next().unwrap();
                assert!(
                    last.starts_with(|c: char| c.is_ascii_uppercase()),
                    "{}: render/ takes `{last}` from crate::{module}: it must draw results, not compute them",
                    path.display()
                );
                checked += 1;
            }
        }
    }
    assert!(checked > 5, "{checked}");
}

#[test]
fn only_the_highs_back_end_imports_good_lp() {
    let root = Path::new(env!("CARGO_MANIFEST_DIR")).join("src");
    for path in rs_files(&root) {
        if !path.ends_with("lp/highs.rs") {
            let text = std::fs::read_to_string(&path).unwrap();
            assert!(!text.contains("good_lp::"), "{}", path.display());
        }
    }
}

/// The text of Rust code without comments, string and char literals (newlines kept), cut at
/// the first `#[cfg(test)]`: unit tests may import what the code may not (the verifier's
/// tests compare it with the solver).
fn code_without_tests(text: &str) -> String {
    let c: Vec<char> = text.chars().collect();
    let ident = |k: usize| c[k].is_alphanumeric() || c[k] == '_';
    let mut out = String::with_capacity(text.len());
    let mut i = 0;
    // `skip(from, to)`: leave out c[from..to], keeping its newlines
    let skip = |out: &mut String, from: usize, to: usize| {
        out.extend(c[from..to.min(c.len())].iter().filter(|&&x| x == '\n'));
        to
    };
    while i < c.len() {
        let at = |k: usize| c.get(k).copied();
        if c[i] == '/' && at(i + 1) == Some('/') {
            let end = (i..c.len()).find(|&k| c[k] == '\n').unwrap_or(c.len());
            i = skip(&mut out, i, end);
        } else if c[i] == '/' && at(i + 1) == Some('*') {
            let (mut depth, mut k) = (0, i);
            while k < c.len() {
                if c[k] == '/' && at(k + 1) == Some('*') {
                    depth += 1;
                    k += 2;
                } else if c[k] == '*' && at(k + 1) == Some('/') {
                    depth -= 1;
                    k += 2;
                    if depth == 0 {
                        break;
                    }
                } else {
                    k += 1;
                }
            }
            i = skip(&mut out, i, k);
        } else if (c[i] == 'r' || (c[i] == 'b' && at(i + 1) == Some('r')))
            && (i == 0 || !ident(i - 1))
            && {
                let k = i + if c[i] == 'b' { 2 } else { 1 };
                let h = (k..c.len()).take_while(|&m| c[m] == '#').count();
                at(k + h) == Some('"')
            }
        {
            // a raw string r#"..."#: it ends at a quote followed by as many hashes
            let k = i + if c[i] == 'b' { 2 } else { 1 };
            let hashes = (k..c.len()).take_while(|&m| c[m] == '#').count();
            let mut m = k + hashes + 1;
            while m < c.len() && !(c[m] == '"' && (1..=hashes).all(|h| at(m + h) == Some('#'))) {
                m += 1;
            }
            out.push_str("\"\"");
            i = skip(&mut out, i, m + 1 + hashes);
        } else if c[i] == '"' {
            let mut m = i + 1;
            while m < c.len() && c[m] != '"' {
                m += if c[m] == '\\' { 2 } else { 1 };
            }
            out.push_str("\"\"");
            i = skip(&mut out, i, m + 1);
        } else if c[i] == '\'' && at(i + 1) == Some('\\') {
            // an escaped char literal: '\n', '\'', '\u{..}'
            let end = (i + 3..c.len()).find(|&k| c[k] == '\'').unwrap_or(c.len());
            out.push_str("' '");
            i = end + 1;
        } else if c[i] == '\'' && at(i + 2) == Some('\'') {
            out.push_str("' '");
            i += 3;
        } else {
            out.push(c[i]);
            i += 1;
        }
    }
    match out.find("#[cfg(test)]") {
        Some(k) => out[..k].to_string(),
        None => out,
    }
}

/// The paths of the use tree (or plain path) that starts at byte `i` of `s`, after a
/// leading `head::`: `a::b`, `a::*`, `{a, b::{c as d, self}}`, each as its segments after
/// `prefix` (`self` names the prefix itself). Returns where the tree ends.
fn use_tree(s: &[u8], i: usize, prefix: &[String], out: &mut Vec<Vec<String>>) -> usize {
    let blank = |mut k: usize| {
        while k < s.len() && s[k].is_ascii_whitespace() {
            k += 1;
        }
        k
    };
    let word = |k: usize| {
        let mut e = k;
        while e < s.len() && (s[e].is_ascii_alphanumeric() || s[e] == b'_') {
            e += 1;
        }
        e
    };
    let mut i = blank(i);
    if s.get(i) == Some(&b'{') {
        i += 1;
        loop {
            i = blank(i);
            match s.get(i) {
                None => return i,
                Some(b'}') => return i + 1,
                _ => {}
            }
            i = blank(use_tree(s, i, prefix, out));
            match s.get(i) {
                Some(b',') => i += 1,
                Some(b'}') => return i + 1,
                _ => return i, // not a use tree after all
            }
        }
    }
    let end = word(i);
    let mut path = prefix.to_vec();
    let segment = String::from_utf8_lossy(&s[i..end]).to_string();
    if end > i && segment != "self" {
        path.push(segment);
    }
    let next = blank(end);
    if end > i && s[next..].starts_with(b"::") {
        return use_tree(s, next + 2, &path, out);
    }
    out.push(path);
    // a rename: `a as b`
    if s[next..].starts_with(b"as") && s.get(next + 2).is_some_and(|b| b.is_ascii_whitespace()) {
        return word(blank(next + 2));
    }
    end
}

/// A file of `src/` (but the binary's `main.rs`) by its module path: `certificate/mod.rs` is
/// `["certificate"]`, `lib.rs` is `[]`.
fn module_files() -> BTreeMap<Vec<String>, std::path::PathBuf> {
    let root = Path::new(env!("CARGO_MANIFEST_DIR")).join("src");
    rs_files(&root)
        .into_iter()
        .filter(|p| p.strip_prefix(&root).unwrap() != Path::new("main.rs"))
        .map(|p| {
            let rel = p.strip_prefix(&root).unwrap().with_extension("");
            let mut module: Vec<String> = rel
                .components()
                .map(|c| c.as_os_str().to_string_lossy().to_string())
                .collect();
            if matches!(module.last().map(String::as_str), Some("mod" | "lib")) {
                module.pop();
            }
            (module, p)
        })
        .collect()
}

/// Every file of `src/` by its module path, with the files it imports (by module path):
/// each path through `crate::`, `super::`, `self::` or one of the file's own child modules,
/// in `use` trees and in code alike, resolved to the deepest file it names (an item that a
/// `mod.rs` defines or re-exports is an import of that `mod.rs`).
fn file_imports() -> BTreeMap<Vec<String>, BTreeSet<Vec<String>>> {
    let files = module_files();
    let mut graph = BTreeMap::new();
    for (module, path) in &files {
        let code = code_without_tests(&std::fs::read_to_string(path).unwrap());
        let s = code.as_bytes();
        let is_dir = path.ends_with("mod.rs") || path.ends_with("lib.rs");
        let children = |name: &str| {
            let mut m = module.clone();
            m.push(name.to_string());
            files.contains_key(&m).then_some(m)
        };
        let mut targets = BTreeSet::new();
        let mut i = 0;
        while i < s.len() {
            let starts = (s[i].is_ascii_alphabetic() || s[i] == b'_')
                && (i == 0 || !(s[i - 1].is_ascii_alphanumeric() || s[i - 1] == b'_'))
                && !code[..i].ends_with(':');
            if !starts {
                i += 1;
                continue;
            }
            let mut end = i;
            while end < s.len() && (s[end].is_ascii_alphanumeric() || s[end] == b'_') {
                end += 1;
            }
            let head = &code[i..end];
            let after = code[end..].trim_start();
            // `pub(in crate::x)` restricts visibility: not an import
            let visibility = code[..i].trim_end().ends_with("(in");
            let base = match head {
                _ if !after.starts_with("::") || visibility => None,
                "crate" => Some(Vec::new()),
                "self" => Some(module.clone()),
                "super" => Some(module[..module.len().saturating_sub(1)].to_vec()),
                _ => children(head).filter(|_| is_dir || path.with_extension("").is_dir()),
            };
            let Some(base) = base else {
                i = end;
                continue;
            };
            let from = end + (code[end..].len() - after.len()) + 2;
            let mut paths = Vec::new();
            let tree_end = use_tree(s, from, &[], &mut paths);
            for p in paths {
                let mut base = base.clone();
                let mut rest = &p[..];
                while rest.first().is_some_and(|h| h == "super") {
                    base.pop();
                    rest = &rest[1..];
                }
                let mut full: Vec<String> = base.into_iter().chain(rest.iter().cloned()).collect();
                while !files.contains_key(&full) {
                    full.pop();
                }
                if &full != module {
                    targets.insert(full);
                }
            }
            i = tree_end.max(end);
        }
        graph.insert(module.clone(), targets);
    }
    graph
}

/// In every folder of `src/` below the root (the root's modules are checked above), the
/// files import each other without a circle: a file (or subfolder, as one) never imports one
/// that imports it, directly or through others; `mod.rs` counts as a file of its folder.
#[test]
fn files_inside_every_folder_import_without_cycle() {
    let files = module_files();
    let imports = file_imports();
    let folders: Vec<&Vec<String>> = files
        .iter()
        .filter(|(m, p)| !m.is_empty() && p.ends_with("mod.rs"))
        .map(|(m, _)| m)
        .collect();
    // a module inside `folder` as the folder's entry: `mod.rs`, `name.rs` or `name/`
    let entry = |folder: &[String], m: &[String]| -> Option<String> {
        if !m.starts_with(folder) {
            return None;
        }
        let Some(name) = m.get(folder.len()) else {
            return Some("mod.rs".to_string());
        };
        let sub = [folder, std::slice::from_ref(name)].concat();
        let is_folder = files.get(&sub).is_some_and(|p| p.ends_with("mod.rs"));
        Some(format!("{name}{}", if is_folder { "/" } else { ".rs" }))
    };
    let mut edges = 0;
    let mut cycles = Vec::new();
    for folder in &folders {
        let name = folder.join("/");
        let mut graph: BTreeMap<String, BTreeSet<String>> = BTreeMap::new();
        for (from, targets) in &imports {
            let Some(a) = entry(folder, from) else {
                continue;
            };
            let deps = graph.entry(a.clone()).or_default();
            for to in targets {
                let Some(b) = entry(folder, to).filter(|b| *b != a) else {
                    continue;
                };
                deps.insert(b);
                edges += 1;
            }
        }
        if let Some(cycle) = find_cycle(&graph) {
            cycles.push(format!("src/{name}/: {}", cycle.join(" -> ")));
        }
    }
    assert!(
        cycles.is_empty(),
        "import cycles between the files of a folder (a file must not import one that imports it):\n{}",
        cycles.join("\n")
    );
    assert!(folders.len() > 8 && edges > 100, "{folders:?} {edges}");
}

/// The verifier re-checks a certificate without the solver: the files of
/// `certificate/verify/` import, outside their own folder, only the certificate's vocabulary
/// (`format`, `interval`) and the arch's and contacts' (the statics and the live load it
/// writes out again; its unit tests may compare with the solver).
#[test]
fn the_verifier_imports_no_solver() {
    let verifier = ["certificate".to_string(), "verify".to_string()];
    let allowed = [
        vec!["certificate", "format"],
        vec!["certificate", "interval"],
        vec!["arch"],
        vec!["contact"],
    ];
    let mut files = 0;
    for (from, targets) in file_imports() {
        if !from.starts_with(&verifier) {
            continue;
        }
        files += 1;
        for to in targets {
            assert!(
                to.starts_with(&verifier) || allowed.iter().any(|a| to == *a),
                "crate::{}: the verifier imports crate::{}",
                from.join("::"),
                to.join("::")
            );
        }
    }
    assert!(files > 5, "{files}");
}
