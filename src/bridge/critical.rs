//! The critical position of a vehicle (bridge spec §4): the influence line λ_c(X) of the
//! collapse multiplier as the vehicle crosses, sampled, and each of its local minima located
//! by golden-section search on λ_c itself (each value a full multiplier survey: λ_static and
//! every limit state below it), bracketed to a width the caller sets.
//!
//! λ_c is continuous and piecewise smooth in X; a sampled local minimum brackets a true one
//! when the samples resolve the line (the influence line is returned so that a reader can
//! see that they do). A minimum at a kink is bracketed as tightly as a smooth one: golden
//! section needs no derivative.

use super::vehicle::{Deck, Vehicle};
use crate::arch::{Arch, InputError};
use crate::load::LiveLoad;
use crate::multiplier::{static_range, survey, LoadOutcome, LoadSurvey, StaticRange};
use crate::settings::Settings;

/// λ_c at one road position: the collapse multiplier, or why there is none.
#[derive(Debug, Clone, PartialEq)]
pub enum Collapse {
    /// The least limit state's multiplier.
    At(f64),
    /// No limit state: the vehicle never breaks the arch there (λ_c = ∞).
    Never,
    /// The arch does not stand under its dead load alone.
    NoEquilibrium,
    /// The survey did not decide (its reason).
    Undecided(String),
}

impl Collapse {
    /// λ_c as a number to minimise: ∞ where the vehicle never breaks the arch, NaN where
    /// nothing was decided.
    pub fn value(&self) -> f64 {
        match self {
            Collapse::At(l) => *l,
            Collapse::Never => f64::INFINITY,
            Collapse::NoEquilibrium | Collapse::Undecided(_) => f64::NAN,
        }
    }
}

/// One sample of the influence line.
#[derive(Debug, Clone, PartialEq)]
pub struct InfluencePoint {
    /// Road position of the first axle (m).
    pub at_m: f64,
    /// λ_c there.
    pub collapse: Collapse,
}

/// A local minimum of λ_c(X), bracketed.
#[derive(Debug, Clone, PartialEq)]
pub struct Minimum {
    /// The best position found (m), inside the bracket.
    pub at_m: f64,
    /// λ_c there (computed at `at_m`).
    pub lambda: f64,
    /// The bracket [lo, hi] (m) that holds the minimum.
    pub bracket_m: (f64, f64),
}

/// The critical position and what located it.
#[derive(Debug, Clone)]
pub struct Critical {
    /// The influence line, ascending in X.
    pub influence: Vec<InfluencePoint>,
    /// Every local minimum, ascending in λ (the first is the critical position X*).
    pub minima: Vec<Minimum>,
    /// The live load and its survey at X*.
    pub at_critical: Option<(LiveLoad, LoadSurvey)>,
    /// The mirror position of X* on a symmetric arch under a symmetric vehicle (a tie).
    pub mirror_m: Option<f64>,
    /// Complete searches (surveys) run in all.
    pub surveys: usize,
    /// Static maxima (λ_static alone) evaluated in locating the minima.
    pub statics: usize,
}

/// How finely to look.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Search {
    /// Samples of the influence line over the crossing (≥ 3).
    pub samples: usize,
    /// A minimum's bracket is narrowed to this width (m).
    pub bracket_m: f64,
    /// Worker threads for the samples and the minima (the answer does not depend on it).
    pub threads: usize,
}

/// λ_c at one road position, with the load placed and its survey (neither off the ring).
pub type Evaluated = (Collapse, Option<LiveLoad>, Option<LoadSurvey>);

/// λ_c of `vehicle` with its first axle at `at_m`, with the load and its survey (neither
/// when the vehicle is off the ring).
pub fn collapse_at(
    arch: &Arch,
    eta: f64,
    mu: f64,
    deck: &Deck,
    vehicle: &Vehicle,
    at_m: f64,
    settings: &Settings,
) -> Result<Evaluated, InputError> {
    if !deck.on_arch(arch, eta, vehicle, at_m) {
        return Ok((Collapse::Never, None, None));
    }
    let load = deck.place(arch, eta, vehicle, at_m)?;
    let outcome = survey(arch, eta, mu, &load, settings)?;
    Ok(match outcome {
        Ok(LoadOutcome::Limits(sv)) => match sv.lambda() {
            Some(l) => (Collapse::At(l), Some(load), Some(sv)),
            None => (Collapse::Never, Some(load), Some(sv)),
        },
        Ok(LoadOutcome::NoCollapse { .. }) => (Collapse::Never, Some(load), None),
        Ok(LoadOutcome::NoEquilibrium) => (Collapse::NoEquilibrium, Some(load), None),
        Err(e) => (Collapse::Undecided(e.to_string()), Some(load), None),
    })
}

