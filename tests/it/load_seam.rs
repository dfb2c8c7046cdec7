//! The seam of P̂ for a live load (docs/design/load-limit-states-on-the-seam.md), on the
//! brute force's own rows and vertices (`load_reference::Case`): the edges of P̂ whose
//! three active rows are a sliding, an extrados and an intrados row form paths, each seam
//! vertex {S, E, I, X} on exactly two of them; a path is closed or ends where λ reaches 0
//! (the floor of the multipliers). The test walks every path by the walk's own rule (drop a
//! row, keep the other three, ratio test) and checks that each step lands on a vertex of P̂
//! with the active set the rule says; it counts the paths of each arch, which decides how a
//! search must find its starting points.

use crate::load_reference::{random_loaded, Case};
use crate::search_reference::Rng;
use arch_enum::contact::ContactKind;
use arch_enum::WeightModel;
use itertools::Itertools;

/// A vertex of P̂: z = (h, v, w, λ) and its active rows (ascending).
type Vertex = ([f64; 4], Vec<usize>);

/// The three kinds a seam row set needs: a sliding, an extrados and an intrados row.
fn is_seam(case: &Case, rows: &[usize]) -> bool {
    let has = |f: fn(ContactKind) -> bool| rows.iter().any(|&r| f(case.contacts()[r].1));
    has(|k| matches!(k, ContactKind::SlidePlus | ContactKind::SlideMinus))
        && has(|k| k == ContactKind::HingeExtrados)
        && has(|k| k == ContactKind::HingeIntrados)
}

fn dot(a: &[f64; 4], z: &[f64; 4]) -> f64 {
    (0..4).map(|k| a[k] * z[k]).sum()
}

/// 1 + ‖z‖₁: the scale of the tolerances at z.
fn scale(z: &[f64; 4]) -> f64 {
    1.0 + z.iter().map(|v| v.abs()).sum::<f64>()
}

/// Every vertex of P̂ with λ ≥ 0 (four rows meeting, admissible to 1e-9 of its scale,
/// within |z| ≤ 10⁶), each once; `None` where a vertex has more than four rows active
/// (the loaded joint's twin rows, or a coincidence: the generic rule does not apply).
fn vertices(rows: &[([f64; 4], f64)]) -> Option<Vec<Vertex>> {
    let mut out: Vec<Vertex> = Vec::new();
    for quad in (0..rows.len()).combinations(4) {
        let a = nalgebra::Matrix4::from_fn(|r, c| rows[quad[r]].0[c]);
        let b = nalgebra::Vector4::from_fn(|r, _| -rows[quad[r]].1);
        let Some(z) = a.lu().solve(&b) else { continue };
        let z = [z[0], z[1], z[2], z[3]];
        if !z.iter().all(|v| v.is_finite()) || z[3] < -1e-12 || scale(&z) > 1e6 {
            continue;
        }
        let tol = 1e-9 * scale(&z);
        let values: Vec<f64> = rows.iter().map(|(a, c)| dot(a, &z) + c).collect();
        if values.iter().any(|&v| v > tol) {
            continue;
        }
        let active: Vec<usize> = (0..rows.len())
            .filter(|&i| values[i].abs() <= tol)
            .collect();
        if active.len() > 4 {
            return None;
        }
        if !out.iter().any(|(_, a)| *a == active) {
            out.push((z, active));
        }
    }
    Some(out)
}

/// How an edge of P̂ ends.
#[derive(Debug, Clone, Copy, PartialEq)]
enum End {
    /// At the row that blocks it first.
    Row(usize),
    /// Where λ reaches 0.
    Floor,
    /// Nowhere within the box of [`vertices`].
    Unbounded,
}

