//! The two sides of a bracket, found in floating point and then proved by the verifier: a
//! state moved strictly inside the admissible set (a margin LP), and a Farkas combination of
//! d + 1 rows chosen by its float cofactors.

use super::loaded::Loaded;
use crate::arch::{Arch, JointLayout};
use crate::contact::Contact;
use crate::lp;
use crate::settings::Settings;
use crate::statics::{Affine, Reactions};
use itertools::Itertools;

/// Tries the brackets [lo, hi] around `s` at relative gaps g = `gap`, 10 `gap`, … up to
/// 1e-4: hi = s (1 + g/2), lo = s (1 − g/2) raised by ulps while `wide(lo, hi, g)` (the gap
/// as computed in floating point must not exceed g: rounding of the two ends could
/// otherwise push it over by a few ulps); returns the first answer of `attempt(lo, hi)`.
pub(super) fn widening<T>(
    s: f64,
    gap: f64,
    wide: impl Fn(f64, f64, f64) -> bool,
    mut attempt: impl FnMut(f64, f64) -> Option<T>,
) -> Option<T> {
    let mut g = gap.max(1e-15);
    while g <= 1e-4 {
        let hi = s * (1.0 + 0.5 * g);
        let mut lo = s * (1.0 - 0.5 * g);
        while wide(lo, hi, g) {
            lo = lo.next_up();
        }
        if let Some(t) = attempt(lo, hi) {
            return Some(t);
        }
        g *= 10.0;
    }
    None
}

/// The Farkas pool of a bracket: the active contacts, and on a continuous arch the interior
/// tangencies also as chords β ± δ.
pub(super) fn chord_pool(arch: &Arch, pattern: &[Loaded]) -> Vec<Loaded> {
    let mut pool: Vec<Loaded> = pattern.to_vec();
    if matches!(arch.layout(), JointLayout::Continuous) {
        for &(c, side) in pattern {
            if c.free {
                for delta in [1e-2, 1e-3, 1e-4] {
                    for b in [c.beta - delta, c.beta + delta] {
                        if b > arch.beta_right() && b < arch.beta_left() {
                            pool.push((Contact { beta: b, ..c }, side));
                        }
                    }
                }
            }
        }
    }
    pool
}

/// An affine function of d unknowns (d = 2, 3 or 4): `g · u + c`.
#[derive(Debug, Clone)]
pub(super) struct Row {
    /// Gradient (the first d components are used).
    pub(super) g: Vec<f64>,
    /// Constant term.
    pub(super) c: f64,
}

impl From<Affine> for Row {
    fn from(a: Affine) -> Row {
        Row {
            g: a.g.to_vec(),
            c: a.c,
        }
    }
}

/// Float cofactor multipliers of d + 1 affine functions (gradients in the first d
/// components, d ≤ 4), normalised to sum 1 when they share a sign, with the Farkas
/// constant. Allocates only for an answer: it runs on every (d+1)-subset of a pool.
fn farkas_float(rows: &[&Row], d: usize) -> Option<(Vec<f64>, f64)> {
    let mut y = [0.0; 5];
    for (i, yi) in y.iter_mut().enumerate().take(d + 1) {
        // the rows other than i
        let col = |k: usize| if k < i { k } else { k + 1 };
        let sign = if i % 2 == 0 { 1.0 } else { -1.0 };
        *yi = sign
            * match d {
                4 => {
                    let g = |k: usize, r: usize| rows[col(k)].g[r];
                    nalgebra::Matrix4::from_fn(|r, k| g(k, r)).determinant()
                }
                3 => minor3([rows[col(0)], rows[col(1)], rows[col(2)]]),
                _ => {
                    let g = |k: usize, r: usize| rows[col(k)].g[r];
                    nalgebra::Matrix2::from_fn(|r, k| g(k, r)).determinant()
                }
            };
    }
    normalised(&y[..=d], rows)
}

/// The determinant of three gradients (as columns, in their order).
fn minor3(rows: [&Row; 3]) -> f64 {
    nalgebra::Matrix3::from_fn(|r, k| rows[k].g[r]).determinant()
}

/// The Farkas combination of `rows` with the cofactors `y`, normalised to sum 1, when they
/// share a sign and its constant is positive.
fn normalised(y: &[f64], rows: &[&Row]) -> Option<(Vec<f64>, f64)> {
    let total: f64 = y.iter().sum();
    if total == 0.0 || !y.iter().all(|v| v * total > 0.0) {
        return None;
    }
    let y: Vec<f64> = y.iter().map(|v| v / total).collect();
    let c: f64 = y.iter().zip(rows).map(|(a, r)| a * r.c).sum();
    (c > 0.0).then_some((y, c))
}

