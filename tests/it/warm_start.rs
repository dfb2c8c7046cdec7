//! The bracket of η_s started from a guess (`limit::solve_near`, used along the limit
//! curve) gives the answer of the bracket started from the whole range (`solve`): on random
//! continuous and discrete arches, with guesses that are exact, slightly off, far off, on
//! the wrong side, and nonsense (negative, beyond the thickness limit, zero width).

use crate::search_reference::{random_joints, Rng};
use arch_enum::limit::solve_near;
use arch_enum::search::RootGuess;
use arch_enum::{solve, Arch, Outcome, Settings, WeightModel};

/// η_s of an outcome, when it has one; the outcome's kind otherwise.
fn eta_s(o: &Outcome) -> Result<f64, &'static str> {
    match o {
        Outcome::Limit(ls) => Ok(ls.eta_static),
        Outcome::Unresolved {
            least_static: Some((eta, _)),
            ..
        } => Ok(*eta),
        Outcome::Unresolved { .. } => Err("unresolved"),
        Outcome::NoCollapse { .. } => Err("no collapse"),
        Outcome::NoEquilibrium { .. } => Err("no equilibrium"),
    }
}

fn random_arch(rng: &mut Rng, k: usize) -> Arch {
    let weight = if k % 3 == 2 {
        WeightModel::Centroid
    } else {
        WeightModel::Centreline
    };
    let br = -1.2 + 2.0 * rng.next();
    let bl = br + 1.6 + 2.2 * rng.next();
    let arch = Arch::new(br, bl, weight).expect("arch");
    match k % 4 {
        0 | 1 => arch,
        2 => arch
            .with_blocks(3 + (rng.next() * 30.0) as usize)
            .expect("blocks"),
        _ => {
            let blocks = 2 + (rng.next() * 12.0) as usize;
            let j = random_joints(rng, br, bl, blocks);
            arch.with_joints(&j[1..j.len() - 1]).expect("joints")
        }
    }
}

#[test]
fn a_guess_changes_the_work_not_the_answer() {
    let s = Settings::default();
    let mut rng = Rng(0x5eed_0fa5_7a11);
    let mut compared = 0;
    for k in 0..60 {
        let arch = random_arch(&mut rng, k);
        let mu = 0.2 + 2.0 * rng.next();
        let reference = solve(&arch, mu, &s).expect("solve").outcome;
        let eta = eta_s(&reference).unwrap_or(0.5);
        let guesses = [
            (eta, 1e-6),
            (eta * (1.0 + 3e-6), 1e-6),
            (eta * (1.0 - 3e-6), 1e-6),
            (eta * 1.3, 1e-3),
            (eta * 0.6, 1e-2),
            (eta * 0.999, 0.5),
            (1.999, 1e-6),
            (-0.1, 1e-3),
            (eta, 0.0),
        ];
        for (g, rel) in guesses {
            let got = solve_near(&arch, mu, Some(RootGuess { eta: g, rel }), &s)
                .expect("solve_near")
                .outcome;
            match (eta_s(&reference), eta_s(&got)) {
                (Ok(a), Ok(b)) => {
                    // the bracket decides η_s to settings.bracket_rel; the refined value
                    // is the same root
                    assert!(
                        (a - b).abs() <= 1e-9 * a,
                        "{arch:?} mu = {mu}: eta_s {a} from the whole range, {b} from the guess ({g}, {rel})"
                    );
                    compared += 1;
                }
                (a, b) => assert_eq!(
                    a.err(),
                    b.err(),
                    "{arch:?} mu = {mu}, guess ({g}, {rel}): the outcomes differ"
                ),
            }
        }
    }
    assert!(compared >= 400, "only {compared} comparisons had an eta_s");
}
