//! Bridge spec §1: span, rise and ring in metres ↔ (α, η, r), both ways, against the
//! spec's formulas written out here (R_i = (L²/4 + f²)/(2f), θ from asin(L/(2R_i)) on
//! either side of the semicircle), and the command line's engineering flags.

use arch_enum::bridge::Intrados;
use std::f64::consts::{FRAC_PI_2, PI};

/// The spec's half-angle: asin(L/(2 R_i)) for f ≤ L/2, π − asin(L/(2 R_i)) above.
fn spec_half_angle(span: f64, rise: f64) -> f64 {
    let ri = (span * span / 4.0 + rise * rise) / (2.0 * rise);
    let a = (span / (2.0 * ri)).min(1.0).asin();
    if rise <= span / 2.0 {
        a
    } else {
        PI - a
    }
}

/// A deterministic uniform generator on [0, 1) (a 64-bit LCG), so that a run repeats.
fn uniform(mut seed: u64) -> impl FnMut() -> f64 {
    move || {
        seed = seed
            .wrapping_mul(6364136223846793005)
            .wrapping_add(1442695040888963407);
        (seed >> 11) as f64 / (1u64 << 53) as f64
    }
}

/// A 10 m semicircular arch with a 0.6 m ring (the engineer): r = 5.3 m,
/// η = 0.6/5.3, α = 0.
#[test]
fn a_ten_metre_semicircle_with_a_sixty_centimetre_ring() {
    let i = Intrados::new(10.0, 5.0).unwrap();
    assert_eq!(i.radius, 5.0);
    assert!(i.alpha().abs() < 1e-15);
    let ring = i.ring(0.6).unwrap();
    assert!((ring.radius - 5.3).abs() < 1e-14);
    assert!((ring.eta - 0.6 / 5.3).abs() < 1e-15);
    // the least ring of a thickness ratio is the ring that has it
    let back = i.ring_of(ring.eta);
    assert!((back.thickness - 0.6).abs() < 1e-14);
}

/// Random segments, semicircles and horseshoes: the half-angle agrees with the spec's
/// formula, and (L, f, t) → (α, η, r) → (L, f, t) reproduces the input to 1e-12.
#[test]
fn engineering_inputs_round_trip() {
    let mut next = uniform(7);
    for _ in 0..2000 {
        let span = 1.0 + 40.0 * next();
        let rise = span * (0.02 + 1.5 * next());
        let t = 0.05 + 0.2 * span * next();
        let i = Intrados::new(span, rise).unwrap();
        let theta = spec_half_angle(span, rise);
        assert!(
            (i.half_angle - theta).abs() < 1e-9,
            "{span} {rise}: {} vs {theta}",
            i.half_angle
        );
        assert!(i.alpha() > -FRAC_PI_2 && i.alpha() < FRAC_PI_2);
        let ring = i.ring(t).unwrap();
        assert!(ring.eta > 0.0 && ring.eta < 2.0);
        // back from the non-dimensional description alone
        let ri = ring.radius * (1.0 - ring.eta / 2.0);
        let j = Intrados::of_opening(i.alpha(), ri);
        let rel = |a: f64, b: f64| (a - b).abs() / b;
        assert!(rel(j.span, span) < 1e-12, "span {span} -> {}", j.span);
        assert!(rel(j.rise, rise) < 1e-12, "rise {rise} -> {}", j.rise);
        assert!(rel(ring.eta * ring.radius, t) < 1e-12);
        assert!(rel(j.ring_of(ring.eta).thickness, t) < 1e-12);
    }
}

/// Lengths must be finite and positive; the error names the flag.
#[test]
fn bad_lengths_name_the_flag() {
    for (span, rise, flag) in [
        (0.0, 1.0, "--span"),
        (10.0, -1.0, "--rise"),
        (f64::NAN, 1.0, "--span"),
    ] {
        let e = Intrados::new(span, rise).unwrap_err().to_string();
        assert!(e.contains(flag), "{e}");
    }
    let e = Intrados::new(10.0, 5.0)
        .unwrap()
        .ring(f64::INFINITY)
        .unwrap_err()
        .to_string();
    assert!(e.contains("--ring"), "{e}");
}

fn arch_enum() -> assert_cmd::Command {
    assert_cmd::Command::cargo_bin("arch-enum").unwrap()
}

/// `--span --rise [--ring]` on the command line: the same answers as the non-dimensional
/// arch it describes (bit for bit), with the `geometry` object added after the document's
/// own keys, and the least ring t* = η* R_i/(1 − η*/2) in metres.
#[test]
fn span_rise_and_ring_give_the_same_answers_as_alpha_and_eta() {
    use crate::cli::json_of;
    // a segmental arch: span 12 m, rise 3 m (R_i = 7.5 m), ring 0.5 m
    let i = Intrados::new(12.0, 3.0).unwrap();
    let alpha = i.alpha().to_string();
    let ring = i.ring(0.5).unwrap();
    let eta = ring.eta.to_string();
    let (a, _) = json_of(&["solve", "--span", "12", "--rise", "3", "--mu", "0.6"]);
    let (b, _) = json_of(&["solve", "--alpha", &alpha, "--mu", "0.6"]);
    assert_eq!(a["eta"], b["eta"]);
    assert_eq!(a["limit_states"], b["limit_states"]);
    let g = &a["geometry"];
    assert_eq!(g["span_m"], 12.0);
    assert_eq!(g["intrados_radius_m"], 7.5);
    let eta_s = a["eta"].as_f64().unwrap();
    let t_star = g["least_ring_m"].as_f64().unwrap();
    assert!((t_star - eta_s * 7.5 / (1.0 - eta_s / 2.0)).abs() < 1e-12 * t_star);
    assert!(b.get("geometry").is_none());
    let (a, _) = json_of(&[
        "assess", "--span", "12", "--rise", "3", "--ring", "0.5", "--mu", "0.6",
    ]);
    let (b, _) = json_of(&["assess", "--alpha", &alpha, "--eta", &eta, "--mu", "0.6"]);
    assert_eq!(a["stands"], b["stands"]);
    assert_eq!(a["geometric_factor"], b["geometric_factor"]);
    assert_eq!(a["geometry"]["eta"].as_f64(), Some(ring.eta));
    assert_eq!(a["geometry"]["radius_m"].as_f64(), Some(7.75));
    // without the flags, the document is the one it was (no geometry key)
    let text = arch_enum()
        .args(["solve", "--alpha", "0", "--mu", "0.6"])
        .output()
        .unwrap();
    assert!(!String::from_utf8_lossy(&text.stdout).contains("geometry"));
}

