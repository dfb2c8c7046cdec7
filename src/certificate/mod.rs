//! Certificates: checkable evidence for η*(μ) that anyone can re-check with
//! [`verify()`] (no LP, no solver).
//!
//! # Format (version 1)
//! A JSON object (this serde type is the schema; `null` stands for +∞ where noted):
//!
//! | key | meaning |
//! |---|---|
//! | `format`, `version` | `"arch-enum-certificate"`, `1` |
//! | `tool` | the producing tool and version |
//! | `arch` | `beta_right`, `beta_left` (radians), `weight` (`centreline`/`centroid`), `joint_angles` (null: continuous) |
//! | `mu` | friction coefficient, `null` = ∞ |
//! | `claim` | `least_thickness` or `no_equilibrium` |
//! | `safe` | `{eta, x: [h, v, w]}`: a state admissible at η_hi over the whole arch (upper bound) |
//! | `collapse` | `{eta, joints: [{beta, kind, y}]}`: d + 1 contacts whose non-negative Farkas combination rules out every state at η_lo (lower bound); `eta` null for the friction-only problem (d = 2) |
//! | `limit_state` | `{eta, x, pattern: [{beta, kind, at}], rates}`: the limit state and a mechanism on its pattern |
//! | `gap`, `gap_relative` | η_hi − η_lo and (η_hi − η_lo)/η_hi |
//!
//! `certify` builds the two sides around the exact limit state: the safe state is the
//! limit state moved into the interior of the admissible set at η_hi = η*(1 + g/2) by a
//! small LP on its active contacts (rows scaled by 1/(η_hi − η*) so that HiGHS works with
//! O(1) numbers); the Farkas contacts are 4-subsets of the active contacts at η_lo =
//! η*(1 − g/2), with interior tangencies also split into chords β ± δ, chosen by their
//! float cofactors and then proved by the verifier. If a side cannot be proved at the
//! requested relative gap g, the gap is widened tenfold (up to 1e-4) and the achieved gap
//! is what the certificate states.

pub mod certify;
pub mod format;
pub mod interval;
pub mod verify;

pub use certify::certify;
pub use format::*;
pub use verify::{verify, Rejection, Report};
