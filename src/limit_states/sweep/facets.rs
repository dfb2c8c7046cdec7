//! The limit states of a loaded discrete arch below λ_static from the vertices of P̂ on
//! which a sliding row is active (docs/design/load-limit-states-on-the-seam.md §5). P̂ is
//! the polytope of the admissible z = (h, v, w, λ) with the box and λ_min ≤ λ ≤ λ_static
//! among its rows. Where P̂ has an interior point, every limit state strictly between
//! λ_min and λ_static has an active sliding row (the theorem of
//! docs/design/limit-states-on-boundary.md, read at fixed λ): a vertex of P̂ whose active
//! set carries a mechanism, or a point of an edge whose three rows have dependent
//! columns. So visiting every vertex of every face F_s = P̂ ∩ {φ_s = 0} of a sliding row s
//! finds them all: the vertex graph of a face of a polytope is connected, and a search
//! over the edges that keep some sliding row active walks every such face it enters; each
//! sliding row never seen active is either shown never active (an LP) or gives a face to
//! enter (the LP's optimal vertex).

use super::geometry::Vertex;
use super::sweeper::Sweeper;
use crate::contact::ContactKind;
use crate::lp::dense::NormalisedRows;
use crate::undecided::Undecided;
use itertools::Itertools;
use nalgebra::{Matrix3, Matrix4, Vector4};
use std::collections::{HashMap, HashSet, VecDeque};

/// A row of P̂: a · z + c ≤ 0.
type Row = ([f64; 4], f64);

/// A row is active at z when |a · z + c| is at most this times the size of its terms,
/// Σ |a_k z_k| + |c| (a few roundings of them): z is met by a 4 × 4 solve, so its own rows
/// hold to rounding, while at 4 000 voussoirs the intrados rows of the joints beside a
/// hinge at the crown are off by about 10⁻¹² (10⁻¹³ of their terms).
const ACTIVE_REL: f64 = 1e-14;

/// Along a direction d (unit 1-norm), a row stays active when |a · d| is at most this times
/// ‖a‖₁, and blocks the step when a · d is above it.
const PIVOT_REL: f64 = 1e-10;

/// A vertex with more rows active than this is not searched (the edges of a degenerate
/// vertex are enumerated from every three of its rows).
const MOST_ACTIVE: usize = 16;

/// The search stops (undecided) after this many vertices per row: a face of P̂ has at most
/// about twice as many vertices as rows, and the searches measured visit about half a
/// vertex per row, but near a long stretch of nearly active hinge rows (10⁴ voussoirs
/// under a point load) one face held more than 55 000 and the search ran for minutes.
const MOST_VERTICES_PER_ROW: usize = 8;

/// A sliding row whose largest value over P̂ (an LP) is below −this times the size of its
/// terms is never active; above −`TOUCH_REL` it is met at the LP's vertex; in between the
/// search says it cannot decide.
const NEVER_ACTIVE_REL: f64 = 1e-9;

/// A sliding row within this (relative to its terms) of zero at its LP's optimal vertex is
/// taken as active there: the LP's own tolerance and the vertex's solve leave about this.
const TOUCH_REL: f64 = 1e-11;

/// The box of P̂'s projection is widened by this (relative to its largest coordinate):
/// its LPs' optima are vertices to rounding.
const BOX_SLACK_REL: f64 = 1e-9;

/// A bound on the relative difference of a row's affine value and its plane's own
/// evaluation (a few roundings of the terms).
const ROUNDING_REL: f64 = 1e-12;

/// Feasibility tolerance of the LPs that decide whether a sliding row is ever active.
const LP_TOL: f64 = 1e-12;

/// The face search's rows and what it knows of them: the planes' rows in z, then the two
/// rows of the λ-range; which are sliding rows (their kind); the rows along +e_k.
pub(super) struct Rows {
    rows: Vec<Row>,
    sliding: Vec<Option<ContactKind>>,
    axes: [usize; 4],
    /// The rows along −e_k.
    negative_axes: [usize; 4],
    /// The rows scaled for the LPs.
    normalised: NormalisedRows,
    /// Each row's ‖a‖₁.
    norms: Vec<f64>,
    /// The rows that are the arch's contacts: the first ones, then the box's six planes,
    /// then the λ-range's two rows.
    contacts: usize,
}

fn dot(a: &[f64; 4], z: &[f64; 4]) -> f64 {
    a[0] * z[0] + a[1] * z[1] + a[2] * z[2] + a[3] * z[3]
}

