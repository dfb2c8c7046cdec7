use arch_enum::statics::Affine;
fn main() {
    let rows: Vec<Affine> = (0..40).map(|i| { let b = i as f64 * 0.08; Affine { g: [b.sin(), b.cos(), 1.0], c: -1.0 - b } }).collect();
    let t = std::time::Instant::now();
    for _ in 0..200 { let _ = arch_enum::lp::max_margin(&rows, 3.0, 1e-10); }
    println!("max_margin: {:?} per call", t.elapsed() / 200);
}
