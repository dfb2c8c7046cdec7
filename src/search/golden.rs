//! Golden-section search for the least value of a function taken as unimodal on an
//! interval (no derivative: a minimum at a kink is found as well as a smooth one).

/// The golden ratio's conjugate, (√5 − 1)/2: each step keeps this fraction of the bracket.
const G: f64 = 0.618_033_988_749_894_8;

/// Searches [lo, hi] for the least `value` of `f` until the bracket is narrower than
/// `rel` · hi, or until `done` accepts a probe (checked for both inner probes before each
/// step). Returns that probe, else the probe of least value seen (`None` when no step
/// probed); an error of `f` ends the search.
pub fn golden_min<T: Clone, E>(
    (mut lo, mut hi): (f64, f64),
    rel: f64,
    mut f: impl FnMut(f64) -> Result<T, E>,
    value: impl Fn(&T) -> f64,
    done: impl Fn(&T) -> bool,
) -> Result<Option<(f64, T)>, E> {
    let (mut c, mut d) = (hi - G * (hi - lo), lo + G * (hi - lo));
    let (mut fc, mut fd) = (f(c)?, f(d)?);
    let mut best: Option<(f64, T)> = None;
    let keep = |x: f64, t: &T, best: &mut Option<(f64, T)>| {
        if best.as_ref().is_none_or(|b| value(t) < value(&b.1)) {
            *best = Some((x, t.clone()));
        }
    };
    keep(c, &fc, &mut best);
    keep(d, &fd, &mut best);
    while hi - lo > rel * hi {
        for (x, t) in [(c, &fc), (d, &fd)] {
            if done(t) {
                return Ok(Some((x, t.clone())));
            }
        }
        if value(&fc) <= value(&fd) {
            (hi, d, fd) = (d, c, fc);
            c = hi - G * (hi - lo);
            fc = f(c)?;
            keep(c, &fc, &mut best);
        } else {
            (lo, c, fc) = (c, d, fd);
            d = lo + G * (hi - lo);
            fd = f(d)?;
            keep(d, &fd, &mut best);
        }
    }
    Ok(best)
}
