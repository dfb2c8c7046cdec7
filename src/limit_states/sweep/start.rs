//! Where a sweep starts: the vertices of P(t) just after the least admissible state (read
//! off the linearisation there), or, where that state is degenerate or P has an interior
//! at the start, every vertex by a walk from a point inside; and, where the least state is
//! unbounded, the least t at which P(t) meets the box.

use super::geometry::{BOX, BOX_EDGE_REL};
use super::sweeper::Sweeper;
use crate::admissibility::{margin_over_arch, Goal, WorkingSet};
use crate::arch::ETA_TOP;
use crate::contact::ContactKind;
use crate::lp;
use crate::statics::{Affine, Reactions};
use crate::undecided::Undecided;

/// The least η at which P(η) meets the box is bisected to this width (relative): the
/// resolution of η.
const BOX_BISECTION_REL: f64 = 1e-15;

impl Sweeper<'_> {
    /// Starts the thickness sweep from the least admissible state (η_s, x_s): every vertex
    /// of P(η) just above it. `Ok(false)`: no state inside the box below the thickness
    /// limit, so no limit state and nothing to sweep; `Err`: why the sweep cannot start.
    pub(super) fn start_at_least(&mut self, eta_s: f64, x_s: Reactions) -> Result<bool, Undecided> {
        let (arch, mu, settings) = (self.arch, self.mu, self.settings);
        // the start: the least admissible state, or, where that state is unbounded (η_s an
        // infimum, approached only as the reactions grow without bound), the least point of
        // P(η) inside the box — below it P(η) lies wholly outside the box, where no state is
        // a limit state, and from it on every vertex of P(η) ∩ box is followed
        // (a bounded least state on or outside the box — possible only with
        // `unbounded_reactions` raised beyond 1e7 / (1 + span) — starts the same way)
        let bounded_start = x_s.iter().all(|v| {
            v.abs() <= settings.unbounded_reactions * (1.0 + arch.span())
                && v.abs() < BOX * (1.0 - BOX_EDGE_REL)
        });
        let (eta_s, x_s) = if bounded_start {
            (eta_s, x_s)
        } else {
            match self.least_in_box(eta_s)? {
                Some(start) => start,
                // no state inside the box below the thickness limit: no limit state
                None => return Ok(false),
            }
        };
        let act = self.active(&x_s, eta_s);
        for v in self.vertices_after(&x_s, eta_s, &act) {
            self.push(v, eta_s);
        }
        if self.alive.is_empty() {
            // a degenerate least state: walk the vertex graph just above η_s instead (limit
            // states in (η_s, η₀] would be missed)
            let eta0 = if eta_s > 0.0 {
                eta_s * (1.0 + settings.sweep_walk_offset)
            } else {
                settings.sweep_min_eta
            };
            // start from the state of largest margin at η₀ (inside P(η₀))
            let centre = if bounded_start {
                let mut ws = WorkingSet::initial(arch);
                margin_over_arch(
                    arch,
                    eta0,
                    mu,
                    ContactKind::active_at(mu),
                    &mut ws,
                    Goal::Optimise,
                    settings,
                )
                .map_or(x_s, |m| m.x)
            } else {
                self.in_box(eta0).map_or(x_s, |(_, x)| x)
            };
            self.start_by_walk(eta0, centre);
        }
        if self.alive.is_empty() {
            return Err(Undecided::Resolution(format!(
                "no vertex of the admissible set found just above eta_s = {eta_s} ({} contacts active there)",
                act.len()
            )));
        }
        Ok(true)
    }

    /// Starts the load sweep from the least admissible multiplier λ_min (a state `x_min`
    /// there): every vertex of P(λ) just above it. `Err`: why the sweep cannot start.
    pub(super) fn start_at_least_load(
        &mut self,
        (lambda_min, x_min): (f64, Reactions),
    ) -> Result<(), Undecided> {
        let (settings, lambda_static) = (self.settings, self.top);
        if x_min.iter().any(|v| v.abs() >= BOX * (1.0 - BOX_EDGE_REL)) {
            return Err(Undecided::Resolution(format!(
                "the least admissible state at lambda = {lambda_min} lies outside the box |x| <= {BOX:e}"
            )));
        }
        // λ_min > 0: P(λ_min) is (generically) the point x_min, and the vertices just after
        // it come from the linearisation there; λ_min = 0: P(0) is the admissible set of the
        // unloaded arch, in general with an interior, and every one of its vertices starts
        if lambda_min > 0.0 {
            let act = self.active(&x_min, lambda_min);
            for v in self.vertices_after(&x_min, lambda_min, &act) {
                self.push(v, lambda_min);
            }
        }
        if self.alive.is_empty() {
            // an interior (or a degenerate least state): every vertex, by a walk from the
            // most interior point
            let t0 = if lambda_min == 0.0 {
                0.0
            } else {
                lambda_min
                    + settings.sweep_walk_offset
                        * (lambda_static - lambda_min).min(1.0 + lambda_min)
            };
            let rows: Vec<Affine> = self.planes.iter().map(|p| p.affine(t0)).collect();
            let centre = lp::max_margin(&rows, 1.0, settings).map_or(x_min, |m| m.0);
            self.start_by_walk(t0, centre);
        }
        if self.alive.is_empty() {
            return Err(Undecided::Resolution(format!(
                "no vertex of the admissible set found at lambda = {lambda_min}"
            )));
        }
        Ok(())
    }

    /// Whether P(η) meets the box, and its point of greatest margin there: the margin LP
    /// over every plane (box sides included) in units of the box, x = BOX·u, so that the
    /// rows keep unit gradients and the dense solver's own bounds never bind.
    fn in_box(&self, eta: f64) -> Option<(bool, Reactions)> {
        let rows: Vec<Affine> = self
            .planes
            .iter()
            .map(|p| {
                let a = p.affine(eta);
                Affine {
                    g: a.g.map(|v| v * BOX),
                    c: a.c,
                }
            })
            .collect();
        let (u, s) = lp::max_margin(&rows, 1.0, self.settings).ok()?;
        Some((s >= 0.0, u.map(|v| v * BOX)))
    }

    /// The least η above `eta_lo` (where P(η) lies outside the box) at which P(η) meets the
    /// box, and a point of P(η) ∩ box there, to the resolution of η (bisection on
    /// [`Self::in_box`] to [`BOX_BISECTION_REL`]): the sweep's start when the least
    /// admissible state is unbounded. `Ok(None)` when P(η) misses the box up to the
    /// thickness limit.
    fn least_in_box(&self, eta_lo: f64) -> Result<Option<(f64, Reactions)>, Undecided> {
        let failed = || {
            Undecided::Lp(format!(
                "the margin LP inside the box failed above eta_s = {eta_lo}"
            ))
        };
        let (ok, mut x) = self.in_box(ETA_TOP).ok_or_else(failed)?;
        if !ok {
            return Ok(None);
        }
        let (mut lo, mut hi) = (eta_lo, ETA_TOP);
        while hi - lo > BOX_BISECTION_REL * hi {
            let m = 0.5 * (lo + hi);
            if m <= lo || m >= hi {
                break;
            }
            let (ok, xm) = self.in_box(m).ok_or_else(failed)?;
            if ok {
                (hi, x) = (m, xm);
            } else {
                lo = m;
            }
        }
        Ok(Some((hi, x)))
    }
}
