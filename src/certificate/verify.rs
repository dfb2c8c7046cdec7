//! Independent re-checking of a certificate ([`crate::certificate`]): no LP, no solver,
//! and its own interval evaluation of the statics (formulation §3) written out again
//! from the formulas, with outward rounding ([`super::interval`]).
//!
//! * **Safe side**: φ ≤ 0 at (η_hi, x) is *proved* on the whole continuum of joints by
//!   second-order Taylor enclosures on subintervals of [β_R, β_L]:
//!   φ(β) ≤ φ(m) + φ'(m)(β − m) + ½ sup φ'' (β − m)², with adaptive splitting; for a
//!   discrete arch, at each listed joint.
//! * **Collapse side**: for d + 1 contacts (d = 3 unknowns h, v, w; d = 2 for the
//!   friction-only problem, where w does not enter) the exact multipliers of a Farkas
//!   combination are the signed cofactors of the d × (d+1) gradient matrix, enclosed in
//!   intervals; if they share a sign and Σ yᵢ φᵢ(0) > 0 rigorously, then Σ yᵢ φᵢ(x) > 0 for
//!   every x, so no admissible state exists. The multipliers stored in the certificate must
//!   match the recomputed ones.
//! * **Limit state**: consistency checks in floating point with stated tolerances
//!   (B λ = 0, λ ≥ 0, Σ λ = 1, L_e ≥ 0, complementarity) — evidence, not proof.

use super::format::{CertJoint, Certificate, Claim, LimitStateCert, FORMAT, VERSION};
use super::interval::{det2, det3, Interval as I};
use std::f64::consts::PI;

/// Tolerances of the floating-point consistency checks of the limit state.
pub const LIMIT_STATE_TOL: f64 = 1e-9;

/// What `verify` proved or checked.
#[derive(Debug, Clone)]
pub struct Report {
    /// One line per check that passed.
    pub checks: Vec<String>,
}

/// Why a certificate does not hold.
#[derive(Debug, Clone, PartialEq)]
pub struct Rejection(pub String);

fn reject<T>(msg: impl Into<String>) -> Result<T, Rejection> {
    Err(Rejection(msg.into()))
}

/// The geometry and weight of the certificate's arch, for interval evaluation.
struct Model {
    beta_r: f64,
    beta_l: f64,
    centroid: bool,
    joints: Option<Vec<f64>>,
}

/// Interval values of N, T, M and their first two β-derivatives at β ∈ `b`.
struct Ntm {
    n: [I; 3],
    t: [I; 3],
    m: [I; 3],
}

impl Model {
    fn rho(&self, eta: f64) -> I {
        if self.centroid {
            let e = I::point(eta);
            I::point(1.0) + e * e * I::new((1.0f64 / 12.0).next_down(), (1.0f64 / 12.0).next_up())
        } else {
            I::point(1.0)
        }
    }

    fn ntm(&self, b: I, x: [f64; 3], eta: f64) -> Ntm {
        let (h, v, w) = (I::point(x[0]), I::point(x[1]), I::point(x[2]));
        let (s, c) = (b.sin(), b.cos());
        let br = I::point(self.beta_r);
        let (sr, cr) = (br.sin(), br.cos());
        let d = b - br;
        let rho = self.rho(eta);
        let one = I::point(1.0);
        let two = I::point(2.0);
        let n0 = h * s + v * c - d * c;
        let t0 = h * c - v * s + d * s;
        let m0 = -(h * (s - sr)) + v * (cr - c) + w + d * c - rho * (s - sr);
        let n1 = t0 - c;
        let t1 = -n0 + s;
        let m1 = -t0 + (one - rho) * c;
        let n2 = two * s - n0;
        let t2 = two * c - t0;
        let m2 = n0 - (two - rho) * s;
        Ntm {
            n: [n0, n1, n2],
            t: [t0, t1, t2],
            m: [m0, m1, m2],
        }
    }
}

