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

use super::format::{
    ArchSpec, CertJoint, Certificate, Claim, ContactKind, LimitStateCert, Location, PatternJoint,
    Side, WeightModel, FORMAT, VERSION,
};
use super::interval::{det2, det3, det4, Interval as I};
use super::verify_statics::{affine, exists, phi, prove_admissible, Model};
use std::f64::consts::PI;

/// Tolerances of the floating-point consistency checks of the limit state.
pub const LIMIT_STATE_TOL: f64 = 1e-9;

/// What `verify` proved or checked, for which arch and friction.
#[derive(Debug, Clone)]
pub struct Report {
    /// The claim that was proved.
    pub claim: Claim,
    /// μ (`None` = ∞).
    pub mu: Option<f64>,
    /// (η_lo, η_hi) of a least-thickness claim; `None` for no equilibrium.
    pub bracket: Option<(f64, f64)>,
    /// The arch the proof is about.
    pub arch: ArchSpec,
    /// One line per check that passed, each saying whether it was *proved* (interval
    /// arithmetic) or *checked* (floating point, evidence only).
    pub checks: Vec<String>,
    /// What the limit-state search lists (certificates with a `search` section).
    pub limit_states: Option<String>,
    /// Load certificates: the load in words.
    pub load: Option<String>,
    /// (λ_lo, λ_hi) of a largest-multiplier claim; for an unbounded multiplier, the λ from
    /// which states are proved admissible at every larger λ, and `None`.
    pub lambda_bracket: Option<(f64, Option<f64>)>,
}

impl Report {
    /// The arch in words: layout, springings, weight model.
    pub fn arch_text(&self) -> String {
        let a = &self.arch;
        let layout = match &a.joint_angles {
            None => "continuous".to_string(),
            Some(j) => format!("discrete ({} joints)", j.len()),
        };
        format!(
            "{layout} arch, beta_right = {}, beta_left = {}, weight {}",
            a.beta_right,
            a.beta_left,
            a.weight.name()
        )
    }

    /// The proved statement, in one line.
    pub fn statement(&self) -> String {
        let mu = mu_text(self.mu);
        if let Some(load) = &self.load {
            return match (self.claim, self.lambda_bracket) {
                (Claim::LargestMultiplier, Some((lo, Some(hi)))) => format!(
                    "proved: for this arch at mu = {mu} under the {load}, lambda_static lies in [{lo}, {hi}] (relative gap {:.3e}; lambda_static = the largest multiplier with a statically admissible state)",
                    (hi - lo) / hi
                ),
                (Claim::UnboundedMultiplier, Some((lo, None))) => format!(
                    "proved: for this arch at mu = {mu} under the {load}, statically admissible states exist at every lambda >= {lo}: lambda_static is unbounded"
                ),
                _ => format!(
                    "proved: for this arch at mu = {mu} under the {load}, no state is statically admissible at any lambda >= 0"
                ),
            };
        }
        match self.bracket {
            Some((lo, hi)) => format!(
                "proved: for this arch at mu = {mu}, eta* lies in [{lo}, {hi}] (relative gap {:.3e}; eta* = the least thickness with a statically admissible state)",
                (hi - lo) / hi
            ),
            None => format!(
                "proved: for this arch at mu = {mu}, no thickness stands (no statically admissible state at any eta)"
            ),
        }
    }
}

/// Why a certificate does not hold.
#[derive(Debug, Clone, PartialEq)]
pub struct Rejection(pub String);

pub(super) fn reject<T>(msg: impl Into<String>) -> Result<T, Rejection> {
    Err(Rejection(msg.into()))
}

/// A joint of a Farkas certificate: on the arch (a listed joint of a discrete arch), a
/// kind that exists at μ, a finite multiplier, and a `side` exactly at the point load's
/// angle `split` (never without a point load).
pub(super) fn check_farkas_joint(
    model: &Model,
    i: usize,
    j: &CertJoint,
    mu: Option<f64>,
    split: Option<f64>,
) -> Result<(), Rejection> {
    model.check_joint(j.beta, &format!("collapse side: joint {i}"))?;
    if !exists(j.kind, mu) {
        return reject(format!(
            "collapse side: joint {i} is {} at beta = {}, but there is no sliding at infinite friction (mu = null): that constraint does not exist in this problem",
            j.kind.name(),
            j.beta
        ));
    }
    if !(j.y.is_finite()) {
        return reject(format!(
            "collapse side: multiplier of joint {i} is not a finite number"
        ));
    }
    check_side(j.beta, j.side, split, &format!("collapse side: joint {i}"))
}

