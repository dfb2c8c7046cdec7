//! The limit curve of an arch with fill: the least friction μ_min(η) at each thickness, the
//! boundary of the region of (η, μ) where the arch with its fill stands.
//!
//! Without fill the friction-only problem does not depend on η: the boundary is η_s(μ),
//! falling as μ grows, and it ends on the vertical branch μ = μ_ms. With fill the fill's load
//! relative to the ring's weight grows as 1/η, so the friction a ring needs moves with its
//! thickness and need not fall as the ring thickens: at low friction the thicknesses that
//! stand can be an interval [η_s, η_up] (a thicker ring carries relatively less fill, and its
//! springings slide as the bare ring's would). η_s(μ) then covers only part of the boundary;
//! μ_min(η) covers all of it, so the curve is traced in η:
//!
//! 1. η\*(∞), the least thickness with fill when no joint slides ([`solve`] at μ = ∞): below
//!    it no friction suffices.
//! 2. μ_min(η) ([`least_friction_for`]: margin LPs bracket μ, then Newton with μ unknown on
//!    the bracket's active pattern, verified over the arch) on a geometric grid of η from
//!    just above η\*(∞) to the thickness limit.
//! 3. Between neighbouring samples of different patterns the change is bisected in η by the
//!    one tracer ([`crate::tracer`]) to neighbouring floats.
//! 4. The least friction at which the arch with its fill stands at all, μ_f = min μ_min(η),
//!    and the thickness η_f that needs no more: golden-section search on the bracket of the
//!    least sample (μ_min taken as unimodal inside it). Thinner than η_f the boundary is the
//!    least thickness η_s(μ); thicker, the greatest thickness η_up(μ) that stands at μ.

use super::boundary::{signature, Signature};
use crate::arch::{Arch, ETA_TOP};
use crate::assess::{least_friction_for, LeastFriction};
use crate::collapse_mode::{classify, CollapseMode};
use crate::contact::Contact;
use crate::limit::{solve, Outcome};
use crate::search::golden_min;
use crate::settings::Settings;
use crate::tracer::{self, Split};
use std::convert::Infallible;

/// How many levels a change between two samples is bisected at most (from a sample spacing
/// of a few per cent, 60 halvings reach neighbouring floats).
const BISECTION_DEPTH: usize = 80;

/// The golden-section search for μ_f stops when its bracket is narrower than this,
/// relative to η (μ_min is flat at its minimum: μ_f is then resolved to about the square
/// of it, η_f only to it).
const LEAST_ETA_REL: f64 = 1e-9;

/// Two changes closer than this in η (relative) are one corner: between them the union of
/// both patterns is active within the activity tolerance, a sliver, not a branch.
const SAME_CHANGE_REL: f64 = 1e-9;

/// μ_min at one thickness.
#[derive(Debug, Clone)]
pub struct FrictionPoint {
    /// The ring's thickness η.
    pub eta: f64,
    /// μ_min(η): the least friction at which it stands.
    pub mu: f64,
    /// Every contact active at μ_min, by increasing β.
    pub pattern: Vec<Contact>,
    /// The collapse mode of that pattern.
    pub mode: CollapseMode,
    /// True when Newton located μ_min on the pattern and the state was verified over the
    /// arch; false when only the LP bracket of μ is known (`mu` its upper end).
    pub exact: bool,
}

/// A stretch of thicknesses whose least-friction states have one pattern.
#[derive(Debug, Clone)]
pub struct FillBranch {
    /// Its mode.
    pub mode: CollapseMode,
    /// Its thinnest and thickest points (samples, or the ends of the bisected changes).
    pub ends: [FrictionPoint; 2],
}

/// A change of pattern between two thicknesses, bisected in η.
#[derive(Debug, Clone)]
pub struct FillChange {
    /// The thinner and the thicker end of the bracket.
    pub ends: [FrictionPoint; 2],
    /// Bisected to neighbouring floats (where two changes across a sliver were merged,
    /// each of them).
    pub tight: bool,
}

