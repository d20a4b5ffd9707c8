//! Blanco's curve handles and skeletons (`../shared/seeds/000_…`): deforming any object as
//! it is, a scan with holes, a soup of pieces, a non-manifold or non-orientable mesh, or a
//! point cloud, by curves sketched over it.
//!
//! A stroke over the object becomes a curve handle ([`place_handle`]): on the surface, or
//! inside along the part's middle (a skeleton curve). Dragging, twisting or scaling its
//! control points moves the object ([`Deformation`]): every vertex between the curve's end
//! planes is held in the frame of its slab (200 frames per curve) and rebuilt from the new
//! frames; the rest follows the curve's ends rigidly or, where curves are linked into a
//! skeleton, a Gaussian blend of the links' motions. No system is solved: a frame is one
//! pass over the vertices, so half a million points follow a drag.
//!
//! Local self-intersection avoidance (§5.5) takes the form the thesis itself proposes in
//! §8.2, "block user interactions that would cause intersections": a change that would turn
//! a slab inside out (its two planes meeting on a vertex's near side, a bend tighter than
//! the part is thick) is held at the largest fraction that folds nothing
//! ([`Deformation::unfolded`]). The thesis' own rule (turn frame `k` until the planes of
//! every `j < k` meet outside both circles of influence) and a neighbours-only angle limit
//! were both tried on a bar of radius 0.2 bent within 0.1: they made more crossing triangle
//! pairs than doing nothing (428 and 304 against 125 and 161), because frames turned away
//! from the tangent squash the slabs the curve runs across.
//!
//! One idea per file:
//! 1. [`shape`]: what is deformed (positions, triangles if any) and who is next to whom;
//! 2. [`filter`]: the stroke's jitter filter (Alg. 1);
//! 3. [`placement`]: samples cast onto the object, and skeleton centroids (§4);
//! 4. [`curve`]: Catmull-Rom through the control points (App. A, with the missing ½), or
//!    rigid limbs (§7);
//! 5. [`frames`]: the frame field (§5.1), twist and scale (§5.3);
//! 6. [`segment`]: the region and the start and end sides (§3.1);
//! 7. [`binding`]: slab coordinates and the stretch ratio (§5.2);
//! 8. [`deformation`]: all of it for one or more handles, with links (§5.4);
//! 9. [`handle`]: the handle's curve, and edits to it (a handle as a document keeps it,
//!    target, number, curve and links, is plain data: [`crate::model::CurveHandle`]).

mod binding;
mod curve;
mod deformation;
mod error;
mod filter;
mod frames;
mod handle;
mod placement;
mod segment;
mod shape;

/// A handle's data is plain data of the document; the app and the ops name it from here.
pub use crate::model::{HandleCurve, HandleKind};
pub use curve::Spline;
pub use deformation::{Deformation, Link, Mover, Segmented, Slabs};
pub use error::SkeletonError;
pub use filter::{JITTER_PX, filter_jitter};
pub use frames::{FRAMES, Frame};
pub use handle::PointEdit;
pub use placement::{HandleStroke, place_handle};
pub use shape::{Neighbours, Shape};
