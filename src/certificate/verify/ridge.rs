//! The `ridge` evidence of a thickness certificate, re-proved in interval arithmetic: that
//! the listed limit states are every limit state with η in (η_hi, 2) of a discrete arch
//! with the centreline weight at finite μ (docs/design/limit-states-on-boundary.md).
//!
//! With the centreline weight, N_j, T_j and m_j = M_j − w are affine in (h, v) alone; the
//! sliding rows cut the friction polygon Q, and the hinge rows leave w the band
//! [max_I l_j, min_E u_k], l = −m − ηN/2, u = −m + ηN/2. The argument, each step proved:
//!
//! 1. **Q is the listed polygon**: its vertices (two lines met, enclosed) satisfy every
//!    other sliding row strictly, `inside` satisfies every sliding row strictly, and the
//!    edges turn around `inside` once, counter-clockwise. So every point of ∂Q lies on a
//!    listed edge.
//! 2. **Every limit state above η_hi lies on the ridge over ∂Q**: the safe state has N > 0
//!    at every joint, so with `inside`, P(η) has an interior point at every η > η_hi; a
//!    limit state there slides at an active sliding row ((h, v) ∈ ∂Q), and by rotation
//!    balance (the third row of B) a mechanism with hinge rates has an active extrados and
//!    intrados row, so the band of w is closed: η = g(h, v), the ridge.
//! 3. **Cells along each edge** (s ∈ [0, 1], vertex to vertex): over a cell, the listed
//!    hinge rows give g as the largest of their pair values 2 (m_E − m_I)/(N_E + N_I)
//!    (each pair is necessary; at the largest, the others are open), provided every other
//!    row is strictly inactive on the box of (s, η, w) — proved. Then at every point of the
//!    cell the active contacts are among the listed ones. Inside a piece (one pair, one
//!    sliding row) the three columns are independent (det ≠ 0 over the cell's η): no
//!    mechanism. Around a junction, a Farkas certificate over the cell's η rules out a
//!    mechanism on the listed contacts and every subset; where the junction is a limit
//!    state, all its contacts are active at one point of the cell only (the difference of
//!    the two pairs' η, or the other sliding row, is monotone along the cell) and the other
//!    points have three independent columns: one limit state, matched (floating point) to
//!    a listed one.

use super::mechanism::{column_over, one_sense_choices, prove_farkas_over};
use super::statics::Model;
use crate::certificate::format::{
    ContactKind, LimitStateCert, NoMechanism, RidgeEdge, RidgeEvidence, Side,
};
use crate::certificate::interval::{det3, Interval as I};

/// Junction cells are tried with these half-widths in s (each edge has length 1), widest
/// first.
const CELL_RADII: [f64; 9] = [1e-5, 1e-6, 1e-7, 1e-8, 1e-9, 1e-10, 1e-11, 1e-12, 1e-13];

/// Two junctions of an edge closer than this (in s) may be proved as one cell: the walk
/// locates a crossing of two nearly parallel rows (neighbouring joints of a fine arch) only
/// to about 10⁻¹¹ at 1 000 voussoirs and 10⁻⁹ at 2 000, and such a crossing recurs at a point
/// of dependent columns, so a breakpoint may stand that far before it.
const CLUSTER_GAP: f64 = 1e-7;

/// A piece's interior is split down to this fraction of its end cells' half-width before
/// a part of it counts as not proved.
const SPLIT_FLOOR: f64 = 1.0 / 4096.0;

/// The cells one piece may be split into before it counts as not proved.
const PIECE_CELLS: usize = 20_000;

/// A junction matches a listed limit state when their η and reactions agree to this
/// (relative; floating point).
const MATCH_REL: f64 = 1e-8;

/// A joint's N, T and m = M − w as affine functions of (h, v): [∂h, ∂v, constant].
struct Rows {
    n: [I; 3],
    t: [I; 3],
    m: [I; 3],
}

/// The rows of the joint at `beta` (formulation §3, centreline weight).
fn rows_at(model: &Model, beta: f64) -> Rows {
    let b = I::point(beta);
    let (s, c) = model.trig(b);
    let br = I::point(model.beta_r);
    let (sr, cr) = model.springing;
    let d = b - br;
    Rows {
        n: [s, c, -(d * c)],
        t: [c, -s, d * s],
        m: [-(s - sr), cr - c, d * c - (s - sr)],
    }
}

fn ev(a: &[I; 3], p: [I; 2]) -> I {
    a[0] * p[0] + a[1] * p[1] + a[2]
}

/// The sliding row ±T − μN of a joint, affine in (h, v).
fn slide_row(r: &Rows, kind: ContactKind, mu: f64) -> [I; 3] {
    let sg = I::point(if kind == ContactKind::SlidePlus {
        1.0
    } else {
        -1.0
    });
    let mu = I::point(mu);
    [0, 1, 2].map(|k| sg * r.t[k] - mu * r.n[k])
}

/// Where two lines a·p + a₂ = 0 meet, enclosed (`None` if they may be parallel).
///
/// The point p̃ solved in floating point, then the error bound of a preconditioned linear
/// system: with Y ≈ A⁻¹ and M = I − Y A (ρ = ‖M‖∞ < 1), p − p̃ = −Y r + M (p − p̃), r =
/// A p̃ + a₂, so |p − p̃|∞ ≤ ‖Y r‖∞ / (1 − ρ) =: δ and p ∈ p̃ − Y r + M [−δ, δ]. Its width is
/// about ‖A⁻¹‖ times the rows' own (10⁻¹³ where the lines of neighbouring joints meet at a
/// fine arch); Cramer's rule in intervals gives one about a hundred times wider.
fn meet(a: &[I; 3], b: &[I; 3]) -> Option<[I; 2]> {
    let (am, bm) = (a.map(I::mid), b.map(I::mid));
    let det = am[0] * bm[1] - am[1] * bm[0];
    if det == 0.0 || !det.is_finite() {
        return None;
    }
    let p = [
        (bm[2] * am[1] - am[2] * bm[1]) / det,
        (bm[0] * am[2] - am[0] * bm[2]) / det,
    ];
    let y = [[bm[1] / det, -am[1] / det], [-bm[0] / det, am[0] / det]];
    let pt = p.map(I::point);
    let r = [ev(a, pt), ev(b, pt)];
    let (rows_a, one) = ([[a[0], a[1]], [b[0], b[1]]], I::point(1.0));
    let mag = |x: I| x.lo.abs().max(x.hi.abs());
    let mut rho = 0.0f64;
    let mut m = [[I::point(0.0); 2]; 2];
    let mut e = [I::point(0.0); 2];
    for i in 0..2 {
        let yi = y[i].map(I::point);
        e[i] = yi[0] * r[0] + yi[1] * r[1];
        for j in 0..2 {
            let ya = yi[0] * rows_a[0][j] + yi[1] * rows_a[1][j];
            m[i][j] = if i == j { one - ya } else { -ya };
        }
        // the row sum of |M| rounded up (an interval sum), so that 1 − ρ is not overstated
        let row = m[i]
            .iter()
            .map(|&x| I::point(mag(x)))
            .fold(I::point(0.0), |acc, x| acc + x);
        rho = rho.max(row.hi);
    }
    let rest = (one - I::point(rho)).recip().filter(|x| x.lo > 0.0)?;
    let delta = (I::point(mag(e[0]).max(mag(e[1]))) * rest).hi;
    let d = I::new(-delta, delta);
    Some(std::array::from_fn(|i| {
        pt[i] - e[i] + (m[i][0] * d + m[i][1] * d)
    }))
}

