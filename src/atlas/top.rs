//! The top of the non-unique band: the largest μ/μ_ms on its boundary with `unique`, over
//! the openings. Each value is a boundary point solved from the condition that ends its
//! branch ([`crate::limit_states::branch_end()`]) at that opening (a column of its own, in a
//! μ range just above the band), so the ratio is exact at every α (on a voussoir arch, whose
//! ends are not solved, a point bisected to neighbouring floats); the α of the largest is
//! found by golden section between the columns around the largest sampled ratio, each
//! value by continuation in α (the ends of the columns around it, moved to that opening by
//! Newton on their defining conditions, [`crate::limit_states::end_on`]; the last of them
//! stands where it is a limit state above η_s and the search finds the arch unique just
//! beyond it, else a column of its own decides). The top
//! is where one branch-end curve peaks, or a corner where the last branch to end changes
//! (the two sides' conditions say which).

use super::classify::Kind;
use super::column::{column, Column, Rectangle};
use super::continued::Branches;
use crate::arch::InputError;
use crate::limit_states::BranchEnd;
use crate::settings::Settings;

/// The golden section stops when its bracket in α is this narrow (relative).
const ALPHA_TOL: f64 = 1e-12;

/// Golden-section steps at most (the bracket shrinks by 0.618 each).
const MAX_STEPS: usize = 80;

/// Samples of μ in each column the search evaluates.
const SAMPLES: usize = 10;

/// The same on a voussoir arch, whose ends are not continued in α: every opening is a
/// column of its own, and an island of the band (the 12-voussoir band at α < 0.6, a few per
/// cent of μ wide) must not fall between its samples.
const VOUSSOIR_SAMPLES: usize = 80;

/// The top of the non-unique band.
#[derive(Debug, Clone)]
pub struct BandTop {
    /// The opening of the largest μ/μ_ms evaluated (in `alpha_bracket`, or where the band
    /// ends abruptly inside it, the last evaluated opening before the edge).
    pub alpha: f64,
    /// The bracket of that opening when the golden section stopped.
    pub alpha_bracket: (f64, f64),
    /// μ of the boundary point there.
    pub mu: f64,
    /// μ_ms there.
    pub mu_ms: f64,
    /// μ/μ_ms there.
    pub ratio: f64,
    /// What ends the branch at the solved openings nearest the top on either side (the
    /// same condition on the same contact: a smooth peak; different: a corner where the
    /// last branch to end changes; "none": no solved opening on that side).
    pub conditions: (String, String),
    /// Openings evaluated.
    pub evaluations: usize,
    /// Every branch end the search solved, with its opening (continued, or a column's of
    /// its own): the traced strips start from them too.
    pub ends: Vec<(f64, BranchEnd)>,
}

impl BandTop {
    /// What the top is: a smooth peak of one branch-end curve (the same condition on both
    /// sides), a corner where the last branch to end changes, or on a voussoir arch the
    /// largest of points bisected to neighbouring floats (where what ends a branch is not
    /// solved, so peak and corner are not told apart).
    pub fn shape(&self) -> &'static str {
        if self.conditions.0 == VOUSSOIR_END || self.conditions.1 == VOUSSOIR_END {
            "the largest of bisected points"
        } else if self.conditions.0 == NONE || self.conditions.1 == NONE {
            "at the edge of the openings evaluated"
        } else if self.conditions.0 == self.conditions.1 {
            "a smooth peak"
        } else {
            "a corner"
        }
    }
}

/// One opening's value: μ/μ_ms of its boundary point, its μ, μ_ms and condition.
type Value = Option<(f64, f64, f64, String)>;

/// A continued end as the top's value.
fn value_of(end: Option<(BranchEnd, f64)>) -> Value {
    end.map(|(e, mu_ms)| (e.mu / mu_ms, e.mu, mu_ms, e.condition.describe()))
}

/// The boundary point's μ/μ_ms at `alpha`, its μ, μ_ms and condition (`None`: no solved
/// point between `non_unique` and `unique` there).
fn ratio_at(
    rect: &Rectangle,
    alpha: f64,
    top: f64,
    settings: &Settings,
) -> Result<(Value, Column), InputError> {
    let sub = Rectangle {
        mu_max_factor: top,
        samples: if rect.blocks.is_some() {
            VOUSSOIR_SAMPLES
        } else {
            SAMPLES
        },
        certify: false,
        ..*rect
    };
    let col = column(&sub, (alpha, None), settings)?;
    let band = band_runs(std::slice::from_ref(&col));
    Ok((best(&col, rect.blocks.is_some(), &band[0]), col))
}

