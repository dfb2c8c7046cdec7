//! Every limit state under the load at one (η, μ): the sweep of P(λ) on a discrete arch,
//! the optimal face at λ_static, the continua of limit states; on a continuous arch the
//! exact λ_static and the limit states of two discretisations carried over.

use super::continuum::{self, NoExtreme};
use super::face;
use super::limit_state::limit_state_on;
use super::outcome::{LoadOutcome, LoadSurvey, LoadUnsettled, StaticRange, UNBOUNDED_SEARCH_TOP};
use super::range::{check_load, static_range, UNBOUNDED_BELOW};
use crate::arch::{check_eta, Arch, InputError, JointLayout};
use crate::contact::Contact;
use crate::family::Tagged;
use crate::kinematics::{column, power};
use crate::limit_states::discretised::{self, agreed, Carried, Part};
use crate::limit_states::sweep::{by_faces, sweep_load_with_top};
use crate::limit_states::LimitState;
use crate::load::{rows, LiveLoad, LoadRow, Side};
use crate::lp::{self, LpOutcome};
use crate::mechanism;
use crate::settings::Settings;
use crate::state::State;
use crate::statics::Reactions;
use crate::undecided::Undecided;

/// Every limit state of `load` on a discrete arch at thickness `eta` and friction `mu`:
/// the static range (two LPs), the state at λ_static checked for a mechanism with positive
/// live power, and the sweep of P(λ) from λ_min to λ_static for the limit states below it.
/// The inner `Err` says why no decision was reached.
pub fn survey(
    arch: &Arch,
    eta: f64,
    mu: f64,
    load: &LiveLoad,
    settings: &Settings,
) -> Result<Result<LoadOutcome, Undecided>, InputError> {
    Ok(survey_partial(arch, eta, mu, load, settings)?.map_err(|u| u.why))
}