/// The critical position of `vehicle` crossing `arch` (thickness `eta`, friction `mu`):
/// the influence line on `search.samples` positions, then each sampled local minimum
/// refined by Brent's method (parabolic steps where λ_c is smooth, golden sections at a
/// kink) to a bracket of `search.bracket_m`. On a symmetric arch under a symmetric vehicle
/// the samples past the axis are the mirror images of those before it (the same λ_c), and
/// only the minima up to the axis are refined (their mirror images tie).
pub fn critical(
    arch: &Arch,
    eta: f64,
    mu: f64,
    deck: &Deck,
    vehicle: &Vehicle,
    search: Search,
    settings: &Settings,
) -> Result<Critical, InputError> {
    if search.samples < 3 || search.samples > 100_000 {
        return Err(InputError::OutOfRange {
            arg: "--samples",
            value: search.samples.to_string(),
            range: "whole numbers 3 to 100000".into(),
        });
    }
    crate::input::check_positive("--bracket", search.bracket_m)?;
    let crossing = Crossing {
        arch,
        eta,
        mu,
        deck,
        vehicle,
        settings,
    };
    let (influence, surveys) = crossing.influence(search)?;
    let values: Vec<f64> = influence.iter().map(|p| p.collapse.value()).collect();
    let n = influence.len();
    // the axis of a mirror-symmetric crossing: minima beyond it are mirror images
    let axis = mirror(arch, eta, deck, vehicle, 0.0).map(|m| 0.5 * m);
    let spacing = (influence[n - 1].at_m - influence[0].at_m) / (n - 1) as f64;
    let starts: Vec<usize> = (0..n)
        .filter(|&i| {
            let v = values[i];
            let left = if i > 0 { values[i - 1] } else { f64::INFINITY };
            let right = if i + 1 < n {
                values[i + 1]
            } else {
                f64::INFINITY
            };
            // a finite sample below its left neighbour and no larger than its right one
            v.is_finite() && v < left && v <= right
        })
        .filter(|&i| axis.is_none_or(|a| influence[i].at_m <= a + 0.5 * spacing))
        .collect();
    let refined = crate::threads::map(&starts, search.threads, |_, &i| {
        let lo = i.saturating_sub(1);
        let hi = (i + 1).min(n - 1);
        crossing.minimum(&influence[lo..=hi], i - lo, search.bracket_m)
    });
    let mut minima = Vec::new();
    let mut statics = 0;
    let mut at_critical = None;
    let mut counted = surveys;
    for r in refined {
        let found = r?;
        counted += found.surveys;
        statics += found.statics;
        if minima.is_empty() || found.minimum.lambda < minima_least(&minima) {
            at_critical = found.at;
        }
        minima.push(found.minimum);
    }
    minima.sort_by(|a, b| a.lambda.total_cmp(&b.lambda));
    let mirror_m = minima
        .first()
        .and_then(|m| mirror(arch, eta, deck, vehicle, m.at_m));
    Ok(Critical {
        influence,
        minima,
        at_critical,
        mirror_m,
        surveys: counted,
        statics,
    })
}

/// The least λ of the minima found so far.
fn minima_least(minima: &[Minimum]) -> f64 {
    minima
        .iter()
        .map(|m| m.lambda)
        .fold(f64::INFINITY, f64::min)
}

/// One vehicle crossing one arch: what every road position is evaluated with.
struct Crossing<'a> {
    arch: &'a Arch,
    eta: f64,
    mu: f64,
    deck: &'a Deck,
    vehicle: &'a Vehicle,
    settings: &'a Settings,
}

/// A refined local minimum, with the load and survey at its position and what it cost.
struct Found {
    minimum: Minimum,
    at: Option<(LiveLoad, LoadSurvey)>,
    surveys: usize,
    statics: usize,
}