/// The joints in groups, a segment tree over their indices: node 1 holds every joint, node i
/// its children 2i and 2i + 1, and each node the hull of its joints' N and m coefficients (an
/// enclosure of every member's, so a slack enclosed with them holds for each member).
struct Groups {
    /// (first joint, one past the last, hull of N, hull of m) per node; node 0 unused.
    nodes: Vec<(usize, usize, [I; 3], [I; 3])>,
}

impl Groups {
    fn new(rows: &[Rows]) -> Groups {
        let mut nodes = vec![(0, 0, [I::point(0.0); 3], [I::point(0.0); 3]); 4 * rows.len().max(1)];
        fn build(
            nodes: &mut [(usize, usize, [I; 3], [I; 3])],
            rows: &[Rows],
            i: usize,
            (lo, hi): (usize, usize),
        ) {
            if hi - lo == 1 {
                nodes[i] = (lo, hi, rows[lo].n, rows[lo].m);
                return;
            }
            let mid = (lo + hi) / 2;
            build(nodes, rows, 2 * i, (lo, mid));
            build(nodes, rows, 2 * i + 1, (mid, hi));
            let hull = |a: [I; 3], b: [I; 3]| std::array::from_fn(|k| a[k].hull(b[k]));
            let (l, r) = (nodes[2 * i], nodes[2 * i + 1]);
            nodes[i] = (lo, hi, hull(l.2, r.2), hull(l.3, r.3));
        }
        if !rows.is_empty() {
            build(&mut nodes, rows, 1, (0, rows.len()));
        }
        Groups { nodes }
    }
}

/// A contact of the ridge: (joint index, kind).
type Row = (usize, ContactKind);

/// One edge, ready for cells: every joint's N and m at its two vertices (each f along the
/// edge is f₀ + s (f₁ − f₀)), the sliding rows not proved below 0 at both (the others are
/// below 0 all along it), its sliding row; the joints' rows
/// and the two vertices themselves, for sums and differences of rows ([`EdgeCtx::combo`]).
struct EdgeCtx<'a> {
    n: Vec<[I; 2]>,
    m: Vec<[I; 2]>,
    slides: Vec<(Row, [I; 2])>,
    row: Row,
    rows: &'a [Rows],
    groups: &'a Groups,
    vertices: [[I; 2]; 2],
    /// The [`PairRows`] built so far on this edge (a few pairs, each asked for by many
    /// cells).
    pairs: std::cell::RefCell<Vec<([Row; 2], std::rc::Rc<PairRows>)>>,
}

impl EdgeCtx<'_> {
    /// An affine row (coefficients) at the two vertices.
    fn at_vertices(&self, c: [I; 3]) -> [I; 2] {
        self.vertices.map(|v| ev(&c, v))
    }

    /// The (p, t) of slack `i` of the pair ([`PairRows`]) for the N and m rows `(n, m)` of
    /// its row (a joint's, or a group's hull: then an enclosure of every member's).
    fn slack_of(&self, pr: &PairRows, i: usize, (n, m): (&[I; 3], &[I; 3])) -> ([I; 2], [I; 2]) {
        let diff = |a: &[I; 3], b: &[I; 3]| std::array::from_fn(|q| a[q] - b[q]);
        let (nk, mk, nj, mj) = (
            &self.rows[pr.k].n,
            &self.rows[pr.k].m,
            &self.rows[pr.j].n,
            &self.rows[pr.j].m,
        );
        let (p, t) = if i.is_multiple_of(2) {
            (diff(mk, m), diff(n, nk))
        } else {
            (diff(m, mj), diff(n, nj))
        };
        (self.at_vertices(p), self.at_vertices(t))
    }

    /// Slack `i` of the pair: 2r is E_r, 2r + 1 is I_r.
    fn slack(&self, pr: &PairRows, i: usize) -> ([I; 2], [I; 2]) {
        let r = &self.rows[i / 2];
        self.slack_of(pr, i, (&r.n, &r.m))
    }

    /// The pair's [`PairRows`], built once per edge.
    fn pair(&self, pair: [Row; 2]) -> std::rc::Rc<PairRows> {
        if let Some((_, pr)) = self.pairs.borrow().iter().find(|(p, _)| *p == pair) {
            return pr.clone();
        }
        let pr = std::rc::Rc::new(pair_rows(self, pair));
        self.pairs.borrow_mut().push((pair, pr.clone()));
        pr
    }

    /// f_x ± f_y (the sign of `sg`) at the two vertices (f: a joint's N or m), the rows' coefficients
    /// combined first: the rows of nearby joints nearly cancel, and their difference taken
    /// after each is enclosed at the vertices would be as wide as the vertices' enclosures
    /// (about 10⁻¹² at 400 voussoirs, where a slack near a breakpoint is 10⁻¹¹).
    fn combo(&self, f: fn(&Rows) -> &[I; 3], (x, y): (usize, usize), sg: f64) -> [I; 2] {
        let (a, b) = (f(&self.rows[x]), f(&self.rows[y]));
        let c: [I; 3] = std::array::from_fn(|k| if sg > 0.0 { a[k] + b[k] } else { a[k] - b[k] });
        self.vertices.map(|v| ev(&c, v))
    }
}

/// A joint's N and m rows, for [`EdgeCtx::combo`].
fn n_row(r: &Rows) -> &[I; 3] {
    &r.n
}
fn m_row(r: &Rows) -> &[I; 3] {
    &r.m
}

/// f₀ + s (f₁ − f₀) over s: the two forms of it, intersected (each encloses it; the
/// first is tighter where f changes little along the edge, the second where f₀ or f₁ is
/// wide, as the value of a row at a vertex is).
fn along(f: [I; 2], s: I) -> I {
    let a = f[0] + s * (f[1] - f[0]);
    let b = (I::point(1.0) - s) * f[0] + s * f[1];
    I::new(a.lo.max(b.lo), a.hi.min(b.hi))
}

