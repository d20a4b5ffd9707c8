//! Why an extrusion was refused.

use super::super::add_curve::AddCurveError;
use crate::mesh::MeshError;

/// Why a base loop and a silhouette did not grow a limb. The messages are sentences for the
/// user.
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
pub enum ExtrudeError {
    /// The base loop could not be put on the surface.
    #[error("{0}")]
    Base(AddCurveError),
    /// The shape has holes in its surface.
    #[error("Only a closed shape can be extruded.")]
    NotClosed,
    /// The silhouette starts or ends far from the base loop, or at one place on it.
    #[error("Start the line near one side of the loop and end it near the other side.")]
    NotNearBase,
    /// The limb's tip would lie inside the shape.
    #[error("The limb would grow into the shape; draw its outline outside it.")]
    Inward,
    /// The limb would pass through the rest of the surface, or the result would not be a
    /// closed manifold mesh.
    #[error(
        "The limb would pass through the shape; draw the loop where it should leave the surface, nearer the outline."
    )]
    Broken(Option<MeshError>),
}