impl Crossing<'_> {
    fn collapse(&self, at_m: f64) -> Result<Evaluated, InputError> {
        collapse_at(
            self.arch,
            self.eta,
            self.mu,
            self.deck,
            self.vehicle,
            at_m,
            self.settings,
        )
    }

    /// The influence line on `search.samples` positions over the crossing, and the surveys
    /// it took: on a mirror-symmetric crossing the positions past the axis take the λ_c of
    /// their mirror images (the same load mirrored, so the same limit states mirrored).
    fn influence(&self, search: Search) -> Result<(Vec<InfluencePoint>, usize), InputError> {
        let (from, to) = self.deck.crossing(self.arch, self.eta, self.vehicle);
        let n = search.samples;
        let positions: Vec<f64> = (0..n)
            .map(|i| crate::arch::grid_angle(from, to, n, i))
            .collect();
        // the sample whose λ_c each sample takes (itself unless it mirrors an earlier one)
        let mirrors = |i: usize| {
            mirror(self.arch, self.eta, self.deck, self.vehicle, positions[i])
                .is_some_and(|m| (m - positions[n - 1 - i]).abs() <= MIRROR_TOL * (1.0 + m.abs()))
        };
        let source: Vec<usize> = (0..n)
            .map(|i| {
                if n - 1 - i < i && mirrors(i) {
                    n - 1 - i
                } else {
                    i
                }
            })
            .collect();
        let own: Vec<usize> = (0..n).filter(|&i| source[i] == i).collect();
        let computed = crate::threads::map(&own, search.threads, |_, &i| {
            self.collapse(positions[i]).map(|(collapse, _, _)| collapse)
        })
        .into_iter()
        .collect::<Result<Vec<_>, _>>()?;
        let mut of = vec![None; n];
        for (&i, c) in own.iter().zip(computed) {
            of[i] = Some(c);
        }
        let influence = (0..n)
            .map(|i| InfluencePoint {
                at_m: positions[i],
                collapse: of[source[i]].clone().expect("every source sample computed"),
            })
            .collect();
        Ok((influence, own.len()))
    }

    /// The local minimum of λ_c bracketed by `samples` (three, or two at an end, the
    /// `best`-th the least), refined by Brent's method to `width`. Where the least limit
    /// state is the static maximum (λ_c = λ_static to `same_state_eta`) at every sample of
    /// the bracket, Brent runs on λ_static (one static maximum per step, not a complete
    /// search), and the complete search at the position found must confirm that λ_c =
    /// λ_static there; λ_c is reported. Where it does not confirm, or the bracket is not of
    /// that kind, Brent runs on λ_c.
    fn minimum(
        &self,
        samples: &[InfluencePoint],
        best: usize,
        width: f64,
    ) -> Result<Found, InputError> {
        let bracket = (samples[0].at_m, samples[samples.len() - 1].at_m);
        let start = (samples[best].at_m, samples[best].collapse.value());
        let mut statics = 0;
        let mut static_value = |x: f64| {
            statics += 1;
            self.static_value(x)
        };
        // λ_c is the static maximum to the resolution of a limit state
        let same_eta = self.settings.same_state_eta;
        let at_static = |c: f64, s: f64| (c - s).abs() <= same_eta * (1.0 + s.abs());
        let mut agree = true;
        for p in samples {
            agree = agree && at_static(p.collapse.value(), static_value(p.at_m)?);
        }
        if agree {
            let m = brent(&mut static_value, bracket, start, width)?;
            let (collapse, load, sv) = self.collapse(m.at_m)?;
            if at_static(collapse.value(), m.lambda) {
                return Ok(Found {
                    minimum: Minimum {
                        lambda: collapse.value(),
                        ..m
                    },
                    at: load.zip(sv),
                    surveys: 1,
                    statics,
                });
            }
        }
        // the surveys Brent ran, kept: the position it ends at is one of them (or the sample)
        let mut seen: Vec<(f64, Evaluated)> = Vec::new();
        let mut f = |x: f64| {
            let e = self.collapse(x)?;
            let v = e.0.value();
            seen.push((x, e));
            Ok(v)
        };
        let m = brent(&mut f, bracket, start, width)?;
        let mut surveys = seen.len();
        let found = match seen.into_iter().find(|(x, _)| *x == m.at_m) {
            Some((_, e)) => e,
            None => {
                surveys += 1;
                self.collapse(m.at_m)?
            }
        };
        Ok(Found {
            minimum: m,
            at: found.1.zip(found.2),
            surveys,
            statics,
        })
    }

    /// λ_static at a road position as a number to minimise: ∞ off the ring or where it is
    /// unbounded, NaN where there is no equilibrium or no decision.
    fn static_value(&self, at_m: f64) -> Result<f64, InputError> {
        let (arch, eta) = (self.arch, self.eta);
        if !self.deck.on_arch(arch, eta, self.vehicle, at_m) {
            return Ok(f64::INFINITY);
        }
        let load = self.deck.place(arch, eta, self.vehicle, at_m)?;
        Ok(
            match static_range(arch, eta, self.mu, &load, self.settings)? {
                Ok(StaticRange::Interval { max, .. }) => max.map_or(f64::INFINITY, |m| m.0),
                Ok(StaticRange::NoEquilibrium) | Err(_) => f64::NAN,
            },
        )
    }
}