/// The limit curve of an arch with fill.
#[derive(Debug, Clone)]
pub struct FillCurve {
    /// η\*(∞): no thinner ring stands at any friction (`None`: nothing stands at μ = ∞).
    pub eta_inf: Option<f64>,
    /// The least friction at which the arch stands at all, μ_f, at the thickness η_f that
    /// needs no more (`None` when nothing stands).
    pub least: Option<FrictionPoint>,
    /// Branches by increasing η.
    pub branches: Vec<FillBranch>,
    /// Pattern changes by increasing η.
    pub changes: Vec<FillChange>,
    /// The samples of μ_min(η), by increasing η.
    pub samples: Vec<FrictionPoint>,
    /// What could not be decided (η and why).
    pub unresolved: Vec<(f64, String)>,
}

/// μ_min at `eta`, with its mode (`None` where no friction suffices).
pub fn point(arch: &Arch, eta: f64, settings: &Settings) -> Option<FrictionPoint> {
    match least_friction_for(arch, eta, settings) {
        LeastFriction::Finite { mu, pattern, exact } if mu.is_finite() => {
            let mid = 0.5 * (arch.beta_right() + arch.beta_left());
            Some(FrictionPoint {
                eta,
                mu,
                mode: classify(&pattern, mid, settings.same_joint),
                pattern,
                exact,
            })
        }
        _ => None,
    }
}

/// The thickness problem with fill in the tracer: samples keyed by their pattern, brackets
/// split in η.
struct Thicknesses<'a> {
    arch: &'a Arch,
    settings: &'a Settings,
}

impl tracer::Problem for Thicknesses<'_> {
    type Sample = FrictionPoint;
    type Key = Signature;
    type Corner = FillChange;
    type Error = Infallible;

    fn key(&self, s: &FrictionPoint) -> Signature {
        signature(self.arch, &s.pattern)
    }

    fn split(&mut self, a: &FrictionPoint, b: &FrictionPoint, depth: usize) -> Split {
        let mid = a.eta + 0.5 * (b.eta - a.eta);
        if depth == 0 {
            Split::Stop { tight: false }
        } else if mid <= a.eta.min(b.eta) || mid >= a.eta.max(b.eta) {
            Split::Stop { tight: true }
        } else {
            Split::At(mid)
        }
    }

    fn sample(
        &mut self,
        eta: f64,
        _: &FrictionPoint,
        _: &FrictionPoint,
    ) -> Result<Option<FrictionPoint>, Infallible> {
        Ok(point(self.arch, eta, self.settings))
    }

    fn exact(&mut self, _: &FrictionPoint, _: &FrictionPoint) -> Option<FillChange> {
        None
    }

    fn bracketed(&mut self, a: &FrictionPoint, b: &FrictionPoint, tight: bool) -> FillChange {
        FillChange {
            ends: [a.clone(), b.clone()],
            tight,
        }
    }
}

/// The thicknesses sampled: geometric from just above η\*(∞) to the thickness limit.
fn thickness_grid(eta_inf: f64, settings: &Settings) -> Vec<f64> {
    let lo = eta_inf * (1.0 + settings.curve_start_rel);
    let n = settings.curve_samples.max(2);
    (0..n)
        .map(|i| {
            if i + 1 == n {
                ETA_TOP
            } else {
                lo * (ETA_TOP / lo).powf(i as f64 / (n - 1) as f64)
            }
        })
        .collect()
}

/// η\*(∞) of the arch with its fill, or why there is none.
fn least_without_sliding(arch: &Arch, settings: &Settings) -> Result<f64, String> {
    let sol = solve(arch, f64::INFINITY, settings).map_err(|e| e.to_string())?;
    if let Some(scan) = &sol.scan {
        if !scan.gaps().is_empty() {
            return Err(format!(
                "at mu = inf the admissible thicknesses are not an interval (inadmissible again at eta = {:?}): the region is not traced",
                scan.gaps()
            ));
        }
    }
    match sol.outcome {
        Outcome::Limit(ls) => Ok(ls.eta_static),
        Outcome::NoEquilibrium { .. } => Err("no thickness stands at mu = inf".into()),
        Outcome::NoCollapse { reason } | Outcome::Unresolved { reason, .. } => Err(reason),
    }
}

