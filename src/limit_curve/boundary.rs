//! Sampling the static boundary η_s(μ) and locating the pattern change between two samples
//! whose patterns differ: the thickness problem's part of the [`crate::tracer`]. A change
//! is located as a corner (Newton on the union of both patterns with μ unknown), a smooth
//! change ([`super::transition`]) or an onset along a branch ([`super::onset`]); when none
//! converges the tracer bisects in μ. Each located change is checked against the boundary
//! itself (η equals η_s at its μ) and classified by the one-sided slopes of η_s(μ) there.

use super::transition::Located;
use super::{onset, transition};
use crate::arch::{Arch, InputError};
use crate::collapse_mode::{classify, CollapseMode};
use crate::contact::ContactKind;
use crate::contact::{Contact, Location};
use crate::limit::{solve_continued, solve_near, LeastLimitState, Outcome, Solution};
use crate::refine::{solve_system, Unknowns};
use crate::search::RootGuess;
use crate::settings::Settings;
use crate::state::State;
use crate::statics::Reactions;
use crate::tracer::{self, Split};
use std::cmp::Ordering;
use std::convert::Infallible;

/// A point of the static boundary η_s(μ) where the active pattern changes (`t` is η): a
/// corner (`detail.kink`: the one-sided slopes differ) or a smooth transition (they agree).
pub type Corner = tracer::Corner<Side, Contact, Shape>;

/// The boundary on one side of a [`Corner`].
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Side {
    /// The mode of the branch on this side.
    pub mode: CollapseMode,
    /// dη_s/dμ on this side (−∞ on the lower side at the vertical purely-sliding branch;
    /// NaN where not defined, at μ = ∞).
    pub slope: f64,
}

/// What a [`Corner`] of the static boundary is besides its place.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Shape {
    /// Whether η_s(μ) has a kink here (the one-sided slopes differ by more than
    /// `settings.kink_slope_rel` of their size).
    pub kink: bool,
    /// The mode named from the corner's own active pattern (e.g.
    /// `rotational_sliding_shoulders` where a springing hinges and slides at once).
    pub mode: CollapseMode,
}

impl Corner {
    /// The modes of the branches it joins: [higher μ, lower μ].
    pub fn between(&self) -> [CollapseMode; 2] {
        [self.sides[1].mode, self.sides[0].mode]
    }
}

/// The change at `at` between the branches of modes `between` = [higher μ, lower μ], with
/// the one-sided slopes `[lower, upper]`.
pub(super) fn corner(
    at: Located,
    exact: bool,
    slopes: [f64; 2],
    between: [CollapseMode; 2],
    shape: Shape,
) -> Corner {
    Corner {
        mu: at.mu,
        t: at.eta,
        x: at.x,
        pattern: at.pattern,
        exact,
        residual: at.residual,
        sides: [
            Side {
                mode: between[1],
                slope: slopes[0],
            },
            Side {
                mode: between[0],
                slope: slopes[1],
            },
        ],
        detail: shape,
    }
}

impl Located {
    /// The state of the boundary sample `s` (its η, reactions and pattern) placed at `mu`.
    pub(super) fn at(mu: f64, s: &Sample, residual: f64) -> Located {
        Located {
            mu,
            eta: s.eta,
            x: s.x,
            pattern: s.pattern.clone(),
            residual,
        }
    }
}

/// The end of the static boundary at the thickness limit (see
/// [`super::LimitCurve::thickness_limit`]).
#[derive(Debug, Clone)]
pub struct ThicknessLimit {
    /// Friction coefficient where η_s reaches the limit.
    pub mu: f64,
    /// η there (`ETA_TOP`, just below 2).
    pub eta: f64,
    /// The lowest branch's pattern there.
    pub pattern: Vec<Contact>,
    /// True when located along the branch by root finding (to adjacent floats in μ);
    /// false when bracketed by bisection on the solver's status.
    pub exact: bool,
}

