//! Pictures: every plot command produces a well-formed SVG (parsed back) with the
//! expected elements, and a PNG that decodes to the requested width; the output format
//! follows --out; tints, colour bar, log axis and joint thinning are checked in the SVG.

use arch_enum::figures::{self, MapGrid};
use arch_enum::render::plot::{mode_color, svg_to_png};
use arch_enum::render::{plot_arch, plot_curve, plot_ecc, plot_map};
use arch_enum::{Arch, CollapseMode, Settings, WeightModel};
use assert_cmd::Command;

fn curve_svg(arches: &[Arch], log_eta: bool) -> String {
    let data = figures::curves(arches, &Settings::default()).unwrap();
    plot_curve::svg(&data, log_eta).unwrap()
}

fn arch_svg(arch: &Arch, mu: f64, eta: Option<f64>) -> Result<String, figures::NoFigure> {
    let scene = figures::scene(arch, mu, eta, &Settings::default())?;
    Ok(plot_arch::svg(&scene).unwrap())
}

fn map_svg(arch: &Arch, n_eta: usize, n_mu: usize, log_eta: bool) -> String {
    let grid = MapGrid {
        n_eta,
        n_mu,
        log_eta,
    };
    let m = figures::map(arch, grid, 2, &Settings::default(), &|_, _| {}).unwrap();
    plot_map::svg(&m, log_eta).unwrap()
}

fn parse(svg: &str) -> roxmltree::Document<'_> {
    roxmltree::Document::parse(svg).unwrap_or_else(|e| panic!("SVG does not parse: {e}"))
}

fn hex(c: plotters::style::RGBColor) -> String {
    format!("#{:02X}{:02X}{:02X}", c.0, c.1, c.2)
}

fn semicircle() -> Arch {
    Arch::symmetric(0.0, WeightModel::Centreline).unwrap()
}

#[test]
fn curve_figure_has_one_path_per_branch_and_a_marker_per_corner() {
    let svg = curve_svg(
        &[
            semicircle(),
            Arch::symmetric(1.15, WeightModel::Centreline).unwrap(),
        ],
        false,
    );
    let doc = parse(&svg);
    // branches: thick polylines of more than two points in each mode's colour
    let thick: Vec<_> = doc
        .descendants()
        .filter(|n| n.has_tag_name("polyline") && n.attribute("stroke-width") == Some("3"))
        .collect();
    for (mode, expected) in [
        (CollapseMode::PurelyRotational, 1),
        (CollapseMode::MixedSlidingRotational, 2),
    ] {
        let n = thick
            .iter()
            .filter(|p| p.attribute("stroke") == Some(hex(mode_color(mode)).as_str()))
            .filter(|p| p.attribute("points").unwrap().split_whitespace().count() > 2)
            .count();
        assert_eq!(n, expected, "{mode:?}");
    }
    // finite corners: alpha = 0 has two, alpha = 1.15 one (its other corner is at mu = inf),
    // plus the corner marker of the legend
    let corners = doc
        .descendants()
        .filter(|n| n.has_tag_name("circle") && n.attribute("r") == Some("5"))
        .count();
    assert_eq!(corners, 3 + 1);
    // the asymptote is drawn and labelled
    assert!(svg.contains("overturning asymptote"));
}

#[test]
fn arch_figure_draws_the_mechanism_blocks() {
    let svg = arch_svg(&semicircle(), 0.35, None).unwrap();
    let doc = parse(&svg);
    let color = hex(mode_color(CollapseMode::MixedSlidingRotational));
    let blocks = doc
        .descendants()
        .filter(|n| {
            n.has_tag_name("polygon")
                && n.attribute("opacity") == Some("0.45")
                && n.attribute("fill") == Some(color.as_str())
        })
        .count();
    assert_eq!(blocks, 4, "five active joints bound four moving blocks");
    assert!(svg.contains("mixed_sliding_rotational") && svg.contains("φ = 19.29°"));
    // above eta* the safe state of greatest margin, no mechanism
    let safe = arch_svg(&semicircle(), 0.35, Some(0.2)).unwrap();
    assert!(safe.contains("safe"));
    assert!(!safe.contains("collapse mechanism"));
    // below eta*: nothing admissible to draw
    assert!(arch_svg(&semicircle(), 0.35, Some(0.1)).is_err());
}

#[test]
fn eccentricity_and_map_figures() {
    let s = Settings::default();
    let svg = plot_ecc::svg(&figures::scene(&semicircle(), 0.35, None, &s).unwrap()).unwrap();
    let doc = parse(&svg);
    assert!(doc
        .descendants()
        .any(|n| n.has_tag_name("text") && n.text().unwrap_or("").contains("line of friction")));
    let markers = doc
        .descendants()
        .filter(|n| n.has_tag_name("circle"))
        .count();
    assert!(markers >= 3, "three hinges marked, found {markers}");
    let map = map_svg(&semicircle(), 6, 8, false);
    let doc = parse(&map);
    let cells = doc.descendants().filter(|n| n.has_tag_name("rect")).count();
    assert!(cells >= 48, "6 x 8 cells, found {cells} rectangles");
}

#[test]
fn png_decodes_to_requested_size() {
    let s = Settings::default();
    let scene = figures::scene(&semicircle(), f64::INFINITY, None, &s).unwrap();
    let svg = plot_ecc::svg(&scene).unwrap();
    let png = svg_to_png(&svg, 640).unwrap();
    let pix = resvg::tiny_skia::Pixmap::decode_png(&png).unwrap();
    assert_eq!(pix.width(), 640);
    assert!(pix.height() > 100);
    // the embedded font rendered text: not a blank image
    assert!(pix.pixels().iter().any(|p| p.red() < 100));
}

#[test]
fn cli_plot_writes_files() {
    let dir = std::env::temp_dir().join(format!("arch-enum-plot-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let png = dir.join("arch.png");
    let out = Command::cargo_bin("arch-enum")
        .unwrap()
        .args([
            "plot", "arch", "--alpha", "0.5", "--mu", "inf", "--png", "--width", "500", "--out",
        ])
        .arg(&png)
        .output()
        .unwrap();
    assert_eq!(
        out.status.code(),
        Some(0),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let pix = resvg::tiny_skia::Pixmap::decode_png(&std::fs::read(&png).unwrap()).unwrap();
    assert_eq!(pix.width(), 500);
    let bad = Command::cargo_bin("arch-enum")
        .unwrap()
        .args([
            "plot", "arch", "--alpha", "0", "--mu", "0.35", "--eta", "0.01",
        ])
        .output()
        .unwrap();
    assert_eq!(bad.status.code(), Some(1));
    assert!(String::from_utf8_lossy(&bad.stderr).contains("eta* ="));
    std::fs::remove_dir_all(&dir).ok();
}
