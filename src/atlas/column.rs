//! One column of the atlas: an opening α, its μ_ms, the samples in μ classified, the changes
//! of kind located by bisection, and the runs of one kind they bound.

use super::certified::certified_kind;
use super::classify::{classify, Classified, Kind};
use crate::arch::{Arch, InputError, WeightModel};
use crate::friction::friction_limit;
use crate::settings::Settings;

/// What the atlas covers.
#[derive(Debug, Clone, Copy)]
pub struct Rectangle {
    /// The least opening (radians).
    pub alpha_min: f64,
    /// The largest opening.
    pub alpha_max: f64,
    /// μ runs from μ_ms(α) to this times μ_ms(α).
    pub mu_max_factor: f64,
    /// Where the weight acts.
    pub weight: WeightModel,
    /// Equal voussoirs, or a continuous arch.
    pub blocks: Option<usize>,
    /// Columns (openings), evenly spaced, ≥ 2.
    pub columns: usize,
    /// Samples of μ per column, ≥ 2.
    pub samples: usize,
    /// Certify (and verify) the ends of every located bracket and one sample per run.
    pub certify: bool,
}

impl Rectangle {
    /// The arch of opening `alpha`.
    pub fn arch(&self, alpha: f64) -> Result<Arch, InputError> {
        let a = Arch::symmetric(alpha, self.weight)?;
        match self.blocks {
            Some(n) => a.with_blocks(n),
            None => Ok(a),
        }
    }

    /// The openings of the columns.
    pub fn alphas(&self) -> Vec<f64> {
        let n = self.columns.max(2);
        (0..n)
            .map(|k| self.alpha_min + (self.alpha_max - self.alpha_min) * k as f64 / (n - 1) as f64)
            .collect()
    }

    /// The μ samples of a column whose μ_ms is `mu_ms`: μ_ms (1 + d), d geometric from
    /// [`FIRST_OFFSET`] to K − 1.
    pub fn mus(&self, mu_ms: f64) -> Vec<f64> {
        let n = self.samples.max(2);
        let top = self.mu_max_factor - 1.0;
        (0..n)
            .map(|j| {
                let d = FIRST_OFFSET * (top / FIRST_OFFSET).powf(j as f64 / (n - 1) as f64);
                mu_ms * (1.0 + d)
            })
            .collect()
    }

    /// Checks the ranges, naming the argument.
    pub fn check(&self) -> Result<(), InputError> {
        let bad = |arg: &'static str, value: f64, range: &str| InputError::OutOfRange {
            arg,
            value: crate::arch::fmt_value(value),
            range: range.into(),
        };
        for (arg, a) in [
            ("--alpha-min", self.alpha_min),
            ("--alpha-max", self.alpha_max),
        ] {
            if a.is_nan() || a.abs() >= std::f64::consts::FRAC_PI_2 {
                return Err(bad(arg, a, "(-pi/2, pi/2) radians"));
            }
        }
        if self.alpha_max.is_nan() || self.alpha_max <= self.alpha_min {
            return Err(bad("--alpha-max", self.alpha_max, "above --alpha-min"));
        }
        if !(self.mu_max_factor > 1.0 + 10.0 * FIRST_OFFSET && self.mu_max_factor <= 1e6) {
            return Err(bad("--mu-max-factor", self.mu_max_factor, "(1.00001, 1e6]"));
        }
        if !(2..=2000).contains(&self.columns) {
            return Err(bad(
                "--columns",
                self.columns as f64,
                "whole numbers 2 to 2000",
            ));
        }
        if !(2..=2000).contains(&self.samples) {
            return Err(bad(
                "--samples",
                self.samples as f64,
                "whole numbers 2 to 2000",
            ));
        }
        Ok(())
    }
}

/// The first sample of a column lies this far above μ_ms (relative): at μ_ms itself every
/// thickness from η_s up is a limit state (the vertical branch).
pub const FIRST_OFFSET: f64 = 1e-6;

/// μ_ms bracketed by two verified certificates (see [`Column::mu_ms_certified`]).
#[derive(Debug, Clone, Copy)]
pub struct MuMsCertified {
    /// μ_ms (1 − δ) and μ_ms (1 + δ).
    pub bracket: (f64, f64),
    /// Whether the verifier proved the list of limit states at the upper end complete.
    pub complete: bool,
}

/// The relative half-width of the certified bracket of μ_ms (the sample just above μ_ms
/// lies at [`FIRST_OFFSET`]).
pub const MU_MS_BRACKET: f64 = 1e-6;

/// Bisections of one bracket stop after this many steps (neighbouring floats come first:
/// about 50 from the samples' spacing).
const MAX_BISECTIONS: usize = 80;