/// The engineer: a 10 m semicircular ring of 0.6 m, 20 kN/m³, 1 m of barrel: the
/// geometry and scope lines, kN from `--width --unit-weight` (the ring's own weight 199.8
/// kN = 20 · 0.6 · π · 5.3), and bad combinations exit 2 naming the flags.
#[test]
fn an_engineer_describes_the_arch_in_metres() {
    let out = arch_enum()
        .args([
            "assess", "--span", "10", "--rise", "5", "--ring", "0.6", "--mu", "0.6",
        ])
        .args(["--width", "1", "--unit-weight", "20"])
        .output()
        .unwrap();
    let text = String::from_utf8_lossy(&out.stdout);
    assert!(
        text.contains("mean radius r = 5.30000 m, eta = t/r = 0.113207547170"),
        "{text}"
    );
    assert!(text.contains("scope               single ring"), "{text}");
    assert!(text.contains("weight of the arch 199.805 kN"), "{text}");
    for (args, flag) in [
        (&["--ring", "0.6", "--eta", "0.1"][..], "--eta/--ring"),
        (&[][..], "--eta"),
        (&["--ring", "-1"][..], "--ring"),
    ] {
        let out = arch_enum()
            .args(["assess", "--span", "10", "--rise", "5", "--mu", "0.6"])
            .args(args)
            .output()
            .unwrap();
        assert_eq!(out.status.code(), Some(2), "{args:?}");
        assert!(
            String::from_utf8_lossy(&out.stderr).contains(flag),
            "{args:?}"
        );
    }
    // a command that takes no thickness refuses --ring rather than ignoring it
    for cmd in ["modes", "curve"] {
        let out = arch_enum()
            .args([cmd, "--span", "10", "--rise", "5", "--ring", "0.6"])
            .output()
            .unwrap();
        assert_eq!(out.status.code(), Some(2), "{cmd}");
        assert!(
            String::from_utf8_lossy(&out.stderr).contains("--ring"),
            "{cmd}"
        );
    }
    let out = arch_enum()
        .args(["solve", "--span", "10", "--rise", "0", "--mu", "0.6"])
        .output()
        .unwrap();
    assert_eq!(out.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&out.stderr).contains("--rise"));
}

/// The fill's statics (bridge spec §2, §5): F and S against composite Simpson quadrature of
/// the spec's pressure p(θ) = (g_f/η)(y_s − κ sin θ) κ sin θ over [max(β_R, 0), min(β, π)];
/// N_f, T_f, M_f and their β- and η-derivatives against central differences; no fill, or a
/// joint below the loaded part, carries nothing.
#[test]
fn fill_statics_against_quadrature_and_differences() {
    use arch_enum::bridge::Fill;
    let mut next = uniform(11);
    // the spec's integrals, written out independently
    let quad = |fill: &Fill, springings: (f64, f64), eta: f64, beta: f64| -> (f64, f64) {
        let (gf, h) = (fill.weight_ratio, fill.depth);
        crate::load_reference::fill_by_simpson(gf, h, eta, springings, (springings.0, beta))
    };
    for case in 0..300 {
        let br = -1.2 + 2.0 * next();
        let bl = PI - br + (next() - 0.5) * 0.6;
        let eta = 0.05 + 0.6 * next();
        let fill = Fill::new(0.3 + next(), 0.05 + 0.4 * next()).unwrap();
        let beta = br + (bl - br) * next();
        let l = fill.load((br, bl), eta, beta);
        let (f, s) = quad(&fill, (br, bl), eta, beta);
        let scale = 1.0 + f.abs() + s.abs();
        assert!(
            (l.f[0] - f).abs() < 1e-10 * scale,
            "case {case}: F {} vs {f}",
            l.f[0]
        );
        assert!(
            (l.s[0] - s).abs() < 1e-10 * scale,
            "case {case}: S {} vs {s}",
            l.s[0]
        );
        // β-derivatives of the actions, away from the kinks at 0 and π
        if beta.abs() > 1e-3 && (beta - PI).abs() > 1e-3 {
            let a = fill.actions((br, bl), eta, beta);
            let d = 1e-5;
            let (lo, hi) = (
                fill.actions((br, bl), eta, beta - d),
                fill.actions((br, bl), eta, beta + d),
            );
            for (k, (x, y, z)) in [(a.n, lo.n, hi.n), (a.t, lo.t, hi.t), (a.m, lo.m, hi.m)]
                .into_iter()
                .enumerate()
            {
                for o in 0..2 {
                    let fd = (z[o] - y[o]) / (2.0 * d);
                    assert!(
                        (x[o + 1] - fd).abs() < 1e-6 * (1.0 + fd.abs()),
                        "case {case} action {k} order {}: {} vs {fd}",
                        o + 1,
                        x[o + 1]
                    );
                }
            }
            // η-derivatives at fixed β: the first against differences of the actions, the
            // second against differences of the first, at every β-derivative order
            let e = 1e-6;
            let (lo, hi) = (
                fill.actions((br, bl), eta - e, beta),
                fill.actions((br, bl), eta + e, beta),
            );
            let trio = |f: &arch_enum::fill::FillActions| [f.n, f.t, f.m];
            for k in 0..3 {
                for o in 0..3 {
                    let fd = (trio(&hi)[k][o] - trio(&lo)[k][o]) / (2.0 * e);
                    let exact = a.eta[0][k][o];
                    assert!(
                        (exact - fd).abs() < 1e-5 * (1.0 + fd.abs()),
                        "case {case} d/deta of action {k} order {o}: {exact} vs {fd}"
                    );
                    let fd2 = (hi.eta[0][k][o] - lo.eta[0][k][o]) / (2.0 * e);
                    let exact2 = a.eta[1][k][o];
                    assert!(
                        (exact2 - fd2).abs() < 1e-4 * (1.0 + fd2.abs()),
                        "case {case} d2/deta2 of action {k} order {o}: {exact2} vs {fd2}"
                    );
                }
            }
            // the spec's identities: dN = T_f − p cos β, dM = −T_f − (η/2) p cos β
            let p = l.f[1];
            assert!((a.n[1] - (a.t[0] - p * beta.cos())).abs() < 1e-12 * scale);
            assert!((a.m[1] - (-a.t[0] - eta / 2.0 * p * beta.cos())).abs() < 1e-12 * scale);
        }
    }
    let none = Fill::new(0.0, 0.5).unwrap();
    assert_eq!(none.load((0.0, PI), 0.2, 2.0).f, [0.0; 3]);
    // a horseshoe's lower flank (β < 0) carries no fill
    let fill = Fill::new(1.0, 0.2).unwrap();
    assert_eq!(fill.load((-0.5, PI + 0.5), 0.2, -0.1).f, [0.0; 3]);
    assert!(Fill::new(-1.0, 0.2)
        .unwrap_err()
        .to_string()
        .contains("--fill-weight"));
    assert!(Fill::new(1.0, f64::NAN)
        .unwrap_err()
        .to_string()
        .contains("--fill-depth"));
}

