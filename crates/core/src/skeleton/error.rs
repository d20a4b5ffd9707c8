//! Why a curve handle or its edit was refused.

/// Why a curve handle or its edit was refused. The messages are sentences for the user.
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
pub enum SkeletonError {
    /// The stroke does not lie over the object.
    #[error("Draw the handle over the object: the stroke misses it.")]
    StrokeMisses,
    /// Fewer than two control points were asked for.
    #[error("A curve handle needs at least two control points.")]
    TooFewPoints,
    /// The stroke is too short to place its control points apart.
    #[error("The stroke is too short for a handle; draw it along the part to move.")]
    StrokeTooShort,
    /// Nothing of the object lies between the handle's ends.
    #[error("No part of the object lies along the handle.")]
    NothingUnder,
    /// A twist, scale or move that is not a number, or a scale of zero or less.
    #[error("A handle's twist, scale or move must be a number, and a scale more than zero.")]
    BadAmount,
    /// The control point asked for does not exist.
    #[error("That handle has no control point {0}.")]
    NoSuchPoint(usize),
}
