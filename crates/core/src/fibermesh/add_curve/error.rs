//! Why a stroke did not become a curve.

/// Why a stroke did not become a curve. The messages are sentences for the user.
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
pub enum AddCurveError {
    /// No two consecutive stroke samples hit the shape.
    #[error("Draw the curve on the shape: the stroke misses it.")]
    Misses,
    /// Part of a closed stroke misses the shape or jumps between parts of it.
    #[error("A closed curve must lie on the shape where you see it; draw it inside the outline.")]
    ClosedOffSurface,
    /// A cross-section stroke starts or ends on the shape, or never crosses it, or its
    /// cut holds no closed loop.
    #[error(
        "That stroke does not cross the shape from side to side; start and end it beside the shape."
    )]
    DoesNotCross,
    /// The walk along the stroke lost its way, or the result is not a valid mesh.
    #[error("The curve could not be placed on the surface; draw it again a little further inside.")]
    NotPlaced,
}