/// What a cell proved.
enum Cell {
    /// Its ridge lies at η ≥ 2 or η ≤ η_hi: no claim there.
    Outside,
    /// The listed contacts are the only ones that may be active; η over the cell.
    Listed(I),
    /// Not proved.
    Open,
}

/// One pair of hinge rows (E_k, I_j) along an edge, for [`Proof::one_pair`]: a = m_k − m_j
/// and b = N_k + N_j at the vertices (η = 2a/b on the pair's piece). Every other hinge row's
/// slack times b is p b + a t, against the pair's row of its own side (u_k − u_r, l_j − l_r:
/// the rows of nearby joints nearly cancel there): slack 2r is E_r, p = m_k − m_r,
/// t = N_r − N_k; slack 2r + 1 is I_r, p = m_r − m_j, t = N_r − N_j ([`EdgeCtx::slack`]).
struct PairRows {
    k: usize,
    j: usize,
    a: [I; 2],
    b: [I; 2],
}

fn pair_rows(e: &EdgeCtx, [(k, _), (j, _)]: [Row; 2]) -> PairRows {
    PairRows {
        k,
        j,
        a: e.combo(m_row, (k, j), -1.0),
        b: e.combo(n_row, (k, j), 1.0),
    }
}

/// The setting of the proof: the model, μ and η_hi.
struct Proof<'a> {
    model: &'a Model,
    joints: &'a [f64],
    eta_hi: f64,
}

impl Proof<'_> {
    /// The cell s ∈ `s` with the sliding rows `slides` and the hinge rows `hinges` listed.
    fn cell(&self, e: &EdgeCtx, s: I, slides: &[Row], hinges: &[Row]) -> Cell {
        if let [a, b] = hinges {
            if a.1 != b.1 && a.0 != b.0 {
                let pair = if a.1 == ContactKind::HingeExtrados {
                    [*a, *b]
                } else {
                    [*b, *a]
                };
                return self.one_pair(e, s, slides, &e.pair(pair));
            }
        }
        let n = |j: usize| along(e.n[j], s);
        let m = |j: usize| along(e.m[j], s);
        let upper = |r: &&Row| r.1 == ContactKind::HingeExtrados;
        let (es, is): (Vec<&Row>, Vec<&Row>) = hinges.iter().partition(upper);
        let mut h: Option<I> = None;
        for &&(ej, _) in &es {
            for &&(ij, _) in is.iter().filter(|r| r.0 != ej) {
                let Some(inv) = (n(ej) + n(ij)).recip().filter(|i| i.lo > 0.0) else {
                    return Cell::Open;
                };
                let eta = I::point(2.0) * (m(ej) - m(ij)) * inv;
                h = Some(h.map_or(eta, |x| I::new(x.lo.max(eta.lo), x.hi.max(eta.hi))));
            }
        }
        let Some(h) = h else { return Cell::Open };
        if h.lo >= 2.0 {
            return Cell::Outside;
        }
        let half = I::point(0.5) * h;
        let u = |j: usize| -m(j) + half * n(j);
        let l = |j: usize| -m(j) - half * n(j);
        let fold = |v: Vec<I>, f: fn(f64, f64) -> f64| {
            v.into_iter()
                .reduce(|a, b| I::new(f(a.lo, b.lo), f(a.hi, b.hi)))
        };
        let (Some(we), Some(wi)) = (
            fold(es.iter().map(|r| u(r.0)).collect(), f64::min),
            fold(is.iter().map(|r| l(r.0)).collect(), f64::max),
        ) else {
            return Cell::Open;
        };
        let (lo, hi) = (we.lo.max(wi.lo), we.hi.min(wi.hi));
        if lo > hi {
            return Cell::Open;
        }
        let w = I::new(lo, hi);
        // where w's enclosure is too wide, a row is inactive if it is strictly beyond some
        // listed row of its side (w ≤ u_e, w ≥ l_i), a difference of rows:
        // u_r − u_e = (m_e − m_r) + η/2 (N_r − N_e), l_i − l_r = (m_r − m_i) + η/2 (N_r − N_i)
        let gap = |(a, b): (usize, usize), r: usize, q: usize| {
            along(e.combo(m_row, (a, b), -1.0), s) + half * along(e.combo(n_row, (r, q), -1.0), s)
        };
        let beyond_e = |r: usize| es.iter().any(|&&(q, _)| gap((q, r), r, q).lo > 0.0);
        let beyond_i = |r: usize| is.iter().any(|&&(q, _)| gap((r, q), r, q).lo > 0.0);
        for j in 0..self.joints.len() {
            if !hinges.contains(&(j, ContactKind::HingeExtrados))
                && (u(j) - w).lo <= 0.0
                && !beyond_e(j)
            {
                return Cell::Open;
            }
            if !hinges.contains(&(j, ContactKind::HingeIntrados))
                && (w - l(j)).lo <= 0.0
                && !beyond_i(j)
            {
                return Cell::Open;
            }
        }
        self.finish(e, s, slides, h)
    }

    /// [`Proof::cell`] with one pair of hinge rows (E_k, I_j) ([`PairRows`]): η = 2a/b is
    /// monotone over the cell (linear-fractional, b > 0), and each other hinge row's slack
    /// times b is a quadratic in s, enclosed in centred form about the cell's middle (tight
    /// near a junction, where the slack vanishes linearly).
    fn one_pair(&self, e: &EdgeCtx, s: I, slides: &[Row], pr: &PairRows) -> Cell {
        self.one_pair_over(e, s, slides, (pr, None)).0
    }

    /// [`Proof::one_pair`] over the slacks `only` (indices as in [`PairRows`]; `None`: all,
    /// through [`Proof::open_slacks`]), with the slacks not proved positive (every one
    /// checked where some fails: a sub-cell of this one needs to check only those; empty
    /// where the cell fails otherwise, or proves).
    fn one_pair_over(
        &self,
        e: &EdgeCtx,
        s: I,
        slides: &[Row],
        (pr, only): (&PairRows, Option<&[usize]>),
    ) -> (Cell, Vec<usize>) {
        let (c, rad) = (I::point(s.mid()), I::new(-0.5 * s.width(), 0.5 * s.width()));
        let sq = I::new(0.0, 0.25 * s.width() * s.width());
        // an affine f along the edge: its value at the middle and its slope
        let at = |f: [I; 2]| (f[0] + c * (f[1] - f[0]), f[1] - f[0]);
        let (a, b) = (pr.a, pr.b);
        // where the cell fails before any slack is tried, its parts keep the parent's list
        // (an empty one: every slack, through the groups)
        let keep = || only.map_or_else(Vec::new, <[usize]>::to_vec);
        if along(b, s).lo <= 0.0 {
            return (Cell::Open, keep());
        }
        let eta_at = |x: f64| {
            let x = I::point(x);
            along(b, x)
                .recip()
                .map(|inv| I::point(2.0) * along(a, x) * inv)
        };
        let (Some(e0), Some(e1)) = (eta_at(s.lo), eta_at(s.hi)) else {
            return (Cell::Open, keep());
        };
        let h = e0.hull(e1);
        if h.lo >= 2.0 {
            return (Cell::Outside, Vec::new());
        }
        // slack · b = p b + a t (p, b, a, t affine in s), enclosed about the middle
        let ((q0, q1), (r0, r1)) = (at(b), at(a));
        let positive = |(p, t): ([I; 2], [I; 2])| {
            let ((p0, p1), (t0, t1)) = (at(p), at(t));
            let g = p0 * q0
                + r0 * t0
                + (p0 * q1 + p1 * q0 + r0 * t1 + r1 * t0) * rad
                + (p1 * q1 + r1 * t1) * sq;
            g.lo > 0.0
        };
        let open: Vec<usize> = match only {
            Some(only) => only
                .iter()
                .copied()
                .filter(|&i| !positive(e.slack(pr, i)))
                .collect(),
            None => self.open_slacks(e, pr, &positive),
        };
        if !open.is_empty() {
            return (Cell::Open, open);
        }
        (self.finish(e, s, slides, h), open)
    }

    /// The slacks of the pair that `positive` does not prove, found by descending the groups
    /// of joints ([`Groups`]): a group whose hull slack is proved positive is proved for
    /// every member; a single joint's is its own slack.
    fn open_slacks(
        &self,
        e: &EdgeCtx,
        pr: &PairRows,
        positive: &dyn Fn(([I; 2], [I; 2])) -> bool,
    ) -> Vec<usize> {
        let mut open = Vec::new();
        if e.rows.is_empty() {
            return open;
        }
        let mut stack: Vec<(usize, usize)> = vec![(1, 0), (1, 1)];
        while let Some((node, side)) = stack.pop() {
            let (lo, hi, n, m) = &e.groups.nodes[node];
            let skip = if side == 0 { pr.k } else { pr.j };
            let holds_skip = (*lo..*hi).contains(&skip);
            if !holds_skip && positive(e.slack_of(pr, side, (n, m))) {
                continue;
            }
            if hi - lo == 1 {
                if !holds_skip {
                    open.push(2 * lo + side);
                }
                continue;
            }
            stack.push((2 * node, side));
            stack.push((2 * node + 1, side));
        }
        open
    }

    /// The end of a cell's proof, once its hinge rows are settled: every sliding row not
    /// listed strictly inactive over the cell, then whether its ridge (η over `h`) needs a
    /// claim at all.
    fn finish(&self, e: &EdgeCtx, s: I, slides: &[Row], h: I) -> Cell {
        if e.slides
            .iter()
            .any(|(r, f)| !slides.contains(r) && along(*f, s).hi >= 0.0)
        {
            return Cell::Open;
        }
        if h.hi <= self.eta_hi {
            return Cell::Outside;
        }
        Cell::Listed(h)
    }

    /// The compatibility column of a row over η.
    fn column(&self, (j, kind): Row, eta: I) -> [I; 3] {
        column_over(kind, self.joints[j], eta)
    }

    /// The sliding column and a pair's two hinge columns are independent over η.
    fn independent(&self, slide: Row, pair: [Row; 2], eta: I) -> bool {
        det3([
            self.column(slide, eta),
            self.column(pair[0], eta),
            self.column(pair[1], eta),
        ])
        .excludes_zero()
    }

    /// The interior of a piece (s in `span`, the pair `pair`), split until every part is
    /// proved; `Err` with the first part that is not, narrower than `floor`.
    fn piece(
        &self,
        e: &EdgeCtx,
        span: (f64, f64),
        pair: [Row; 2],
        floor: f64,
    ) -> Result<usize, f64> {
        // each part with the slacks its parent did not prove (`None`: all)
        let mut stack: Vec<(f64, f64, Option<Vec<usize>>)> = vec![(span.0, span.1, None)];
        let mut cells = 0;
        // a piece's pair joins rows of distinct joints (`cell` takes the general path else)
        let rows = (pair[0].0 != pair[1].0).then(|| e.pair(pair));
        while let Some((a, b, only)) = stack.pop() {
            if b <= a {
                continue;
            }
            cells += 1;
            let s = I::new(a, b);
            let (cell, open) = match &rows {
                Some(pr) => self.one_pair_over(e, s, &[e.row], (pr, only.as_deref())),
                None => (self.cell(e, s, &[e.row], &pair), Vec::new()),
            };
            let open = (rows.is_some() && !open.is_empty()).then_some(open);
            let proved = match cell {
                Cell::Outside => true,
                Cell::Listed(h) => self.independent(e.row, pair, h),
                Cell::Open => false,
            };
            if !proved {
                if b - a < floor || cells > PIECE_CELLS {
                    return Err(0.5 * (a + b));
                }
                let mid = 0.5 * (a + b);
                stack.push((mid, b, open.clone()));
                stack.push((a, mid, open));
            }
        }
        Ok(cells)
    }
}

