//! Re-checking the evidence of the limit-state search (the `search` section of a
//! certificate, issue 10): which limit states exist with η in [η_s, 2).
//!
//! * **No mechanism** at a listed state (the least admissible state, or a point of the
//!   sweep): *proved* in interval arithmetic by the Farkas alternative of the kinematic LP
//!   on the listed contacts — `c_j · y + z + u p_j ≤ 0` for every contact kept, z > 0,
//!   u ≥ 0, so no rates λ ≥ 0, Σ λ = 1, B λ = 0, L_e = p · λ ≥ 0 exist — for every choice
//!   of one sliding sense at a joint where both are listed. That the listed contacts are
//!   the state's whole active set is *checked* in floating point (for a discrete arch,
//!   every other contact at every joint at least [`INACTIVE_REL`] below zero).
//! * **Limit states above η_s**: admissibility at the joints (floating point) and the
//!   consistency of the mechanism, as for the certificate's limit state.
//! * **μ = ∞** (`hinges_only`): the safe state is *proved* to lie strictly inside P(η_hi)
//!   (every φ < 0 over the whole arch); a hinge-only mechanism λ has λᵀφ(x) = L_e(λ) for
//!   every x (formulation §6), so a limit state needs P(η) without interior, and P(η) grows
//!   with η: no limit state has η ≥ η_hi.
//!
//! What is *not* re-proved: that the sweep met every event (its completeness argument,
//! docs/limit-states.md), or that two discretisations agreed (`refined`).

use super::format::{
    Certificate, ContactKind, KinematicFarkas, LimitStateCert, NoMechanism, SafeSide,
    SearchEvidence, SearchMethod, Side,
};
use super::interval::Interval as I;
use super::live::Live;
use super::verify::{check_limit_state, check_pattern, reject, Rejection, LIMIT_STATE_TOL};
use super::verify_statics::{kinds, phi, prove_admissible, Model, Ntm};

/// A contact not listed in a state's pattern must lie at least this far below zero,
/// relative to (1 + ‖x‖₁), for the pattern to count as the state's whole active set.
pub const INACTIVE_REL: f64 = 1e-12;

/// Samples of a continuous arch for the floating-point admissibility check of a limit
/// state above η_s.
const SAMPLES: usize = 2000;