fn phi(kind: &str, k: usize, a: &Ntm, eta: f64, mu: Option<f64>) -> I {
    let he = I::point(eta) * I::point(0.5);
    match kind {
        "hinge_extrados" => a.m[k] - he * a.n[k],
        "hinge_intrados" => -a.m[k] - he * a.n[k],
        "slide_plus" => a.t[k] - I::point(mu.unwrap_or(f64::INFINITY)) * a.n[k],
        _ => -a.t[k] - I::point(mu.unwrap_or(f64::INFINITY)) * a.n[k],
    }
}

fn kinds(mu: Option<f64>) -> &'static [&'static str] {
    match mu {
        Some(_) => &[
            "hinge_extrados",
            "hinge_intrados",
            "slide_plus",
            "slide_minus",
        ],
        None => &["hinge_extrados", "hinge_intrados"],
    }
}

/// Upper bound of φ over [a, b] by the second-order Taylor form at the midpoint.
fn taylor_upper(
    model: &Model,
    kind: &str,
    a: f64,
    b: f64,
    x: [f64; 3],
    eta: f64,
    mu: Option<f64>,
) -> (f64, f64) {
    let m = 0.5 * (a + b);
    let r = (b - m).max(m - a);
    let at_m = model.ntm(I::point(m), x, eta);
    let over = model.ntm(I::new(a, b), x, eta);
    let f0 = phi(kind, 0, &at_m, eta, mu);
    let f1 = phi(kind, 1, &at_m, eta, mu);
    let f2 = phi(kind, 2, &over, eta, mu);
    let p = f1.lo.abs().max(f1.hi.abs());
    let q = f2.hi;
    // max over |t| ≤ r of p|t| + q t²/2
    let g = |t: f64| p * t + 0.5 * q * t * t;
    let mut best = g(r).max(0.0);
    if q < 0.0 {
        let t = (p / -q).min(r);
        best = best.max(g(t));
    }
    // a little slack for the rounding of this final bound
    let upper = (f0.hi + best * (1.0 + 1e-12)).next_up();
    (upper, f0.lo)
}

/// Proves φ ≤ 0 for every activation function over the arch at (η, x).
fn prove_admissible(
    model: &Model,
    x: [f64; 3],
    eta: f64,
    mu: Option<f64>,
) -> Result<usize, Rejection> {
    let mut pieces = 0usize;
    for &kind in kinds(mu) {
        if let Some(joints) = &model.joints {
            for &b in joints {
                let v = phi(kind, 0, &model.ntm(I::point(b), x, eta), eta, mu);
                if v.hi > 0.0 {
                    return reject(format!("safe side: {kind} at the joint beta = {b} is not proved <= 0 (upper bound {:e})", v.hi));
                }
                pieces += 1;
            }
            continue;
        }
        let n0 = 64;
        let (lo, hi) = (model.beta_r, model.beta_l);
        let mut stack: Vec<(f64, f64, usize)> = (0..n0)
            .map(|i| {
                let a = if i == 0 {
                    lo
                } else {
                    lo + (hi - lo) * i as f64 / n0 as f64
                };
                let b = if i + 1 == n0 {
                    hi
                } else {
                    lo + (hi - lo) * (i + 1) as f64 / n0 as f64
                };
                (a, b, 0)
            })
            .collect();
        while let Some((a, b, depth)) = stack.pop() {
            pieces += 1;
            if pieces > 2_000_000 {
                return reject("safe side: enclosure work limit reached without a proof");
            }
            let (upper, lower_mid) = taylor_upper(model, kind, a, b, x, eta, mu);
            if upper <= 0.0 {
                continue;
            }
            if lower_mid > 0.0 {
                return reject(format!(
                    "safe side: {kind} is positive at beta = {} (phi >= {lower_mid:e}): the state is not admissible",
                    0.5 * (a + b)
                ));
            }
            if depth >= 60 || b - a <= 4.0 * f64::EPSILON * a.abs().max(1.0) {
                return reject(format!(
                    "safe side: {kind} near beta = {a} could not be proved <= 0 (bound {upper:e})"
                ));
            }
            let m = 0.5 * (a + b);
            stack.push((a, m, depth + 1));
            stack.push((m, b, depth + 1));
        }
    }
    Ok(pieces)
}