/// Fill of zero weight is no fill: the same arch (bit for bit, so every answer is today's);
/// with fill, the scan's forces (`forces_with`) are the full statics' order 0 bit for bit,
/// and the β-derivatives obey the spec's identities with the fill's pressure p:
/// dN/dβ = T − cos β − p cos β, dT/dβ = −N + sin β + p sin β,
/// dM/dβ = −T + (1 − ρ) cos β − (η/2) p cos β (ρ the ring's centroid factor).
#[test]
fn fill_enters_the_statics_and_zero_fill_is_none() {
    use arch_enum::bridge::Fill;
    use arch_enum::statics::{actions, forces_with};
    use arch_enum::{Arch, WeightModel};
    let plain = Arch::symmetric(0.2, WeightModel::Centroid).unwrap();
    assert_eq!(plain.clone().with_fill(Fill::new(0.0, 0.4).unwrap()), plain);
    let mut next = uniform(0xf111_5a71_0000_0001);
    for case in 0..200 {
        let weight = if case % 2 == 0 {
            WeightModel::Centreline
        } else {
            WeightModel::Centroid
        };
        let (br, bl) = (-0.5 + next(), PI - 0.5 + next());
        let eta = 0.05 + 0.5 * next();
        let arch = Arch::new(br, bl, weight)
            .unwrap()
            .with_fill(Fill::new(0.2 + next(), 0.4 * next()).unwrap());
        let fill = *arch.fill().unwrap();
        let beta = br + (bl - br) * next();
        let a = actions(&arch, eta, beta);
        let f = forces_with(&arch, eta, beta, beta.sin_cos());
        for k in 0..3 {
            let full = [a.n[0], a.t[0], a.m[0]][k];
            assert_eq!(
                (f[k].g, f[k].c),
                (full.g, full.c),
                "case {case}: order 0 differs"
            );
        }
        let p = fill.load((br, bl), eta, beta).f[1];
        let (s, c) = beta.sin_cos();
        let x = [next() - 0.5, next() - 0.5, next() - 0.5];
        let (n, t) = (a.n[0].at(&x), a.t[0].at(&x));
        let rho = weight.rho(eta);
        let checks = [
            (a.n[1].at(&x), t - c - p * c),
            (a.t[1].at(&x), -n + s + p * s),
            (a.m[1].at(&x), -t + (1.0 - rho) * c - 0.5 * eta * p * c),
        ];
        for (got, want) in checks {
            assert!(
                (got - want).abs() < 1e-12 * (1.0 + want.abs()),
                "case {case}: {got} vs {want}"
            );
        }
    }
}

/// A 10 m semicircle, 0.6 m ring, 20 kN/m³, 1 m barrel, μ = 0.6 (the engineer).
fn ten_metre_deck(dispersal: f64) -> (arch_enum::Arch, f64, arch_enum::bridge::Deck) {
    let ring = Intrados::new(10.0, 5.0).unwrap().ring(0.6).unwrap();
    let arch = arch_enum::Arch::symmetric(0.0, arch_enum::WeightModel::Centreline).unwrap();
    let deck = arch_enum::bridge::Deck::new(ring.radius, 20.0, 1.0, dispersal).unwrap();
    (arch, ring.eta, deck)
}

fn least_lambda(arch: &arch_enum::Arch, eta: f64, load: &arch_enum::load::LiveLoad) -> Option<f64> {
    least_lambda_at(arch, eta, 0.6, load)
}

fn least_lambda_at(
    arch: &arch_enum::Arch,
    eta: f64,
    mu: f64,
    load: &arch_enum::load::LiveLoad,
) -> Option<f64> {
    use arch_enum::multiplier::{survey, LoadOutcome};
    match survey(arch, eta, mu, load, &arch_enum::Settings::default()).unwrap() {
        Ok(LoadOutcome::Limits(s)) => s.lambda(),
        _ => None,
    }
}

