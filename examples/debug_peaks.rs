use arch_enum::*;
fn main() {
    let a: Vec<f64> = std::env::args()
        .skip(1)
        .map(|s| s.parse().unwrap())
        .collect();
    let arch = Arch::new(a[0], a[1], WeightModel::Centreline).unwrap();
    let (eta, mu) = (a[2], a[3]);
    let s = Settings::default();
    let mut ws = admissibility::WorkingSet::initial(&arch);
    let m = admissibility::max_margin(
        &arch,
        eta,
        mu,
        JointMode::active_at(mu),
        &mut ws,
        admissibility::Goal::Optimise,
        &s,
    )
    .unwrap();
    println!("x = {:?} margin {:e} lp {:e}", m.x, m.margin, m.lp_margin);
    let st = scan::State {
        arch: &arch,
        eta,
        mu,
        x: m.x,
    };
    for p in st.near_active(&s, -1e9) {
        let g = admissibility::grad_norm(&arch, eta, mu, p.contact.mode, p.contact.beta);
        let (n, t, mm) = statics::internal_forces(&arch, eta, &m.x, p.contact.beta);
        println!(
            "{:?} beta {:.9} slack {:e}  N {:e} T {:e} M {:e} d2 {:e}",
            p.contact.mode,
            p.contact.beta,
            -p.value / g,
            n,
            t,
            mm,
            st.phi(p.contact.mode, p.contact.beta)[2]
        );
    }
}
