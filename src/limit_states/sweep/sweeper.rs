//! The sweep's state: the planes of P(t), the vertices alive with their deaths, what was
//! found so far; and the one activity test every step uses.

use super::found::{CheckedPoint, LimitState};
use super::geometry::{Plane, Vertex, BOX};
use crate::arch::Arch;
use crate::contact::ContactKind;
use crate::load::LiveLoad;
use crate::settings::Settings;
use crate::statics::{magnitude, reaction_scale, Reactions};
use crate::undecided::Undecided;

/// What the sweep's parameter t is.
#[derive(Debug, Clone, Copy)]
pub(super) enum Param<'a> {
    /// t = η: the thickness problem (self-weight only).
    Thickness,
    /// t = λ: the multiplier of a live load at fixed η.
    Multiplier { eta: f64, load: &'a LiveLoad },
}

pub(super) struct Sweeper<'a> {
    pub(super) arch: &'a Arch,
    pub(super) mu: f64,
    pub(super) param: Param<'a>,
    /// The end of the sweep: η's thickness limit, or λ_static.
    pub(super) top: f64,
    pub(super) planes: Vec<Plane>,
    /// The most coefficients of any plane's constant term and of any gradient component
    /// (the slots of a vertex's screen), when the planes are many enough to screen.
    pub(super) screen_slots: Option<(usize, usize)>,
    /// Where there is a screen, every plane's coefficients in its slots
    /// ([`super::geometry::slot_layout`]).
    pub(super) screen_coeffs: Vec<f64>,
    pub(super) settings: &'a Settings,
    /// The vertices alive, each with its death (the parameter and the plane that crosses
    /// it), `None` when it survives to the top.
    pub(super) alive: Vec<(Vertex, Option<(f64, usize)>)>,
    pub(super) states: Vec<LimitState>,
    pub(super) no_mechanism: Vec<CheckedPoint>,
    /// The first kinematic LP that the back end could not decide: the sweep then decides
    /// nothing (an undecided point is neither a limit state nor "no mechanism").
    pub(super) lp_failure: Option<Undecided>,
}

/// Below this many planes a vertex's death tests each plane on its own: building the
/// screen costs about as much as testing some dozens of planes.
const SCREEN_MIN_PLANES: usize = 200;

/// The screen is used only where its products per plane (Bernstein coefficients × slots,
/// at most) are at most this: beyond, a plane's own crossing polynomial is as cheap to
/// bound. Measured (callgrind, whole commands, the same output either way): the load
/// sweeps (work 10) cost 12–24 % less with the screen; the sweeps in η of the true
/// centroid (work 54: a constant term quadratic, gradients affine) 11–12 % more, with
/// fill (130) more still.
const SCREEN_MAX_WORK: usize = 30;

impl<'a> Sweeper<'a> {
    /// A sweep over `planes` up to `top`, with nothing alive or found yet.
    pub(super) fn new(
        arch: &'a Arch,
        mu: f64,
        param: Param<'a>,
        top: f64,
        planes: Vec<Plane>,
        settings: &'a Settings,
    ) -> Sweeper<'a> {
        let (c_len, g_len) = planes.iter().fold((0, 0), |(c, g), p| {
            let gl = p.g.iter().map(|q| q.coeffs().len()).max().unwrap_or(0);
            (c.max(p.c.coeffs().len()), g.max(gl))
        });
        // a vertex's det has degree ≤ 3 (g_len − 1), its numerators ≤ 2 (g_len − 1) +
        // c_len − 1: the crossing polynomials' coefficients are at most c_len + 3 g_len − 3
        let slots = c_len + 3 * g_len;
        let work = slots * (slots.saturating_sub(3)).max(1);
        let screen_slots = (planes.len() >= SCREEN_MIN_PLANES && work <= SCREEN_MAX_WORK)
            .then_some((c_len, g_len));
        let screen_coeffs = screen_slots.map_or_else(Vec::new, |(c, g)| {
            super::geometry::slot_layout(&planes, c, g)
        });
        Sweeper {
            arch,
            mu,
            param,
            top,
            planes,
            screen_slots,
            screen_coeffs,
            settings,
            alive: Vec::new(),
            states: Vec::new(),
            no_mechanism: Vec::new(),
            lp_failure: None,
        }
    }
}

impl Sweeper<'_> {
    /// `event_tol` in units of the state's size (1 + ‖x‖₁): a point lies on a plane, or
    /// inside it, to this.
    pub(super) fn tol(&self, x: &Reactions) -> f64 {
        self.settings.event_tol * reaction_scale(x)
    }

    /// Planes active at (x, η): |φ| within `event_tol` of the plane's own magnitude
    /// ([`magnitude`]: shallow arches have φ of order η).
    pub(super) fn active(&self, x: &Reactions, eta: f64) -> Vec<usize> {
        self.active_among(x, eta, 0..self.planes.len())
    }

    /// The thickness of the planes' magnitudes at sweep parameter `eta`.
    fn thickness(&self, eta: f64) -> f64 {
        match self.param {
            Param::Thickness => eta,
            Param::Multiplier { eta, .. } => eta,
        }
    }

    /// The largest tolerance [`Sweeper::active`] gives a contact plane at (x, η) (the box's
    /// planes have their own, larger one).
    pub(super) fn contact_tol(&self, x: &Reactions, eta: f64) -> f64 {
        let floor = self.settings.magnitude_floor;
        let t = self.thickness(eta);
        self.settings.event_tol
            * [ContactKind::HingeIntrados, ContactKind::SlidePlus]
                .map(|k| magnitude(k, t, self.mu, x, floor))
                .into_iter()
                .fold(0.0, f64::max)
    }

    /// [`Sweeper::active`] among the planes `candidates` (ascending): the caller knows the
    /// others are not active.
    pub(super) fn active_among(
        &self,
        x: &Reactions,
        eta: f64,
        candidates: impl IntoIterator<Item = usize>,
    ) -> Vec<usize> {
        let thickness = self.thickness(eta);
        candidates
            .into_iter()
            .filter(|&i| {
                let p = &self.planes[i];
                let size = match p.contact {
                    Some(c) => {
                        magnitude(c.kind, thickness, self.mu, x, self.settings.magnitude_floor)
                    }
                    None => BOX,
                };
                p.value(x, eta).abs() <= self.settings.event_tol * size
            })
            .collect()
    }
}
