//! Why two loops did not make a tunnel.

use super::super::add_curve::AddCurveError;
use crate::mesh::MeshError;

/// Why two loops did not make a tunnel. The messages are sentences for the user.
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
pub enum TunnelError {
    /// A loop could not be put on the surface.
    #[error("{0}")]
    Loop(AddCurveError),
    /// The shape has holes in its surface.
    #[error("Only a closed shape can be tunnelled through.")]
    NotClosed,
    /// The loops touch, cross, or one lies inside the other.
    #[error("The two loops must not touch; draw the second one on the other side.")]
    LoopsTouch,
    /// The straight way from one loop to the other leaves the shape.
    #[error(
        "The two loops do not face each other through the shape; draw the second one on the opposite side."
    )]
    NotFacing,
    /// The tube would pass through the rest of the surface, or the result would not be a
    /// closed manifold mesh.
    #[error("The tunnel would leave a broken surface; try other loops.")]
    Broken(Option<MeshError>),
}
