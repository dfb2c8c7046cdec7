//! The one integration-test binary (one link on 2 cores); modules by subject.

mod assess;
mod certificates;
mod cli;
mod compas;
mod continuum_reference;
mod dense_grid;
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
mod loads;
mod model;
mod modes;
mod plots;
mod readme;
mod reference;
mod ridge;
mod search_reference;
mod serve;
mod warm_start;
