//! Why a sparse solve failed.

/// Why a sparse solve failed.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum SolveError {
    /// A zero or negative pivot: some free unknowns are not determined by the equations.
    #[error(
        "The equations do not determine every free unknown (the system is not positive definite); \
         fix at least one vertex in each connected part."
    )]
    NotPositiveDefinite,
    /// A pivot vanished up to round-off: some free unknowns are determined only by noise.
    #[error(
        "The equations barely determine some free unknowns (the system is numerically singular); \
         fix at least one vertex in each connected part."
    )]
    Singular,
    /// An input has the wrong length.
    #[error("The {what} has length {found}, but {expected} was expected.")]
    DimensionMismatch {
        /// Which input.
        what: &'static str,
        /// The length the system needs.
        expected: usize,
        /// The length given.
        found: usize,
    },
    /// [`Prefactored::refactor_values`](super::Prefactored::refactor_values) got a matrix with another shape or pattern.
    #[error("The matrix has a different sparsity pattern from the one that was factored.")]
    PatternMismatch,
    /// The matrix holds NaN or an infinity.
    #[error("The matrix contains a value that is not a finite number.")]
    NonFiniteValue,
    /// An iteration built on the solves ran away: its result was not finite.
    #[error("The optimization diverged; the change is too large to follow in one step.")]
    Diverged,
    /// faer could not factor for another reason (out of memory, index overflow).
    #[error("The sparse factorization failed: {0}.")]
    Factorization(String),
}

impl SolveError {
    /// Whether the equations leave some free unknown undetermined (exactly or numerically):
    /// [`SolveError::NotPositiveDefinite`] or [`SolveError::Singular`]. The usual fix is to fix
    /// a vertex or add a soft constraint in each connected part.
    pub fn is_underdetermined(&self) -> bool {
        matches!(self, SolveError::NotPositiveDefinite | SolveError::Singular)
    }
}
