//! Discrete differential geometry on a [`Mesh`](crate::mesh::Mesh): normals, areas,
//! Laplacians, mean curvature and the guarded cotangent weights of an editing region's one-rings; fractions and sums of affine transforms (`transform_blend`).
//!
//! Everything reads positions and connectivity and returns new per-element data in `f64`;
//! nothing here changes a mesh. Sign conventions follow Nealen et al. 2006 ("Laplacian Mesh
//! Optimization"): the Laplacian is `δ_i = Σ_j w_ij (v_i - v_j)`, positive semi-definite, so on
//! a convex surface `δ` points outward and `M⁻¹ L x = 2 H n` with `H > 0` (Meyer et al. 2003).

mod area;
mod bvh;
mod closest;
mod cotan_weights;
mod laplacian;
mod normals;
mod raycast;
mod shape_diameter;
mod transform_blend;

pub use area::{
    enclosed_volume, face_area, mass_matrix, total_area, vertex_areas, vertex_areas_barycentric,
};
pub use bvh::Bvh;
pub use closest::{barycentric, closest_point_on_triangle};
pub(crate) use cotan_weights::OneRingWeights;
pub use laplacian::{
    cotan_laplacian, cotan_laplacian_coordinates, mean_curvature, mean_curvature_normals,
    uniform_laplacian,
};
pub use normals::{
    face_normal, face_normals, flipped_faces, vertex_normals, vertex_normals_into,
    vertex_normals_of,
};
pub use raycast::{RayHit, raycast};
pub(crate) use raycast::{intersect_triangle, segment_crosses_triangle};
pub use shape_diameter::{SDF_RAYS, shape_diameter};
pub use transform_blend::{Fractions, exp_affine, fraction, log_affine, sum};
