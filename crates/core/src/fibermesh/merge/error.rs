//! Why two models were not merged.

use crate::mesh::MeshError;

/// Why two shapes were not merged. The messages are sentences for the user.
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
pub enum MergeError {
    /// The op names one model twice.
    #[error("Pick two different models to merge.")]
    SameModel,
    /// One of the shapes has holes in its surface.
    #[error("Only closed shapes can be merged.")]
    NotClosed,
    /// The shapes do not overlap.
    #[error("The two models do not touch; move one into the other first.")]
    NotTouching,
    /// One shape lies wholly inside the other.
    #[error("One model lies inside the other; move it so that part of it sticks out.")]
    Inside,
    /// The surfaces meet in a way that leaves no closed manifold (they only graze, or the
    /// seam would pass through a surface).
    #[error("The models meet too thinly to be joined; push one further into the other.")]
    Broken(Option<MeshError>),
}