/// [`survey`], with what an undecided survey decided all the same (the static range, the
/// limit states found: [`LoadUnsettled`]).
pub fn survey_partial(
    arch: &Arch,
    eta: f64,
    mu: f64,
    load: &LiveLoad,
    settings: &Settings,
) -> Result<Result<LoadOutcome, LoadUnsettled>, InputError> {
    if !matches!(arch.layout(), JointLayout::Discrete(_)) {
        // the exchange for each end once (static_range would run the largest twice)
        check_eta(eta)?;
        crate::arch::check_mu(mu)?;
        check_load(arch, load)?;
        return Ok(continuous_survey(arch, eta, mu, load, settings));
    }
    let range = match static_range(arch, eta, mu, load, settings)? {
        Ok(r) => r,
        Err(e) => return Ok(Err(e.into())),
    };
    let (min, max) = match range {
        StaticRange::NoEquilibrium => return Ok(Ok(LoadOutcome::NoEquilibrium)),
        StaticRange::Interval { min, max } => (min, max),
    };
    let JointLayout::Discrete(joints) = arch.layout() else {
        unreachable!("continuous arches answered above")
    };
    let all_rows = rows(arch, joints, eta, mu, load);
    // an undecided survey keeps its static range (exact)
    let unsettled = |why: Undecided| LoadUnsettled {
        why,
        lambda_min: Some(min.0),
        lambda_static: max.map(|m| m.0),
        mechanism_at_static: None,
        found: Vec::new(),
        below_static: 0,
    };
    let continua = match continua(arch, eta, mu, load, &all_rows, settings) {
        Ok(c) => c,
        Err(e) => return Ok(Err(unsettled(e))),
    };
    // a state whose active set holds a continuum's pair belongs to that continuum
    let in_continuum = |pattern: &[Contact], sides: &[Side]| {
        continua.iter().any(|c| {
            c.pattern.iter().zip(&c.sides).all(|(p, s)| {
                pattern
                    .iter()
                    .zip(sides)
                    .any(|(q, t)| q.beta == p.beta && q.kind == p.kind && t == s)
            })
        })
    };
    let top = max.map_or(UNBOUNDED_SEARCH_TOP, |m| m.0);
    // the sweep below λ_static (at μ = ∞ there is nothing below it to search: associative)
    let swept = mu
        .is_finite()
        .then(|| sweep_load_with_top(arch, eta, mu, load, min, top, settings));
    // the states at λ_static: the optimal face whole, by a walk on its vertices from the
    // LP's, with the sweep's points at the top; the LP's state where neither gave one
    let at_top = swept.as_ref().map_or(&[][..], |(_, at_top)| &at_top[..]);
    let at_static = match max {
        None => None,
        Some(lp) => {
            match states_at_static(arch, (eta, mu), load, &all_rows, lp, at_top, settings) {
                Ok(a) => Some(a),
                Err(e) => return Ok(Err(unsettled(e))),
            }
        }
    };
    let max = at_static.as_ref().map(|a| a.state);
    if mu.is_infinite() {
        return Ok(Ok(associative(min, max, at_static)));
    }
    let (sw, _) = swept.expect("swept at finite mu");
    if let Some(f) = sw.failure {
        let why = match max {
            Some(m) => f.map_text(|f| {
                let n = joints.len();
                format!("{f} (lambda_static of these {n} joints = {}, exact)", m.0)
            }),
            None => f,
        };
        return Ok(Err(with_static_states(unsettled(why), at_static)));
    }
    // where the arch does not stand unloaded (λ_min > 0) the state at λ_min is the
    // unloading end: the arch fails there as λ decreases, and it is never reported as a
    // collapse under the load, whatever mechanism the load could also drive there
    let above_min = |l: f64| min.0 == 0.0 || l > min.0 * (1.0 + settings.root_slack);
    let mut limit_states: Vec<LimitState> = sw
        .states
        .into_iter()
        .filter(|s| s.t < top * (1.0 - settings.root_slack) && above_min(s.t))
        .collect();
    let mut no_mechanism = sw.no_mechanism;
    let (mechanism_at_static, at_static) = match at_static {
        Some(a) => {
            no_mechanism.extend(a.without);
            (!a.limit_states.is_empty(), a.limit_states)
        }
        None => (false, Vec::new()),
    };
    limit_states.extend(at_static);
    limit_states.retain(|s| !in_continuum(&s.pattern, &s.sides));
    limit_states.extend(continua);
    limit_states.sort_by(|a, b| a.t.total_cmp(&b.t));
    if max.is_none() && limit_states.is_empty() {
        return Ok(Ok(LoadOutcome::NoCollapse {
            lambda_min: min,
            events: sw.events,
        }));
    }
    Ok(Ok(LoadOutcome::Limits(LoadSurvey {
        lambda_min: min,
        lambda_static: max,
        mechanism_at_static,
        limit_states,
        events: sw.events,
        method: search_method(joints.len(), settings),
        no_mechanism,
    })))
}

/// How the limit states of a discrete arch of `joints` joints below λ_static are searched:
/// the sweep, or beyond its budget the face search
/// ([`crate::limit_states::sweep::faces_load`]).
fn search_method(joints: usize, settings: &Settings) -> &'static str {
    if by_faces(joints, settings) {
        "faces"
    } else {
        "sweep"
    }
}

/// An undecided survey of a discrete arch with the states at λ_static, decided without the
/// sweep (by the optimal face).
fn with_static_states(u: LoadUnsettled, at_static: Option<face::AtStatic>) -> LoadUnsettled {
    let found = at_static.map(|a| a.limit_states);
    LoadUnsettled {
        mechanism_at_static: found.as_ref().map(|f| !f.is_empty()),
        found: found.unwrap_or_default(),
        ..u
    }
}

/// The states at λ_static of a discrete arch: the optimal face whole, by a walk on its
/// vertices from the LP's state `lp`, with the sweep's points at the top (`at_top`); the
/// LP's state where neither gave one. An LP failure there is no decision (`Err`), never
/// "no mechanism".
fn states_at_static(
    arch: &Arch,
    (eta, mu): (f64, f64),
    load: &LiveLoad,
    all_rows: &[LoadRow],
    (lambda_lp, x_lp): (f64, Reactions),
    at_top: &[Reactions],
    settings: &Settings,
) -> Result<face::AtStatic, Undecided> {
    let mut points = face::walk(all_rows, eta, mu, lambda_lp, x_lp, settings);
    points.extend(at_top.iter().copied());
    let mut f = face::face(all_rows, eta, mu, lambda_lp, &points, settings);
    if f.vertices.is_empty() {
        f = face::face(all_rows, eta, mu, lambda_lp, &[x_lp], settings);
    }
    face::decide(arch, eta, mu, load, all_rows, &f, settings)
}

