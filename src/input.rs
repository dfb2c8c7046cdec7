//! Bad input: the one error type of the crate and the range checks that build it, below
//! every module that validates a number.

use thiserror::Error;

/// Bad input: the only errors of this crate. Each message names the argument,
/// its valid range and the value received.
#[derive(Debug, Error, Clone, PartialEq)]
pub enum InputError {
    /// A numeric argument outside its valid range (or NaN).
    #[error("invalid value for {arg}: {value} (valid range: {range})")]
    OutOfRange {
        /// The argument, as the user spells it (e.g. `--mu`).
        arg: &'static str,
        /// The value received, formatted.
        value: String,
        /// The valid range, in words.
        range: String,
    },
    /// Arguments that are individually valid but inconsistent.
    #[error("invalid {arg}: {reason}")]
    Inconsistent {
        /// The argument(s) concerned.
        arg: &'static str,
        /// What is wrong.
        reason: String,
    },
}

/// Formats a number for messages: plain for ordinary magnitudes, scientific otherwise.
pub fn fmt_value(v: f64) -> String {
    if v != 0.0 && v.is_finite() && (v.abs() < 1e-4 || v.abs() >= 1e7) {
        format!("{v:e}")
    } else {
        format!("{v}")
    }
}

pub(crate) fn check_finite(arg: &'static str, value: f64, range: &str) -> Result<(), InputError> {
    if value.is_finite() {
        Ok(())
    } else {
        Err(InputError::OutOfRange {
            arg,
            value: fmt_value(value),
            range: range.to_string(),
        })
    }
}

/// A finite positive number (a length, a width, a unit weight), or the error naming `arg`.
pub fn check_positive(arg: &'static str, v: f64) -> Result<f64, InputError> {
    check_finite_from(arg, v, v > 0.0, "a finite number > 0")
}

/// A finite number ≥ 0 (a weight ratio or depth that may be zero), or the error naming `arg`.
pub fn check_non_negative(arg: &'static str, v: f64) -> Result<f64, InputError> {
    check_finite_from(arg, v, v >= 0.0, "a finite number >= 0")
}

fn check_finite_from(arg: &'static str, v: f64, ok: bool, range: &str) -> Result<f64, InputError> {
    if v.is_finite() && ok {
        Ok(v)
    } else {
        Err(InputError::OutOfRange {
            arg,
            value: fmt_value(v),
            range: range.into(),
        })
    }
}