/// Re-checks `search` against the bracket [η_lo, safe.eta]; returns the lines of the
/// report (each saying proved or checked) and the one-line verdict on the limit states.
pub(super) fn verify_search(
    model: &Model,
    cert: &Certificate,
    search: &SearchEvidence,
    eta_lo: f64,
    safe: &SafeSide,
) -> Result<(Vec<String>, String), Rejection> {
    let mu = cert.mu;
    let mut checks = Vec::new();
    let count = usize::from(search.mechanism_at_eta) + search.limit_states_above.len();
    if search.unique != (count == 1) {
        return reject(format!(
            "search: unique = {} but {count} limit states are listed (mechanism at eta_s: {}, {} above)",
            search.unique,
            search.mechanism_at_eta,
            search.limit_states_above.len()
        ));
    }
    // the certificate's limit state is the least one
    let least = if search.mechanism_at_eta {
        cert.limit_state.as_ref()
    } else {
        search.limit_states_above.first()
    };
    match (least, &cert.limit_state) {
        (Some(a), Some(b)) if a.eta == b.eta && a.x == b.x => {}
        (None, None) => {}
        _ => return reject(
            "search: the certificate's limit_state is not the least limit state the search lists",
        ),
    }
    if search.mechanism_at_eta && cert.limit_state.is_none() {
        return reject("search: mechanism_at_eta is true but no limit_state is given");
    }
    // the least admissible state without a mechanism
    if let Some(ls) = &search.least_state {
        if search.mechanism_at_eta {
            return reject(
                "search: a least_state without mechanism is listed, but mechanism_at_eta is true",
            );
        }
        if !(ls.eta >= eta_lo && ls.eta <= safe.eta) {
            return reject(format!(
                "search: least_state eta = {} lies outside [eta_lo, eta_hi]",
                ls.eta
            ));
        }
        let proved = thickness_no_mechanism(model, mu, ls, "search: least_state")?;
        checks.push(if proved {
            format!(
                "proved (interval arithmetic): the {} contacts active at the least admissible state (eta = {}) carry no mechanism without dilatancy (Farkas); checked (floating point): they are its whole active set{}",
                ls.pattern.len(),
                ls.eta,
                if model.joints.is_some() { "" } else { " (at the listed contacts; a continuous arch's other angles are not enumerated)" }
            )
        } else {
            format!(
                "not proved: the least admissible state (eta = {}) carries no mechanism (no Farkas certificate covers every sliding sense)",
                ls.eta
            )
        });
    } else if !search.mechanism_at_eta {
        checks.push("no least admissible state is listed: eta_s is not attained by a bounded state (an infimum), so no limit state exists there".into());
    }
    // limit states above η_s
    let mut last = safe.eta;
    for (i, ls) in search.limit_states_above.iter().enumerate() {
        let whose = format!("search: limit state above eta_s {i}");
        finite(ls, &whose)?;
        check_pattern(model, &ls.pattern, mu, None, &whose)?;
        if ls.eta < last {
            return reject(format!(
                "{whose}: eta = {} is not above eta_hi and the previous listed state (not ascending)",
                ls.eta
            ));
        }
        last = ls.eta;
        check_limit_state(model, mu, ls, eta_lo, 2.0)?;
        admissible_at_samples(model, mu, ls, &whose)?;
    }
    if !search.limit_states_above.is_empty() {
        checks.push(format!(
            "checked (floating point, tolerance {LIMIT_STATE_TOL:e}; evidence, not proof): {} limit state(s) above eta_s, admissible, each with a mechanism without dilatancy (eta = {})",
            search.limit_states_above.len(),
            search
                .limit_states_above
                .iter()
                .map(|s| s.eta.to_string())
                .collect::<Vec<_>>()
                .join(", ")
        ));
    }
    // the method's own evidence
    match search.method {
        SearchMethod::Sweep => {
            if model.joints.is_none() {
                return reject("search: method sweep needs a discrete arch");
            }
            let mut proved = 0;
            for (i, p) in search.no_mechanism.iter().enumerate() {
                if thickness_no_mechanism(model, mu, p, &format!("search: no_mechanism {i}"))? {
                    proved += 1;
                }
            }
            let n = search.no_mechanism.len();
            checks.push(format!(
                "proved (interval arithmetic) at {proved} of the {n} points the sweep checked without finding a mechanism ({} events): their active contacts carry no mechanism (Farkas); not re-proved: that the sweep met every event (docs/limit-states.md)",
                search.events
            ));
            if proved < n {
                checks.push(format!(
                    "not proved: {} points of the sweep have no Farkas certificate covering every sliding sense",
                    n - proved
                ));
            }
        }
        SearchMethod::HingesOnly => {
            if mu.is_some() {
                return reject("search: method hinges_only needs infinite friction (mu = null)");
            }
            if !search.limit_states_above.is_empty() || !search.no_mechanism.is_empty() {
                return reject("search: method hinges_only lists nothing above eta_s");
            }
            prove_admissible(model, safe.x, safe.eta, mu, true).map_err(|e| {
                Rejection(format!("search (hinges_only): the safe state is not proved strictly inside P(eta_hi): {}", e.0))
            })?;
            checks.push(format!(
                "proved (interval arithmetic): the safe state lies strictly inside P(eta_hi) (every phi < 0 over the whole arch), so at mu = inf no limit state has eta >= {} (a hinge-only mechanism needs P(eta) without interior, formulation §6)",
                safe.eta
            ));
        }
        SearchMethod::Refined => {
            if model.joints.is_some() {
                return reject("search: method refined is for a continuous arch");
            }
            checks.push("not re-checked: that the refined limit states of two discretisations agreed (method refined); the listed states are checked above".into());
        }
    }
    let verdict = match (count, search.mechanism_at_eta) {
        (0, _) => {
            "no limit state with eta in [eta_s, 2): the arch is safe from eta_s on".to_string()
        }
        (1, true) => "one limit state with eta in [eta_s, 2), at eta_s (unique)".to_string(),
        (1, false) => "one limit state with eta in [eta_s, 2), above eta_s (unique; none at eta_s)"
            .to_string(),
        (n, _) => format!("{n} limit states with eta in [eta_s, 2) (not unique)"),
    };
    Ok((
        checks,
        format!(
            "the search ({}) lists {verdict}",
            method_name(search.method)
        ),
    ))
}