/// How the cell around a junction was settled.
enum Settled {
    /// No mechanism on its contacts over the cell (Farkas), or nothing to claim there.
    NoMechanism,
    /// One limit state in the cell, the junction's, matched to a listed one.
    Listed,
    /// The cell around the least limit state (at η_s): no other limit state is excluded
    /// there, up to this η (the top of the cell's range).
    NearLeast(f64),
}

/// Whether a junction is (to floating point, [`MATCH_REL`]) the listed limit state `ls`.
fn matches(jn: &NoMechanism, ls: &LimitStateCert) -> bool {
    let scale = 1.0 + jn.x.iter().map(|v| v.abs()).sum::<f64>();
    (ls.eta - jn.eta).abs() <= MATCH_REL * jn.eta
        && (0..3).all(|k| (ls.x[k] - jn.x[k]).abs() <= MATCH_REL * scale)
}

/// Re-proves the ridge evidence; `Ok` with the report's lines, `Err` with the reason the
/// list is not proved complete (a line of the report, not a rejection: nothing false is
/// claimed by evidence that fails to prove).
pub(super) fn prove_ridge(
    model: &Model,
    mu: f64,
    ridge: &RidgeEvidence,
    (listed, least): (&[&LimitStateCert], Option<&LimitStateCert>),
    (eta_hi, x_hi): (f64, [f64; 3]),
) -> Result<Vec<String>, String> {
    let Some(joints) = &model.joints else {
        return Err("the ridge needs a discrete arch".into());
    };
    if model.centroid {
        return Err("the ridge needs the centreline weight".into());
    }
    let rows: Vec<Rows> = joints.iter().map(|&b| rows_at(model, b)).collect();
    let groups = Groups::new(&rows);
    let mut lines = vec![polygon(mu, joints, &rows, ridge)?];
    // P(η) has an interior point at every η > η_hi
    let p = [I::point(x_hi[0]), I::point(x_hi[1])];
    if rows.iter().any(|r| ev(&r.n, p).lo <= 0.0) {
        return Err("the safe state does not have N > 0 at every joint".into());
    }
    lines.push(format!(
        "proved (interval arithmetic): N > 0 at every joint of the safe state and a point strictly inside Q, so P(eta) has an interior point at every eta > {eta_hi}: every limit state there slides at an active sliding row and has an active extrados and intrados row (rotation balance), so it lies on the ridge over the edges of Q (docs/design/limit-states-on-boundary.md §2–3)"
    ));
    let proof = Proof {
        model,
        joints,
        eta_hi,
    };
    let mut t = Tally {
        floor: eta_hi,
        ..Tally::default()
    };
    for k in 0..ridge.edges.len() {
        let e = edge_ctx(joints, (&rows, &groups), mu, ridge, k)?;
        proof.edge(&e, (ridge, k), (listed, least), &mut t)?;
    }
    let Tally {
        cells,
        pieces,
        by_farkas,
        matched,
        floor,
    } = t;
    lines.push(format!(
        "proved (interval arithmetic): along the {pieces} pieces of the ridge ({cells} cells), every other row is strictly inactive and the sliding and hinge columns are independent, so no limit state lies inside a piece; around {by_farkas} junctions the contacts carry no mechanism over the cell's eta (Farkas){}",
        if matched > 0 {
            format!("; around {matched}, one limit state only (all its contacts are active at one point of the cell), matched to a listed limit state (checked, floating point)")
        } else {
            String::new()
        }
    ));
    if floor > eta_hi {
        lines.push(format!(
            "not proved: around the least limit state, that no other limit state has eta in ({eta_hi}, {floor}] ({:.1e} relative; its cell's contacts carry a mechanism)",
            floor / eta_hi - 1.0
        ));
    }
    lines.push(format!(
        "proved: the listed limit states are every limit state with eta in ({floor}, 2){}",
        match matched {
            0 => String::new(),
            n => format!(
                " (up to the floating-point match of {n} junction state(s) to listed limit states)"
            ),
        }
    ));
    Ok(lines)
}