fn norm1(a: &[f64; 4]) -> f64 {
    a.iter().map(|v| v.abs()).sum()
}

impl Rows {
    /// The rows of the sweeper's planes (constant gradients, constant terms affine in λ:
    /// a load sweep's) and λ_min ≤ λ ≤ `top`; `None` where a plane is not of that form.
    pub(super) fn of(sw: &Sweeper, lambda_min: f64, top: f64) -> Option<Rows> {
        let mut rows = Vec::with_capacity(sw.planes.len() + 2);
        let mut sliding = Vec::with_capacity(sw.planes.len() + 2);
        let mut axes = [usize::MAX; 4];
        let mut negative_axes = [usize::MAX; 4];
        let mut contacts = 0;
        for (i, p) in sw.planes.iter().enumerate() {
            let g = p.g.iter().map(|q| q.coeffs()).collect::<Vec<_>>();
            let c = p.c.coeffs();
            if p.scaled || g.iter().any(|q| q.len() > 1) || c.len() > 2 {
                return None;
            }
            let at = |q: &[f64], k: usize| q.get(k).copied().unwrap_or(0.0);
            let a = [at(g[0], 0), at(g[1], 0), at(g[2], 0), at(c, 1)];
            for k in 0..3 {
                let mut e = [0.0; 4];
                e[k] = 1.0;
                if p.contact.is_none() && a == e {
                    axes[k] = i;
                }
                e[k] = -1.0;
                if p.contact.is_none() && a == e {
                    negative_axes[k] = i;
                }
            }
            contacts += usize::from(p.contact.is_some());
            sliding.push(
                p.contact
                    .map(|c| c.kind)
                    .filter(|k| matches!(k, ContactKind::SlidePlus | ContactKind::SlideMinus)),
            );
            rows.push((a, at(c, 0)));
        }
        rows.push(([0.0, 0.0, 0.0, -1.0], lambda_min));
        rows.push(([0.0, 0.0, 0.0, 1.0], -top));
        sliding.extend([None, None]);
        axes[3] = rows.len() - 1;
        negative_axes[3] = rows.len() - 2;
        let found = axes.iter().chain(&negative_axes).all(|&a| a != usize::MAX);
        let contacts_first = sw.planes[..contacts].iter().all(|p| p.contact.is_some());
        (found && contacts_first && contacts == sw.planes.len() - 6).then(|| Rows {
            normalised: NormalisedRows::new(&rows),
            norms: rows.iter().map(|(a, _)| norm1(a)).collect(),
            rows,
            sliding,
            axes,
            negative_axes,
            contacts,
        })
    }

    fn value(&self, i: usize, z: &[f64; 4]) -> f64 {
        dot(&self.rows[i].0, z) + self.rows[i].1
    }

    /// The rows active at z, ascending (each row's terms summed only where its value is
    /// within a millionth of z's size of zero: most rows are far from it); with `wide`
    /// (the sweeper's largest tolerance for a contact, [`Sweeper::contact_tol`]) also the
    /// planes [`Sweeper::active`] may find active there, ascending: the box's, and the
    /// contacts' within twice `wide` of zero and the difference of the two evaluations (a
    /// few roundings of the terms).
    fn active(&self, z: &[f64; 4], wide: Option<f64>) -> (Vec<usize>, Vec<usize>) {
        let near = 1e-6 * (1.0 + norm1(z));
        let size = z.iter().fold(0.0f64, |m, v| m.max(v.abs()));
        let (mut out, mut candidates) = (Vec::new(), Vec::new());
        for (i, ((a, c), &norm)) in self.rows.iter().zip(&self.norms).enumerate() {
            let v = dot(a, z) + c;
            if wide.is_some_and(|w| {
                i < self.contacts && v.abs() <= 2.0 * w + ROUNDING_REL * (norm * size + c.abs())
            }) {
                candidates.push(i);
            }
            if v.abs() > near * norm.max(c.abs()) {
                continue;
            }
            let terms = (0..4).map(|k| (a[k] * z[k]).abs()).sum::<f64>() + c.abs();
            if v.abs() <= ACTIVE_REL * terms {
                out.push(i);
            }
        }
        if wide.is_some() {
            // the box's planes, after the contacts (the λ-range's rows are no planes)
            candidates.extend(self.contacts..self.rows.len() - 2);
        }
        (out, candidates)
    }

