//! The figures of `arch-enum plot`: each gathers what the solver found and returns an
//! SVG document (or the reason there is nothing to draw).

use crate::admissibility::{max_margin, Goal, WorkingSet};
use crate::arch::Arch;
use crate::contact::ContactKind;
use crate::limit::{solve, Outcome};
use crate::limit_curve::trace;
use crate::render::plot_curve::{curve_data, CurveData};
use crate::render::{plot_arch, plot_curve, plot_ecc, plot_map};
use crate::scan::State;
use crate::settings::Settings;

/// Why a figure could not be drawn (a result, not bad input).
#[derive(Debug, Clone, PartialEq)]
pub struct NoFigure(pub String);

fn label(arch: &Arch) -> String {
    if arch.is_symmetric() {
        format!(
            "α = {}",
            crate::render::plot::short_num(0.0 - arch.beta_right())
        )
    } else {
        format!(
            "β_R = {:.3}, β_L = {:.3}",
            arch.beta_right(),
            arch.beta_left()
        )
    }
}

fn curve_of(arch: &Arch, settings: &Settings) -> Option<CurveData> {
    let c = trace(arch, settings);
    let mu_ms = c.mu_ms?;
    let top = c
        .corners
        .iter()
        .filter(|k| k.mu.is_finite())
        .map(|k| k.mu)
        .fold(mu_ms, f64::max);
    curve_data(
        arch,
        &label(arch),
        &c,
        (3.0 * top).max(2.0 * mu_ms),
        14,
        settings,
    )
}

/// The limit curves of several arches in one figure.
pub fn curve(arches: &[Arch], settings: &Settings) -> Result<String, NoFigure> {
    let data: Vec<CurveData> = arches
        .iter()
        .filter_map(|a| curve_of(a, settings))
        .collect();
    if data.is_empty() {
        return Err(NoFigure(
            "no arch has a limit curve (none can stand)".into(),
        ));
    }
    plot_curve::svg(&data, "Limit curves η*(μ) by collapse mode").map_err(NoFigure)
}

/// The state drawn by `arch` and `eccentricity`: the limit state at η*(μ) when `eta` is
/// `None`, else the state of greatest margin at `eta` (which must be ≥ η*).
struct Drawn {
    eta: f64,
    x: crate::statics::Reactions,
    pattern: Vec<crate::contact::Contact>,
    limit: Option<crate::limit::LimitState>,
}

fn state(arch: &Arch, mu: f64, eta: Option<f64>, settings: &Settings) -> Result<Drawn, NoFigure> {
    let sol = solve(arch, mu, settings).map_err(|e| NoFigure(e.to_string()))?;
    let ls = match sol.outcome {
        Outcome::Limit(ls) => ls,
        Outcome::NoEquilibrium { reason, .. }
        | Outcome::Unresolved { reason, .. }
        | Outcome::NoCollapse { reason } => return Err(NoFigure(reason)),
    };
    match eta {
        None => Ok(Drawn {
            eta: ls.eta,
            x: ls.x,
            pattern: ls.pattern.clone(),
            limit: Some(ls),
        }),
        Some(e) if e < ls.eta * (1.0 - 1e-12) => Err(NoFigure(format!(
            "no admissible state at eta = {e}: the least thickness at this friction is eta* = {}",
            ls.eta
        ))),
        Some(e) if e <= ls.eta * (1.0 + 1e-12) => Ok(Drawn {
            eta: ls.eta,
            x: ls.x,
            pattern: ls.pattern.clone(),
            limit: Some(ls),
        }),
        Some(e) => {
            let mut ws = WorkingSet::initial(arch);
            let m = max_margin(
                arch,
                e,
                mu,
                ContactKind::active_at(mu),
                &mut ws,
                Goal::Optimise,
                settings,
            )
            .map_err(|err| NoFigure(format!("margin LP failed: {err:?}")))?;
            let st = State {
                arch,
                eta: e,
                mu,
                x: m.x,
            };
            // the contacts of least slack (within 1% of the margin)
            let mut peaks = st.peaks(settings);
            peaks.sort_by(|a, b| b.value.total_cmp(&a.value));
            let best = peaks.first().map_or(0.0, |p| p.value);
            let pattern = peaks
                .iter()
                .filter(|p| p.value >= best * 1.01 - 1e-15)
                .take(6)
                .map(|p| p.contact)
                .collect();
            Ok(Drawn {
                eta: e,
                x: m.x,
                pattern,
                limit: None,
            })
        }
    }
}

/// The arch to scale with its lines and active joints, and the mechanism beneath.
pub fn arch(
    arch: &Arch,
    mu: f64,
    eta: Option<f64>,
    settings: &Settings,
) -> Result<String, NoFigure> {
    let d = state(arch, mu, eta, settings)?;
    let fig = plot_arch::ArchFigure {
        arch,
        mu,
        eta: d.eta,
        x: d.x,
        pattern: &d.pattern,
        mechanism: d.limit.as_ref().map(|l| &l.mechanism),
        mode: d.limit.as_ref().map(|l| l.mode),
    };
    plot_arch::svg(&fig).map_err(NoFigure)
}

/// The eccentricities e_M and e_T against β.
pub fn eccentricity(
    arch: &Arch,
    mu: f64,
    eta: Option<f64>,
    settings: &Settings,
) -> Result<String, NoFigure> {
    let d = state(arch, mu, eta, settings)?;
    plot_ecc::svg(
        arch,
        d.eta,
        mu,
        &d.x,
        &d.pattern,
        d.limit.as_ref().map(|l| l.mode),
    )
    .map_err(NoFigure)
}

/// The margin map over the η–μ plane with the limit curve, on an `n_eta` × `n_mu` grid.
pub fn map(
    arch: &Arch,
    n_eta: usize,
    n_mu: usize,
    settings: &Settings,
    progress: &(dyn Fn(usize, usize) + Sync),
) -> Result<String, NoFigure> {
    let curve = curve_of(arch, settings)
        .ok_or_else(|| NoFigure("the arch cannot stand at any friction".into()))?;
    let mu_lo = 0.7 * curve.mu_ms;
    let mu_hi = curve
        .branches
        .iter()
        .flat_map(|b| b.1.iter().map(|p| p.0))
        .fold(curve.mu_ms, f64::max);
    let eta_top = (1.6
        * curve
            .branches
            .iter()
            .flat_map(|b| b.1.iter().map(|p| p.1))
            .fold(0.0, f64::max))
    .min(1.999);
    let mus: Vec<f64> = (0..n_mu)
        .map(|j| mu_lo * (mu_hi / mu_lo).powf((j as f64 + 0.5) / n_mu as f64))
        .collect();
    let etas: Vec<f64> = (0..n_eta)
        .map(|i| eta_top * (i as f64 + 0.5) / n_eta as f64)
        .collect();
    let values = crate::margin_map::margin_map(arch, &etas, &mus, settings, 2, progress);
    plot_map::svg(&label(arch), &etas, &mus, &values, Some(&curve)).map_err(NoFigure)
}
