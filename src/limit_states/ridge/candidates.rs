//! Every point of the ridge over ∂Q where a limit state may be: the apexes of Q (V2) and
//! the points the walk along each sliding edge returns (V, E1, E2), once Q is known to
//! satisfy G1 where the ridge needs it: no sliding lines through a vertex that could carry
//! a mechanism without hinge rates, none along an edge there, none beside a short edge.

use super::near::{verify, Bounds, EdgeView, JointTree, Verdict};
use super::polygon::{lines, on_box, q_polygon, Line};
use super::rows::{ev, hinge_rows, hinge_rows_of, in_band, Candidate, HingeRow, JointRows, TOL};
use super::walk::{walk_edge, Walked};
use crate::arch::ETA_TOP;
use crate::contact::ContactKind;
use crate::kinematics::column;
use crate::undecided::Undecided;
use std::f64::consts::{PI, TAU};

/// An edge of Q shorter (ℓ₁) than this times 1 + the size of its start is not walked.
const SHORT_EDGE_REL: f64 = 1e-12;

/// A vertex of Q with the index (in the lines) of the edge that leaves it.
type QVertex = ([f64; 2], usize);

/// 1 + |h| + |v|: the size the walk's tests at p are relative to.
fn scale(p: [f64; 2]) -> f64 {
    1.0 + p[0].abs() + p[1].abs()
}

/// Every candidate on the ridge with η in (eta_lo, ETA_TOP), and the subsets of joints
/// their `near` indices name.
pub(super) fn candidates(
    js: &[JointRows],
    mu: f64,
    eta_lo: f64,
) -> Result<(Vec<Candidate>, Vec<Vec<usize>>), Undecided> {
    candidates_walked(js, mu, eta_lo, js.len() <= WHOLE_ARCH_JOINTS)
}

/// [`candidates`], the arch walked whole (one chunk with every joint) or in chunks.
fn candidates_walked(
    js: &[JointRows],
    mu: f64,
    eta_lo: f64,
    whole: bool,
) -> Result<(Vec<Candidate>, Vec<Vec<usize>>), Undecided> {
    let lines = lines(js, mu);
    let poly = q_polygon(&lines);
    if poly.len() < 3 {
        return Err(Undecided::Resolution(
            "the friction polygon Q has no interior".into(),
        ));
    }
    let in_range = |eta: f64| eta > eta_lo && eta < ETA_TOP;
    let mut out = Vec::new();
    let subsets = along_edges(js, (&lines, &poly), (&in_range, whole), mu, &mut out)?;
    let mut all = apexes(js, &lines, &poly, &in_range);
    all.append(&mut out);
    Ok((all, subsets))
}

/// G1 counts a sliding line through a vertex q of Q when |a · q + b| is below this times
/// |a|₁ (1 + |h| + |v|): about 100 times the candidates' own activity tolerance (`adm_tol`,
/// 10⁻¹² of the row's magnitude (1 + |h| + |v| + |w|) max(min(μ, 1), 10⁻³); the two scales
/// differ by a factor of order one), so that it counts every line the check may take as
/// active at q. (It was the walk's 10⁻⁹.)
const G1_TOL: f64 = 1e-10;

/// Sliding columns whose widest angular gap is within this (radians) of π count as able to
/// balance with non-negative rates ([`may_slide_purely`]): rates that balance them to
/// about this (relative), above the kinematic LP's rank and rate tolerances (10⁻¹⁰), count
/// as a mechanism.
const PURE_SLIDING_GAP: f64 = 1e-9;

/// A sliding line through a vertex of Q at an angle below this (radians) to one of the
/// vertex's two edges counts as running along that edge (G1's "no two lines coincide"):
/// it stays within the check's activity tolerance (10⁻¹²) of the edge for a stretch of at
/// least 10⁻⁶ of the arch's scale.
const ALONG_EDGE: f64 = 1e-6;

/// The sliding lines among `lines` that pass through q (to G1's tolerance).
fn through<'a>(lines: impl Iterator<Item = &'a Line>, q: [f64; 2]) -> Vec<&'a Line> {
    lines
        .filter(|l| {
            let na = l.a[0].abs() + l.a[1].abs();
            l.slide.is_some()
                && (l.a[0] * q[0] + l.a[1] * q[1] + l.b).abs() <= G1_TOL * na * scale(q)
        })
        .collect()
}

