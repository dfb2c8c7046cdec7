fn main() {
    let arch = arch_enum::Arch::symmetric(std::env::args().nth(1).map(|a| a.parse().unwrap()).unwrap_or(0.0), arch_enum::WeightModel::Centreline).unwrap();
    let mu: f64 = std::env::args().nth(2).map(|a| a.parse().unwrap()).unwrap_or(f64::INFINITY);
    let t = std::time::Instant::now();
    let s = arch_enum::solve(&arch, mu, &arch_enum::Settings::default()).unwrap();
    println!("{:?}", t.elapsed());
    println!("{:#?}", s.outcome);
    for c in &s.candidates { println!("{:?} {}", c.eta, c.verdict); }
}
