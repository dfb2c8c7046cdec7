//! The founding paper, one to one: for each opening α_s of its Table 1 (−π/6, 0, π/6, 1,
//! 1.15), the η–μ limit curve with its corners, and the arch with its lines of thrust and
//! friction and its mechanism at every characteristic point of that curve — the corners
//! (μ_rm and the μ_ms corner, at their η), the middle of every mixed branch, the purely
//! sliding state of the vertical branch at μ = μ_ms, the purely rotational state and, at
//! α_s = 1.15, the overturning limit as μ → ∞. It writes SVG and PNG of each figure,
//! `index.md` (each figure's α, μ, η and mode) and `table.md`: every characteristic value
//! beside the paper's where the paper prints it (`tests/data/paper_values.csv`).
//!
//! ```sh
//! cargo run --release --example paper_figures -- paper
//! ```
//!
//! The figures are matched to the paper's by content (opening, friction, mode), not by
//! number: the paper itself is not part of this repository.

use arch_enum::figures::{self, ArchScene};
use arch_enum::limit_curve::{trace, Corner, LimitCurve};
use arch_enum::render::table::right_half_angle;
use arch_enum::render::{plot::svg_to_png, plot_arch, plot_curve};
use arch_enum::{Arch, CollapseMode, ContactKind, Settings, WeightModel};
use std::f64::consts::PI;
use std::fmt::Write as _;
use std::path::{Path, PathBuf};

/// The five openings of the paper's Table 1, with the labels its tables use.
const OPENINGS: [(&str, f64); 5] = [
    ("-pi/6", -PI / 6.0),
    ("0", 0.0),
    ("pi/6", PI / 6.0),
    ("1", 1.0),
    ("1.15", 1.15),
];

/// What the table needs said beside it.
const NOTES: &str = "
- The paper's results table prints the two β_N values of α_s = π/6 (at η_rm and at the
  μ_ms corner) the other way round; its figure captions, two independent recomputations and
  arch-enum agree with the order above.
- Mode names are read from the shoulders inwards (`arch-enum --help`): the mixed branches of
  α_s ≤ π/6 slide at the springings and rotate nearer the crown (mixed sliding–rotational);
  those of α_s = 1 and 1.15 rotate at the springings and slide near the crown (mixed
  rotational–sliding), which is the paper's name for the upper branch of α_s = 1.15 although
  a crown hinge lies inside its sliding joints. At the μ_rm corners of α_s ≤ π/6 and the
  μ_ms corners of α_s = 1 and 1.15 a springing rotates and slides at once
  (rotational_sliding_shoulders).
- β_N is the intrados hinge and β_T the sliding joint in the right half, in radians from the
  horizontal; `–` where the pattern has none.
";

/// One figure to draw: the arch at friction `mu` and thickness `eta` (`None`: at η*(μ)).
struct Point {
    what: String,
    mu: f64,
    eta: Option<f64>,
}

/// One characteristic value of a curve, named as the paper's tables name it.
struct Value {
    opening: &'static str,
    quantity: String,
    value: f64,
}

fn save(dir: &Path, name: &str, svg: &str) {
    std::fs::write(dir.join(format!("{name}.svg")), svg).expect("write svg");
    let png = svg_to_png(svg, 1000).expect("png");
    std::fs::write(dir.join(format!("{name}.png")), png).expect("write png");
}

/// The points of the curve the paper draws an arch at.
fn points(curve: &LimitCurve) -> Vec<Point> {
    let mut out = Vec::new();
    for b in &curve.branches {
        let name = b.mode.name();
        let p = match b.mode {
            // every η ≥ η_ms is a limit state at μ_ms: one a quarter above the corner
            CollapseMode::PurelySliding => Point {
                what: format!("{name} at mu_ms, 1.25 eta_ms"),
                mu: b.mu_min,
                eta: Some(1.25 * b.eta_min),
            },
            // the Couplet–Heyman state holds for every μ above μ_rm: drawn at μ = ∞
            CollapseMode::PurelyRotational => Point {
                what: format!("{name} at mu = inf"),
                mu: f64::INFINITY,
                eta: None,
            },
            _ if b.mu_max.is_finite() => Point {
                what: format!("{name} in the middle of its branch"),
                mu: (b.mu_min * b.mu_max).sqrt(),
                eta: None,
            },
            _ => Point {
                what: format!("{name} at 3 mu_min of its branch"),
                mu: 3.0 * b.mu_min,
                eta: None,
            },
        };
        out.push(p);
    }
    for c in curve.corners.iter().chain(&curve.transitions) {
        let [a, b] = c.between();
        let what = if c.mu.is_infinite() {
            format!("{} limit as mu -> inf", b.name())
        } else {
            format!("corner {} / {}", a.name(), b.name())
        };
        out.push(Point {
            what,
            mu: c.mu,
            eta: None,
        });
    }
    out.sort_by(|p, q| q.mu.total_cmp(&p.mu));
    out
}

