//! Re-checking the evidence of a limit-state search, for both families: the `search`
//! section of a thickness certificate (which limit states exist with η in [η_s, 2)) and the
//! `load_search` section of a load certificate (the limit states under the load). One
//! walker re-checks the listed states and each method's own evidence.
//!
//! * **No mechanism** at a listed state (the least admissible state, the state at
//!   λ_static, or a point of the sweep): *proved* in interval arithmetic by the Farkas
//!   alternative of the kinematic LP on the listed contacts — `c_j · y + z + u p_j ≤ 0` for
//!   every contact kept, z > 0, u ≥ 0, so no rates λ ≥ 0, Σ λ = 1, B λ = 0, L_e = p · λ ≥ 0
//!   exist; under a load with the total power P_j = p_j + λ q_j and the live power q_j
//!   again, `c_j · y + z + u P_j + v q_j ≤ 0`, v ≥ 0 — for every choice of one sliding sense
//!   per section. That the listed contacts are the state's whole active set is *checked* in
//!   floating point (for a discrete arch, every other contact at every joint at least
//!   [`INACTIVE_REL`](super::mechanism::INACTIVE_REL) below zero).
//! * **Limit states**: admissibility (every joint, or 2000 samples per piece of a
//!   continuous arch) and the consistency of the mechanism (under a load: one sliding sense
//!   per section, live power > 0) — *checked* in floating point.
//! * **μ = ∞**, thickness (`hinges_only`): the safe state is *proved* to lie strictly
//!   inside P(η_hi) (every φ < 0 over the whole arch); a hinge-only mechanism λ has
//!   λᵀφ(x) = L_e(λ) for every x (formulation §6), so a limit state needs P(η) without
//!   interior, and P(η) grows with η: no limit state has η ≥ η_hi.
//! * **μ = ∞**, load (`associative`): every mechanism is made of hinges and dissipates
//!   nothing, so for compatible rates Σ φ λ̇ = L_dead + λ L_live (virtual work,
//!   docs/loads.md); a limit state at λ* has L_dead + λ* L_live = 0 with L_live > 0, and a
//!   state admissible at λ' > λ* would give (λ' − λ*) L_live ≤ 0. With the state *proved*
//!   admissible at λ_lo, no limit state lies below λ_lo (none at all when λ is unbounded).
//!
//! * **The ridge** (`ridge`, thickness, discrete arch, centreline weight): that the listed
//!   limit states are every one above η_hi, *proved* from Q's edges, the ridge's pieces and
//!   their junctions ([`super::ridge`]).
//!
//! What is *not* re-proved: that the sweep met every event (its completeness argument,
//! docs/limit-states.md, docs/loads.md), that two discretisations agreed (`refined`), and
//! λ_min. Method `found` claims no complete list: its `unique = false` rests on the listed
//! states (at least two, distinct), each checked.

use super::enclosure::prove_state;
use super::joints::check_pattern;
use super::limit_state::{check_admissible, check_limit_state, check_load_limit_state};
use super::live::{Live, StateAt};
use super::mechanism::no_mechanism;
use super::report::{reject, Rejection};
use super::ridge::prove_ridge;
use super::statics::{Model, LIMIT_STATE_TOL};
use crate::certificate::format::{
    Certificate, KinematicFarkas, LimitStateCert, LoadLimitStateCert, LoadSearchEvidence,
    LoadSearchMethod, NoMechanism, PatternJoint, SafeSide, SearchEvidence, SearchMethod,
};

/// How a search established its list, for the walker: the sweep, the μ = ∞ argument
/// (`hinges_only` or `associative`), or the refinement.
#[derive(Clone, Copy)]
enum Method {
    /// The sweep, or a load's face search (`faces`): points checked without a mechanism.
    Sweep(&'static str),
    Infinite(&'static str),
    Refined,
    Ridge,
    Found,
}

impl Method {
    fn name(self) -> &'static str {
        match self {
            Method::Sweep(name) => name,
            Method::Infinite(name) => name,
            Method::Refined => "refined",
            Method::Ridge => "ridge",
            Method::Found => "found",
        }
    }
}

/// A state listed without a mechanism: the state, its pattern and the Farkas proof.
type Point<'a> = (StateAt<'a>, &'a [PatternJoint], &'a [KinematicFarkas]);

