//! Face areas, vertex areas (the lumped mass matrix) and enclosed volume.
//!
//! [`vertex_areas`] uses the mixed Voronoi areas of Meyer, Desbrun, Schröder and Barr,
//! "Discrete Differential-Geometry Operators for Triangulated 2-Manifolds" (2003), Fig. 4:
//! the Voronoi region of each corner in non-obtuse triangles, and half or a quarter of the
//! triangle in obtuse ones. It is what makes `M⁻¹ L x / 2` converge to the mean curvature
//! normal; the simpler barycentric areas (a third of each face) do not on irregular meshes.

use super::normals::face_cross;
use crate::mesh::{FaceId, Mesh};
use crate::solve::SparseMatrix;

/// Area of one triangle.
pub fn face_area(mesh: &Mesh, f: FaceId) -> f64 {
    0.5 * face_cross(mesh, f).length()
}

/// Sum of all face areas.
pub fn total_area(mesh: &Mesh) -> f64 {
    mesh.faces().map(|f| face_area(mesh, f)).sum()
}

/// Mixed Voronoi area of every vertex (Meyer et al. 2003); they sum to [`total_area`].
pub fn vertex_areas(mesh: &Mesh) -> Vec<f64> {
    let mut areas = vec![0.0; mesh.n_vertices()];
    for f in mesh.faces() {
        let corners = mesh.face_vertices(f);
        let positions = mesh.face_positions(f);
        let double_area = face_cross(mesh, f).length();
        if double_area == 0.0 {
            continue;
        }
        let area = 0.5 * double_area;
        let is_obtuse = |k: usize| {
            let (p, q, r) = (positions[k], positions[(k + 1) % 3], positions[(k + 2) % 3]);
            (q - p).dot(r - p) < 0.0
        };
        let obtuse_corner = (0..3).find(|&k| is_obtuse(k));
        for k in 0..3 {
            let (p, q, r) = (positions[k], positions[(k + 1) % 3], positions[(k + 2) % 3]);
            let share = match obtuse_corner {
                // Voronoi region: the cotangent of the angle opposite each edge at p is
                // dot / |cross|, and |cross| is twice the triangle's area for every corner.
                None => {
                    let cot_q = (p - q).dot(r - q) / double_area;
                    let cot_r = (p - r).dot(q - r) / double_area;
                    ((r - p).length_squared() * cot_q + (q - p).length_squared() * cot_r) / 8.0
                }
                Some(obtuse) if obtuse == k => area / 2.0,
                Some(_) => area / 4.0,
            };
            areas[corners[k].index()] += share;
        }
    }
    areas
}

/// A third of each incident face's area per vertex: always positive, but biased on
/// irregular meshes.
pub fn vertex_areas_barycentric(mesh: &Mesh) -> Vec<f64> {
    let mut areas = vec![0.0; mesh.n_vertices()];
    for f in mesh.faces() {
        let third = face_area(mesh, f) / 3.0;
        for v in mesh.face_vertices(f) {
            areas[v.index()] += third;
        }
    }
    areas
}

/// The lumped mass matrix: diagonal, with the mixed Voronoi [`vertex_areas`].
pub fn mass_matrix(mesh: &Mesh) -> SparseMatrix {
    SparseMatrix::diagonal(&vertex_areas(mesh))
}

/// Signed volume enclosed by a closed mesh (divergence theorem), positive when the faces
/// point outward. For a mesh with holes it depends on where the origin is.
pub fn enclosed_volume(mesh: &Mesh) -> f64 {
    mesh.faces()
        .map(|f| {
            let [a, b, c] = mesh.face_positions(f);
            a.dot(b.cross(c))
        })
        .sum::<f64>()
        / 6.0
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::mesh::{TriSoup, fixtures, primitives};
    use glam::DVec3;
    use std::f64::consts::PI;

    #[test]
    fn vertex_areas_sum_to_the_total_area() {
        for fixture in fixtures::all() {
            let total = total_area(&fixture.mesh);
            for areas in [
                vertex_areas(&fixture.mesh),
                vertex_areas_barycentric(&fixture.mesh),
            ] {
                let sum: f64 = areas.iter().sum();
                assert!(
                    (sum - total).abs() < 1e-12 * total.max(1.0),
                    "{}: {sum} vs {total}",
                    fixture.name
                );
                assert!(areas.iter().all(|&a| a > 0.0), "{}", fixture.name);
            }
        }
    }

    #[test]
    fn right_triangle_areas_are_known() {
        let soup = TriSoup {
            positions: vec![DVec3::ZERO, DVec3::X, DVec3::Y],
            triangles: vec![[0, 1, 2]],
        };
        let mesh = Mesh::from_soup(&soup).unwrap();
        assert_eq!(face_area(&mesh, FaceId(0)), 0.5);
        // Right angle at vertex 0: Voronoi regions are the squares to the hypotenuse midpoint.
        assert_eq!(vertex_areas(&mesh), vec![0.25, 0.125, 0.125]);
        let obtuse = TriSoup {
            positions: vec![DVec3::ZERO, DVec3::X, DVec3::new(-1.0, 1.0, 0.0)],
            triangles: vec![[0, 1, 2]],
        };
        let mesh = Mesh::from_soup(&obtuse).unwrap();
        assert_eq!(vertex_areas(&mesh), vec![0.25, 0.125, 0.125]);
    }

    #[test]
    fn volumes_match_closed_forms() {
        assert!((enclosed_volume(&primitives::cube(2.0)) - 8.0).abs() < 1e-12);
        let sphere = primitives::icosphere(2.0, 5);
        let exact = 4.0 / 3.0 * PI * 8.0;
        assert!((enclosed_volume(&sphere) / exact - 1.0).abs() < 2e-3);
        assert!((total_area(&sphere) / (4.0 * PI * 4.0) - 1.0).abs() < 2e-3);
    }

    #[test]
    fn mass_matrix_is_diagonal_areas() {
        let mesh = primitives::grid(2, 2, 2.0);
        let m = mass_matrix(&mesh);
        assert_eq!(m.nnz(), 9);
        assert_eq!(m.get(4, 4), vertex_areas(&mesh)[4]);
        // The centre's Voronoi cell in a grid of unit cells is a unit square.
        assert!((m.get(4, 4) - 1.0).abs() < 1e-12);
    }
}