/// What identifies a pattern along the limit curve: each contact's kind and place, and,
/// on a discrete arch, its joint (a hinge moving to another joint changes the pattern;
/// on a continuous arch contacts move with μ and only their kinds and places count).
pub(super) type Signature = Vec<(ContactKind, Location, Option<u64>)>;

pub(super) fn signature(arch: &Arch, p: &[Contact]) -> Signature {
    let discrete = matches!(arch.layout(), crate::arch::JointLayout::Discrete(_));
    p.iter()
        .map(|c| (c.kind, c.at, discrete.then(|| c.beta.to_bits())))
        .collect()
}

/// Each contact's kind and place (for counting contacts of a kind).
fn kinds(p: &[Contact]) -> Vec<(ContactKind, Location)> {
    p.iter().map(|c| (c.kind, c.at)).collect()
}

/// One point of the static boundary: the least admissible state at μ.
#[derive(Debug, Clone)]
pub(super) struct Sample {
    pub(super) mu: f64,
    /// η_s(μ).
    pub(super) eta: f64,
    /// The least admissible state.
    pub(super) x: Reactions,
    /// Every contact active there, by increasing β.
    pub(super) pattern: Vec<Contact>,
    pub(super) sig: Signature,
    /// The solver's answer at μ (the limit-state search starts from it).
    pub(super) solution: crate::limit::Solution,
}

pub(super) struct Tracer<'a> {
    pub(super) arch: &'a Arch,
    pub(super) settings: &'a Settings,
    pub(super) solves: usize,
    pub(super) unresolved: Vec<(f64, String)>,
    pub(super) no_collapse: Vec<f64>,
    pub(super) no_equilibrium: Vec<f64>,
    /// The least limit state of the last solve that found one: the next solve near a guess
    /// starts from its pattern ([`crate::limit::solve_continued`]).
    last: Option<LeastLimitState>,
}

