//! Whether an arch stands at every thickness: a state without tension admissible as
//! η → 0⁺ (then η_s = 0, [`super::Outcome::NoCollapse`]).

use crate::admissibility::WorkingSet;
use crate::arch::{Arch, JointLayout};
use crate::contact::ContactKind;
use crate::lp::{self, LpOutcome};
use crate::search::margin_at;
use crate::settings::Settings;
use crate::statics::{actions, reaction_scale, Affine, Reactions};
use crate::undecided::Undecided;

/// A continuous arch's state is checked for tension at this many equal steps of the arch
/// (N ≥ 0 sampled: M ≡ 0 on an interval is impossible, so the samples never decide in
/// practice).
const TENSION_SAMPLES: usize = 4096;

/// Why [`super::Outcome::NoCollapse`].
pub(super) const NO_COLLAPSE: &str = "a state without tension is admissible at vanishing thickness, so the arch stands at every eta > 0 (eta_s = 0); limit states above it can still exist (non-associative friction): the limit-state search lists them";

/// A state admissible as η → 0⁺, if there is one: φ(x, 0) ≤ 0 for every activation
/// function **and** N ≥ 0 at every joint. At η = 0 the hinge conditions |M| ≤ ηN/2 reduce
/// to M = 0 and no longer imply N ≥ 0 (at finite μ the friction conditions |T| ≤ μN still
/// do; at μ = ∞ nothing does): a two-voussoir arch at μ = ∞ always has M = 0 at its three
/// joints for one x, in tension or not, and only without tension does that x stand at
/// every η > 0. Such a state is admissible at every η > 0 (admissibility is monotone once
/// N ≥ 0). A discrete arch is checked at every joint (margin LP with the rows −N ≤ 0, then
/// every row evaluated at its state); a continuous one by the continuum margin LP at η = 0
/// and N ≥ 0 sampled over the arch at its state (M ≡ 0 on an interval is impossible, so
/// this is never met in practice). Tolerances are distances to the planes, relative to the
/// state's size, as the margin LP's own decision.
pub(crate) fn vanishing_thickness_state(
    arch: &Arch,
    mu: f64,
    settings: &Settings,
) -> Result<Option<Reactions>, Undecided> {
    let modes = ContactKind::active_at(mu);
    let lp_err = |e: LpOutcome| match e {
        LpOutcome::Infeasible => Undecided::Lp("margin LP infeasible".to_string()),
        LpOutcome::Failed(m) => Undecided::Lp(m),
    };
    // distances to the planes (rows normalised to unit gradient), as the margin LP's own
    // decision at η = 0 (the hinge slabs |M| ≤ ηN/2 have no width there, so a relative
    // test on φ alone would judge the LP's rounding)
    let distance = |r: &Affine, x: &Reactions| r.at(x) / r.grad_norm().max(f64::MIN_POSITIVE);
    match arch.layout() {
        JointLayout::Discrete(joints) => {
            let mut rows: Vec<Affine> = Vec::new();
            for &beta in joints {
                let a = actions(arch, 0.0, beta);
                rows.extend(modes.iter().map(|&k| a.activation(k, 0, 0.0, mu)));
                rows.push(Affine::combine(-1.0, &a.n[0], 0.0, &a.n[0]));
            }
            let (x, _) = lp::max_margin(&rows, arch.span(), settings).map_err(lp_err)?;
            // exact evaluation of every row at the LP's state
            let worst = rows
                .iter()
                .map(|r| distance(r, &x))
                .fold(f64::NEG_INFINITY, f64::max);
            Ok((worst <= settings.adm_tol * reaction_scale(&x)).then_some(x))
        }
        JointLayout::Continuous => {
            let mut ws = WorkingSet::initial(arch);
            let m = margin_at(arch, 0.0, mu, modes, &mut ws, settings)?;
            let tol = settings.adm_tol * reaction_scale(&m.x);
            if m.margin < -tol {
                return Ok(None);
            }
            let (a, b) = (arch.beta_right(), arch.beta_left());
            let tension = (0..=TENSION_SAMPLES)
                .map(|i| {
                    let n =
                        actions(arch, 0.0, a + (b - a) * i as f64 / TENSION_SAMPLES as f64).n[0];
                    -distance(&n, &m.x)
                })
                .fold(f64::NEG_INFINITY, f64::max);
            Ok((tension <= tol).then_some(m.x))
        }
    }
}
