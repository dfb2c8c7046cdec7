//! The tree is the architecture: the modules of `src/` import each other without cycles,
//! `render/` draws and formats without calling the solver, and only the HiGHS back end
//! imports good_lp. Read from the sources, so a new import that breaks a rule fails here.

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

#[test]
fn module_imports_have_no_cycle() {
    let graph = imports();
    // depth-first search with colours: a grey node reached again closes a cycle
    fn visit<'a>(
        n: &'a str,
        g: &'a BTreeMap<String, BTreeSet<String>>,
        colour: &mut BTreeMap<&'a str, u8>,
        path: &mut Vec<&'a str>,
    ) {
        match colour.get(n) {
            Some(2) => return,
            Some(1) => panic!("import cycle: {} -> {n}", path.join(" -> ")),
            _ => {}
        }
        colour.insert(n, 1);
        path.push(n);
        for d in g.get(n).into_iter().flatten() {
            visit(d, g, colour, path);
        }
        path.pop();
        colour.insert(n, 2);
    }
    let mut colour = BTreeMap::new();
    for n in graph.keys() {
        visit(n, &graph, &mut colour, &mut Vec::new());
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