/// Where the edge of P̂ that keeps `keep` (three rows) and leaves row `drop` at vertex `z`
/// ends.
fn step(rows: &[([f64; 4], f64)], z: &[f64; 4], keep: &[usize], drop: usize) -> End {
    // the direction: orthogonal to the three kept gradients (cofactors of the 3 × 4 rows)
    let m = |r: usize, c: usize| rows[keep[r]].0[c];
    let mut d = [0.0; 4];
    for (k, dk) in d.iter_mut().enumerate() {
        let cols: Vec<usize> = (0..4).filter(|&c| c != k).collect();
        let minor = nalgebra::Matrix3::from_fn(|r, c| m(r, cols[c])).determinant();
        *dk = if k % 2 == 0 { minor } else { -minor };
    }
    // the dropped row becomes slack along the edge
    if dot(&rows[drop].0, &d) > 0.0 {
        d = d.map(|v| -v);
    }
    let size = d.iter().map(|v| v.abs()).sum::<f64>();
    let mut best: Option<(f64, Option<usize>)> = None;
    if d[3] < 0.0 {
        best = Some((-z[3] / d[3], None)); // the floor λ = 0
    }
    for (r, (a, c)) in rows.iter().enumerate() {
        if keep.contains(&r) || r == drop {
            continue;
        }
        let rate = dot(a, &d);
        let norm = a.iter().map(|v| v.abs()).sum::<f64>();
        if rate <= 1e-12 * norm * size {
            continue;
        }
        let t = (-(dot(a, z) + c) / rate).max(0.0);
        if best.is_none_or(|b| t < b.0) {
            best = Some((t, Some(r)));
        }
    }
    match best {
        Some((t, _)) if scale(&std::array::from_fn(|k| z[k] + t * d[k])) > 1e6 => End::Unbounded,
        Some((_, Some(r))) => End::Row(r),
        Some((_, None)) => End::Floor,
        None => End::Unbounded,
    }
}

/// What the seam of one arch is made of: its vertices, its paths (closed or ending on the
/// floor λ = 0), and the vertices with three sliding rows active (pure sliding's).
#[derive(Default, Debug)]
struct Seam {
    vertices: usize,
    closed: usize,
    open: usize,
    three_sliding: usize,
    /// Paths through the vertex of largest λ (the static maximum's), paths with an end on
    /// the floor, paths with neither (a search must find a start on them some other way).
    through_top: usize,
    on_floor: usize,
    hidden: usize,
    /// Seam vertices that are limit states (the brute force's kinematic LP), on paths of
    /// each kind: through the top, with a floor end (not through the top), neither.
    limit_states: [usize; 3],
}

