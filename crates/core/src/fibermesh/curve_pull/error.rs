//! Why a pull failed.

use crate::solve::SolveError;

/// Why a pull failed. The messages are sentences for the user.
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
pub enum PullError {
    /// The drag target is not a finite point.
    #[error(
        "The curve cannot be pulled there from this view; turn the view so the curve faces you, then pull."
    )]
    BadTarget,
    /// The output buffer does not have one entry per node (a bug).
    #[error("The curve network has {expected} points, but {found} were given.")]
    WrongLength {
        /// Nodes of the network.
        expected: usize,
        /// Length of the buffer.
        found: usize,
    },
    /// A solve failed.
    #[error("The shape could not follow that pull; pull a shorter way.")]
    Solve(#[from] SolveError),
}
