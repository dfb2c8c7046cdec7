//! An independent model of the arch for the tests: the formulas of formulation §3–4
//! written out again (not calling `arch_enum::statics` or `kinematics`), a dense
//! sampling check of admissibility, and a fixed-grid LP for η*.

use arch_enum::{Arch, JointLayout, LeastLimitState};
use good_lp::{highs, variable, Expression, ProblemVariables, SolverModel};

/// (N, T, M) at β for reactions x, centreline (rho = 1) or centroid weight.
pub fn ntm(beta_r: f64, rho: f64, x: [f64; 3], beta: f64) -> (f64, f64, f64) {
    let (h, v, w) = (x[0], x[1], x[2]);
    let d = beta - beta_r;
    let n = h * beta.sin() + v * beta.cos() - d * beta.cos();
    let t = h * beta.cos() - v * beta.sin() + d * beta.sin();
    let m = -h * (beta.sin() - beta_r.sin()) + v * (beta_r.cos() - beta.cos()) + w + d * beta.cos()
        - rho * (beta.sin() - beta_r.sin());
    (n, t, m)
}

/// The four activation functions (E, I, S+, S−) at β; sliding ones are −∞ for μ = ∞.
pub fn phis(beta_r: f64, rho: f64, eta: f64, mu: f64, x: [f64; 3], beta: f64) -> [f64; 4] {
    let (n, t, m) = ntm(beta_r, rho, x, beta);
    let s = if mu.is_finite() {
        [t - mu * n, -t - mu * n]
    } else {
        [f64::NEG_INFINITY; 2]
    };
    [m - eta * n / 2.0, -m - eta * n / 2.0, s[0], s[1]]
}

/// The joint angles to check: every listed joint of a discrete arch, or `n` equally
/// spaced angles of a continuous one.
pub fn sample_joints(arch: &Arch, n: usize) -> Vec<f64> {
    match arch.layout() {
        JointLayout::Discrete(j) => j.clone(),
        JointLayout::Continuous => {
            let (a, b) = (arch.beta_right(), arch.beta_left());
            (0..=n).map(|i| a + (b - a) * i as f64 / n as f64).collect()
        }
    }
}

/// The magnitude of the activation functions of a state: (1 + |x|₁)·min(η, μ, 1),
/// but not below 1e-3 (M, N and T are sums of terms of size |x|).
pub fn scale(ls: &LeastLimitState) -> f64 {
    (1.0 + ls.x.iter().map(|v| v.abs()).sum::<f64>()) * ls.eta.min(ls.mu).clamp(1e-3, 1.0)
}

/// Greatest activation over `n` sampled joints, relative to [`scale`].
pub fn max_rel_violation(arch: &Arch, ls: &LeastLimitState, n: usize) -> f64 {
    let rho = arch.weight().rho(ls.eta);
    let scale = scale(ls);
    sample_joints(arch, n)
        .iter()
        .flat_map(|&b| phis(arch.beta_right(), rho, ls.eta, ls.mu, ls.x, b))
        .fold(f64::NEG_INFINITY, f64::max)
        / scale
}

/// B-matrix column of a contact (formulation §4), written out again.
pub fn column(kind: arch_enum::ContactKind, beta: f64, eta: f64) -> [f64; 3] {
    use arch_enum::ContactKind::*;
    let (s, c) = (beta.sin(), beta.cos());
    match kind {
        HingeExtrados => [-(1.0 + eta / 2.0) * s, (1.0 + eta / 2.0) * c, -1.0],
        HingeIntrados => [(1.0 - eta / 2.0) * s, -(1.0 - eta / 2.0) * c, 1.0],
        SlidePlus => [c, s, 0.0],
        SlideMinus => [-c, -s, 0.0],
    }
}

/// Is there x with every activation ≤ 0 at the given joints (fixed-grid LP)?
pub fn grid_feasible(beta_r: f64, joints: &[f64], eta: f64, mu: f64) -> bool {
    let mut vars = ProblemVariables::new();
    let h = vars.add(variable());
    let v = vars.add(variable());
    let w = vars.add(variable());
    let mut p = vars.minimise(Expression::from(0.0)).using(highs);
    p = p
        .set_option("primal_feasibility_tolerance", 1e-10)
        .set_option("output_flag", false);
    for &b in joints {
        let (s, c, d) = (b.sin(), b.cos(), b - beta_r);
        // N = gN·x + cN etc.
        let gn = [s, c, 0.0];
        let cn = -d * c;
        let gt = [c, -s, 0.0];
        let ct = d * s;
        let gm = [-(s - beta_r.sin()), beta_r.cos() - c, 1.0];
        let cm = d * c - (s - beta_r.sin());
        let mut rows = Vec::with_capacity(4);
        let comb = |a: f64, g1: [f64; 3], c1: f64, k: f64, g2: [f64; 3], c2: f64| {
            (
                [
                    a * g1[0] + k * g2[0],
                    a * g1[1] + k * g2[1],
                    a * g1[2] + k * g2[2],
                ],
                a * c1 + k * c2,
            )
        };
        rows.push(comb(1.0, gm, cm, -eta / 2.0, gn, cn));
        rows.push(comb(-1.0, gm, cm, -eta / 2.0, gn, cn));
        if mu.is_finite() {
            rows.push(comb(1.0, gt, ct, -mu, gn, cn));
            rows.push(comb(-1.0, gt, ct, -mu, gn, cn));
        }
        for (g, c0) in rows {
            let norm = (g[0] * g[0] + g[1] * g[1] + g[2] * g[2]).sqrt().max(1e-300);
            let e = (g[0] / norm) * h + (g[1] / norm) * v + (g[2] / norm) * w;
            p = p.with(e.leq(-c0 / norm));
        }
    }
    p.solve().is_ok()
}

/// η* of the arch discretised into `n` equal voussoirs, by bisection on the
/// fixed-grid LP (to `tol` absolute).
pub fn grid_eta(beta_r: f64, beta_l: f64, n: usize, mu: f64, tol: f64) -> f64 {
    let joints: Vec<f64> = (0..=n)
        .map(|i| beta_r + (beta_l - beta_r) * i as f64 / n as f64)
        .collect();
    let (mut lo, mut hi) = (0.0, 1.99);
    assert!(
        grid_feasible(beta_r, &joints, hi, mu),
        "grid LP infeasible at eta = 1.99"
    );
    while hi - lo > tol {
        let mid = 0.5 * (lo + hi);
        if grid_feasible(beta_r, &joints, mid, mu) {
            hi = mid;
        } else {
            lo = mid;
        }
    }
    0.5 * (lo + hi)
}
