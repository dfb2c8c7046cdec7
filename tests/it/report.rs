//! `arch-enum report`: the page holds the commands' own numbers (each formatted from the
//! CLI's `--json`), a certificate that `verify` accepts when taken out of the page, the
//! figures, and refuses bad flags by name.

use crate::cli::{arch_enum, json_of};
use arch_enum::render::table::sig;

/// The report for `flags`, written to standard output.
fn report(flags: &[&str]) -> String {
    let out = arch_enum()
        .args(["report", "--out", "-"])
        .args(flags)
        .output()
        .unwrap();
    assert_eq!(
        out.status.code(),
        Some(0),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    String::from_utf8(out.stdout).unwrap()
}

/// The certificate in the page's download link, percent-decoded.
fn embedded_certificate(page: &str) -> String {
    let start = page
        .find("data:application/json;charset=utf-8,")
        .expect("a certificate link")
        + "data:application/json;charset=utf-8,".len();
    let end = start + page[start..].find('"').unwrap();
    let raw = &page.as_bytes()[start..end];
    let mut bytes = Vec::new();
    let mut i = 0;
    while i < raw.len() {
        if raw[i] == b'%' {
            let hex = std::str::from_utf8(&raw[i + 1..i + 3]).unwrap();
            bytes.push(u8::from_str_radix(hex, 16).unwrap());
            i += 3;
        } else {
            bytes.push(raw[i]);
            i += 1;
        }
    }
    String::from_utf8(bytes).unwrap()
}

/// `verify` accepts the certificate taken out of `page`.
fn certificate_verifies(page: &str) {
    let dir = std::env::temp_dir().join(format!("arch-enum-report-test-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let file = dir.join(format!("{}.json", page.len()));
    std::fs::write(&file, embedded_certificate(page)).unwrap();
    let out = arch_enum()
        .args(["verify", file.to_str().unwrap()])
        .output()
        .unwrap();
    let _ = std::fs::remove_file(&file);
    assert_eq!(
        out.status.code(),
        Some(0),
        "{}",
        String::from_utf8_lossy(&out.stdout)
    );
}

#[test]
fn the_arch_report_holds_the_cli_numbers_and_a_certificate() {
    let flags = ["--alpha", "0", "--eta", "0.2", "--mu", "0.6"];
    let page = report(&flags);
    let (a, _) = json_of(&[&["assess"][..], &flags].concat());
    for (key, digits) in [
        ("eta_min", 10),
        ("geometric_factor", 6),
        ("mu_min", 12),
        ("friction_factor", 6),
    ] {
        let shown = sig(a[key].as_f64().unwrap(), digits);
        assert!(page.contains(&shown), "{key} = {shown} not in the report");
    }
    assert!(page.contains("The arch stands under its own weight"));
    assert!(page.contains("Certificate verified"));
    assert_eq!(page.matches("<figure>").count(), 1, "the arch");
    // nothing fetched: no source or link out of the page (the SVG namespace is a name)
    for fetch in ["src=\"http", "href=\"http", "url(http", "<script"] {
        assert!(!page.contains(fetch), "{fetch}");
    }
    certificate_verifies(&page);
}

#[test]
fn the_load_report_holds_the_cli_numbers_and_a_certificate() {
    let flags = [
        "--alpha",
        "0",
        "--blocks",
        "20",
        "--eta",
        "0.3",
        "--mu",
        "0.8",
        "--horizontal",
    ];
    let page = report(&flags);
    let (l, _) = json_of(&[&["load"][..], &flags].concat());
    let lambda = sig(l["lambda"].as_f64().unwrap(), 10);
    assert!(
        page.contains(&lambda),
        "lambda = {lambda} not in the report"
    );
    let static_ = sig(l["lambda_static"].as_f64().unwrap(), 10);
    assert!(page.contains(&static_));
    assert!(page.contains("Certificate verified"));
    assert_eq!(page.matches("<figure>").count(), 2, "the arch and the load");
    certificate_verifies(&page);
}

#[test]
fn a_report_without_a_certificate_says_why() {
    // three voussoirs with fill stand at the thinnest ring scanned: whether they stand at
    // every thickness is not decided, so there is no certificate, and the page says why
    let page = report(&[
        "--alpha",
        "0",
        "--eta",
        "0.3",
        "--mu",
        "0.8",
        "--fill-ratio",
        "1",
        "--fill-height",
        "0.1",
        "--blocks",
        "3",
    ]);
    assert!(page.contains("No certificate: "), "the reason is shown");
    assert!(page.contains("and its fill"));
}
