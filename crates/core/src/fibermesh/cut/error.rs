//! Why a stroke did not cut a shape.

use crate::mesh::MeshError;

/// Why a stroke did not cut a shape. The messages are sentences for the user.
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
pub enum CutError {
    /// The stroke starts or ends on the shape, misses it, or leaves nothing on one side.
    #[error("To cut, draw across the shape from beside it to beside it.")]
    DoesNotCross,
    /// The shape has holes in its surface, so it has no inside to close.
    #[error("Only a closed shape can be cut.")]
    NotClosed,
    /// The cut section, laid flat, crosses itself (a stroke that bends back on itself
    /// through the shape).
    #[error("The cut section would fold over itself; cut with a straighter stroke.")]
    FoldedSection,
    /// One loop of the cut lies inside another (a ring-shaped section, as across a torus).
    #[error("The cut section would be a ring; cut elsewhere.")]
    RingSection,
    /// The cut section is too thin to mesh.
    #[error("The cut section is too thin to close; cut where the shape is thicker.")]
    ThinSection,
    /// A cap would pass through the rest of the surface (a section that runs into a part
    /// of the shape behind it).
    #[error("The cut's cap would pass through the shape; cut elsewhere.")]
    CapCrosses,
    /// The result would not be a closed manifold mesh (a bug or a degenerate cut).
    #[error("The cut would leave a broken surface ({0}); try another stroke.")]
    Broken(MeshError),
}
