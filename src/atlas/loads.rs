//! The load map of the atlas: where non-associative friction lowers the collapse multiplier
//! of a horizontal body force (an acceleration towards the right springing) below its static
//! maximum, over openings α of symmetric arches and thicknesses η = f η\*(α, μ) (f the
//! thickness factor over the arch's own least thickness), at a few friction coefficients.
//!
//! Each cell is the complete load survey ([`crate::multiplier::survey`]: λ_static exact,
//! every limit state below it), and its answer is λ_c/λ_static. A sampled map: a reduction
//! narrower than the grid's spacing is not seen, and a cell without a reduction proves
//! nothing about its neighbours.

use super::certified::certified_reduction;
use super::column::Rectangle;
use crate::arch::InputError;
use crate::collapse_mode::CollapseMode;
use crate::limit::{solve, Outcome};
use crate::limit_states::LimitState;
use crate::load::LiveLoad;
use crate::multiplier::{follow, static_range, survey_partial, LoadOutcome, StaticRange};
use crate::settings::Settings;
use crate::threads;

/// A reduction is counted where λ_c is below λ_static by more than this (relative): the
/// resolution at which two limit states are told apart.
pub const REDUCTION_TOL: f64 = 1e-9;

/// The thinnest ring of the map, as a factor over η\*.
pub const FACTOR_MIN: f64 = 1.02;

/// Rings at least this thick (η) are left out: the thickness limit is 2.
pub const ETA_MAX: f64 = 1.9;

/// What the load map covers.
#[derive(Debug, Clone)]
pub struct LoadGrid {
    /// The openings (its α range, columns, weight and joints; its μ samples are not used).
    pub rect: Rectangle,
    /// The friction coefficients, each a map of its own.
    pub mus: Vec<f64>,
    /// Thickness factors per opening, geometric from [`FACTOR_MIN`] to `factor_max`.
    pub factors: usize,
    /// The thickest ring, as a factor over η\*.
    pub factor_max: f64,
}

/// What one cell answers.
#[derive(Debug, Clone, PartialEq)]
pub enum CellAnswer {
    /// The collapse multiplier and the static maximum, with the least limit state's mode.
    Ratio {
        /// λ_static.
        lambda_static: f64,
        /// λ_c, the least limit state's λ (with `at_most`, the least found: λ_c ≤ it).
        lambda_c: f64,
        /// The least limit state's mode (with `at_most`, the least found's).
        mode: CollapseMode,
        /// Whether `lambda_c` is only a bound: the survey did not settle, but found a limit
        /// state below λ_static, verified on the continuum ([`crate::multiplier::LoadUnsettled`]),
        /// so the cell is reduced by at least 1 − `lambda_c`/λ_static.
        at_most: bool,
    },
    /// The load drives no mechanism (λ unbounded, or no limit state).
    NoCollapse,
    /// No ring of the map: no thickness stands at this μ, or the arch stands at every
    /// thickness (no η\* to scale), or the ring would be at least [`ETA_MAX`].
    NoRing,
    /// The survey reached no decision (why).
    Undecided(String),
}

/// One cell of the map.
#[derive(Debug, Clone, PartialEq)]
pub struct LoadCell {
    /// Opening.
    pub alpha: f64,
    /// Thickness factor over η\*(α, μ).
    pub factor: f64,
    /// Friction coefficient.
    pub mu: f64,
    /// The thickness (`None` where there is no ring).
    pub eta: Option<f64>,
    /// Its answer.
    pub answer: CellAnswer,
    /// With [`Rectangle::certify`], at a reduced cell: the reduction a verified load
    /// certificate proves at least ([`super::certified_reduction`]), or why not.
    pub certified: Option<Result<f64, String>>,
}

impl LoadCell {
    /// 1 − λ_c/λ_static, where both exist.
    pub fn reduction(&self) -> Option<f64> {
        self.ratio().map(|(s, c, _)| 1.0 - c / s)
    }

    /// (λ_static, λ_c, the least limit state's mode), where the cell has both.
    pub fn ratio(&self) -> Option<(f64, f64, CollapseMode)> {
        match self.answer {
            CellAnswer::Ratio {
                lambda_static,
                lambda_c,
                mode,
                ..
            } => Some((lambda_static, lambda_c, mode)),
            _ => None,
        }
    }

