//! The edges of the domain as named regression tests: μ at and near μ_ms, sideways
//! arches whose least states grow without bound, very large finite μ, and LPs one back
//! end cannot decide. Each reference value was computed independently (in the issue that
//! reported the case, or as said at the test) and is written here, never in `src/`.

use crate::cli::json_of;

/// The `eta`, `status` and `attained` of `solve --json` with these arguments.
fn solved(args: &[&str]) -> (String, f64, Option<bool>) {
    let mut all = vec!["solve"];
    all.extend_from_slice(args);
    let (v, code) = json_of(&all);
    assert!(code == 0 || code == 1, "{all:?}: exit {code}, {v}");
    (
        v["status"].as_str().unwrap().to_string(),
        v["eta"].as_f64().unwrap_or(f64::NAN),
        v["attained"].as_bool(),
    )
}

/// Both LP paths fail on one margin LP near this sideways arch's infimum (the dense
/// simplex's optimum touches its box, HiGHS stops with "HiGHS error while solving
/// model"): the dense simplex in HiGHS's retry box decides it, and the answer is the
/// infimum found at μ = 1.7 (the same weightless line of thrust), not "unresolved".
#[test]
fn an_lp_one_back_end_cannot_solve_is_solved_another_way() {
    let (status, eta, attained) = solved(&[
        "--beta-right",
        "-1.4325646298716197",
        "--beta-left",
        "0.15906317839841866",
        "--mu",
        "1.7181703989942783",
    ]);
    assert_eq!(status, "ok");
    assert!((eta - 0.353351604289215).abs() < 1e-14, "{eta}");
    assert_eq!(attained, Some(false));
}

/// A μ within the resolution band above μ_ms is not left unresolved when the arch
/// stands at no η < 2 even without sliding (μ = ∞): admissibility only grows with μ, so
/// no friction makes it stand. (Reference: the independent check, and `solve
/// --mu inf` on this arch.)
#[test]
fn near_mu_ms_an_arch_that_stands_at_no_friction_has_no_equilibrium() {
    let arch = [
        "--beta-right",
        "1.3173171303776912",
        "--beta-left",
        "4.513760350322722",
        "--weight",
        "centroid",
    ];
    for mu in ["5.053055364696166", "inf"] {
        let mut args = arch.to_vec();
        args.extend(["--mu", mu]);
        let (status, _, _) = solved(&args);
        assert_eq!(status, "no_equilibrium", "mu = {mu}");
    }
}
