//! The assessment report: one self-contained HTML page (inline SVG and style, no script, no
//! network) built from the commands' own `--json` documents and figures, so that every
//! number in it is the number the command line prints. Printed from a browser it is the
//! document an engineer hands in.

use crate::render::table::sig;
use serde_json::Value;
use std::fmt::Write;

/// What the report shows, each part as its command gave it.
pub struct ReportInput<'a> {
    /// The report's title.
    pub title: &'a str,
    /// The flags as given (the command line after `report`), one `--name value` each.
    pub flags: &'a [String],
    /// `assess --json`.
    pub assess: &'a Value,
    /// `load --json` (with `--critical` for a vehicle), when a live load is given.
    pub load: Option<&'a Value>,
    /// The certificate: `certify --json`, the certificate itself and `verify --json`, or
    /// why there is none.
    pub certificate: Result<Certified<'a>, String>,
    /// Figures: a caption and an SVG document each.
    pub figures: &'a [(String, String)],
    /// The tool and its LP back end.
    pub versions: &'a str,
}

/// A certificate and its verification.
pub struct Certified<'a> {
    /// `certify --json`.
    pub summary: &'a Value,
    /// The certificate file's text.
    pub file: &'a str,
    /// `verify --json`, and whether `verify` accepted it (exit 0).
    pub verified: (&'a Value, bool),
}