/// The answer at μ = ∞, associative (hinges only): the static maximum is the only limit
/// state, and none exists where λ is unbounded (see `continuous_survey`).
fn associative(
    min: (f64, Reactions),
    max: Option<(f64, Reactions)>,
    at_static: Option<face::AtStatic>,
) -> LoadOutcome {
    match (max, at_static) {
        (Some(m), Some(a)) => LoadOutcome::Limits(LoadSurvey {
            lambda_min: min,
            lambda_static: Some(m),
            mechanism_at_static: !a.limit_states.is_empty(),
            limit_states: a.limit_states,
            events: 0,
            method: "associative",
            no_mechanism: Vec::new(),
        }),
        _ => LoadOutcome::NoCollapse {
            lambda_min: min,
            events: 0,
        },
    }
}

/// Two compatibility columns cancel when their sum is below this in every component (the
/// columns are of size 1: exact cancellation leaves rounding only).
const CANCEL_TOL: f64 = 1e-12;

/// Two sliding columns whose sums are below `CANCEL_TOL` point opposite ways to within
/// ~1.5 `CANCEL_TOL` in angle: only pairs whose directions agree modulo π to this are
/// compared component by component (a window far wider than the test it guards).
const DIRECTION_WINDOW: f64 = 1e-9;

/// The pairs (i < j, in row order) of sliding rows whose compatibility columns cancel (see
/// [`continua`]), excluding one joint's section sliding both ways. The rows are sorted by the
/// direction of their sliding column modulo π and only neighbours within
/// `DIRECTION_WINDOW` (with the wrap at π) are compared: N log N, not all N² pairs.
fn cancelling_pairs(rows: &[LoadRow], eta: f64) -> Vec<(usize, usize)> {
    let col = |r: &LoadRow| column(r.contact.kind, r.contact.beta, eta);
    let mut dir: Vec<(f64, usize)> = (0..rows.len())
        .filter(|&i| !rows[i].contact.kind.is_hinge())
        .map(|i| {
            let c = col(&rows[i]);
            (c[1].atan2(c[0]).rem_euclid(std::f64::consts::PI), i)
        })
        .collect();
    dir.sort_by(|a, b| a.0.total_cmp(&b.0));
    let near = |a: f64, b: f64| std::f64::consts::PI - (b - a) <= DIRECTION_WINDOW;
    let mut out = Vec::new();
    for (k, &(a, i)) in dir.iter().enumerate() {
        // the rows just after this one, and (near 0) those just below π
        let ahead = dir[k + 1..]
            .iter()
            .take_while(|&&(b, _)| b - a <= DIRECTION_WINDOW);
        let wrap = dir[k + 1..].iter().rev().take_while(|&&(b, _)| near(a, b));
        for &(_, j) in ahead.chain(wrap) {
            let (p, q) = (&rows[i.min(j)], &rows[i.max(j)]);
            if p.contact.beta == q.contact.beta && p.side == q.side {
                continue; // one joint slides one way only
            }
            let (cp, cq) = (col(p), col(q));
            if (0..3).all(|k| (cp[k] + cq[k]).abs() <= CANCEL_TOL) {
                out.push((i.min(j), i.max(j)));
            }
        }
    }
    out.sort_unstable();
    out.dedup();
    out
}

