//! Independent re-checking of a certificate ([`crate::certificate`]): no LP, no solver,
//! and its own interval evaluation of the statics (formulation §3) written out again
//! from the formulas, with outward rounding ([`super::interval`]).
//!
//! Both problems are checked by the same code over their rows — the thickness problem's
//! at η, the load problem's at λ with a live part (`live.rs`):
//!
//! * **Safe side** (an admissible state at η_hi, or at λ_lo under a load): φ ≤ 0 is
//!   *proved* on the whole continuum of joints by second-order Taylor enclosures on
//!   subintervals of [β_R, β_L]: φ(β) ≤ φ(m) + φ'(m)(β − m) + ½ sup φ'' (β − m)², with
//!   adaptive splitting (both sides of a loaded section); for a discrete arch, at each
//!   listed joint.
//! * **Collapse side** (at η_lo, at λ_hi, or over every λ ≥ 0): for d + 1 contacts (d = 3
//!   unknowns h, v, w; d = 2 where w does not enter; d = 4 with λ) the exact multipliers of
//!   a Farkas combination are the signed cofactors of the d × (d+1) gradient matrix,
//!   enclosed in intervals; if they share a sign and Σ yᵢ φᵢ(0) > 0 rigorously, then
//!   Σ yᵢ φᵢ(x) > 0 for every x, so no admissible state exists. The multipliers stored in
//!   the certificate must match the recomputed ones.
//! * **Limit state**: consistency checks in floating point with stated tolerances
//!   (B λ = 0, λ ≥ 0, Σ λ = 1, L_e ≥ 0, complementarity) — evidence, not proof.
//!
//! This file is the dispatcher [`verify()`]; each file below it imports only files further
//! down, and none imports the solver: the vocabulary (`report.rs`, `statics.rs`, `live.rs`
//! with the state of either problem), the proofs and checks of either problem
//! (`enclosure.rs`, `farkas.rs`, `joints.rs`, `limit_state.rs`, `mechanism.rs`, `input.rs`,
//! and the search walker `search.rs`), and the claims (`thickness.rs`; `load.rs` with
//! `load_unbounded.rs`).

mod centred;
mod enclosure;
mod farkas;
mod input;
mod joints;
mod limit_state;
mod live;
mod load;
mod load_unbounded;
mod mechanism;
mod report;
mod ridge;
mod search;
mod statics;
mod thickness;
mod vertical;

pub(crate) use mechanism::one_sense_choices;
pub use report::{Rejection, Report};
pub use search::distinct_in_lambda;
pub use statics::LIMIT_STATE_TOL;

use crate::certificate::format::{Certificate, Claim, FarkasCell, FORMAT, VERSION};
use enclosure::prove_state;
use input::{check_finite, model_of};
use live::{Live, StateAt};
use load::{check_state, verify_load};
use report::reject;
use thickness::{prove_cell, verify_thickness};

/// Re-checks `cert`. Ok with what was proved and checked, or the first reason it fails.
pub fn verify(cert: &Certificate) -> Result<Report, Rejection> {
    if cert.format != FORMAT || cert.version != VERSION {
        return reject(format!(
            "not an {FORMAT} version {VERSION} certificate (found {} version {})",
            cert.format, cert.version
        ));
    }
    check_finite(cert)?;
    let model = model_of(cert)?;
    if let Some(mu) = cert.mu {
        if mu.is_nan() || mu <= 0.0 {
            return reject(format!(
                "mu = {mu}: must be positive (null for infinite friction)"
            ));
        }
    }
    let load_claim = matches!(
        cert.claim,
        Claim::LargestMultiplier | Claim::UnboundedMultiplier
    );
    if load_claim || cert.load.is_some() || cert.multiplier.is_some() || cert.load_search.is_some()
    {
        return verify_load(cert, &model);
    }
    verify_thickness(cert, &model)
}

/// Proves only the admissible side of a certificate — the safe state of a least-thickness
/// certificate, `multiplier.admissible` of a load certificate — (used by `certify` while it
/// searches for the other side).
pub fn prove_admissible_side(cert: &Certificate) -> Result<usize, Rejection> {
    check_finite(cert)?;
    let model = model_of(cert)?;
    let Some(spec) = &cert.load else {
        let Some(safe) = &cert.safe else {
            return reject("no safe side");
        };
        return prove_state(
            &model,
            StateAt::bare(safe.x, safe.eta),
            cert.mu,
            false,
            "safe side",
        );
    };
    let Some(adm) = cert.multiplier.as_ref().and_then(|m| m.admissible.as_ref()) else {
        return reject("no admissible side");
    };
    check_state(adm, "multiplier.admissible")?;
    let live = Live::of(spec, &model)?;
    let state = StateAt::loaded(&live, adm.lambda, adm.x);
    prove_state(&model, state, cert.mu, false, "admissible side")
}

/// Proves one Farkas cell of a `no_equilibrium` certificate over its whole η interval, on
/// the certificate's arch and μ (used by `certify` while it covers [0, 2]); returns its
/// margin.
pub fn prove_farkas_cell(cert: &Certificate, cell: &FarkasCell) -> Result<f64, Rejection> {
    let model = model_of(cert)?;
    prove_cell(&model, cell, cert.mu)
}
