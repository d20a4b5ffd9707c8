//! Uniform and cotangent Laplacians, and mean curvature from the cotangent one.
//!
//! Both matrices follow Nealen et al. 2006 (sections 2 and 3): row `i` computes the Laplacian
//! coordinate `δ_i = v_i - Σ_j w_ij v_j`.
//! - Uniform ("umbrella"): `w_ij = 1 / valence(i)`, so `δ_i` is `v_i` minus the mean of its
//!   neighbours. Not symmetric; it ignores geometry, which is what FiberMesh wants for
//!   fairing (it also evens out the vertex spacing).
//! - Cotangent: unnormalised weights `w_ij = (cot α_ij + cot β_ij) / 2` over the two angles
//!   opposite edge `ij`, with `L_ii = Σ_j w_ij`. Symmetric positive semi-definite, zero row
//!   sums, and exact on linear functions over flat meshes. Divided by the [mixed Voronoi
//!   areas](super::vertex_areas) it is the Laplace–Beltrami operator: `M⁻¹ L x = 2 H n`.
//!
//! A current limitation: no clamping of cotangents, so needle triangles give huge or
//! negative weights (obtuse angles); a triangle with zero area contributes nothing.

use glam::DVec3;

use super::area::vertex_areas;
use super::normals::vertex_normals;
use crate::mesh::{HalfedgeId, Mesh};
use crate::solve::{SparseMatrix, Triplets};

/// Half the cotangent of the angle opposite half-edge `h` in its face; zero when the face
/// has no area.
fn half_cot_opposite(mesh: &Mesh, h: HalfedgeId) -> f64 {
    let apex = mesh.position(mesh.tail(mesh.prev(h)));
    let u = mesh.position(mesh.tail(h)) - apex;
    let v = mesh.position(mesh.head(h)) - apex;
    let double_area = u.cross(v).length();
    if double_area == 0.0 {
        0.0
    } else {
        0.5 * u.dot(v) / double_area
    }
}

fn halfedges(mesh: &Mesh) -> impl Iterator<Item = HalfedgeId> + use<> {
    (0..mesh.n_halfedges() as u32).map(HalfedgeId)
}

/// The uniform Laplacian: `L_ii = 1`, `L_ij = -1 / valence(i)` for neighbours `j`.
///
/// Built column by column from the one-rings (column `j` holds row `j` and the rows of `j`'s
/// neighbours), so no triplets are sorted: large meshes build it several times faster.
pub fn uniform_laplacian(mesh: &Mesh) -> SparseMatrix {
    let n = mesh.n_vertices();
    let inverse_valence: Vec<f64> = mesh
        .vertices()
        .map(|v| 1.0 / mesh.valence(v) as f64)
        .collect();
    let mut col_ptr = Vec::with_capacity(n + 1);
    col_ptr.push(0u32);
    let mut rows = Vec::with_capacity(n + mesh.n_halfedges());
    let mut values = Vec::with_capacity(n + mesh.n_halfedges());
    let mut column = Vec::new();
    for v in mesh.vertices() {
        column.clear();
        column.push((v.0, 1.0));
        column.extend(
            mesh.vertex_neighbors(v)
                .map(|u| (u.0, -inverse_valence[u.index()])),
        );
        column.sort_unstable_by_key(|&(row, _)| row);
        rows.extend(column.iter().map(|&(row, _)| row));
        values.extend(column.iter().map(|&(_, value)| value));
        col_ptr.push(rows.len() as u32);
    }
    SparseMatrix::from_columns(n, col_ptr, rows, values)
}