/// Whether sliding rows may carry a mechanism without hinge rates (the corollary's only
/// mechanisms off the ridge): their columns ±(cos β, sin β, 0) balance with non-negative
/// rates, not all zero, exactly when no open half-plane holds them all, i.e. when the
/// widest angular gap between them is at most π (within [`PURE_SLIDING_GAP`]; both senses
/// of one joint leave a gap of π).
fn may_slide_purely(js: &[JointRows], rows: &[(usize, ContactKind)]) -> bool {
    let angle = |&(j, kind): &(usize, ContactKind)| {
        let turn = if kind == ContactKind::SlideMinus {
            PI
        } else {
            0.0
        };
        (js[j].beta + turn).rem_euclid(TAU)
    };
    let mut angles: Vec<f64> = rows.iter().map(angle).collect();
    angles.sort_by(f64::total_cmp);
    let (first, last) = (angles[0], angles[angles.len() - 1]);
    let widest = angles
        .windows(2)
        .map(|w| w[1] - w[0])
        .fold(TAU - (last - first), f64::max);
    widest <= PI + PURE_SLIDING_GAP
}

/// Whether two lines' directions differ by less than [`ALONG_EDGE`].
fn parallel(l: &Line, e: &Line) -> bool {
    let cross = l.a[0] * e.a[1] - l.a[1] * e.a[0];
    cross.abs() <= ALONG_EDGE * l.a[0].hypot(l.a[1]) * e.a[0].hypot(e.a[1])
}

/// Why G1 fails at vertex `v` of Q among the sliding lines `among` (every line, or a
/// chunk's), if it does. The ridge's theorem needs G1 only to exclude mechanisms without
/// hinge rates, which need sliding lines meeting at one point of Q with columns that
/// balance (a pure-sliding mechanism may then hold over an interval of η, off the ridge),
/// and lines that coincide along an edge (two sliding rows active along a piece). So more than two lines through a vertex pass where
/// their columns cannot balance ([`may_slide_purely`]) and none runs along one of the
/// vertex's edges ([`ALONG_EDGE`]): every limit state there has hinge rates, so it is the
/// ridge's point at the vertex, which the check decides on every contact active there, the
/// extra lines included (`verify` proves each of them strictly inactive at the vertex, or
/// says it cannot). Beside a sliding edge too short to walk ([`walked`]) the vertex may
/// have no candidate of its own and the edge's points are not found: any third line fails
/// there.
fn breaks_g1<'a>(
    (lines, poly): (&[Line], &[QVertex]),
    v: usize,
    among: impl Iterator<Item = &'a Line>,
    js: &[JointRows],
) -> Option<String> {
    let m = poly.len();
    let (q, leaving) = poly[v];
    let before = (v + m - 1) % m;
    let rows = through(among, q);
    if rows.len() <= 2 || on_box(q) {
        return None;
    }
    let n = rows.len();
    let short = |k: usize| lines[poly[k].1].slide.is_some() && !walked(lines, poly, k);
    if short(v) || short(before) {
        return Some(format!(
            "{n} sliding lines meet beside an edge of Q too short to walk"
        ));
    }
    let edges = [&lines[poly[before].1], &lines[leaving]];
    let along = |l: &&Line| edges.iter().any(|e| e.slide != l.slide && parallel(l, e));
    if rows.iter().any(along) {
        return Some(format!("{n} sliding lines meet, one along an edge of Q,"));
    }
    let slides: Vec<(usize, ContactKind)> = rows.iter().filter_map(|l| l.slide).collect();
    may_slide_purely(js, &slides)
        .then(|| format!("{n} sliding lines whose columns may balance without hinge rates meet"))
}

/// G1 at every vertex of Q off the box ([`breaks_g1`] among every line).
pub(super) fn no_third_line(
    js: &[JointRows],
    lines: &[Line],
    poly: &[QVertex],
) -> Result<(), Undecided> {
    for v in 0..poly.len() {
        if let Some(why) = breaks_g1((lines, poly), v, lines.iter(), js) {
            let q = poly[v].0;
            return Err(Undecided::NotCovered(format!(
                "{why} at the vertex ({}, {}) of Q",
                q[0], q[1]
            )));
        }
    }
    Ok(())
}