/// Interval gradient (w.r.t. x) and constant term of an activation function at β.
fn affine(model: &Model, kind: &str, beta: f64, eta: f64, mu: Option<f64>) -> ([I; 3], I) {
    let b = I::point(beta);
    let (s, c) = (b.sin(), b.cos());
    let br = I::point(model.beta_r);
    let (sr, cr) = (br.sin(), br.cos());
    let d = b - br;
    let rho = model.rho(eta);
    let z = I::point(0.0);
    let gn = [s, c, z];
    let gt = [c, -s, z];
    let gm = [-(s - sr), cr - c, I::point(1.0)];
    let (n0, t0, m0) = (-(d * c), d * s, d * c - rho * (s - sr));
    let he = I::point(0.5) * I::point(eta);
    let m = I::point(mu.unwrap_or(0.0));
    let comb = |a: I, g1: [I; 3], c1: I, k: I, g2: [I; 3], c2: I| {
        (
            [
                a * g1[0] + k * g2[0],
                a * g1[1] + k * g2[1],
                a * g1[2] + k * g2[2],
            ],
            a * c1 + k * c2,
        )
    };
    match kind {
        "hinge_extrados" => comb(I::point(1.0), gm, m0, -he, gn, n0),
        "hinge_intrados" => comb(I::point(-1.0), gm, m0, -he, gn, n0),
        "slide_plus" => comb(I::point(1.0), gt, t0, -m, gn, n0),
        _ => comb(I::point(-1.0), gt, t0, -m, gn, n0),
    }
}

/// Proves that the Farkas joints rule out every state at η (or, with `friction_only`,
/// every (h, v) for the sliding conditions alone).
fn prove_farkas(
    model: &Model,
    joints: &[CertJoint],
    eta: f64,
    mu: Option<f64>,
    friction_only: bool,
) -> Result<f64, Rejection> {
    let d = if friction_only { 2 } else { 3 };
    if joints.len() != d + 1 {
        return reject(format!(
            "collapse side: a Farkas certificate here needs exactly {} joints, found {}",
            d + 1,
            joints.len()
        ));
    }
    for j in joints {
        if !(j.beta >= model.beta_r && j.beta <= model.beta_l) {
            return reject(format!(
                "collapse side: joint beta = {} lies outside the arch",
                j.beta
            ));
        }
        if let Some(js) = &model.joints {
            if !js.contains(&j.beta) {
                return reject(format!(
                    "collapse side: beta = {} is not a joint of this discrete arch",
                    j.beta
                ));
            }
        }
        if friction_only && j.kind.starts_with("hinge") {
            return reject(
                "collapse side: the friction-only certificate may use sliding joints only",
            );
        }
        if mu.is_none() && !j.kind.starts_with("hinge") {
            return reject("collapse side: no sliding joints at infinite friction");
        }
    }
    let aff: Vec<([I; 3], I)> = joints
        .iter()
        .map(|j| affine(model, &j.kind, j.beta, eta, mu))
        .collect();
    let y: Vec<I> = (0..=d)
        .map(|i| {
            let cols: Vec<usize> = (0..=d).filter(|&k| k != i).collect();
            let sign = if i % 2 == 0 { 1.0 } else { -1.0 };
            let det = if d == 3 {
                det3([aff[cols[0]].0, aff[cols[1]].0, aff[cols[2]].0])
            } else {
                det2([
                    [aff[cols[0]].0[0], aff[cols[0]].0[1]],
                    [aff[cols[1]].0[0], aff[cols[1]].0[1]],
                ])
            };
            det.scale(sign)
        })
        .collect();
    let positive = y.iter().all(|v| v.lo > 0.0);
    let negative = y.iter().all(|v| v.hi < 0.0);
    if !positive && !negative {
        return reject("collapse side: the exact Farkas multipliers do not share a sign (or are not resolved): no proof");
    }
    let y: Vec<I> = if negative {
        y.iter().map(|v| -*v).collect()
    } else {
        y
    };
    // the stored multipliers must be the recomputed ones (normalised to sum 1)
    let total: f64 = y.iter().map(|v| v.mid()).sum();
    let stored_total: f64 = joints.iter().map(|j| j.y).sum();
    for (j, v) in joints.iter().zip(&y) {
        let (a, b) = (v.mid() / total, j.y / stored_total);
        if stored_total.is_nan()
            || stored_total <= 0.0
            || (a - b).abs() > 1e-6 * (1.0 + a.abs())
            || j.y < 0.0
        {
            return reject(format!("collapse side: stored multiplier {} at beta = {} does not match the recomputed {a:.9e} (normalised)", j.y, j.beta));
        }
    }
    let c = y
        .iter()
        .zip(&aff)
        .fold(I::point(0.0), |acc, (yi, (_, ci))| acc + *yi * *ci);
    if c.lo <= 0.0 {
        return reject(format!(
            "collapse side: sum y_i phi_i(0) = [{:e}, {:e}] is not proved > 0",
            c.lo, c.hi
        ));
    }
    Ok(c.lo / total)
}