/// The paper's name of a corner's values: μ_rm and η_rm where rotation meets a mixed mode,
/// μ_ms and η_ms at the purely sliding branch, η_inf at the asymptote.
fn corner_values(opening: &'static str, arch: &Arch, c: &Corner) -> Vec<Value> {
    let [a, b] = c.between();
    let tag = if c.mu.is_infinite() {
        "inf".to_string()
    } else if a == CollapseMode::PurelyRotational {
        "rm".to_string()
    } else if b == CollapseMode::PurelySliding {
        "ms".to_string()
    } else {
        format!("{}/{}", a.name(), b.name())
    };
    // where the paper's table gives the angles: at η_rm for the rotational corner, at the
    // corner's μ otherwise
    let at = if tag == "rm" {
        "eta_rm".to_string()
    } else {
        format!("mu_{tag}")
    };
    let mut v = Vec::new();
    let mut push = |quantity: String, value: f64| {
        v.push(Value {
            opening,
            quantity,
            value,
        })
    };
    if c.mu.is_finite() {
        push(format!("mu_{tag}"), c.mu);
    }
    push(format!("eta_{tag}"), c.t);
    let hinge = right_half_angle(arch, &c.pattern, |j| j.kind == ContactKind::HingeIntrados);
    let slide = right_half_angle(arch, &c.pattern, |j| !j.kind.is_hinge());
    if let Some(bn) = hinge {
        push(format!("beta_N at {at}"), bn);
    }
    if let Some(bt) = slide {
        push(format!("beta_T at {at}"), bt);
    }
    v
}

/// The paper's values: (opening, quantity) → the value as printed.
fn paper_values(path: &Path) -> Vec<(String, String, String)> {
    let text = std::fs::read_to_string(path).expect("read tests/data/paper_values.csv");
    text.lines()
        .filter(|l| !l.starts_with('#') && !l.trim().is_empty())
        .map(|l| {
            let f: Vec<&str> = l.split(',').map(str::trim).collect();
            (f[0].to_string(), f[1].to_string(), f[2].to_string())
        })
        .collect()
}

/// The number of significant digits of a printed value.
fn significant(printed: &str) -> i32 {
    printed
        .trim_start_matches(['-', '0', '.'])
        .chars()
        .filter(char::is_ascii_digit)
        .count() as i32
}

/// Whether `value` rounds to `printed` at the printed number of significant digits.
fn agrees(value: f64, printed: &str) -> (bool, f64) {
    let p: f64 = printed.parse().expect("a number");
    let digits = significant(printed);
    let scale = 10f64.powi(digits - 1 - p.abs().log10().floor() as i32);
    ((value * scale).round() == (p * scale).round(), value - p)
}

fn table(values: &[Value], paper: &[(String, String, String)]) -> String {
    let mut t = String::from(
        "| opening α_s | quantity | paper | arch-enum | agrees to the printed digits |\n\
         |:---|:---|---:|---:|:---|\n",
    );
    for v in values {
        let printed = paper
            .iter()
            .find(|(o, q, _)| o == v.opening && *q == v.quantity)
            .map(|(_, _, p)| p.as_str());
        let (paper, verdict) = match printed {
            Some(p) => {
                let (ok, diff) = agrees(v.value, p);
                let word = if ok {
                    "yes".to_string()
                } else {
                    format!("no ({diff:+.1e})")
                };
                (p.to_string(), word)
            }
            None => (
                "–".to_string(),
                "not printed in the paper's values we hold".to_string(),
            ),
        };
        let _ = writeln!(
            t,
            "| {} | {} | {paper} | {:.10} | {verdict} |",
            v.opening, v.quantity, v.value
        );
    }
    t
}

fn draw(dir: &Path, label: &str, arch: &Arch, p: &Point, s: &Settings) -> Option<String> {
    let scene: ArchScene = match figures::scene(arch, p.mu, p.eta, s) {
        Ok(scene) => scene,
        Err(e) => {
            eprintln!("alpha {label}, {}: no figure: {e:?}", p.what);
            return None;
        }
    };
    let mode = scene.mode.map_or("safe", |m| m.name());
    let mu = if p.mu.is_finite() {
        format!("{:.6}", p.mu)
    } else {
        "inf".into()
    };
    let name = format!("alpha_{}_mu_{mu}_{mode}", label.replace('/', "_"));
    save(dir, &name, &plot_arch::svg(&scene).expect("arch figure"));
    Some(format!(
        "| `{name}` | {label} | {mu} | {:.8} | {mode} | {} |",
        scene.eta, p.what
    ))
}

fn main() {
    let dir = PathBuf::from(std::env::args().nth(1).unwrap_or_else(|| "paper".into()));
    std::fs::create_dir_all(&dir).expect("create the output folder");
    let s = Settings::default();
    let data = Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/data/paper_values.csv");
    let paper = paper_values(&data);
    let mut index =
        String::from("| figure | α_s | μ | η | mode | what |\n|:---|:---|---:|---:|:---|:---|\n");
    let mut values = Vec::new();
    for (label, alpha) in OPENINGS {
        let arch = Arch::symmetric(alpha, WeightModel::Centreline).expect("arch");
        let curve = trace(&arch, &s);
        let data = figures::curve(&arch, &s).expect("a limit curve");
        let name = format!("alpha_{}_curve", label.replace('/', "_"));
        save(
            &dir,
            &name,
            &plot_curve::svg(&[data], false).expect("curve"),
        );
        let _ = writeln!(
            index,
            "| `{name}` | {label} | | | | the η–μ limit curve and its corners |"
        );
        for p in points(&curve) {
            if let Some(row) = draw(&dir, label, &arch, &p, &s) {
                index.push_str(&row);
                index.push('\n');
            }
        }
        let mut corners: Vec<&Corner> = curve.corners.iter().chain(&curve.transitions).collect();
        corners.sort_by(|a, b| b.mu.total_cmp(&a.mu));
        for c in corners {
            values.extend(corner_values(label, &arch, c));
        }
    }
    let mut table = table(&values, &paper);
    table.push_str(NOTES);
    std::fs::write(dir.join("index.md"), &index).expect("write index.md");
    std::fs::write(dir.join("table.md"), &table).expect("write table.md");
    println!("{index}\n{table}");
}