/// V2: an apex of joint k (both its sliding lines meet: N_k = T_k = 0) has M_k = 0, so
/// w = −m_k(q) at every η and E_k, I_k are always active: the ridge is the vertical
/// segment over q; its events are where another hinge row reaches w.
fn apexes(
    js: &[JointRows],
    lines: &[Line],
    poly: &[QVertex],
    in_range: &impl Fn(f64) -> bool,
) -> Vec<Candidate> {
    let mut out = Vec::new();
    for k in 0..poly.len() {
        let (q, e1) = poly[k];
        let e0 = poly[(k + poly.len() - 1) % poly.len()].1;
        let (Some((j0, _)), Some((j1, _))) = (lines[e0].slide, lines[e1].slide) else {
            continue;
        };
        if j0 != j1 {
            continue;
        }
        let hr = hinge_rows(js, q, [0.0, 0.0]);
        let w = -ev(&js[j0].m, q);
        for r in hr.iter().filter(|r| r.j != j0 && r.c[2] != 0.0) {
            let eta = (w - r.c[0]) / r.c[2];
            if in_range(eta) && in_band(&hr, 0.0, eta, w, TOL * scale(q)) {
                out.push(Candidate {
                    x: [q[0], q[1], w],
                    eta,
                    near: None,
                });
            }
        }
    }
    out
}

/// The frame p = p0 + t d of a line of Q: parametrised from the foot of the perpendicular
/// from the origin (not from a vertex, which may be on the box, 10⁶ away: t would lose ~10
/// digits), d of unit length.
pub(super) fn edge_frame(line: &Line) -> ([f64; 2], [f64; 2]) {
    let (a, b) = (line.a, line.b);
    let na2 = a[0] * a[0] + a[1] * a[1];
    let p0 = [-b * a[0] / na2, -b * a[1] / na2];
    let d = [-a[1] / na2.sqrt(), a[0] / na2.sqrt()];
    (p0, d)
}

/// A chunk of the walk along ∂Q ends after this many pieces (or at the last edge): the
/// joints near a chunk grow with the stretch of the arch its pieces sweep.
const CHUNK_PIECES: usize = 24;

/// An arch of at most this many joints is walked in one chunk with every joint (the chunks'
/// bookkeeping costs more than it saves there).
const WHOLE_ARCH_JOINTS: usize = 768;

/// Whether the edge of Q from vertex `k` is walked: a sliding edge long enough.
fn walked(lines: &[Line], poly: &[QVertex], k: usize) -> bool {
    let (q0, ri) = poly[k];
    let q1 = poly[(k + 1) % poly.len()].0;
    let len = (q1[0] - q0[0]).abs() + (q1[1] - q0[1]).abs();
    lines[ri].slide.is_some() && len > SHORT_EDGE_REL * scale(q0)
}

/// The sliding edges of Q long enough to walk, by the index of their first vertex.
fn walkable(lines: &[Line], poly: &[QVertex]) -> Vec<usize> {
    (0..poly.len())
        .filter(|&k| walked(lines, poly, k))
        .collect()
}

/// A hinge row by its joint and side (upper: extrados), whatever the rows walked.
type RowId = (usize, bool);

/// Where the walk along ∂Q stands: the edge (a position in the walkable edges) and, inside
/// it, the point and the pair of rows the next piece starts with.
#[derive(Clone, Copy)]
struct Cursor {
    edge: usize,
    inside: Option<(f64, RowId, RowId)>,
}