impl<'a> Tracer<'a> {
    /// A tracer that has solved nothing yet.
    pub(super) fn new(arch: &'a Arch, settings: &'a Settings) -> Tracer<'a> {
        Tracer {
            arch,
            settings,
            solves: 0,
            unresolved: Vec::new(),
            no_collapse: Vec::new(),
            no_equilibrium: Vec::new(),
            last: None,
        }
    }

    /// Takes over what another tracer (of the same arch, run on another thread) counted and
    /// recorded, after what this one recorded.
    pub(super) fn absorb(&mut self, other: Tracer) {
        self.solves += other.solves;
        self.unresolved.extend(other.unresolved);
        self.no_collapse.extend(other.no_collapse);
        self.no_equilibrium.extend(other.no_equilibrium);
    }
    /// The solution at μ near `guess`, continued from the last least limit state found
    /// when there is a guess (the same answer, fewer margin LPs where the pattern holds).
    fn solve(&mut self, mu: f64, guess: Option<RootGuess>) -> Result<Solution, InputError> {
        self.solves += 1;
        let solved = match (guess, &self.last) {
            (Some(g), Some(p)) => solve_continued(self.arch, mu, g, p, self.settings),
            _ => solve_near(self.arch, mu, guess, self.settings),
        };
        if let Ok(Solution {
            outcome: Outcome::Limit(ls),
            ..
        }) = &solved
        {
            self.last = Some(ls.clone());
        }
        solved
    }

    /// The boundary at μ, without recording anything.
    fn boundary(&mut self, mu: f64, guess: Option<RootGuess>) -> Result<Sample, Box<Outcome>> {
        let solution = match self.solve(mu, guess) {
            Ok(s) => s,
            Err(e) => {
                return Err(Box::new(Outcome::Unresolved {
                    eta_lo: 0.0,
                    eta_hi: 2.0,
                    reason: e.to_string(),
                    least_static: None,
                }))
            }
        };
        let (eta, x) = match &solution.outcome {
            Outcome::Limit(ls) => (ls.eta_static, ls.x_static),
            Outcome::Unresolved {
                least_static: Some((eta, x)),
                ..
            } => (*eta, *x),
            other => return Err(Box::new(other.clone())),
        };
        let pattern = self.sample_pattern(mu, eta, x);
        Ok(Sample {
            mu,
            eta,
            x,
            sig: signature(self.arch, &pattern),
            pattern,
            solution,
        })
    }

    /// The contacts active at (x, η, μ) (the scan's).
    fn active(&self, mu: f64, eta: f64, x: Reactions) -> Vec<Contact> {
        let st = State {
            arch: self.arch,
            eta,
            mu,
            x,
        };
        st.verdict(ContactKind::active_at(mu), self.settings).active
    }

    /// The pattern of a boundary sample: the scan's active contacts, plus any active
    /// maximum of the same kind that the scan's grid did not separate from one of them (two
    /// tangencies closer than a grid cell, as where two hinges approach each other before
    /// they merge): each active interior contact's neighbourhood of ±2 cells is searched on
    /// a grid 100 times finer, maxima bracketed by sign changes of dφ/dβ and bisected to
    /// the resolution of β; maxima closer than two fine cells to a known one are the same.
    fn sample_pattern(&self, mu: f64, eta: f64, x: Reactions) -> Vec<Contact> {
        let st = State {
            arch: self.arch,
            eta,
            mu,
            x,
        };
        let mut active = st.verdict(ContactKind::active_at(mu), self.settings).active;
        if !matches!(self.arch.layout(), crate::arch::JointLayout::Continuous) {
            return active;
        }
        let (lo, hi) = (self.arch.beta_right(), self.arch.beta_left());
        let cell = (hi - lo) / self.settings.scan_points as f64;
        let mut extra = Vec::new();
        for c in active.iter().filter(|c| c.at == Location::Interior) {
            let scale =
                crate::statics::magnitude(c.kind, eta, mu, &x, self.settings.magnitude_floor);
            let (a, b) = ((c.beta - 2.0 * cell).max(lo), (c.beta + 2.0 * cell).min(hi));
            let n = 400;
            let d1 = |beta: f64| st.phi(c.kind, beta)[1];
            let grid: Vec<f64> = (0..=n).map(|i| a + (b - a) * i as f64 / n as f64).collect();
            let slopes: Vec<f64> = grid.iter().map(|&beta| d1(beta)).collect();
            for (w, s) in grid.windows(2).zip(slopes.windows(2)) {
                let (mut l, mut r) = (w[0], w[1]);
                if !(s[0] > 0.0 && s[1] <= 0.0) {
                    continue;
                }
                for _ in 0..60 {
                    let m = 0.5 * (l + r);
                    if m <= l || m >= r {
                        break; // adjacent floats: further halvings change nothing
                    }
                    if d1(m) > 0.0 {
                        l = m;
                    } else {
                        r = m;
                    }
                }
                let beta = 0.5 * (l + r);
                let known = active.iter().chain(&extra).any(|d: &Contact| {
                    d.kind == c.kind && (d.beta - beta).abs() < 2.0 * (b - a) / n as f64
                });
                if !known && st.phi(c.kind, beta)[0] >= -10.0 * self.settings.adm_tol * scale {
                    extra.push(Contact { beta, ..*c });
                }
            }
        }
        active.extend(extra);
        active.sort_by(|a, b| a.beta.total_cmp(&b.beta).then(a.kind.cmp(&b.kind)));
        active
    }

    /// The boundary at μ, η_s expected near `guess` (the bracket starts there); what is
    /// not a boundary point is recorded by kind.
    pub(super) fn sample_near(&mut self, mu: f64, guess: Option<RootGuess>) -> Option<Sample> {
        match self.boundary(mu, guess).map_err(|e| *e) {
            Ok(s) => Some(s),
            Err(Outcome::NoCollapse { .. }) => {
                self.no_collapse.push(mu);
                None
            }
            Err(Outcome::NoEquilibrium { .. }) => {
                self.no_equilibrium.push(mu);
                None
            }
            Err(Outcome::Unresolved { reason, .. }) => {
                self.unresolved.push((mu, reason));
                None
            }
            Err(Outcome::Limit(_)) => None,
        }
    }

    pub(super) fn mode_of(&self, p: &[Contact]) -> CollapseMode {
        classify(
            p,
            0.5 * (self.arch.beta_right() + self.arch.beta_left()),
            self.settings.same_joint,
        )
    }

    /// η_s at μ (expected near `guess`), or NaN: the boundary's η without its pattern.
    fn eta_s(&mut self, mu: f64, guess: RootGuess) -> f64 {
        self.solves += 1;
        match solve_near(self.arch, mu, Some(guess), self.settings).map(|s| s.outcome) {
            Ok(Outcome::Limit(ls)) => ls.eta_static,
            Ok(Outcome::Unresolved {
                least_static: Some((eta, _)),
                ..
            }) => eta,
            _ => f64::NAN,
        }
    }

    /// The one-sided slope dη_s/dμ at (μ, η) on the side `side` (+1: larger μ, −1:
    /// smaller μ), from η_s at μ(1 + side·δ) and μ(1 + 2 side·δ) (second order,
    /// δ = `settings.slope_step`), and η_s extrapolated from that side to μ itself
    /// (2η₁ − η₂, also second order). NaN when either solve fails.
    pub(super) fn slope(&mut self, mu: f64, eta: f64, side: f64) -> (f64, f64) {
        let d = self.settings.slope_step;
        // η_s moves by about (μ/η dη/dμ) · δ: guesses within 4δ, widened if steeper
        let rel = 4.0 * d;
        let e1 = self.eta_s(mu * (1.0 + side * d), RootGuess { eta, rel });
        let e2 = self.eta_s(
            mu * (1.0 + 2.0 * side * d),
            RootGuess {
                eta: if e1.is_finite() { 2.0 * e1 - eta } else { eta },
                rel,
            },
        );
        (
            (4.0 * (e1 - eta) - (e2 - eta)) / (2.0 * side * d * mu),
            2.0 * e1 - e2,
        )
    }

    /// Whether two one-sided slopes differ: a kink (NaN slopes count as a kink, since
    /// no smoothness was shown).
    pub(super) fn is_kink(&self, lower: f64, upper: f64, eta: f64, mu: f64) -> bool {
        let scale = lower.abs().max(upper.abs()).max(eta / mu);
        let close = (lower - upper)
            .abs()
            .partial_cmp(&(self.settings.kink_slope_rel * scale));
        !matches!(close, Some(Ordering::Less | Ordering::Equal))
    }

    /// A located change (its state and the pattern it was solved on, refined), checked:
    /// μ within the samples' range, the state admissible, and
    /// η equal (to `settings.boundary_match`) to η_s extrapolated to μ from each side
    /// (from the right only at μ_ms, `at_mu_ms`, where the left is the vertical branch);
    /// then classified by the slopes on both sides.
    fn accept(
        &mut self,
        mut at: Located,
        range: (f64, f64),
        between: [CollapseMode; 2],
        at_mu_ms: bool,
    ) -> Option<Corner> {
        let (mu, eta) = (at.mu, at.eta);
        let tol = self.settings.root_slack;
        if !(mu >= range.0 * (1.0 - tol) && mu <= range.1 * (1.0 + tol)) {
            return None;
        }
        let st = State {
            arch: self.arch,
            eta,
            mu,
            x: at.x,
        };
        let verdict = st.verdict(ContactKind::active_at(mu), self.settings);
        if verdict.worst > self.settings.adm_tol {
            return None;
        }
        let (upper, from_right) = self.slope(mu, eta, 1.0);
        let (lower, from_left) = if at_mu_ms {
            (f64::NEG_INFINITY, eta)
        } else {
            self.slope(mu, eta, -1.0)
        };
        let off = |e: f64| {
            let d = (e - eta)
                .abs()
                .partial_cmp(&(self.settings.boundary_match * eta));
            !matches!(d, Some(Ordering::Less | Ordering::Equal))
        };
        if off(from_right) || off(from_left) {
            return None;
        }
        at.pattern
            .sort_by(|a, b| a.beta.total_cmp(&b.beta).then(a.kind.cmp(&b.kind)));
        let shape = Shape {
            kink: self.is_kink(lower, upper, eta, mu),
            mode: self.mode_of(&at.pattern),
        };
        Some(corner(at, true, [lower, upper], between, shape))
    }

    /// Newton on the union of two patterns with η and μ unknown, from the state
    /// (x, η, μ), accepted only when the state's active set covers both patterns (as many
    /// active contacts of each kind and place as either pattern has: where two tangencies
    /// of one kind merge, the union converges to a point that is on neither side's
    /// pattern, and the change is a smooth one, [`transition`]).
    pub(super) fn union_newton(
        &mut self,
        upper: &[Contact],
        lower: &[Contact],
        start: (Reactions, f64, f64),
        range: (f64, f64),
        between: [CollapseMode; 2],
        at_mu_ms: bool,
    ) -> Option<Corner> {
        let mut union: Vec<Contact> = lower.to_vec();
        for c in upper {
            let dup = union.iter().any(|d| {
                d.kind == c.kind
                    && d.at == c.at
                    && (d.beta - c.beta).abs() < self.settings.track_angle
            });
            if !dup {
                union.push(*c);
            }
        }
        // a determined system: |U| + free rows for 5 + free unknowns (x, η, μ, angles)
        if union.len() < 5 {
            return None;
        }
        let from = State {
            arch: self.arch,
            eta: start.1,
            mu: start.2,
            x: start.0,
        };
        let r = solve_system(&from, &union, Unknowns::TMu, self.settings).ok()?;
        // the union must determine the point: a rank-deficient Jacobian (e.g. a mirror
        // pair of contacts on a symmetric arch duplicating rows) leaves a curve of
        // solutions along one branch, and Newton stops anywhere on it
        if !self.determined(&r.contacts, &r) {
            return None;
        }
        let active = kinds(&self.active(r.mu, r.t, r.x));
        let count = |s: &[(ContactKind, Location)], k: &(ContactKind, Location)| {
            s.iter().filter(|c| *c == k).count()
        };
        let covers = |p: &[Contact]| {
            let sig = kinds(p);
            sig.iter().all(|k| count(&active, k) >= count(&sig, k))
        };
        if !(covers(upper) && covers(lower)) {
            return None;
        }
        let at = Located {
            mu: r.mu,
            eta: r.t,
            x: r.x,
            pattern: r.contacts,
            residual: r.residual,
        };
        self.accept(at, range, between, at_mu_ms)
    }

    /// A smooth change between `a` and `b` ([`transition`]), tried from each side.
    fn smooth(&mut self, a: &Sample, b: &Sample, between: [CollapseMode; 2]) -> Option<Corner> {
        let range = (b.mu, a.mu);
        for (on_b, extra) in transition::candidates(&a.pattern, &b.pattern) {
            let s = if on_b { b } else { a };
            let Some(l) = transition::locate(
                self.arch,
                &s.pattern,
                extra,
                (s.x, s.eta, s.mu),
                self.settings,
            ) else {
                continue;
            };
            if let Some(c) = self.accept(l, range, between, false) {
                return Some(c);
            }
        }
        None
    }

    /// Whether the corner system of `contacts` (unknowns x, η, μ, free angles) has full
    /// column rank at the solution `r` (relative singular value above `rank_tol` after
    /// column equilibration).
    fn determined(&self, contacts: &[Contact], r: &crate::refine::Refined) -> bool {
        let mut z: Vec<f64> = r.x.to_vec();
        z.extend([r.t, r.mu]);
        z.extend(contacts.iter().filter(|c| c.free).map(|c| c.beta));
        let Some((_, rows)) =
            crate::refine::residual_and_jacobian(self.arch, contacts, r.t, r.mu, Unknowns::TMu, &z)
        else {
            return false;
        };
        let mut m = nalgebra::DMatrix::from_fn(rows.len(), z.len(), |i, j| rows[i][j]);
        if m.nrows() < m.ncols() {
            return false;
        }
        for j in 0..m.ncols() {
            let n = m.column(j).norm();
            if n > 0.0 {
                m.column_mut(j).scale_mut(1.0 / n);
            }
        }
        let sv = m.singular_values();
        sv.min() > self.settings.rank_tol * sv.max()
    }

    /// A contact of one sample's pattern joining the other's branch ([`onset`]): along
    /// `a`'s branch down to `b.mu`, and along `b`'s up to `a.mu`; the first onset met
    /// from each side is tried.
    fn onset(&mut self, a: &Sample, b: &Sample, between: [CollapseMode; 2]) -> Option<Corner> {
        let range = (b.mu, a.mu);
        let track = self.settings.track_angle;
        let new_in = |p: &[Contact], q: &[Contact]| -> Vec<Contact> {
            q.iter()
                .filter(|c| {
                    !p.iter().any(|d| {
                        d.kind == c.kind && d.at == c.at && (d.beta - c.beta).abs() < track
                    })
                })
                .copied()
                .collect()
        };
        for (from, to) in [(a, b), (b, a)] {
            let mut found: Vec<Located> = new_in(&from.pattern, &to.pattern)
                .iter()
                .filter_map(|c| {
                    onset::locate(
                        self.arch,
                        &from.pattern,
                        c,
                        (from.x, from.eta, from.mu),
                        to.mu,
                        self.settings,
                    )
                })
                .collect();
            // the first onset met when leaving `from`
            found.sort_by(|p, q| (p.mu - from.mu).abs().total_cmp(&(q.mu - from.mu).abs()));
            if let Some(o) = found.into_iter().next() {
                if let Some(c) = self.accept(o, range, between, false) {
                    return Some(c);
                }
            }
        }
        None
    }

    /// The corner with the vertical purely-sliding branch reached along the branch of the
    /// lowest sample `low`: its pattern followed to μ = μ_ms (Newton with η unknown), where
    /// the friction-limiting contacts become active too. Used when the union of the two
    /// patterns is not a determined system (a three-contact KKT branch, or a sliding
    /// contact that moves between the sample and μ_ms).
    pub(super) fn follow_to_mu_ms(
        &mut self,
        low: &Sample,
        mu_ms: f64,
        between: [CollapseMode; 2],
    ) -> Option<Corner> {
        let start = State {
            arch: self.arch,
            eta: low.eta,
            mu: mu_ms,
            x: low.x,
        };
        let r = solve_system(&start, &low.pattern, Unknowns::T, self.settings).ok()?;
        let at = Located {
            mu: mu_ms,
            eta: r.t,
            x: r.x,
            pattern: self.active(mu_ms, r.t, r.x),
            residual: r.residual,
        };
        let range = (mu_ms * (1.0 - self.settings.root_slack), low.mu);
        self.accept(at, range, between, true)
    }

    /// The thickness limit bracketed by bisection in μ between `ne` (no equilibrium) and
    /// the sample `low` (a boundary point), when it cannot be reached along the branch.
    pub(super) fn thickness_limit_by_bisection(&mut self, ne: f64, low: &Sample) -> ThicknessLimit {
        let (mut lo, mut hi) = (ne, low.mu);
        let mut pattern = low.pattern.clone();
        for _ in 0..60 {
            if hi - lo <= self.settings.same_root * hi {
                break;
            }
            let m = 0.5 * (lo + hi);
            match self.boundary(m, None) {
                Ok(s) => {
                    hi = m;
                    pattern = s.pattern;
                }
                Err(_) => lo = m,
            }
        }
        ThicknessLimit {
            mu: hi,
            eta: crate::arch::ETA_TOP,
            pattern,
            exact: false,
        }
    }

    /// The pattern changes between samples `a` (higher μ) and `b` (lower μ) with
    /// different patterns ([`tracer::locate`]).
    pub(super) fn locate(&mut self, a: &Sample, b: &Sample, depth: usize) -> Vec<Corner> {
        tracer::locate(self, a, b, depth).unwrap_or_else(|e| match e {})
    }
}

