//! Separation over the continuum: the local maxima of each activation function
//! φ(β) over the joints of the arch for a given state x (formulation §3).
//!
//! For a continuous arch each φ is sampled on `Settings::scan_points` equally spaced
//! angles, a sign change of dφ/dβ in a cell brackets an interior maximum that is then
//! refined by safeguarded Newton on dφ/dβ = 0 with the exact d²φ/dβ²; the springings
//! are maxima when φ decreases into the arch. For a discrete arch the listed joints
//! are evaluated directly.

use crate::arch::{grid_angle, JointLayout, Radians};
use crate::contact::ContactKind;
use crate::contact::{Contact, Location, Peak};
use crate::settings::Settings;
use crate::state::State;
use crate::statics::{actions, actions_with, activation_of, forces_with, ring_slopes};

impl State<'_> {
    /// φ of `mode` and its first two β-derivatives at `beta`.
    pub fn phi(&self, mode: ContactKind, beta: Radians) -> [f64; 3] {
        let a = actions(self.arch, self.eta, beta);
        [0, 1, 2].map(|k| a.activation(mode, k, self.eta, self.mu).at(&self.x))
    }

    /// The local maxima of every active activation function over the continuum; for a
    /// discrete arch every joint's value (each joint is its own contact: two adjacent joints
    /// active with the same kind are two contacts, and a local-maximum filter over the joint
    /// sequence would drop one of them from the active set).
    pub fn peaks(&self, settings: &Settings) -> Vec<Peak> {
        match self.arch.layout() {
            JointLayout::Continuous => self.continuous_peaks(settings),
            JointLayout::Discrete(joints) => self.discrete_peaks(joints, true),
        }
    }

    /// Every contact (mode at a joint) whose value is at least `floor`; for a
    /// continuous arch, the local maxima above `floor`.
    pub fn near_active(&self, settings: &Settings, floor: f64) -> Vec<Peak> {
        let mut out = match self.arch.layout() {
            JointLayout::Continuous => self.continuous_peaks(settings),
            JointLayout::Discrete(joints) => self.discrete_peaks(joints, true),
        };
        out.retain(|p| p.value >= floor);
        out.sort_by(|a, b| b.value.total_cmp(&a.value));
        out
    }

    fn location(&self, beta: Radians) -> Location {
        if beta == self.arch.beta_right() || beta == self.arch.beta_left() {
            Location::Springing
        } else {
            Location::Interior
        }
    }

    fn discrete_peaks(&self, joints: &[Radians], all: bool) -> Vec<Peak> {
        let modes = ContactKind::active_at(self.mu);
        let mut values = vec![[0.0; 4]; joints.len()];
        let trig = self.arch.joint_sin_cos();
        let cached = trig.len() == joints.len();
        for (j, &beta) in joints.iter().enumerate() {
            let sc = if cached { trig[j] } else { beta.sin_cos() };
            let f = forces_with(self.arch, self.eta, beta, sc);
            for (k, &mode) in modes.iter().enumerate() {
                values[j][k] = activation_of(mode, &f, self.eta, self.mu).at(&self.x);
            }
        }
        let mut out = Vec::new();
        for (k, &mode) in modes.iter().enumerate() {
            for (j, &beta) in joints.iter().enumerate() {
                let v = values[j][k];
                let left_ok = j == 0 || values[j - 1][k] <= v;
                let right_ok = j + 1 == joints.len() || values[j + 1][k] < v;
                if all || (left_ok && right_ok) {
                    out.push(Peak {
                        contact: Contact {
                            beta,
                            kind: mode,
                            at: self.location(beta),
                            free: false,
                        },
                        value: v,
                        sin_cos: cached.then(|| trig[j]),
                    });
                }
            }
        }
        out
    }

    fn continuous_peaks(&self, settings: &Settings) -> Vec<Peak> {
        let (a, b) = (self.arch.beta_right(), self.arch.beta_left());
        let modes = ContactKind::active_at(self.mu);
        let n = settings.scan_points.max(3);
        let phi = |beta: Radians, orders: usize, only: Option<usize>| {
            let act = match self.arch.scan_sin_cos(n, beta) {
                Some(sc) => actions_with(self.arch, self.eta, beta, sc),
                None => actions(self.arch, self.eta, beta),
            };
            let mut out = [[0.0; 3]; 4];
            for (k, &mode) in modes.iter().enumerate() {
                if only.is_some_and(|o| o != k) {
                    continue;
                }
                for (d, slot) in out[k].iter_mut().enumerate().take(orders) {
                    *slot = act.activation(mode, d, self.eta, self.mu).at(&self.x);
                }
            }
            out
        };
        // the slopes from N and T at x (the ring's weight alone: not with fill)
        let ring = self
            .arch
            .scan_trig(n)
            .filter(|_| self.arch.fill().is_none());
        let terms = 2.0 + self.x[0].abs() + self.x[1].abs() + (b - a);
        let friction = if self.mu.is_finite() { self.mu } else { 0.0 };
        let sure = SLOPE_SIGN_ULPS * f64::EPSILON * terms * (1.0 + self.eta + friction);
        let on_grid = ring.map(|trig| {
            move |grid: &[Radians]| {
                let slopes = grid
                    .iter()
                    .zip(trig)
                    .map(|(&beta, &sc)| {
                        ring_slopes(self.arch, (self.eta, self.mu), beta, sc, &self.x, modes)
                    })
                    .collect();
                (slopes, sure)
            }
        });
        peaks_over_with(
            (a, Location::Springing),
            (b, Location::Springing),
            modes,
            n,
            &phi,
            on_grid.as_ref().map(|f| f as &Slopes<'_>),
        )
    }
}