/// The search section being walked: its name in messages, and the live load (load
/// certificates), which sets the words of the proofs.
struct Walk<'a> {
    section: &'static str,
    live: Option<&'a Live>,
}

impl Walk<'_> {
    /// The kind of mechanism ruled out, in words.
    fn power(&self) -> &'static str {
        match self.live {
            Some(_) => " with non-negative total and live power",
            None => "",
        }
    }

    /// The line of a listed state without a mechanism (`what`: which state, in words),
    /// proved or not.
    fn listed_state(
        &self,
        model: &Model,
        mu: Option<f64>,
        (state, pattern, farkas): Point,
        what: String,
        whose: &str,
    ) -> Result<String, Rejection> {
        let proved = no_mechanism(model, mu, state, pattern, farkas, whose)?;
        Ok(if proved {
            format!(
                "proved (interval arithmetic): the {} contacts active at {what} carry no mechanism {} (Farkas); checked (floating point): they are its whole active set{}",
                pattern.len(),
                if self.live.is_some() { self.power().trim_start() } else { "without dilatancy" },
                if model.joints.is_some() { "" } else { " (at the listed contacts; a continuous arch's other angles are not enumerated)" }
            )
        } else {
            format!(
                "not proved: {what} carries no mechanism (no Farkas certificate covers every sliding sense)"
            )
        })
    }

    /// The line of the limit states listed (`values`: their parameters), each checked.
    fn states_line(&self, n: usize, values: Vec<f64>) -> String {
        let (above, live, param) = match self.live {
            Some(_) => ("", " of positive live power", "lambda"),
            None => (" above eta_s", "", "eta"),
        };
        format!(
            "checked (floating point, tolerance {LIMIT_STATE_TOL:e}; evidence, not proof): {n} limit state(s){above}, admissible, each with a mechanism without dilatancy{live} ({param} = {})",
            values.iter().map(|v| v.to_string()).collect::<Vec<_>>().join(", ")
        )
    }

    /// The method's own evidence: the sweep's `points` without a mechanism, the μ = ∞
    /// argument (`infinite`, the family's own), or the refinement (not re-checked);
    /// pushes the report's lines.
    #[allow(clippy::too_many_arguments)]
    fn method_evidence(
        &self,
        model: &Model,
        mu: Option<f64>,
        (method, events): (Method, usize),
        points: &[Point],
        checks: &mut Vec<String>,
        infinite: impl FnOnce(&mut Vec<String>) -> Result<(), Rejection>,
    ) -> Result<(), Rejection> {
        let section = self.section;
        match method {
            Method::Sweep(name) => {
                if model.joints.is_none() {
                    return reject(format!("{section}: method {name} needs a discrete arch"));
                }
                if self.live.is_some() && mu.is_none() {
                    return reject(
                        "load_search: methods sweep and faces are for finite friction (mu = inf is associative)",
                    );
                }
                let mut proved = 0;
                for (i, &(state, pattern, farkas)) in points.iter().enumerate() {
                    let whose = format!("{section}: no_mechanism {i}");
                    if no_mechanism(model, mu, state, pattern, farkas, &whose)? {
                        proved += 1;
                    }
                }
                let n = points.len();
                let (search, covered) = match (name, self.live) {
                    ("faces", _) => ("face search", "visited every vertex of the admissible (x, lambda) on which a sliding row is active (docs/loads.md), so that no limit state lies elsewhere"),
                    (_, Some(_)) => ("sweep", "met every event of P(lambda) (docs/loads.md), so that no limit state lies between them"),
                    (_, None) => ("sweep", "met every event (docs/limit-states.md)"),
                };
                checks.push(format!(
                    "proved (interval arithmetic) at {proved} of the {n} points the {search} checked without finding a mechanism ({events} events): their active contacts carry no mechanism{} (Farkas); not re-proved: that the {search} {covered}",
                    self.power(),
                ));
                if proved < n {
                    checks.push(format!(
                        "not proved: {} points of the {search} have no Farkas certificate covering every sliding sense",
                        n - proved
                    ));
                }
            }
            Method::Infinite(_) => infinite(checks)?,
            Method::Ridge => {} // re-proved by the caller (`ridge.rs`)
            Method::Refined => {
                if model.joints.is_some() {
                    return reject(format!(
                        "{section}: method refined is for a continuous arch"
                    ));
                }
                if self.live.is_some() && !points.is_empty() {
                    return reject("load_search: method refined lists no sweep points");
                }
                checks.push("not re-checked: that the refined limit states of two discretisations agreed (method refined); the listed states are checked above".into());
            }
            Method::Found if self.live.is_some() => {
                if !points.is_empty() {
                    return reject("load_search: method found lists no sweep points");
                }
                checks.push("not claimed: that the listed limit states are every one (method found: the search did not settle); the collapse multiplier is at most the least listed lambda, each listed state checked above".into());
            }
            Method::Found => {
                if model.joints.is_some() || !points.is_empty() {
                    return reject(format!(
                        "{section}: method found is for a continuous arch under its own weight, with no sweep points"
                    ));
                }
                checks.push("not claimed: that the listed limit states are every one (method found: the discretisations did not settle); unique = false rests on the listed states, checked above".into());
            }
        }
        Ok(())
    }
}