/// Searches `pool` (labels and their rows) for a (d+1)-subset with a valid float Farkas
/// combination, best margin first, and returns the first (labels with their multipliers)
/// that `check` accepts (the verifier proves).
pub(super) fn find_farkas<T: Clone>(
    pool: &[(T, Row)],
    d: usize,
    check: impl Fn(&[(T, f64)]) -> bool,
) -> Option<Vec<(T, f64)>> {
    let mut found: Vec<(f64, Vec<usize>, Vec<f64>)> = Vec::new();
    let mut keep = |sub: &[usize], (y, c): (Vec<f64>, f64)| {
        let norm: f64 = y
            .iter()
            .zip(sub)
            .map(|(a, &i)| a * pool[i].1.c.abs())
            .sum::<f64>()
            .max(f64::MIN_POSITIVE);
        found.push((c / norm, sub.to_vec(), y));
    };
    if d == 3 && pool.len() <= MINOR_TABLE_MOST {
        quadruples(pool, &mut keep);
    } else {
        for sub in (0..pool.len()).combinations(d + 1) {
            let mut buf = [&pool[0].1; 5];
            for (slot, &i) in buf.iter_mut().zip(&sub) {
                *slot = &pool[i].1;
            }
            if let Some(f) = farkas_float(&buf[..=d], d) {
                keep(&sub, f);
            }
        }
    }
    found.sort_by(|a, b| b.0.total_cmp(&a.0));
    found.into_iter().take(12).find_map(|(_, sub, y)| {
        let labelled: Vec<(T, f64)> = sub
            .iter()
            .zip(&y)
            .map(|(&i, &y)| (pool[i].0.clone(), y))
            .collect();
        check(&labelled).then_some(labelled)
    })
}

/// Pools of at most this many rows in three unknowns tabulate their 3 × 3 minors (n³
/// numbers) once, instead of four per 4-subset.
const MINOR_TABLE_MOST: usize = 160;

/// Every 4-subset (ascending, in the order of `combinations`) of a pool of rows in three
/// unknowns with a valid float Farkas combination, handed to `keep`: the cofactors are
/// looked up in a table of the pool's 3 × 3 minors, each computed once (the same numbers
/// as [`farkas_float`]'s).
fn quadruples<T>(pool: &[(T, Row)], keep: &mut impl FnMut(&[usize], (Vec<f64>, f64))) {
    let n = pool.len();
    let mut minors = vec![0.0; n * n * n];
    let at = |a: usize, b: usize, c: usize| (a * n + b) * n + c;
    for (a, b, c) in (0..n).tuple_combinations() {
        minors[at(a, b, c)] = minor3([&pool[a].1, &pool[b].1, &pool[c].1]);
    }
    for (a, b, c, e) in (0..n).tuple_combinations() {
        let y = [
            minors[at(b, c, e)],
            -minors[at(a, c, e)],
            minors[at(a, b, e)],
            -minors[at(a, b, c)],
        ];
        let rows = [&pool[a].1, &pool[b].1, &pool[c].1, &pool[e].1];
        if let Some(f) = normalised(&y, &rows) {
            keep(&[a, b, c, e], f);
        }
    }
}

/// The rows of `pool` that `keep` accepts, with the coordinates `drop` left out: they do
/// not enter those rows (w in the sliding rows: T and N do not involve it; λ in the rows of
/// sections that do not carry the point load, or, through x − λ d, in all that do), so a
/// Farkas certificate among them is that much lower in dimension.
pub(super) fn reduced<T: Clone>(
    pool: &[(T, Row)],
    keep: impl Fn(&T) -> bool,
    drop: &[usize],
) -> Vec<(T, Row)> {
    pool.iter()
        .filter(|(l, _)| keep(l))
        .map(|(l, r)| {
            let g =
                r.g.iter()
                    .enumerate()
                    .filter(|(k, _)| !drop.contains(k))
                    .map(|(_, v)| *v)
                    .collect();
            (l.clone(), Row { g, c: r.c })
        })
        .collect()
}

/// A state near `x_s` strictly inside the `rows` (affine in x, at the target parameter):
/// the margin LP in the displacement δ with every row's value at x_s scaled by `k`
/// (1 over the parameter step, so that the LP works with O(1) numbers).
pub(super) fn move_inside(
    rows: &[Affine],
    x_s: Reactions,
    k: f64,
    settings: &Settings,
) -> Option<Reactions> {
    let rows: Vec<Affine> = rows
        .iter()
        .map(|a| Affine {
            g: a.g,
            c: k * a.at(&x_s),
        })
        .collect();
    let (d, s) = lp::max_margin(&rows, 1.0, settings).ok()?;
    if s.is_nan() || s <= 0.0 {
        return None;
    }
    Some([x_s[0] + d[0] / k, x_s[1] + d[1] / k, x_s[2] + d[2] / k])
}
