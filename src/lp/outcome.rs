//! What an LP returns instead of a solution: the vocabulary the dispatcher and every back
//! end share.

/// Why an LP returned no solution.
#[derive(Debug, Clone, PartialEq)]
pub enum LpOutcome {
    /// The LP is infeasible (normal rejection path of the enumeration).
    Infeasible,
    /// The back end reported anything else (unbounded, numerical failure): the message.
    Failed(String),
}
