//! The static multiplier range of a loaded **continuous** arch: the exchange method on the
//! semi-infinite LP in (h, v, w, λ), then Newton on the active pattern.
//!
//! At fixed η and μ the activation functions are affine in z = (h, v, w, λ) at every angle
//! of the continuum (at the point load's angle on both sides). The LP on a finite working
//! set of angles gives z; a scan of each smooth piece of the arch at z
//! ([`crate::scan::peaks_over`], exact derivatives) finds the most violated angles, which
//! join the working set, until the whole arch is admissible to `EXCHANGE_TOL` (at the cap on
//! λ, the direction in which λ grows must be). Each round's LP starts from the last one's
//! optimal basis ([`lp::WarmStart`]); λ_min = 0 is settled first, where the arch stands
//! unloaded, by one margin LP at λ = 0 and a scan of its state. The LP's z
//! (good to the back end's tolerance) then starts Newton on the square system of the active
//! pattern — φ = 0 at each contact, dφ/dβ = 0 at each interior tangency, unknowns z and
//! the tangency angles — whose root is verified by a scan (every φ ≤ `adm_tol` × its
//! magnitude): exact to rounding.

use crate::arch::{grid_angle, Arch, Radians};
use crate::contact::{Contact, ContactKind, Location, Peak};
use crate::family::{self, Tagged};
use crate::load::{live_activation, LiveLoad, Side};
use crate::lp::{self, LpOutcome};
use crate::refine::{self, Objective, Refined, Start, Unknowns};
use crate::scan::peaks_over;
use crate::settings::Settings;
use crate::statics::{actions, magnitude, Affine, Reactions};
use crate::undecided::Undecided;
use itertools::Itertools;
use nalgebra::{DMatrix, DVector};
use std::cell::{Cell, OnceCell};

/// Two rows that agree to this relative tolerance in every coefficient are one function
/// (twins: the extrados hinge of both sides of a loaded section).
const TWIN_REL: f64 = 1e-13;
/// Newton's tolerance on the load's rows (scaled residual): they are affine in (x, λ), so
/// Newton reaches the rounding level, and the least λ can be as small as 1e-10 (near μ_ms),
/// where only a residual this small fixes its leading digits.
const LOAD_NEWTON_TOL: f64 = 1e-15;
/// A vertex's multiplier above −this is ≥ 0 (rounding).
const MULTIPLIER_SLACK: f64 = 1e-9;
/// Relative violation at which the exchange stops (Newton finishes the job).
const EXCHANGE_TOL: f64 = 1e-9;
/// At most this many exchange rounds.
const MAX_ROUNDS: usize = 200;
/// The exchange's starting angles keep this distance from a point load's angle (which
/// joins the working set on both sides of its section).
const SAME_ANGLE: f64 = 1e-12;
/// A violated angle within this of one already in the working set (radians) adds nothing.
const WORK_GAP: f64 = 1e-9;
/// A multiplier within this (relative) of the cap is at the cap.
const AT_CAP_REL: f64 = 1e-9;
/// The exchange's state makes a contact active, for Newton, within this × its magnitude
/// (the LP's tolerance, well above rounding and below any real slack).
const ACTIVE_SLACK: f64 = 1e-7;
/// Newton from the exchange's state may move it this far (relative): the LP's state is good
/// to the back end's tolerance, so a root farther away is another vertex.
const EXCHANGE_REACH: f64 = 1e-2;
/// The multiplier is capped here in the LP (a finite working set can leave it unbounded);
/// an answer at the cap means unbounded.
const LAMBDA_CAP: f64 = 1e9;

/// A smooth piece of the arch: its two ends (angle, location) and the side of the loaded
/// section its sections are on.
type Piece = ((Radians, Location), (Radians, Location), Side);