/// Dispersal (bridge spec §5): with s = 0 an axle through fill is today's point load at the
/// extrados point below it (λ scaled by the axle's size); a patch narrowing to a point tends
/// to the point load; a symmetric two-axle vehicle and its mirror position give one answer
/// on a symmetric arch; a vehicle off the ring is refused by name.
#[test]
fn dispersal_tends_to_the_point_load_and_keeps_symmetry() {
    use arch_enum::bridge::{Fill, Vehicle};
    use arch_enum::load::LiveLoad;
    use arch_enum::pressure::{Patch, Pressure};
    let (bare, eta, deck0) = ten_metre_deck(0.0);
    let arch = bare.clone().with_fill(Fill::new(0.9, 0.3 / 5.3).unwrap());
    let axle = Vehicle::new(&[100.0], &[]).unwrap();
    let kappa = 1.0 + eta / 2.0;
    for at in [1.3, 2.5, 4.2, 6.9] {
        let LiveLoad::Pressure(p) = deck0.place(&arch, eta, &axle, at).unwrap() else {
            panic!("a vehicle is a pressure")
        };
        let q = p.points()[0].q;
        let beta = p.points()[0].beta;
        let via_vehicle = least_lambda(&arch, eta, &LiveLoad::Pressure(p)).unwrap();
        let point = least_lambda(&arch, eta, &LiveLoad::Point { beta }).unwrap();
        assert!(
            (via_vehicle * q - point).abs() <= 1e-10 * point,
            "at {at}: {via_vehicle} * {q} vs {point}"
        );
        // narrow patches centred on the point: the error falls with the width
        let x = kappa * beta.cos();
        let errs: Vec<f64> = [1e-2, 1e-3, 1e-4]
            .iter()
            .map(|&h| {
                let patch = Patch {
                    x_lo: x - h,
                    x_hi: x + h,
                    q: 0.5 / h,
                };
                let l = least_lambda(
                    &arch,
                    eta,
                    &LiveLoad::Pressure(Pressure::new(&[patch], &[]).unwrap()),
                )
                .unwrap();
                (l - point).abs() / point
            })
            .collect();
        assert!(
            errs[2] < 1e-4 && errs[2] < errs[0],
            "at {at}: relative errors {errs:?}"
        );
    }
    // a symmetric vehicle at X and at its mirror position on the symmetric arch
    let (_, _, deck) = ten_metre_deck(0.5);
    let pair = Vehicle::new(&[100.0, 100.0], &[1.2]).unwrap();
    // 5.6: the pair centred on the crown, a degenerate static maximum (six contacts, two
    // mirror mechanisms) that must still be decided
    for at in [2.0, 3.7, 5.3, 5.6] {
        let mirror = 10.0 + 1.2 - at;
        let l =
            |x: f64| least_lambda(&arch, eta, &deck.place(&arch, eta, &pair, x).unwrap()).unwrap();
        let (a, b) = (l(at), l(mirror));
        assert!((a - b).abs() <= 1e-9 * a, "at {at}: {a} vs mirror {b}");
    }
    let err = deck.place(&arch, eta, &pair, 40.0).unwrap_err().to_string();
    assert!(err.contains("--at"), "{err}");
}

/// The critical position of one axle on the bare ring (no fill: a point load) against the
/// least λ over a grid of 121 point-load runs across the crossing: never above it, within
/// what the grid's spacing can miss, and located more precisely than the grid (its bracket
/// narrower than the grid's spacing).
#[test]
fn the_critical_position_beats_a_fine_grid_of_point_loads() {
    use arch_enum::bridge::{critical, Search, Vehicle};
    let (arch, eta, deck) = ten_metre_deck(0.5);
    let axle = Vehicle::new(&[100.0], &[]).unwrap();
    let settings = arch_enum::Settings::default();
    let c = critical(
        &arch,
        eta,
        0.6,
        &deck,
        &axle,
        Search {
            samples: 41,
            bracket_m: 1e-6,
            threads: 2,
        },
        &settings,
    )
    .unwrap();
    let best = &c.minima[0];
    let (from, to) = deck.crossing(&arch, eta, &axle);
    let n = 121;
    let spacing = (to - from) / (n - 1) as f64;
    let mut grid = (f64::INFINITY, 0.0);
    for i in 0..n {
        let at = from + spacing * i as f64;
        if let Ok(load) = deck.place(&arch, eta, &axle, at) {
            if let Some(l) = least_lambda(&arch, eta, &load) {
                if l < grid.0 {
                    grid = (l, at);
                }
            }
        }
    }
    println!(
        "critical X* = {} lambda = {} (bracket {:?}); grid best X = {} lambda = {}",
        best.at_m, best.lambda, best.bracket_m, grid.1, grid.0
    );
    assert!(
        best.lambda <= grid.0 * (1.0 + 1e-12),
        "the grid found less: {grid:?} vs {best:?}"
    );
    assert!(
        grid.0 - best.lambda <= 0.05 * best.lambda,
        "too far below the grid: {grid:?} vs {best:?}"
    );
    let mirror = c.mirror_m.unwrap();
    let near = (best.at_m - grid.1).abs().min((mirror - grid.1).abs());
    assert!(
        near <= spacing,
        "X* = {} (mirror {mirror}) far from the grid's {}",
        best.at_m,
        grid.1
    );
    assert!(best.bracket_m.1 - best.bracket_m.0 <= 1e-6 && 1e-6 < 1e-4 * spacing);
}

