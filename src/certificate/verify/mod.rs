//! Independent re-checking of a certificate ([`crate::certificate`]): no LP, no solver,
//! and its own interval evaluation of the statics (formulation §3) written out again
//! from the formulas, with outward rounding ([`super::interval`]).
//!
//! * **Safe side**: φ ≤ 0 at (η_hi, x) is *proved* on the whole continuum of joints by
//!   second-order Taylor enclosures on subintervals of [β_R, β_L]:
//!   φ(β) ≤ φ(m) + φ'(m)(β − m) + ½ sup φ'' (β − m)², with adaptive splitting; for a
//!   discrete arch, at each listed joint.
//! * **Collapse side**: for d + 1 contacts (d = 3 unknowns h, v, w; d = 2 for the
//!   friction-only problem, where w does not enter) the exact multipliers of a Farkas
//!   combination are the signed cofactors of the d × (d+1) gradient matrix, enclosed in
//!   intervals; if they share a sign and Σ yᵢ φᵢ(0) > 0 rigorously, then Σ yᵢ φᵢ(x) > 0 for
//!   every x, so no admissible state exists. The multipliers stored in the certificate must
//!   match the recomputed ones.
//! * **Limit state**: consistency checks in floating point with stated tolerances
//!   (B λ = 0, λ ≥ 0, Σ λ = 1, L_e ≥ 0, complementarity) — evidence, not proof.
//!
//! This file is the dispatcher [`verify()`]; each file below it imports only files further
//! down, and none imports the solver: the vocabulary (`report.rs`, `statics.rs`, `live.rs`),
//! the proofs and checks (`enclosure.rs`, `farkas.rs`, `joints.rs`, `limit_state.rs`,
//! `mechanism.rs`, `input.rs`), and the claims (`thickness.rs` with `search.rs`; `load.rs`
//! with `load_admissible.rs`, `load_farkas.rs`, `load_unbounded.rs`, `load_search.rs` with
//! `load_limit_state.rs`).

mod enclosure;
mod farkas;
mod input;
mod joints;
mod limit_state;
mod live;
mod load;
mod load_admissible;
mod load_farkas;
mod load_limit_state;
mod load_search;
mod load_unbounded;
mod mechanism;
mod report;
mod search;
mod statics;
mod thickness;

pub use limit_state::LIMIT_STATE_TOL;
pub(crate) use load_admissible::prove_admissible_side;
pub use report::{Rejection, Report};
pub use thickness::prove_safe_only;

use crate::certificate::format::{Certificate, Claim, FORMAT, VERSION};
use input::{check_finite, model_of};
use load::verify_load;
use report::reject;
use thickness::verify_thickness;

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