/// What the edges proved, for the report.
#[derive(Default)]
struct Tally {
    cells: usize,
    pieces: usize,
    by_farkas: usize,
    matched: usize,
    /// The η from which the list is proved complete (above η_hi where the least limit
    /// state's cell is left open).
    floor: f64,
}

impl Proof<'_> {
    /// Edge k of the ridge: the cell around each junction (its start, its breakpoints, its
    /// last vertex), then its pieces between the cells.
    fn edge(
        &self,
        e: &EdgeCtx,
        (ridge, k): (&RidgeEvidence, usize),
        (listed, least): (&[&LimitStateCert], Option<&LimitStateCert>),
        t: &mut Tally,
    ) -> Result<(), String> {
        let m = ridge.edges.len();
        let (prev, next) = (&ridge.edges[(k + m - 1) % m], &ridge.edges[(k + 1) % m]);
        let (prev_row, next_row) = (edge_row(self.joints, prev)?, edge_row(self.joints, next)?);
        let edge = &ridge.edges[k];
        let ends = ends(edge)?;
        let pairs = edge_pairs(self.joints, edge)?;
        let prev_pair = *edge_pairs(self.joints, prev)?
            .last()
            .ok_or("an edge without pieces")?;
        let next_pair = edge_pairs(self.joints, next)?[0];
        // the junctions: 0..pieces (junction i starts piece i), then the last vertex
        let last = ends.len() - 1;
        let jn_at = |i: usize| {
            if i == last {
                &next.junctions[0]
            } else {
                &edge.junctions[i]
            }
        };
        let slides_at = |i: usize| {
            let mut slides = vec![e.row];
            if i == 0 {
                slides.push(prev_row);
            }
            if i == last {
                slides.push(next_row);
            }
            slides
        };
        // the pieces before and after a junction (at a vertex, the neighbouring edge's), and
        // this edge's own
        let before = |i: usize| if i == 0 { prev_pair } else { pairs[i - 1] };
        let after = |i: usize| if i == last { next_pair } else { pairs[i] };
        let beside = |i: usize, j: usize| {
            [
                i.checked_sub(1).map(|p| pairs[p]),
                (j < last).then(|| pairs[j]),
            ]
        };
        // a cell around junctions i..=j stays within half the distance to the others
        let room = |i: usize, j: usize| {
            let half = |a: usize, b: usize| (ends[b] - ends[a]).abs() / 2.0;
            let r = if i > 0 { half(i - 1, i) } else { 1.0 };
            if j < last {
                r.min(half(j, j + 1))
            } else {
                r
            }
        };
        // how far each junction's cell reaches before and after it
        let mut reach = vec![(0.0, 0.0); ends.len()];
        let mut i = 0;
        while i <= last {
            // two junctions closer than a shallow crossing is located: one cell, if it proves
            let j = i + 1;
            let cluster = (j <= last && ends[j] - ends[i] <= CLUSTER_GAP)
                .then(|| {
                    let mut slides = slides_at(i);
                    slides.extend(slides_at(j));
                    slides.sort();
                    slides.dedup();
                    let mut around = vec![before(i), pairs[i], after(j)];
                    around.dedup();
                    self.cluster(
                        (e, [jn_at(i), jn_at(j)], &slides[..], &around[..]),
                        ((ends[i], ends[j]), room(i, j), beside(i, j)),
                    )
                })
                .flatten();
            let (j, r, how) = match cluster {
                Some(r) => (j, r, Settled::NoMechanism),
                None => {
                    let mut around = vec![before(i), after(i)];
                    around.dedup();
                    let slides = slides_at(i);
                    let (r, how) = self
                        .junction(
                            (e, jn_at(i), &slides[..], &around[..]),
                            (ends[i], room(i, i), beside(i, i)),
                            (listed, least),
                        )
                        .map_err(|why| format!("edge {k}, junction at s = {}: {why}", ends[i]))?;
                    (i, r, how)
                }
            };
            reach[i].0 = r;
            reach[j].1 = r;
            if j > i {
                (reach[i].1, reach[j].0) = (f64::INFINITY, f64::INFINITY);
            }
            t.cells += 1;
            match how {
                Settled::NoMechanism => t.by_farkas += 1,
                Settled::Listed => t.matched += 1,
                Settled::NearLeast(top) => t.floor = t.floor.max(top),
            }
            i = j + 1;
        }
        for (i, pair) in pairs.iter().enumerate() {
            let span = (ends[i] + reach[i].1, ends[i + 1] - reach[i + 1].0);
            let floor = reach[i].1.min(reach[i + 1].0) * SPLIT_FLOOR;
            t.cells += self
                .piece(e, span, *pair, floor)
                .map_err(|s| format!("edge {k}, piece {i}: not proved near s = {s}"))?;
            t.pieces += 1;
        }
        Ok(())
    }
}