/// The largest μ/μ_ms of a column's solved `non_unique`/`unique` points, with its μ, μ_ms
/// and condition. On a voussoir arch (`discrete`), whose search is complete by itself, a
/// point bisected to neighbouring floats counts too, at its non-unique end (the kinds
/// change there, decided to the solver's tolerances: ~10⁻¹⁰ of μ).
fn best(col: &Column, discrete: bool, band: &[(f64, f64)]) -> Value {
    let mu_ms = col.mu_ms?;
    let in_band = |mu: f64| {
        let r = mu / mu_ms;
        band.iter()
            .any(|&(lo, hi)| r >= lo * (1.0 - BAND_SLACK) && r <= hi * (1.0 + BAND_SLACK))
    };
    col.boundaries
        .iter()
        .filter(|p| p.between == [Kind::NonUnique, Kind::Unique])
        .filter(|p| in_band(p.bracket.0))
        .filter_map(|p| match &p.end {
            Some(Ok(e)) => Some((e.mu / mu_ms, e.mu, mu_ms, e.condition.describe())),
            None if discrete && p.tight => {
                Some((p.bracket.0 / mu_ms, p.bracket.0, mu_ms, VOUSSOIR_END.into()))
            }
            _ => None,
        })
        .max_by(|a, b| a.0.total_cmp(&b.0))
}

/// A boundary point belongs to a run of the band when its μ/μ_ms lies in the run's
/// interval to this (relative).
const BAND_SLACK: f64 = 1e-9;

/// A run reaches down to μ_ms when it starts below μ_ms (1 + this): at the column's first
/// sample.
const AT_MU_MS: f64 = 1e-4;

/// The non-unique runs of each column that belong to the band, as μ/μ_ms intervals: the
/// runs reaching down to μ_ms, and every run joined to one of them through runs of
/// neighbouring columns whose intervals overlap (an island of the band above a stretch of
/// `unique`, as the 12-voussoir band has at α ≈ 0.6, is joined to it; a sliver of a voussoir
/// arch far from it is not). Where no run reaches μ_ms, every non-unique run.
fn band_runs(columns: &[Column]) -> Vec<Vec<(f64, f64)>> {
    let runs: Vec<Vec<(f64, f64)>> = columns
        .iter()
        .map(|c| match c.mu_ms {
            Some(ms) => c
                .runs
                .iter()
                .filter(|r| r.0 == Some(Kind::NonUnique))
                .map(|r| (r.1 / ms, r.2 / ms))
                .collect(),
            None => Vec::new(),
        })
        .collect();
    let mut band: Vec<Vec<(f64, f64)>> = runs
        .iter()
        .map(|rs| {
            rs.iter()
                .copied()
                .filter(|r| r.0 < 1.0 + AT_MU_MS)
                .collect()
        })
        .collect();
    if band.iter().all(Vec::is_empty) {
        return runs;
    }
    let overlap = |a: &(f64, f64), b: &(f64, f64)| a.0 <= b.1 && b.0 <= a.1;
    loop {
        let mut grew = false;
        for k in 0..columns.len() {
            let neighbours: Vec<(f64, f64)> = [k.wrapping_sub(1), k + 1]
                .iter()
                .filter_map(|&j| band.get(j))
                .flatten()
                .copied()
                .collect();
            for r in &runs[k] {
                if !band[k].contains(r) && neighbours.iter().any(|n| overlap(n, r)) {
                    band[k].push(*r);
                    grew = true;
                }
            }
        }
        if !grew {
            return band;
        }
    }
}

/// The condition of a side of the top without a solved opening.
const NONE: &str = "none";

/// What ends the band at a voussoir arch's point: the exact search's kinds change.
const VOUSSOIR_END: &str = "the voussoir arch's last limit state above eta_s (bisected)";