/// A change of kind located between two floats of μ at one α.
#[derive(Debug, Clone)]
pub struct BoundaryPoint {
    /// The opening.
    pub alpha: f64,
    /// The kinds below and above.
    pub between: [Kind; 2],
    /// The last μ of the lower kind and the first of the upper one.
    pub bracket: (f64, f64),
    /// Whether the bracket's ends are neighbouring floats (else the bisection stopped at a
    /// sample the search did not decide, or at its step limit).
    pub tight: bool,
    /// Why the bisection stopped short of neighbouring floats, if it did.
    pub stopped: Option<String>,
    /// With [`Rectangle::certify`]: verified certificates at the bracket's two ends state the
    /// two kinds (`Ok`, true where the verifier proved both lists of limit states complete,
    /// false where it only checked the listed states), or why not (`Err`).
    pub certified: Option<Result<bool, String>>,
}

impl BoundaryPoint {
    /// The point's μ: the middle of its bracket.
    pub fn mu(&self) -> f64 {
        0.5 * (self.bracket.0 + self.bracket.1)
    }
}

/// One sample of a column.
#[derive(Debug, Clone)]
pub struct Sample {
    /// Friction coefficient.
    pub mu: f64,
    /// Its classification.
    pub kind: Classified,
}

/// One opening: μ_ms, the samples, the changes of kind and the runs they bound.
#[derive(Debug, Clone)]
pub struct Column {
    /// The opening.
    pub alpha: f64,
    /// μ_ms(α) (`None`: no finite μ gives equilibrium; the column is left out).
    pub mu_ms: Option<f64>,
    /// Whether μ_ms is exact (a verified pattern).
    pub mu_ms_exact: bool,
    /// The samples, ascending in μ.
    pub samples: Vec<Sample>,
    /// The changes of kind, ascending in μ.
    pub boundaries: Vec<BoundaryPoint>,
    /// Maximal runs of one kind: (kind, μ from, μ to), from μ_ms to K μ_ms; `None` for a
    /// stretch the search did not decide.
    pub runs: Vec<(Option<Kind>, f64, f64)>,
    /// With [`Rectangle::certify`], one per run: a sample inside it and whether a verified
    /// certificate there states the run's kind (`Ok(complete)` as for a bracket; `Err`: why
    /// not).
    pub runs_certified: Vec<(f64, Result<bool, String>)>,
    /// With [`Rectangle::certify`]: μ_ms in a bracket [μ_ms (1 − δ), μ_ms (1 + δ)] (δ =
    /// [`MU_MS_BRACKET`]) whose ends verified certificates state as no equilibrium and as the
    /// first run's kind, with whether both lists were proved complete (`Err`: why not).
    pub mu_ms_certified: Option<Result<MuMsCertified, String>>,
    /// (α, μ_ms(α)) at [`CURVE_STEPS`] − 1 openings between this column and the next (none
    /// after the last): the μ_ms curve between columns, which the regions follow.
    pub mu_ms_between: Vec<[f64; 2]>,
}

/// The μ_ms curve is evaluated at this many steps per strip between columns: at the default
/// spacing (0.05 rad) its chords then lie within ~5e-6 of it, relative (the other boundaries
/// are joined by straight segments). Even, so that a strip's middle is one of the points.
pub const CURVE_STEPS: usize = 16;

/// One column at `alpha` (`next`: the following column's opening): μ_ms, the samples, the
/// located changes, the runs, and the μ_ms curve up to the next column.
pub(super) fn column(
    rect: &Rectangle,
    (alpha, next): (f64, Option<f64>),
    settings: &Settings,
) -> Result<Column, InputError> {
    let arch = rect.arch(alpha)?;
    let limit = friction_limit(&arch, settings).ok().flatten();
    let mut col = Column {
        alpha,
        mu_ms: limit.as_ref().map(|l| l.mu),
        mu_ms_exact: limit.as_ref().is_some_and(|l| l.exact),
        samples: Vec::new(),
        boundaries: Vec::new(),
        runs: Vec::new(),
        runs_certified: Vec::new(),
        mu_ms_certified: None,
        mu_ms_between: Vec::new(),
    };
    if let Some(next) = next {
        for i in 1..CURVE_STEPS {
            let a = alpha + (next - alpha) * i as f64 / CURVE_STEPS as f64;
            if let Some(l) = friction_limit(&rect.arch(a)?, settings).ok().flatten() {
                col.mu_ms_between.push([a, l.mu]);
            }
        }
    }
    let Some(mu_ms) = col.mu_ms else {
        return Ok(col);
    };
    for mu in rect.mus(mu_ms) {
        let kind = classify(&arch, mu, settings)?;
        col.samples.push(Sample { mu, kind });
    }
    let kind_of = |s: &Sample| s.kind.as_ref().ok().map(|k| k.0);
    for w in 0..col.samples.len() - 1 {
        let (a, b) = (&col.samples[w], &col.samples[w + 1]);
        if let (Some(ka), Some(kb)) = (kind_of(a), kind_of(b)) {
            if ka != kb {
                locate(
                    &arch,
                    alpha,
                    (a.mu, ka),
                    (b.mu, kb),
                    settings,
                    &mut col.boundaries,
                    0,
                )?;
            }
        }
    }
    col.runs = runs(&col, rect.mu_max_factor);
    if rect.certify {
        certify_column(&arch, &mut col, settings);
    }
    Ok(col)
}