    /// Whether the cell says whether λ_c lies below λ_static: it has both, or the load has
    /// no limit state at all (no collapse, so no reduction).
    pub fn answered(&self) -> bool {
        matches!(
            self.answer,
            CellAnswer::Ratio { .. } | CellAnswer::NoCollapse
        )
    }

    /// Whether its λ_c is only a bound (a survey that did not settle, a limit state found
    /// below λ_static): its reduction is then at least [`LoadCell::reduction`].
    pub fn at_least(&self) -> bool {
        matches!(self.answer, CellAnswer::Ratio { at_most: true, .. })
    }

    /// Whether non-associative friction lowers λ_c below λ_static here.
    pub fn reduced(&self) -> bool {
        self.reduction().is_some_and(|r| r > REDUCTION_TOL)
    }
}

/// Where a reduction begins or ends along η at one opening and friction: bisected in the
/// thickness factor between two answered cells ([`LoadCell::answered`]), one reduced and one not.
#[derive(Debug, Clone, PartialEq)]
pub struct LoadBoundary {
    /// Opening.
    pub alpha: f64,
    /// Friction coefficient.
    pub mu: f64,
    /// Whether the thinner side is the reduced one (else the thicker side is).
    pub reduced_below: bool,
    /// The last factor of the thinner side's answer and the first of the thicker's.
    pub factors: (f64, f64),
    /// The same, as thicknesses η.
    pub etas: (f64, f64),
    /// Why the bisection stopped before [`BOUNDARY_REL`] (a midpoint without a ratio, or
    /// undecided where the reduced side's limit state could not be followed), if it did.
    pub stopped: Option<String>,
    /// The reduction 1 − λ_c/λ_static at the bracket's reduced end (the limit state there
    /// from the survey, or followed to it).
    pub reduction: f64,
    /// Whether [`Self::reduction`] is only a lower bound: the reduced end was decided by a
    /// limit state followed there or found by a survey that did not settle (λ_c is at most
    /// that state's λ), not by a settled survey.
    pub at_least: bool,
    /// Midpoints where the survey did not decide but the reduced side's least limit state,
    /// followed there ([`crate::multiplier::follow`]), is a limit state below λ_static: the
    /// midpoint is reduced.
    pub followed: usize,
    /// Midpoints where the survey did not settle, the followed state failed, and a limit
    /// state the survey found below λ_static (verified) decided them reduced
    /// ([`LoadCell::at_least`]); the reduction at the reduced end is then at least its value.
    pub bounded: usize,
    /// With [`Rectangle::certify`]: the reduction a verified load certificate proves at least
    /// at the bracket's reduced end ([`super::certified_reduction`]), or why not (the other
    /// end, without a reduction, is not certified as such).
    pub certified: Option<Result<f64, String>>,
}

impl LoadBoundary {
    /// The reduced end of the bracket: (factor, η).
    pub fn reduced_end(&self) -> (f64, f64) {
        if self.reduced_below {
            (self.factors.0, self.etas.0)
        } else {
            (self.factors.1, self.etas.1)
        }
    }
}

/// A boundary of the reduction is bisected until its factors are this close (relative).
pub const BOUNDARY_REL: f64 = 1e-9;

/// The whole load map.
#[derive(Debug, Clone)]
pub struct LoadMap {
    /// What it covers.
    pub grid: LoadGrid,
    /// The openings (the semicircle among them where the range holds it).
    pub alphas: Vec<f64>,
    /// The thickness factors.
    pub factors: Vec<f64>,
    /// Every cell: by μ, then α, then factor.
    pub cells: Vec<LoadCell>,
    /// Where the reduction begins or ends between neighbouring cells, by μ, then α, then η.
    pub boundaries: Vec<LoadBoundary>,
}

impl LoadMap {
    /// The cells at friction `mu`.
    pub fn at(&self, mu: f64) -> impl Iterator<Item = &LoadCell> {
        self.cells.iter().filter(move |c| c.mu == mu)
    }

    /// The cell of the largest reduction at `mu`, if any cell has one.
    pub fn largest(&self, mu: f64) -> Option<&LoadCell> {
        self.at(mu)
            .filter(|c| c.reduced())
            .max_by(|a, b| a.reduction().unwrap().total_cmp(&b.reduction().unwrap()))
    }