/// The problem: arch, η, μ, load; and, from the second scan of a solve on (every scan
/// evaluates the activation functions at the same angles, and their trigonometry is most
/// of a scan's work), those values on the scan's grid of each smooth piece.
struct Loaded<'a> {
    arch: &'a Arch,
    eta: f64,
    mu: f64,
    load: &'a LiveLoad,
    scans: Cell<usize>,
    grids: OnceCell<Vec<Grid>>,
}

/// The sampling grid of one smooth piece as [`peaks_over`] lays it out (`n` angles from
/// `a` to `b`, the last one `b` itself), with each mode's activation function and its
/// β-derivative there: the dead part (affine in x) and the live coefficient of λ.
struct Grid {
    a: Radians,
    b: Radians,
    betas: Vec<Radians>,
    rows: Vec<[[(Affine, f64); 2]; 4]>,
}

impl Grid {
    /// The cached rows at `beta` if it is one of the grid's angles.
    fn at(&self, beta: Radians) -> Option<&[[(Affine, f64); 2]; 4]> {
        let n = self.betas.len();
        let t = (beta - self.a) / (self.b - self.a) * (n - 1) as f64;
        if !(t >= 0.0 && t <= (n - 1) as f64) {
            return None;
        }
        let i = t.round() as usize;
        (self.betas[i] == beta).then(|| &self.rows[i])
    }
}

