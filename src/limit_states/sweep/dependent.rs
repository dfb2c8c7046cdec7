//! Three active contacts whose compatibility columns are dependent carry a mechanism
//! without a fourth (formulation §4: e.g. a slide parallel to the line through two
//! hinges). A vertex of P(t) has three active contacts along its whole path, so the sweep
//! checks the points of the path where its three columns are dependent, besides the
//! events.

use super::geometry::{det3, Vertex};
use super::sweeper::{Param, Sweeper};
use crate::contact::Contact;
use crate::kinematics::column;
use crate::limit_states::poly::Poly;
use crate::load::{LiveLoad, Side};

/// The determinant of three columns (a cubic in η) vanishes identically, the columns being
/// dependent for every η, when its coefficients are all below this fraction of their
/// largest.
const ALWAYS_DEPENDENT_REL: f64 = 1e-13;

/// Three columns that do not depend on λ are dependent when the determinant of their
/// matrix is at most this times the cube of its norm.
const DEPENDENT_COLUMNS_REL: f64 = 1e-12;

/// The least λ at which a three-contact mechanism's power turns ≥ 0 is checked a little
/// past its root: relatively by `same_root`, and absolutely by this near λ = 0.
const PAST_ROOT_ABS: f64 = 1e-15;

impl Sweeper<'_> {
    /// Three active contacts carry a mechanism only where their compatibility columns are
    /// dependent (e.g. a slide parallel to the line through two hinges): the roots of the
    /// cubic det[c₁(η) c₂(η) c₃(η)] during the vertex's life, each checked.
    pub(super) fn three_contact_mechanisms(&mut self, v: &Vertex, from: f64, to: f64) {
        if let Param::Multiplier { eta, load } = self.param {
            self.three_contact_under_load(v, from, to, eta, load);
            return;
        }
        let Some(cs) = v
            .planes
            .iter()
            .map(|&i| self.planes[i].contact)
            .collect::<Option<Vec<Contact>>>()
        else {
            return;
        };
        let col = |c: &Contact| {
            let (c0, c1) = (column(c.kind, c.beta, 0.0), column(c.kind, c.beta, 1.0));
            [0, 1, 2].map(|k| Poly::linear(c0[k], c1[k] - c0[k]))
        };
        let cols: Vec<[Poly; 3]> = cs.iter().map(col).collect();
        let det = det3([0, 1, 2].map(|r| [&cols[0][r], &cols[1][r], &cols[2][r]]));
        let scale = det.norm().max(f64::MIN_POSITIVE);
        let roots = match det.roots_in(from, to, ALWAYS_DEPENDENT_REL, scale) {
            Some(r) => r,
            // dependent for every η (e.g. two slides at one joint): the sweep's events and
            // the least state cover such sets
            None => return,
        };
        for r in roots {
            if r <= from * (1.0 + self.settings.same_root) {
                continue;
            }
            let x = v.at(r);
            let act = self.active(&x, r);
            self.check(x, r, &act);
        }
    }

    /// Under a live load at fixed η the columns do not depend on λ: three contacts with
    /// dependent columns stay dependent along the whole vertex path, and their one rate
    /// vector r (B r = 0) has total power L_dead·r + λ L_live·r, linear in λ. It is a
    /// limit state from the least λ of the path at which that power is ≥ 0, if L_live·r > 0
    /// (checked there by the kinematic LP like any event).
    fn three_contact_under_load(
        &mut self,
        v: &Vertex,
        from: f64,
        to: f64,
        eta: f64,
        load: &LiveLoad,
    ) {
        let Some(cs) = v
            .planes
            .iter()
            .map(|&i| self.planes[i].contact.map(|c| (c, self.planes[i].side)))
            .collect::<Option<Vec<(Contact, Side)>>>()
        else {
            return;
        };
        let cols: Vec<[f64; 3]> = cs
            .iter()
            .map(|(c, _)| column(c.kind, c.beta, eta))
            .collect();
        let m = nalgebra::Matrix3::from_fn(|r, c| cols[c][r]);
        let scale = m.norm();
        if m.determinant().abs() > DEPENDENT_COLUMNS_REL * scale * scale * scale {
            return;
        }
        // the rate vector: a null vector of the column matrix (cross product of two rows)
        let rows = [m.row(0), m.row(1), m.row(2)];
        let mut r = nalgebra::Vector3::zeros();
        for (a, b) in [(0, 1), (0, 2), (1, 2)] {
            let c = rows[a].transpose().cross(&rows[b].transpose());
            if c.norm() > r.norm() {
                r = c;
            }
        }
        if r.norm() == 0.0 {
            return;
        }
        let plain: Vec<Contact> = cs.iter().map(|p| p.0).collect();
        let dead = crate::kinematics::power(self.arch, eta, &plain);
        let live = load.power(self.arch, eta, &cs);
        let (d, l): (f64, f64) = (0..3).fold((0.0, 0.0), |(d, l), k| {
            (d + dead[k] * r[k], l + live[k] * r[k])
        });
        let sign = if r.iter().all(|v| *v >= 0.0) {
            1.0
        } else if r.iter().all(|v| *v <= 0.0) {
            -1.0
        } else {
            return;
        };
        let (d, l) = (sign * d, sign * l);
        if l <= 0.0 {
            return;
        }
        let t = from.max(-d / l);
        if t >= to {
            return;
        }
        let t = if t > from {
            t * (1.0 + self.settings.same_root) + PAST_ROOT_ABS
        } else {
            t
        };
        let x = v.at(t);
        let act = self.active(&x, t);
        self.check(x, t, &act);
    }
}
