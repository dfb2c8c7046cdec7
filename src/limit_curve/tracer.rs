//! Sampling η*(μ) for the tracer and locating the corner between two samples whose
//! patterns differ (Newton on the union of both patterns with μ unknown, bisection in μ
//! as the fallback).

use super::Corner;
use crate::arch::Arch;
use crate::collapse_mode::{classify, CollapseMode};
use crate::contact::ContactKind;
use crate::contact::{Contact, Location};
use crate::limit::{solve, LimitState, Outcome};
use crate::refine::{solve_system, Unknowns};
use crate::settings::Settings;
use crate::state::State;
use crate::statics::Reactions;

type Signature = Vec<(ContactKind, Location)>;

pub(super) fn signature(p: &[Contact]) -> Signature {
    p.iter().map(|c| (c.kind, c.at)).collect()
}

#[derive(Debug, Clone)]
pub(super) struct Sample {
    pub(super) ls: LimitState,
    pub(super) sig: Signature,
}

pub(super) struct Tracer<'a> {
    pub(super) arch: &'a Arch,
    pub(super) settings: &'a Settings,
    pub(super) solves: usize,
    pub(super) unresolved: Vec<(f64, String)>,
    pub(super) no_collapse: Vec<f64>,
    pub(super) no_equilibrium: Vec<f64>,
}

impl Tracer<'_> {
    pub(super) fn sample(&mut self, mu: f64) -> Option<Sample> {
        self.solves += 1;
        match solve(self.arch, mu, self.settings).map(|s| s.outcome) {
            Ok(Outcome::Limit(ls)) => Some(Sample {
                sig: signature(&ls.pattern),
                ls,
            }),
            Ok(Outcome::NoCollapse { .. }) => {
                self.no_collapse.push(mu);
                None
            }
            Ok(Outcome::NoEquilibrium { .. }) => {
                self.no_equilibrium.push(mu);
                None
            }
            Ok(Outcome::Unresolved { reason, .. }) => {
                self.unresolved.push((mu, reason));
                None
            }
            Err(e) => {
                self.unresolved.push((mu, e.to_string()));
                None
            }
        }
    }

    pub(super) fn mode_of(&self, p: &[Contact]) -> CollapseMode {
        classify(
            p,
            0.5 * (self.arch.beta_right() + self.arch.beta_left()),
            self.settings.same_joint,
        )
    }

    /// Newton on the union of two patterns with η and μ unknown, from the state
    /// (x, η, μ); verified admissible and with μ in [mu_lo, mu_hi].
    pub(super) fn corner_newton(
        &self,
        upper: &[Contact],
        lower: &[Contact],
        start: (Reactions, f64, f64),
        mu_range: (f64, f64),
        between: [CollapseMode; 2],
    ) -> Option<Corner> {
        let mut union: Vec<Contact> = lower.to_vec();
        for c in upper {
            let dup = union.iter().any(|d| {
                d.kind == c.kind
                    && d.at == c.at
                    && (d.beta - c.beta).abs() < self.settings.track_angle
            });
            if !dup {
                union.push(*c);
            }
        }
        let s = self.settings;
        let from = State {
            arch: self.arch,
            eta: start.1,
            mu: start.2,
            x: start.0,
        };
        let r = solve_system(&from, &union, Unknowns::EtaMu, s).ok()?;
        let tol = self.settings.root_slack;
        if !(r.mu >= mu_range.0 * (1.0 - tol) && r.mu <= mu_range.1 * (1.0 + tol)) {
            return None;
        }
        let st = State {
            arch: self.arch,
            eta: r.eta,
            mu: r.mu,
            x: r.x,
        };
        let v = st.verdict(ContactKind::active_at(r.mu), s);
        if v.worst > s.adm_tol {
            return None;
        }
        let joints = v.active;
        let mode = self.mode_of(&joints);
        Some(Corner {
            mu: r.mu,
            eta: r.eta,
            x: r.x,
            joints,
            between,
            mode,
            exact: true,
            residual: r.residual,
        })
    }

    /// The corners between samples `a` (higher μ) and `b` (lower μ) with different
    /// patterns.
    pub(super) fn locate(&mut self, a: &Sample, b: &Sample, depth: usize) -> Vec<Corner> {
        let between = [self.mode_of(&a.ls.pattern), self.mode_of(&b.ls.pattern)];
        let range = (b.ls.mu, a.ls.mu);
        for start in [&b.ls, &a.ls] {
            if let Some(c) = self.corner_newton(
                &a.ls.pattern,
                &b.ls.pattern,
                (start.x, start.eta, start.mu),
                range,
                between,
            ) {
                return vec![c];
            }
        }
        let mid_mu = (a.ls.mu * b.ls.mu).sqrt();
        if depth == 0 || a.ls.mu / b.ls.mu < 1.0 + self.settings.same_root {
            return vec![bracketed(a, b, between)];
        }
        let Some(m) = self.sample(mid_mu) else {
            return vec![bracketed(a, b, between)];
        };
        if m.sig == a.sig {
            self.locate(&m, b, depth - 1)
        } else if m.sig == b.sig {
            self.locate(a, &m, depth - 1)
        } else {
            let mut v = self.locate(a, &m, depth - 1);
            v.extend(self.locate(&m, b, depth - 1));
            v
        }
    }
}

/// A corner known only to lie between samples `a` and `b` (reported with
/// `exact: false`).
pub(super) fn bracketed(a: &Sample, b: &Sample, between: [CollapseMode; 2]) -> Corner {
    Corner {
        mu: (a.ls.mu * b.ls.mu).sqrt(),
        eta: 0.5 * (a.ls.eta + b.ls.eta),
        x: b.ls.x,
        joints: b.ls.pattern.clone(),
        between,
        mode: between[1],
        exact: false,
        residual: f64::NAN,
    }
}