    /// The boundary at `mu` whose reduced end has the largest reduction, if any: a branch's
    /// reduction can grow towards where the branch ends, beyond every cell's.
    pub fn largest_at_boundary(&self, mu: f64) -> Option<&LoadBoundary> {
        self.boundaries
            .iter()
            .filter(|b| b.mu == mu && b.reduction.is_finite())
            .max_by(|a, b| a.reduction.total_cmp(&b.reduction))
    }

    /// The semicircle's largest reduction at `mu` (0 where it has none; `None` where the
    /// map holds no semicircle).
    pub fn semicircle(&self, mu: f64) -> Option<f64> {
        let cells: Vec<&LoadCell> = self.at(mu).filter(|c| c.alpha == 0.0).collect();
        (!cells.is_empty()).then(|| {
            let r = cells.iter().filter_map(|c| c.reduction());
            r.fold(0.0, f64::max)
        })
    }
}

/// The load map over `grid` on `threads` threads; `progress(done, total)` after each cell.
pub fn load_map(
    grid: &LoadGrid,
    settings: &Settings,
    threads: usize,
    progress: &(dyn Fn(usize, usize) + Sync),
) -> Result<LoadMap, InputError> {
    check(grid)?;
    let alphas = openings(&grid.rect);
    let n = grid.factors;
    let factors: Vec<f64> = (0..n)
        .map(|k| FACTOR_MIN * (grid.factor_max / FACTOR_MIN).powf(k as f64 / (n - 1) as f64))
        .collect();
    // η*(α, μ) once per opening and friction, then every thickness of it
    let columns: Vec<(f64, f64)> = grid
        .mus
        .iter()
        .flat_map(|&mu| alphas.iter().map(move |&a| (mu, a)))
        .collect();
    let stars = threads::map(&columns, threads, |_, &(mu, alpha)| {
        least(&grid.rect, alpha, mu, settings)
    })
    .into_iter()
    .collect::<Result<Vec<_>, _>>()?;
    let cells: Vec<(f64, f64, f64, &Least)> = columns
        .iter()
        .zip(&stars)
        .flat_map(|(&(mu, a), star)| factors.iter().map(move |&f| (mu, a, f, star)))
        .collect();
    let cells = threads::map_with_progress(
        &cells,
        threads,
        progress,
        |_, &(mu, alpha, factor, star)| cell(&grid.rect, (alpha, factor, mu), star, settings),
    )
    .into_iter()
    .collect::<Result<Vec<_>, _>>()?;
    // between neighbouring thicknesses of one opening and friction, reduced and not
    let changes: Vec<(&LoadCell, &LoadCell, f64)> = cells
        .chunks(n)
        .zip(&stars)
        .filter_map(|(column, star)| Some((column, *star.as_ref().ok()?)))
        .flat_map(|(column, star)| {
            column
                .windows(2)
                .filter(|w| w[0].answered() && w[1].answered())
                .filter(|w| w[0].reduced() != w[1].reduced())
                .map(move |w| (&w[0], &w[1], star))
        })
        .collect();
    let boundaries = threads::map(&changes, threads, |_, &(lo, hi, star)| {
        boundary(&grid.rect, (lo, hi), star, settings)
    })
    .into_iter()
    .collect::<Result<Vec<_>, _>>()?;
    Ok(LoadMap {
        grid: grid.clone(),
        alphas,
        factors,
        cells,
        boundaries,
    })
}