/// The critical position with fill, against complete surveys run one by one: on the
/// continuous arch under a symmetric pair, every sample of the influence line (those past
/// the axis taken from their mirror images) equals the survey at its own position; on 40
/// voussoirs under an unsymmetric pair, located by static maxima where the least limit
/// state is the static one, no survey on a grid around X* (four sample spacings, 41
/// points) finds a smaller λ_c, and the bracket is as narrow as asked.
#[test]
fn the_critical_position_with_fill_agrees_with_surveys_one_by_one() {
    use arch_enum::bridge::{critical, Fill, Search, Vehicle};
    let (bare, eta, deck) = ten_metre_deck(0.5);
    let settings = arch_enum::Settings::default();
    let fill = Fill::new(0.9, 0.3 / 5.3).unwrap();
    let search = |samples| Search {
        samples,
        bracket_m: 1e-6,
        threads: 2,
    };
    let arch = bare.clone().with_fill(fill);
    let pair = Vehicle::new(&[100.0, 100.0], &[1.2]).unwrap();
    let c = critical(&arch, eta, 0.6, &deck, &pair, search(9), &settings).unwrap();
    for p in &c.influence {
        let direct = deck
            .place(&arch, eta, &pair, p.at_m)
            .ok()
            .and_then(|load| least_lambda(&arch, eta, &load));
        let sampled = p.collapse.value();
        match direct {
            Some(l) => assert!(
                (sampled - l).abs() <= 1e-9 * l,
                "at {}: {sampled} vs {l}",
                p.at_m
            ),
            None => assert!(sampled.is_infinite(), "at {}: {sampled}", p.at_m),
        }
    }
    assert!(
        c.surveys < c.influence.len(),
        "the mirrored half was surveyed: {}",
        c.surveys
    );
    let blocks = bare.with_blocks(40).unwrap().with_fill(fill);
    let uneven = Vehicle::new(&[100.0, 60.0], &[1.5]).unwrap();
    let c = critical(&blocks, eta, 0.6, &deck, &uneven, search(21), &settings).unwrap();
    let best = &c.minima[0];
    assert!(
        c.statics > 0 && c.mirror_m.is_none(),
        "{} static maxima",
        c.statics
    );
    assert!(best.bracket_m.1 - best.bracket_m.0 <= 1e-6, "{best:?}");
    let spacing = (c.influence[1].at_m - c.influence[0].at_m).abs();
    for k in 0..=40 {
        let at = best.at_m + spacing * (k as f64 / 10.0 - 2.0);
        let load = deck.place(&blocks, eta, &uneven, at).unwrap();
        let l = least_lambda(&blocks, eta, &load).unwrap();
        assert!(
            l >= best.lambda * (1.0 - 1e-12),
            "at {at}: {l} below {best:?}"
        );
    }
}

/// A minimum whose bracketing samples are not all at their static maximum (the 10 m
/// segment of rise 6 m with a 1.5 m ring, μ = 1: next to the first sample the axle drives no
/// mechanism) is located on λ_c itself, one complete search a step: more searches than
/// the samples and the other minimum take, and no survey on a grid over its bracket of
/// samples finds less.
#[test]
fn a_minimum_beside_a_sample_without_collapse_is_located_on_lambda_c() {
    use arch_enum::bridge::{critical, Deck, Search, Vehicle};
    let intrados = Intrados::new(10.0, 6.0).unwrap();
    let (alpha, ring) = (intrados.alpha(), intrados.ring(1.5).unwrap());
    let arch = arch_enum::Arch::symmetric(alpha, arch_enum::WeightModel::Centreline).unwrap();
    let deck = Deck::new(ring.radius, 20.0, 1.0, 0.5).unwrap();
    let axle = Vehicle::new(&[100.0], &[]).unwrap();
    let search = Search {
        samples: 11,
        bracket_m: 1e-6,
        threads: 2,
    };
    let settings = arch_enum::Settings::default();
    let c = critical(&arch, ring.eta, 1.0, &deck, &axle, search, &settings).unwrap();
    assert!(
        c.surveys > 6 + 2,
        "{} searches: not located on lambda_c",
        c.surveys
    );
    let first = &c.influence[0];
    let end = c
        .minima
        .iter()
        .find(|m| m.bracket_m.0 <= first.at_m + 1e-9)
        .expect("a minimum at the start of the crossing");
    let spacing = c.influence[1].at_m - first.at_m;
    for k in 0..=20 {
        let at = first.at_m + spacing * k as f64 / 20.0;
        let load = deck.place(&arch, ring.eta, &axle, at).unwrap();
        if let Some(l) = least_lambda_at(&arch, ring.eta, 1.0, &load) {
            assert!(
                l >= end.lambda * (1.0 - 1e-12),
                "at {at}: {l} below {end:?}"
            );
        }
    }
}

/// A continuous arch with fill under a two-axle vehicle spread through it: fine equal
/// discretisations (the angles of the patches' edges not among their joints) converge to
/// the continuous arch's collapse multiplier from above, the error falling with the
/// spacing.
#[test]
fn a_filled_continuous_arch_is_the_limit_of_fine_discretisations() {
    use arch_enum::bridge::{Fill, Vehicle};
    let (bare, eta, deck) = ten_metre_deck(0.5);
    let arch = bare.with_fill(Fill::new(0.9, 0.3 / 5.3).unwrap());
    let pair = Vehicle::new(&[100.0, 100.0], &[1.2]).unwrap();
    let load = deck.place(&arch, eta, &pair, 3.1).unwrap();
    let exact = least_lambda(&arch, eta, &load).unwrap();
    let errs: Vec<f64> = [50, 100, 200]
        .iter()
        .map(|&n| {
            let discrete = arch.clone().with_blocks(n).unwrap();
            let l = least_lambda(&discrete, eta, &load).unwrap();
            (l - exact) / exact
        })
        .collect();
    println!("continuous lambda {exact}; discretisations' relative excess {errs:?}");
    assert!(errs.iter().all(|&e| e >= -1e-12), "{errs:?}");
    assert!(errs[2] < errs[0] && errs[2] < 1e-3, "{errs:?}");
}

fn load_json(args: &[&str]) -> serde_json::Value {
    let out = arch_enum()
        .arg("load")
        .args(args)
        .arg("--json")
        .output()
        .unwrap();
    assert!(
        out.status.code().is_some_and(|c| c <= 1),
        "{args:?}: {out:?}"
    );
    serde_json::from_slice(&out.stdout).unwrap()
}

/// The README's bridge in metres: span, rise, ring, barrel and unit weight (no μ).
pub const DIMENSIONS: [&str; 10] = [
    "--span",
    "10",
    "--rise",
    "5",
    "--ring",
    "0.6",
    "--width",
    "1",
    "--unit-weight",
    "20",
];

/// Its fill (18 kN/m³, 0.3 m of it above the crown's extrados).
pub const FILL: [&str; 4] = ["--fill-weight", "18", "--fill-depth", "0.3"];

