//! Why a computation reached no decision: a status inside a result (what the method could
//! not establish), never an answer and never bad input (that is [`crate::arch::InputError`]).
//! The variant names the step that could not decide; the text says what happened, in the
//! words every report prints.

use std::fmt;

/// Why no decision was reached.
#[derive(Debug, Clone, PartialEq, Eq)]
pub enum Undecided {
    /// The LP back end failed on an LP (its own message).
    Lp(String),
    /// Newton on a pattern gave no root that passes the checks, or no pattern could be
    /// refined.
    Newton(String),
    /// A budget of this version was reached: too many joints, events or rounds (the text
    /// names the setting).
    Budget(String),
    /// A continuous arch's list from two discretisations could not be established: a
    /// discretisation failed, or the two lists differ.
    Discretisation(String),
    /// A quantity lies below what the method resolves in double precision (roots too
    /// close, a thickness too small, a degenerate geometry), or the search has no state
    /// to start from.
    Resolution(String),
    /// A case the method does not cover yet.
    NotCovered(String),
}

impl Undecided {
    /// An LP the back end failed on, with the back end's message.
    pub fn back_end(message: impl fmt::Display) -> Undecided {
        Undecided::Lp(format!("LP back end: {message}"))
    }

    /// The text.
    pub fn text(&self) -> &str {
        match self {
            Undecided::Lp(t)
            | Undecided::Newton(t)
            | Undecided::Budget(t)
            | Undecided::Discretisation(t)
            | Undecided::Resolution(t)
            | Undecided::NotCovered(t) => t,
        }
    }

    /// The same failure, its text rewritten by `f` (context added around it).
    pub fn map_text(self, f: impl FnOnce(String) -> String) -> Undecided {
        match self {
            Undecided::Lp(t) => Undecided::Lp(f(t)),
            Undecided::Newton(t) => Undecided::Newton(f(t)),
            Undecided::Budget(t) => Undecided::Budget(f(t)),
            Undecided::Discretisation(t) => Undecided::Discretisation(f(t)),
            Undecided::Resolution(t) => Undecided::Resolution(f(t)),
            Undecided::NotCovered(t) => Undecided::NotCovered(f(t)),
        }
    }
}

impl fmt::Display for Undecided {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.text())
    }
}

impl std::error::Error for Undecided {}