/// The change between the cells `lo` (thinner) and `hi` of one opening and friction,
/// bisected in the factor over η\* = `star` down to [`BOUNDARY_REL`] (each midpoint the
/// complete load survey, as a cell is).
fn boundary(
    rect: &Rectangle,
    (lo, hi): (&LoadCell, &LoadCell),
    star: f64,
    settings: &Settings,
) -> Result<LoadBoundary, InputError> {
    let (alpha, mu, below) = (lo.alpha, lo.mu, lo.reduced());
    let certify = rect.certify;
    // the midpoints are not certified (the cells and the bracket's reduced end are)
    let rect = &Rectangle {
        certify: false,
        ..*rect
    };
    let (mut f0, mut f1) = (lo.factor, hi.factor);
    // the reduced end's least limit state, followed where the survey does not decide
    let reduced_end = if below { lo } else { hi };
    // the reduced end's least limit state: the cell's (surveyed again only if needed), then
    // each reduced midpoint's
    let mut tracked: Option<Option<LimitState>> = None;
    let mut reduction = reduced_end.reduction().unwrap_or(f64::NAN);
    let mut at_least = reduced_end.at_least();
    let (mut stopped, mut followed, mut bounded) = (None, 0, 0);
    while f1 - f0 > BOUNDARY_REL * f1 {
        let mid = 0.5 * (f0 + f1);
        let (c, least) = surveyed(rect, (alpha, mid, mu), &Ok(star), settings)?;
        // a survey that did not settle (a bound, or undecided): the reduced side's state
        // followed first, as where the survey finds nothing; a bound decides where it fails
        let bound = c.at_least();
        let reduced = match &c.answer {
            CellAnswer::Ratio { at_most: false, .. } => c.reduced(),
            CellAnswer::NoCollapse => false,
            CellAnswer::Ratio { .. } | CellAnswer::Undecided(_) => {
                if tracked.is_none() {
                    let at = (alpha, reduced_end.factor, mu);
                    tracked = Some(surveyed(rect, at, &Ok(star), settings)?.1);
                }
                let from = tracked.as_ref().and_then(Option::as_ref);
                match follow_reduced(rect, (alpha, mid * star, mu), from, settings)? {
                    Ok((state, r)) => {
                        followed += 1;
                        tracked = Some(Some(state));
                        reduction = r;
                        at_least = true;
                        if below {
                            f0 = mid
                        } else {
                            f1 = mid
                        }
                        continue;
                    }
                    Err(_) if bound => {
                        bounded += 1;
                        c.reduced()
                    }
                    Err(why) => {
                        let e = mid * star;
                        stopped = Some(format!(
                            "the load survey did not decide at eta = {e} ({why})"
                        ));
                        break;
                    }
                }
            }
            CellAnswer::NoRing => {
                stopped = Some(format!("no ring at eta = {}", mid * star));
                break;
            }
        };
        if reduced {
            tracked = Some(least);
            reduction = c.reduction().unwrap_or(f64::NAN);
            at_least = bound;
        }
        if reduced == below {
            f0 = mid
        } else {
            f1 = mid
        }
    }
    let reduced_eta = if below { f0 } else { f1 } * star;
    let certified = certify
        .then(|| rect.arch(alpha))
        .transpose()?
        .map(|arch| certified_reduction(&arch, (reduced_eta, mu), &horizontal(), settings));
    Ok(LoadBoundary {
        alpha,
        mu,
        reduced_below: below,
        factors: (f0, f1),
        etas: (f0 * star, f1 * star),
        stopped,
        reduction,
        at_least,
        followed,
        bounded,
        certified,
    })
}

/// The reduced side's least limit state `from` followed to (α, η, μ) where the survey did
/// not decide: the state there and its reduction below λ_static, if it is a limit state
/// below λ_static by more than [`REDUCTION_TOL`]; else why not.
fn follow_reduced(
    rect: &Rectangle,
    (alpha, eta, mu): (f64, f64, f64),
    from: Option<&LimitState>,
    settings: &Settings,
) -> Result<Result<(LimitState, f64), String>, InputError> {
    let Some(from) = from else {
        return Ok(Err("no limit state to follow".into()));
    };
    let (arch, load) = (rect.arch(alpha)?, horizontal());
    let top = match static_range(&arch, eta, mu, &load, settings)? {
        Ok(StaticRange::Interval { max: Some(m), .. }) => m.0,
        _ => return Ok(Err("no finite lambda_static".into())),
    };
    Ok(match follow(&arch, (eta, mu), &load, from, settings) {
        Ok(s) if 1.0 - s.t / top > REDUCTION_TOL => {
            let r = 1.0 - s.t / top;
            Ok((s, r))
        }
        Ok(s) => Err(format!(
            "the followed limit state lambda = {} is not below lambda_static = {top}",
            s.t
        )),
        Err(why) => Err(format!("the followed limit state ends: {why}")),
    })
}

/// The horizontal acceleration of the map, towards the right springing.
fn horizontal() -> LiveLoad {
    LiveLoad::Horizontal {
        towards_right: true,
    }
}