impl Proof<'_> {
    /// The cell around the junction `jn` at s = `at` (half-width at most `room`), with its
    /// listed sliding rows and the pairs of the pieces on either side (`beside`: this
    /// edge's before and after it): the half-width used and how it was settled.
    fn junction(
        &self,
        (e, jn, slides, pairs): (&EdgeCtx, &NoMechanism, &[Row], &[[Row; 2]]),
        (at, room, beside): (f64, f64, [Option<[Row; 2]>; 2]),
        (listed, least): (&[&LimitStateCert], Option<&LimitStateCert>),
    ) -> Result<(f64, Settled), String> {
        let hinges: Vec<Row> = {
            let mut h: Vec<Row> = pairs.iter().flatten().copied().collect();
            h.sort();
            h.dedup();
            h
        };
        let mut last = String::from("no cell proved");
        let mut near: Vec<(f64, f64)> = Vec::new();
        // a cell of half-width r stands only if this edge's pieces beside it are proved from
        // its ends out to the widest cell's (where the pieces' own proofs take over)
        let widest = CELL_RADII[0].min(room);
        let beside_ok = |r: f64| {
            let floor = r * SPLIT_FLOOR;
            let piece = |p: [Row; 2], span| self.piece(e, span, p, floor).is_ok();
            beside[0].is_none_or(|p| piece(p, (at - widest, at - r)))
                && beside[1].is_none_or(|p| piece(p, (at + r, at + widest)))
        };
        for r in CELL_RADII.iter().map(|&r| r.min(room)) {
            let s = I::new((at - r).max(0.0), (at + r).min(1.0));
            let h = match self.cell(e, s, slides, &hinges) {
                Cell::Outside if beside_ok(r) => return Ok((r, Settled::NoMechanism)),
                Cell::Outside => {
                    last = "the pieces beside its cell are not proved up to it".into();
                    continue;
                }
                Cell::Open => {
                    last = "the other rows are not proved inactive around it".into();
                    continue;
                }
                Cell::Listed(h) => h,
            };
            let no_mechanism = self.farkas_covers(jn, slides.iter().chain(&hinges), h)?;
            if no_mechanism && beside_ok(r) {
                return Ok((r, Settled::NoMechanism));
            }
            match self.one_point((e, jn), s, slides, pairs, h) {
                Ok(()) if listed.iter().any(|ls| matches(jn, ls)) && beside_ok(r) => {
                    return Ok((r, Settled::Listed))
                }
                _ if no_mechanism => {
                    last = "the pieces beside its cell are not proved up to it".into()
                }
                Ok(()) => {
                    last = format!(
                        "its contacts may carry a mechanism (eta = {}) and no listed limit state is there",
                        jn.eta
                    )
                }
                Err(why) => last = why,
            }
            if least.is_some_and(|ls| matches(jn, ls)) {
                near.push((r, h.hi));
            }
        }
        // the least limit state: the narrowest cell whose pieces beside it are proved up
        // to the widest cell's ends, with no claim below its top
        near.sort_by(|a, b| a.0.total_cmp(&b.0));
        near.into_iter()
            .find(|&(r, _)| beside_ok(r))
            .map(|(r, top)| (r, Settled::NearLeast(top)))
            .ok_or(last)
    }

    /// Two junctions closer than [`CLUSTER_GAP`] (s in `span`) as one cell, widened by a
    /// half-width at most `room`: the rows of the pieces around and between them listed, and
    /// no mechanism on them over the cell's η, proved by either junction's Farkas
    /// certificates (a limit state inside is not matched here). The half-width used.
    fn cluster(
        &self,
        (e, jns, slides, pairs): (&EdgeCtx, [&NoMechanism; 2], &[Row], &[[Row; 2]]),
        (span, room, beside): ((f64, f64), f64, [Option<[Row; 2]>; 2]),
    ) -> Option<f64> {
        let mut hinges: Vec<Row> = pairs.iter().flatten().copied().collect();
        hinges.sort();
        hinges.dedup();
        let widest = CELL_RADII[0].min(room);
        let beside_ok = |r: f64| {
            let floor = r * SPLIT_FLOOR;
            let piece = |p: [Row; 2], span| self.piece(e, span, p, floor).is_ok();
            beside[0].is_none_or(|p| piece(p, (span.0 - widest, span.0 - r)))
                && beside[1].is_none_or(|p| piece(p, (span.1 + r, span.1 + widest)))
        };
        CELL_RADII.iter().map(|&r| r.min(room)).find(|&r| {
            let s = I::new((span.0 - r).max(0.0), (span.1 + r).min(1.0));
            let proved = match self.cell(e, s, slides, &hinges) {
                Cell::Outside => true,
                Cell::Listed(h) => jns.iter().any(|jn| {
                    self.farkas_covers(jn, slides.iter().chain(&hinges), h)
                        .unwrap_or(false)
                }),
                Cell::Open => false,
            };
            proved && beside_ok(r)
        })
    }

    /// Whether the junction's Farkas certificates cover every one-sense choice of its
    /// pattern over η ∈ `h`, the pattern holding every listed contact of the cell.
    fn farkas_covers<'r>(
        &self,
        jn: &NoMechanism,
        cell: impl Iterator<Item = &'r Row>,
        h: I,
    ) -> Result<bool, String> {
        for j in &jn.pattern {
            index(self.joints, j.beta)?;
        }
        let keyed: Vec<(f64, ContactKind, Option<Side>)> = jn
            .pattern
            .iter()
            .map(|j| (j.beta, j.kind, j.side))
            .collect();
        for &(j, kind) in cell {
            if !keyed.iter().any(|k| k.0 == self.joints[j] && k.1 == kind) {
                return Err(format!(
                    "its pattern lacks {} at beta = {}",
                    kind.name(),
                    self.joints[j]
                ));
            }
        }
        let Some(choices) = one_sense_choices(&keyed) else {
            return Ok(false);
        };
        let proved: Vec<&Vec<usize>> = jn
            .farkas
            .iter()
            .filter(|f| f.drop.iter().all(|&d| d < keyed.len()))
            .filter(|f| prove_farkas_over(self.model, (h, None), &keyed, f))
            .map(|f| &f.drop)
            .collect();
        Ok(choices
            .iter()
            .all(|c| proved.iter().any(|d| d.iter().all(|i| c.contains(i)))))
    }

    /// At most one point of the cell can be a limit state, the junction: at a vertex, the
    /// other sliding row vanishes there only and, away from it, the contacts of the edge
    /// carry no mechanism (one pair's independent columns, or the junction's Farkas
    /// certificate without that row); at a breakpoint, the two pairs' η cross once and
    /// each pair's columns are independent of the sliding column.
    fn one_point(
        &self,
        (e, jn): (&EdgeCtx, &NoMechanism),
        s: I,
        slides: &[Row],
        pairs: &[[Row; 2]],
        h: I,
    ) -> Result<(), String> {
        let independent = |p: &[Row; 2]| self.independent(e.row, *p, h);
        match (slides, pairs) {
            ([_, other], _) => {
                let f = e.slides.iter().find(|(r, _)| r == other).map(|x| x.1);
                if !f.is_some_and(|f| (f[1] - f[0]).excludes_zero()) {
                    return Err("the other sliding row may vanish more than once".into());
                }
                if let [p] = pairs {
                    if independent(p) {
                        return Ok(());
                    }
                }
                match self.without(jn, *other, h) {
                    true => Ok(()),
                    false => Err(
                        "no Farkas certificate covers the edge's contacts away from the vertex"
                            .into(),
                    ),
                }
            }
            ([_], [p, q]) => {
                if !(independent(p) && independent(q)) {
                    return Err("a pair's columns may be dependent with the sliding column".into());
                }
                let d = self.slope(e, *p, s) - self.slope(e, *q, s);
                match d.excludes_zero() {
                    true => Ok(()),
                    false => Err("the two pairs' eta may meet more than once".into()),
                }
            }
            // a point of dependent columns: the pair's η is monotone along the cell and the
            // determinant vanishes at one η of the cell's range only
            ([_], [p]) => {
                if self.slope(e, *p, s).excludes_zero()
                    && self.det_slope(e.row, *p, h).excludes_zero()
                {
                    Ok(())
                } else {
                    Err("the columns may be dependent at more than one point of the cell".into())
                }
            }
            _ => Err("a limit state where the cell lists other contacts is not covered".into()),
        }
    }

    /// Whether one of the junction's Farkas certificates leaves out no contact but `row`
    /// and is proved over η ∈ `h` (no mechanism on the others).
    fn without(&self, jn: &NoMechanism, (j, kind): Row, h: I) -> bool {
        let keyed: Vec<(f64, ContactKind, Option<Side>)> = jn
            .pattern
            .iter()
            .map(|p| (p.beta, p.kind, p.side))
            .collect();
        let Some(at) = keyed
            .iter()
            .position(|k| k.0 == self.joints[j] && k.1 == kind)
        else {
            return false;
        };
        jn.farkas.iter().any(|f| {
            f.drop.iter().all(|&d| d == at) && prove_farkas_over(self.model, (h, None), &keyed, f)
        })
    }

    /// d/dη of det[sliding column, E column, I column] over η ∈ `h`: the hinge columns
    /// change with η by [−sin β, cos β, 0]/2 (formulation §4: radii 1 ± η/2).
    fn det_slope(&self, slide: Row, pair: [Row; 2], h: I) -> I {
        let rate = |(j, _): Row| {
            let b = I::point(self.joints[j]);
            let half = I::point(0.5);
            [-(half * b.sin()), half * b.cos(), I::point(0.0)]
        };
        let (cs, ce, ci) = (
            self.column(slide, h),
            self.column(pair[0], h),
            self.column(pair[1], h),
        );
        det3([cs, rate(pair[0]), ci]) + det3([cs, ce, rate(pair[1])])
    }

    /// dη/ds of a pair's η = 2 a/b along the edge, over s.
    fn slope(&self, e: &EdgeCtx, [(ej, _), (ij, _)]: [Row; 2], s: I) -> I {
        let (a, b) = (
            e.combo(m_row, (ej, ij), -1.0),
            e.combo(n_row, (ej, ij), 1.0),
        );
        let (a1, b1) = (a[1] - a[0], b[1] - b[0]);
        let bs = along(b, s);
        let num = I::point(2.0) * (a1 * bs - along(a, s) * b1);
        match (bs * bs).recip() {
            Some(inv) => num * inv,
            None => I::new(f64::NEG_INFINITY, f64::INFINITY),
        }
    }
}

