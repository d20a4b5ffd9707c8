//! Why a region edit was refused.

use crate::feature::FeatureError;

/// Why a region edit was refused. The messages are sentences for the user.
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
pub enum RegionError {
    /// The reference curve starts off the model.
    #[error("Start the reference curve on the model: it begins where there is no surface.")]
    ReferenceMissesModel,
    /// The reference curve leaves the model.
    #[error("The reference curve leaves the model; draw it on the surface from end to end.")]
    ReferenceLeavesModel,
    /// The reference curve crosses itself or turns back.
    #[error(
        "The reference curve folds back on itself; draw it as one line that does not turn back."
    )]
    ReferenceFolds,
    /// The reference curve's ends land on one vertex.
    #[error("The reference curve is too short for this mesh; draw it across a few triangles.")]
    ReferenceTooShort,
    /// No edge path follows the reference curve.
    #[error(
        "No path on the surface follows the reference curve; keep it on the side of the model you see."
    )]
    NoPath,
    /// The boundary crosses itself.
    #[error("The boundary crosses itself; draw it as one loop around the reference curve.")]
    BoundaryCrosses,
    /// The boundary does not hold the reference curve, or no surface.
    #[error("The boundary must enclose the reference curve and some of the surface around it.")]
    BoundaryMissesReference,
    /// Fewer than two levels, or a level outside [0, 1].
    #[error("The fall-off needs at least two levels, each a weight from 0 to 1.")]
    BadLevels,
    /// An area's lasso has fewer than three points or one that is not a number.
    #[error("Draw an area of the fall-off as a loop of at least three points.")]
    BadArea,
    /// A number of the transform is NaN or infinite.
    #[error("The transform is not a number.")]
    TransformNotFinite,
    /// The transform's last row is not 0, 0, 0, 1.
    #[error("The transform is not affine: its last row must be 0, 0, 0, 1.")]
    TransformNotAffine,
    /// The transform mirrors or flattens.
    #[error("The transform mirrors or flattens the region; it must keep its orientation.")]
    TransformMirrors,
    /// The transform has no real logarithm: it turns by half a turn.
    #[error("The transform turns the region by half a turn; turn it in two steps.")]
    TransformTurnsHalfWay,
    /// No handle, a handle off the curve's 0..1, or two at one place.
    #[error(
        "Handles sit on the reference curve at distinct places from 0 (its start) to 1 (its end), at least one."
    )]
    BadHandles,
    /// The region's faces have no loop around them, so it cannot be laid flat.
    #[error(
        "The region reaches the edge of the surface or holds no triangle, so it cannot be shown flat; draw the boundary on the surface."
    )]
    NotADisc,
    /// Neither a transform, handles nor a profile, or more than one.
    #[error(
        "A region edit moves by one transform, by handles or by a profile: give exactly one of them."
    )]
    MotionUnclear,
    /// The plane across the reference curve there does not cross the region.
    #[error("The region has no cross-section there; slide the plane along the reference curve.")]
    NoProfile,
    /// A profile stroke with fewer than two points or a point that is not a number.
    #[error("Draw the new profile as a line of at least two points.")]
    BadProfileStroke,
}

impl From<FeatureError> for RegionError {
    /// The placement's refusals, in the words of the region's two curves.
    fn from(error: FeatureError) -> Self {
        match error {
            FeatureError::MissesMesh => RegionError::ReferenceMissesModel,
            FeatureError::LeavesMesh => RegionError::ReferenceLeavesModel,
            FeatureError::FoldsBack => RegionError::ReferenceFolds,
            FeatureError::TooShort => RegionError::ReferenceTooShort,
            FeatureError::RegionCrosses => RegionError::BoundaryCrosses,
            FeatureError::NoPath | FeatureError::AmountNotFinite | FeatureError::Deform(_) => {
                RegionError::NoPath
            }
            FeatureError::RegionMissesSketch => RegionError::BoundaryMissesReference,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn messages_are_sentences() {
        for error in [
            RegionError::ReferenceMissesModel,
            RegionError::ReferenceLeavesModel,
            RegionError::ReferenceFolds,
            RegionError::ReferenceTooShort,
            RegionError::NoPath,
            RegionError::BoundaryCrosses,
            RegionError::BoundaryMissesReference,
            RegionError::BadLevels,
            RegionError::BadArea,
            RegionError::TransformNotFinite,
            RegionError::TransformNotAffine,
            RegionError::TransformMirrors,
            RegionError::TransformTurnsHalfWay,
            RegionError::BadHandles,
            RegionError::MotionUnclear,
            RegionError::NotADisc,
            RegionError::NoProfile,
            RegionError::BadProfileStroke,
        ] {
            let text = error.to_string();
            assert!(text.ends_with('.') && text.chars().next().unwrap().is_uppercase());
        }
    }
}