/// [`no_mechanism`] for a state of the thickness problem.
fn thickness_no_mechanism(
    model: &Model,
    mu: Option<f64>,
    p: &NoMechanism,
    whose: &str,
) -> Result<bool, Rejection> {
    let state = StateAt {
        x: p.x,
        eta: p.eta,
        load: None,
    };
    no_mechanism(model, mu, state, &p.pattern, &p.farkas, whose)
}

fn method_name(m: SearchMethod) -> &'static str {
    match m {
        SearchMethod::Sweep => "sweep",
        SearchMethod::HingesOnly => "hinges only",
        SearchMethod::Refined => "refined",
    }
}

fn finite(ls: &LimitStateCert, whose: &str) -> Result<(), Rejection> {
    let ok = ls.eta.is_finite()
        && ls.x.iter().all(|v| v.is_finite())
        && ls.rates.iter().all(|v| v.is_finite())
        && ls.pattern.iter().all(|j| j.beta.is_finite());
    if ok {
        Ok(())
    } else {
        reject(format!("{whose}: every number must be finite"))
    }
}

/// φ ≤ tol·(1 + ‖x‖₁) at every joint (discrete) or at [`SAMPLES`] angles (continuous):
/// a floating-point check.
fn admissible_at_samples(
    model: &Model,
    mu: Option<f64>,
    ls: &LimitStateCert,
    whose: &str,
) -> Result<(), Rejection> {
    let scale = 1.0 + ls.x.iter().map(|v| v.abs()).sum::<f64>();
    let angles: Vec<f64> = match &model.joints {
        Some(j) => j.clone(),
        None => (0..=SAMPLES)
            .map(|i| model.beta_r + (model.beta_l - model.beta_r) * i as f64 / SAMPLES as f64)
            .collect(),
    };
    for &b in &angles {
        let a = model.ntm(I::point(b), ls.x, ls.eta);
        for &k in kinds(mu) {
            let v = phi(k, 0, &a, ls.eta, mu).mid();
            if v.is_nan() || v > LIMIT_STATE_TOL * scale {
                return reject(format!(
                    "{whose}: not admissible, {} = {v:e} > 0 at beta = {b}",
                    k.name()
                ));
            }
        }
    }
    Ok(())
}

/// A state of either problem, for the checks of a listed state: reactions x at thickness
/// η and, under a live load, its multiplier λ.
#[derive(Clone, Copy)]
pub(super) struct StateAt<'a> {
    /// Reactions.
    pub(super) x: [f64; 3],
    /// Thickness.
    pub(super) eta: f64,
    /// The live load and λ (load certificates).
    pub(super) load: Option<(&'a Live, f64)>,
}

impl StateAt<'_> {
    /// N, T, M (with β-derivatives) at the joint β on `side`: the dead actions of x,
    /// plus λ times the live ones where the section carries the load.
    pub(super) fn ntm(&self, model: &Model, beta: f64, side: Option<Side>) -> Ntm {
        let b = I::point(beta);
        let dead = model.ntm(b, self.x, self.eta);
        match self.load {
            Some((live, lambda)) => match live.ntm(model, b, live.carries(beta, side)) {
                Some(l) => dead.plus(lambda, &l),
                None => dead,
            },
            None => dead,
        }
    }

    /// The point load's angle (two sections there).
    fn split(&self) -> Option<f64> {
        self.load.and_then(|(live, _)| live.split())
    }
}

