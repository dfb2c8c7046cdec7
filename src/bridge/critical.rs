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
use crate::multiplier::{survey, LoadOutcome, LoadSurvey};
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
    /// Surveys run in all.
    pub surveys: usize,
}

/// How finely to look.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Search {
    /// Samples of the influence line over the crossing (≥ 3).
    pub samples: usize,
    /// A minimum's bracket is narrowed to this width (m).
    pub bracket_m: f64,
}

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
) -> Result<(Collapse, Option<LiveLoad>, Option<LoadSurvey>), InputError> {
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

/// The critical position of `vehicle` crossing `arch` (thickness `eta`, friction `mu`).
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
    let (from, to) = deck.crossing(arch, eta, vehicle);
    let n = search.samples;
    let mut surveys = 0;
    let mut lambda = |at: f64| -> Result<f64, InputError> {
        surveys += 1;
        Ok(collapse_at(arch, eta, mu, deck, vehicle, at, settings)?
            .0
            .value())
    };
    let mut influence = Vec::with_capacity(n);
    for i in 0..n {
        let at_m = crate::arch::grid_angle(from, to, n, i);
        let (collapse, _, _) = collapse_at(arch, eta, mu, deck, vehicle, at_m, settings)?;
        influence.push(InfluencePoint { at_m, collapse });
    }
    let values: Vec<f64> = influence.iter().map(|p| p.collapse.value()).collect();
    let mut minima = Vec::new();
    for i in 0..n {
        let v = values[i];
        let left = if i > 0 { values[i - 1] } else { f64::INFINITY };
        let right = if i + 1 < n {
            values[i + 1]
        } else {
            f64::INFINITY
        };
        // a finite sample no larger than its neighbours (the first of a flat run)
        if !(v.is_finite() && v < left && v <= right) {
            continue;
        }
        let lo = influence[i.saturating_sub(1)].at_m;
        let hi = influence[(i + 1).min(n - 1)].at_m;
        minima.push(golden(
            &mut lambda,
            (lo, hi),
            (influence[i].at_m, v),
            search.bracket_m,
        )?);
    }
    minima.sort_by(|a, b| a.lambda.total_cmp(&b.lambda));
    let at_critical = match minima.first() {
        Some(m) => {
            let (_, load, sv) = collapse_at(arch, eta, mu, deck, vehicle, m.at_m, settings)?;
            load.zip(sv)
        }
        None => None,
    };
    let mirror_m = minima
        .first()
        .and_then(|m| mirror(arch, eta, deck, vehicle, m.at_m));
    Ok(Critical {
        influence,
        minima,
        at_critical,
        mirror_m,
        surveys: surveys + n + 1,
    })
}

/// Golden-section search for the least λ_c in `bracket`, from the sample `best` inside it,
/// until the bracket is narrower than `width`: returns the best position evaluated.
fn golden(
    lambda: &mut dyn FnMut(f64) -> Result<f64, InputError>,
    (mut lo, mut hi): (f64, f64),
    mut best: (f64, f64),
    width: f64,
) -> Result<Minimum, InputError> {
    const INV_PHI: f64 = 0.618_033_988_749_894_9;
    let mut x1 = hi - INV_PHI * (hi - lo);
    let mut x2 = lo + INV_PHI * (hi - lo);
    let (mut f1, mut f2) = (lambda(x1)?, lambda(x2)?);
    for (x, f) in [(x1, f1), (x2, f2)] {
        if f < best.1 {
            best = (x, f);
        }
    }
    while hi - lo > width {
        // NaN (undecided) compares false: treated as larger
        if f1 <= f2 || f2.is_nan() {
            hi = x2;
            x2 = x1;
            f2 = f1;
            x1 = hi - INV_PHI * (hi - lo);
            f1 = lambda(x1)?;
            if f1 < best.1 {
                best = (x1, f1);
            }
        } else {
            lo = x1;
            x1 = x2;
            f1 = f2;
            x2 = lo + INV_PHI * (hi - lo);
            f2 = lambda(x2)?;
            if f2 < best.1 {
                best = (x2, f2);
            }
        }
        if x1 == x2 {
            break;
        }
    }
    Ok(Minimum {
        at_m: best.0,
        lambda: best.1,
        bracket_m: (lo, hi),
    })
}

/// On a symmetric arch under a symmetric vehicle (its axles and gaps the same read from
/// either end), the position whose load is the mirror image of the vehicle at `at_m`.
fn mirror(arch: &Arch, eta: f64, deck: &Deck, vehicle: &Vehicle, at_m: f64) -> Option<f64> {
    let palindrome = |v: &[f64]| v.iter().eq(v.iter().rev());
    let gaps: Vec<f64> = vehicle.offsets_m.windows(2).map(|w| w[1] - w[0]).collect();
    if !(arch.is_symmetric() && palindrome(&vehicle.axles_kn) && palindrome(&gaps)) {
        return None;
    }
    // the road position below the centre, and the vehicle's reach behind its first axle
    let centre = -(1.0 - 0.5 * eta) * arch.beta_left().cos() * deck.radius_m;
    Some(2.0 * centre + vehicle.length_m() - at_m)
}