/// The certificates of a column: both ends of every located bracket, and the middle sample
/// of every decided run.
fn certify_column(arch: &Arch, col: &mut Column, settings: &Settings) {
    let holds = |mu: f64, want: Kind| match certified_kind(arch, mu, settings) {
        Ok((k, complete)) if k == want => Ok(complete),
        Ok((k, _)) => Err(format!("the certificate at mu = {mu} states {}", k.name())),
        Err(e) => Err(format!("at mu = {mu}: {e}")),
    };
    let both = |a: Result<bool, String>, b: Result<bool, String>| Ok(a? && b?);
    if let (Some(ms), Some((Some(first), _, _))) = (col.mu_ms, col.runs.first()) {
        let (lo, hi) = (ms * (1.0 - MU_MS_BRACKET), ms * (1.0 + MU_MS_BRACKET));
        col.mu_ms_certified = Some(both(holds(lo, Kind::NoEquilibrium), holds(hi, *first)).map(
            |complete| MuMsCertified {
                bracket: (lo, hi),
                complete,
            },
        ));
    }
    for p in &mut col.boundaries {
        let (lo, hi) = p.bracket;
        p.certified = Some(both(holds(lo, p.between[0]), holds(hi, p.between[1])));
    }
    for &(kind, from, to) in &col.runs {
        let Some(kind) = kind else { continue };
        let inside: Vec<f64> = col
            .samples
            .iter()
            .filter(|s| s.mu > from && s.mu < to && s.kind.is_ok())
            .map(|s| s.mu)
            .collect();
        if let Some(&mu) = inside.get(inside.len() / 2) {
            col.runs_certified.push((mu, holds(mu, kind)));
        }
    }
}

/// Bisects [lo, hi] between kinds `ka` (at lo) and `kb` (at hi) down to neighbouring floats;
/// a third kind met in between splits the bracket in two.
fn locate(
    arch: &Arch,
    alpha: f64,
    (mut lo, ka): (f64, Kind),
    (mut hi, kb): (f64, Kind),
    settings: &Settings,
    out: &mut Vec<BoundaryPoint>,
    depth: usize,
) -> Result<(), InputError> {
    let mut tight = false;
    let mut stopped = Some(format!("{MAX_BISECTIONS} bisections"));
    for _ in 0..MAX_BISECTIONS {
        let m = 0.5 * (lo + hi);
        if m <= lo || m >= hi {
            (tight, stopped) = (true, None);
            break;
        }
        match classify(arch, m, settings)? {
            Ok((k, _)) if k == ka => lo = m,
            Ok((k, _)) if k == kb => hi = m,
            Ok((k, _)) if depth < 4 => {
                locate(arch, alpha, (lo, ka), (m, k), settings, out, depth + 1)?;
                return locate(arch, alpha, (m, k), (hi, kb), settings, out, depth + 1);
            }
            Ok((k, _)) => {
                stopped = Some(format!("a fourth kind ({}) inside the bracket", k.name()));
                break;
            }
            Err(e) => {
                stopped = Some(format!("undecided at mu = {m}: {e}"));
                break;
            }
        }
    }
    out.push(BoundaryPoint {
        alpha,
        between: [ka, kb],
        bracket: (lo, hi),
        tight,
        stopped,
        certified: None,
    });
    Ok(())
}

/// The runs of a column from μ_ms to K μ_ms: each sample's kind (an undecided sample is a
/// run of its own, `None`), cut at the located boundaries.
fn runs(col: &Column, factor: f64) -> Vec<(Option<Kind>, f64, f64)> {
    let Some(mu_ms) = col.mu_ms else {
        return Vec::new();
    };
    let mut out: Vec<(Option<Kind>, f64, f64)> = Vec::new();
    let mut b = col.boundaries.iter().peekable();
    for s in &col.samples {
        let k = s.kind.as_ref().ok().map(|k| k.0);
        // the boundaries below this sample close the runs before it
        while let Some(p) = b.next_if(|p| p.bracket.1 <= s.mu) {
            if let Some(last) = out.last_mut() {
                last.2 = p.mu();
            }
            out.push((Some(p.between[1]), p.mu(), p.mu()));
        }
        match out.last_mut() {
            Some(last) if last.0 == k => last.2 = s.mu,
            Some(last) => {
                let cut = 0.5 * (last.2 + s.mu);
                last.2 = cut;
                out.push((k, cut, s.mu));
            }
            None => out.push((k, mu_ms, s.mu)),
        }
    }
    if let Some(last) = out.last_mut() {
        last.2 = factor * mu_ms;
    }
    out.retain(|r| r.2 > r.1);
    out
}