/// The README's bridge and μ = 0.6, without fill.
const ENGINEER: [&str; 12] = [
    DIMENSIONS[0],
    DIMENSIONS[1],
    DIMENSIONS[2],
    DIMENSIONS[3],
    DIMENSIONS[4],
    DIMENSIONS[5],
    DIMENSIONS[6],
    DIMENSIONS[7],
    DIMENSIONS[8],
    DIMENSIONS[9],
    "--mu",
    "0.6",
];

/// The JSON contract of `load` with a vehicle (issue 23): `lambda` the adequacy factor,
/// `lambda_static`, `vehicle {axles_kn, spacing_m, at_m}`, `units.lambda_kn` = λ × the
/// vehicle's total, `fill {weight_kn_m3, depth_m}` (null without fill), `geometry`; with
/// `--critical`, `critical {at_m, lambda, mode, pattern, second}` and `influence`, X* the
/// least λ of the influence line and `load`'s own answer at X*. Fill of zero weight gives
/// the numbers without fill, bit for bit; bad bridge flags are refused by name.
#[test]
fn load_with_a_vehicle_keeps_the_json_contract() {
    let mut args = ENGINEER.to_vec();
    args.extend(["--axles", "100,100", "--spacing", "1.2", "--at", "3.1"]);
    let bare = load_json(&args);
    assert!(bare["fill"].is_null());
    assert_eq!(
        bare["vehicle"]["axles_kn"],
        serde_json::json!([100.0, 100.0])
    );
    assert_eq!(bare["vehicle"]["spacing_m"], serde_json::json!([1.2]));
    assert_eq!(bare["vehicle"]["at_m"], serde_json::json!(3.1));
    let lambda = bare["lambda"].as_f64().unwrap();
    let kn = bare["units"]["lambda_kn"].as_f64().unwrap();
    assert_eq!(kn, lambda * 200.0);
    assert!(bare["lambda_static"].as_f64().unwrap() >= lambda);
    assert_eq!(bare["geometry"]["span_m"], serde_json::json!(10.0));
    // zero fill: the same numbers bit for bit
    let mut zero = args.clone();
    zero.extend(["--fill-ratio", "0", "--fill-height", "0.1"]);
    let z = load_json(&zero);
    assert_eq!(z["lambda"], bare["lambda"]);
    assert_eq!(z["limit_states"], bare["limit_states"]);
    // fill, and the critical position
    let mut filled = ENGINEER.to_vec();
    filled.extend([
        "--fill-weight",
        "18",
        "--fill-depth",
        "0.3",
        "--axles",
        "100",
        "--critical",
        "--samples",
        "15",
    ]);
    let c = load_json(&filled);
    assert_eq!(c["fill"]["weight_kn_m3"], serde_json::json!(18.0));
    assert_eq!(c["fill"]["depth_m"], serde_json::json!(0.3));
    let crit = &c["critical"];
    let at = crit["at_m"].as_f64().unwrap();
    assert_eq!(c["vehicle"]["at_m"].as_f64().unwrap(), at);
    assert_eq!(crit["lambda"], c["lambda"], "load answers at X*");
    assert!(crit["mode"].is_string() && crit["pattern"].as_array().is_some_and(|p| !p.is_empty()));
    assert!(crit.get("second").is_some());
    let least = c["influence"]
        .as_array()
        .unwrap()
        .iter()
        .filter_map(|p| p["lambda"].as_f64())
        .fold(f64::INFINITY, f64::min);
    assert!(
        crit["lambda"].as_f64().unwrap() <= least,
        "X* above a sample of its line"
    );
    // refused by name
    for (extra, flag) in [
        (vec!["--axles", "100"], "--axles"),
        (
            vec!["--axles", "100", "--at", "3", "--dispersal", "-1"],
            "--dispersal",
        ),
        (vec!["--axles", "100,-5", "--at", "3"], "--axles"),
        (
            vec!["--axles", "100,100,100", "--spacing", "1,2,3", "--at", "3"],
            "--spacing",
        ),
        (vec!["--axles", "100", "--at", "40"], "--at"),
        (
            vec![
                "--fill-weight",
                "18",
                "--fill-depth",
                "-0.3",
                "--axles",
                "100",
                "--at",
                "3",
            ],
            "--fill-depth",
        ),
    ] {
        let mut a = ENGINEER.to_vec();
        a.extend(extra.iter().copied());
        let out = arch_enum().arg("load").args(&a).output().unwrap();
        assert_eq!(out.status.code(), Some(2), "{a:?}");
        let err = String::from_utf8(out.stderr).unwrap();
        assert!(
            err.contains(flag) && !err.contains("panicked"),
            "{a:?}: {err}"
        );
    }
}

/// What is not solved yet is refused by name, never answered with the wrong derivatives:
/// the limit curve of an arch with fill traced in μ (its friction limit is a curve in η
/// there) and a horizontal acceleration with fill.
#[test]
fn fill_is_refused_where_it_is_not_solved() {
    use arch_enum::bridge::Fill;
    use arch_enum::load::LiveLoad;
    let settings = arch_enum::Settings::default();
    let filled = arch_enum::Arch::symmetric(0.0, arch_enum::WeightModel::Centreline)
        .unwrap()
        .with_fill(Fill::new(0.9, 0.05).unwrap());
    let curve = arch_enum::limit_curve::trace(&filled, &settings);
    assert_eq!(
        curve.status(),
        arch_enum::limit_curve::CurveStatus::Unresolved
    );
    assert!(curve.unresolved[0].1.contains("--fill-weight"));
    let horizontal = LiveLoad::Horizontal {
        towards_right: true,
    };
    let err = arch_enum::multiplier::survey(&filled, 0.2, 0.6, &horizontal, &settings)
        .unwrap_err()
        .to_string();
    assert!(err.contains("--fill-weight"), "{err}");
}