/// Re-checks the `search` section of a thickness certificate against the bracket
/// [η_lo, safe.eta]; returns the lines of the report (each saying proved or checked) and the
/// one-line verdict on the limit states.
pub(super) fn verify_search(
    model: &Model,
    cert: &Certificate,
    search: &SearchEvidence,
    eta_lo: f64,
    safe: &SafeSide,
) -> Result<(Vec<String>, String), Rejection> {
    let mu = cert.mu;
    let walk = Walk {
        section: "search",
        live: None,
    };
    let mut checks = Vec::new();
    let count = check_listing(cert, search)?;
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
        let what = format!("the least admissible state (eta = {})", ls.eta);
        checks.push(walk.listed_state(model, mu, point(ls), what, "search: least_state")?);
    } else if !search.mechanism_at_eta {
        checks.push("no least admissible state is listed: eta_s is not attained by a bounded state (an infimum), so no limit state exists there".into());
    }
    limit_states_above(model, mu, search, eta_lo, safe)?;
    if !search.limit_states_above.is_empty() {
        let etas = search.limit_states_above.iter().map(|s| s.eta).collect();
        checks.push(walk.states_line(search.limit_states_above.len(), etas));
    }
    let method = match search.method {
        SearchMethod::Sweep => Method::Sweep("sweep"),
        SearchMethod::HingesOnly => Method::Infinite("hinges only"),
        SearchMethod::Refined => Method::Refined,
        SearchMethod::Ridge => Method::Ridge,
        SearchMethod::Found if search.unique => {
            return reject("search: method found claims no complete list, so not unique = true")
        }
        SearchMethod::Found => {
            found_distinct(cert, search)?;
            Method::Found
        }
    };
    ridge_evidence(model, cert, search, safe, &mut checks)?;
    let points: Vec<Point> = search.no_mechanism.iter().map(point).collect();
    walk.method_evidence(model, mu, (method, search.events), &points, &mut checks, |checks| {
        if mu.is_some() {
            return reject("search: method hinges_only needs infinite friction (mu = null)");
        }
        if !search.limit_states_above.is_empty() || !search.no_mechanism.is_empty() {
            return reject("search: method hinges_only lists nothing above eta_s");
        }
        let state = StateAt::bare(safe.x, safe.eta);
        prove_state(model, state, mu, true, "safe side").map_err(|e| {
            Rejection(format!("search (hinges_only): the safe state is not proved strictly inside P(eta_hi): {}", e.0))
        })?;
        checks.push(format!(
            "proved (interval arithmetic): the safe state lies strictly inside P(eta_hi) (every phi < 0 over the whole arch), so at mu = inf no limit state has eta >= {} (a hinge-only mechanism needs P(eta) without interior, formulation §6)",
            safe.eta
        ));
        Ok(())
    })?;
    let verdict = match (count, search.mechanism_at_eta) {
        (0, _) => {
            "no limit state with eta in [eta_s, 2): the arch is safe from eta_s on".to_string()
        }
        (1, true) => "one limit state with eta in [eta_s, 2), at eta_s (unique)".to_string(),
        (1, false) => "one limit state with eta in [eta_s, 2), above eta_s (unique; none at eta_s)"
            .to_string(),
        (n, _) if search.method == SearchMethod::Found => format!(
            "at least {n} limit states with eta in [eta_s, 2) (not unique; the list is not claimed complete)"
        ),
        (n, _) => format!("{n} limit states with eta in [eta_s, 2) (not unique)"),
    };
    Ok((
        checks,
        format!("the search ({}) lists {verdict}", method.name()),
    ))
}