/// The index of a joint angle among the arch's joints.
fn index(joints: &[f64], beta: f64) -> Result<usize, String> {
    joints
        .iter()
        .position(|&b| b == beta)
        .ok_or_else(|| format!("beta = {beta} is not a joint of the arch"))
}

/// The pair of hinge rows of each piece of an edge.
fn edge_pairs(joints: &[f64], edge: &RidgeEdge) -> Result<Vec<[Row; 2]>, String> {
    if edge.pieces.is_empty() {
        return Err("an edge without pieces".into());
    }
    edge.pieces
        .iter()
        .map(|p| {
            Ok([
                (index(joints, p.extrados)?, ContactKind::HingeExtrados),
                (index(joints, p.intrados)?, ContactKind::HingeIntrados),
            ])
        })
        .collect()
}

/// The sliding row of an edge.
fn edge_row(joints: &[f64], edge: &RidgeEdge) -> Result<Row, String> {
    if !matches!(
        edge.row.kind,
        ContactKind::SlidePlus | ContactKind::SlideMinus
    ) {
        return Err("an edge's row must be a sliding row".into());
    }
    Ok((index(joints, edge.row.beta)?, edge.row.kind))
}

/// The positions of an edge's junctions: 0, the ends of its pieces but the last, and 1.
fn ends(edge: &RidgeEdge) -> Result<Vec<f64>, String> {
    let n = edge.pieces.len();
    if n == 0 || edge.junctions.len() != n {
        return Err("an edge needs a junction per piece".into());
    }
    let mut ends = vec![0.0];
    for p in &edge.pieces {
        if !(p.end > *ends.last().expect("nonempty") && p.end <= 1.0) {
            return Err("the pieces' ends must increase in (0, 1]".into());
        }
        ends.push(p.end);
    }
    if ends[n] != 1.0 {
        return Err("the last piece must end at s = 1".into());
    }
    Ok(ends)
}