/// A cheaper form of a scan's slopes on its grid than its `phi`, for the sign tests of
/// [`peaks_over_with`] (every value it returns and every Newton step is `phi`'s): dφ/dβ of
/// each mode at each angle of the grid given, and a bound above which a slope's sign is that
/// of `phi`'s (both within rounding of the exact slope).
pub type Slopes<'a> = dyn Fn(&[Radians]) -> (Vec<[f64; 4]>, f64) + 'a;

/// The sign of a slope from [`ring_slopes`] is sure above this many ε times
/// (2 + |h| + |v| + |β − β_R|)(1 + η + μ): each of the two forms rounds by at most ~16 of
/// them (a few products and sums of terms of that size), so a margin of 2; the largest gap
/// seen on 20 000 random states is ~1.7 of them
/// (`identities::ring_slopes_agree_with_the_full_evaluation_within_the_scan_bound`).
const SLOPE_SIGN_ULPS: f64 = 64.0;

/// The local maxima of each activation function over the smooth piece [a, b] of a
/// continuous arch; `phi(β, orders, only)[k]` holds the value and the first `orders − 1`
/// β-derivatives of `modes[k]` (all modes at once, from one evaluation of the actions; the
/// rest zero; with `only = Some(k)` `modes[k]` alone is needed, the others may be zero):
/// sampled on `n` equally spaced angles, a sign change of dφ/dβ in a cell brackets an interior maximum refined by
/// safeguarded Newton on dφ/dβ = 0 with the exact d²φ/dβ²; an end of the piece is a
/// maximum when φ decreases into the piece (its location as given: a springing, or the
/// fixed angle of a point load, which is no free tangency).
pub fn peaks_over(
    a: (Radians, Location),
    b: (Radians, Location),
    modes: &[ContactKind],
    n: usize,
    phi: &dyn Fn(Radians, usize, Option<usize>) -> [[f64; 3]; 4],
) -> Vec<Peak> {
    peaks_over_with(a, b, modes, n, phi, None)
}