/// The walk along each sliding edge of Q, in chunks of [`CHUNK_PIECES`] pieces, each with
/// the joints that may be active over it ([`super::near`]): the points it returns inside
/// the box are added to `out`, and the chunks' subsets of joints returned. G1 (where more
/// than two sliding lines meet at a vertex of Q, [`breaks_g1`]) is tested at each vertex among
/// the lines of the joints of the chunk that reaches it (the others are further than the
/// test's tolerance); where it fails, or a walk fails, the answer is the one
/// [`no_third_line`] over every line gives first.
fn along_edges(
    js: &[JointRows],
    (lines, poly): (&[Line], &[QVertex]),
    (in_range, whole): (&impl Fn(f64) -> bool, bool),
    mu: f64,
    out: &mut Vec<Candidate>,
) -> Result<Vec<Vec<usize>>, Undecided> {
    let edges = walkable(lines, poly);
    // (an arch walked whole needs no tree)
    let tree = JointTree::new(js, mu, !whole);
    let mut in_walk = vec![false; js.len()];
    let mut tested = vec![false; poly.len()];
    let mut subsets: Vec<Vec<usize>> = Vec::new();
    let mut guess: Vec<usize> = (0..js.len()).collect();
    let mut at = Cursor {
        edge: 0,
        inside: None,
    };
    while at.edge < edges.len() {
        let geometry = (lines, poly, edges.as_slice());
        let (walked, next_at) =
            match walk_chunk(js, geometry, (at, whole), (mu, &tree), &guess, &mut in_walk) {
                Ok(w) => w,
                Err(e) => {
                    no_third_line(js, lines, poly)?;
                    return Err(e);
                }
            };
        for &v in walked.vertices.iter().flatten() {
            let lines_of = walked.subset.iter().flat_map(|&j| [2 * j, 2 * j + 1]);
            let among = lines_of.map(|l| &lines[l]);
            if !std::mem::replace(&mut tested[v], true)
                && breaks_g1((lines, poly), v, among, js).is_some()
            {
                no_third_line(js, lines, poly)?;
            }
        }
        for (_, p0, d, wk) in &walked.walks {
            for &(t, eta, w) in &wk.points {
                let p = [p0[0] + t * d[0], p0[1] + t * d[1]];
                if in_range(eta) && !on_box(p) {
                    out.push(Candidate {
                        x: [p[0], p[1], w],
                        eta,
                        near: Some(subsets.len()),
                    });
                }
            }
        }
        at = next_at;
        guess = walked.next;
        subsets.push(walked.subset);
    }
    // vertices of Q on no walked edge (between sides of the box or short edges)
    let untested_third =
        |v: usize| !tested[v] && breaks_g1((lines, poly), v, lines.iter(), js).is_some();
    if (0..poly.len()).any(untested_third) {
        no_third_line(js, lines, poly)?;
    }
    Ok(subsets)
}

/// A chunk walked: each walk's ends, frame and walk, the vertices of Q each walk reached
/// (its edge's start, its end), the joints whose rows may be near active over the chunk
/// (ascending) and the joints predicted near in the next chunk.
struct ChunkWalk {
    walks: Vec<WalkedEdge>,
    vertices: Vec<Vec<usize>>,
    subset: Vec<usize>,
    next: Vec<usize>,
}

/// The walk of one chunk from `at` with the hinge rows of the joints `guess`, grown by the
/// joints whose hinge rows [`verify`] cannot show inactive until it shows every other one
/// is (or with every joint, where a walk with fewer fails). An arch walked `whole` is one
/// chunk with every joint, unverified.
/// Returns the chunk and where the next one starts. `in_walk` is all false on entry and on
/// return.
fn walk_chunk(
    js: &[JointRows],
    geometry: (&[Line], &[QVertex], &[usize]),
    (at, whole): (Cursor, bool),
    (mu, tree): (f64, &JointTree),
    guess: &[usize],
    in_walk: &mut [bool],
) -> Result<(ChunkWalk, Cursor), Undecided> {
    let budget = if whole { usize::MAX } else { CHUNK_PIECES };
    let mut set: Vec<usize> = guess.to_vec();
    set.extend(at.inside.iter().flat_map(|(_, e, i)| [e.0, i.0]));
    set.sort_unstable();
    set.dedup();
    set.iter().for_each(|&j| in_walk[j] = true);
    let (walks, next_at, subset, next) = loop {
        let (walks, next_at) = match walk_from(js, geometry, at, &set, budget) {
            Ok(w) => w,
            Err(e) if set.len() == js.len() => {
                set.iter().for_each(|&j| in_walk[j] = false);
                return Err(e);
            }
            Err(_) => {
                set = (0..js.len()).collect();
                set.iter().for_each(|&j| in_walk[j] = true);
                continue;
            }
        };
        if whole && set.len() == js.len() {
            break (walks, next_at, set.clone(), set.clone());
        }
        let verdict = verified(js, (mu, tree), &walks, in_walk);
        if verdict.failing.is_empty() {
            // `on` comes out ascending (the tree is walked left to right)
            break (walks, next_at, verdict.on, verdict.next);
        }
        verdict.failing.iter().for_each(|&j| in_walk[j] = true);
        set.extend(verdict.failing);
        set.sort_unstable();
    };
    set.iter().for_each(|&j| in_walk[j] = false);
    let (_, poly, edges) = geometry;
    let vertices = walks
        .iter()
        .enumerate()
        .map(|(n, w)| {
            let k = edges[at.edge + n];
            let starts = (n > 0 || at.inside.is_none()).then_some(k);
            let ends = w.4.stopped.is_none().then_some((k + 1) % poly.len());
            starts.into_iter().chain(ends).collect()
        })
        .collect();
    let walks = walks
        .into_iter()
        .map(|(q, p0, d, _, wk)| (q, p0, d, wk))
        .collect();
    let chunk = ChunkWalk {
        walks,
        vertices,
        subset,
        next,
    };
    Ok((chunk, next_at))
}

