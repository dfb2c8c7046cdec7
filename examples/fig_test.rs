use arch_enum::*;
fn main() {
    let s = Settings::default();
    let mut data = vec![];
    for (l, a) in [("α = 0", 0.0), ("α = π/6", 0.5235987755982988), ("α = 1", 1.0), ("α = 1.15", 1.15)] {
        let arch = Arch::symmetric(a, WeightModel::Centreline).unwrap();
        let c = limit_curve::trace(&arch, &s);
        data.push(render::plot_curve::curve_data(&arch, l, &c, 10.0, 16, &s).unwrap());
    }
    let svg = render::plot_curve::svg(&data, "Limit curves η*(μ)").unwrap();
    std::fs::write("/tmp/curve.svg", &svg).unwrap();
    std::fs::write("/tmp/curve.png", render::plot::svg_to_png(&svg, 900).unwrap()).unwrap();
}