impl<'a> Loaded<'a> {
    fn new(arch: &'a Arch, eta: f64, mu: f64, load: &'a LiveLoad) -> Loaded<'a> {
        Loaded {
            arch,
            eta,
            mu,
            load,
            scans: Cell::new(0),
            grids: OnceCell::new(),
        }
    }

    /// The grid of each smooth piece with the activation functions there.
    fn grids(&self, settings: &Settings) -> Vec<Grid> {
        let modes = ContactKind::active_at(self.mu);
        let n = settings.scan_points.max(3);
        self.pieces()
            .into_iter()
            .map(|piece| {
                let ((a, _), (b, _), _) = piece;
                // the grid of `peaks_over`, angle for angle
                let betas: Vec<Radians> = (0..n).map(|i| grid_angle(a, b, n, i)).collect();
                let rows = betas
                    .iter()
                    .map(|&beta| {
                        let act = actions(self.arch, self.eta, beta);
                        let side = self.side_at(&piece, beta);
                        let live = self.load.actions_d(self.arch, self.eta, beta, side);
                        let mut r = [[(
                            Affine {
                                g: [0.0; 3],
                                c: 0.0,
                            },
                            0.0,
                        ); 2]; 4];
                        for (k, &mode) in modes.iter().enumerate() {
                            for (d, slot) in r[k].iter_mut().enumerate() {
                                *slot = (
                                    act.activation(mode, d, self.eta, self.mu),
                                    live_activation(mode, self.eta, self.mu, live[d]),
                                );
                            }
                        }
                        r
                    })
                    .collect();
                Grid { a, b, betas, rows }
            })
            .collect()
    }

    /// (a, c) of every mode's activation function at β on `side` (β-derivative 0), in the
    /// order of [`ContactKind::active_at`]: [`Self::row`] for all modes at once.
    fn rows_at(&self, beta: Radians, side: Side) -> Vec<([f64; 4], f64)> {
        let act = actions(self.arch, self.eta, beta);
        let live = self.load.actions_d(self.arch, self.eta, beta, side)[0];
        ContactKind::active_at(self.mu)
            .iter()
            .map(|&kind| {
                let dead = act.activation(kind, 0, self.eta, self.mu);
                (
                    [
                        dead.g[0],
                        dead.g[1],
                        dead.g[2],
                        live_activation(kind, self.eta, self.mu, live),
                    ],
                    dead.c,
                )
            })
            .collect()
    }

    /// (a, c) of the activation function `kind` at β on `side`, β-derivative `order`:
    /// a · (h, v, w, λ) + c.
    fn row(&self, kind: ContactKind, beta: Radians, side: Side, order: usize) -> ([f64; 4], f64) {
        let dead = actions(self.arch, self.eta, beta).activation(kind, order, self.eta, self.mu);
        let live = self.load.actions_d(self.arch, self.eta, beta, side)[order];
        (
            [
                dead.g[0],
                dead.g[1],
                dead.g[2],
                live_activation(kind, self.eta, self.mu, live),
            ],
            dead.c,
        )
    }

    /// The smooth pieces of the arch: one, or one more at each of the load's breaks strictly
    /// inside (each end with its location, and the side of the section that belongs to the
    /// piece: `Before` on the first, `After` beyond the first break).
    fn pieces(&self) -> Vec<Piece> {
        let (a, b) = (self.arch.beta_right(), self.arch.beta_left());
        // a load at the left springing is carried by the section there (its free body is
        // the whole arch); at the right springing by every section but the springing's
        if matches!(*self.load, LiveLoad::Point { beta } if beta == b) {
            return vec![(
                (a, Location::Springing),
                (b, Location::Springing),
                Side::After,
            )];
        }
        let mut ends = vec![(a, Location::Springing)];
        ends.extend(
            self.load
                .breaks(self.arch, self.eta)
                .into_iter()
                .filter(|&t| t > a && t < b)
                .map(|t| (t, Location::Interior)),
        );
        ends.push((b, Location::Springing));
        ends.windows(2)
            .enumerate()
            .map(|(i, w)| (w[0], w[1], if i == 0 { Side::Before } else { Side::After }))
            .collect()
    }

    /// The side at which the piece `(from, to, side)` evaluates the load at `beta`: its own,
    /// except at the ends of a pressure's piece, where the values (at a point load) and the
    /// β-derivatives (at a patch's edge) are the piece's own, one-sided ones.
    fn side_at(&self, (from, to, side): &Piece, beta: Radians) -> Side {
        if !matches!(self.load, LiveLoad::Pressure(_)) {
            return *side;
        }
        // a point load at a springing is carried as by `LiveLoad::Point`: by every section
        // but the right springing's, and by the left springing's (the whole arch)
        if beta == self.arch.beta_right() {
            Side::Before
        } else if beta == self.arch.beta_left() || beta == from.0 {
            Side::After
        } else if beta == to.0 {
            Side::Before
        } else {
            *side
        }
    }

    /// The local maxima of every activation function at (x, λ) over the whole arch.
    fn peaks(&self, x: &Reactions, lambda: f64, settings: &Settings) -> Vec<(Peak, Side)> {
        let modes = ContactKind::active_at(self.mu);
        let mut out = Vec::new();
        let grids = (self.scans.replace(self.scans.get() + 1) > 0)
            .then(|| self.grids.get_or_init(|| self.grids(settings)));
        for (i, piece) in self.pieces().into_iter().enumerate() {
            let (from, to, _) = piece;
            let grid = grids.map(|g| &g[i]);
            let phi = |beta: Radians, orders: usize, _only: Option<usize>| {
                let mut v = [[0.0; 3]; 4];
                if orders <= 2 {
                    if let Some(rows) = grid.and_then(|g| g.at(beta)) {
                        for (k, _) in modes.iter().enumerate() {
                            for (d, slot) in v[k].iter_mut().enumerate().take(orders) {
                                let (dead, live) = &rows[k][d];
                                *slot = dead.at(x) + lambda * live;
                            }
                        }
                        return v;
                    }
                }
                let act = actions(self.arch, self.eta, beta);
                let live =
                    self.load
                        .actions_d(self.arch, self.eta, beta, self.side_at(&piece, beta));
                for (k, &mode) in modes.iter().enumerate() {
                    for (d, slot) in v[k].iter_mut().enumerate().take(orders) {
                        *slot = act.activation(mode, d, self.eta, self.mu).at(x)
                            + lambda * live_activation(mode, self.eta, self.mu, live[d]);
                    }
                }
                v
            };
            // each peak tagged with the side it was evaluated on (a pressure's piece ends
            // at a point load on its `before` side)
            out.extend(
                peaks_over(from, to, modes, settings.scan_points, &phi)
                    .into_iter()
                    .map(|p| (p, self.side_at(&piece, p.contact.beta))),
            );
        }
        out
    }

    fn magnitude(&self, kind: ContactKind, x: &Reactions, lambda: f64, settings: &Settings) -> f64 {
        magnitude(kind, self.eta, self.mu, x, settings.magnitude_floor) * (1.0 + lambda.abs())
    }

    /// The size of an activation function along the direction (x/λ, 1), times λ: its
    /// magnitude with λ added to the reactions' norm, (1 + ‖x‖₁ + λ) × η or min(μ, 1).
    fn ray_magnitude(
        &self,
        kind: ContactKind,
        x: &Reactions,
        lambda: f64,
        settings: &Settings,
    ) -> f64 {
        let floor = settings.magnitude_floor;
        magnitude(kind, self.eta, self.mu, x, floor)
            + lambda.abs() * magnitude(kind, self.eta, self.mu, &[0.0; 3], floor)
    }
}