/// Continua of limit states. Two active contacts whose compatibility columns cancel — the
/// two sections of the point load's joint sliding opposite ways (the zero-width piece that
/// carries the load slides along the joint between blocks at rest), or two joints half a
/// turn apart sliding the same way (the piece between them translates) — carry the
/// mechanism (½, ½) wherever both are active. Its live power is fixed and its total power
/// is affine in λ, so every admissible state with both active and total power ≥ 0 is a
/// limit state: a polyhedron in (x, λ), whose least and largest λ are two LPs. Each
/// continuum is returned as its least state, with `continuum_to` its largest λ.
pub fn continua(
    arch: &Arch,
    eta: f64,
    mu: f64,
    load: &LiveLoad,
    rows: &[LoadRow],
    settings: &Settings,
) -> Result<Vec<LimitState>, Undecided> {
    let mut out = Vec::new();
    if !mu.is_finite() {
        return Ok(out); // hinge columns cancel only at η = 0
    }
    let ineq: Vec<([f64; 4], f64)> = rows.iter().map(LoadRow::pair).collect();
    for (i, j) in cancelling_pairs(rows, eta) {
        let (p, q) = (&rows[i], &rows[j]);
        let pair = [(p.contact, p.side), (q.contact, q.side)];
        let plain = [p.contact, q.contact];
        let dead = power(arch, eta, &plain);
        let live = load.power(arch, eta, &pair);
        let (d, l) = (0.5 * (dead[0] + dead[1]), 0.5 * (live[0] + live[1]));
        if l <= settings.rate_tol {
            continue;
        }
        // total power d + λ l ≥ 0
        let mut with_power = ineq.clone();
        with_power.push(([0.0, 0.0, 0.0, -l], -d));
        let equal = [p.pair(), q.pair()];
        let from = match lp::multiplier_extreme(&with_power, &equal, false, settings) {
            Ok(Some(z)) => z,
            Ok(None) => continue,
            Err(LpOutcome::Infeasible) => continue,
            Err(LpOutcome::Failed(e)) => return Err(Undecided::back_end(e)),
        };
        let to = match lp::multiplier_extreme(&with_power, &equal, true, settings) {
            Ok(Some(z)) => z[3],
            Ok(None) => f64::INFINITY,
            Err(LpOutcome::Infeasible) => from[3],
            Err(LpOutcome::Failed(e)) => return Err(Undecided::back_end(e)),
        };
        let x = [from[0], from[1], from[2]];
        let st = State { arch, eta, mu, x };
        let Ok(Some((mechanism, live_power))) =
            mechanism::find_under_load(&st, from[3], load, &pair, settings)
        else {
            continue;
        };
        let contacts = (plain.to_vec(), vec![p.side, q.side]);
        out.push(LimitState {
            continuum_to: Some(to),
            ..LimitState::new(
                arch,
                (from[3], x),
                contacts,
                (mechanism, live_power),
                settings,
            )
        });
    }
    Ok(out)
}

/// A continuous arch: λ_static exact (exchange and Newton, [`continuum`]). At μ = ∞ every
/// mechanism is made of hinges, with no dissipation, so a limit state at λ* has
/// L_dead + λ* L_live = 0; an admissible state at any λ' > λ* would give
/// L_dead + λ' L_live ≤ 0 (virtual work), impossible with L_live > 0: the only limit state
/// is at λ_static (the associative case), and none exists when λ is unbounded. At finite
/// μ the limit states below λ_static are not searched on the continuum yet: no decision.
fn continuous_survey(
    arch: &Arch,
    eta: f64,
    mu: f64,
    load: &LiveLoad,
    settings: &Settings,
) -> Result<LoadOutcome, LoadUnsettled> {
    let min = match continuum::extreme(arch, eta, mu, load, false, settings) {
        Ok(Some((l, x, _))) => (l, x),
        Ok(None) => return Err(Undecided::Lp(UNBOUNDED_BELOW.into()).into()),
        Err(NoExtreme::NoState) => return Ok(LoadOutcome::NoEquilibrium),
        Err(NoExtreme::Undecided(e)) => return Err(e.into()),
    };
    let max = match continuum::extreme(arch, eta, mu, load, true, settings) {
        Ok(m) => m,
        Err(NoExtreme::NoState) => return Ok(LoadOutcome::NoEquilibrium),
        Err(NoExtreme::Undecided(e)) => return Err(e.into()),
    };
    if mu.is_finite() {
        return continuous_finite_friction(arch, eta, mu, load, min, max, settings);
    }
    let Some((lambda, x, pattern)) = max else {
        return Ok(LoadOutcome::NoCollapse {
            lambda_min: min,
            events: 0,
        });
    };
    let limit_states: Vec<LimitState> =
        limit_state_on(arch, eta, mu, load, (lambda, x), &pattern, settings)?
            .into_iter()
            .collect();
    Ok(LoadOutcome::Limits(LoadSurvey {
        lambda_min: min,
        lambda_static: Some((lambda, x)),
        mechanism_at_static: !limit_states.is_empty(),
        limit_states,
        events: 0,
        method: "associative",
        no_mechanism: Vec::new(),
    }))
}