/// Re-checks `cert`. Ok with the list of checks passed, or the first reason it fails.
pub fn verify(cert: &Certificate) -> Result<Report, Rejection> {
    let mut checks = Vec::new();
    if cert.format != FORMAT || cert.version != VERSION {
        return reject(format!(
            "not an {FORMAT} version {VERSION} certificate (found {} version {})",
            cert.format, cert.version
        ));
    }
    let a = &cert.arch;
    if !(a.beta_right.is_finite()
        && a.beta_left.is_finite()
        && a.beta_right < a.beta_left
        && a.beta_left - a.beta_right <= 2.0 * PI)
    {
        return reject("arch: springings out of order or out of range");
    }
    let centroid = match a.weight.as_str() {
        "centreline" => false,
        "centroid" => true,
        w => return reject(format!("arch: unknown weight model {w}")),
    };
    let model = Model {
        beta_r: a.beta_right,
        beta_l: a.beta_left,
        centroid,
        joints: a.joint_angles.clone(),
    };
    if let Some(mu) = cert.mu {
        if !(mu.is_finite() && mu > 0.0) {
            return reject("mu must be finite and positive (null for infinite friction)");
        }
    }
    match cert.claim {
        Claim::NoEquilibrium => {
            let Some(f) = &cert.collapse else {
                return reject("no_equilibrium claim without a Farkas certificate");
            };
            let margin = prove_farkas(&model, &f.joints, 1.0, cert.mu, true)?;
            checks.push(format!(
                "proved: no (h, v) satisfies |T| <= mu N at the {} listed joints (Farkas, margin {margin:.3e}), so no thickness can stand at mu = {}",
                f.joints.len(),
                cert.mu.map_or("inf".into(), |m| m.to_string())
            ));
        }
        Claim::LeastThickness => {
            let (Some(safe), Some(col)) = (&cert.safe, &cert.collapse) else {
                return reject(
                    "least_thickness claim needs both a safe state and a Farkas certificate",
                );
            };
            let Some(eta_lo) = col.eta else {
                return reject("collapse side: missing eta");
            };
            if !(eta_lo > 0.0 && safe.eta < 2.0 && eta_lo <= safe.eta) {
                return reject(format!(
                    "need 0 < eta_lo <= eta_hi < 2, found eta_lo = {eta_lo}, eta_hi = {}",
                    safe.eta
                ));
            }
            let pieces = prove_admissible(&model, safe.x, safe.eta, cert.mu)?;
            checks.push(format!(
                "proved: the state x = {:?} is admissible at eta_hi = {} over the whole arch ({pieces} enclosures)",
                safe.x, safe.eta
            ));
            let margin = prove_farkas(&model, &col.joints, eta_lo, cert.mu, false)?;
            checks.push(format!(
                "proved: no state is admissible at eta_lo = {eta_lo} (Farkas on {} joints, margin {margin:.3e})",
                col.joints.len()
            ));
            let gap = safe.eta - eta_lo;
            if let Some(g) = cert.gap {
                if (g - gap).abs() > 1e-15 * safe.eta + 1e-300 {
                    return reject(format!(
                        "stated gap {g} differs from eta_hi - eta_lo = {gap}"
                    ));
                }
            }
            checks.push(format!(
                "hence eta*(mu) lies in [{eta_lo}, {}] (gap {gap:.3e}, relative {:.3e})",
                safe.eta,
                gap / safe.eta
            ));
            if let Some(ls) = &cert.limit_state {
                check_limit_state(&model, cert.mu, ls, eta_lo, safe.eta)?;
                checks.push("checked: the limit state is consistent (B lambda = 0, lambda >= 0, sum 1, L_e >= 0, complementarity)".into());
            }
        }
    }
    Ok(Report { checks })
}