/// A multiplier λ, an admissible state there and its active contacts.
pub type Extreme = (f64, Reactions, Vec<Tagged<Side>>);

/// Why [`extreme`] has no multiplier to return.
#[derive(Debug, Clone, PartialEq)]
pub enum NoExtreme {
    /// No state is admissible at any λ ≥ 0.
    NoState,
    /// No decision: an LP failed, the exchange did not converge, or Newton found no
    /// admissible root.
    Undecided(Undecided),
}

impl From<LpOutcome> for NoExtreme {
    fn from(e: LpOutcome) -> NoExtreme {
        match e {
            LpOutcome::Infeasible => NoExtreme::NoState,
            LpOutcome::Failed(t) => NoExtreme::Undecided(Undecided::Lp(t)),
        }
    }
}

/// The least (`maximise` false) or largest admissible λ ≥ 0 of a continuous arch, with the
/// state there and its active pattern. `Ok(None)`: unbounded.
pub fn extreme(
    arch: &Arch,
    eta: f64,
    mu: f64,
    load: &LiveLoad,
    maximise: bool,
    settings: &Settings,
) -> Result<Option<Extreme>, NoExtreme> {
    let p = Loaded::new(arch, eta, mu, load);
    let (a, b) = (arch.beta_right(), arch.beta_left());
    let modes = ContactKind::active_at(mu);
    // the working set: equally spaced angles, both sides of a point load's section
    let mut work: Vec<(Radians, Side)> = (0..=64)
        .map(|i| (a + (b - a) * i as f64 / 64.0, Side::After))
        .collect();
    for beta in load.breaks(arch, eta) {
        work.retain(|(w, _)| (w - beta).abs() > SAME_ANGLE);
        work.push((beta, Side::Before));
        if load.splits(beta) {
            work.push((beta, Side::After));
        }
    }
    // λ_min = 0 when the arch stands unloaded: the state of largest margin at λ = 0 on
    // the working set, verified over the whole arch, proves it (one margin LP and one
    // scan instead of an exchange whose every feasible state at λ = 0 is optimal, so
    // that its LP vertices wander over the unloaded admissible set)
    if !maximise {
        if let Some(found) = stands_unloaded(&p, &work, settings) {
            return Ok(Some(found));
        }
    }
    // the rows of the working set, appended as angles join it (each LP extends the last,
    // so its optimal basis starts the next: `lp::WarmStart`); the cap first
    let mut rows: Vec<([f64; 4], f64)> = Vec::with_capacity(modes.len() * (work.len() + 16) + 1);
    if maximise {
        rows.push(([0.0, 0.0, 0.0, 1.0], -LAMBDA_CAP));
    }
    let mut in_rows = 0;
    let mut warm = lp::WarmStart::default();
    for _ in 0..MAX_ROUNDS {
        for &(beta, side) in &work[in_rows..] {
            rows.extend(p.rows_at(beta, side));
        }
        in_rows = work.len();
        let z = match lp::multiplier_extreme_warm(&rows, maximise, settings, &mut warm)? {
            Some(z) => z,
            None => return Ok(None),
        };
        let (x, lambda) = ([z[0], z[1], z[2]], z[3]);
        let peaks = p.peaks(&x, lambda, settings);
        // at the cap (or on the back end's box) the working set leaves λ free to grow and
        // the state stands for the direction (x/λ, 1) in which it grows: its violations are
        // measured against that direction's size, (1 + ‖x‖₁ + λ), and join the working set
        // until the direction is admissible over the whole arch (against the state's own
        // magnitude, which grows like λ² there, every violation would pass)
        let at_cap = maximise && (lambda >= LAMBDA_CAP * (1.0 - AT_CAP_REL) || lp::on_box(&z));
        let size = |kind: ContactKind| {
            if at_cap {
                p.ray_magnitude(kind, &x, lambda, settings)
            } else {
                p.magnitude(kind, &x, lambda, settings)
            }
        };
        let violated: Vec<&(Peak, Side)> = peaks
            .iter()
            .filter(|(pk, _)| pk.value > EXCHANGE_TOL * size(pk.contact.kind))
            .collect();
        let before = work.len();
        for (pk, side) in violated {
            let beta = pk.contact.beta;
            if !work
                .iter()
                .any(|(w, s)| (w - beta).abs() <= WORK_GAP && s == side)
            {
                work.push((beta, *side));
            }
        }
        // admissible to the exchange's tolerance, or every violation sits at an angle
        // already in the working set (the LP's own tolerance): Newton takes over
        if work.len() == before {
            // at the cap on a working set the multiplier may still be bounded on the whole
            // arch: only a state at the cap admissible over the whole arch says unbounded
            if at_cap {
                return Ok(None);
            }
            return refine(&p, x, lambda, &peaks, maximise, settings).map(Some);
        }
    }
    Err(NoExtreme::Undecided(Undecided::Budget(format!(
        "the exchange did not converge in {MAX_ROUNDS} rounds"
    ))))
}

