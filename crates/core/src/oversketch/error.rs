//! Why an over-sketch was refused.

use crate::deform::DeformError;

/// Why an over-sketch was refused. The messages are sentences for the user.
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
pub enum OversketchError {
    /// No silhouette piece has both ends near the stroke's ends.
    #[error(
        "That stroke does not follow an outline of a model; draw along the edge you want to change."
    )]
    NoMatch,
    /// A piece matched, but it is a guess (far ends or a close alternative).
    #[error(
        "It is unclear which part of the outline that stroke redraws; start and end it closer to the outline."
    )]
    LowConfidence,
    /// A manual handle's silhouette is no longer in sight, or its curve misses the mesh.
    #[error("The picked outline or curve is no longer on the model as seen; pick it again.")]
    HandleLost,
    /// A part ROI was asked for, but the handle's thickness sets no part apart.
    #[error(
        "No part of the model stands out around that outline (an ear, a finger); bend it with the region near the stroke instead."
    )]
    NoPart,
    /// The matched handle could not drive a deformation.
    #[error("The shape could not be bent to follow that stroke.")]
    Deform(#[from] DeformError),
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn messages_are_sentences() {
        for error in [
            OversketchError::NoMatch,
            OversketchError::LowConfidence,
            OversketchError::HandleLost,
        ] {
            assert!(error.to_string().ends_with('.'));
        }
        let deform = OversketchError::from(DeformError::DependentHandles);
        assert!(deform.to_string().ends_with('.'));
    }
}