/// Proves only the safe side of a least-thickness certificate (used by `certify` while
/// it searches for the lower side).
pub fn prove_safe_only(cert: &Certificate) -> Result<usize, Rejection> {
    let a = &cert.arch;
    let model = Model {
        beta_r: a.beta_right,
        beta_l: a.beta_left,
        centroid: a.weight == "centroid",
        joints: a.joint_angles.clone(),
    };
    let Some(safe) = &cert.safe else {
        return reject("no safe side");
    };
    prove_admissible(&model, safe.x, safe.eta, cert.mu)
}

fn check_limit_state(
    model: &Model,
    mu: Option<f64>,
    ls: &LimitStateCert,
    eta_lo: f64,
    eta_hi: f64,
) -> Result<(), Rejection> {
    let tol = LIMIT_STATE_TOL;
    if !(ls.eta >= eta_lo && ls.eta <= eta_hi) {
        return reject(format!(
            "limit state: eta = {} outside [eta_lo, eta_hi]",
            ls.eta
        ));
    }
    if ls.rates.len() != ls.pattern.len() || ls.rates.iter().any(|&r| r.is_nan() || r < 0.0) {
        return reject("limit state: rates must be one non-negative number per pattern joint");
    }
    if (ls.rates.iter().sum::<f64>() - 1.0).abs() > tol {
        return reject("limit state: rates do not sum to 1");
    }
    let eta = ls.eta;
    let scale = 1.0 + ls.x.iter().map(|v| v.abs()).sum::<f64>();
    let mut b = [0.0; 3];
    for (j, &r) in ls.pattern.iter().zip(&ls.rates) {
        let (s, c) = (j.beta.sin(), j.beta.cos());
        let (re, ri) = (1.0 + eta / 2.0, 1.0 - eta / 2.0);
        let col = match j.kind.as_str() {
            "hinge_extrados" => [-re * s, re * c, -1.0],
            "hinge_intrados" => [ri * s, -ri * c, 1.0],
            "slide_plus" => [c, s, 0.0],
            "slide_minus" => [-c, -s, 0.0],
            k => return reject(format!("limit state: unknown joint kind {k}")),
        };
        for i in 0..3 {
            b[i] += r * col[i];
        }
        let v = phi(&j.kind, 0, &model.ntm(I::point(j.beta), ls.x, eta), eta, mu);
        if v.mid().abs() > tol * scale {
            return reject(format!(
                "limit state: {} at beta = {} is not active (phi = {:e})",
                j.kind,
                j.beta,
                v.mid()
            ));
        }
    }
    if b.iter().any(|v| v.abs() > tol) {
        return reject(format!("limit state: B lambda = {b:?} is not zero"));
    }
    // external power: blocks between distinct pattern joints
    let rho = model.rho(eta).mid();
    let mut angles: Vec<f64> = ls.pattern.iter().map(|j| j.beta).collect();
    angles.sort_by(f64::total_cmp);
    angles.dedup();
    let mut power = 0.0;
    for w in angles.windows(2) {
        let (mut vy, mut psi) = (0.0, 0.0);
        for (j, &r) in ls.pattern.iter().zip(&ls.rates) {
            if j.beta <= w[0] {
                let (s, c) = (j.beta.sin(), j.beta.cos());
                let (re, ri) = (1.0 + eta / 2.0, 1.0 - eta / 2.0);
                let (cy, cp) = match j.kind.as_str() {
                    "hinge_extrados" => (re * c, -1.0),
                    "hinge_intrados" => (-ri * c, 1.0),
                    "slide_plus" => (s, 0.0),
                    _ => (-s, 0.0),
                };
                vy += r * cy;
                psi += r * cp;
            }
        }
        power -= (w[1] - w[0]) * vy + psi * rho * (w[1].sin() - w[0].sin());
    }
    if power < -tol {
        return reject(format!(
            "limit state: external power L_e = {power:e} is negative"
        ));
    }
    Ok(())
}