/// A continuous arch at finite friction: the limit states below λ_static from two
/// discretisations (J and 2J equal pieces, the point load's angle a joint of both), each
/// discrete limit state carried over to the continuum ([`continuum::carry_over`]) and kept
/// when it is one there too (a mechanism with positive live power); the answer stands when
/// both discretisations give the same set (or, where they differ, two finer ones), as for the
/// thickness search. λ_static itself is the exact continuum's. A continuum of limit states in a discretisation (the loaded
/// point sliding along its section) is not carried over yet: no decision then. Where the
/// discretisations do not settle, the states they found (each verified on the continuum)
/// and the state at λ_static are kept with the reason ([`LoadUnsettled`]).
fn continuous_finite_friction(
    arch: &Arch,
    eta: f64,
    mu: f64,
    load: &LiveLoad,
    min: (f64, Reactions),
    max: Option<continuum::Extreme>,
    settings: &Settings,
) -> Result<LoadOutcome, LoadUnsettled> {
    // unbounded: the discretisations sweep up to `UNBOUNDED_SEARCH_TOP`, as a discrete arch's
    let top = max.as_ref().map_or(UNBOUNDED_SEARCH_TOP, |m| m.0);
    let carry =
        |pieces, part| carried_states(arch, eta, mu, load, (pieces, part), top, min, settings);
    // λ to `same_state_eta` × (1 + |λ|): a multiplier near zero is fixed in absolute terms
    let same = |p: &LimitState, q: &LimitState| {
        discretised::same_state(p, q, settings.same_state_eta * (1.0 + p.t.abs()), settings)
    };
    let sort = |l: &mut Vec<LimitState>| l.sort_by(|p, q| p.t.total_cmp(&q.t));
    let at_static = |(lambda_s, x_s, pattern_s): &continuum::Extreme| {
        limit_state_on(arch, eta, mu, load, (*lambda_s, *x_s), pattern_s, settings)
    };
    let (fine, events, _) = match agreed(settings, carry, same, sort) {
        Ok(a) => a,
        Err(u) => {
            // the state at λ_static too, where its check decides (it tops the list)
            // (each carried state lies below λ_static: `below`)
            let mut found = u.found;
            let below_static = found.len();
            let checked = max.as_ref().and_then(|m| at_static(m).ok());
            let mechanism_at_static = checked.as_ref().map(Option::is_some);
            found.extend(checked.flatten());
            return Err(LoadUnsettled {
                why: u.why,
                lambda_min: Some(min.0),
                lambda_static: max.map(|m| m.0),
                mechanism_at_static,
                found,
                below_static,
            });
        }
    };
    let Some(m) = &max else {
        if fine.is_empty() {
            return Ok(LoadOutcome::NoCollapse {
                lambda_min: min,
                events: events.unwrap_or(0),
            });
        }
        return Ok(LoadOutcome::Limits(LoadSurvey {
            lambda_min: min,
            lambda_static: None,
            mechanism_at_static: false,
            limit_states: fine,
            events: events.unwrap_or(0),
            method: "refined",
            no_mechanism: Vec::new(),
        }));
    };
    let at_static = at_static(m)?;
    let mechanism_at_static = at_static.is_some();
    let mut limit_states = fine;
    limit_states.extend(at_static);
    Ok(LoadOutcome::Limits(LoadSurvey {
        lambda_min: min,
        lambda_static: Some((m.0, m.1)),
        mechanism_at_static,
        limit_states,
        events: events.unwrap_or(0),
        method: "refined",
        no_mechanism: Vec::new(),
    }))
}