/// An admissible state at λ = 0, if the most interior state of the working set `work`
/// (the static margin LP at λ = 0, [`lp::max_margin`]) is admissible over the whole arch
/// ([`verify`]): the state and its active contacts. `None` says nothing (the arch may
/// still stand unloaded; the exchange decides).
fn stands_unloaded(p: &Loaded, work: &[(Radians, Side)], settings: &Settings) -> Option<Extreme> {
    let modes = ContactKind::active_at(p.mu);
    let rows: Vec<Affine> = work
        .iter()
        .flat_map(|&(beta, _)| {
            let a = actions(p.arch, p.eta, beta);
            modes.iter().map(move |&m| a.activation(m, 0, p.eta, p.mu))
        })
        .collect();
    let (x, s) = lp::max_margin(&rows, p.arch.span(), settings).ok()?;
    if s < 0.0 {
        return None;
    }
    let pattern = verify(p, &x, 0.0, settings).ok()?;
    Some((0.0, x, pattern))
}

/// Newton on the active pattern from the exchange's (x, λ), verified by a scan; λ = 0
/// with the arch standing unloaded needs no refinement.
fn refine(
    p: &Loaded,
    x: Reactions,
    lambda: f64,
    peaks: &[(Peak, Side)],
    maximise: bool,
    settings: &Settings,
) -> Result<Extreme, NoExtreme> {
    if !maximise && lambda == 0.0 {
        return Ok((
            0.0,
            x,
            active(p, &x, 0.0, peaks, 10.0 * settings.adm_tol, settings),
        ));
    }
    let pattern = active(p, &x, lambda, peaks, ACTIVE_SLACK, settings);
    newton_verified(
        p,
        x,
        lambda,
        &pattern,
        Refinement {
            maximise: Some(maximise),
            reach: EXCHANGE_REACH,
        },
        settings,
    )
    .map_err(NoExtreme::Undecided)
}