/// [`peaks_over`], with the slopes on the grid from `slopes` where given (a cheaper form
/// than `phi`, equal to rounding: they only say where dφ/dβ changes sign, and where one is
/// too near zero for its sign to be sure, `phi`'s slope decides); every value returned and
/// every Newton step is `phi`'s.
pub fn peaks_over_with(
    (a, at_a): (Radians, Location),
    (b, at_b): (Radians, Location),
    modes: &[ContactKind],
    n: usize,
    phi: &dyn Fn(Radians, usize, Option<usize>) -> [[f64; 3]; 4],
    slopes: Option<&Slopes<'_>>,
) -> Vec<Peak> {
    let n = n.max(3);
    let grid: Vec<Radians> = (0..n).map(|i| grid_angle(a, b, n, i)).collect();
    // slopes on the grid (second derivatives only where Newton needs them): `phi`'s, with
    // its values at the ends; or the cheaper ones, each replaced by `phi`'s where it is too
    // near zero to be sure of its sign (so every sign is `phi`'s)
    let mut ends = None;
    let slope: Vec<[f64; 4]> = match slopes {
        None => {
            let all: Vec<[[f64; 3]; 4]> = grid.iter().map(|&beta| phi(beta, 2, None)).collect();
            ends = Some((all[0], all[n - 1]));
            all.iter().map(|v| v.map(|m| m[1])).collect()
        }
        Some(f) => {
            let (mut slope, sure) = f(&grid);
            for (s, &beta) in slope.iter_mut().zip(&grid) {
                for (k, v) in s.iter_mut().enumerate().take(modes.len()) {
                    if v.abs() <= sure {
                        *v = phi(beta, 2, Some(k))[k][1];
                    }
                }
            }
            slope
        }
    };
    let (at_first, at_last) = ends.unwrap_or_else(|| (phi(a, 1, None), phi(b, 1, None)));
    let mut out = Vec::new();
    for (k, &mode) in modes.iter().enumerate() {
        let slope = |i: usize| slope[i][k];
        let push = |out: &mut Vec<Peak>, beta: Radians, value: f64, at: Location, free: bool| {
            out.push(Peak {
                contact: Contact {
                    beta,
                    kind: mode,
                    at,
                    free,
                },
                value,
                sin_cos: None,
            })
        };
        if slope(0) <= 0.0 {
            push(&mut out, a, at_first[k][0], at_a, false);
        }
        if slope(n - 1) >= 0.0 {
            push(&mut out, b, at_last[k][0], at_b, false);
        }
        for i in 0..n - 1 {
            if slope(i) > 0.0 && slope(i + 1) <= 0.0 {
                let newton = |x: Radians| {
                    let v = phi(x, 3, Some(k))[k];
                    [v[1], v[2]]
                };
                let beta = refine_max(&newton, (grid[i], grid[i + 1]), slope(i + 1));
                if beta > a && beta < b {
                    let v = phi(beta, 1, Some(k))[k][0];
                    push(&mut out, beta, v, Location::Interior, true);
                }
            }
        }
    }
    out
}

/// Root of dφ/dβ in [lo, hi] where it goes from positive to `fhi` ≤ 0: Newton with the
/// exact second derivative, safeguarded by bisection.
fn refine_max(
    phi: &dyn Fn(Radians) -> [f64; 2],
    (mut lo, mut hi): (Radians, Radians),
    fhi: f64,
) -> Radians {
    if fhi == 0.0 {
        return hi;
    }
    let mut beta = 0.5 * (lo + hi);
    for _ in 0..100 {
        let [f, df] = phi(beta);
        if f > 0.0 {
            lo = beta;
        } else {
            hi = beta;
        }
        let newton = if df < 0.0 { beta - f / df } else { f64::NAN };
        let next = if newton > lo && newton < hi {
            newton
        } else {
            0.5 * (lo + hi)
        };
        let step = (next - beta).abs();
        beta = next;
        if step <= 4.0 * f64::EPSILON * (1.0 + beta.abs())
            || hi - lo <= 4.0 * f64::EPSILON * (1.0 + beta.abs())
        {
            break;
        }
    }
    beta
}

/// What a scan of a state over the whole arch says about it.
#[derive(Debug, Clone)]
pub struct Verdict {
    /// The greatest activation relative to its magnitude
    /// ([`crate::statics::magnitude`]): admissible when ≤ `adm_tol`.
    pub worst: f64,
    /// Every contact with φ ≥ −10 `adm_tol` × magnitude (the active pattern), by
    /// increasing β, then mode.
    pub active: Vec<Contact>,
}