/// μ_f: the golden-section minimum of μ_min(η) on the bracket of the least sample.
fn least_friction(arch: &Arch, samples: &[FrictionPoint], settings: &Settings) -> FrictionPoint {
    let k = (0..samples.len())
        .min_by(|&i, &j| samples[i].mu.total_cmp(&samples[j].mu))
        .expect("samples");
    let bracket = (
        samples[k.saturating_sub(1)].eta,
        samples[(k + 1).min(samples.len() - 1)].eta,
    );
    let at = |eta: f64| Ok::<_, Infallible>(point(arch, eta, settings));
    let mu = |p: &Option<FrictionPoint>| p.as_ref().map_or(f64::INFINITY, |p| p.mu);
    let Ok(found) = golden_min(bracket, LEAST_ETA_REL, at, mu, |_| false);
    match found {
        Some((_, Some(p))) if p.mu < samples[k].mu => p,
        _ => samples[k].clone(),
    }
}

/// The changes (by increasing η) with each sliver between two of them removed: the two
/// become one, from the first's thinner end to the second's thicker end.
fn merge_slivers(changes: Vec<FillChange>) -> Vec<FillChange> {
    let mut out: Vec<FillChange> = Vec::with_capacity(changes.len());
    for c in changes {
        match out.last_mut() {
            Some(p) if c.ends[0].eta - p.ends[1].eta <= SAME_CHANGE_REL * c.ends[0].eta => {
                p.ends[1] = c.ends[1].clone();
                p.tight &= c.tight;
            }
            _ => out.push(c),
        }
    }
    out
}

/// The branches between the changes (both by increasing η).
fn branches(samples: &[FrictionPoint], changes: &[FillChange]) -> Vec<FillBranch> {
    let (Some(first), Some(last)) = (samples.first(), samples.last()) else {
        return Vec::new();
    };
    let mut from = first.clone();
    let mut out = Vec::new();
    for c in changes {
        out.push(FillBranch {
            mode: from.mode,
            ends: [from, c.ends[0].clone()],
        });
        from = c.ends[1].clone();
    }
    out.push(FillBranch {
        mode: from.mode,
        ends: [from, last.clone()],
    });
    out
}

/// The limit curve of `arch` (with its fill), its samples on `threads` threads.
pub fn trace(arch: &Arch, settings: &Settings, threads: usize) -> FillCurve {
    let mut curve = FillCurve {
        eta_inf: None,
        least: None,
        branches: Vec::new(),
        changes: Vec::new(),
        samples: Vec::new(),
        unresolved: Vec::new(),
    };
    let eta_inf = match least_without_sliding(arch, settings) {
        Ok(eta) => eta,
        Err(why) => {
            curve.unresolved.push((f64::INFINITY, why));
            return curve;
        }
    };
    curve.eta_inf = Some(eta_inf);
    let grid = thickness_grid(eta_inf, settings);
    let found = crate::threads::map(&grid, threads, |_, &eta| point(arch, eta, settings));
    for (eta, p) in grid.iter().zip(found) {
        match p {
            Some(p) if !p.exact => {
                curve
                    .unresolved
                    .push((*eta, format!("mu_min is bracketed only (at most {})", p.mu)));
                curve.samples.push(p);
            }
            Some(p) => curve.samples.push(p),
            None => curve
                .unresolved
                .push((*eta, "no friction makes this thickness stand".into())),
        }
    }
    let pairs: Vec<(&FrictionPoint, &FrictionPoint)> = curve
        .samples
        .windows(2)
        .map(|w| (&w[0], &w[1]))
        .filter(|(a, b)| signature(arch, &a.pattern) != signature(arch, &b.pattern))
        .collect();
    let located = crate::threads::map(&pairs, threads, |_, (a, b)| {
        let Ok(found) = tracer::locate(&mut Thicknesses { arch, settings }, a, b, BISECTION_DEPTH);
        found
    });
    curve.changes = merge_slivers(located.into_iter().flatten().collect());
    curve.branches = branches(&curve.samples, &curve.changes);
    if !curve.samples.is_empty() {
        curve.least = Some(least_friction(arch, &curve.samples, settings));
    }
    curve
}