/// Method `found` rests on its listed limit states alone: at least two (the one at η_s
/// counted), pairwise distinct (η or reactions), so that `unique = false` follows from them.
fn found_distinct(cert: &Certificate, search: &SearchEvidence) -> Result<(), Rejection> {
    let at_eta_s = cert
        .limit_state
        .as_ref()
        .filter(|_| search.mechanism_at_eta);
    let listed: Vec<&LimitStateCert> = at_eta_s
        .into_iter()
        .chain(&search.limit_states_above)
        .collect();
    if listed.len() < 2 {
        return reject(format!(
            "search: method found lists {} limit state(s): not unique needs two",
            listed.len()
        ));
    }
    for (i, a) in listed.iter().enumerate() {
        for b in &listed[i + 1..] {
            if a.eta == b.eta && a.x == b.x {
                return reject(format!(
                    "search: method found lists the limit state at eta = {} twice",
                    a.eta
                ));
            }
        }
    }
    Ok(())
}

/// The `ridge` section (method `ridge` only), re-proved: its lines, or a line saying what
/// it does not prove.
fn ridge_evidence(
    model: &Model,
    cert: &Certificate,
    search: &SearchEvidence,
    safe: &SafeSide,
    checks: &mut Vec<String>,
) -> Result<(), Rejection> {
    let ridge = match (search.method, &search.ridge, cert.mu) {
        (SearchMethod::Ridge, Some(ridge), Some(mu)) => (ridge, mu),
        (SearchMethod::Ridge, _, _) => {
            return reject("search: method ridge needs a ridge section and finite mu")
        }
        (_, Some(_), _) => return reject("search: a ridge section belongs to method ridge"),
        (_, None, _) => return Ok(()),
    };
    if !search.no_mechanism.is_empty() {
        return reject("search: method ridge lists no sweep points");
    }
    let at_eta_s = cert
        .limit_state
        .as_ref()
        .filter(|_| search.mechanism_at_eta);
    let listed: Vec<&LimitStateCert> = search.limit_states_above.iter().chain(at_eta_s).collect();
    match prove_ridge(model, ridge.1, ridge.0, (&listed, at_eta_s), (safe.eta, safe.x)) {
        Ok(lines) => checks.extend(lines),
        Err(why) => checks.push(format!(
            "not proved: that the listed limit states are every one above eta_hi (the ridge evidence does not prove it: {why})"
        )),
    }
    Ok(())
}

/// A state of the thickness problem listed without a mechanism.
fn point(p: &NoMechanism) -> Point<'_> {
    let state = StateAt::bare(p.x, p.eta);
    (state, &p.pattern, &p.farkas)
}

/// The listing agrees with itself and with the certificate: `unique` with the number of
/// limit states listed (returned), the certificate's limit state the least one.
fn check_listing(cert: &Certificate, search: &SearchEvidence) -> Result<usize, Rejection> {
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
    Ok(count)
}