impl State<'_> {
    /// Scans the state for the activation functions `modes`: its worst relative
    /// violation and its active contacts.
    pub fn verdict(&self, modes: &[ContactKind], settings: &Settings) -> Verdict {
        let mag = |m: ContactKind| {
            crate::statics::magnitude(m, self.eta, self.mu, &self.x, settings.magnitude_floor)
        };
        if let JointLayout::Discrete(joints) = self.arch.layout() {
            return self
                .discrete_verdict(joints, modes, &mag, settings, f64::INFINITY)
                .unwrap_or_else(|worst| Verdict {
                    worst,
                    active: Vec::new(),
                });
        }
        let peaks: Vec<Peak> = self
            .peaks(settings)
            .into_iter()
            .filter(|p| modes.contains(&p.contact.kind))
            .collect();
        let worst = peaks
            .iter()
            .map(|p| p.value / mag(p.contact.kind))
            .fold(f64::NEG_INFINITY, f64::max);
        let mut active: Vec<Contact> = peaks
            .iter()
            .filter(|p| p.value >= -10.0 * settings.adm_tol * mag(p.contact.kind))
            .map(|p| p.contact)
            .collect();
        active.sort_by(|a, b| a.beta.total_cmp(&b.beta).then(a.kind.cmp(&b.kind)));
        Verdict { worst, active }
    }

    /// [`Self::verdict`] when the state is admissible: `Err(r)` as soon as some contact has
    /// φ / magnitude = r above `adm_tol` (on a discrete arch the first one met, without
    /// scanning the rest; on a continuous arch the worst).
    pub fn admissible_verdict(
        &self,
        modes: &[ContactKind],
        settings: &Settings,
    ) -> Result<Verdict, f64> {
        if let JointLayout::Discrete(joints) = self.arch.layout() {
            let mag = |m: ContactKind| {
                crate::statics::magnitude(m, self.eta, self.mu, &self.x, settings.magnitude_floor)
            };
            return self.discrete_verdict(joints, modes, &mag, settings, settings.adm_tol);
        }
        let v = self.verdict(modes, settings);
        if v.worst > settings.adm_tol {
            Err(v.worst)
        } else {
            Ok(v)
        }
    }

    /// [`Self::verdict`] of a discrete arch in one pass over its joints (the same values,
    /// the same verdict), without listing every contact first; `Err(r)` at the first
    /// contact whose φ / magnitude = r exceeds `stop_above`.
    fn discrete_verdict(
        &self,
        joints: &[Radians],
        modes: &[ContactKind],
        mag: &dyn Fn(ContactKind) -> f64,
        settings: &Settings,
        stop_above: f64,
    ) -> Result<Verdict, f64> {
        let kinds: Vec<(ContactKind, f64)> = ContactKind::active_at(self.mu)
            .iter()
            .filter(|k| modes.contains(k))
            .map(|&k| (k, mag(k)))
            .collect();
        let trig = self.arch.joint_sin_cos();
        let cached = trig.len() == joints.len();
        let mut worst = f64::NEG_INFINITY;
        let mut active = Vec::new();
        for (j, &beta) in joints.iter().enumerate() {
            let sc = if cached { trig[j] } else { beta.sin_cos() };
            let f = forces_with(self.arch, self.eta, beta, sc);
            for &(kind, m) in &kinds {
                let value = activation_of(kind, &f, self.eta, self.mu).at(&self.x);
                if value / m > stop_above {
                    return Err(value / m);
                }
                worst = worst.max(value / m);
                if value >= -10.0 * settings.adm_tol * m {
                    active.push(Contact {
                        beta,
                        kind,
                        at: self.location(beta),
                        free: false,
                    });
                }
            }
        }
        active.sort_by(|a, b| a.beta.total_cmp(&b.beta).then(a.kind.cmp(&b.kind)));
        Ok(Verdict { worst, active })
    }
}