/// A patch load on the road (bridge spec §3, §5): uniform over the whole road on the
/// symmetric arch, its least limit state is symmetric (each contact's mirror is a contact);
/// narrowing about a point with its total held, its collapse load in kN tends to that of one
/// axle of the same total there.
#[test]
fn patch_loads_keep_symmetry_and_narrow_to_an_axle() {
    use arch_enum::bridge::vehicle::RoadPatch;
    use arch_enum::bridge::{Fill, Vehicle};
    use arch_enum::multiplier::{survey, LoadOutcome};
    let (bare, eta, deck) = ten_metre_deck(0.5);
    let arch = bare.with_fill(Fill::new(0.9, 0.3 / 5.3).unwrap());
    let whole = Vehicle::patch_only(RoadPatch::new(10.0, -1.0, 11.0).unwrap());
    let load = deck.place(&arch, eta, &whole, 0.0).unwrap();
    let Ok(LoadOutcome::Limits(s)) =
        survey(&arch, eta, 0.6, &load, &arch_enum::Settings::default()).unwrap()
    else {
        panic!("the whole road loaded: no limit states")
    };
    let least = &s.limit_states[0];
    for c in &least.pattern {
        let mirrored = least
            .pattern
            .iter()
            .any(|d| d.kind == c.kind.mirrored() && (d.beta - (PI - c.beta)).abs() < 1e-9);
        assert!(mirrored, "{c:?} without its mirror in {:?}", least.pattern);
    }
    let axle = least_lambda(
        &arch,
        eta,
        &deck
            .place(&arch, eta, &Vehicle::new(&[2.0], &[]).unwrap(), 3.3)
            .unwrap(),
    )
    .unwrap()
        * 2.0;
    let errs: Vec<f64> = [0.2, 0.02, 0.002]
        .iter()
        .map(|&w| {
            let v =
                Vehicle::patch_only(RoadPatch::new(2.0 / w, 3.3 - w / 2.0, 3.3 + w / 2.0).unwrap());
            let kn = least_lambda(&arch, eta, &deck.place(&arch, eta, &v, 0.0).unwrap()).unwrap()
                * v.total_kn(1.0);
            (kn - axle).abs() / axle
        })
        .collect();
    println!("narrowing patch: relative differences {errs:?} from the axle's {axle} kN");
    assert!(errs[2] < errs[0] && errs[2] < 1e-3, "{errs:?}");
}

