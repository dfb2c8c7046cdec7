use arch_enum::*;
fn main() {
    let alpha: f64 = std::env::args().nth(1).unwrap().parse().unwrap();
    let arch = Arch::symmetric(alpha, WeightModel::Centreline).unwrap();
    let t = std::time::Instant::now();
    let c = limit_curve::trace(&arch, &Settings::default());
    println!("{:?} solves {} mu_min {:?}", t.elapsed(), c.solves, c.mu_min);
    for b in &c.branches { println!("B {:<28} mu [{:.10}, {:.10}] eta [{:.10}, {:.10}] {:?}", b.mode.name(), b.mu_min, b.mu_max, b.eta_min, b.eta_max, b.pattern.iter().map(|c| (c.mode.name(), format!("{:.4}", c.beta))).collect::<Vec<_>>()); }
    for k in &c.corners { println!("C mu {:.12} eta {:.12} exact {} res {:.1e} {:?} {:?}", k.mu, k.eta, k.exact, k.residual, k.between.map(|m| m.name()), k.joints.iter().map(|c| (c.mode.name(), format!("{:.8}", c.beta))).collect::<Vec<_>>()); }
    for u in &c.unresolved { println!("U {:?}", u); }
}