/// [`newton`] on `pattern`, verified over the arch; where the pattern has equations too
/// many (a contact within the activity slack that is not active at the root, or redundant
/// ones at a degenerate vertex), Newton on ever smaller subsets of it, the first root that is
/// admissible over the whole arch. Returns λ, the state and its active contacts
/// ([`verify`]).
fn newton_verified(
    p: &Loaded,
    x: Reactions,
    lambda: f64,
    pattern: &[Tagged<Side>],
    goal: Refinement,
    settings: &Settings,
) -> Result<Extreme, Undecided> {
    let verified = |(l, x): (f64, Reactions)| verify(p, &x, l, settings).map(|a| (l, x, a));
    let first = match newton(p, x, lambda, pattern, goal, settings) {
        Ok(r) => match verified(r) {
            Ok(found) => return Ok(found),
            Err(_) => Undecided::Newton(
                "the root of the pattern's system is not admissible over the arch".to_string(),
            ),
        },
        Err(e) => e,
    };
    // fewer and fewer contacts, down to a vertex's four: a degenerate vertex (more active
    // contacts than unknowns, as a symmetric load on a symmetric arch makes) is the root of
    // some four of them; any admissible root is the optimum when its multipliers are ≥ 0
    let n = pattern.len();
    let smallest = if n <= MAX_DEGENERATE {
        4.min(n)
    } else {
        n.saturating_sub(1)
    };
    for size in (smallest.max(1)..n).rev() {
        for keep in (0..n).combinations(size) {
            let rest: Vec<Tagged<Side>> = keep.iter().map(|&i| pattern[i]).collect();
            if let Ok(Ok(found)) = newton(p, x, lambda, &rest, goal, settings).map(verified) {
                return Ok(found);
            }
        }
    }
    Err(first)
}

/// A pattern of at most this many contacts is searched for a vertex among all its subsets
/// (C(12, 4) = 495 Newton solves at the most); a larger one only drops one contact at a time.
const MAX_DEGENERATE: usize = 12;

/// The contacts among `peaks` with φ ≥ −slack × magnitude.
fn active(
    p: &Loaded,
    x: &Reactions,
    lambda: f64,
    peaks: &[(Peak, Side)],
    slack: f64,
    settings: &Settings,
) -> Vec<Tagged<Side>> {
    peaks
        .iter()
        .filter(|(pk, _)| pk.value >= -slack * p.magnitude(pk.contact.kind, x, lambda, settings))
        .map(|(pk, side)| (pk.contact, *side))
        .collect()
}

/// The state over the whole arch: admissible (every φ ≤ `adm_tol` × its magnitude), with
/// its active contacts sorted by (β, side, kind); `Err` says why not.
fn verify(
    p: &Loaded,
    x: &Reactions,
    lambda: f64,
    settings: &Settings,
) -> Result<Vec<Tagged<Side>>, Undecided> {
    let peaks = p.peaks(x, lambda, settings);
    let worst = peaks
        .iter()
        .map(|(pk, _)| pk.value / p.magnitude(pk.contact.kind, x, lambda, settings))
        .fold(f64::NEG_INFINITY, f64::max);
    if worst > settings.adm_tol {
        return Err(Undecided::Newton(format!(
            "the refined state is not admissible over the arch (worst relative violation {worst:e})"
        )));
    }
    let mut pattern = active(p, x, lambda, &peaks, 10.0 * settings.adm_tol, settings);
    pattern.sort_by(|a, b| {
        a.0.beta
            .total_cmp(&b.0.beta)
            .then((a.1 == Side::After).cmp(&(b.1 == Side::After)))
            .then(a.0.kind.cmp(&b.0.kind))
    });
    Ok(pattern)
}

