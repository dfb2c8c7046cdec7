//! The lines of a drawn state as points in the plane of the arch (x towards the right
//! springing, y up, lengths divided by r): the outline, the line of thrust, the line of
//! friction and the contacts. The data behind `to_compas` and `--compas`; the SVG figure
//! draws the same lines from [`ArchScene::lines`] itself.

use super::thrust_line::Eccentricity;
use super::ArchScene;
use crate::contact::ContactKind;

/// A point of the plane of the arch (x, y), in units of r.
pub type Point = (f64, f64);

/// The point at radius `r` and angle `beta`.
fn polar(r: f64, beta: f64) -> Point {
    (r * beta.cos(), r * beta.sin())
}

impl ArchScene {
    /// The closed outline of the arch at its thickness η: the extrados from β_R to β_L,
    /// the intrados back, and the first point again (at least one point per 0.02 rad).
    pub fn outline(&self) -> Vec<Point> {
        let (a, b) = (self.arch.beta_right(), self.arch.beta_left());
        let n = (((b - a) / 0.02).ceil() as usize).max(2);
        let at = |i: usize| a + (b - a) * i as f64 / n as f64;
        let mut pts: Vec<Point> = (0..=n)
            .map(|i| polar(1.0 + self.eta / 2.0, at(i)))
            .collect();
        pts.extend((0..=n).rev().map(|i| polar(1.0 - self.eta / 2.0, at(i))));
        pts.push(pts[0]);
        pts
    }

    /// The line of thrust: where the resultant cuts each sampled joint, at radius
    /// 1 + e_M (joints in compression only, N > 0), from β_R to β_L.
    pub fn thrust_line(&self) -> Vec<Point> {
        self.line(|e| e.e_m)
    }

    /// The line of friction: radius 1 + e_T, e_T = (T/N)/μ · η/2 (joints with N > 0);
    /// empty at μ = ∞, where no joint can slide.
    pub fn friction_line(&self) -> Vec<Point> {
        if self.mu.is_finite() {
            self.line(|e| e.e_t)
        } else {
            Vec::new()
        }
    }

    fn line(&self, f: impl Fn(&Eccentricity) -> f64) -> Vec<Point> {
        self.lines
            .iter()
            .filter(|e| e.n > 0.0 && f(e).is_finite())
            .map(|e| polar(1.0 + f(e), e.beta))
            .collect()
    }

    /// The hinges of the pattern: the extrados (1 + η/2) or intrados (1 − η/2) point of
    /// the joint, with the kind.
    pub fn hinges(&self) -> Vec<(Point, ContactKind)> {
        self.pattern
            .iter()
            .filter(|c| c.kind.is_hinge())
            .map(|c| {
                let r = match c.kind {
                    ContactKind::HingeExtrados => 1.0 + self.eta / 2.0,
                    _ => 1.0 - self.eta / 2.0,
                };
                (polar(r, c.beta), c.kind)
            })
            .collect()
    }

    /// The sliding joints of the pattern: the centreline point of the joint, with the
    /// kind (S+ or S−).
    pub fn sliding(&self) -> Vec<(Point, ContactKind)> {
        self.pattern
            .iter()
            .filter(|c| !c.kind.is_hinge())
            .map(|c| (polar(1.0, c.beta), c.kind))
            .collect()
    }
}