/// Walks every seam path of `case`; `Err` where a step lands anywhere but on a vertex with
/// the rule's active set; `Ok(None)` where a vertex is degenerate.
fn seam(case: &Case) -> Result<Option<Seam>, String> {
    let rows: Vec<([f64; 4], f64)> = case.contacts().iter().map(|&c| case.row(c)).collect();
    let Some(vs) = vertices(&rows) else {
        return Ok(None);
    };
    let sliding = |r: usize| {
        matches!(
            case.contacts()[r].1,
            ContactKind::SlidePlus | ContactKind::SlideMinus
        )
    };
    let mut out = Seam {
        three_sliding: vs
            .iter()
            .filter(|(_, a)| a.iter().filter(|&&r| sliding(r)).count() >= 3)
            .count(),
        ..Seam::default()
    };
    let on: Vec<usize> = (0..vs.len()).filter(|&i| is_seam(case, &vs[i].1)).collect();
    out.vertices = on.len();
    let top = (0..vs.len()).max_by(|&a, &b| vs[a].0[3].total_cmp(&vs[b].0[3]));
    let mut seen = vec![false; vs.len()];
    for &start in &on {
        if seen[start] {
            continue;
        }
        // walk both ways from `start`: each step leaves by the seam edge not come by
        let mut ends = 0;
        let (mut has_top, mut floor) = (false, false);
        let mut states = 0;
        for first in 0..2 {
            let (mut at, mut came): (usize, Option<usize>) = (start, None);
            let mut leave = first;
            loop {
                seen[at] = true;
                has_top |= Some(at) == top;
                let contacts: Vec<(usize, ContactKind)> =
                    vs[at].1.iter().map(|&r| case.contacts()[r]).collect();
                states += usize::from(case.mechanism(&contacts, vs[at].0[3].max(0.0)).is_some());
                let (z, act) = &vs[at];
                // the seam edges at `at`: drop a row so that the other three stay seam rows
                let edges: Vec<usize> = act
                    .iter()
                    .copied()
                    .filter(|&d| {
                        let keep: Vec<usize> = act.iter().copied().filter(|&r| r != d).collect();
                        is_seam(case, &keep)
                    })
                    .collect();
                if edges.len() != 2 {
                    return Err(format!("vertex {act:?} has {} seam edges", edges.len()));
                }
                let drop = match came {
                    // the edge come by kept every row but the one that blocked it (now in
                    // `act`): leave by dropping the other candidate
                    Some(blocker) => *edges.iter().find(|&&d| d != blocker).unwrap_or(&edges[0]),
                    None => edges[leave],
                };
                let keep: Vec<usize> = act.iter().copied().filter(|&r| r != drop).collect();
                let blocker = match step(&rows, z, &keep, drop) {
                    End::Row(r) => r,
                    end => {
                        ends += 1;
                        floor |= end == End::Floor;
                        break;
                    }
                };
                let mut want = keep.clone();
                want.push(blocker);
                want.sort_unstable();
                let Some(next) = vs.iter().position(|(_, a)| *a == want) else {
                    return Err(format!(
                        "the edge {keep:?} from {act:?} ends at row {blocker}, not at a vertex"
                    ));
                };
                if next == start {
                    break; // closed
                }
                if seen[next] && came.is_some() {
                    return Err(format!("the path from {start} meets itself at {next}"));
                }
                (at, came) = (next, Some(blocker));
                leave = 0;
            }
            if ends == 0 {
                break; // a closed path needs one way round only
            }
        }
        if ends == 0 {
            out.closed += 1;
        } else {
            out.open += 1;
        }
        out.limit_states[if has_top {
            0
        } else if floor {
            1
        } else {
            2
        }] += states;
        out.through_top += usize::from(has_top);
        out.on_floor += usize::from(floor);
        out.hidden += usize::from(!has_top && !floor);
    }
    Ok(Some(out))
}

/// The seam on random small loaded arches (finite μ): every step of every walk lands on a
/// vertex of P̂ with the active set the rule gives; the paths per arch are counted.
#[test]
fn the_seam_of_a_loaded_arch_is_paths_the_walk_follows() {
    let mut rng = Rng(0x5ea3_0000_0001);
    let (mut arches, mut degenerate, mut errors) = (0, 0, Vec::new());
    let mut by_paths = [0usize; 4];
    let mut total = Seam::default();
    for case in 0..400 {
        let c = random_loaded(&mut rng);
        if c.mu.is_infinite() {
            continue;
        }
        let centroid = c.weight == WeightModel::Centroid;
        let reference = Case::new(&c.joints, centroid, c.eta, c.mu, c.load);
        match seam(&reference) {
            Ok(Some(s)) => {
                arches += 1;
                by_paths[(s.closed + s.open).min(3)] += 1;
                total.vertices += s.vertices;
                total.closed += s.closed;
                total.open += s.open;
                total.three_sliding += s.three_sliding;
                total.through_top += s.through_top;
                total.on_floor += s.on_floor;
                total.hidden += s.hidden;
                (0..3).for_each(|k| total.limit_states[k] += s.limit_states[k]);
            }
            Ok(None) => degenerate += 1,
            Err(e) => errors.push(format!("case {case}: {e}")),
        }
    }
    println!(
        "{arches} arches ({degenerate} with a degenerate vertex): seam vertices {}, paths closed {} open {}, arches with 0/1/2/3+ paths {by_paths:?}, vertices with three sliding rows {}; paths through the top {}, with an end on the floor {}, neither {}; limit states on them {:?}",
        total.vertices, total.closed, total.open, total.three_sliding, total.through_top, total.on_floor, total.hidden, total.limit_states
    );
    assert!(errors.is_empty(), "{}", errors.join("\n"));
    assert!(arches >= 100 && total.vertices >= 100, "{arches} arches");
}
