//! Cross-check against an independent dense fixed-grid LP (written in `model`, not
//! using the crate's statics or LP code), on points of the mixed branch of the
//! semicircle. A grid of n equal voussoirs is a discrete arch, so
//! η*_grid(n) ≤ η*_continuous, and the gap is a discretisation error of order 1/n²:
//! the test checks the ordering and that the gap is within the second-order
//! discretisation bound, and that the crate's own discrete solve (`--blocks n`)
//! agrees with the grid LP. (Gap ratios between grids are not monotone: the gap
//! depends on how close the nearest joint falls to the haunch hinge β_N.)

use crate::model::grid_eta;
use arch_enum::{solve, Arch, Outcome, Settings, WeightModel};
use std::f64::consts::PI;

fn eta_of(arch: &Arch, mu: f64) -> f64 {
    match solve(arch, mu, &Settings::default()).unwrap().outcome {
        Outcome::Limit(ls) => ls.eta,
        other => panic!("mu = {mu}: {other:?}"),
    }
}

#[test]
fn mixed_branch_matches_dense_grid() {
    let arch = Arch::symmetric(0.0, WeightModel::Centreline).unwrap();
    for mu in [0.32, 0.35, 0.39] {
        let exact = eta_of(&arch, mu);
        let bisect_tol = 1e-10;
        let g1 = grid_eta(0.0, PI, 400, mu, bisect_tol);
        let g2 = grid_eta(0.0, PI, 1000, mu, bisect_tol);
        for (n, g) in [(400.0, g1), (1000.0, g2)] {
            let gap = exact - g;
            // discrete arches are never weaker than the continuous one ...
            assert!(
                gap > -2.0 * bisect_tol,
                "mu = {mu}, n = {n}: exact {exact} below grid {g}"
            );
            // ... and the grid misses a tangency point by at most half a spacing h = pi/n,
            // which lowers phi there by at most |phi''| h^2 / 8 and eta* by at most
            // |phi''| h^2 / (4 N); |phi''| / N < 4 on these states, so gap < h^2.
            let h = PI / n;
            assert!(
                gap < h * h,
                "mu = {mu}, n = {n}: gap {gap} exceeds h^2 = {}",
                h * h
            );
        }
        // the crate's discrete solver on the same stereotomy agrees with the grid LP
        let d = eta_of(&arch.clone().with_blocks(400).unwrap(), mu);
        assert!(
            (d - g1).abs() < 1e-8,
            "mu = {mu}: discrete solve {d} vs grid LP {g1}"
        );
    }
}