/// Two road positions are mirror images when they agree to this relative to their size.
const MIRROR_TOL: f64 = 1e-12;

/// Brent's minimisation of λ_c in `bracket` from the sample `best` inside it, until the
/// bracket is narrower than `width` (R. P. Brent, Algorithms for Minimization without
/// Derivatives, 1973, ch. 5): parabolic steps through the three best points when they are
/// finite and the step stays well inside, golden sections otherwise. Returns the best
/// position evaluated, with the final bracket.
fn brent(
    f: &mut dyn FnMut(f64) -> Result<f64, InputError>,
    (mut a, mut b): (f64, f64),
    (x0, f0): (f64, f64),
    width: f64,
) -> Result<Minimum, InputError> {
    const CGOLD: f64 = 0.381_966_011_250_105_1;
    let (mut x, mut w, mut v) = (x0, x0, x0);
    let (mut fx, mut fw, mut fv) = (f0, f0, f0);
    let (mut d, mut e): (f64, f64) = (0.0, 0.0);
    let tol1 = 0.25 * width;
    for _ in 0..200 {
        let xm = 0.5 * (a + b);
        if b - a <= width || (x - xm).abs() <= 2.0 * tol1 - 0.5 * (b - a) {
            break;
        }
        let smooth = fx.is_finite() && fw.is_finite() && fv.is_finite();
        let mut golden = true;
        if smooth && e.abs() > tol1 {
            let r = (x - w) * (fx - fv);
            let mut q = (x - v) * (fx - fw);
            let mut p = (x - v) * q - (x - w) * r;
            q = 2.0 * (q - r);
            if q > 0.0 {
                p = -p;
            } else {
                q = -q;
            }
            let last = e;
            if p.abs() < (0.5 * q * last).abs() && p > q * (a - x) && p < q * (b - x) {
                e = d;
                d = p / q;
                if (x + d) - a < 2.0 * tol1 || b - (x + d) < 2.0 * tol1 {
                    d = tol1.copysign(xm - x);
                }
                golden = false;
            }
        }
        if golden {
            e = if x >= xm { a - x } else { b - x };
            d = CGOLD * e;
        }
        let u = if d.abs() >= tol1 {
            x + d
        } else {
            x + tol1.copysign(d)
        };
        let fu = f(u)?;
        // NaN (undecided) compares false: never taken as better
        if fu <= fx {
            if u >= x {
                a = x;
            } else {
                b = x;
            }
            (v, fv, w, fw, x, fx) = (w, fw, x, fx, u, fu);
        } else {
            if u < x {
                a = u;
            } else {
                b = u;
            }
            if fu <= fw || w == x {
                (v, fv, w, fw) = (w, fw, u, fu);
            } else if fu <= fv || v == x || v == w {
                (v, fv) = (u, fu);
            }
        }
    }
    Ok(Minimum {
        at_m: x,
        lambda: fx,
        bracket_m: (a, b),
    })
}

/// On a symmetric arch under a symmetric vehicle (its axles and gaps the same read from
/// either end), the position whose load is the mirror image of the vehicle at `at_m`.
fn mirror(arch: &Arch, eta: f64, deck: &Deck, vehicle: &Vehicle, at_m: f64) -> Option<f64> {
    let palindrome = |v: &[f64]| v.iter().eq(v.iter().rev());
    let gaps: Vec<f64> = vehicle.offsets_m.windows(2).map(|w| w[1] - w[0]).collect();
    // the road position below the centre, and the vehicle's reach behind its first axle
    let centre = -(1.0 - 0.5 * eta) * arch.beta_left().cos() * deck.radius_m;
    let patch_symmetric = vehicle
        .patch
        .is_none_or(|p| (p.from_m + p.to_m - 2.0 * centre).abs() <= 1e-12 * (1.0 + centre.abs()));
    let symmetric = arch.is_symmetric() && palindrome(&vehicle.axles_kn) && palindrome(&gaps);
    if !(symmetric && patch_symmetric) {
        return None;
    }
    Some(2.0 * centre + vehicle.length_m() - at_m)
}