/// Whether (x, λ) is admissible over the whole continuous arch at friction `mu`: the worst
/// activation relative to its magnitude at most `settings.adm_tol`, as every refined state
/// here is checked.
pub(crate) fn admissible(
    (arch, eta, load): (&Arch, f64, &LiveLoad),
    mu: f64,
    x: &Reactions,
    lambda: f64,
    settings: &Settings,
) -> bool {
    verify(&Loaded::new(arch, eta, mu, load), x, lambda, settings).is_ok()
}

/// How a pattern is solved: the least or largest multiplier (an underdetermined pattern is
/// completed by the KKT conditions of that optimum), or a limit state of a discretisation
/// carried over (no objective); and how far from its start the root may lie (relative).
#[derive(Debug, Clone, Copy)]
pub(crate) struct Refinement {
    /// `Some(true)`: the largest λ; `Some(false)`: the least; `None`: no objective.
    pub(crate) maximise: Option<bool>,
    /// The root must lie within this relative distance of the start.
    pub(crate) reach: f64,
}

/// Newton on the system of `pattern` (twins merged) in the load family
/// ([`crate::refine::solve`], unknown λ): φ = 0 at each contact, dφ/dβ = 0 at each free
/// (tangency) contact. Where that is one or more equations short and an objective is given,
/// the KKT conditions of the optimum complete it (Σ y_i ∇_z φ_i = ±e_λ, y_i ≥ 0). A pattern
/// with more than four distinct rows is not a vertex (no square system); a root farther
/// than `goal.reach` from the start, or with λ < 0, is rejected; so is a square pattern's
/// root (a vertex) whose multipliers, Σ y_i ∇_z φ_i = ±e_λ, are not all ≥ 0 when an
/// objective is given: an admissible vertex that is not the optimum (a back end's inexact
/// z can point at one).
fn newton(
    p: &Loaded,
    x: Reactions,
    lambda: f64,
    pattern: &[Tagged<Side>],
    goal: Refinement,
    settings: &Settings,
) -> Result<(f64, Reactions), Undecided> {
    let pattern = distinct_rows(p, pattern);
    let n = pattern.len();
    let k = pattern.iter().filter(|c| c.0.free).count();
    if n > 4 {
        return Err(Undecided::Newton(format!(
            "the pattern has {n} contacts ({k} tangencies): not a vertex, no square system to refine"
        )));
    }
    let objective = match goal.maximise {
        Some(true) => Objective::Largest,
        Some(false) => Objective::Least,
        None if n == 4 => Objective::Least,
        None => {
            return Err(Undecided::Newton(format!(
                "the pattern has {n} contacts ({k} tangencies): too few for a vertex"
            )))
        }
    };
    let family = family::Load {
        arch: p.arch,
        eta: p.eta,
        load: p.load,
    };
    let start = Start {
        x,
        t: lambda,
        mu: p.mu,
    };
    let tight = Settings {
        newton_tol: LOAD_NEWTON_TOL,
        ..settings.clone()
    };
    let r = refine::solve(&family, &pattern, start, Unknowns::T, objective, &tight)
        .map_err(|e| Undecided::Newton(format!("Newton on the active pattern failed: {e:?}")))?;
    let scale0 = 1.0 + x.iter().map(|v| v.abs()).sum::<f64>() + lambda.abs();
    let moved = (0..3).fold((r.t - lambda).abs(), |m, q| m.max((r.x[q] - x[q]).abs()));
    if moved > goal.reach * scale0 || r.t < 0.0 {
        return Err(Undecided::Newton(format!(
            "Newton left the start's neighbourhood (moved {moved:e}, lambda {})",
            r.t
        )));
    }
    if n == 4 && goal.maximise.is_some() && !vertex_is_optimal(p, &r, objective) {
        return Err(Undecided::Newton(
            "a multiplier of the vertex is negative: not the optimum".into(),
        ));
    }
    Ok((r.t, r.x))
}