const STYLE: &str = "body{font-family:system-ui,-apple-system,'Segoe UI',Roboto,sans-serif;max-width:60rem;margin:2rem auto;padding:0 1rem;color:#1b1b1b;line-height:1.45}
h1{font-size:1.6rem;margin-bottom:.2rem}h2{font-size:1.2rem;border-bottom:1px solid #ccc;padding-bottom:.2rem;margin-top:2rem}
table{border-collapse:collapse;margin:.5rem 0}td,th{border:1px solid #ccc;padding:.25rem .6rem;text-align:left;vertical-align:top}
th{background:#f3f3f3;font-weight:600}td.n{font-variant-numeric:tabular-nums;text-align:right}
.verdict{font-size:1.15rem;font-weight:600;padding:.6rem .8rem;border-radius:.3rem;margin:.6rem 0}
.ok{background:#e6f4ea;border:1px solid #34a853}.bad{background:#fce8e6;border:1px solid #d93025}.note{background:#fef7e0;border:1px solid #f9ab00}
figure{margin:1rem 0;break-inside:avoid}figure svg{width:100%;height:auto;border:1px solid #eee}figcaption{font-size:.9rem;color:#444}
code,pre{font-family:ui-monospace,Menlo,Consolas,monospace;font-size:.85rem}pre{white-space:pre-wrap;word-break:break-all;background:#f7f7f7;padding:.5rem}
.small{font-size:.85rem;color:#444}.flag{white-space:nowrap}@media print{body{margin:0;max-width:none}a{color:inherit}h2{break-after:avoid}figure svg{max-height:24cm;width:auto;max-width:100%}}";

/// The report as one HTML document.
pub fn html(r: &ReportInput) -> String {
    let mut h = String::new();
    let _ = write!(
        h,
        "<!DOCTYPE html>\n<html lang=\"en\"><head><meta charset=\"utf-8\"><meta name=\"viewport\" content=\"width=device-width, initial-scale=1\"><title>{}</title><style>{STYLE}</style></head><body>\n<h1>{}</h1>\n<p class=\"small\">Limit analysis of a masonry arch with limited, non-associative friction (arch-enum). Every number below is the command line's own (<code>--json</code>); the certificate can be re-checked by anyone with <code>arch-enum verify</code>.</p>\n",
        esc(r.title),
        esc(r.title)
    );
    verdict(&mut h, r);
    inputs(&mut h, r);
    assessment(&mut h, r.assess);
    if let Some(load) = r.load {
        live_load(&mut h, load);
    }
    certificate(&mut h, &r.certificate);
    figures(&mut h, r.figures);
    scope(&mut h, r);
    h.push_str("</body></html>\n");
    h
}

/// `&`, `<`, `>` and `"` escaped.
fn esc(s: &str) -> String {
    s.replace('&', "&amp;")
        .replace('<', "&lt;")
        .replace('>', "&gt;")
        .replace('"', "&quot;")
}

/// A number to `digits` significant digits, a string as it is, a boolean as yes or no.
fn num(v: &Value, digits: usize) -> String {
    match v {
        Value::Number(_) => v.as_f64().map_or("—".into(), |x| sig(x, digits)),
        Value::String(s) => esc(s),
        Value::Bool(b) => (if *b { "yes" } else { "no" }).into(),
        _ => "—".into(),
    }
}

/// An input as given: the shortest decimal that reads back to it.
fn given(v: &Value) -> String {
    match v.as_f64() {
        Some(x) => format!("{x}"),
        None => num(v, 6),
    }
}

fn row(h: &mut String, name: &str, value: &str) {
    let _ = writeln!(h, "<tr><th>{name}</th><td class=\"n\">{value}</td></tr>");
}

/// The verdict in one sentence: whether the ring stands, and the vehicle's factor.
fn verdict(h: &mut String, r: &ReportInput) {
    let a = r.assess;
    let stands = a["stands"].as_bool() == Some(true);
    let mut text = if stands {
        format!(
            "The arch stands under its own weight{}: geometric factor of safety η/η* = {}, friction factor μ/μ_min = {}.",
            if a["fill"].is_object() { " and its fill" } else { "" },
            num(&a["geometric_factor"], 4),
            num(&a["friction_factor"], 4)
        )
    } else {
        "The arch does not stand under its own weight at this thickness and friction.".to_string()
    };
    if let Some(load) = r.load {
        let kn = &load["units"]["lambda_kn"];
        let at = &load["critical"]["at_m"];
        let _ = match (load["lambda"].as_f64(), load["vehicle"].is_object()) {
            (Some(l), true) => write!(
                text,
                " The vehicle's adequacy factor is λ = {}{}{}.",
                sig(l, 4),
                if kn.is_number() {
                    format!(" ({} kN in all)", num(kn, 4))
                } else {
                    String::new()
                },
                if at.is_number() {
                    format!(" at its critical position X* = {} m", num(at, 5))
                } else {
                    String::new()
                }
            ),
            (Some(l), false) => write!(
                text,
                " The live load's collapse multiplier is λ = {}.",
                sig(l, 6)
            ),
            (None, _) => write!(
                text,
                " The live load does not collapse the arch (status {}).",
                num(&load["status"], 4)
            ),
        };
    }
    let class = if stands { "ok" } else { "bad" };
    let _ = writeln!(h, "<div class=\"verdict {class}\">{}</div>", esc(&text));
}

fn inputs(h: &mut String, r: &ReportInput) {
    h.push_str("<h2>Inputs</h2>\n");
    let flags: Vec<String> = r
        .flags
        .iter()
        .map(|f| format!("<span class=\"flag\">{}</span>", esc(f)))
        .collect();
    let _ = writeln!(
        h,
        "<p>As given: <code>arch-enum report {}</code></p>",
        flags.join(" ")
    );
    h.push_str("<table>\n");
    let a = r.assess;
    let g = &a["geometry"];
    if g.is_object() {
        row(h, "span (m)", &given(&g["span_m"]));
        row(h, "rise (m)", &given(&g["rise_m"]));
        row(h, "ring thickness t (m)", &given(&g["ring_m"]));
        row(h, "radius of the centreline r (m)", &given(&g["radius_m"]));
    }
    row(h, "η = t/r", &num(&a["eta"], 10));
    let arch = &a["arch"];
    row(
        h,
        "springings β_R, β_L (rad)",
        &format!(
            "{}, {}",
            given(&arch["beta_right"]),
            given(&arch["beta_left"])
        ),
    );
    let joints = match arch["joints"].as_array() {
        Some(j) => format!(
            "{} voussoirs ({} joints)",
            j.len().saturating_sub(1),
            j.len()
        ),
        None => given(&arch["joints"]),
    };
    row(h, "joints", &joints);
    row(h, "weight model", &given(&arch["weight"]));
    row(h, "friction coefficient μ", &given(&a["mu"]));
    let f = &a["fill"];
    if f.is_object() {
        row(h, "fill unit weight (kN/m³)", &given(&f["weight_kn_m3"]));
        row(
            h,
            "fill depth above the extrados crown (m)",
            &given(&f["depth_m"]),
        );
    }
    if let Some(v) = r.load.map(|l| &l["vehicle"]).filter(|v| v.is_object()) {
        let axles: Vec<String> = v["axles_kn"]
            .as_array()
            .into_iter()
            .flatten()
            .map(given)
            .collect();
        let spacing: Vec<String> = v["spacing_m"]
            .as_array()
            .into_iter()
            .flatten()
            .map(given)
            .collect();
        row(h, "axles (kN)", &axles.join(", "));
        if !spacing.is_empty() {
            row(h, "spacing (m)", &spacing.join(", "));
        }
        row(
            h,
            "dispersal through the fill (horizontal : vertical)",
            &given(&v["dispersal"]),
        );
        row(h, "effective width (m)", &given(&v["effective_width_m"]));
    }
    h.push_str("</table>\n");
}

fn assessment(h: &mut String, a: &Value) {
    h.push_str("<h2>The arch under its own weight</h2>\n<table>\n");
    row(
        h,
        "stands",
        if a["stands"].as_bool() == Some(true) {
            "yes"
        } else {
            "no"
        },
    );
    row(h, "least thickness η* at this μ", &num(&a["eta_min"], 10));
    if let Some(t) = a["geometry"]["least_ring_m"].as_f64() {
        row(h, "least ring t* (m)", &sig(t, 6));
    }
    row(
        h,
        "geometric factor of safety η/η*",
        &num(&a["geometric_factor"], 6),
    );
    row(h, "least friction μ_min at this η", &num(&a["mu_min"], 12));
    row(h, "friction factor μ/μ_min", &num(&a["friction_factor"], 6));
    row(h, "collapse mode at η*", &num(&a["mode"], 6));
    h.push_str("</table>\n");
}

fn live_load(h: &mut String, l: &Value) {
    h.push_str("<h2>The live load</h2>\n<table>\n");
    row(h, "status", &num(&l["status"], 4));
    row(
        h,
        "collapse multiplier λ (adequacy factor)",
        &num(&l["lambda"], 10),
    );
    if l["units"]["lambda_kn"].is_number() {
        row(
            h,
            "total live load at collapse (kN)",
            &num(&l["units"]["lambda_kn"], 6),
        );
    }
    row(
        h,
        "largest admissible multiplier λ_static",
        &num(&l["lambda_static"], 10),
    );
    row(
        h,
        "reduction by non-associative friction 1 − λ/λ_static",
        &num(&l["reduction"], 4),
    );
    row(
        h,
        "only one limit state up to λ_static (unique)",
        &num(&l["unique"], 4),
    );
    let c = &l["critical"];
    if c.is_object() {
        row(
            h,
            "critical position X* (m, first axle from the left springing)",
            &num(&c["at_m"], 8),
        );
        row(h, "collapse mode at X*", &num(&c["mode"], 4));
        if c["second"].is_object() {
            row(
                h,
                "second-worst local minimum: X (m), λ",
                &format!(
                    "{}, {}",
                    num(&c["second"]["at_m"], 6),
                    num(&c["second"]["lambda"], 6)
                ),
            );
        }
    }
    h.push_str("</table>\n");
    let states = l["limit_states"].as_array().cloned().unwrap_or_default();
    if !states.is_empty() {
        h.push_str("<p>Every limit state (statically and kinematically admissible, orthogonal) up to λ_static:</p>\n<table><tr><th>λ</th><th>mode</th><th>active contacts (kind at β, degrees)</th></tr>\n");
        for s in &states {
            let _ = writeln!(
                h,
                "<tr><td class=\"n\">{}</td><td>{}</td><td>{}</td></tr>",
                num(&s["lambda"], 10),
                num(&s["mode"], 4),
                pattern(&s["pattern"])
            );
        }
        h.push_str("</table>\n");
    }
}

fn pattern(p: &Value) -> String {
    let short = |k: &str| match k {
        "hinge_intrados" => "I",
        "hinge_extrados" => "E",
        "slide_plus" => "S+",
        "slide_minus" => "S−",
        _ => "?",
    };
    p.as_array()
        .into_iter()
        .flatten()
        .map(|c| {
            let deg = c["beta"]
                .as_f64()
                .map_or("—".into(), |b| format!("{:.2}°", b.to_degrees()));
            format!("{} {deg}", short(c["kind"].as_str().unwrap_or("")))
        })
        .collect::<Vec<_>>()
        .join(", ")
}

fn certificate(h: &mut String, c: &Result<Certified, String>) {
    h.push_str("<h2>Certificate</h2>\n");
    let c = match c {
        Ok(c) => c,
        Err(why) => {
            let _ = writeln!(
                h,
                "<div class=\"verdict note\">No certificate: {}</div>",
                esc(why)
            );
            return;
        }
    };
    let (v, accepted) = c.verified;
    let (class, word) = if accepted {
        ("ok", "verified")
    } else {
        ("bad", "REJECTED")
    };
    let s = c.summary;
    let bracket = if s["lambda_lo"].is_number() {
        format!(
            "λ ∈ [{}, {}]",
            num(&s["lambda_lo"], 15),
            num(&s["lambda_hi"], 15)
        )
    } else {
        format!(
            "η* ∈ [{}, {}]",
            num(&s["eta_lo"], 15),
            num(&s["eta_hi"], 15)
        )
    };
    let _ = writeln!(
        h,
        "<div class=\"verdict {class}\">Certificate {word} by <code>arch-enum verify</code> (interval arithmetic, no LP, no solver): {} (relative gap {}).</div>",
        esc(&bracket),
        num(&s["gap_relative"], 3)
    );
    h.push_str("<ul>\n");
    for check in v["checks"].as_array().into_iter().flatten() {
        let _ = writeln!(
            h,
            "<li class=\"small\">{}</li>",
            esc(check.as_str().unwrap_or(""))
        );
    }
    h.push_str("</ul>\n");
    let _ = writeln!(
        h,
        "<p><a download=\"certificate.json\" href=\"data:application/json;charset=utf-8,{}\">Download the certificate</a> and re-check it: <code>arch-enum verify certificate.json</code>.</p>",
        percent_encode(c.file)
    );
}

/// `text` percent-encoded for a `data:` URL (every byte but unreserved ASCII).
fn percent_encode(text: &str) -> String {
    let mut out = String::with_capacity(text.len() * 2);
    for b in text.bytes() {
        if b.is_ascii_alphanumeric() || b"-_.~".contains(&b) {
            out.push(b as char);
        } else {
            let _ = write!(out, "%{b:02X}");
        }
    }
    out
}

fn figures(h: &mut String, figs: &[(String, String)]) {
    if figs.is_empty() {
        return;
    }
    h.push_str("<h2>Figures</h2>\n");
    for (caption, svg) in figs {
        let body = svg.find("<svg").map_or(svg.as_str(), |i| &svg[i..]);
        let _ = writeln!(
            h,
            "<figure>{body}<figcaption>{}</figcaption></figure>",
            esc(caption)
        );
    }
}

fn scope(h: &mut String, r: &ReportInput) {
    h.push_str("<h2>Scope and assumptions</h2>\n<ul>\n");
    let scope = r.load.map_or(&Value::Null, |l| &l["scope"]);
    let text = scope.as_str().unwrap_or(
        "rigid blocks without crushing; one ring, one span; radial joints; joints without tension or cohesion",
    );
    for part in text.split("; ") {
        let _ = writeln!(h, "<li>{}</li>", esc(part));
    }
    h.push_str("<li>friction at the joints is Coulomb's, non-associative: sliding without dilatancy; every limit state is searched, not only the associative one</li>\n</ul>\n");
    let _ = writeln!(h, "<p class=\"small\">{}</p>", esc(r.versions));
}
