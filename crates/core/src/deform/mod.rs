//! Detail-preserving Laplacian editing, the engine behind over-sketching.
//!
//! The method is Nealen's editing framework (dissertation Ch. 4, §4.2; Nealen et al. 2005):
//! a lasso ROI moves, every other vertex stays put, and the ROI minimises
//! `Σ_i ||(L x)_i - δ_i||²` over the Laplacian coordinates of the ROI and its first anchor
//! ring (Eq. 4.1) plus handle constraints, with normalised cotangent weights (Eqs. 4.3,
//! 4.4); see `region.rs` for the anchor rings. Handles are
//! vertices or points inside edges and faces, constrained through their barycentric
//! combination (Eq. 4.2), either exactly or by weighted rows ([`HandleFit`]). The least
//! squares go through [`Prefactored`](crate::solve::Prefactored): factor once when the ROI or
//! handle set changes, back-substitute on every drag frame.
//!
//! **Rotations.** A linear Laplacian edit keeps the details' rest orientation, so a bent
//! tube's bumps shear sideways instead of turning with the surface (64 degrees off the
//! normal in `tests/suite/deform.rs`). [`Rotations::Arap`] rotates each rest Laplacian coordinate
//! by a per-vertex rotation, `δ_i → R_i δ_i`, found by as-rigid-as-possible local steps
//! (Sorkine & Alexa 2007): alternately fit `R_i` to vertex `i`'s cotangent-weighted
//! one-ring (a 3x3 Procrustes problem, `rotation.rs`) and re-solve. This is rotation
//! estimation for Laplacian coordinates in the manner of Lipman et al. 2004 and Au et al.'s
//! dual Laplacian editing (2006), with ARAP's local step. Why this one:
//! - Each iteration reuses the same factorization (only the right-hand side changes): one
//!   back-substitution plus a 3x3 fit per vertex, interactive on 5k-vertex ROIs. Methods that
//!   fold rotations into the matrix (Sorkine et al. 2004's linearised similarities) must
//!   refactor, and linearised rotations break down near 90 degrees.
//! - It keeps Nealen's bi-Laplacian global step. We tried ARAP's own global step (a
//!   membrane energy): dragging a silhouette curve outward then gives a cone with a crease
//!   along the curve (the largest dihedral angle grows by 36 degrees, against 16 here),
//!   where the user drew a rounded outline.
//! - It is stable: the rotated coordinates of a vertex depend only on its own rotation.
//!   Averaging neighbouring rotations into `δ_i` (ARAP's right-hand side) with this global
//!   step drifted without bound (bump tilts 6 degrees after 8 iterations, 32 after 128);
//!   this form settles (5.9 degrees after 2 iterations, 5.3 after 4, 5.8 after 128), and reaches the same answer
//!   from the linear solution as a start, only slower.
//! - Starting guess: plain ARAP starting from the linear solve propagates rotations slowly
//!   (over 100 iterations for the 90 degree bend). We start instead from the handles'
//!   best-fit rotation, spread over the ROI by how far each vertex follows the handles in
//!   the linear edit (the same factorization with unit handle displacements, computed in
//!   `new`). Then [`EditParams::DEFAULT_ARAP_ITERATIONS`] iterations suffice.
//! - SEED (Bao & Howard 2014, §5.1) found Nealen-style orientation adjustment 4 to 8 times
//!   slower than the plain solve and made it optional; here [`Rotations::None`] is the plain
//!   solve and each rotation iteration costs one more back-substitution.
//!
//! Limits:
//! - Laplacian coordinates mix detail with base curvature: where an edit bends the base
//!   strongly, bumps there grow or shrink (about 10% in the pull test). Multiresolution
//!   editing would separate them.
//! - One best-fit rotation starts all vertices; handles that turn in opposite directions
//!   start from a poor guess and need more iterations.
//! - Stretching only moves vertices: large stretches leave long thin triangles (SEED §5.2
//!   remeshes before and after).
//! - Exact handles inside edges and faces cost a dense `n × k` block (`exact_handles.rs`),
//!   fine for a few hundred silhouette points.

mod error;
mod exact_handles;
mod handle;
mod laplacian_edit;
mod params;
mod region;
mod rotation;

pub use error::DeformError;
pub use handle::HandlePoint;
pub use laplacian_edit::LaplacianEdit;
pub use params::{EditParams, HandleFit, Rotations};
pub(crate) use rotation::best_rotation;
