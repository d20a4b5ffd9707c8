//! Why a model could not be made symmetric.

/// Why a symmetry could not be made or kept. The messages are sentences for the user.
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
pub enum SymmetryError {
    /// Symmetrize was asked of a model the plane does not cut.
    #[error(
        "The symmetry plane does not cut this model, so there is no half to mirror; move the plane through it first."
    )]
    PlaneMissesModel,
    /// The kept half and its mirror image do not join into one surface.
    #[error(
        "The half kept and its mirror image do not join into one surface along the plane (the model touches the plane without crossing it); move the plane a little."
    )]
    JoinFailed,
    /// The surface folds over itself where it crosses the plane.
    #[error(
        "The surface folds over itself where it crosses the symmetry plane, so it cannot be mirrored there; undo and make a smaller change."
    )]
    Folded,
}
