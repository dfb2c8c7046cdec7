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
    format!("{} ({:.0}°)", short_trimmed(mu), mu.atan().to_degrees())
}

/// [`short_num`] with trailing zeros trimmed: "0.4", "0.593", "12.5".
pub fn short_trimmed(v: f64) -> String {
    let t = short_num(v);
    if t.contains('.') && !t.contains('e') {
        t.trim_end_matches('0').trim_end_matches('.').to_string()
    } else {
        t
    }
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

/// "α = 0.524" for a symmetric arch, else its springing angles.
pub fn arch_label(arch: &crate::arch::Arch) -> String {
    if arch.is_symmetric() {
        format!("α = {}", short_num(0.0 - arch.beta_right()))
    } else {
        format!(
            "β_R = {:.3}, β_L = {:.3}",
            arch.beta_right(),
            arch.beta_left()
        )
    }
}

/// One axis of a chart: its range, linear or logarithmic, and its ticks. Charts are built on
/// u = v (linear) or u = ln v (log), so both kinds of axis have the same type; data are
/// placed with [`Axis::to`], and every tick of an axis is printed with the same format.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Axis {
    /// Lower end (> 0 on a log axis).
    pub lo: f64,
    /// Upper end.
    pub hi: f64,
    /// Logarithmic scale.
    pub log: bool,
}

/// Roughly how many ticks a linear axis gets.
const LINEAR_TICKS: f64 = 6.0;

impl Axis {
    /// The chart coordinate of the value `v`.
    pub fn to(&self, v: f64) -> f64 {
        if self.log {
            v.ln()
        } else {
            v
        }
    }

    /// The value at the chart coordinate `u`.
    pub fn from(&self, u: f64) -> f64 {
        if self.log {
            u.exp()
        } else {
            u
        }
    }

    /// The chart coordinates spanned, with the ticks as key points.
    pub fn range(&self) -> AxisCoord {
        AxisCoord {
            lo: self.to(self.lo),
            hi: self.to(self.hi),
            keys: self.ticks().iter().map(|&v| self.to(v)).collect(),
        }
    }

    fn linear_step(&self) -> f64 {
        let raw = (self.hi - self.lo) / LINEAR_TICKS;
        let mag = 10f64.powf(raw.log10().floor());
        [1.0, 2.0, 5.0, 10.0]
            .into_iter()
            .map(|m| m * mag)
            .find(|&s| s >= raw * (1.0 - 1e-9))
            .unwrap_or(10.0 * mag)
    }

    /// Tick values: multiples of 1, 2 or 5 × 10^k (linear), or 1, 2, 3, 5 × 10^k thinned to
    /// at most eight (log).
    pub fn ticks(&self) -> Vec<f64> {
        if !self.log {
            let step = self.linear_step();
            let k0 = (self.lo / step - 1e-9).ceil() as i64;
            let k1 = (self.hi / step + 1e-9).floor() as i64;
            return (k0..=k1).map(|k| k as f64 * step).collect();
        }
        let e0 = self.lo.log10().floor() as i32;
        let e1 = self.hi.log10().ceil() as i32;
        let with = |ms: &[f64]| -> Vec<f64> {
            (e0..=e1)
                .flat_map(|e| ms.iter().map(move |m| m * 10f64.powi(e)))
                .filter(|&v| v >= self.lo * (1.0 - 1e-9) && v <= self.hi * (1.0 + 1e-9))
                .collect()
        };
        let mut t = with(&[1.0, 2.0, 3.0, 5.0]);
        if t.len() < 4 {
            t = with(&[1.0, 2.0, 3.0, 4.0, 5.0, 7.0]);
        }
        if t.len() > 8 {
            t = with(&[1.0, 3.0]);
        }
        if t.len() > 8 {
            t = with(&[1.0]);
        }
        t
    }

    /// Decimals shared by every tick label of the axis.
    pub fn decimals(&self) -> usize {
        let dec = |v: f64| (-(v.abs().log10() + 1e-9).floor()).max(0.0) as usize;
        if self.log {
            self.ticks().into_iter().map(dec).max().unwrap_or(0).min(6)
        } else {
            dec(self.linear_step()).min(6)
        }
    }

    /// A μ tick label "μ (φ°)" at chart coordinate `u`: μ in the axis's format, the friction
    /// angle φ = atan μ with one decimal when the whole axis stays below 10°, else none.
    pub fn mu_label(&self, u: f64) -> String {
        let d = usize::from(self.hi.atan().to_degrees() < 10.0);
        format!(
            "{} ({:.d$}°)",
            self.label(u),
            self.from(u).atan().to_degrees()
        )
    }

    /// The tick label at chart coordinate `u`, in the axis's one format.
    pub fn label(&self, u: f64) -> String {
        let d = self.decimals();
        format!("{:.d$}", self.from(u))
    }
}

