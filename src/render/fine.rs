//! Paths with sub-pixel coordinates. plotters hands its backends whole-pixel coordinates,
//! so a line of thrust drawn through it is stair-stepped once the SVG is scaled (a 3000 px
//! PNG is 3.1 times the 960 px document). A path drawn through [`Fine`] keeps its coordinates
//! to 1/100 px: plotters draws a placeholder in its place in the drawing order, and
//! [`Fine::finish`] writes the path there as an SVG `polyline` or `polygon` with fractional
//! coordinates, the attributes as plotters writes them (`opacity`, `stroke`/`fill`,
//! `stroke-width`, `points`).

use crate::render::plot::FAMILY;
use plotters::coord::ranged1d::Ranged;
use plotters::prelude::*;
use std::cell::RefCell;
use std::fmt::Write as _;

/// The affine map from a chart's values to SVG pixels, as plotters maps them before it
/// rounds: the plotting area's first to last pixel, y upwards.
#[derive(Debug, Clone, Copy)]
struct PixelMap {
    x: [f64; 4],
    y: [f64; 4],
}

impl PixelMap {
    fn of<DB, X, Y>(ch: &ChartContext<DB, Cartesian2d<X, Y>>) -> PixelMap
    where
        DB: DrawingBackend,
        X: Ranged<ValueType = f64>,
        Y: Ranged<ValueType = f64>,
    {
        let (px, py) = ch.plotting_area().get_pixel_range();
        let spec = ch.as_coord_spec();
        let (rx, ry) = (spec.x_spec().range(), spec.y_spec().range());
        PixelMap {
            x: [rx.start, rx.end, px.start as f64, (px.end - 1) as f64],
            y: [ry.start, ry.end, (py.end - 1) as f64, py.start as f64],
        }
    }

    fn at(&self, (u, v): (f64, f64)) -> (f64, f64) {
        let lin = |[lo, hi, p0, p1]: [f64; 4], t: f64| p0 + (p1 - p0) * (t - lo) / (hi - lo);
        (lin(self.x, u), lin(self.y, v))
    }
}

/// The paths of one SVG document, written into it by [`Fine::finish`].
#[derive(Debug, Default)]
pub struct Fine {
    elements: RefCell<Vec<String>>,
}

fn token(k: usize) -> String {
    format!("fine-path-{k}-placeholder")
}

fn hex(c: RGBAColor) -> String {
    format!("#{:02X}{:02X}{:02X}", c.0, c.1, c.2)
}

impl Fine {
    /// Draws the open path through `points` (chart values) with `style`'s colour and
    /// stroke width, dashed `dash` = (on, off) pixels when given.
    pub fn polyline<DB, X, Y>(
        &self,
        ch: &ChartContext<DB, Cartesian2d<X, Y>>,
        points: &[(f64, f64)],
        style: ShapeStyle,
        dash: Option<(f64, f64)>,
    ) -> Result<(), String>
    where
        DB: DrawingBackend,
        X: Ranged<ValueType = f64>,
        Y: Ranged<ValueType = f64>,
    {
        let dash = dash.map_or(String::new(), |(on, off)| {
            format!(" stroke-dasharray=\"{on} {off}\"")
        });
        let element = format!(
            "<polyline fill=\"none\" opacity=\"{}\" stroke=\"{}\" stroke-width=\"{}\"{dash} points=\"{}\"/>",
            style.color.3,
            hex(style.color),
            style.stroke_width,
            Self::points(ch, points)
        );
        self.place(ch, points, element)
    }

    /// Fills the polygon through `points` (chart values) with `style`'s colour.
    pub fn polygon<DB, X, Y>(
        &self,
        ch: &ChartContext<DB, Cartesian2d<X, Y>>,
        points: &[(f64, f64)],
        style: ShapeStyle,
    ) -> Result<(), String>
    where
        DB: DrawingBackend,
        X: Ranged<ValueType = f64>,
        Y: Ranged<ValueType = f64>,
    {
        let element = format!(
            "<polygon opacity=\"{}\" fill=\"{}\" points=\"{}\"/>",
            style.color.3,
            hex(style.color),
            Self::points(ch, points)
        );
        self.place(ch, points, element)
    }

    fn points<DB, X, Y>(ch: &ChartContext<DB, Cartesian2d<X, Y>>, points: &[(f64, f64)]) -> String
    where
        DB: DrawingBackend,
        X: Ranged<ValueType = f64>,
        Y: Ranged<ValueType = f64>,
    {
        let map = PixelMap::of(ch);
        points
            .iter()
            .filter(|p| p.0.is_finite() && p.1.is_finite())
            .fold(String::new(), |mut s, &p| {
                let (x, y) = map.at(p);
                let _ = write!(s, "{x:.2},{y:.2} ");
                s
            })
    }

    /// Draws the placeholder of `element` where plotters would draw the path.
    fn place<DB, X, Y>(
        &self,
        ch: &ChartContext<DB, Cartesian2d<X, Y>>,
        points: &[(f64, f64)],
        element: String,
    ) -> Result<(), String>
    where
        DB: DrawingBackend,
        X: Ranged<ValueType = f64>,
        Y: Ranged<ValueType = f64>,
    {
        let Some(&at) = points.first() else {
            return Ok(());
        };
        let k = {
            let mut e = self.elements.borrow_mut();
            e.push(element);
            e.len() - 1
        };
        ch.plotting_area()
            .draw(&Text::new(token(k), at, (FAMILY, 1).into_font()))
            .map_err(|e| e.to_string())
    }

    /// `svg` with every placeholder replaced by its path.
    pub fn finish(&self, svg: &str) -> String {
        let mut out = svg.to_string();
        for (k, element) in self.elements.borrow().iter().enumerate() {
            let t = token(k);
            let Some(at) = out.find(&t) else { continue };
            let start = out[..at].rfind("<text").unwrap_or(at);
            let end = out[at..]
                .find("</text>")
                .map_or(at + t.len(), |e| at + e + 7);
            out.replace_range(start..end, element);
        }
        out
    }
}