/// The limit states below λ_static of the `pieces`-piece discretisation of a continuous arch
/// carried over to the continuum (adjacent contacts merged into tangencies, Newton with λ
/// unknown, verified over the arch), with the events of its sweep (`None` where it found no
/// limit state to sweep to); `part`: of its search at μ, or of its searches at shifted μ
/// (near where a branch ends, the discretisation's own branch may have ended at μ;
/// [`discretised::shifted`]), which have no events.
#[allow(clippy::too_many_arguments)]
fn carried_states(
    arch: &Arch,
    eta: f64,
    mu: f64,
    load: &LiveLoad,
    (pieces, part): (usize, Part),
    lambda_s: f64,
    min: (f64, Reactions),
    settings: &Settings,
) -> Result<Carried, Undecided> {
    let (a, b) = (arch.beta_right(), arch.beta_left());
    let above_min = |l: f64| min.0 == 0.0 || l > min.0 * (1.0 + settings.root_slack);
    let mut events = None;
    let mut joints: Vec<f64> = (0..=pieces)
        .map(|i| {
            if i == pieces {
                b
            } else {
                a + (b - a) * i as f64 / pieces as f64
            }
        })
        .collect();
    for beta in load.breaks(arch, eta) {
        if !joints.contains(&beta) {
            joints.push(beta);
        }
    }
    joints.sort_by(f64::total_cmp);
    let discrete = arch
        .clone()
        .with_joints(&joints)
        .map_err(|e| Undecided::Discretisation(e.to_string()))?;
    let mut narrowed = false;
    let states = match part {
        Part::AtMu => match survey(&discrete, eta, mu, load, settings)
            .map_err(|e| Undecided::Discretisation(e.to_string()))?
        {
            Ok(LoadOutcome::Limits(sv)) => {
                events = Some(sv.events);
                sv.limit_states
            }
            Ok(LoadOutcome::NoCollapse { .. }) => Vec::new(),
            Ok(LoadOutcome::NoEquilibrium) => {
                return Err(Undecided::Discretisation(format!(
                    "the {pieces}-piece discretisation has no admissible state"
                )))
            }
            Err(e) => return Err(e.map_text(|e| format!("{pieces} pieces: {e}"))),
        },
        Part::Shifted => {
            let at = |m: f64| match survey(&discrete, eta, m, load, settings) {
                Ok(Ok(LoadOutcome::Limits(sv))) => Ok(sv.limit_states),
                _ => Err(()),
            };
            // a face of states (a continuum at one λ) found there is not carried
            let (found, n) = discretised::shifted(mu, pieces, settings, at);
            narrowed = n;
            found
                .into_iter()
                .flatten()
                .filter(|s| s.continuum_to.is_none())
                .collect()
        }
    };
    let h = (b - a) / pieces as f64;
    let mut found: Vec<LimitState> = Vec::new();
    for st in &states {
        // a face of states at the discretisation's own static maximum (a continuum at
        // one λ): its states lie at or above the continuous arch's λ_static, which is
        // decided on the continuum itself below
        if st.continuum_to.is_some_and(|to| to <= st.t) {
            continue;
        }
        if st.continuum_to.is_some() {
            return Err(Undecided::NotCovered(format!(
                    "the {pieces}-piece discretisation has a continuum of limit states from lambda = {} (the loaded point sliding along its section): not carried over to the continuous arch yet",
                    st.t
                )));
        }
        let pattern: Vec<Tagged<Side>> = st.pattern.iter().copied().zip(st.sides.clone()).collect();
        let Some((l, x, active)) =
            continuum::carry_over(arch, eta, mu, load, (st.t, st.x), &pattern, h, settings)
        else {
            continue;
        };
        if !below(l, lambda_s, settings) || !above_min(l) {
            continue;
        }
        found.extend(limit_state_on(
            arch,
            eta,
            mu,
            load,
            (l, x),
            &active,
            settings,
        )?);
    }
    Ok(Carried {
        states: found,
        events,
        narrowed,
    })
}

/// Whether λ lies below `top` by more than the resolution at which a multiplier is decided:
/// `root_slack` relative, and absolute below 1 (the rows are of size 1 in x and λ, so a λ
/// near zero is fixed to rounding in absolute terms, not relative ones).
pub(crate) fn below(l: f64, top: f64, settings: &Settings) -> bool {
    l < top - settings.root_slack * top.abs().max(1.0)
}
