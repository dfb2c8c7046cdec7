//! The regions of the atlas as polygons of (α, μ): consecutive columns holding the same kinds
//! in the same order are joined run by run (the runs' ends, the located boundaries, joined
//! through the points traced between the columns where there are some, else by straight
//! segments); where the kinds of two neighbouring columns differ, each column's
//! runs hold up to the middle of the strip between them, or up to the band's tip on the
//! μ_ms curve where the boundary is traced to one. The lowest run starts on the μ_ms
//! curve, which the polygons follow through its points between the columns; below it, down
//! to μ = 0, lies the region without equilibrium.

use super::classify::Kind;
use super::column::{folded, Column, ColumnNotch};
use super::traced::Traced;

/// A polygon of (α, μ) vertices, closed (the last vertex joins the first).
type Polygon = Vec<[f64; 2]>;

/// Two openings closer than this are one (a strip's middle computed two ways).
const SAME_ALPHA: f64 = 1e-12;

/// Every region of `columns` (ascending in α; those without μ_ms left out); `top`, the top of
/// the non-unique band, is a vertex of the edge between `non_unique` and `unique` in the
/// strip that holds it.
pub(super) fn regions(
    columns: &[Column],
    traced: &[Option<Traced>],
    top: Option<[f64; 2]>,
) -> Vec<(Kind, Polygon)> {
    // the columns with μ_ms, each with the boundary traced from it
    let (cols, traced): (Vec<&Column>, Vec<Option<&Traced>>) = columns
        .iter()
        .zip(
            traced
                .iter()
                .map(Option::as_ref)
                .chain(std::iter::repeat(None)),
        )
        .filter(|c| c.0.mu_ms.is_some())
        .unzip();
    if cols.is_empty() {
        return Vec::new();
    }
    let (folded, notches): (Vec<Column>, Vec<Option<ColumnNotch>>) =
        cols.iter().map(|c| folded(c)).unzip();
    let cols: Vec<&Column> = folded.iter().collect();
    let curve = mu_ms_curve(&cols);
    let signature = |c: &Column| c.runs.iter().map(|r| r.0).collect::<Vec<_>>();
    let mut out = Vec::new();
    let mut i = 0;
    while i < cols.len() {
        let mut j = i;
        while j + 1 < cols.len() && signature(cols[j + 1]) == signature(cols[i]) {
            j += 1;
        }
        // the groups meet in the middle of the strip between them, or at a tip of the
        // band traced there
        let tip_of = |k: usize| traced[k].and_then(|t| t.tip.map(|p| (t, p)));
        let (before, left) = match i.checked_sub(1) {
            Some(k) => tip_of(k).map_or((None, 0.5 * (cols[k].alpha + cols[i].alpha)), |(t, p)| {
                (Some(t), p[0])
            }),
            None => (None, cols[i].alpha),
        };
        let right = match tip_of(j) {
            _ if j + 1 == cols.len() => cols[j].alpha,
            Some((_, p)) => p[0],
            None => 0.5 * (cols[j].alpha + cols[j + 1].alpha),
        };
        for (r, run) in cols[i].runs.iter().enumerate() {
            let Some(kind) = run.0 else {
                continue; // not decided: left out of every region
            };
            let group = (&cols[i..=j], &traced[i..=j], &notches[i..=j], before);
            let kind_of = |k: usize| cols[i].runs.get(k).and_then(|r| r.0);
            // the top of the band on the edge between non_unique (below) and unique
            let band = |below: usize| {
                top.filter(|_| {
                    below + 1 < cols[i].runs.len()
                        && kind_of(below) == Some(Kind::NonUnique)
                        && kind_of(below + 1) == Some(Kind::Unique)
                })
            };
            let lower = if r == 0 {
                on_curve(&curve, left, right)
            } else {
                with_vertex(
                    edge(group, (left, right), &curve, |c| c.runs[r].1),
                    r.checked_sub(1).and_then(band),
                )
            };
            let mut p = lower;
            p.extend(
                with_vertex(edge(group, (left, right), &curve, |c| c.runs[r].2), band(r))
                    .into_iter()
                    .rev(),
            );
            p.dedup();
            out.push((kind, p));
        }
        i = j + 1;
    }
    let mut below = vec![[cols[0].alpha, 0.0], [cols[cols.len() - 1].alpha, 0.0]];
    below.extend(curve.iter().rev());
    below.dedup();
    out.push((Kind::NoEquilibrium, below));
    out
}

/// The μ_ms curve through the columns and the points between them, ascending in α.
pub(super) fn mu_ms_curve(cols: &[&Column]) -> Vec<[f64; 2]> {
    cols.iter()
        .flat_map(|c| {
            std::iter::once([c.alpha, c.mu_ms.expect("columns with mu_ms")])
                .chain(c.mu_ms_between.iter().copied())
        })
        .collect()
}

/// The curve's points from α = `left` to `right`, ends included (a strip's middle is one of
/// them when the steps per strip are even; an end between two points, such as a tip, lies
/// on the chord between them).
fn on_curve(curve: &[[f64; 2]], left: f64, right: f64) -> Polygon {
    let inner: Vec<[f64; 2]> = curve
        .iter()
        .filter(|q| q[0] >= left - SAME_ALPHA && q[0] <= right + SAME_ALPHA)
        .copied()
        .collect();
    let mut p = vec![[left, interpolate(curve, left)]];
    p.extend(inner);
    p.push([right, interpolate(curve, right)]);
    p.dedup_by(|a, b| (a[0] - b[0]).abs() <= SAME_ALPHA && a[1] == b[1]);
    p
}