/// Checks a state listed without mechanism (its `pattern` and `farkas` at `state`);
/// `Ok(true)` when the Farkas certificates prove it for every one-sense choice,
/// `Ok(false)` when they do not cover them all, `Err` when something stated is false.
pub(super) fn no_mechanism(
    model: &Model,
    mu: Option<f64>,
    state: StateAt,
    pattern: &[super::format::PatternJoint],
    farkas: &[KinematicFarkas],
    whose: &str,
) -> Result<bool, Rejection> {
    if !(state.eta.is_finite()
        && state.eta > 0.0
        && state.eta < 2.0
        && state.x.iter().all(|v| v.is_finite()))
    {
        return reject(format!("{whose}: eta must lie in (0, 2) and x be finite"));
    }
    if let Some((_, lambda)) = state.load {
        if !(lambda.is_finite() && lambda >= 0.0) {
            return reject(format!(
                "{whose}: lambda = {lambda} must be finite and >= 0"
            ));
        }
    }
    if pattern.len() > 64 {
        return reject(format!("{whose}: more than 64 contacts"));
    }
    let keyed: Vec<(f64, ContactKind, Option<Side>)> =
        pattern.iter().map(|j| (j.beta, j.kind, j.side)).collect();
    // the pattern: valid joints, active (floating point), and the whole active set
    check_pattern(model, pattern, mu, state.split(), whose)?;
    let scale = 1.0 + state.x.iter().map(|v| v.abs()).sum::<f64>();
    for &(b, k, side) in &keyed {
        let v = phi(k, 0, &state.ntm(model, b, side), state.eta, mu).mid();
        if v.is_nan() || v.abs() > LIMIT_STATE_TOL * scale {
            return reject(format!(
                "{whose}: {} at beta = {b} is not active (phi = {v:e})",
                k.name()
            ));
        }
    }
    if let Some(joints) = &model.joints {
        for &b in joints {
            for side in sections(b, state.split()) {
                let a = state.ntm(model, b, side);
                for &k in kinds(mu) {
                    if keyed.contains(&(b, k, side)) {
                        continue;
                    }
                    let v = phi(k, 0, &a, state.eta, mu).mid();
                    if v.is_nan() || v > -INACTIVE_REL * scale {
                        return reject(format!(
                            "{whose}: {} at beta = {b}{} is active or violated (phi = {v:e}) but not in the pattern",
                            k.name(),
                            side_text(side)
                        ));
                    }
                }
            }
        }
    }
    // every one-sense choice must be covered by a proved Farkas certificate (a section
    // slides one way only)
    let both: Vec<(usize, usize)> = (0..keyed.len())
        .filter(|&i| keyed[i].1 == ContactKind::SlidePlus)
        .filter_map(|i| {
            (0..keyed.len())
                .find(|&k| {
                    keyed[k].1 == ContactKind::SlideMinus
                        && keyed[k].0 == keyed[i].0
                        && keyed[k].2 == keyed[i].2
                })
                .map(|k| (i, k))
        })
        .collect();
    if both.len() > 8 {
        return Ok(false);
    }
    let mut proved: Vec<&KinematicFarkas> = Vec::new();
    for (i, f) in farkas.iter().enumerate() {
        if f.drop.iter().any(|&d| d >= keyed.len()) {
            return reject(format!(
                "{whose}: farkas {i} drops a contact that is not in the pattern"
            ));
        }
        if state.load.is_none() && f.v != 0.0 {
            return reject(format!(
                "{whose}: farkas {i} has a live-power multiplier v, but there is no live load"
            ));
        }
        if prove_farkas(model, state, &keyed, f) {
            proved.push(f);
        } else {
            return reject(format!(
                "{whose}: farkas {i} does not prove that the kinematic LP is infeasible"
            ));
        }
    }
    let covered = (0..1usize << both.len()).all(|choice| {
        let dropped: Vec<usize> = both
            .iter()
            .enumerate()
            .map(|(b, &(pl, mi))| if choice >> b & 1 == 0 { mi } else { pl })
            .collect();
        proved
            .iter()
            .any(|f| f.drop.iter().all(|d| dropped.contains(d)))
    });
    Ok(covered)
}

/// The sections at a joint: two (`before`, `after`) at the point load's angle, else one.
pub(super) fn sections(beta: f64, split: Option<f64>) -> Vec<Option<Side>> {
    if split == Some(beta) {
        vec![Some(Side::Before), Some(Side::After)]
    } else {
        vec![None]
    }
}

/// " (before)" / " (after)" / "".
pub(super) fn side_text(side: Option<Side>) -> &'static str {
    match side {
        Some(Side::Before) => " (before the loaded point)",
        Some(Side::After) => " (after the loaded point)",
        None => "",
    }
}