/// The cotangent Laplacian `L` (unnormalised, symmetric, positive semi-definite): see the
/// module docs for the weights.
pub fn cotan_laplacian(mesh: &Mesh) -> SparseMatrix {
    let n = mesh.n_vertices();
    let mut triplets = Triplets::with_capacity(n, n, 4 * mesh.n_halfedges());
    // Each half-edge adds the cotangent of its own opposite angle, so an interior edge gets
    // both, and a boundary edge one.
    for h in halfedges(mesh) {
        let w = half_cot_opposite(mesh, h);
        let (i, j) = (mesh.tail(h).index(), mesh.head(h).index());
        triplets.push(i, j, -w);
        triplets.push(j, i, -w);
        triplets.push(i, i, w);
        triplets.push(j, j, w);
    }
    triplets.build()
}

/// The cotangent Laplacian applied to the positions, `Σ_j w_ij (v_i − v_j)`, and its
/// diagonal `Σ_j w_ij`, at every vertex: what [`cotan_laplacian`] gives, without building
/// the matrix.
pub fn cotan_laplacian_coordinates(mesh: &Mesh) -> (Vec<DVec3>, Vec<f64>) {
    let mut laplacian = vec![DVec3::ZERO; mesh.n_vertices()];
    let mut diagonal = vec![0.0; mesh.n_vertices()];
    for h in halfedges(mesh) {
        let w = half_cot_opposite(mesh, h);
        let (i, j) = (mesh.tail(h).index(), mesh.head(h).index());
        let difference = w * (mesh.positions()[i] - mesh.positions()[j]);
        laplacian[i] += difference;
        laplacian[j] -= difference;
        diagonal[i] += w;
        diagonal[j] += w;
    }
    (laplacian, diagonal)
}

/// The mean curvature normal `H n = M⁻¹ L x / 2` at every vertex, with mixed Voronoi areas.
///
/// On boundary vertices this is not a curvature: it also holds the boundary's own bending.
pub fn mean_curvature_normals(mesh: &Mesh) -> Vec<DVec3> {
    let (laplacian, _) = cotan_laplacian_coordinates(mesh);
    let areas = vertex_areas(mesh);
    laplacian
        .iter()
        .zip(&areas)
        .map(|(&lx, &area)| {
            if area > 0.0 {
                lx / (2.0 * area)
            } else {
                DVec3::ZERO
            }
        })
        .collect()
}

