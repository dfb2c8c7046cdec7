//! Prints μ_ms of a symmetric arch (exact pattern when found).
use arch_enum::*;
fn main() {
    let alpha: f64 = std::env::args().nth(1).unwrap().parse().unwrap();
    let arch = Arch::symmetric(alpha, WeightModel::Centreline).unwrap();
    let f = friction_limit(&arch, &Settings::default())
        .unwrap()
        .unwrap();
    println!("mu_ms = {:.15} exact {} x = {:?}", f.mu, f.exact, f.x);
    for c in &f.pattern {
        println!("  {:?} {:.12} {:?}", c.mode, c.beta, c.at);
    }
}
