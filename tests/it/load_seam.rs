//! The seam of P̂ for a live load (docs/design/load-limit-states-on-the-seam.md), on the
//! brute force's own rows and vertices (`load_reference::Case`): the edges of P̂ whose
//! three active rows are a sliding, an extrados and an intrados row form paths, each seam
//! vertex {S, E, I, X} on exactly two of them; a path is closed or ends where λ reaches 0
//! (the floor of the multipliers) or where it leaves the box |z| ≤ 10⁶. The test walks every path by the walk's own rule (drop a
//! row, keep the other three, ratio test) and checks that each step lands on a vertex of P̂
//! with the active set the rule says; it counts the paths of each arch, which decides how a
//! search must find its starting points.

use crate::load_reference::{meeting_points, random_loaded, Case};
use crate::search_reference::Rng;
use arch_enum::contact::ContactKind;
use arch_enum::limit_states::LimitState;
use arch_enum::load::LiveLoad;
use arch_enum::multiplier::{survey, LoadOutcome};
use arch_enum::{Arch, Settings, WeightModel};

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
    for (z, values) in meeting_points(rows) {
        let tol = 1e-9 * scale(&z);
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

/// What the seam of one arch is made of: its vertices, its paths (closed, or with ends on
/// the floor λ = 0 or leaving the box), the vertices with three sliding rows active (pure
/// sliding's), and the limit states on its paths strictly below the top.
#[derive(Default, Debug)]
struct Seam {
    vertices: usize,
    closed: usize,
    open: usize,
    three_sliding: usize,
    /// Paths through the vertex of largest λ, paths with an end on the floor (and not
    /// through it), and the others ("hidden": a search must find a start on them some
    /// other way), split into closed ones and ones that leave the box.
    through_top: usize,
    on_floor: usize,
    hidden_closed: usize,
    hidden_box: usize,
    /// Seam vertices below the top that are limit states (the brute force's kinematic LP),
    /// on paths of each kind: through the top, with a floor end, hidden; with their λ.
    limit_states: [Vec<f64>; 3],
}

/// One path walked from a seam vertex: its vertices (each once) and how it ended.
#[derive(Default)]
struct Path {
    vertices: Vec<usize>,
    ends: Vec<End>,
}

/// The seam edges at a vertex with active rows `act`: the rows whose dropping leaves three
/// seam rows.
fn seam_edges(case: &Case, act: &[usize]) -> Vec<usize> {
    act.iter()
        .copied()
        .filter(|&d| {
            let keep: Vec<usize> = act.iter().copied().filter(|&r| r != d).collect();
            is_seam(case, &keep)
        })
        .collect()
}

/// Walks the seam path through `start` both ways (one way round where it closes).
fn walk(
    case: &Case,
    rows: &[([f64; 4], f64)],
    vs: &[Vertex],
    start: usize,
) -> Result<Path, String> {
    let mut path = Path::default();
    for first in 0..2 {
        let (mut at, mut came): (usize, Option<usize>) = (start, None);
        loop {
            if !path.vertices.contains(&at) {
                path.vertices.push(at);
            }
            let (z, act) = &vs[at];
            let edges = seam_edges(case, act);
            if edges.len() != 2 {
                return Err(format!("vertex {act:?} has {} seam edges", edges.len()));
            }
            // the edge come by kept every row but the one that blocked it (now in `act`):
            // leave by dropping the other
            let drop = match came {
                Some(blocker) => *edges.iter().find(|&&d| d != blocker).unwrap_or(&edges[0]),
                None => edges[first],
            };
            let keep: Vec<usize> = act.iter().copied().filter(|&r| r != drop).collect();
            let blocker = match step(rows, z, &keep, drop) {
                End::Row(r) => r,
                end => {
                    path.ends.push(end);
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
            if path.vertices.contains(&next) {
                return Err(format!("the path from {start} meets itself at {next}"));
            }
            (at, came) = (next, Some(blocker));
        }
        if path.ends.is_empty() {
            break; // a closed path needs one way round only
        }
    }
    Ok(path)
}

/// Walks every seam path of `case`; `Err` where a step lands anywhere but on a vertex with
/// the rule's active set; `Ok(None)` where a vertex has more than four rows active.
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
    let top_lambda = top.map_or(f64::INFINITY, |t| vs[t].0[3]);
    let mut seen = vec![false; vs.len()];
    for &start in &on {
        if seen[start] {
            continue;
        }
        let path = walk(case, &rows, &vs, start)?;
        path.vertices.iter().for_each(|&v| seen[v] = true);
        let through_top = path.vertices.iter().any(|&v| Some(v) == top);
        let floor = path.ends.contains(&End::Floor);
        let kind = if through_top {
            0
        } else if floor {
            1
        } else {
            2
        };
        out.through_top += usize::from(through_top);
        out.on_floor += usize::from(floor && !through_top);
        if path.ends.is_empty() {
            out.closed += 1;
            out.hidden_closed += usize::from(kind == 2);
        } else {
            out.open += 1;
            out.hidden_box += usize::from(kind == 2);
        }
        for &v in &path.vertices {
            let lambda = vs[v].0[3].max(0.0);
            let contacts: Vec<(usize, ContactKind)> =
                vs[v].1.iter().map(|&r| case.contacts()[r]).collect();
            if lambda < top_lambda * (1.0 - 1e-9) && case.mechanism(&contacts, lambda).is_some() {
                out.limit_states[kind].push(lambda);
            }
        }
    }
    Ok(Some(out))
}

/// The seam on random small loaded arches (finite μ): every step of every walk lands on a
/// vertex of P̂ with the active set the rule gives. The paths per arch are counted and
/// printed (one run's figures are in the design note), with the limit states on them that
/// the brute force lists (not states at λ_min, where the arch fails by unloading, nor of a
/// continuum).
#[test]
fn the_seam_of_a_loaded_arch_is_paths_the_walk_follows() {
    let mut rng = Rng(0x5ea3_0000_0001);
    let (mut arches, mut errors) = (0, Vec::new());
    // arches left out: a vertex with more than four rows active, under a point load at a
    // joint (its twin rows) or otherwise
    let mut degenerate = [0usize; 2];
    let mut by_paths = [0usize; 4];
    let mut total = Seam::default();
    let (mut listed_by_kind, mut unlisted) = ([0usize; 3], 0);
    for case in 0..400 {
        let c = random_loaded(&mut rng);
        if c.mu.is_infinite() {
            continue;
        }
        let centroid = c.weight == WeightModel::Centroid;
        let reference = Case::new(&c.joints, centroid, c.eta, c.mu, c.load);
        let s = match seam(&reference) {
            Ok(Some(s)) => s,
            Ok(None) => {
                let at_joint =
                    matches!(c.load, LiveLoad::Point { beta } if c.joints.contains(&beta));
                degenerate[usize::from(!at_joint)] += 1;
                continue;
            }
            Err(e) => {
                errors.push(format!("case {case}: {e}"));
                continue;
            }
        };
        arches += 1;
        let paths = s.closed + s.open;
        by_paths[paths.min(3)] += 1;
        // the seam vertices with a mechanism that the brute force lists (the others are
        // states at λ_min, where the arch fails by unloading, or of a continuum)
        if s.limit_states.iter().any(|l| !l.is_empty()) {
            let listed = reference.brute_force();
            let is_listed = |l: &f64| listed.iter().any(|&m| (m - l).abs() <= 1e-8 * (1.0 + l));
            for (states, count) in s.limit_states.iter().zip(&mut listed_by_kind) {
                let n = states.iter().filter(|l| is_listed(l)).count();
                *count += n;
                unlisted += states.len() - n;
            }
        }
        total.vertices += s.vertices;
        total.closed += s.closed;
        total.open += s.open;
        total.three_sliding += s.three_sliding;
        total.through_top += s.through_top;
        total.on_floor += s.on_floor;
        total.hidden_closed += s.hidden_closed;
        total.hidden_box += s.hidden_box;
    }
    println!(
        "{arches} arches (left out with a degenerate vertex: {} under a point load at a joint, {} others); seam vertices {}; paths closed {} open {}; arches with 0/1/2/3+ paths {by_paths:?}; vertices with three sliding rows {}; paths through the top {}, with a floor end {}, hidden {} closed + {} leaving the box; limit states below the top (listed by the brute force) on them {listed_by_kind:?}, and {unlisted} seam vertices with a mechanism it does not list",
        degenerate[0], degenerate[1], total.vertices, total.closed, total.open, total.three_sliding,
        total.through_top, total.on_floor, total.hidden_closed, total.hidden_box
    );
    assert!(errors.is_empty(), "{}", errors.join("\n"));
    assert!(arches >= 100 && total.vertices >= 100, "{arches} arches");
}

/// The survey of one loaded discrete arch with the sweep below λ_static and with the face
/// search there (the sweep's budget set below the arch's joints), or why they differ;
/// `None` where the survey gives no limit states to compare.
fn compare_faces(
    arch: &Arch,
    (eta, mu): (f64, f64),
    load: &LiveLoad,
) -> Option<Result<usize, String>> {
    let swept_settings = Settings::default();
    let faced_settings = Settings {
        load_sweep_max_joints: 2,
        ..Settings::default()
    };
    let run = |settings: &Settings| match survey(arch, eta, mu, load, settings) {
        Ok(Ok(LoadOutcome::Limits(s))) => Some(Ok(s)),
        Ok(Ok(_)) => None,
        Ok(Err(u)) => Some(Err(u.to_string())),
        Err(e) => Some(Err(e.to_string())),
    };
    let (swept, faced) = (run(&swept_settings)?, run(&faced_settings));
    let swept = match swept {
        Ok(s) => s,
        Err(_) => return None, // the sweep itself undecided: nothing to compare
    };
    let faced = match faced {
        Some(Ok(s)) => s,
        Some(Err(e)) => return Some(Err(format!("the face search: {e}"))),
        None => return Some(Err("the face search: no limit states".into())),
    };
    let key = |l: &LimitState| {
        let kinds: Vec<(ContactKind, f64)> = l.pattern.iter().map(|c| (c.kind, c.beta)).collect();
        (l.t, kinds)
    };
    let (a, b): (Vec<_>, Vec<_>) = (
        swept.limit_states.iter().map(key).collect(),
        faced.limit_states.iter().map(key).collect(),
    );
    // the same states, in any order (two states at one λ may come out in either order)
    let same_state = |p: &(f64, Vec<(ContactKind, f64)>), q: &(f64, Vec<(ContactKind, f64)>)| {
        (p.0 - q.0).abs() <= 1e-8 * (1.0 + p.0.abs())
            && p.1.len() == q.1.len()
            && p.1
                .iter()
                .zip(&q.1)
                .all(|(x, y)| x.0 == y.0 && (x.1 - y.1).abs() <= 1e-9)
    };
    let within = |l: &[(f64, Vec<(ContactKind, f64)>)], m: &[(f64, Vec<(ContactKind, f64)>)]| {
        l.iter().all(|p| m.iter().any(|q| same_state(p, q)))
    };
    let same = a.len() == b.len()
        && within(&a, &b)
        && within(&b, &a)
        && swept.mechanism_at_static == faced.mechanism_at_static
        && faced.method == "faces";
    if same {
        Some(Ok(a.len()))
    } else {
        Some(Err(format!(
            "lambda in ({}, {:?}), method {}:\nsweep {a:?}\nfaces {b:?}",
            swept.lambda_min.0,
            swept.lambda_static.map(|m| m.0),
            faced.method
        )))
    }
}

/// The survey with the face search below λ_static (`sweep::faces_load`, design note §5)
/// answers as the survey with the sweep: the same limit states (λ and contacts) and the
/// same verdict at λ_static, on random small loaded arches (`load_reference`'s, finite μ;
/// `FACE_CASES=N` draws N) and on semicircles of 20–120 equal voussoirs under point and
/// horizontal loads.
#[test]
fn the_face_search_finds_what_the_sweep_finds() {
    let mut rng = Rng(0xface_0000_0001);
    let cases = crate::cases_from_env("FACE_CASES", 4000);
    let (mut compared, mut states, mut failures) = (0, 0, Vec::new());
    let mut run = |name: String, r: Option<Result<usize, String>>| match r {
        Some(Ok(n)) => {
            compared += 1;
            states += n;
        }
        Some(Err(e)) => failures.push(format!("{name}: {e}")),
        None => {}
    };
    for case in 0..cases {
        let c = random_loaded(&mut rng);
        let only = std::env::var("FACE_ONLY")
            .ok()
            .and_then(|v| v.parse::<usize>().ok());
        if only.is_some_and(|o| o != case) {
            continue;
        }
        if c.mu.is_finite() {
            run(
                format!("case {case}"),
                compare_faces(&c.arch, (c.eta, c.mu), &c.load),
            );
        }
    }
    for blocks in [20, 60, 120] {
        let arch = Arch::symmetric(0.0, WeightModel::Centreline)
            .unwrap()
            .with_blocks(blocks)
            .unwrap();
        for load in [
            LiveLoad::Horizontal {
                towards_right: true,
            },
            LiveLoad::Point { beta: 0.7 },
            LiveLoad::Point { beta: 1.3 },
        ] {
            for (eta, mu) in [(0.3, 0.6), (0.2, 1.0), (0.4, 0.45)] {
                run(
                    format!("{blocks} voussoirs {load:?} eta {eta} mu {mu}"),
                    compare_faces(&arch, (eta, mu), &load),
                );
            }
        }
    }
    println!(
        "{compared} arches compared, {states} limit states (those at lambda_static included), {} differences",
        failures.len()
    );
    assert!(failures.is_empty(), "{}", failures.join("\n"));
    assert!(
        compared >= 150 && states >= 30,
        "{compared} compared, {states} states"
    );
}