/// The vertices of edge k (enclosed) and every joint's N, m and sliding rows at them.
fn edge_ctx<'a>(
    joints: &[f64],
    (rows, groups): (&'a [Rows], &'a Groups),
    mu: f64,
    ridge: &RidgeEvidence,
    k: usize,
) -> Result<EdgeCtx<'a>, String> {
    let m = ridge.edges.len();
    let line = |e: &RidgeEdge| -> Result<[I; 3], String> {
        let (j, kind) = edge_row(joints, e)?;
        Ok(slide_row(&rows[j], kind, mu))
    };
    let (l0, l1, l2) = (
        line(&ridge.edges[(k + m - 1) % m])?,
        line(&ridge.edges[k])?,
        line(&ridge.edges[(k + 1) % m])?,
    );
    let (Some(v0), Some(v1)) = (meet(&l0, &l1), meet(&l1, &l2)) else {
        return Err(format!(
            "the lines of edge {k} and a neighbour may be parallel"
        ));
    };
    let at = |a: &[I; 3]| [ev(a, v0), ev(a, v1)];
    // the neighbours' lines pass through the vertices exactly (v0 and v1 are where they
    // meet this edge's line): their rows are 0 there, not the enclosure of the row over the
    // vertex's box (about 10⁻¹¹ wide at 2 000 voussoirs, while such a line, nearly
    // parallel to the edge, stays within 10⁻⁷ of it)
    let (prev, next) = (
        edge_row(joints, &ridge.edges[(k + m - 1) % m])?,
        edge_row(joints, &ridge.edges[(k + 1) % m])?,
    );
    let mut slides = Vec::with_capacity(2 * rows.len());
    for (j, r) in rows.iter().enumerate() {
        for kind in [ContactKind::SlidePlus, ContactKind::SlideMinus] {
            // on the edge its own row is 0: each row less it, enclosed at the vertices (the
            // lines of neighbouring joints nearly cancel there)
            let own = slide_row(r, kind, mu);
            let mut f = at(&std::array::from_fn(|i| own[i] - l1[i]));
            if (j, kind) == prev {
                f[0] = I::point(0.0);
            }
            if (j, kind) == next {
                f[1] = I::point(0.0);
            }
            // a row below 0 at both vertices is below 0 all along the edge (affine in s)
            if f[0].hi >= 0.0 || f[1].hi >= 0.0 {
                slides.push(((j, kind), f));
            }
        }
    }
    Ok(EdgeCtx {
        n: rows.iter().map(|r| at(&r.n)).collect(),
        m: rows.iter().map(|r| at(&r.m)).collect(),
        slides,
        row: edge_row(joints, &ridge.edges[k])?,
        rows,
        groups,
        vertices: [v0, v1],
        pairs: Default::default(),
    })
}

/// Step 1: Q is the polygon of the listed edges. Returns the report's line.
fn polygon(
    mu: f64,
    joints: &[f64],
    rows: &[Rows],
    ridge: &RidgeEvidence,
) -> Result<String, String> {
    let m = ridge.edges.len();
    if m < 3 {
        return Err("Q needs at least three edges".into());
    }
    let q = [I::point(ridge.inside[0]), I::point(ridge.inside[1])];
    for r in rows {
        for kind in [ContactKind::SlidePlus, ContactKind::SlideMinus] {
            if ev(&slide_row(r, kind, mu), q).hi >= 0.0 {
                return Err("the point inside is not strictly inside Q".into());
            }
        }
    }
    let edge_rows: Vec<Row> = ridge
        .edges
        .iter()
        .map(|e| edge_row(joints, e))
        .collect::<Result<_, _>>()?;
    let line = |(j, kind): Row| slide_row(&rows[j], kind, mu);
    let mut vertices = Vec::with_capacity(m);
    for k in 0..m {
        let (a, b) = (edge_rows[(k + m - 1) % m], edge_rows[k]);
        if a.0 == b.0 {
            return Err("an apex of Q (both lines of one joint) is not covered".into());
        }
        let v = meet(&line(a), &line(b)).ok_or("two consecutive edges may be parallel")?;
        for (j, r) in rows.iter().enumerate() {
            for kind in [ContactKind::SlidePlus, ContactKind::SlideMinus] {
                if (j, kind) != a && (j, kind) != b && ev(&slide_row(r, kind, mu), v).hi >= 0.0 {
                    return Err(format!(
                        "a third sliding row may pass through vertex {k} of Q"
                    ));
                }
            }
        }
        // the two sliding columns there are not parallel (no pure sliding)
        let (ba, bb) = (I::point(joints[a.0]), I::point(joints[b.0]));
        if !(ba.cos() * bb.sin() - ba.sin() * bb.cos()).excludes_zero() {
            return Err(format!("the sliding columns at vertex {k} may be parallel"));
        }
        vertices.push(v);
    }
    let mut turn = 0.0;
    for k in 0..m {
        let (a, b) = (vertices[k], vertices[(k + 1) % m]);
        let (ax, ay, bx, by) = (a[0] - q[0], a[1] - q[1], b[0] - q[0], b[1] - q[1]);
        if (ax * by - ay * bx).lo <= 0.0 {
            return Err(format!(
                "edge {k} does not turn counter-clockwise around the point inside"
            ));
        }
        let ang = |x: I, y: I| y.mid().atan2(x.mid());
        let d = ang(bx, by) - ang(ax, ay);
        turn += if d < 0.0 {
            d + std::f64::consts::TAU
        } else {
            d
        };
    }
    // each step turns by an angle in (0, π) (proved above); their sum is 2π times the
    // winding number, which a floating-point sum within 1 of 2π settles
    if (turn - std::f64::consts::TAU).abs() > 1.0 {
        return Err("the edges wind around the point inside more than once".into());
    }
    Ok(format!(
        "proved (interval arithmetic): the friction polygon Q is the listed polygon of {m} edges (each vertex enclosed where two lines meet satisfies every other sliding row strictly, the point inside satisfies all, and the edges turn once around it)"
    ))
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Lines through a dyadic point p with exact coefficients meet exactly at p: the
    /// enclosure holds p, and is narrow even where the lines are nearly parallel (angle
    /// 2⁻²⁰); widened coefficients widen it; parallel lines give none.
    #[test]
    fn meet_encloses_the_point_where_lines_cross() {
        let p = [0.5, -1.25];
        let line = |a0: f64, a1: f64| {
            [
                I::point(a0),
                I::point(a1),
                I::point(-(a0 * p[0] + a1 * p[1])),
            ]
        };
        let eps = 2f64.powi(-20);
        // (lines, the width allowed: rounding times about the norm of A⁻¹)
        for (a, b, most) in [
            (line(1.0, 3.0), line(2.0, -1.0), 1e-14),
            (line(1.0, 1.0), line(1.0, 1.0 + eps), 1e-8),
            (line(-0.75, 0.5), line(-0.75 - eps, 0.5), 1e-8),
        ] {
            let v = meet(&a, &b).expect("lines that cross");
            for k in 0..2 {
                assert!(v[k].lo <= p[k] && p[k] <= v[k].hi, "{v:?}");
                assert!(v[k].width() < most, "{v:?}");
            }
            // each coefficient widened by 1e-15: still holds p, wider
            let wide = |l: [I; 3]| l.map(|x| I::new(x.lo - 1e-15, x.hi + 1e-15));
            let w = meet(&wide(a), &wide(b)).expect("lines that cross");
            for k in 0..2 {
                assert!(w[k].lo <= p[k] && p[k] <= w[k].hi && w[k].width() >= v[k].width());
            }
        }
        assert!(meet(&line(1.0, 2.0), &line(2.0, 4.0)).is_none());
    }
}
