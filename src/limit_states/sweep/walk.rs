//! The vertices of P(t) where P(t) is not a point: a walk on its vertex graph from a point
//! inside it (the start of a sweep whose least state is degenerate, or whose P(t) has an
//! interior at the start).

use super::geometry::{PlaneAt, Vertex};
use super::sweeper::Sweeper;
use crate::statics::Reactions;

/// The walk's first ray, from the start to a facet: any direction serves that is not
/// parallel to a plane, so a fixed one of no particular alignment.
const FIRST_RAY: [f64; 3] = [0.6, 0.3, 0.7416];

/// Projected on the first facet, the direction the walk slides along within it to an edge
/// (as [`FIRST_RAY`], of no particular alignment).
const SLIDE_RAY: [f64; 3] = [0.31, -0.77, 0.55];

/// A ray whose rate towards a plane is below this times 1 + its ℓ₁ size is parallel to
/// the plane (it never meets it).
const PARALLEL_REL: f64 = 1e-14;

/// The walk gives up after visiting this many triples per plane (a safety net: a polytope
/// in three dimensions with n facets has at most 2n − 4 vertices).
const MAX_TRIPLES_PER_PLANE: usize = 20;

impl Sweeper<'_> {
    /// The vertices of P(η) by a walk on its vertex graph from `start` (a point of P(η)):
    /// shoot a ray to a facet, slide within it to an edge, along the edge to a vertex; then
    /// from each vertex along each of its three edges to the next plane (a ratio test over
    /// every plane). The vertex graph of a bounded polytope is connected, so the walk visits
    /// every vertex. Used where the least state is degenerate (its active planes' normals
    /// dependent, so that P(η_s) is not a point) and the first-order start does not apply.
    fn vertices_by_walk(&self, eta: f64, start: Reactions) -> Vec<[usize; 3]> {
        let g: Vec<[f64; 3]> = self.planes.iter().map(|p| p.affine(eta).g).collect();
        let at: Vec<PlaneAt> = self.planes.iter().map(|p| p.at(eta)).collect();
        let phi = |x: &Reactions, i: usize| at[i].value(x);
        let dot = |a: &[f64; 3], b: &[f64; 3]| a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
        let cross = |a: &[f64; 3], b: &[f64; 3]| {
            [
                a[1] * b[2] - a[2] * b[1],
                a[2] * b[0] - a[0] * b[2],
                a[0] * b[1] - a[1] * b[0],
            ]
        };
        // the first plane hit from x along d, skipping `skip`
        let shoot = |x: &Reactions, d: &[f64; 3], skip: &[usize]| -> Option<(usize, f64)> {
            let mut best: Option<(usize, f64)> = None;
            for (i, gi) in g.iter().enumerate() {
                if skip.contains(&i) {
                    continue;
                }
                let rate = dot(gi, d);
                if rate <= PARALLEL_REL * (1.0 + d.iter().map(|v| v.abs()).sum::<f64>()) {
                    continue;
                }
                let t = (-phi(x, i)).max(0.0) / rate;
                if best.is_none_or(|(_, bt)| t < bt) {
                    best = Some((i, t));
                }
            }
            best
        };
        let step = |x: &Reactions, d: &[f64; 3], t: f64| {
            [x[0] + t * d[0], x[1] + t * d[1], x[2] + t * d[2]]
        };
        let d1 = FIRST_RAY;
        let Some((p1, t1)) = shoot(&start, &d1, &[]) else {
            return vec![];
        };
        let x1 = step(&start, &d1, t1);
        let n1 = dot(&g[p1], &g[p1]);
        let u = SLIDE_RAY;
        let k = dot(&u, &g[p1]) / n1;
        let d2 = [
            u[0] - k * g[p1][0],
            u[1] - k * g[p1][1],
            u[2] - k * g[p1][2],
        ];
        let Some((p2, t2)) = shoot(&x1, &d2, &[p1]) else {
            return vec![];
        };
        let x2 = step(&x1, &d2, t2);
        let d3 = cross(&g[p1], &g[p2]);
        let Some((p3, _)) =
            shoot(&x2, &d3, &[p1, p2]).or_else(|| shoot(&x2, &[-d3[0], -d3[1], -d3[2]], &[p1, p2]))
        else {
            return vec![];
        };
        let mut seen: Vec<[usize; 3]> = Vec::new();
        let mut queue = vec![[p1, p2, p3]];
        while let Some(mut t) = queue.pop() {
            t.sort_unstable();
            if seen.contains(&t) || seen.len() > MAX_TRIPLES_PER_PLANE * self.planes.len() {
                continue;
            }
            seen.push(t);
            let v = Vertex::new(&self.planes, t);
            let x = v.at(eta);
            let tol = self.tol(&x);
            if !x.iter().all(|c| c.is_finite())
                || (0..self.planes.len()).any(|i| !t.contains(&i) && phi(&x, i) > tol)
            {
                continue; // not a vertex of P(η): do not walk on from it
            }
            for drop in 0..3 {
                let (p, q, k) = (t[(drop + 1) % 3], t[(drop + 2) % 3], t[drop]);
                let mut d = cross(&g[p], &g[q]);
                if dot(&g[k], &d) > 0.0 {
                    d = [-d[0], -d[1], -d[2]];
                }
                if let Some((r, _)) = shoot(&x, &d, &[p, q, k]) {
                    queue.push([p, q, r]);
                }
            }
        }
        seen
    }

    /// Starts from every vertex of P(t), found by a walk on its vertex graph from `centre`
    /// (a point inside P(t)).
    pub(super) fn start_by_walk(&mut self, t: f64, centre: Reactions) {
        let at: Vec<PlaneAt> = self.planes.iter().map(|p| p.at(t)).collect();
        for tri in self.vertices_by_walk(t, centre) {
            let v = Vertex::new(&self.planes, tri);
            let x = v.at(t);
            let tol = self.tol(&x);
            let feasible =
                (at.iter().enumerate()).all(|(i, p)| tri.contains(&i) || p.value(&x) <= tol);
            if !feasible {
                continue;
            }
            // a degenerate vertex (more planes through it than its three): only the
            // triples whose path stays inside the others just after t continue — e.g. at
            // λ = 0 the two sides of a loaded section are one plane, and the vertex on the
            // side that is violated for λ > 0 ends at once
            let mut act = self.active(&x, t);
            for p in tri {
                if !act.contains(&p) {
                    act.push(p);
                }
            }
            act.sort_unstable();
            if act.len() == 3 {
                self.push(v, t);
            } else {
                for w in self.vertices_after(&x, t, &act) {
                    self.push(w, t);
                }
            }
        }
    }
}