/// The limit states listed above η_s, each checked in floating point (ascending, finite,
/// admissible, with a mechanism).
fn limit_states_above(
    model: &Model,
    mu: Option<f64>,
    search: &SearchEvidence,
    eta_lo: f64,
    safe: &SafeSide,
) -> Result<(), Rejection> {
    let mut last = safe.eta;
    for (i, ls) in search.limit_states_above.iter().enumerate() {
        let whose = format!("search: limit state above eta_s {i}");
        finite(ls, &whose)?;
        check_pattern(model, &ls.pattern, mu, &[], &whose)?;
        if ls.eta < last {
            return reject(format!(
                "{whose}: eta = {} is not above eta_hi and the previous listed state (not ascending)",
                ls.eta
            ));
        }
        last = ls.eta;
        check_limit_state(model, mu, ls, eta_lo, 2.0)?;
        let state = StateAt::bare(ls.x, ls.eta);
        check_admissible(model, mu, state, &whose)?;
    }
    Ok(())
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

/// Re-checks the `load_search` section of a load certificate against the claim: λ_static in
/// [λ_lo, λ_hi] (`hi` `None`: unbounded, admissible states from λ_lo on). Returns the
/// report's lines and the verdict.
pub(super) fn verify_load_search(
    model: &Model,
    live: &Live,
    mu: Option<f64>,
    search: &LoadSearchEvidence,
    lo: f64,
    hi: Option<f64>,
) -> Result<(Vec<String>, String), Rejection> {
    let walk = Walk {
        section: "load_search",
        live: Some(live),
    };
    let mut checks = Vec::new();
    let unique = check_load_listing(search, lo)?;
    let states = &search.limit_states;
    let mut last = f64::NEG_INFINITY;
    for (i, ls) in states.iter().enumerate() {
        let whose = format!("load_search: limit state {i}");
        if ls.lambda.is_nan() || ls.lambda < last {
            return reject(format!("{whose}: lambda = {} is not ascending", ls.lambda));
        }
        last = ls.lambda;
        if hi.is_some_and(|h| ls.lambda >= h) {
            return reject(format!(
                "{whose}: lambda = {} is not below lambda_hi = {} (no state is admissible there)",
                ls.lambda,
                hi.unwrap_or(f64::INFINITY)
            ));
        }
        let state = StateAt::loaded(live, ls.lambda, ls.x);
        check_load_limit_state(model, state, mu, ls, &whose)?;
    }
    if !states.is_empty() {
        checks.push(walk.states_line(states.len(), states.iter().map(|s| s.lambda).collect()));
    }
    if let Some(c) = states.iter().find(|s| s.continuum.is_some()) {
        checks.push(format!(
            "not re-checked: the continuum of limit states from lambda = {} (only its least state is checked)",
            c.lambda
        ));
    }
    check_mechanism_at_static(search, lo, hi)?;
    static_state(model, &walk, mu, search, (lo, hi), &mut checks)?;
    let method = match search.method {
        LoadSearchMethod::Sweep => Method::Sweep("sweep"),
        LoadSearchMethod::Faces => Method::Sweep("faces"),
        LoadSearchMethod::Associative => Method::Infinite("associative"),
        LoadSearchMethod::Refined => Method::Refined,
        LoadSearchMethod::Found => Method::Found,
    };
    let mut points: Vec<Point> = Vec::new();
    for (i, p) in search.no_mechanism.iter().enumerate() {
        let top = hi.unwrap_or(f64::INFINITY);
        if matches!(method, Method::Sweep(_)) && !(p.lambda >= search.lambda_min && p.lambda <= top)
        {
            return reject(format!(
                "load_search: no_mechanism {i}: lambda = {} lies outside [lambda_min, lambda_hi]",
                p.lambda
            ));
        }
        points.push((StateAt::loaded(live, p.lambda, p.x), &p.pattern, &p.farkas));
    }
    walk.method_evidence(
        model,
        mu,
        (method, search.events),
        &points,
        &mut checks,
        |checks| associative(mu, search, (lo, hi), checks),
    )?;
    if search.lambda_min > 0.0 {
        checks.push(format!(
            "not proved: lambda_min = {} (below it the arch does not stand; the state there is an unloading limit, never a collapse)",
            search.lambda_min
        ));
    }
    Ok((checks, load_verdict(search, unique, method)))
}

/// The listing agrees with itself: `unique` (returned) with the limit states listed, the
/// collapse multiplier with the least of them, λ_min in [0, λ_lo].
fn check_load_listing(search: &LoadSearchEvidence, lo: f64) -> Result<bool, Rejection> {
    let states = &search.limit_states;
    if search.method == LoadSearchMethod::Found
        && (search.unique || search.lambda.is_some() || states.is_empty())
    {
        return reject("load_search: method found claims no complete list: it lists limit states, with unique = false and no collapse multiplier (lambda = null)");
    }
    // (method found: not claimed, whatever is listed)
    let unique = search.method != LoadSearchMethod::Found
        && states.len() == 1
        && states[0]
            .continuum
            .as_ref()
            .is_none_or(|c| c.to.is_some_and(|to| to <= states[0].lambda));
    if search.unique != unique {
        return reject(format!(
            "load_search: unique = {} but {} limit state(s) are listed{}",
            search.unique,
            states.len(),
            if states.iter().any(|s| s.continuum.is_some()) {
                " (with a continuum)"
            } else {
                ""
            }
        ));
    }
    if search.method != LoadSearchMethod::Found && search.lambda != states.first().map(|s| s.lambda)
    {
        return reject(format!(
            "load_search: the collapse multiplier lambda = {:?} is not the least listed limit state's ({:?})",
            search.lambda,
            states.first().map(|s| s.lambda)
        ));
    }
    if !(search.lambda_min.is_finite() && search.lambda_min >= 0.0 && search.lambda_min <= lo) {
        return reject(format!(
            "load_search: lambda_min = {} must lie in [0, lambda_lo = {lo}]",
            search.lambda_min
        ));
    }
    Ok(unique)
}

/// `mechanism_at_static` agrees with the limit states listed in [λ_lo, λ_hi].
fn check_mechanism_at_static(
    search: &LoadSearchEvidence,
    lo: f64,
    hi: Option<f64>,
) -> Result<(), Rejection> {
    let states = &search.limit_states;
    // a state at λ_static: an isolated one in the bracket, or a continuum reaching it
    let isolated_at_static = states
        .iter()
        .any(|s| s.continuum.is_none() && s.lambda >= lo);
    let at_static = isolated_at_static
        || states.iter().any(|s| {
            s.continuum
                .as_ref()
                .is_some_and(|c| c.to.is_none_or(|to| to >= lo))
        });
    match (search.mechanism_at_static, hi) {
        (true, None) => {
            return reject("load_search: mechanism_at_static is true, but lambda_static is unbounded")
        }
        (true, Some(_)) if !at_static => {
            return reject(format!(
                "load_search: mechanism_at_static is true, but no listed limit state (or continuum of them) reaches [lambda_lo, lambda_hi] (from {lo})"
            ))
        }
        (false, Some(_)) if isolated_at_static => {
            return reject(format!(
                "load_search: mechanism_at_static is false, but a listed limit state lies in [lambda_lo, lambda_hi] (from {lo})"
            ))
        }
        _ => {}
    }
    Ok(())
}

/// The state at λ_static listed without a mechanism, proved to carry none; pushes the
/// report's line.
fn static_state(
    model: &Model,
    walk: &Walk,
    mu: Option<f64>,
    search: &LoadSearchEvidence,
    (lo, hi): (f64, Option<f64>),
    checks: &mut Vec<String>,
) -> Result<(), Rejection> {
    match (&search.static_state, hi, walk.live) {
        (Some(_), _, _) if search.mechanism_at_static => {
            return reject("load_search: a static_state without mechanism is listed, but mechanism_at_static is true")
        }
        (Some(_), None, _) => {
            return reject("load_search: a static_state is listed, but lambda_static is unbounded")
        }
        (Some(p), Some(h), Some(live)) => {
            if !(p.lambda >= lo && p.lambda <= h) {
                return reject(format!(
                    "load_search: static_state lambda = {} lies outside [lambda_lo, lambda_hi]",
                    p.lambda
                ));
            }
            let point = (StateAt::loaded(live, p.lambda, p.x), &p.pattern[..], &p.farkas[..]);
            let what = format!("the state at lambda_static (lambda = {})", p.lambda);
            checks.push(walk.listed_state(model, mu, point, what, "load_search: static_state")?);
        }
        (None, Some(_), _) if !search.mechanism_at_static => checks.push(
            "not proved: that the state at lambda_static carries no mechanism (no evidence listed)"
                .into(),
        ),
        _ => {}
    }
    Ok(())
}

/// The evidence of method `associative` (μ = ∞): virtual work; pushes the report's line.
fn associative(
    mu: Option<f64>,
    search: &LoadSearchEvidence,
    (lo, hi): (f64, Option<f64>),
    checks: &mut Vec<String>,
) -> Result<(), Rejection> {
    if mu.is_some() {
        return reject("load_search: method associative needs infinite friction (mu = null)");
    }
    if !search.no_mechanism.is_empty() {
        return reject("load_search: method associative lists no sweep points");
    }
    if search.limit_states.iter().any(|s| s.lambda < lo) {
        return reject(format!(
            "load_search (associative): a limit state below lambda_lo = {lo} is listed, which virtual work rules out"
        ));
    }
    checks.push(match hi {
        Some(_) => format!(
            "proved (virtual work, mu = inf): no limit state lies below lambda_lo = {lo}: a hinge-only mechanism dissipates nothing, so a limit state at lambda* admits no state at any lambda > lambda*, and one is proved admissible at lambda_lo; with lambda_hi, every limit state lies in [lambda_lo, lambda_hi)"
        ),
        None => "proved (virtual work, mu = inf): no limit state exists: a hinge-only mechanism dissipates nothing, so a limit state at lambda* admits no state at any lambda > lambda*, and states are proved admissible at every lambda from lambda_lo on".to_string(),
    });
    Ok(())
}

/// The one-line verdict on the limit states listed under the load.
/// How many of the listed limit states (ascending in λ) are distinct in λ: apart by more
/// than the checks' tolerance [`LIMIT_STATE_TOL`] × (1 + |λ|). Two distinct ones, each
/// checked as a limit state, make the answer not unique whatever the list misses.
pub fn distinct_in_lambda(states: &[LoadLimitStateCert]) -> usize {
    let apart = |a: f64, b: f64| (b - a).abs() > LIMIT_STATE_TOL * (1.0 + b.abs());
    states.len().min(1)
        + states
            .windows(2)
            .filter(|w| apart(w[0].lambda, w[1].lambda))
            .count()
}

fn load_verdict(search: &LoadSearchEvidence, unique: bool, method: Method) -> String {
    let states = &search.limit_states;
    let verdict = match (states.len(), unique) {
        (n, _) if search.method == LoadSearchMethod::Found => format!(
            "{n} limit state(s) found, the least at lambda = {}{}: the collapse multiplier is at most that (the list is not claimed complete)",
            states[0].lambda,
            match distinct_in_lambda(states) {
                d if d >= 2 => format!(" ({d} distinct in lambda, each checked as a limit state: not unique)"),
                _ => String::new(),
            }
        ),
        (0, _) => "no limit state: the load never drives a mechanism".to_string(),
        (1, true) => format!(
            "one limit state, lambda = {} (unique{})",
            states[0].lambda,
            if search.mechanism_at_static {
                ", at lambda_static"
            } else {
                ""
            }
        ),
        (n, _) => format!(
            "{n} limit states, the least at lambda = {} (not unique{})",
            states[0].lambda,
            if states.iter().any(|s| s.continuum.is_some()) {
                "; with a continuum"
            } else {
                ""
            }
        ),
    };
    format!("the search ({}) lists {verdict}", method.name())
}