/// `side` must be given exactly at the point load's angle `split` (the two sections
/// there differ) and nowhere else.
pub(super) fn check_side(
    beta: f64,
    side: Option<Side>,
    split: Option<f64>,
    what: &str,
) -> Result<(), Rejection> {
    match (split == Some(beta), side) {
        (true, None) => reject(format!(
            "{what}: beta = {beta} is the point load's angle: give the side of the loaded section (before or after)"
        )),
        (false, Some(_)) => reject(format!(
            "{what}: a side is given at beta = {beta}, but only the point load's own section has two sides"
        )),
        _ => Ok(()),
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
    let mut aff: Vec<([I; 3], I)> = Vec::with_capacity(joints.len());
    for (i, j) in joints.iter().enumerate() {
        check_farkas_joint(model, i, j, mu, None)?;
        if friction_only && j.kind.is_hinge() {
            return reject(format!(
                "collapse side: joint {i} is {}, but the friction-only certificate may use sliding joints only",
                j.kind.name()
            ));
        }
        // `exists` guarantees a finite μ for sliding rows; hinge rows do not use it
        aff.push(affine(model, j.kind, j.beta, eta, mu.unwrap_or(0.0)));
    }
    let rows: Vec<(Vec<I>, I)> = aff.iter().map(|(g, c)| (g[..d].to_vec(), *c)).collect();
    let stored: Vec<(f64, String)> = joints
        .iter()
        .map(|j| (j.y, format!("beta = {}", j.beta)))
        .collect();
    prove_cofactors(&rows, &stored)
}

/// The Farkas proof for d + 1 affine rows `g · u + c ≤ 0` in d unknowns (d = 2, 3 or 4):
/// the exact multipliers are the signed cofactors of the gradients, enclosed in
/// intervals; they must share a sign, match the `stored` ones (normalised to sum 1; each
/// with a label for the messages), and give Σ yᵢ cᵢ > 0 rigorously, so that
/// Σ yᵢ rowᵢ(u) = Σ yᵢ cᵢ > 0 for every u: no u satisfies all rows. Returns the margin
/// Σ yᵢ cᵢ / Σ yᵢ (lower bound).
pub(super) fn prove_cofactors(
    rows: &[(Vec<I>, I)],
    stored: &[(f64, String)],
) -> Result<f64, Rejection> {
    let d = rows.len() - 1;
    let y: Vec<I> = (0..=d)
        .map(|i| {
            let cols: Vec<usize> = (0..=d).filter(|&k| k != i).collect();
            let sign = if i % 2 == 0 { 1.0 } else { -1.0 };
            let g = |k: usize, r: usize| rows[cols[k]].0[r];
            let det = match d {
                4 => det4([0, 1, 2, 3].map(|k| [0, 1, 2, 3].map(|r| g(k, r)))),
                3 => det3([0, 1, 2].map(|k| [0, 1, 2].map(|r| g(k, r)))),
                _ => det2([[g(0, 0), g(0, 1)], [g(1, 0), g(1, 1)]]),
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
    let stored_total: f64 = stored.iter().map(|s| s.0).sum();
    for ((sy, label), v) in stored.iter().zip(&y) {
        let (a, b) = (v.mid() / total, sy / stored_total);
        if stored_total.is_nan()
            || stored_total <= 0.0
            || (a - b).abs() > 1e-6 * (1.0 + a.abs())
            || *sy < 0.0
        {
            return reject(format!("collapse side: stored multiplier {sy} at {label} does not match the recomputed {a:.9e} (normalised)"));
        }
    }
    let c = y
        .iter()
        .zip(rows)
        .fold(I::point(0.0), |acc, (yi, (_, ci))| acc + *yi * *ci);
    if c.lo.is_nan() || c.lo <= 0.0 {
        return reject(format!(
            "collapse side: sum y_i phi_i(0) = [{:e}, {:e}] is not proved > 0",
            c.lo, c.hi
        ));
    }
    Ok(c.lo / total)
}

/// Every number of the certificate must be finite (JSON cannot carry NaN or ∞, but a
/// certificate built in memory can).
fn check_finite(cert: &Certificate) -> Result<(), Rejection> {
    let mut nums: Vec<(&str, f64)> = vec![
        ("arch.beta_right", cert.arch.beta_right),
        ("arch.beta_left", cert.arch.beta_left),
    ];
    if let Some(js) = &cert.arch.joint_angles {
        nums.extend(js.iter().map(|&b| ("arch.joint_angles", b)));
    }
    if let Some(mu) = cert.mu {
        nums.push(("mu", mu));
    }
    if let Some(s) = &cert.safe {
        nums.push(("safe.eta", s.eta));
        nums.extend(s.x.iter().map(|&v| ("safe.x", v)));
    }
    if let Some(f) = &cert.collapse {
        if let Some(e) = f.eta {
            nums.push(("collapse.eta", e));
        }
        for j in &f.joints {
            nums.extend([("collapse.joints.beta", j.beta), ("collapse.joints.y", j.y)]);
        }
    }
    if let Some(ls) = &cert.limit_state {
        nums.push(("limit_state.eta", ls.eta));
        nums.extend(ls.x.iter().map(|&v| ("limit_state.x", v)));
        nums.extend(
            ls.pattern
                .iter()
                .map(|j| ("limit_state.pattern.beta", j.beta)),
        );
        nums.extend(ls.rates.iter().map(|&v| ("limit_state.rates", v)));
        nums.push((
            "limit_state.complementarity_residual",
            ls.complementarity_residual,
        ));
    }
    if let Some(g) = cert.gap {
        nums.push(("gap", g));
    }
    if let Some(g) = cert.gap_relative {
        nums.push(("gap_relative", g));
    }
    match nums.iter().find(|(_, v)| !v.is_finite()) {
        Some((field, v)) => reject(format!("{field}: {v} is not a finite number")),
        None => Ok(()),
    }
}

/// The arch of the certificate, checked: springings in order, the joints of a discrete
/// arch strictly increasing from β_R to β_L.
pub(super) fn model_of(cert: &Certificate) -> Result<Model, Rejection> {
    let a = &cert.arch;
    if !(a.beta_right < a.beta_left && a.beta_left - a.beta_right <= 2.0 * PI) {
        return reject(format!(
            "arch: need beta_right < beta_left <= beta_right + 2 pi, found beta_right = {}, beta_left = {}",
            a.beta_right, a.beta_left
        ));
    }
    if let Some(js) = &a.joint_angles {
        if js.len() < 2 {
            return reject(
                "arch: joint_angles of a discrete arch need at least the two springings",
            );
        }
        if js.first() != Some(&a.beta_right) || js.last() != Some(&a.beta_left) {
            return reject("arch: joint_angles must start at beta_right and end at beta_left (the springings are joints)");
        }
        if let Some(w) = js
            .windows(2)
            .find(|w| w[0].is_nan() || w[1].is_nan() || w[1] <= w[0])
        {
            return reject(format!(
                "arch: joint_angles must be strictly increasing, found {} then {}",
                w[0], w[1]
            ));
        }
    }
    Ok(Model {
        beta_r: a.beta_right,
        beta_l: a.beta_left,
        centroid: a.weight == WeightModel::Centroid,
        joints: a.joint_angles.clone(),
    })
}

/// The pattern of the limit state: every joint inside the arch (at a listed joint of a
/// discrete arch), `at` matching its angle, its kind existing at μ, and the list strictly
/// increasing in (β, kind) (two contacts may share a joint).
pub(super) fn check_pattern(
    model: &Model,
    pattern: &[PatternJoint],
    mu: Option<f64>,
    split: Option<f64>,
    whose: &str,
) -> Result<(), Rejection> {
    for (i, j) in pattern.iter().enumerate() {
        let what = format!("{whose}: pattern joint {i}");
        model.check_joint(j.beta, &what)?;
        check_side(j.beta, j.side, split, &what)?;
        if !exists(j.kind, mu) {
            return reject(format!(
                "{what} is {}, but there is no sliding at infinite friction (mu = null)",
                j.kind.name()
            ));
        }
        let at_springing = j.beta == model.beta_r || j.beta == model.beta_l;
        if at_springing != (j.at == Location::Springing) {
            return reject(format!(
                "{what}: at = {} does not match beta = {} (the springings are {} and {})",
                if j.at == Location::Springing {
                    "springing"
                } else {
                    "interior"
                },
                j.beta,
                model.beta_r,
                model.beta_l
            ));
        }
    }
    // the side of the loaded section orders `before` first (no side: one section)
    let key = |j: &PatternJoint| (j.side != Some(Side::Before), j.kind);
    if let Some(w) = pattern
        .windows(2)
        .find(|w| !(w[0].beta < w[1].beta || (w[0].beta == w[1].beta && key(&w[0]) < key(&w[1]))))
    {
        return reject(format!(
            "{whose}: pattern must be strictly increasing in (beta, {}kind), found {} at {} then {} at {}",
            if split.is_some() { "side, " } else { "" },
            w[0].kind.name(),
            w[0].beta,
            w[1].kind.name(),
            w[1].beta
        ));
    }
    Ok(())
}

/// "inf" for `None`, else the number.
fn mu_text(mu: Option<f64>) -> String {
    mu.map_or("inf".into(), |m| m.to_string())
}

/// Re-checks `cert`. Ok with what was proved and checked, or the first reason it fails.
pub fn verify(cert: &Certificate) -> Result<Report, Rejection> {
    let mut checks = Vec::new();
    let mut limit_states = None;
    if cert.format != FORMAT || cert.version != VERSION {
        return reject(format!(
            "not an {FORMAT} version {VERSION} certificate (found {} version {})",
            cert.format, cert.version
        ));
    }
    check_finite(cert)?;
    let model = model_of(cert)?;
    if let Some(mu) = cert.mu {
        if mu.is_nan() || mu <= 0.0 {
            return reject(format!(
                "mu = {mu}: must be positive (null for infinite friction)"
            ));
        }
    }
    let load_claim = matches!(
        cert.claim,
        Claim::LargestMultiplier | Claim::UnboundedMultiplier
    );
    if load_claim || cert.load.is_some() || cert.multiplier.is_some() || cert.load_search.is_some()
    {
        return super::verify_load::verify_load(cert, &model);
    }
    let bracket = match cert.claim {
        Claim::LargestMultiplier | Claim::UnboundedMultiplier => {
            unreachable!("load claims are verified by verify_load")
        }
        Claim::NoEquilibrium => {
            let Some(f) = &cert.collapse else {
                return reject("no_equilibrium claim without a Farkas certificate");
            };
            if cert.mu.is_none() {
                return reject("no_equilibrium claim at infinite friction (mu = null): the friction-only problem has no sliding rows there");
            }
            if f.eta.is_some() {
                return reject(
                    "collapse side: a no_equilibrium (friction-only) certificate has eta = null",
                );
            }
            if cert.safe.is_some() || cert.limit_state.is_some() || cert.search.is_some() {
                return reject("a no_equilibrium claim cannot carry a safe state or a limit state");
            }
            let margin = prove_farkas(&model, &f.joints, 1.0, cert.mu, true)?;
            checks.push(format!(
                "proved (interval arithmetic): no (h, v) satisfies |T| <= mu N at the {} listed joints (Farkas, margin {margin:.3e}), so no thickness can stand at mu = {}",
                f.joints.len(),
                mu_text(cert.mu)
            ));
            None
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
            if let Some(ls) = &cert.limit_state {
                check_pattern(&model, &ls.pattern, cert.mu, None, "limit state")?;
            }
            let pieces = prove_admissible(&model, safe.x, safe.eta, cert.mu, false)?;
            checks.push(format!(
                "proved (interval arithmetic): the state x = [{}, {}, {}] is admissible at eta_hi = {} over the whole arch ({pieces} enclosures)",
                safe.x[0], safe.x[1], safe.x[2], safe.eta
            ));
            let margin = prove_farkas(&model, &col.joints, eta_lo, cert.mu, false)?;
            checks.push(format!(
                "proved (interval arithmetic): no state is admissible at eta_lo = {eta_lo} (Farkas on {} joints, margin {margin:.3e})",
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
            if let Some(g) = cert.gap_relative {
                let r = gap / safe.eta;
                if (g - r).abs() > 1e-15 + 1e-9 * r {
                    return reject(format!(
                        "stated gap_relative {g} differs from (eta_hi - eta_lo)/eta_hi = {r}"
                    ));
                }
            }
            if let Some(ls) = &cert.limit_state {
                // the least limit state lies above η_s where η_s carries no mechanism
                let above = cert.search.as_ref().is_some_and(|s| !s.mechanism_at_eta);
                check_limit_state(
                    &model,
                    cert.mu,
                    ls,
                    eta_lo,
                    if above { 2.0 } else { safe.eta },
                )?;
                checks.push(format!(
                    "checked (floating point, tolerance {LIMIT_STATE_TOL:e}; evidence, not proof): the limit state at eta = {} is consistent (pattern active, B lambda = 0, lambda >= 0, sum 1, L_e >= 0)",
                    ls.eta
                ));
            }
            if let Some(search) = &cert.search {
                let (lines, verdict) =
                    super::verify_search::verify_search(&model, cert, search, eta_lo, safe)?;
                checks.extend(lines);
                limit_states = Some(verdict);
            }
            Some((eta_lo, safe.eta))
        }
    };
    Ok(Report {
        claim: cert.claim,
        mu: cert.mu,
        bracket,
        arch: cert.arch.clone(),
        checks,
        limit_states,
        load: None,
        lambda_bracket: None,
    })
}

/// Proves only the safe side of a least-thickness certificate (used by `certify` while
/// it searches for the lower side).
pub fn prove_safe_only(cert: &Certificate) -> Result<usize, Rejection> {
    check_finite(cert)?;
    let model = model_of(cert)?;
    let Some(safe) = &cert.safe else {
        return reject("no safe side");
    };
    prove_admissible(&model, safe.x, safe.eta, cert.mu, false)
}

pub(super) fn check_limit_state(
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
    if ls.rates.len() != ls.pattern.len() || ls.rates.iter().any(|&r| r < 0.0) {
        return reject("limit state: rates must be one non-negative number per pattern joint");
    }
    if (ls.rates.iter().sum::<f64>() - 1.0).abs() > tol {
        return reject("limit state: rates do not sum to 1");
    }
    let eta = ls.eta;
    let scale = 1.0 + ls.x.iter().map(|v| v.abs()).sum::<f64>();
    let (re, ri) = (1.0 + eta / 2.0, 1.0 - eta / 2.0);
    let mut b = [0.0; 3];
    for (j, &r) in ls.pattern.iter().zip(&ls.rates) {
        let (s, c) = (j.beta.sin(), j.beta.cos());
        let col = match j.kind {
            ContactKind::HingeExtrados => [-re * s, re * c, -1.0],
            ContactKind::HingeIntrados => [ri * s, -ri * c, 1.0],
            ContactKind::SlidePlus => [c, s, 0.0],
            ContactKind::SlideMinus => [-c, -s, 0.0],
        };
        for i in 0..3 {
            b[i] += r * col[i];
        }
        let v = phi(j.kind, 0, &model.ntm(I::point(j.beta), ls.x, eta), eta, mu);
        if v.mid().is_nan() || v.mid().abs() > tol * scale {
            return reject(format!(
                "limit state: {} at beta = {} is not active (phi = {:e})",
                j.kind.name(),
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
                let (cy, cp) = match j.kind {
                    ContactKind::HingeExtrados => (re * c, -1.0),
                    ContactKind::HingeIntrados => (-ri * c, 1.0),
                    ContactKind::SlidePlus => (s, 0.0),
                    ContactKind::SlideMinus => (-s, 0.0),
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