/// One edge of a group's run, left to right: `mu` at each column (with the points traced
/// from it to the next column where the edge is the boundary they trace), and out to `left`
/// and `right` at the same μ/μ_ms as at the nearest column, or where the edge is the
/// boundary traced to a tip of the band (`before` the group, or from its last column),
/// through the traced points to the tip.
fn edge(
    (group, traced, notches, before): Group,
    (left, right): (f64, f64),
    curve: &[[f64; 2]],
    mu: impl Fn(&Column) -> f64,
) -> Polygon {
    let held =
        |c: &Column, a: f64| mu(c) / c.mu_ms.expect("columns with mu_ms") * interpolate(curve, a);
    let (first, last) = (group[0], group[group.len() - 1]);
    let on_curve = |tip: [f64; 2]| [tip[0], interpolate(curve, tip[0])];
    let mut items: Vec<Item> = Vec::new();
    let start = match before.and_then(|t| Some((t, t.tip?))) {
        // the tip on the μ_ms curve as the lowest run's polygon has it
        Some((t, tip)) if t.to_mu == mu(first) => {
            items.extend(items_of(t));
            on_curve(tip)
        }
        _ => [left, held(first, left)],
    };
    for (k, c) in group.iter().enumerate() {
        // the column's own notch where this edge is the boundary above it
        let notch = notches[k].filter(|n| n.0 == mu(c)).map(|n| n.1);
        items.push((c.alpha, mu(c), notch));
        // the boundary traced from this column's point to the next one's
        let traced = traced[k].filter(|t| {
            group
                .get(k + 1)
                .is_some_and(|n| t.from_mu == mu(c) && t.to_mu == mu(n))
        });
        items.extend(traced.into_iter().flat_map(items_of));
    }
    let end = match traced[group.len() - 1].and_then(|t| Some((t, t.tip?))) {
        Some((t, tip)) if t.from_mu == mu(last) => {
            items.extend(items_of(t));
            on_curve(tip)
        }
        _ => [right, held(last, right)],
    };
    let mut p = vec![start];
    p.extend(path(&items));
    p.push(end);
    p.dedup();
    p
}

/// A run of consecutive columns with the same kinds: the columns, the boundaries traced
/// from each, their own notches, and the tip strip before the first.
type Group<'a> = (
    &'a [&'a Column],
    &'a [Option<&'a Traced>],
    &'a [Option<ColumnNotch>],
    Option<&'a Traced>,
);

/// A point of an edge: α, μ, and the notch of uniqueness below it (the lower branch's end,
/// the upper branch's birth), where there is one.
type Item = (f64, f64, Option<[f64; 2]>);

/// The points of a traced boundary as [`Item`]s.
fn items_of(t: &Traced) -> Vec<Item> {
    t.points
        .iter()
        .map(|q| {
            let notch = q.notch.as_ref().map(|n| [n.below.mu, n.birth.mu()]);
            (q.alpha, q.end.mu, notch)
        })
        .collect()
}

/// An edge's path through its points (the columns' and the traced ones), left to right:
/// through each point's μ, and for each run of consecutive points with a notch below them, along the run's lower ends, back
/// along its births and on along its upper ends (so each notch is a tongue of `unique`
/// reaching into the band).
fn path(items: &[Item]) -> Polygon {
    let mut p = Vec::new();
    let mut k = 0;
    while k < items.len() {
        let run = items[k..]
            .iter()
            .map_while(|q| q.2.map(|n| (q.0, n)))
            .collect::<Vec<_>>();
        if run.is_empty() {
            p.push([items[k].0, items[k].1]);
            k += 1;
            continue;
        }
        p.extend(run.iter().map(|(a, n)| [*a, n[0]]));
        p.extend(run.iter().rev().map(|(a, n)| [*a, n[1]]));
        p.extend(items[k..k + run.len()].iter().map(|q| [q.0, q.1]));
        k += run.len();
    }
    p
}

/// `edge` (left to right, turning back in α only along a notch) with `vertex` inserted into
/// the last of its segments whose span of α holds it strictly (the upper path, where a
/// notch turns back).
fn with_vertex(mut edge: Polygon, vertex: Option<[f64; 2]>) -> Polygon {
    if let Some(v) = vertex {
        let k = (1..edge.len())
            .rev()
            .find(|&k| edge[k - 1][0] < v[0] && v[0] < edge[k][0]);
        if let Some(k) = k {
            edge.insert(k, v);
        }
    }
    edge
}

/// The μ_ms curve's value at `alpha`, linear between its points (held at its ends).
pub(super) fn interpolate(curve: &[[f64; 2]], alpha: f64) -> f64 {
    if curve.len() == 1 {
        return curve[0][1];
    }
    let k = curve
        .partition_point(|p| p[0] < alpha)
        .clamp(1, curve.len() - 1);
    let (p, q) = (curve[k - 1], curve[k]);
    if q[0] == p[0] {
        return p[1];
    }
    let t = ((alpha - p[0]) / (q[0] - p[0])).clamp(0.0, 1.0);
    p[1] + (q[1] - p[1]) * t
}