/// The edges of the cells centred on `c` (ascending): midpoints between neighbours
/// (geometric on a log axis), the outer edges half a step out.
pub fn cell_edges(c: &[f64], log: bool) -> Vec<f64> {
    let n = c.len();
    let mid = |a: f64, b: f64| if log { (a * b).sqrt() } else { 0.5 * (a + b) };
    let out = |a: f64, b: f64| {
        if log {
            a * (a / b).sqrt()
        } else {
            1.5 * a - 0.5 * b
        }
    };
    let mut e = vec![if n > 1 { out(c[0], c[1]) } else { c[0] }];
    e.extend(c.windows(2).map(|w| mid(w[0], w[1])));
    e.push(if n > 1 { out(c[n - 1], c[n - 2]) } else { c[0] });
    e
}

/// The estimated width of `text` in pixels at font `size` (DejaVu Sans, mostly digits).
pub fn text_width(text: &str, size: u32) -> i32 {
    (0.47 * size as f64 * text.chars().count() as f64).ceil() as i32
}

/// A legend's column of collapse modes: `title` at `(lx, ly)`, then a line in each mode's
/// colour and its name, 24 px apart. Returns the y of the last row.
pub fn legend_modes<DB: plotters::prelude::DrawingBackend>(
    area: &plotters::prelude::DrawingArea<DB, plotters::coord::Shift>,
    title: &str,
    modes: &[CollapseMode],
    (lx, mut ly): (i32, i32),
) -> Result<i32, String> {
    use plotters::prelude::*;
    let e = |e: DrawingAreaErrorKind<DB::ErrorType>| e.to_string();
    area.draw(&Text::new(title, (lx, ly), (FAMILY, 14)))
        .map_err(e)?;
    for mode in modes {
        ly += 24;
        area.draw(&PathElement::new(
            vec![(lx, ly + 7), (lx + 26, ly + 7)],
            mode_color(*mode).stroke_width(3),
        ))
        .map_err(e)?;
        area.draw(&Text::new(mode.name(), (lx + 34, ly), (FAMILY, 13)))
            .map_err(e)?;
    }
    Ok(ly)
}

/// A legend row at `(lx, ly)`: a swatch of `color` at `opacity` and its `text`.
pub fn legend_swatch<DB: plotters::prelude::DrawingBackend>(
    area: &plotters::prelude::DrawingArea<DB, plotters::coord::Shift>,
    (lx, ly): (i32, i32),
    color: RGBColor,
    opacity: f64,
    text: &str,
) -> Result<(), String> {
    use plotters::prelude::*;
    area.draw(&Rectangle::new(
        [(lx + 2, ly + 1), (lx + 24, ly + 14)],
        color.mix(opacity).filled(),
    ))
    .and_then(|_| area.draw(&Text::new(text.to_string(), (lx + 34, ly), (FAMILY, 13))))
    .map_err(|e| e.to_string())
}

/// Draws `text` on a white backing box (so a line behind it does not strike it through),
/// anchored at the pixel `at` of `area` by `pos`.
pub fn boxed_text<DB: plotters::prelude::DrawingBackend>(
    area: &plotters::prelude::DrawingArea<DB, plotters::coord::Shift>,
    text: &str,
    at: (i32, i32),
    size: u32,
    pos: plotters::style::text_anchor::Pos,
    color: RGBColor,
) -> Result<(), String> {
    use plotters::prelude::*;
    use plotters::style::text_anchor::{HPos, VPos};
    let w = text_width(text, size);
    let h = size as i32 + 2;
    let x0 = match pos.h_pos {
        HPos::Left => at.0,
        HPos::Center => at.0 - w / 2,
        HPos::Right => at.0 - w,
    };
    let y0 = match pos.v_pos {
        VPos::Top => at.1,
        VPos::Center => at.1 - h / 2,
        VPos::Bottom => at.1 - h,
    };
    area.draw(&Rectangle::new(
        [(x0 - 2, y0 - 1), (x0 + w + 2, y0 + h + 1)],
        WHITE.mix(0.85).filled(),
    ))
    .map_err(|e| e.to_string())?;
    area.draw(&Text::new(
        text.to_string(),
        at,
        TextStyle::from((FAMILY, size).into_font())
            .pos(pos)
            .color(&color),
    ))
    .map_err(|e| e.to_string())
}

/// The chart coordinate of an [`Axis`]: linear in u from `to(lo)` to `to(hi)`, with the
/// axis's ticks as its only key points.
#[derive(Debug, Clone, PartialEq)]
pub struct AxisCoord {
    lo: f64,
    hi: f64,
    keys: Vec<f64>,
}

impl plotters::coord::ranged1d::Ranged for AxisCoord {
    type ValueType = f64;
    type FormatOption = plotters::coord::ranged1d::DefaultFormatting;

    fn map(&self, v: &f64, limit: (i32, i32)) -> i32 {
        let t = (v - self.lo) / (self.hi - self.lo);
        limit.0 + (t * (limit.1 - limit.0) as f64).round() as i32
    }

    fn key_points<H: plotters::coord::ranged1d::KeyPointHint>(&self, _hint: H) -> Vec<f64> {
        self.keys.clone()
    }

    fn range(&self) -> std::ops::Range<f64> {
        self.lo..self.hi
    }
}
