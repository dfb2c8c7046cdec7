//! The search machinery shared by the thickness problem ([`crate::limit`]) and the
//! friction-only problem ([`crate::friction`]): bracketing the root of the continuum
//! margin, and the candidate active contacts at the bracket's upper end.

pub mod bracket;
pub mod candidates;
pub mod golden;

pub use bracket::{bracket_near, bracket_root, margin_at, Bracket, RootGuess};
pub use candidates::candidates_at;
pub use golden::golden_min;
