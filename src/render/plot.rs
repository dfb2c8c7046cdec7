//! Shared pieces of the figures: mode colours (the same in every figure), sizes, and
//! SVG → PNG rendering in-process with the embedded DejaVu Sans font (no system fonts).

use crate::collapse_mode::CollapseMode;
use plotters::style::RGBColor;

#[cfg(feature = "png")]
/// The font embedded for PNG rendering (DejaVu Sans, see `assets/fonts/DejaVu-LICENSE.txt`).
pub const FONT: &[u8] = include_bytes!("../../assets/fonts/DejaVuSans.ttf");

/// Font family used in every figure.
pub const FAMILY: &str = "DejaVu Sans";

/// The colour of a collapse mode, identical across figures.
pub fn mode_color(mode: CollapseMode) -> RGBColor {
    match mode {
        CollapseMode::PurelyRotational => RGBColor(31, 119, 180),
        CollapseMode::MixedSlidingRotational => RGBColor(255, 127, 14),
        CollapseMode::MixedRotationalSliding => RGBColor(44, 160, 44),
        CollapseMode::RotationalSlidingShoulders => RGBColor(148, 103, 189),
        CollapseMode::PurelySliding => RGBColor(214, 39, 40),
        CollapseMode::Overturning => RGBColor(140, 86, 75),
        CollapseMode::MixedInterleaved => RGBColor(127, 127, 127),
    }
}

#[cfg(feature = "png")]
/// Renders an SVG document to PNG bytes, `width` pixels wide (height keeps the aspect).
pub fn svg_to_png(svg: &str, width: u32) -> Result<Vec<u8>, String> {
    let mut opt = resvg::usvg::Options {
        font_family: FAMILY.to_string(),
        ..Default::default()
    };
    {
        let db = opt.fontdb_mut();
        db.load_font_data(FONT.to_vec());
        db.set_sans_serif_family(FAMILY);
        db.set_serif_family(FAMILY);
        db.set_monospace_family(FAMILY);
    }
    let tree =
        resvg::usvg::Tree::from_str(svg, &opt).map_err(|e| format!("SVG not parsed: {e}"))?;
    let size = tree.size();
    let scale = width as f32 / size.width();
    let height = (size.height() * scale).ceil() as u32;
    let mut pixmap = resvg::tiny_skia::Pixmap::new(width, height).ok_or("empty image")?;
    pixmap.fill(resvg::tiny_skia::Color::WHITE);
    resvg::render(
        &tree,
        resvg::tiny_skia::Transform::from_scale(scale, scale),
        &mut pixmap.as_mut(),
    );
    pixmap
        .encode_png()
        .map_err(|e| format!("PNG encoding failed: {e}"))
}

/// "0.3 (17°)": μ with up to 3 significant digits, trailing zeros trimmed, and the
/// friction angle φ = atan μ.
pub fn mu_label(mu: f64) -> String {
    let t = short_num(mu);
    let t = if t.contains('.') && !t.contains('e') {
        t.trim_end_matches('0').trim_end_matches('.').to_string()
    } else {
        t
    };
    format!("{t} ({:.0}°)", mu.atan().to_degrees())
}

/// A number with 3 significant digits, plain where readable.
pub fn short_num(v: f64) -> String {
    if v.abs() < 1e-12 {
        "0".into()
    } else if v.abs() >= 1e-3 && v.abs() < 1e4 {
        let digits = (2 - v.abs().log10().floor() as i32).max(0) as usize;
        format!("{v:.digits$}")
    } else {
        format!("{v:.2e}")
    }
}