/// The compatibility column of a contact at η (formulation §4), in intervals.
pub(super) fn column(kind: ContactKind, beta: f64, eta: f64) -> [I; 3] {
    let b = I::point(beta);
    let (s, c) = (b.sin(), b.cos());
    let half = I::point(0.5) * I::point(eta);
    let (re, ri) = (I::point(1.0) + half, I::point(1.0) - half);
    let (one, zero) = (I::point(1.0), I::point(0.0));
    match kind {
        ContactKind::HingeExtrados => [-(re * s), re * c, -one],
        ContactKind::HingeIntrados => [ri * s, -(ri * c), one],
        ContactKind::SlidePlus => [c, s, zero],
        ContactKind::SlideMinus => [-c, -s, zero],
    }
}

/// `c_j · y + z + u p_j` proved ≤ 0 in intervals for every kept contact, with z > 0
/// and u ≥ 0. The external power p_j of a contact: minus the work of the weight of the
/// blocks beyond it (between consecutive distinct kept joints) in its unit motion,
/// p_j = −Σ_m [W_m c_j,y + ρ (sin β_{m+1} − sin β_m) c_j,ψ], W_m = β_{m+1} − β_m.
/// Under a live load at λ the power is the total one, P_j = p_j + λ q_j, and the live
/// power q_j ([`Live::power`]) enters again with its own multiplier v ≥ 0:
/// `c_j · y + z + u P_j + v q_j ≤ 0`.
pub(super) fn prove_farkas(
    model: &Model,
    state: StateAt,
    pattern: &[(f64, ContactKind, Option<Side>)],
    f: &KinematicFarkas,
) -> bool {
    if !(f.z > 0.0
        && f.u >= 0.0
        && f.v >= 0.0
        && f.z.is_finite()
        && f.u.is_finite()
        && f.v.is_finite())
        || f.y.iter().any(|v| !v.is_finite())
    {
        return false;
    }
    let kept: Vec<(f64, ContactKind, Option<Side>)> = (0..pattern.len())
        .filter(|i| !f.drop.contains(i))
        .map(|i| pattern[i])
        .collect();
    let columns: Vec<[I; 3]> = kept
        .iter()
        .map(|&(beta, kind, _)| column(kind, beta, state.eta))
        .collect();
    let work = weight_work(model, state.eta, &kept, &columns);
    let live: Option<(Vec<I>, I)> = state.load.map(|(l, lambda)| {
        (
            l.power(model, &kept, &columns),
            I::point(f.u) * I::point(lambda) + I::point(f.v),
        )
    });
    let y = f.y.map(I::point);
    (0..kept.len()).all(|i| {
        let col = &columns[i];
        let mut value =
            col[0] * y[0] + col[1] * y[1] + col[2] * y[2] + I::point(f.z) - I::point(f.u) * work[i];
        if let Some((q, k)) = &live {
            value = value + *k * q[i];
        }
        value.hi <= 0.0
    })
}

/// The work of the weight in the unit motion of each contact of `kept` (with its
/// compatibility `columns`): Σ over the blocks after it (between consecutive distinct
/// kept angles) of W_m c_y + ρ (sin β_{m+1} − sin β_m) c_ψ, W_m = β_{m+1} − β_m; the
/// external power of the weight is its negative, p_j.
pub(super) fn weight_work(
    model: &Model,
    eta: f64,
    kept: &[(f64, ContactKind, Option<Side>)],
    columns: &[[I; 3]],
) -> Vec<I> {
    let mut angles: Vec<f64> = kept.iter().map(|&(b, _, _)| b).collect();
    angles.sort_by(f64::total_cmp);
    angles.dedup();
    let rho = model.rho(eta);
    let blocks: Vec<(f64, I, I)> = angles
        .windows(2)
        .map(|w| {
            let (a, b) = (I::point(w[0]), I::point(w[1]));
            (w[0], b - a, rho * (b.sin() - a.sin()))
        })
        .collect();
    kept.iter()
        .zip(columns)
        .map(|(&(beta, _, _), col)| {
            blocks
                .iter()
                .filter(|(start, _, _)| *start >= beta)
                .fold(I::point(0.0), |acc, &(_, w, wgx)| {
                    acc + w * col[1] + wgx * col[2]
                })
        })
        .collect()
}
