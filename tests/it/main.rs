//! The one integration-test binary (one link on 2 cores); modules by subject.

mod assess;
mod atlas;
mod bridge;
mod bridge_certificates;
mod certificates;
mod cli;
mod compas;
mod continuum_reference;
mod dense_grid;
mod edges;
mod fill_thickness;
mod hard_cases;
mod identities;
mod intervals;
mod invariants;
mod jacobian;
mod layering;
mod limit_states;
mod load_certificates;
mod load_continuum_reference;
mod load_reference;
mod load_seam;
mod loads;
mod model;
mod modes;
mod paper;
mod plots;
mod python_types;
mod readme;
mod reference;
mod report;
mod ridge;
mod search_reference;
mod serve;
mod warm_start;

/// How many random cases a campaign runs: the environment variable `name` where it holds a
/// count (`FACE_CASES=20000` and the like, for longer runs by hand), else `default`.
fn cases_from_env(name: &str, default: usize) -> usize {
    std::env::var(name)
        .ok()
        .and_then(|v| v.parse().ok())
        .unwrap_or(default)
}
