//! Mirror symmetry: which vertices pair up across a plane, models made symmetric, and the
//! mirror image of a model.
//!
//! A model is *symmetric* about a plane when every vertex has a partner at its mirror image
//! (to [`EXACT`] of its bounding-box diagonal); two models are *mirror twins* when one is the
//! other reflected, vertex for vertex. Nothing is stored to say so: the pairing is found
//! again from the positions ([`partners`], [`are_twins`]), so no later op, undo or file can
//! leave a stale table behind, and an edit made with symmetry off simply ends it.
//!
//! Every op made with symmetry on ends with the models it changed made exact again
//! ([`mirror_positions`], [`symmetrized`], [`mirrored_model`]), so the pairing holds to
//! rounding after any sequence of ops.

mod curves;
mod error;
mod grid;
mod mirror_model;
mod outline;
mod pairing;
mod symmetrize;

pub use curves::{Place, mirrored_curves};
pub use error::SymmetryError;
pub use mirror_model::mirrored_model;
pub use outline::symmetric_outline;
pub use pairing::{
    Keep, are_twins, are_twins_within, changed_side, mirror_positions, moved_side, partners,
    partners_within, side_of_model,
};
pub use symmetrize::symmetrized;

/// How close, relative to a model's bounding-box diagonal, a vertex must be to its partner's
/// mirror image for the two to pair up.
pub const EXACT: f64 = 1e-9;

/// A model's bounding-box diagonal (1 for an empty or single-point one, so tolerances
/// scaled by it stay positive).
pub fn diagonal(mesh: &crate::mesh::Mesh) -> f64 {
    mesh.bounding_box()
        .map(|(lo, hi)| (hi - lo).length())
        .filter(|d| *d > 0.0)
        .unwrap_or(1.0)
}