/// The top of the non-unique band over the columns (`None`: no column has a solved point
/// between `non_unique` and `unique`).
pub(super) fn band_top(
    rect: &Rectangle,
    columns: &[Column],
    settings: &Settings,
) -> Result<Option<BandTop>, InputError> {
    let band = band_runs(columns);
    let discrete = rect.blocks.is_some();
    let sampled: Vec<(usize, f64)> = columns
        .iter()
        .enumerate()
        .filter_map(|(k, c)| best(c, discrete, &band[k]).map(|b| (k, b.0)))
        .collect();
    let Some(&(k, r)) = sampled.iter().max_by(|a, b| a.1.total_cmp(&b.1)) else {
        return Ok(None);
    };
    let (mut a, mut b) = (
        columns[k.saturating_sub(1)].alpha,
        columns[(k + 1).min(columns.len() - 1)].alpha,
    );
    // every column of the search reaches a little above the largest sampled ratio
    let top = 1.0 + 1.5 * (r - 1.0);
    let mut evaluations = 0;
    // the ends of the columns around the largest, continued in α (a column where that fails)
    let mut branches = Branches::of(&columns[k.saturating_sub(1)..=(k + 1).min(columns.len() - 1)]);
    // every opening evaluated, with its value (the sampled columns around the largest first)
    let mut log: Vec<(f64, Value)> = columns[k.saturating_sub(1)..=(k + 1).min(columns.len() - 1)]
        .iter()
        .zip(&band[k.saturating_sub(1)..])
        .map(|(c, b)| (c.alpha, best(c, discrete, b)))
        .collect();
    let mut ends: Vec<(f64, BranchEnd)> = Vec::new();
    let mut f = |alpha: f64| -> Result<Value, InputError> {
        evaluations += 1;
        let v = match branches.at(rect, alpha, settings)? {
            Some(e) => {
                ends.push((alpha, e.0.clone()));
                value_of(Some(e))
            }
            None => {
                let (v, col) = ratio_at(rect, alpha, top, settings)?;
                ends.extend(Branches::of([&col]).into_ends());
                v
            }
        };
        log.push((alpha, v.clone()));
        Ok(v)
    };
    let g = 0.5 * (5f64.sqrt() - 1.0);
    let (mut x1, mut x2) = (b - g * (b - a), a + g * (b - a));
    let value = |v: &Value| v.as_ref().map_or(f64::NEG_INFINITY, |v| v.0);
    let (mut f1, mut f2) = (f(x1)?, f(x2)?);
    for _ in 0..MAX_STEPS {
        if b - a <= ALPHA_TOL * a.abs().max(1.0) {
            break;
        }
        if value(&f1) >= value(&f2) {
            (b, x2, f2) = (x2, x1, f1);
            x1 = b - g * (b - a);
            f1 = f(x1)?;
        } else {
            (a, x1, f1) = (x1, x2, f2);
            x2 = a + g * (b - a);
            f2 = f(x2)?;
        }
    }
    f(a)?;
    f(b)?;
    // the largest value evaluated (where the band ends abruptly inside the bracket, as an
    // island of a voussoir arch does at its tip, the golden section closes on the edge and
    // its last points may lie beyond it)
    let Some((alpha, Some((ratio, mu, mu_ms, _)))) = log
        .iter()
        .filter(|(_, v)| v.is_some())
        .max_by(|p, q| value(&p.1).total_cmp(&value(&q.1)))
        .cloned()
    else {
        return Ok(None);
    };
    // the condition of the solved opening nearest the top on each side (within ~10⁻¹² of a
    // corner both conditions hold, and an end there may not be solved: one from further)
    let nearest = |left: bool| {
        log.iter()
            .filter(|(x, v)| v.is_some() && (*x < alpha) == left && *x != alpha)
            .min_by(|p, q| (p.0 - alpha).abs().total_cmp(&(q.0 - alpha).abs()))
            .and_then(|(_, v)| v.clone())
    };
    let (left, right) = (nearest(true), nearest(false));
    let name = |v: &Value| v.as_ref().map_or(NONE.into(), |v| v.3.clone());
    Ok(Some(BandTop {
        alpha,
        alpha_bracket: (a, b),
        mu,
        mu_ms,
        ratio,
        conditions: (name(&left), name(&right)),
        evaluations,
        ends,
    }))
}