    /// The box of P̂'s projection onto (h, v, λ), widened by `BOX_SLACK_REL`: the least and
    /// largest h and v (four LPs) and λ's own range [λ_min, top] (rows of P̂; no LP: the
    /// simplex stalls on λ's, whose optimal face is a whole facet); `None` where an LP
    /// fails.
    fn projection_box(&self) -> Option<[[f64; 2]; 3]> {
        let widened = |lo: f64, hi: f64| {
            let slack = BOX_SLACK_REL * (1.0 + lo.abs().max(hi.abs()));
            [lo - slack, hi + slack]
        };
        let mut out = [[0.0; 2]; 3];
        for k in [0, 1] {
            // the row along +e_k is x_k + c ≤ 0: its largest value less c is x_k's
            let up = |row: usize| -> Option<f64> {
                let basis = self
                    .normalised
                    .max_row(row, self.axes, None, LP_TOL)
                    .ok()??;
                let z = self.meet(&basis)?;
                Some(z[k])
            };
            out[k] = widened(up(self.negative_axes[k])?, up(self.axes[k])?);
        }
        // the rows −λ + λ_min ≤ 0 and λ − top ≤ 0
        out[2] = widened(
            self.rows[self.negative_axes[3]].1,
            -self.rows[self.axes[3]].1,
        );
        Some(out)
    }

    /// Whether sliding row r is negative over the whole box `b` of (h, v, λ) (it has no w):
    /// then it is active nowhere on P̂.
    fn below_box(&self, r: usize, b: &[[f64; 2]; 3]) -> bool {
        let (a, c) = &self.rows[r];
        let most = |g: f64, range: [f64; 2]| (g * range[0]).max(g * range[1]);
        most(a[0], b[0]) + most(a[1], b[1]) + most(a[3], b[2]) + c < 0.0
    }

    /// For each direction d from the vertex z with active rows `act`, the first row d
    /// meets: the least step −(a · z + c) / (a · d) over the rows rising along d and not
    /// active (the first such row where steps tie); `None` where no row rises. One pass
    /// over the rows for all directions, each row's value taken once.
    fn blockers(&self, z: &[f64; 4], act: &[usize], directions: &[[f64; 4]]) -> Vec<Option<usize>> {
        let mut best: Vec<(f64, Option<usize>)> = vec![(f64::INFINITY, None); directions.len()];
        for (i, ((a, c), &norm)) in self.rows.iter().zip(&self.norms).enumerate() {
            let mut value = None;
            for (d, best) in directions.iter().zip(best.iter_mut()) {
                let rate = dot(a, d);
                if rate <= PIVOT_REL * norm {
                    continue;
                }
                let v = *value.get_or_insert_with(|| (!act.contains(&i)).then(|| dot(a, z) + c));
                let Some(v) = v else {
                    break; // an active row
                };
                let step = (-v / rate).max(0.0);
                if step < best.0 {
                    *best = (step, Some(i));
                }
            }
        }
        best.into_iter().map(|b| b.1).collect()
    }

    /// The point where the four rows `basis` meet.
    fn meet(&self, basis: &[usize; 4]) -> Option<[f64; 4]> {
        let m = Matrix4::from_fn(|r, c| self.rows[basis[r]].0[c]);
        let b = Vector4::from_fn(|r, _| -self.rows[basis[r]].1);
        let z = m.lu().solve(&b)?;
        let z = [z[0], z[1], z[2], z[3]];
        z.iter().all(|v| v.is_finite()).then_some(z)
    }
}

/// The direction along which the three rows `t` stay at zero (their cofactors), scaled to
/// unit 1-norm; `None` where they are dependent.
fn edge_direction(rows: &Rows, t: [usize; 3]) -> Option<[f64; 4]> {
    let mut d = [0.0; 4];
    for (k, dk) in d.iter_mut().enumerate() {
        let cols: Vec<usize> = (0..4).filter(|&c| c != k).collect();
        let minor = Matrix3::from_fn(|r, c| rows.rows[t[r]].0[cols[c]]).determinant();
        *dk = if k % 2 == 0 { minor } else { -minor };
    }
    let scale = t.iter().map(|&i| rows.norms[i]).product::<f64>();
    let n = norm1(&d);
    (n > PIVOT_REL * scale).then(|| d.map(|v| v / n))
}

/// The search's state: the vertices found (by their active rows), those not yet expanded,
/// the edges whose three rows were checked for dependent columns.
struct Search<'r> {
    rows: &'r Rows,
    index: HashMap<Vec<usize>, usize>,
    vertices: Vec<[f64; 4]>,
    queue: VecDeque<Vec<usize>>,
    seen_active: Vec<bool>,
    triples: HashSet<[usize; 3]>,
    /// The sets of rows whose meeting point was added.
    met: HashSet<Vec<usize>>,
}