/// The ranges, each named by its flag.
fn check(grid: &LoadGrid) -> Result<(), InputError> {
    grid.rect.check()?;
    let bad = |arg: &'static str, value: String, range: &str| InputError::OutOfRange {
        arg,
        value,
        range: range.into(),
    };
    if grid.mus.is_empty() {
        return Err(bad("--mu", "none".into(), "one or more of 0 < mu < inf"));
    }
    for &mu in &grid.mus {
        crate::arch::check_mu(mu)?;
        if !mu.is_finite() {
            return Err(bad("--mu", crate::arch::fmt_value(mu), "0 < mu < inf"));
        }
    }
    if !(2..=200).contains(&grid.factors) {
        return Err(bad(
            "--factors",
            grid.factors.to_string(),
            "whole numbers 2 to 200",
        ));
    }
    if !(grid.factor_max > FACTOR_MIN && grid.factor_max <= 100.0) {
        let v = crate::arch::fmt_value(grid.factor_max);
        return Err(bad("--factor-max", v, "1.02 < F <= 100"));
    }
    Ok(())
}

/// The openings of the columns, with the semicircle put exactly where a column rounds to
/// it, and added where the range holds it but no column lies on it.
fn openings(rect: &Rectangle) -> Vec<f64> {
    let mut alphas = rect.alphas();
    let step = (rect.alpha_max - rect.alpha_min) / (alphas.len() - 1) as f64;
    for a in alphas.iter_mut().filter(|a| a.abs() < 1e-9 * step) {
        *a = 0.0;
    }
    if rect.alpha_min < 0.0 && rect.alpha_max > 0.0 && !alphas.contains(&0.0) {
        alphas.push(0.0);
        alphas.sort_by(f64::total_cmp);
    }
    alphas
}

/// η\*(α, μ), or the answer of every cell of that opening and friction without it.
type Least = Result<f64, CellAnswer>;

/// η\*(α, μ) of the opening `alpha` at friction `mu`.
fn least(rect: &Rectangle, alpha: f64, mu: f64, settings: &Settings) -> Result<Least, InputError> {
    Ok(match solve(&rect.arch(alpha)?, mu, settings)?.outcome {
        Outcome::Limit(ls) => Ok(ls.eta_static),
        Outcome::Unresolved { reason, .. } => Err(CellAnswer::Undecided(reason)),
        _ => Err(CellAnswer::NoRing),
    })
}

/// One cell: the ring f η\* and its load survey.
fn cell(
    rect: &Rectangle,
    at: (f64, f64, f64),
    least: &Least,
    settings: &Settings,
) -> Result<LoadCell, InputError> {
    surveyed(rect, at, least, settings).map(|(c, _)| c)
}

/// [`cell`], and the least limit state of its survey where it has one.
fn surveyed(
    rect: &Rectangle,
    (alpha, factor, mu): (f64, f64, f64),
    least: &Least,
    settings: &Settings,
) -> Result<(LoadCell, Option<LimitState>), InputError> {
    let arch = rect.arch(alpha)?;
    let at = |eta, answer| LoadCell {
        alpha,
        factor,
        mu,
        eta,
        answer,
        certified: None,
    };
    let eta_star = match least {
        Ok(e) => *e,
        Err(answer) => return Ok((at(None, answer.clone()), None)),
    };
    let eta = factor * eta_star;
    if eta >= ETA_MAX {
        return Ok((at(None, CellAnswer::NoRing), None));
    }
    let load = horizontal();
    let mut first = None;
    let mut ratio = |lambda_static: f64, least: &LimitState, at_most: bool| {
        first = Some(least.clone());
        CellAnswer::Ratio {
            lambda_static,
            lambda_c: least.t,
            mode: least.mode,
            at_most,
        }
    };
    let answer = match survey_partial(&arch, eta, mu, &load, settings)? {
        Ok(LoadOutcome::Limits(sv)) => match (sv.lambda_static, sv.limit_states.first()) {
            (Some((lambda_static, _)), Some(least)) => ratio(lambda_static, least, false),
            _ => CellAnswer::NoCollapse,
        },
        Ok(LoadOutcome::NoCollapse { .. }) => CellAnswer::NoCollapse,
        Ok(LoadOutcome::NoEquilibrium) => CellAnswer::NoRing,
        // not settled, but a verified limit state below λ_static: reduced, by at least
        Err(u) => match (u.lambda_static, u.reduction_at_least()) {
            (Some(lambda_static), Some(_)) => ratio(lambda_static, &u.found[0], true),
            _ => CellAnswer::Undecided(u.why.to_string()),
        },
    };
    let mut c = at(Some(eta), answer);
    if rect.certify && c.reduced() {
        c.certified = Some(certified_reduction(&arch, (eta, mu), &load, settings));
    }
    Ok((c, first))
}