/// The pattern with twins merged: one contact for one function (the extrados hinge rows of
/// both sides of the point load's section are one, to rounding).
fn distinct_rows(p: &Loaded, pattern: &[Tagged<Side>]) -> Vec<Tagged<Side>> {
    let twin = |p1: &Tagged<Side>, p2: &Tagged<Side>| {
        let (a1, c1) = p.row(p1.0.kind, p1.0.beta, p1.1, 0);
        let (a2, c2) = p.row(p2.0.kind, p2.0.beta, p2.1, 0);
        p1.0.kind == p2.0.kind
            && p1.0.beta == p2.0.beta
            && (c1 - c2).abs() <= TWIN_REL * (1.0 + c1.abs())
            && (0..4).all(|k| (a1[k] - a2[k]).abs() <= TWIN_REL * (1.0 + a1[k].abs()))
    };
    let mut unique: Vec<Tagged<Side>> = Vec::new();
    for c in pattern {
        if !unique.iter().any(|u| twin(u, c)) {
            unique.push(*c);
        }
    }
    unique
}

/// Whether the vertex `r` (four rows) is the optimum of `objective`: its multipliers,
/// Σ y_i ∇_(x,λ) φ_i = ±e_λ, are all ≥ −`MULTIPLIER_SLACK`.
fn vertex_is_optimal(p: &Loaded, r: &Refined<Side>, objective: Objective) -> bool {
    let a = DMatrix::from_fn(4, r.contacts.len(), |row, c| {
        p.row(r.contacts[c].kind, r.contacts[c].beta, r.tags[c], 0)
            .0[row]
    });
    let sign = if objective == Objective::Largest {
        1.0
    } else {
        -1.0
    };
    let e = DVector::from_fn(4, |row, _| if row == 3 { sign } else { 0.0 });
    !a.lu()
        .solve(&e)
        .is_some_and(|y| y.iter().any(|&v| v < -MULTIPLIER_SLACK))
}

/// A limit state of a discretisation carried over to the continuum: contacts of one kind
/// on one side of the loaded section at adjacent joints (spacing `h`) become one tangency
/// contact (a springing or the point load's section stays where it is), Newton with λ
/// unknown on that pattern, the state verified over the whole arch; `None` when any step
/// fails. Returns λ, the state and its active contacts.
#[allow(clippy::too_many_arguments)]
pub fn carry_over(
    arch: &Arch,
    eta: f64,
    mu: f64,
    load: &LiveLoad,
    (lambda, x): (f64, Reactions),
    pattern: &[Tagged<Side>],
    h: f64,
    settings: &Settings,
) -> Option<Extreme> {
    let breaks = load.breaks(arch, eta);
    let fixed = |c: &(Contact, Side)| c.0.at == Location::Springing || breaks.contains(&c.0.beta);
    let merged: Vec<Tagged<Side>> = family::merge_adjacent(pattern, h, fixed)
        .into_iter()
        .collect();
    followed(arch, (eta, mu), load, (lambda, x), &merged, settings)
}

/// The state of a continuous pattern at (η, μ): Newton with λ unknown from (λ, x) (a limit
/// state of the pattern at another thickness or friction, or a discrete one carried over),
/// the root within 0.1 (relative) of the start and verified over the whole arch; `None`
/// when either fails. Returns λ, the state and its active contacts.
pub(crate) fn followed(
    arch: &Arch,
    (eta, mu): (f64, f64),
    load: &LiveLoad,
    (lambda, x): (f64, Reactions),
    pattern: &[Tagged<Side>],
    settings: &Settings,
) -> Option<Extreme> {
    let p = Loaded::new(arch, eta, mu, load);
    let goal = Refinement {
        maximise: None,
        reach: 0.1,
    };
    newton_verified(&p, x, lambda, pattern, goal, settings).ok()
}