/// `plot influence`: the figure of a crossing over fill (the line with X* labelled, the fill
/// shaded, the arch at X* beneath), in SVG; it needs a vehicle with `--critical`, and refuses
/// `--json` by name.
#[test]
fn plot_influence_draws_the_crossing() {
    let dir = std::env::temp_dir().join(format!("arch-enum-influence-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let out = dir.join("influence.svg");
    let mut args = vec!["plot", "influence"];
    args.extend(ENGINEER);
    args.extend(["--axles", "100", "--critical", "--samples", "9"]);
    args.extend(["--fill-weight", "18", "--fill-depth", "0.3"]);
    let run = arch_enum()
        .args(&args)
        .arg("--out")
        .arg(&out)
        .output()
        .unwrap();
    assert_eq!(run.status.code(), Some(0), "{run:?}");
    let svg = std::fs::read_to_string(&out).unwrap();
    assert!(
        svg.contains("X* = ") && svg.contains("collapse mechanism"),
        "the figure lacks its parts"
    );
    assert!(svg.contains("fill (shaded)"), "the fill is not drawn");
    for (extra, flag) in [
        (vec!["--axles", "100", "--at", "3"], "--critical"),
        (vec!["--axles", "100", "--critical", "--json"], "--json"),
    ] {
        let mut a = vec!["plot", "influence"];
        a.extend(ENGINEER);
        a.extend(extra.iter().copied());
        let run = arch_enum()
            .args(&a)
            .arg("--out")
            .arg(&out)
            .output()
            .unwrap();
        assert_eq!(run.status.code(), Some(2), "{a:?}");
        assert!(
            String::from_utf8(run.stderr).unwrap().contains(flag),
            "{a:?}"
        );
    }
    std::fs::remove_dir_all(&dir).ok();
}

/// `solve` with fill (bridge spec §2): `--fill-weight --fill-depth` with `--unit-weight` on
/// `--span --rise --ring` is the same arch as `--fill-ratio --fill-height` with g_f = γ_f/γ
/// and h = h_c/r (the same η_s, bit for bit); the JSON carries `fill` (with the road's depth
/// above the least ring, h r*), `thickness_scan` and `geometry`; zero fill weight is the
/// arch without fill (the same η_s); the text says the scope and the scan; a fill in kN
/// without the masonry's unit weight exits 2 naming the flags.
#[test]
fn solve_takes_fill_in_kn_and_non_dimensionally() {
    use crate::cli::json_of;
    // the README's bridge without its barrel width (solve answers per unit width)
    let mut args = vec!["solve", "--mu", "0.6", "--unit-weight", "20"];
    args.extend(&DIMENSIONS[..6]);
    args.extend(FILL);
    let (a, _) = json_of(&args);
    let h = (0.3 / 5.3).to_string();
    let (b, _) = json_of(&[
        "solve",
        "--alpha",
        "0",
        "--fill-ratio",
        "0.9",
        "--fill-height",
        &h,
        "--mu",
        "0.6",
    ]);
    assert_eq!(a["eta"], b["eta"]);
    let eta_s = a["eta"].as_f64().unwrap();
    let f = &a["fill"];
    assert_eq!(f["weight_kn_m3"], 18.0);
    assert_eq!(f["weight_ratio"], 0.9);
    let r_star = 5.0 / (1.0 - eta_s / 2.0);
    let d = f["depth_at_least_ring_m"].as_f64().unwrap();
    assert!((d - 0.3 / 5.3 * r_star).abs() < 1e-12, "{d}");
    assert_eq!(a["thickness_scan"]["interval"], true);
    assert!(a["thickness_scan"]["lowest_admissible"].as_f64().unwrap() > eta_s);
    assert!(a["geometry"]["least_ring_m"].as_f64().is_some());
    // the fill lightens the semicircle's demand: η_s below the bare ring's
    let (bare, _) = json_of(&["solve", "--alpha", "0", "--mu", "0.6"]);
    assert!(eta_s < bare["eta"].as_f64().unwrap());
    let (zero, _) = json_of(&[
        "solve",
        "--alpha",
        "0",
        "--fill-ratio",
        "0",
        "--fill-height",
        "0.1",
        "--mu",
        "0.6",
    ]);
    assert_eq!(zero["eta"], bare["eta"]);
    assert!(zero.get("thickness_scan").is_none());
    let text = arch_enum()
        .args([
            "solve",
            "--alpha",
            "0",
            "--fill-ratio",
            "0.9",
            "--fill-height",
            "0.1",
            "--mu",
            "0.6",
        ])
        .output()
        .unwrap();
    let text = String::from_utf8(text.stdout).unwrap();
    assert!(text.contains("the fill a vertical dead load"), "{text}");
    assert!(
        text.contains("an interval (to the scan's spacing)"),
        "{text}"
    );
    let out = arch_enum()
        .args([
            "solve",
            "--alpha",
            "0",
            "--fill-weight",
            "18",
            "--fill-depth",
            "0.3",
            "--mu",
            "0.6",
        ])
        .output()
        .unwrap();
    assert_eq!(out.status.code(), Some(2));
    let err = String::from_utf8(out.stderr).unwrap();
    assert!(
        err.contains("--fill-weight") && err.contains("--unit-weight"),
        "{err}"
    );
    for (flag, bad) in [
        ("--fill-ratio", ["nan", "0.1"]),
        ("--fill-height", ["1", "-0.1"]),
    ] {
        let out = arch_enum()
            .args([
                "solve",
                "--alpha",
                "0",
                "--mu",
                "0.6",
                "--fill-ratio",
                bad[0],
            ])
            .args(["--fill-height", bad[1]])
            .output()
            .unwrap();
        assert_eq!(out.status.code(), Some(2));
        let err = String::from_utf8(out.stderr).unwrap();
        assert!(err.contains(&format!("invalid value for {flag}")), "{err}");
    }
    // a shallow segment under fill with η_s below 1e-4: η_s answered, the search declined
    // by name (the sweep's rows span 1/η there)
    let (doc, _) = json_of(&[
        "solve",
        "--alpha",
        "-1.5",
        "--fill-ratio",
        "1",
        "--fill-height",
        "0.1",
        "--mu",
        "0.6",
    ]);
    assert!(doc["eta"].as_f64().unwrap() < 1e-4);
    assert_eq!(doc["search"]["complete"], false);
    assert!(doc["search"]["reason"]
        .as_str()
        .unwrap()
        .contains("with fill"));
}

/// `plot arch` with fill: the least thickness of the arch with its fill, drawn with the
/// fill shaded up to the road and labelled; without fill flags no fill is drawn.
#[test]
fn plot_arch_draws_the_fill() {
    let dir = std::env::temp_dir().join(format!("arch-enum-fill-arch-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let out = dir.join("arch.svg");
    for (fill, drawn) in [
        (vec!["--fill-ratio", "0.9", "--fill-height", "0.1"], true),
        (vec![], false),
    ] {
        let run = arch_enum()
            .args(["plot", "arch", "--alpha", "0", "--mu", "0.6"])
            .args(&fill)
            .arg("--out")
            .arg(&out)
            .output()
            .unwrap();
        assert_eq!(run.status.code(), Some(0), "{run:?}");
        let svg = std::fs::read_to_string(&out).unwrap();
        assert_eq!(svg.contains("fill (shaded)"), drawn);
        // the least thickness drawn is that of `solve` with the same flags
        let (doc, _) = crate::cli::json_of(
            &[vec!["solve", "--alpha", "0", "--mu", "0.6"], fill.clone()].concat(),
        );
        let eta = doc["eta"].as_f64().unwrap();
        let shown = format!("η = {}", arch_enum::render::plot::short_num(eta));
        assert!(svg.contains(&shown), "{shown} not in the caption");
    }
    std::fs::remove_dir_all(&dir).ok();
}

/// `load-curve` on a bridge (fill and a vehicle at `--at`): at each μ the λ of `load` with the
/// same flags, and the bridge's keys (scope, fill, vehicle, geometry) in its document; the
/// vehicle's critical position moves with μ, so `--critical` is refused by name.
#[test]
fn load_curve_takes_the_bridge_flags() {
    use crate::cli::json_of;
    let mut bridge: Vec<&str> = DIMENSIONS.iter().chain(&FILL).copied().collect();
    bridge.extend(["--axles", "100,100", "--spacing", "1.2"]);
    let mut curve = vec![
        "load-curve",
        "--at",
        "3.0",
        "--points",
        "2",
        "--mu-min",
        "0.45",
    ];
    curve.extend(["--mu-max", "0.6"]);
    curve.extend(&bridge);
    let (v, code) = json_of(&curve);
    assert_eq!(code, 0, "{v}");
    assert_eq!(v["fill"]["weight_kn_m3"], 18.0);
    assert_eq!(v["vehicle"]["axles_kn"][1], 100.0);
    assert!(v["scope"].as_str().unwrap().contains("fill"));
    assert!(v["geometry"]["radius_m"].as_f64().is_some());
    let points = v["points"].as_array().unwrap();
    assert_eq!(points.len(), 3);
    for p in points {
        let mu = p["mu"]
            .as_f64()
            .map_or("inf".to_string(), |m| m.to_string());
        let mut load = vec!["load", "--at", "3.0", "--mu", &mu];
        load.extend(&bridge);
        let (w, code) = json_of(&load);
        assert_eq!(code, 0, "{w}");
        let (a, b) = (p["lambda"].as_f64().unwrap(), w["lambda"].as_f64().unwrap());
        assert!(
            (a - b).abs() <= 1e-9 * b,
            "mu {mu}: load-curve {a}, load {b}"
        );
    }
    let mut critical = vec!["load-curve", "--critical"];
    critical.extend(&bridge);
    let (v, code) = json_of(&critical);
    assert_eq!(code, 2);
    assert!(v["message"].as_str().unwrap().contains("--critical"), "{v}");
}
