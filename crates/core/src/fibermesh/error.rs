//! Why a stroke did not become a shape.

use crate::curve::StrokeError;
use crate::mesh::MeshError;
use crate::solve::SolveError;

/// Why a stroke did not become a shape. The messages are sentences for the user.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum CreateError {
    /// The stroke itself is unusable (too few points, not finite, too short).
    #[error("{0}")]
    Stroke(StrokeError),
    /// The ends of the stroke are far apart.
    #[error("Close the outline: end the stroke near where it started.")]
    NotClosed,
    /// The outline crosses itself other than by overshooting its start.
    #[error("That outline crosses itself; draw it without loops.")]
    SelfCrossing,
    /// The outline encloses (almost) no area.
    #[error("The outline encloses almost no area; draw a rounder shape.")]
    NoArea,
    /// The outline is too thin somewhere for the mesh resolution.
    #[error("The outline is too thin in places to build a surface; draw it wider.")]
    TooThin,
    /// The camera is degenerate or the stroke misses the drawing plane.
    #[error("The stroke cannot be placed in the scene from this view; reset the camera.")]
    BadView,
    /// A sparse solve failed.
    #[error("The surface could not be computed for that outline; draw a simpler, rounder one.")]
    Solve(SolveError),
    /// The stitched mesh is broken (a bug).
    #[error("The surface mesh could not be built: {0}")]
    Mesh(MeshError),
}