/// Signed mean curvature `H` at every vertex: the mean curvature normal along the outward
/// vertex normal, so a sphere of radius `r` gives `1 / r` and a flat patch 0.
///
/// Boundary vertices get the normal part of [`mean_curvature_normals`], which is zero on a
/// flat patch but otherwise not a curvature.
pub fn mean_curvature(mesh: &Mesh) -> Vec<f64> {
    let normals = vertex_normals(mesh);
    mean_curvature_normals(mesh)
        .iter()
        .zip(&normals)
        .map(|(hn, n)| hn.dot(*n))
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::mesh::{TriSoup, fixtures, primitives};

    fn interior_vertices(mesh: &Mesh) -> impl Iterator<Item = usize> + '_ {
        mesh.vertices()
            .filter(|&v| !mesh.is_boundary_vertex(v))
            .map(|v| v.index())
    }

    /// `L f` for a scalar function per vertex.
    fn apply(l: &SparseMatrix, f: &[f64]) -> Vec<f64> {
        let mut out = vec![0.0; f.len()];
        l.mul_vec(f, &mut out);
        out
    }

    #[test]
    fn rows_sum_to_zero_and_cotan_is_symmetric() {
        for fixture in fixtures::all() {
            let mesh = &fixture.mesh;
            for l in [uniform_laplacian(mesh), cotan_laplacian(mesh)] {
                let row_sums = apply(&l, &vec![1.0; mesh.n_vertices()]);
                assert!(row_sums.iter().all(|s| s.abs() < 1e-12), "{}", fixture.name);
            }
            let l = cotan_laplacian(mesh);
            for col in 0..l.ncols() {
                for (row, value) in l.column(col) {
                    assert!((l.get(col, row) - value).abs() < 1e-14, "{}", fixture.name);
                }
            }
            assert!(
                uniform_laplacian(mesh)
                    .column(0)
                    .any(|(row, v)| row == 0 && v == 1.0)
            );
        }
    }

    #[test]
    fn cotan_weights_of_a_right_triangle() {
        let soup = TriSoup {
            positions: vec![DVec3::ZERO, DVec3::X, DVec3::Y],
            triangles: vec![[0, 1, 2]],
        };
        let l = cotan_laplacian(&Mesh::from_soup(&soup).unwrap());
        // Edge 1-2 faces the right angle (cot 0); the legs face 45 degree angles (cot 1).
        assert_eq!(
            l.to_dense(),
            vec![
                vec![1.0, -0.5, -0.5],
                vec![-0.5, 0.5, 0.0],
                vec![-0.5, 0.0, 0.5]
            ]
        );
    }

    #[test]
    fn laplacians_vanish_on_linear_functions_inside_a_flat_patch() {
        let mut mesh = primitives::grid(8, 6, 2.0);
        let linear = |p: DVec3| 0.3 + 2.0 * p.x - 1.5 * p.y;
        // The uniform Laplacian is exact only on the regular grid.
        let f: Vec<f64> = mesh.positions().iter().map(|&p| linear(p)).collect();
        let uniform = apply(&uniform_laplacian(&mesh), &f);
        assert!(interior_vertices(&mesh).all(|i| uniform[i].abs() < 1e-12));
        // The cotangent Laplacian is exact on any flat triangulation: jiggle the interior.
        let interior: Vec<usize> = interior_vertices(&mesh).collect();
        for (k, &i) in interior.iter().enumerate() {
            let angle = k as f64 * 2.4;
            mesh.positions_mut()[i] += 0.05 * DVec3::new(angle.cos(), angle.sin(), 0.0);
        }
        let f: Vec<f64> = mesh.positions().iter().map(|&p| linear(p)).collect();
        let cotan = apply(&cotan_laplacian(&mesh), &f);
        assert!(
            interior.iter().all(|&i| cotan[i].abs() < 1e-12),
            "{cotan:?}"
        );
        let curvature = mean_curvature(&mesh);
        assert!(curvature.iter().all(|h| h.abs() < 1e-12));
    }

    #[test]
    fn sphere_mean_curvature_tends_to_one_over_radius() {
        // Subdivision 1 is so symmetric that it is exact; from 2 on the maximum relative error
        // falls by about 4 per level (second order): 1.1e-4, 2.9e-5, 7.2e-6, 1.8e-6.
        let radius = 2.0;
        let mut previous_error = f64::INFINITY;
        for subdivisions in 2..=5 {
            let mesh = primitives::icosphere(radius, subdivisions);
            let error = mean_curvature(&mesh)
                .iter()
                .map(|h| (h * radius - 1.0).abs())
                .fold(0.0, f64::max);
            assert!(
                error < previous_error / 3.0,
                "subdivision {subdivisions}: error {error}, before {previous_error}"
            );
            previous_error = error;
        }
        assert!(
            previous_error < 1e-5,
            "relative error {previous_error} at 5 subdivisions"
        );
        let coarse = mean_curvature(&primitives::icosphere(radius, 1));
        assert!(coarse.iter().all(|h| (h * radius - 1.0).abs() < 1e-12));
    }

    #[test]
    fn uniform_laplacian_points_outward_on_a_sphere() {
        // Only its normal part: on irregular meshes the umbrella operator also has a large
        // tangential part (it pulls vertices towards their neighbours' centroid).
        let mesh = primitives::icosphere(1.0, 3);
        let mut delta = vec![DVec3::ZERO; mesh.n_vertices()];
        uniform_laplacian(&mesh).mul_dvec3(mesh.positions(), &mut delta);
        assert!(
            delta
                .iter()
                .zip(mesh.positions())
                .all(|(d, p)| d.dot(*p) > 0.0)
        );
    }
}
