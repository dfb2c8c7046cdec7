//! The curve tracer, written once over a parametric problem: a curve t(μ) of a problem
//! family (η_s(μ) of the thickness problem, λ(μ) of the load problem at a fixed η) is
//! sampled in μ, each sample keyed by its branch (the pattern of its least state), and every
//! change of branch between two samples on different branches is located: exactly where the
//! problem can (Newton in (t, μ) on the union of both sides' patterns), else by bisection in
//! μ on the key, a third branch met on the way bracketed in turn. The problem says how to
//! sample, key, split a bracket and locate a change exactly ([`Problem`]); the tracer
//! gives back one [`Corner`] type for every problem.

use crate::statics::Reactions;

/// A change of branch of a curve t(μ), located: exactly (Newton in (t, μ)) or only
/// bracketed in μ. `S` is what the problem knows of each side, `P` a contact of its
/// pattern, `D` what else it says of the corner.
#[derive(Debug, Clone)]
pub struct Corner<S, P, D> {
    /// Friction coefficient (∞ for the asymptote of a branch; where only bracketed, a
    /// point of the bracket).
    pub mu: f64,
    /// The family's parameter t there (η, or λ; NaN where not located).
    pub t: f64,
    /// Reactions of the corner state.
    pub x: Reactions,
    /// Every contact active at the corner, by increasing β.
    pub pattern: Vec<P>,
    /// True when located by Newton and verified; false when only bracketed in μ.
    pub exact: bool,
    /// Scaled Newton residual (0 for a corner at infinity, NaN where not located).
    pub residual: f64,
    /// The curve on either side: [lower μ, higher μ].
    pub sides: [S; 2],
    /// What the problem says of the corner besides.
    pub detail: D,
}

/// How a bracket of two samples on different branches is split.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Split {
    /// Sample the curve at this μ, strictly inside the bracket.
    At(f64),
    /// Stop: the change is only bracketed (`tight`: by neighbouring floats).
    Stop {
        /// The bracket's ends are neighbouring floats.
        tight: bool,
    },
}

/// What a parametric problem gives the tracer.
pub trait Problem {
    /// A point of the curve: μ and the answer there.
    type Sample;
    /// What stays the same along a branch.
    type Key: PartialEq;
    /// A located change of branch.
    type Corner;
    /// Why the curve cannot be sampled (the trace stops).
    type Error;
    /// The branch of a sample.
    fn key(&self, s: &Self::Sample) -> Self::Key;
    /// Where to split the bracket `a`, `b` (samples on different branches) after `depth`
    /// more levels may be spent, or that it is not split further.
    fn split(&mut self, a: &Self::Sample, b: &Self::Sample, depth: usize) -> Split;
    /// The curve at `mu` inside the bracket `a`, `b` (`None`: no sample there).
    fn sample(
        &mut self,
        mu: f64,
        a: &Self::Sample,
        b: &Self::Sample,
    ) -> Result<Option<Self::Sample>, Self::Error>;
    /// The change between `a` and `b` located exactly, where the problem can.
    fn exact(&mut self, a: &Self::Sample, b: &Self::Sample) -> Option<Self::Corner>;
    /// The change known only to lie between `a` and `b`.
    fn bracketed(&mut self, a: &Self::Sample, b: &Self::Sample, tight: bool) -> Self::Corner;
    /// Further changes near those `found` between `a` and `b` (a short branch beside a
    /// corner that no sample saw); none unless the problem looks.
    fn beside(
        &mut self,
        a: &Self::Sample,
        b: &Self::Sample,
        found: &[Self::Corner],
        depth: usize,
    ) -> Result<Vec<Self::Corner>, Self::Error> {
        let _ = (a, b, found, depth);
        Ok(Vec::new())
    }
}

/// Every change of branch between the samples `a` and `b` (on different branches), in
/// order from `a` to `b`: the one located exactly, or else the bracket bisected — a sample
/// on `a`'s branch or `b`'s narrows it, one on a third branch splits it in two — until the
/// problem stops the split; then whatever the problem finds beside them.
pub fn locate<P: Problem>(
    p: &mut P,
    a: &P::Sample,
    b: &P::Sample,
    depth: usize,
) -> Result<Vec<P::Corner>, P::Error> {
    let mut out = match p.exact(a, b) {
        Some(c) => vec![c],
        None => bisect(p, a, b, depth)?,
    };
    let more = p.beside(a, b, &out, depth)?;
    out.extend(more);
    Ok(out)
}

/// One bisection step of [`locate`].
fn bisect<P: Problem>(
    p: &mut P,
    a: &P::Sample,
    b: &P::Sample,
    depth: usize,
) -> Result<Vec<P::Corner>, P::Error> {
    let mid = match p.split(a, b, depth) {
        Split::At(mid) => mid,
        Split::Stop { tight } => return Ok(vec![p.bracketed(a, b, tight)]),
    };
    let Some(m) = p.sample(mid, a, b)? else {
        return Ok(vec![p.bracketed(a, b, false)]);
    };
    let (k, deeper) = (p.key(&m), depth.saturating_sub(1));
    if k == p.key(a) {
        locate(p, &m, b, deeper)
    } else if k == p.key(b) {
        locate(p, a, &m, deeper)
    } else {
        let mut out = locate(p, a, &m, deeper)?;
        out.extend(locate(p, &m, b, deeper)?);
        Ok(out)
    }
}
