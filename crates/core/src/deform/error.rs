//! Why a Laplacian edit could not be set up.

use crate::solve::SolveError;

/// Why a [`LaplacianEdit`](super::LaplacianEdit) could not be set up.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum DeformError {
    /// The ROI mask does not have one flag per mesh vertex.
    #[error("The ROI has {found} flags, but the mesh has {expected} vertices.")]
    RoiLength {
        /// Number of mesh vertices.
        expected: usize,
        /// Length of the mask given.
        found: usize,
    },
    /// A handle names a vertex that does not exist, or its weights are not finite or do not
    /// sum to one.
    #[error("Handle {index} is not a point of the mesh.")]
    InvalidHandle {
        /// Index of the handle.
        index: usize,
    },
    /// A handle does not touch the ROI, so it cannot move.
    #[error("Handle {index} lies outside the region that may move.")]
    HandleOutsideRoi {
        /// Index of the handle.
        index: usize,
    },
    /// Two exact handles sit on the same vertex.
    #[error("Handle {index} sits on a vertex another handle already holds.")]
    ConflictingHandles {
        /// Index of the later handle.
        index: usize,
    },
    /// Exact handles that cannot all be met, such as three points on one edge.
    #[error("Some handles constrain the same vertices too often to be met exactly.")]
    DependentHandles,
    /// A soft handle weight that is not a positive number.
    #[error("The handle weight must be a positive number.")]
    InvalidWeight,
    /// The system could not be factored.
    #[error(transparent)]
    Solve(#[from] SolveError),
}