/// The thickness problem's part of the tracer: samples by decreasing μ (`a` the higher),
/// keyed by their pattern's signature; a change located as a corner, a smooth change or an
/// onset; the bracket halved geometrically for at most `depth` levels.
impl tracer::Problem for Tracer<'_> {
    type Sample = Sample;
    type Key = Signature;
    type Corner = Corner;
    type Error = Infallible;

    fn key(&self, s: &Sample) -> Signature {
        s.sig.clone()
    }

    fn split(&mut self, a: &Sample, b: &Sample, depth: usize) -> Split {
        if depth == 0 || a.mu / b.mu < 1.0 + self.settings.same_root {
            return Split::Stop { tight: false };
        }
        Split::At((a.mu * b.mu).sqrt())
    }

    fn sample(&mut self, mu: f64, a: &Sample, b: &Sample) -> Result<Option<Sample>, Infallible> {
        Ok(self.sample_near(mu, Some(between(a.eta, b.eta))))
    }

    fn exact(&mut self, a: &Sample, b: &Sample) -> Option<Corner> {
        let between = [self.mode_of(&a.pattern), self.mode_of(&b.pattern)];
        let range = (b.mu, a.mu);
        for start in [b, a] {
            let from = (start.x, start.eta, start.mu);
            if let Some(c) = self.union_newton(&a.pattern, &b.pattern, from, range, between, false)
            {
                return Some(c);
            }
        }
        self.smooth(a, b, between)
            .or_else(|| self.onset(a, b, between))
    }

    /// A change known only to lie between samples `a` and `b` (`exact: false`); its
    /// slopes are the boundary's on either side of the bracket.
    fn bracketed(&mut self, a: &Sample, b: &Sample, _: bool) -> Corner {
        let between = [self.mode_of(&a.pattern), self.mode_of(&b.pattern)];
        let (lower, upper) = (
            self.slope(b.mu, b.eta, -1.0).0,
            self.slope(a.mu, a.eta, 1.0).0,
        );
        let at = Located {
            eta: 0.5 * (a.eta + b.eta),
            ..Located::at((a.mu * b.mu).sqrt(), b, f64::NAN)
        };
        let shape = Shape {
            kink: self.is_kink(lower, upper, at.eta, at.mu),
            mode: between[1],
        };
        corner(at, false, [lower, upper], between, shape)
    }

    /// After an exact change: the boundary beside it (10⁻³ of μ away: nearer, a contact
    /// joining with a zero multiplier is within the activity tolerance), for other changes
    /// before a sample.
    fn beside(
        &mut self,
        a: &Sample,
        b: &Sample,
        found: &[Corner],
        depth: usize,
    ) -> Result<Vec<Corner>, Infallible> {
        let mut out = Vec::new();
        let Some(c) = found.last().filter(|c| c.exact && depth > 0) else {
            return Ok(out);
        };
        let step = 1e3 * self.settings.slope_step;
        let beside = RootGuess {
            eta: c.t,
            rel: 4.0 * step,
        };
        if c.mu < a.mu * (1.0 - 2.0 * step) {
            if let Some(m) = self.sample_near(c.mu * (1.0 + step), Some(beside)) {
                if m.sig != a.sig {
                    out.extend(self.locate(a, &m, depth - 1));
                }
            }
        }
        if c.mu > b.mu * (1.0 + 2.0 * step) {
            if let Some(m) = self.sample_near(c.mu * (1.0 - step), Some(beside)) {
                if m.sig != b.sig {
                    out.extend(self.locate(&m, b, depth - 1));
                }
            }
        }
        Ok(out)
    }
}

/// Where η_s is expected between two points of the boundary at η `a` and `b`: their mean,
/// within their difference (at least 10⁻⁶ of it).
pub(super) fn between(a: f64, b: f64) -> RootGuess {
    let eta = 0.5 * (a + b);
    RootGuess {
        eta,
        rel: ((a - b).abs() / eta).max(1e-6),
    }
}
