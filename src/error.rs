//! The library's error type; each variant maps to one C status code.

use std::fmt;

/// Why a constructor or a solve failed. The message names the violated condition.
#[derive(Clone, Debug, PartialEq)]
pub enum Error {
    /// An argument is NaN, infinite, negative or out of its documented range.
    InvalidArgument(String),
    /// The elastic constants do not give a positive definite in-plane energy.
    InadmissibleMaterial(String),
    /// An iterative method stopped without converging.
    NoConvergence(String),
    /// The method ran, but its error estimate exceeds the requested tolerance.
    ToleranceNotMet {
        /// The error estimate reached.
        estimate: f64,
        /// The tolerance asked for.
        tolerance: f64,
        /// What limited the accuracy.
        detail: String,
    },
    /// The solver found the stick-edge root of the assumed form, but that solution violates
    /// an admissibility condition (p < 0 somewhere in the contact, |q| > mu p on the stick
    /// zone, or slip against the friction): no solution of this form exists for this input.
    NoAdmissibleSolution(String),
    /// A bug: an internal invariant failed (reported as ORTHOSLIP_ERROR_INTERNAL; a panic
    /// caught at the C ABI is ORTHOSLIP_ERROR_PANIC instead).
    Internal(String),
}

impl fmt::Display for Error {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Error::InvalidArgument(m) => write!(f, "invalid argument: {m}"),
            Error::InadmissibleMaterial(m) => write!(f, "inadmissible material: {m}"),
            Error::NoConvergence(m) => write!(f, "no convergence: {m}"),
            Error::ToleranceNotMet {
                estimate,
                tolerance,
                detail,
            } => write!(
                f,
                "tolerance not met: error estimate {estimate:.3e} > tolerance {tolerance:.3e} ({detail})"
            ),
            Error::NoAdmissibleSolution(m) => write!(f, "no admissible solution: {m}"),
            Error::Internal(m) => write!(f, "internal error: {m}"),
        }
    }
}

impl std::error::Error for Error {}

impl Error {
    /// The same failure with its message (a tolerance miss: its detail) rewritten by `say`,
    /// for a caller that adds where it happened; an inadmissible material and an internal
    /// error keep theirs.
    pub(crate) fn reworded(self, say: impl FnOnce(String) -> String) -> Error {
        match self {
            Error::InvalidArgument(m) => Error::InvalidArgument(say(m)),
            Error::NoConvergence(m) => Error::NoConvergence(say(m)),
            Error::NoAdmissibleSolution(m) => Error::NoAdmissibleSolution(say(m)),
            Error::ToleranceNotMet {
                estimate,
                tolerance,
                detail,
            } => Error::ToleranceNotMet {
                estimate,
                tolerance,
                detail: say(detail),
            },
            other => other,
        }
    }
}

/// Shorthand for results of this crate.
pub type Result<T> = std::result::Result<T, Error>;
