//! Why a feature sketch was refused.

use crate::deform::DeformError;

/// Why a feature sketch was refused. The messages are sentences for the user.
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
pub enum FeatureError {
    /// The sketch's first point is not over the model.
    #[error("Start the sketch on the model: it begins where there is no surface.")]
    MissesMesh,
    /// Some point of the sketch is not over the model.
    #[error("The sketch leaves the model; draw it on the surface from end to end.")]
    LeavesMesh,
    /// The sketch crosses itself or turns back on itself.
    #[error("The sketch folds back on itself; draw it as one line that does not turn back.")]
    FoldsBack,
    /// The sketch's ends land on the same vertex.
    #[error("The sketch is too short for this mesh; draw it across a few triangles.")]
    TooShort,
    /// No edge path under the sketch connects its ends (it crosses a hole or a silhouette).
    #[error(
        "No path on the surface follows that sketch; keep it on the side of the model you see."
    )]
    NoPath,
    /// The region lasso crosses itself.
    #[error("The region crosses itself; draw it as one loop.")]
    RegionCrosses,
    /// The region lasso holds no vertex, or not the sketch.
    #[error("The region must hold the sketch and some of the surface around it.")]
    RegionMissesSketch,
    /// The amount is NaN or infinite.
    #[error("The amount of the feature is not a number.")]
    AmountNotFinite,
    /// The region could not be solved.
    #[error(
        "The surface around the sketch could not take that feature; draw it shorter or on a smoother part."
    )]
    Deform(#[from] DeformError),
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn messages_are_sentences() {
        for error in [
            FeatureError::MissesMesh,
            FeatureError::LeavesMesh,
            FeatureError::FoldsBack,
            FeatureError::TooShort,
            FeatureError::NoPath,
            FeatureError::RegionCrosses,
            FeatureError::RegionMissesSketch,
            FeatureError::AmountNotFinite,
        ] {
            let text = error.to_string();
            assert!(text.ends_with('.') && text.chars().next().unwrap().is_uppercase());
        }
    }
}