impl Search<'_> {
    /// Adds the vertex at z, unless known, with its active rows: those that hold to
    /// rounding there and the rows `defining` it (met by a 4 × 4 solve, they hold to its
    /// accuracy, which may be coarser); checks it.
    fn add(
        &mut self,
        sw: &mut Sweeper,
        (z, defining): ([f64; 4], &[usize]),
        band: (f64, f64),
    ) -> Result<(), Undecided> {
        // the same rows meet at the same point: known (its active rows, taken at the
        // first meeting, are those of a nondegenerate vertex met from any side)
        let mut key = defining.to_vec();
        key.sort_unstable();
        if !self.met.insert(key) {
            return Ok(());
        }
        let in_band = z[3] > band.0 && z[3] < band.1;
        let x = [z[0], z[1], z[2]];
        let wide = in_band.then(|| sw.contact_tol(&x, z[3]));
        let (mut act, candidates) = self.rows.active(&z, wide);
        act.extend_from_slice(defining);
        act.sort_unstable();
        act.dedup();
        if act.len() > MOST_ACTIVE {
            return Err(Undecided::NotCovered(format!(
                "a vertex of the admissible (x, lambda) with {} rows active at lambda = {}",
                act.len(),
                z[3]
            )));
        }
        if self.index.contains_key(&act) {
            return Ok(());
        }
        if self.vertices.len() >= MOST_VERTICES_PER_ROW * self.rows.rows.len() {
            return Err(Undecided::NotCovered(format!(
                "the face search met more than {} vertices ({MOST_VERTICES_PER_ROW} per row of the admissible (x, lambda)) and stopped",
                self.vertices.len()
            )));
        }
        act.iter().for_each(|&i| self.seen_active[i] = true);
        self.index.insert(act.clone(), self.vertices.len());
        self.vertices.push(z);
        if in_band {
            let planes = sw.active_among(&x, z[3], candidates);
            sw.check(x, z[3], &planes);
        }
        self.queue.push_back(act);
        Ok(())
    }

    /// The edges at the vertex with active rows `act` that keep a sliding row active: each
    /// followed to its next vertex, and its three rows checked for dependent columns.
    fn expand(
        &mut self,
        sw: &mut Sweeper,
        act: &[usize],
        band: (f64, f64),
    ) -> Result<(), Undecided> {
        let z = self.vertices[self.index[act]];
        // each edge once, with every triple that gives it (rows equal to one another, as
        // the loaded joint's twin rows, give it from several triples: each is checked)
        let mut edges: Vec<([f64; 4], Vec<[usize; 3]>)> = Vec::new();
        for t in act.iter().copied().combinations(3) {
            let t = [t[0], t[1], t[2]];
            let Some(d) = edge_direction(self.rows, t) else {
                continue;
            };
            for d in [d, d.map(|v| -v)] {
                let along = |i: usize| dot(&self.rows.rows[i].0, &d);
                let tol = |i: usize| PIVOT_REL * self.rows.norms[i];
                // an edge: no active row rises along d, and the rows that stay active
                // (rank 3) hold a sliding row
                if act.iter().any(|&i| along(i) > tol(i))
                    || !act
                        .iter()
                        .any(|&i| self.rows.sliding[i].is_some() && along(i).abs() <= tol(i))
                {
                    continue;
                }
                match edges
                    .iter_mut()
                    .find(|e| norm1(&[0, 1, 2, 3].map(|k| e.0[k] - d[k])) < 1e-9)
                {
                    Some(e) => e.1.push(t),
                    None => edges.push((d, vec![t])),
                }
            }
        }
        let directions: Vec<[f64; 4]> = edges.iter().map(|e| e.0).collect();
        let blockers = self.rows.blockers(&z, act, &directions);
        for ((_, triples), blocker) in edges.iter().zip(blockers) {
            let next = self.reach(sw, (z, triples[0], blocker), band)?;
            for &t in triples {
                self.dependent(sw, t, (z[3], next[3]), band);
            }
        }
        Ok(())
    }

    /// The limit state along the edge of the rows `t` (from λ = `ends.0` to `ends.1`) where
    /// their columns are dependent ([`Sweeper::three_contact_mechanisms`]), once per triple.
    fn dependent(&mut self, sw: &mut Sweeper, t: [usize; 3], ends: (f64, f64), band: (f64, f64)) {
        let mut key = t;
        key.sort_unstable();
        if !t.iter().all(|&i| i < self.rows.contacts) || !self.triples.insert(key) {
            return;
        }
        let (lo, hi) = (
            ends.0.min(ends.1).max(band.0),
            ends.0.max(ends.1).min(band.1),
        );
        if hi > lo {
            let v = Vertex::new(&sw.planes, t);
            if v.det.norm() > 0.0 {
                sw.three_contact_mechanisms(&v, lo, hi);
            }
        }
    }

    /// The vertex where the edge of the rows `t` from z ends, on the row `blocker` that
    /// stops it ([`Rows::blockers`]; `None`: no row does), added.
    fn reach(
        &mut self,
        sw: &mut Sweeper,
        (z, t, blocker): ([f64; 4], [usize; 3], Option<usize>),
        band: (f64, f64),
    ) -> Result<[f64; 4], Undecided> {
        let Some(blocker) = blocker else {
            return Err(Undecided::NotCovered(
                "an unbounded edge of the admissible (x, lambda)".into(),
            ));
        };
        let Some(next) = self.rows.meet(&[t[0], t[1], t[2], blocker]) else {
            return Err(Undecided::NotCovered(format!(
                "an edge of the admissible (x, lambda) ends where its rows are dependent (lambda = {})",
                z[3]
            )));
        };
        self.add(sw, (next, &[t[0], t[1], t[2], blocker]), band)?;
        Ok(next)
    }
}

