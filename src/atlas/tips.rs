//! Where a kind begins or ends along the μ_ms curve: between two columns whose first samples
//! (μ = μ_ms (1 + 10⁻⁶)) differ in kind, the opening is bisected to neighbouring floats, each
//! step classifying the arch at its own μ_ms (1 + 10⁻⁶). The tips of a band that touches
//! μ_ms, to the last float of α.

use super::classify::{classify, Kind};
use super::column::{Column, Rectangle, FIRST_OFFSET};
use crate::arch::InputError;
use crate::friction::friction_limit;
use crate::settings::Settings;

/// Bisections in α stop after this many steps (neighbouring floats come first).
const MAX_STEPS: usize = 80;

/// A change of kind along the μ_ms curve.
#[derive(Debug, Clone)]
pub struct Tip {
    /// The kinds at the smaller and at the larger opening.
    pub between: [Kind; 2],
    /// The last opening of the first kind and the first of the second.
    pub alpha: (f64, f64),
    /// μ_ms at the middle of the bracket.
    pub mu_ms: f64,
    /// Whether the bracket's ends are neighbouring floats (else: why it stopped).
    pub stopped: Option<String>,
}

/// The kind at `alpha` just above its own μ_ms (`None`: no μ_ms, or undecided).
fn kind_at(
    rect: &Rectangle,
    alpha: f64,
    settings: &Settings,
) -> Result<Option<(Kind, f64)>, InputError> {
    let arch = rect.arch(alpha)?;
    let Some(l) = friction_limit(&arch, settings).ok().flatten() else {
        return Ok(None);
    };
    let mu = l.mu * (1.0 + FIRST_OFFSET);
    Ok(classify(&arch, mu, settings)?.ok().map(|(k, _)| (k, l.mu)))
}

/// Every tip between consecutive columns whose first samples differ in kind.
pub(super) fn tips(
    rect: &Rectangle,
    columns: &[Column],
    settings: &Settings,
) -> Result<Vec<Tip>, InputError> {
    let first = |c: &Column| {
        c.samples
            .first()
            .and_then(|s| s.kind.as_ref().ok())
            .map(|k| k.0)
    };
    let mut out = Vec::new();
    for w in columns.windows(2) {
        let (Some(ka), Some(kb)) = (first(&w[0]), first(&w[1])) else {
            continue;
        };
        if ka == kb {
            continue;
        }
        let (mut lo, mut hi) = (w[0].alpha, w[1].alpha);
        let mut stopped = Some(format!("{MAX_STEPS} bisections"));
        for _ in 0..MAX_STEPS {
            let m = 0.5 * (lo + hi);
            if m <= lo || m >= hi {
                stopped = None;
                break;
            }
            match kind_at(rect, m, settings)? {
                Some((k, _)) if k == ka => lo = m,
                Some((k, _)) if k == kb => hi = m,
                Some((k, _)) => {
                    stopped = Some(format!("a third kind ({}) at alpha = {m}", k.name()));
                    break;
                }
                None => {
                    stopped = Some(format!("undecided at alpha = {m}"));
                    break;
                }
            }
        }
        let mid = 0.5 * (lo + hi);
        let mu_ms = friction_limit(&rect.arch(mid)?, settings)
            .ok()
            .flatten()
            .map_or(f64::NAN, |l| l.mu);
        out.push(Tip {
            between: [ka, kb],
            alpha: (lo, hi),
            mu_ms,
            stopped,
        });
    }
    Ok(out)
}
