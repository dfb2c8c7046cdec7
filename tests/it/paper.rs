//! `examples/paper_figures`: the founding paper's figures and characteristic values, one
//! to one, and docs/paper.md kept equal to what the example prints.

use std::path::{Path, PathBuf};
use std::process::Command;

/// The example's binary, beside this test's own binary. `cargo test` builds the examples,
/// but not `cargo test --test it`: build it here too (nothing to do when it is current).
fn example() -> PathBuf {
    let built = Command::new(env!("CARGO"))
        .args([
            "build",
            "--release",
            "--quiet",
            "--example",
            "paper_figures",
        ])
        .current_dir(env!("CARGO_MANIFEST_DIR"))
        .status()
        .expect("run cargo");
    assert!(
        built.success(),
        "cargo build --example paper_figures failed"
    );
    let exe = std::env::current_exe().expect("the test binary");
    let dir = exe
        .parent()
        .and_then(Path::parent)
        .expect("the target folder");
    dir.join("examples").join("paper_figures")
}

/// The rows of the first Markdown table that starts with `header` in `text`.
fn rows<'a>(text: &'a str, header: &str) -> Vec<&'a str> {
    text.lines()
        .skip_while(|l| !l.starts_with(header))
        .skip(2)
        .take_while(|l| l.starts_with("| "))
        .collect()
}

#[test]
fn the_paper_one_to_one() {
    let out = std::env::temp_dir().join(format!("arch-enum-paper-{}", std::process::id()));
    let status = Command::new(example())
        .arg(&out)
        .output()
        .expect("run examples/paper_figures");
    assert!(status.status.success(), "{status:?}");
    let index = std::fs::read_to_string(out.join("index.md")).unwrap();
    let table = std::fs::read_to_string(out.join("table.md")).unwrap();
    // every figure the index lists was written, and every opening has its curve
    let figures = rows(&index, "| figure |");
    assert!(figures.len() >= 5 + 4 * 5, "{} figures", figures.len());
    for row in &figures {
        let name = row.split('`').nth(1).unwrap();
        for ext in ["svg", "png"] {
            let f = out.join(format!("{name}.{ext}"));
            assert!(
                std::fs::metadata(&f)
                    .map(|m| m.len() > 1000)
                    .unwrap_or(false),
                "{f:?}"
            );
        }
    }
    for alpha in ["-pi_6", "0", "pi_6", "1", "1.15"] {
        assert!(index.contains(&format!("`alpha_{alpha}_curve`")), "{alpha}");
    }
    assert!(index.contains("| 1.15 | inf | 1.44204569 | overturning |"));
    // every value the paper prints agrees to its printed digits; all 14 are compared
    let values = rows(&table, "| opening α_s |");
    let compared: Vec<&&str> = values.iter().filter(|r| !r.contains("| – |")).collect();
    assert_eq!(compared.len(), 14, "{values:#?}");
    assert!(
        compared.iter().all(|r| r.ends_with("| yes |")),
        "{compared:#?}"
    );
    // docs/paper.md holds exactly what the example prints
    let doc = std::fs::read_to_string(Path::new(env!("CARGO_MANIFEST_DIR")).join("docs/paper.md"))
        .unwrap();
    assert_eq!(
        rows(&doc, "| opening α_s |"),
        values,
        "docs/paper.md's table is stale"
    );
    assert_eq!(
        rows(&doc, "| figure |"),
        figures,
        "docs/paper.md's figure list is stale"
    );
    let _ = std::fs::remove_dir_all(&out);
}