/// Every limit state of `sw`'s load strictly between `lambda_min` and `top` with a sliding
/// row active, checked by `sw` (its states and points without a mechanism); the vertices
/// visited. `Err` where the search cannot decide (a degenerate vertex, an LP the dense
/// simplex cannot solve): the caller then knows nothing from it.
pub(super) fn search(sw: &mut Sweeper, lambda_min: f64, top: f64) -> Result<usize, Undecided> {
    let Some(rows) = Rows::of(sw, lambda_min, top) else {
        return Err(Undecided::NotCovered(
            "the face search needs rows affine in lambda with constant gradients".into(),
        ));
    };
    let root = sw.settings.same_root;
    let band = (
        lambda_min + root * (1.0 + lambda_min.abs()),
        top - root * (1.0 + top.abs()),
    );
    let mut s = Search {
        rows: &rows,
        index: HashMap::new(),
        vertices: Vec::new(),
        queue: VecDeque::new(),
        seen_active: vec![false; rows.rows.len()],
        triples: HashSet::new(),
        met: HashSet::new(),
    };
    // rows negative over the box of P̂'s projection need no LP (where the box's LPs fail,
    // every row gets its LP)
    let bounds = rows.projection_box();
    // each LP starts from the optimum of the last one of its kind where it can (the
    // neighbouring joint's row)
    let mut warm = [None; 2];
    for r in 0..rows.rows.len() {
        let Some(kind) = rows.sliding[r] else {
            continue;
        };
        if s.seen_active[r] || bounds.is_some_and(|b| rows.below_box(r, &b)) {
            continue;
        }
        let warm = &mut warm[usize::from(kind == ContactKind::SlidePlus)];
        let lp = rows
            .normalised
            .max_row(r, rows.axes, *warm, LP_TOL)
            .map_err(|e| Undecided::Lp(format!("the face search's LP: {e:?}")))?;
        let Some(basis) = lp else {
            return Ok(0); // P̂ is empty
        };
        *warm = Some(basis);
        let Some(z) = rows.meet(&basis) else {
            return Err(Undecided::NotCovered(
                "a singular basis of the face search's LP".into(),
            ));
        };
        // the LP's optimum is the row's largest value over P̂ (to the LP's tolerance):
        // clearly negative, the row is never active; zero to rounding at the vertex of its
        // basis, that vertex starts a search; in between, undecided
        let (a, c) = &rows.rows[r];
        let terms = (0..4).map(|k| (a[k] * z[k]).abs()).sum::<f64>() + c.abs();
        let at = rows.value(r, &z);
        if at < -NEVER_ACTIVE_REL * terms {
            continue;
        }
        if at.abs() > TOUCH_REL * terms {
            return Err(Undecided::NotCovered(format!(
                "the sliding row {r} comes within {:e} of active (relative) at most: neither shown inactive nor met",
                -at / terms
            )));
        }
        let mut defining = basis.to_vec();
        defining.push(r);
        s.add(sw, (z, &defining), band)?;
        while let Some(act) = s.queue.pop_front() {
            s.expand(sw, &act, band)?;
        }
    }
    Ok(s.vertices.len())
}
