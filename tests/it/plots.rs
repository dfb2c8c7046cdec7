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
    // every sub-pixel path was written in place of its placeholder (render::fine)
    assert!(
        !svg.contains("fine-path"),
        "a placeholder is left in the SVG"
    );
    roxmltree::Document::parse(svg).unwrap_or_else(|e| panic!("SVG does not parse: {e}"))
}

/// The lines of thrust and friction keep sub-pixel coordinates: the line of thrust of the
/// semicircle at μ = 0.35 (801 points about 1.5 px apart, curving gently) has second
/// differences under 0.25 px, where coordinates rounded to whole pixels jump by 1–2 px.
#[test]
fn lines_keep_sub_pixel_coordinates() {
    let svg = arch_svg(&semicircle(), 0.35, None).unwrap();
    let doc = parse(&svg);
    let thrust = doc
        .descendants()
        .find(|n| {
            n.has_tag_name("polyline")
                && n.attribute("stroke") == Some("#000000")
                && n.attribute("stroke-width") == Some("2")
        })
        .expect("the line of thrust");
    let pts = points_of(&thrust);
    assert!(pts.len() > 500, "{} points", pts.len());
    let fractional = pts.iter().filter(|p| p.0.fract() != 0.0).count();
    assert!(
        fractional * 10 > pts.len() * 9,
        "{fractional} of {}",
        pts.len()
    );
    let d2 = pts
        .windows(3)
        .map(|w| (w[2].0 - 2.0 * w[1].0 + w[0].0).abs() + (w[2].1 - 2.0 * w[1].1 + w[0].1).abs())
        .fold(0.0, f64::max);
    assert!(d2 < 0.25, "largest second difference {d2} px");
    // the dashed line of friction is one dashed path, not hundreds of dashes
    assert!(doc
        .descendants()
        .any(|n| n.attribute("stroke-dasharray") == Some("6 4")
            && n.attribute("stroke") == Some("#FF7F0E")));
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
    // alpha = 0: rotational and sliding-rotational; alpha = 1.15: rotational-sliding
    for (mode, expected) in [
        (CollapseMode::PurelyRotational, 1),
        (CollapseMode::MixedSlidingRotational, 1),
        (CollapseMode::MixedRotationalSliding, 1),
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
    let blocks = moving_blocks(&svg, CollapseMode::MixedSlidingRotational);
    assert_eq!(blocks, 4, "five active joints bound four moving blocks");
    assert!(svg.contains("mixed_sliding_rotational") && svg.contains("φ = 19.29°"));
    // above eta* the safe state of greatest margin, no mechanism
    let safe = arch_svg(&semicircle(), 0.35, Some(0.2)).unwrap();
    assert!(safe.contains("safe"));
    assert!(!safe.contains("collapse mechanism"));
    // below eta*: nothing admissible to draw
    assert!(arch_svg(&semicircle(), 0.35, Some(0.1)).is_err());
    // a detached crown (E and I at one joint, their angles apart in the last bits) bounds
    // no block: two blocks, not a third of zero width drawn as a stray line across the crown
    let horseshoe = Arch::symmetric(1.15, WeightModel::Centreline).unwrap();
    let svg = arch_svg(&horseshoe, f64::INFINITY, None).unwrap();
    let moving = moving_blocks(&svg, CollapseMode::Overturning);
    assert_eq!(moving, 2, "two blocks turn about the springings");
}

/// The displaced blocks of the mechanism panel: polygons filled with the mode's colour.
fn moving_blocks(svg: &str, mode: CollapseMode) -> usize {
    let color = hex(mode_color(mode));
    parse(svg)
        .descendants()
        .filter(|n| {
            n.has_tag_name("polygon")
                && n.attribute("opacity") == Some("0.45")
                && n.attribute("fill") == Some(color.as_str())
        })
        .count()
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
    // The embedded font rendered the text: against the same figure without its text
    // elements, marks of glyph size appear, at least one for every two characters (the
    // glyphs of a word may touch; 268 marks for 244 characters here).
    let bare = svg_to_png(&without_text(&svg), 640).unwrap();
    let bare = resvg::tiny_skia::Pixmap::decode_png(&bare).unwrap();
    let chars = text_chars(&svg);
    let marks = glyph_marks(&pix, &bare);
    assert!(
        chars > 100 && 2 * marks >= chars,
        "{marks} glyph marks for {chars} characters"
    );
    // and the measure tells a missing font: rendered with no font, no mark
    let tree = resvg::usvg::Tree::from_str(&svg, &resvg::usvg::Options::default()).unwrap();
    let mut no_font = resvg::tiny_skia::Pixmap::new(pix.width(), pix.height()).unwrap();
    no_font.fill(resvg::tiny_skia::Color::WHITE);
    let scale = pix.width() as f32 / tree.size().width();
    resvg::render(
        &tree,
        resvg::tiny_skia::Transform::from_scale(scale, scale),
        &mut no_font.as_mut(),
    );
    assert_eq!(glyph_marks(&no_font, &bare), 0, "text drawn without a font");
}

/// `svg` without its text: every `<text …>…</text>` element removed.
fn without_text(svg: &str) -> String {
    let mut out = String::new();
    let mut rest = svg;
    while let Some(i) = rest.find("<text") {
        out.push_str(&rest[..i]);
        let end = rest[i..].find("</text>").expect("a closed text element") + "</text>".len();
        rest = &rest[i + end..];
    }
    out.push_str(rest);
    out
}

/// The characters (spaces excepted) of every text element of `svg`.
fn text_chars(svg: &str) -> usize {
    let doc = parse(svg);
    doc.descendants()
        .filter(|n| n.has_tag_name("text"))
        .map(|n| {
            n.text()
                .unwrap_or("")
                .chars()
                .filter(|c| !c.is_whitespace())
                .count()
        })
        .sum()
}

/// The marks of glyph size drawn in `with` and not in `without` (the same picture without
/// its text): connected pieces (8-neighbours) of pixels dark in `with` and light in
/// `without`, of 2 to 400 pixels.
fn glyph_marks(with: &resvg::tiny_skia::Pixmap, without: &resvg::tiny_skia::Pixmap) -> usize {
    let (w, h) = (with.width() as usize, with.height() as usize);
    let luma = |p: &resvg::tiny_skia::PremultipliedColorU8| {
        (p.red() as u32 + p.green() as u32 + p.blue() as u32) / 3
    };
    let mut ink: Vec<bool> = with
        .pixels()
        .iter()
        .zip(without.pixels())
        .map(|(a, b)| luma(a) < 128 && luma(b) >= 128)
        .collect();
    let mut marks = 0;
    for start in 0..w * h {
        if !ink[start] {
            continue;
        }
        ink[start] = false;
        let (mut size, mut stack) = (0, vec![start]);
        while let Some(i) = stack.pop() {
            size += 1;
            let (x, y) = ((i % w) as i64, (i / w) as i64);
            for (dx, dy) in [
                (-1, -1),
                (0, -1),
                (1, -1),
                (-1, 0),
                (1, 0),
                (-1, 1),
                (0, 1),
                (1, 1),
            ] {
                let (nx, ny) = (x + dx, y + dy);
                if nx >= 0 && ny >= 0 && (nx as usize) < w && (ny as usize) < h {
                    let j = ny as usize * w + nx as usize;
                    if ink[j] {
                        ink[j] = false;
                        stack.push(j);
                    }
                }
            }
        }
        if (2..=400).contains(&size) {
            marks += 1;
        }
    }
    marks
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

fn plot(args: &[&str], out: &std::path::Path) -> std::process::Output {
    Command::cargo_bin("arch-enum")
        .unwrap()
        .arg("plot")
        .args(args)
        .arg("--out")
        .arg(out)
        .output()
        .unwrap()
}

#[test]
fn output_format_follows_the_out_extension() {
    let dir = std::env::temp_dir().join(format!("arch-enum-fmt-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let args = ["arch", "--alpha", "0.5", "--mu", "inf", "--width", "300"];
    // .png without --png is a PNG, .svg is an SVG (any case)
    let png = dir.join("x.png");
    assert_eq!(plot(&args, &png).status.code(), Some(0));
    assert!(std::fs::read(&png)
        .unwrap()
        .starts_with(b"\x89PNG\r\n\x1a\n"));
    let svg = dir.join("x.SVG");
    assert_eq!(plot(&args, &svg).status.code(), Some(0));
    let text = std::fs::read_to_string(&svg).unwrap();
    parse(&text);
    // --png with an .svg path, or an unknown extension: bad input naming --out
    for (extra, name) in [(Some("--png"), "y.svg"), (None, "y.jpg"), (None, "y")] {
        let path = dir.join(name);
        let mut a: Vec<&str> = args.to_vec();
        a.extend(extra);
        let out = plot(&a, &path);
        let err = String::from_utf8_lossy(&out.stderr);
        assert_eq!(out.status.code(), Some(2), "{name}: {err}");
        assert!(
            err.contains("--out") && err.contains(".png") && err.contains(".svg"),
            "{err}"
        );
        assert!(!path.exists(), "{name} must not be written");
    }
    std::fs::remove_dir_all(&dir).ok();
}

/// A polygon's fill, opacity and points.
type Poly<'a> = (&'a str, f64, Vec<(f64, f64)>);

/// The `points` of a polyline or polygon.
fn points_of(n: &roxmltree::Node) -> Vec<(f64, f64)> {
    n.attribute("points")
        .unwrap()
        .split_whitespace()
        .map(|p| {
            let (x, y) = p.split_once(',').unwrap();
            (x.parse().unwrap(), y.parse().unwrap())
        })
        .collect()
}

/// Every polygon of the document.
fn polygons<'a>(doc: &'a roxmltree::Document) -> Vec<Poly<'a>> {
    doc.descendants()
        .filter(|n| n.has_tag_name("polygon"))
        .map(|n| {
            let pts = points_of(&n);
            let opacity = n.attribute("opacity").map_or(1.0, |o| o.parse().unwrap());
            (n.attribute("fill").unwrap_or(""), opacity, pts)
        })
        .collect()
}

#[test]
fn several_arches_each_tint_their_own_safe_domain() {
    let arches: Vec<Arch> = [0.0, 0.524, 1.0]
        .iter()
        .map(|&a| Arch::symmetric(a, WeightModel::Centreline).unwrap())
        .collect();
    let svg = curve_svg(&arches, false);
    let doc = parse(&svg);
    let polys = polygons(&doc);
    // nothing opaque or white is painted over another arch's tint, no collapse tint
    assert!(polys.iter().all(|p| p.0 != "#FFFFFF"), "a whitening layer");
    assert!(!polys.iter().any(|p| p.0 == hex(plot_curve::COLLAPSE_TINT)));
    let safe: Vec<_> = polys
        .iter()
        .filter(|p| p.0 == hex(plot_curve::SAFE_TINT))
        .collect();
    assert_eq!(safe.len(), 3, "one safe layer per arch");
    assert!(safe
        .iter()
        .all(|p| (p.1 - plot_curve::SAFE_OPACITY).abs() < 1e-9));
    // each layer starts at its own arch's sliding branch (a vertical red line)
    let sliding = hex(mode_color(CollapseMode::PurelySliding));
    let mut walls: Vec<f64> = doc
        .descendants()
        .filter(|n| n.has_tag_name("polyline") && n.attribute("stroke") == Some(&*sliding))
        .filter_map(|n| {
            let xs: Vec<&str> = n
                .attribute("points")
                .unwrap()
                .split_whitespace()
                .map(|p| p.split_once(',').unwrap().0)
                .collect();
            // vertical: the legend's sample line is horizontal
            (xs.len() == 2 && xs[0] == xs[1]).then(|| xs[0].parse().unwrap())
        })
        .collect();
    let mut lefts: Vec<f64> = safe
        .iter()
        .map(|p| p.2.iter().map(|q| q.0).fold(f64::INFINITY, f64::min))
        .collect();
    walls.sort_by(f64::total_cmp);
    lefts.sort_by(f64::total_cmp);
    assert_eq!(walls.len(), 3);
    for (w, l) in walls.iter().zip(&lefts) {
        assert!(
            (w - l).abs() <= 1.0,
            "safe layer from {l}, sliding branch at {w}"
        );
    }
    // a single arch: its safe and collapse domains, each once
    let one = curve_svg(&arches[1..2], false);
    let doc = parse(&one);
    let polys = polygons(&doc);
    for tint in [plot_curve::SAFE_TINT, plot_curve::COLLAPSE_TINT] {
        assert_eq!(polys.iter().filter(|p| p.0 == hex(tint)).count(), 1);
    }
}

#[test]
fn map_has_a_colour_bar() {
    let svg = map_svg(&semicircle(), 6, 8, false);
    let doc = parse(&svg);
    let bar: std::collections::BTreeSet<&str> = doc
        .descendants()
        .filter(|n| n.has_tag_name("rect") && n.attribute("width") == Some("22"))
        .filter_map(|n| n.attribute("fill"))
        .filter(|f| *f != "none")
        .collect();
    assert_eq!(bar.len(), 10, "five safe and five collapse bands: {bar:?}");
    let texts: Vec<String> = doc
        .descendants()
        .filter(|n| n.has_tag_name("text"))
        .map(|n| n.text().unwrap_or("").trim().to_string())
        .collect();
    assert!(texts.iter().any(|t| t.starts_with("margin")), "bar title");
    let signed = texts
        .iter()
        .filter(|t| (t.starts_with('+') || t.starts_with('-')) && t[1..].parse::<f64>().is_ok())
        .count();
    assert_eq!(signed, 11, "one value per band edge");
}

/// (value, y) of the tick labels of the η axis (numbers right-aligned left of the plot).
fn eta_ticks(doc: &roxmltree::Document) -> Vec<(f64, f64)> {
    doc.descendants()
        .filter(|n| n.has_tag_name("text") && n.attribute("text-anchor") == Some("end"))
        .filter(|n| n.attribute("x").unwrap().parse::<f64>().unwrap() < 100.0)
        .filter_map(|n| {
            let v: f64 = n.text()?.trim().parse().ok()?;
            Some((v, n.attribute("y")?.parse().ok()?))
        })
        .collect()
}

/// Largest deviation of y from the straight line through the first and last ticks, with
/// the values mapped by `f`, relative to the span.
fn bend(ticks: &[(f64, f64)], f: fn(f64) -> f64) -> f64 {
    let (a, b) = (ticks[0], ticks[ticks.len() - 1]);
    ticks
        .iter()
        .map(|&(v, y)| {
            let t = (f(v) - f(a.0)) / (f(b.0) - f(a.0));
            (a.1 + t * (b.1 - a.1) - y).abs() / (b.1 - a.1).abs()
        })
        .fold(0.0, f64::max)
}

#[test]
fn log_eta_puts_eta_on_a_log_axis() {
    let shallow = Arch::symmetric(-1.2, WeightModel::Centreline).unwrap();
    for (svg, log) in [
        (curve_svg(std::slice::from_ref(&shallow), true), true),
        (curve_svg(std::slice::from_ref(&shallow), false), false),
        (map_svg(&semicircle(), 6, 8, true), true),
    ] {
        let doc = parse(&svg);
        let ticks = eta_ticks(&doc);
        assert!(ticks.len() >= 3, "{ticks:?}");
        assert!(ticks.iter().all(|t| t.0 > 0.0) || !log);
        if log {
            assert!(bend(&ticks, f64::ln) < 0.01, "not logarithmic: {ticks:?}");
            assert!(bend(&ticks, |v| v) > 0.05, "linear: {ticks:?}");
        } else {
            assert!(bend(&ticks, |v| v) < 0.01, "not linear: {ticks:?}");
        }
        // one format on the axis: every label has the same number of decimals
        let labels: Vec<String> = doc
            .descendants()
            .filter(|n| n.has_tag_name("text") && n.attribute("text-anchor") == Some("end"))
            .filter(|n| n.attribute("x").unwrap().parse::<f64>().unwrap() < 100.0)
            .filter_map(|n| n.text().map(|t| t.trim().to_string()))
            .filter(|t| t.parse::<f64>().is_ok())
            .collect();
        let decimals = |t: &String| t.split_once('.').map_or(0, |d| d.1.len());
        assert!(
            labels.iter().all(|t| decimals(t) == decimals(&labels[0])),
            "{labels:?}"
        );
    }
}

#[test]
fn joint_lines_are_drawn_only_when_visible() {
    let joint_lines = |blocks: usize| {
        let arch = semicircle().with_blocks(blocks).unwrap();
        let svg = arch_svg(&arch, 0.35, None).unwrap();
        let doc = parse(&svg);
        let n = doc
            .descendants()
            .filter(|n| n.has_tag_name("polyline") && n.attribute("stroke") == Some("#786E64"))
            .count();
        (n, svg)
    };
    let (twelve, _) = joint_lines(12);
    assert_eq!(twelve, 13, "12 voussoirs: 13 joints drawn");
    let (many, svg) = joint_lines(100_000);
    assert_eq!(many, 0, "100000 joints would paint the arch grey");
    assert!(svg.contains("not drawn"));
    assert!(svg.len() < 2_000_000, "{} bytes", svg.len());
}

/// Issue 10: the limit-state diagram marks smooth transitions apart from corners and draws
/// the limit states above the boundary, each with a legend entry — only where they exist.
#[test]
fn diagram_marks_transitions_and_limit_states_above_the_boundary() {
    let s = Settings::default();
    let with = |alpha: f64| {
        let d = arch_enum::figures::curve(
            &Arch::symmetric(alpha, WeightModel::Centreline).unwrap(),
            &s,
        )
        .unwrap();
        arch_enum::render::plot_curve::svg(&[d], false).unwrap()
    };
    // α = 0.8: a mirror pair of limit states above η_s near μ_ms; α = 1.05: two transitions
    let a = with(0.8);
    assert!(a.contains("limit state above η_s"));
    let b = with(1.05);
    assert!(b.contains("smooth transition"));
    assert!(!b.contains("limit state above η_s"));
    // the semicircle has neither
    let c = with(0.0);
    assert!(!c.contains("smooth transition") && !c.contains("limit state above η_s"));
}

/// Issue 10: `plot arch --limit-states` draws one labelled panel per limit state — for the
/// non-unique α = 0.8 arch near μ_ms, the state at η_s and the mirror pair above it; a
/// case with no limit state is refused with exit 1 and a reason.
#[test]
fn every_limit_state_gets_a_panel() {
    let s = Settings::default();
    let arch = Arch::symmetric(0.8, WeightModel::Centreline).unwrap();
    let scenes = figures::limit_scenes(&arch, 1.1540692474221415, &s).unwrap();
    assert_eq!(scenes.len(), 3);
    let svg = plot_arch::svg_panels(&scenes).unwrap();
    for k in 1..=3 {
        assert!(svg.contains(&format!("limit state {k} of 3")), "{k}");
    }
    assert_eq!(svg.matches("above eta_s").count(), 2);
    // decodes as one picture
    svg_to_png(&svg, 600).unwrap();
    // the unsymmetric arch of the issue at mu = 0.96: no mechanism at eta_s, one above
    let arch = Arch::new(-0.67, 2.72, WeightModel::Centreline).unwrap();
    let scenes = figures::limit_scenes(&arch, 0.96, &s).unwrap();
    assert_eq!(scenes.len(), 1);
    assert!(scenes[0].0.contains("above eta_s"));
}

/// `plot load`: one panel per limit state (the collapse first), the load drawn with its
/// multiplier; a load that never breaks the arch draws nothing (exit 1, said why).
#[test]
fn load_figure_has_a_panel_per_limit_state_and_the_load() {
    let dir = std::env::temp_dir().join(format!("arch-enum-plot-load-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let svg = dir.join("load.svg");
    let out = Command::cargo_bin("arch-enum")
        .unwrap()
        .args([
            "plot",
            "load",
            "--beta-right",
            "0.2442",
            "--beta-left",
            "3.1489",
            "--joints",
            "0.2442,0.8409,1.2686,2.0653,2.3805,2.7970,3.1489",
            "--eta",
            "0.6364",
            "--mu",
            "1.0246",
            "--horizontal-left",
            "--out",
        ])
        .arg(&svg)
        .output()
        .unwrap();
    assert_eq!(
        out.status.code(),
        Some(0),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let text = std::fs::read_to_string(&svg).unwrap();
    assert!(
        text.contains("collapse: limit state 1 of 3: lambda = 0.880055708"),
        "labels"
    );
    assert_eq!(text.matches("limit state 3 of 3").count(), 1);
    assert_eq!(
        text.matches("horizontal λ·weight, λ = ").count(),
        3,
        "one load label per panel"
    );
    let none = Command::cargo_bin("arch-enum")
        .unwrap()
        .args([
            "plot",
            "load",
            "--alpha",
            "0",
            "--blocks",
            "8",
            "--eta",
            "0.05",
            "--mu",
            "inf",
            "--horizontal",
            "--out",
        ])
        .arg(dir.join("none.svg"))
        .output()
        .unwrap();
    assert_eq!(none.status.code(), Some(1));
    assert!(String::from_utf8_lossy(&none.stderr).contains("no figure"));
    std::fs::remove_dir_all(&dir).ok();
}

/// `plot load-curve`: the λ–μ figure names λ_static, λ and the μ = ∞ value, and shades the
/// window where λ < λ_static (one polygon per interval of it).
#[test]
fn load_curve_figure_shades_the_reduction() {
    let dir = std::env::temp_dir().join(format!("arch-enum-plot-lmu-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let svg = dir.join("lmu.svg");
    let out = Command::cargo_bin("arch-enum")
        .unwrap()
        .args([
            "plot",
            "load-curve",
            "--beta-right",
            "0.2442",
            "--beta-left",
            "3.1489",
            "--joints",
            "0.2442,0.8409,1.2686,2.0653,2.3805,2.7970,3.1489",
            "--eta",
            "0.6364",
            "--horizontal-left",
            "--mu-min",
            "0.6",
            "--mu-max",
            "2",
            "--points",
            "30",
            "--out",
        ])
        .arg(&svg)
        .output()
        .unwrap();
    assert_eq!(
        out.status.code(),
        Some(0),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let text = std::fs::read_to_string(&svg).unwrap();
    assert!(text.contains("λ_static (largest admissible)"));
    assert!(text.contains("μ = ∞: λ = 1.33"));
    let shaded = text.matches("fill=\"#D62728\"").count();
    assert!(shaded >= 3, "{shaded} shaded intervals");
    std::fs::remove_dir_all(&dir).ok();
}

/// The extreme mechanisms of a 2-dof cone (the semicircle at μ = 0.35: five contacts, rank
/// 3): two, each compatible (B λ = 0), of unit sum and non-negative power, mirror images of
/// each other, and their mean is the symmetric representative; `plot arch --mechanism K`
/// draws each and names an out-of-range K with the range.
#[test]
fn extreme_mechanisms_of_a_two_dof_cone() {
    let settings = Settings::default();
    let scene = figures::scene(&semicircle(), 0.35, None, &settings).unwrap();
    let m = scene.mechanism.clone().unwrap();
    assert_eq!(m.dof, 2);
    let rays = arch_enum::mechanism::extreme_mechanisms(&scene.arch, scene.eta, &m, &settings);
    assert_eq!(rays.len(), 2, "{rays:?}");
    for r in &rays {
        let res = arch_enum::kinematics::compatibility_residual(scene.eta, &m.contacts, r);
        assert!(res.iter().all(|v| v.abs() < 1e-12), "{res:?}");
        assert!((r.iter().sum::<f64>() - 1.0).abs() < 1e-12);
        assert!(r.iter().all(|&v| v >= 0.0));
        let p = arch_enum::kinematics::power(&scene.arch, scene.eta, &m.contacts);
        assert!(p.iter().zip(r).map(|(a, b)| a * b).sum::<f64>() >= 0.0);
    }
    let n = m.rates.len();
    for i in 0..n {
        // mirror images (contacts are sorted by beta, the pattern is symmetric)
        assert!((rays[0][i] - rays[1][n - 1 - i]).abs() < 1e-12, "{rays:?}");
        let mean = 0.5 * (rays[0][i] + rays[1][i]);
        assert!(
            (mean - m.rates[i]).abs() < 1e-12,
            "{mean} vs {}",
            m.rates[i]
        );
    }
    let two = figures::extreme_scene(scene.clone(), 2, &settings).unwrap();
    assert_eq!(two.ray, Some((2, 2)));
    assert_eq!(
        figures::extreme_scene(scene, 3, &settings).unwrap_err(),
        figures::ExtremeChoice::OutOfRange(2)
    );
    let plot = |k: &str| {
        Command::cargo_bin("arch-enum")
            .unwrap()
            .args(["plot", "arch", "--alpha", "0", "--mu", "0.35"])
            .args(["--mechanism", k, "--out", "-"])
            .output()
            .unwrap()
    };
    let out = plot("1");
    assert_eq!(out.status.code(), Some(0));
    assert!(String::from_utf8_lossy(&out.stdout).contains("extreme 1 of 2"));
    let out = plot("3");
    assert_eq!(out.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&out.stderr).contains("--mechanism: 3 (valid range: 1 to 2"));
}

/// `plot curve` with fill draws μ_min(η) (traced in η): thick polylines in the modes'
/// colours through many points, the least friction μ_f marked where the curve turns (no
/// point of the curve lies left of it), the safe domain tinted right of the curve, and
/// the labels of μ_f and η*(∞). With fill the figure takes one opening, by name.
#[test]
fn fill_curve_figure_turns_at_the_least_friction() {
    use arch_enum::bridge::Fill;
    use arch_enum::figures::fill_curve::fill_curve;
    use arch_enum::render::plot_curve::SAFE_TINT;
    let arch = semicircle().with_fill(Fill::new(0.9, 0.0566).unwrap());
    let data = fill_curve(&arch, &Settings::default(), 2).unwrap();
    let svg = arch_enum::render::plot_fill_curve::svg(&data).unwrap();
    let doc = parse(&svg);
    let curve: Vec<(f64, f64)> = doc
        .descendants()
        .filter(|n| n.has_tag_name("polyline") && n.attribute("stroke-width") == Some("3"))
        .filter(|n| n.attribute("points").unwrap().split_whitespace().count() > 2)
        .flat_map(|n| points_of(&n))
        .collect();
    assert!(curve.len() > 100, "{} points", curve.len());
    let marks: Vec<(f64, f64)> = doc
        .descendants()
        .filter(|n| n.has_tag_name("circle") && n.attribute("r") == Some("6"))
        .map(|n| {
            let at = |a: &str| n.attribute(a).unwrap().parse::<f64>().unwrap();
            (at("cx"), at("cy"))
        })
        .collect();
    assert_eq!(marks.len(), 2, "the least friction and the legend's marker");
    let least = marks
        .iter()
        .copied()
        .min_by(|a, b| a.0.total_cmp(&b.0))
        .unwrap();
    let left = curve.iter().map(|p| p.0).fold(f64::INFINITY, f64::min);
    assert!(
        (left - least.0).abs() < 1.0,
        "curve's left end {left} vs mu_f at {}",
        least.0
    );
    // the turn is inside: points of the curve lie above and below the mark
    assert!(
        curve.iter().any(|p| p.1 < least.1 - 50.0) && curve.iter().any(|p| p.1 > least.1 + 50.0)
    );
    assert!(polygons(&doc).iter().any(|p| p.0 == hex(SAFE_TINT)));
    assert!(
        svg.contains("μ_f = 0.260") && svg.contains("η*(∞) = 0.0646"),
        "labels"
    );
    let dir = std::env::temp_dir().join(format!("fill_curve_{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let out = dir.join("c.svg");
    let two = [
        "curve",
        "--alpha",
        "0",
        "--alpha",
        "1",
        "--fill-ratio",
        "0.9",
        "--fill-height",
        "0.05",
    ];
    let o = plot(&two, &out);
    assert_eq!(o.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&o.stderr).contains("--alpha"));
    let one = [
        "curve",
        "--alpha",
        "0",
        "--fill-ratio",
        "0.9",
        "--fill-height",
        "0.05",
    ];
    assert_eq!(plot(&one, &out).status.code(), Some(0));
    assert!(std::fs::read_to_string(&out)
        .unwrap()
        .contains("least friction"));
    std::fs::remove_dir_all(&dir).ok();
}

/// The fill of every rect of `doc` (rects with no fill left out).
fn rect_fills<'a>(doc: &'a roxmltree::Document) -> Vec<(&'a str, [f64; 4])> {
    doc.descendants()
        .filter(|n| n.has_tag_name("rect"))
        .filter_map(|n| {
            let at = |a: &str| n.attribute(a).and_then(|v| v.parse::<f64>().ok());
            let fill = n.attribute("fill").filter(|f| *f != "none")?;
            Some((fill, [at("x")?, at("y")?, at("width")?, at("height")?]))
        })
        .collect()
}

/// The load map's figure (`plot atlas --horizontal`): one panel per μ, every cell filled by
/// its answer (one rect per cell of its colour, besides the legend's swatch), a reduced cell
/// coloured from the reduction scale with its reduction written inside it, a boundary as a
/// black bar, and the same from the command line (five voussoirs, two friction coefficients).
#[test]
fn load_map_figure_fills_each_cell_by_its_answer() {
    use arch_enum::atlas::loads::{load_map, CellAnswer, LoadBoundary, LoadGrid};
    use arch_enum::atlas::Rectangle;
    use arch_enum::render::plot_load_map::{self, NOT_REDUCED, NO_COLLAPSE, UNDECIDED};
    let grid = LoadGrid {
        rect: Rectangle {
            alpha_min: -0.2,
            alpha_max: 0.6,
            mu_max_factor: 10.0,
            weight: WeightModel::Centreline,
            blocks: Some(5),
            columns: 3,
            samples: 40,
            certify: false,
        },
        mus: vec![0.6, 1.0],
        factors: 4,
        factor_max: 2.5,
    };
    let mut map = load_map(&grid, &Settings::default(), 2, &|_, _| {}).unwrap();
    // the drawing is a pure function of the map: give it one reduced and one undecided
    // cell, and a boundary between the reduced cell and the next thicker one
    let ratio = |c: &arch_enum::atlas::loads::LoadCell| c.ratio().is_some();
    let k = map
        .cells
        .iter()
        .position(ratio)
        .expect("a cell with a ratio");
    let (lambda_static, _, mode) = map.cells[k].ratio().unwrap();
    map.cells[k].answer = CellAnswer::Ratio {
        lambda_static,
        lambda_c: 0.875 * lambda_static,
        mode,
        at_most: false,
    };
    let reduced = map.cells[k].clone();
    let u = map.cells.iter().rposition(ratio).unwrap();
    map.cells[u].answer = CellAnswer::Undecided("test".into());
    let next = map.factors[map
        .factors
        .iter()
        .position(|&f| f == reduced.factor)
        .unwrap()
        + 1];
    let star = reduced.eta.unwrap() / reduced.factor;
    map.boundaries = vec![LoadBoundary {
        alpha: reduced.alpha,
        mu: reduced.mu,
        reduced_below: true,
        factors: (reduced.factor * 1.01, reduced.factor * 1.01),
        etas: (reduced.factor * 1.01 * star, reduced.factor * 1.01 * star),
        stopped: None,
        reduction: 0.125,
        at_least: true,
        followed: 1,
        bounded: 0,
        certified: None,
    }];
    assert!(next > reduced.factor * 1.01);
    let svg = plot_load_map::svg(&map, false).unwrap();
    let doc = parse(&svg);
    let fills = rect_fills(&doc);
    let count = |c: plotters::style::RGBColor| fills.iter().filter(|f| f.0 == hex(c)).count();
    let of = |p: &dyn Fn(&arch_enum::atlas::loads::LoadCell) -> bool| {
        map.cells.iter().filter(|c| p(c)).count()
    };
    // each cell once, and its legend swatch
    assert_eq!(count(NOT_REDUCED), of(&|c| ratio(c) && !c.reduced()) + 1);
    assert_eq!(count(UNDECIDED), 2);
    let no_collapse = of(&|c| c.answer == CellAnswer::NoCollapse);
    if no_collapse > 0 {
        assert_eq!(count(NO_COLLAPSE), no_collapse + 1);
    }
    // the reduced cell: "12.5" written inside the rect of its colour, which no other cell has
    let text = doc
        .descendants()
        .find(|n| n.has_tag_name("text") && n.text().map(str::trim) == Some("12.5"))
        .expect("the reduction written in its cell");
    let at = |a: &str| text.attribute(a).unwrap().parse::<f64>().unwrap();
    let (tx, ty) = (at("x"), at("y"));
    let cell = fills
        .iter()
        .filter(|(_, [x, y, w, h])| tx > *x && tx < x + w && ty > *y - 12.0 && ty < y + h)
        .min_by(|a, b| (a.1[2] * a.1[3]).total_cmp(&(b.1[2] * b.1[3])))
        .expect("a filled rect under the text");
    // 12.5 % on a scale to 15 %: a colour of its own (no step of the colour bar has it)
    assert!([NOT_REDUCED, NO_COLLAPSE, UNDECIDED]
        .iter()
        .all(|c| hex(*c) != cell.0));
    assert_eq!(
        fills.iter().filter(|f| f.0 == cell.0).count(),
        1,
        "{}",
        cell.0
    );
    assert!(
        svg.contains("λ_c &lt; λ_static in 1 of"),
        "the caption counts it"
    );
    // a boundary decided by following its limit state gives a lower bound, and says so
    assert!(
        svg.contains("; ≥ 12.5 % at a boundary"),
        "the caption's bound"
    );
    // the boundary bar, and the legend's two bars
    let bars = doc
        .descendants()
        .filter(|n| n.has_tag_name("polyline") && n.attribute("stroke-width") == Some("3"))
        .count();
    // two ticks each (the legend's vertical bar only where a bisection stopped)
    assert_eq!(bars, 4, "one boundary and its legend");
    // from the command line: one panel per mu, every cell drawn
    let dir = std::env::temp_dir().join(format!("load_map_{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let out = dir.join("m.svg");
    let args = [
        "atlas",
        "--horizontal",
        "--mu",
        "0.6,1",
        "--blocks",
        "5",
        "--alpha-min",
        "-0.2",
        "--alpha-max",
        "0.6",
        "--columns",
        "3",
        "--factors",
        "4",
        "--factor-max",
        "2.5",
    ];
    let o = plot(&args, &out);
    assert_eq!(
        o.status.code(),
        Some(0),
        "{}",
        String::from_utf8_lossy(&o.stderr)
    );
    let svg = std::fs::read_to_string(&out).unwrap();
    assert_eq!(svg.matches("μ = 0.6:").count(), 1);
    assert_eq!(svg.matches("μ = 1:").count(), 1);
    assert!(svg.contains("η / η*(α, μ)"), "the factor up the map");
    // the heights at which cells start: one row of edges shared by every opening
    let rows = |svg: &str| {
        let doc = parse(svg);
        let mut ys: Vec<i64> = rect_fills(&doc)
            .iter()
            .filter(|(_, [_, _, w, _])| *w < 200.0)
            .map(|(_, [_, y, _, _])| (y * 10.0).round() as i64)
            .collect();
        ys.sort();
        ys.dedup();
        ys.len()
    };
    let by_factor = rows(&svg);
    // --eta-axis: the thickness itself up the map, each opening's cells at f eta*, so the
    // openings' cells start at heights of their own
    let mut by_eta = args.to_vec();
    by_eta.push("--eta-axis");
    assert_eq!(plot(&by_eta, &out).status.code(), Some(0));
    let svg = std::fs::read_to_string(&out).unwrap();
    assert!(svg.contains("thickness ratio η = t / r") && !svg.contains("η / η*(α, μ)"));
    assert!(rows(&svg) > by_factor, "{} vs {by_factor}", rows(&svg));
    let o = plot(&["atlas", "--eta-axis"], &out);
    assert_eq!(o.status.code(), Some(2), "--eta-axis needs --horizontal");
    let o = plot(
        &["atlas", "--horizontal", "--mu", "1", "--factors", "1"],
        &out,
    );
    assert_eq!(o.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&o.stderr).contains("--factors"));
    std::fs::remove_dir_all(&dir).ok();
}
