//! Connectivity and seed: front and back copies of the planar mesh, stitched along the
//! outline (FiberMesh §3.3.3), lifted off the plane by a rotund inflation seed.
//!
//! Layout of the closed mesh: the outline's vertices first (`0..n_boundary`, in outline
//! order; they are the control curve), then the front interior, then the back interior.
//! Front triangles keep the planar orientation, so they face the camera; back triangles
//! are reversed. The result is a closed genus-0 manifold: the doubled disk.
//!
//! The seed height solves a Poisson problem on the planar mesh, `-Δu = 1` with `u = 0` on
//! the outline (uniform Laplacian, `u_i - mean_j u_j = ē_i² / 4` for mean incident edge
//! length `ē_i`, which is `-Δu · h² / 4` on a triangular lattice), and lifts vertex `i` to
//! `±√(4 u_i)`. For a disk of radius `R`, `u = (R² - ρ²) / 4`, so the seed is the sphere;
//! for a long strip of half-width `w` it is an ellipse `√2` times taller than wide. The
//! Poisson solution adapts to the local width of any outline, where a distance-to-outline
//! seed would need the medial axis. Without a seed the doubled disk is flat, its normals
//! cancel along the outline and every Laplacian magnitude is zero, which is a fixed point
//! of the optimization.

use super::CreateError;
use super::outline::DrawingPlane;
use super::triangulate::PlanarMesh;
use crate::mesh::{Mesh, TriSoup, VertexId};
use crate::solve::{Prefactored, Triplets};

/// `z = ±√(SEED_SCALE u)`: 4 makes the seed of a disk a sphere.
const SEED_SCALE: f64 = 4.0;

/// Stitches front and back copies of `planar` and lifts them by the seed; returns the mesh
/// and the outline's vertices in order.
///
/// Errors: [`CreateError::Solve`] if the seed's Poisson solve fails and
/// [`CreateError::Mesh`] if the stitched soup is not a manifold (a bug, not an input
/// problem).
pub(crate) fn inflate(
    planar: &PlanarMesh,
    plane: &DrawingPlane,
) -> Result<(Mesh, Vec<VertexId>), CreateError> {
    let nb = planar.n_boundary;
    let ni = planar.points.len() - nb;
    let heights = seed_heights(planar)?;
    let mut positions = Vec::with_capacity(nb + 2 * ni);
    positions.extend(
        planar.points[..nb]
            .iter()
            .map(|&p| plane.world_from_plane(p, 0.0)),
    );
    for side in [1.0, -1.0] {
        positions.extend(
            (nb..nb + ni).map(|i| plane.world_from_plane(planar.points[i], side * heights[i])),
        );
    }
    let back = |i: u32| if (i as usize) < nb { i } else { i + ni as u32 };
    let mut triangles = Vec::with_capacity(2 * planar.triangles.len());
    triangles.extend_from_slice(&planar.triangles);
    triangles.extend(
        planar
            .triangles
            .iter()
            .map(|&[a, b, c]| [back(a), back(c), back(b)]),
    );
    let mesh = Mesh::from_soup(&TriSoup {
        positions,
        triangles,
    })
    .map_err(CreateError::Mesh)?;
    Ok((mesh, (0..nb as u32).map(VertexId).collect()))
}

/// The seed height of every planar vertex (zero on the outline); see the module docs.
fn seed_heights(planar: &PlanarMesh) -> Result<Vec<f64>, CreateError> {
    let n = planar.points.len();
    let nb = planar.n_boundary;
    let neighbors = planar_neighbors(n, &planar.triangles);
    let mut triplets = Triplets::with_capacity(n - nb, n, 7 * (n - nb));
    let mut rhs = Vec::with_capacity(n - nb);
    for i in nb..n {
        let ring = &neighbors[i];
        let p = planar.points[i];
        let mean_length = ring
            .iter()
            .map(|&j| p.distance(planar.points[j as usize]))
            .sum::<f64>()
            / ring.len() as f64;
        triplets.push(i - nb, i, 1.0);
        for &j in ring {
            triplets.push(i - nb, j as usize, -1.0 / ring.len() as f64);
        }
        rhs.push(0.25 * mean_length * mean_length);
    }
    let fixed: Vec<bool> = (0..n).map(|i| i < nb).collect();
    let mut solver = Prefactored::new(&triplets.build(), &fixed).map_err(CreateError::Solve)?;
    let mut u = vec![0.0; n];
    solver
        .solve_scalar(&rhs, &vec![0.0; n], &mut u)
        .map_err(CreateError::Solve)?;
    Ok(u.iter()
        .map(|&u| (SEED_SCALE * u.max(0.0)).sqrt())
        .collect())
}

/// Sorted, unique neighbours of each vertex of a triangle list.
fn planar_neighbors(n: usize, triangles: &[[u32; 3]]) -> Vec<Vec<u32>> {
    let mut neighbors = vec![Vec::with_capacity(6); n];
    for t in triangles {
        for k in 0..3 {
            let (a, b) = (t[k], t[(k + 1) % 3]);
            neighbors[a as usize].push(b);
            neighbors[b as usize].push(a);
        }
    }
    for ring in &mut neighbors {
        ring.sort_unstable();
        ring.dedup();
    }
    neighbors
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::camera::Camera;
    use crate::fibermesh::triangulate::triangulate;
    use glam::DVec2;
    use std::f64::consts::TAU;

    #[test]
    fn the_seed_of_a_disk_is_close_to_a_sphere() {
        let n = 96;
        let outline: Vec<DVec2> = (0..n)
            .map(|k| DVec2::from_angle(TAU * k as f64 / n as f64))
            .collect();
        let planar = triangulate(&outline, TAU / n as f64).unwrap();
        let plane = DrawingPlane::facing(&Camera::default()).unwrap();
        let (mesh, curve) = inflate(&planar, &plane).unwrap();
        mesh.validate().unwrap();
        assert!(mesh.is_closed());
        assert_eq!(mesh.genus(), Some(0));
        assert_eq!(curve.len(), n);
        for &p in mesh.positions() {
            let r = (plane.plane_from_world(p).length_squared() + plane.height(p).powi(2)).sqrt();
            assert!((r - 1.0).abs() < 0.05, "radius {r}");
        }
    }
}