/// [`verify`] over the bounds of a chunk's walks, with the two rows of its first piece as
/// the reference rows.
fn verified(
    js: &[JointRows],
    (mu, tree): (f64, &JointTree),
    walks: &[EdgeWalk],
    in_walk: &[bool],
) -> Verdict {
    let first = &walks[0];
    let pc = first.4.pieces[0];
    let views: Vec<EdgeView> = walks
        .iter()
        .map(|(q, p0, d, hr, wk)| (*q, *p0, *d, hr.as_slice(), wk))
        .collect();
    let bounds = Bounds::new(js, [first.3[pc.2].j, first.3[pc.3].j], &views);
    verify(js, tree, mu, &bounds, in_walk)
}

/// One walk as a chunk keeps it: its ends, its frame p = p0 + t d and the walk.
type WalkedEdge = (([f64; 2], [f64; 2]), [f64; 2], [f64; 2], Walked);

/// One walk: its ends, its frame p = p0 + t d, its hinge rows and the walk.
type EdgeWalk = (
    ([f64; 2], [f64; 2]),
    [f64; 2],
    [f64; 2],
    Vec<HingeRow>,
    Walked,
);

/// The walks of one chunk from `at` with the hinge rows of the joints `set` (ascending):
/// edge after edge until `budget` pieces, and where the next chunk starts.
fn walk_from(
    js: &[JointRows],
    (lines, poly, edges): (&[Line], &[QVertex], &[usize]),
    mut at: Cursor,
    set: &[usize],
    budget: usize,
) -> Result<(Vec<EdgeWalk>, Cursor), Undecided> {
    let mut walks = Vec::new();
    let mut pieces = 0;
    let row_of = |(j, upper): RowId| {
        let k = set
            .binary_search(&j)
            .expect("the cursor's joints are in the set");
        2 * k + usize::from(!upper)
    };
    while at.edge < edges.len() && pieces < budget {
        let (q0, ri) = poly[edges[at.edge]];
        let q1 = poly[(edges[at.edge] + 1) % poly.len()].0;
        let sl = lines[ri]
            .slide
            .expect("a walkable edge lies on a sliding line");
        let (p0, d) = edge_frame(&lines[ri]);
        let tof = |q: [f64; 2]| (q[0] - p0[0]) * d[0] + (q[1] - p0[1]) * d[1];
        let hr = hinge_rows_of(js, set.iter().copied(), p0, d);
        let cs = column(sl.1, js[sl.0].beta, 0.0);
        let from = at.inside.map(|(t, e, i)| (t, row_of(e), row_of(i)));
        let wk = walk_edge(&hr, (tof(q0), tof(q1)), (from, budget - pieces), cs, js)?;
        pieces += wk.pieces.len();
        at = match wk.stopped {
            Some((t, e, i)) => Cursor {
                edge: at.edge,
                inside: Some((t, (hr[e].j, hr[e].upper), (hr[i].j, hr[i].upper))),
            },
            None => Cursor {
                edge: at.edge + 1,
                inside: None,
            },
        };
        let (ts, te) = (wk.pieces[0].0, wk.pieces[wk.pieces.len() - 1].1);
        let ends = [ts, te].map(|t| [p0[0] + t * d[0], p0[1] + t * d[1]]);
        walks.push(((ends[0], ends[1]), p0, d, hr, wk));
    }
    Ok((walks, at))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::arch::{Arch, JointLayout, WeightModel};

    /// Sliding columns balance with non-negative rates exactly when no open half-plane
    /// holds them all (one joint sliding both ways among them does); neighbours of one
    /// sense never do.
    #[test]
    fn pure_sliding_needs_columns_around_the_origin() {
        use ContactKind::{SlideMinus as M, SlidePlus as P};
        let js: Vec<JointRows> = [
            0.0,
            0.1,
            0.2,
            2.0 * PI / 3.0,
            4.0 * PI / 3.0,
            PI / 2.0 + 0.05,
        ]
        .iter()
        .map(|&beta| JointRows {
            beta,
            n: [0.0; 3],
            t: [0.0; 3],
            m: [0.0; 3],
        })
        .collect();
        let slides = |rows: &[(usize, ContactKind)]| may_slide_purely(&js, rows);
        // three at 120°: around the origin
        assert!(slides(&[(0, P), (3, P), (4, P)]));
        // three neighbours of one sense, or of both senses spread over less than π
        assert!(!slides(&[(0, P), (1, P), (2, P)]));
        assert!(!slides(&[(0, M), (1, M), (2, M)]));
        // 0 and 0.1 + π are nearly opposite (widest gap π + 0.1): not alone ...
        assert!(!slides(&[(0, P), (1, M), (2, M)]));
        // ... but with a third between them on the short side (gaps π/2 + 0.05 twice, π − 0.1)
        assert!(slides(&[(0, P), (1, M), (5, P)]));
        // both senses of one joint balance (a gap of π)
        assert!(slides(&[(0, P), (0, M), (1, P)]));
    }

    /// The chunked walk finds the same candidates as the whole one, to the bit, and the
    /// joints it leaves out of a candidate's subset are clearly away from it: on symmetric
    /// and unsymmetric voussoir arches of 100 to 400 joints and a range of friction.
    #[test]
    fn the_chunked_walk_finds_what_the_whole_walk_finds() {
        let mut compared = 0;
        for (k, &(a, b, n, mu)) in [
            (-0.5, 0.5, 100, 0.6),
            (-1.0, 1.0, 160, 0.4),
            (-0.3, 1.2, 240, 0.9),
            (-1.2, 0.2, 300, 1.3),
            (-0.8, 0.8, 400, 0.7),
            (-0.2, 0.9, 120, 2.0),
            (-0.9, 0.9, 200, 3.0),
            (0.1, 1.3, 150, 1.1),
        ]
        .iter()
        .enumerate()
        {
            let arch = Arch::new(a, b, WeightModel::Centreline)
                .and_then(|x| x.with_blocks(n))
                .unwrap_or_else(|e| panic!("case {k}: {e:?}"));
            let JointLayout::Discrete(joints) = arch.layout() else {
                unreachable!()
            };
            let js: Vec<JointRows> = joints.iter().map(|&b| JointRows::at(&arch, b)).collect();
            let (Ok(whole), Ok(chunked)) = (
                candidates_walked(&js, mu, 0.0, true),
                candidates_walked(&js, mu, 0.0, false),
            ) else {
                continue;
            };
            let bits = |c: &[Candidate]| {
                c.iter()
                    .map(|c| (c.eta.to_bits(), c.x.map(f64::to_bits)))
                    .collect::<Vec<_>>()
            };
            assert_eq!(bits(&whole.0), bits(&chunked.0), "case {k}");
            assert!(chunked.1.len() > 1, "case {k}: walked in one chunk");
            for c in &chunked.0 {
                let Some(near) = c.near else { continue };
                let near = &chunked.1[near];
                let size = (1.0 + c.x.iter().map(|v| v.abs()).sum::<f64>()) * c.eta.max(1.0);
                for (j, jr) in js.iter().enumerate() {
                    if near.binary_search(&j).is_ok() {
                        continue;
                    }
                    let p = [c.x[0], c.x[1]];
                    let (n, t, m) = (ev(&jr.n, p), ev(&jr.t, p), ev(&jr.m, p) + c.x[2]);
                    let most = [
                        m - 0.5 * c.eta * n,
                        -m - 0.5 * c.eta * n,
                        t - mu * n,
                        -t - mu * n,
                    ]
                    .into_iter()
                    .fold(f64::NEG_INFINITY, f64::max);
                    assert!(
                        most < -1e-8 * size,
                        "case {k}: joint {j} left out at {most}"
                    );
                }
            }
            compared += 1;
        }
        assert!(compared >= 6, "only {compared} arches compared");
    }
}
