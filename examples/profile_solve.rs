//! Rough profile of one solve: time per stage.
use arch_enum::*;
fn main() {
    let args: Vec<f64> = std::env::args().skip(1).map(|a| a.parse().unwrap()).collect();
    let arch = Arch::symmetric(args[0], WeightModel::Centreline).unwrap();
    let s = Settings::default();
    let t = std::time::Instant::now();
    let mut ws = admissibility::WorkingSet::initial(&arch);
    let mut n = 0;
    let mut rounds = 0;
    for i in 0..40 { let eta = 0.1 + i as f64 * 0.001; let m = admissibility::max_margin(&arch, eta, args[1], JointMode::active_at(args[1]), &mut ws, admissibility::Goal::Decide, &s).unwrap(); n += 1; rounds += m.rounds; }
    println!("40 margins: {:?}, rounds {rounds}, ws {}", t.elapsed(), ws.joints().len());
    let t = std::time::Instant::now();
    let sol = solve(&arch, args[1], &s).unwrap();
    println!("solve: {:?}, candidates {}", t.elapsed(), sol.candidates.len());
    let _ = n;
}
