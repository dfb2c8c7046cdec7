//! Certificates: checkable evidence for η*(μ), and for the largest multiplier λ_static of a
//! live load ([`certify_load()`]), that anyone can re-check with [`verify()`] (no LP, no
//! solver).
//!
//! # Format (version 1)
//! A JSON object (the serde types of [`format`](mod@format) are the schema; `null` stands for +∞
//! where noted). Closed sets are enums and anything else is rejected **when read**, with
//! an error naming the field, the unknown value and the expected ones:
//! `kind` ∈ {`hinge_extrados`, `hinge_intrados`, `slide_plus`, `slide_minus`},
//! `at` ∈ {`springing`, `interior`}, `weight` ∈ {`centreline`, `centroid`}.
//!
//! | key | meaning |
//! |---|---|
//! | `format`, `version` | `"arch-enum-certificate"`, `1` |
//! | `tool` | the producing tool and version |
//! | `arch` | `beta_right` < `beta_left` (radians), `weight`, `joint_angles`: `null` for a continuous arch, else strictly increasing from `beta_right` to `beta_left` |
//! | `mu` | friction coefficient > 0, `null` = ∞ (then only the hinge kinds exist) |
//! | `claim` | `least_thickness` or `no_equilibrium` |
//! | `safe` | `{eta, x: [h, v, w]}`: a state admissible at η_hi over the whole arch (upper bound); absent for `no_equilibrium` |
//! | `collapse` | `{eta, joints: [{beta, kind, y}]}`: d + 1 contacts whose non-negative Farkas combination rules out every state at η_lo (lower bound); `eta` null for the friction-only problem (d = 2, sliding kinds only) |
//! | `limit_state` | `{eta, x, pattern: [{beta, kind, at}], rates, complementarity_residual}`: the limit state and a mechanism on its pattern, the pattern strictly increasing in (β, kind); absent for `no_equilibrium` |
//! | `gap`, `gap_relative` | η_hi − η_lo and (η_hi − η_lo)/η_hi |
//! | `search` | optional (absent where the limit-state search was not completed, unless the states it found decide `unique = false`: method `found`): `{method, events, mechanism_at_eta, unique, least_state, limit_states_above, no_mechanism, ridge}`; `method` ∈ {`sweep`, `hinges_only`, `refined`, `ridge`, `found`}; `least_state` and each `no_mechanism` entry are `{eta, x, pattern, farkas: [{drop, y, z, u}]}` |
//!
//! **Load certificates** (`claim` ∈ {`largest_multiplier`, `unbounded_multiplier`,
//! `no_equilibrium`} with a `load` section) carry none of `safe`, `collapse`, `limit_state`,
//! `search`, and instead:
//!
//! | key | meaning |
//! |---|---|
//! | `load` | `{eta, kind, towards, beta}`: η, `kind` ∈ {`horizontal`, `point`}, `towards` ∈ {`right`, `left`} (horizontal only), `beta` (point only) |
//! | `multiplier` | `admissible: {lambda, x}` (a state admissible at λ_lo), `infeasible: {lambda, joints: [{beta, kind, side, y}], lambda_row}` (Farkas at λ_hi; `lambda` null for `no_equilibrium`: rows in (h, v, w, λ) and `lambda_row` the multiplier of −λ ≤ 0), `transfer` ∈ {`right`, `left`} or `recession: {lambda, x}` (`unbounded_multiplier`) |
//! | `gap`, `gap_relative` | λ_hi − λ_lo and (λ_hi − λ_lo)/λ_hi |
//! | `load_search` | `{method, events, lambda_min, mechanism_at_static, unique, lambda, limit_states, static_state, no_mechanism}`; `method` ∈ {`sweep`, `associative`, `refined`, `found`} (`found`: the survey did not settle; the states it found, `unique` false and `lambda` null, the list not claimed complete); limit states `{lambda, x, pattern, rates, live_power, continuum}`; `static_state` and `no_mechanism` entries `{lambda, x, pattern, farkas: [{drop, y, z, u, v}]}` |
//!
//! `side` ∈ {`before`, `after`} is given exactly at the point load's own angle (the section
//! just before the loaded point, or just after it), on joints and pattern contacts alike.
//!
//! Every number must be finite; every joint of `collapse` and `pattern` must lie in
//! [β_R, β_L], at a listed joint of a discrete arch, with a kind that exists at `mu`;
//! `at` must be `springing` exactly at β_R and β_L. [`verify()`] rejects anything else,
//! saying what was wrong, before it proves anything.
//!
//! # What is proved
//! [`verify()`] *proves*, in interval arithmetic with outward rounding, that the safe
//! state is admissible at η_hi over the whole continuum (or at every listed joint) and
//! that no state is admissible at η_lo: so the least thickness with a statically
//! admissible state lies in [η_lo, η_hi] (for `no_equilibrium`: no (h, v) satisfies the
//! friction conditions at the listed joints, so no thickness stands). The limit state is
//! only *checked* in floating point ([`verify::LIMIT_STATE_TOL`]): evidence, not proof.
//! The [`Report`] names the arch, μ and the bracket. With a `search` section the least
//! thickness is η_s (the bracket is around the least admissible state, which need not
//! carry a mechanism) and [`verify()`] also re-checks the limit-state list
//! (`verify/search.rs`): it *proves* that each state listed without a mechanism has none
//! (Farkas alternative of the kinematic LP, interval arithmetic) and, at μ = ∞, that the
//! safe state lies strictly inside P(η_hi) (so no limit state lies above); it *checks* the
//! listed limit states and active sets in floating point, and does not re-prove the
//! completeness of the sweep or of the refinement.
//!
//! For a load certificate [`verify()`] *proves* the admissible state at λ_lo (at every joint
//! and both sides of a loaded section, or over the continuum) and the Farkas certificate at
//! λ_hi, so λ_lo ≤ λ_static < λ_hi (the admissible (x, λ) are convex); or that no state exists
//! at any λ ≥ 0; or that a state stays admissible along a transfer of the point load to a
//! springing or a recession direction (λ_static unbounded). With a `load_search` section it
//! *proves* each listed state without a mechanism (Farkas alternative of the kinematic LP
//! with the live power) and, at μ = ∞, that no limit state lies below λ_lo (virtual work);
//! it *checks* the limit states in floating point and does not re-prove the completeness of
//! the sweep (docs/loads.md).
//!
//! # How certificates are built
//! `certify` builds the two sides around the exact limit state: the safe state is the
//! limit state moved into the interior of the admissible set at η_hi = η*(1 + g/2) by a
//! small LP on its active contacts (rows scaled by 1/(η_hi − η*) so that HiGHS works with
//! O(1) numbers); the Farkas contacts are 4-subsets of the active contacts at η_lo ≈
//! η*(1 − g/2) (raised by ulps until (η_hi − η_lo)/η_hi ≤ g in floating point), with
//! interior tangencies also split into chords β ± δ, chosen by their float cofactors and
//! then proved by the verifier. If a side cannot be proved at the requested relative gap
//! g, the gap is widened tenfold (up to 1e-4) and the best certificate is returned;
//! [`Certificate::delivers_gap`] says whether the request was met (the command line then
//! reports `gap_not_reached` and exits 1).
//!
//! # Layout
//! [`format`](mod@format) and [`interval`] are the vocabulary. [`verify`](mod@verify)
//! imports only them (and the vocabulary of arch, contacts and load that the format
//! re-exports), never the
//! solver; [`certify`](mod@certify) imports the solver and the verifier. In each folder
//! `mod.rs` is the dispatcher and every file imports only files below it, never one that
//! imports it (`tests/it/layering.rs`).

pub mod certify;
pub mod format;
pub mod interval;
pub mod verify;

pub use certify::{certify, certify_found, certify_load};
pub use format::*;
pub use verify::{distinct_in_lambda, verify, Rejection, Report};
