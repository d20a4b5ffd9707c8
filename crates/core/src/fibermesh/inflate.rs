//! Connectivity and seed: front and back copies of the planar mesh, stitched along the
//! outline (FiberMesh §3.3.3), lifted off the plane by a rotund inflation seed.
//!
//! Layout of the closed mesh: the outline's vertices first (`0..n_boundary`, in outline
//! order; they are the control curve), then the front interior, then the back interior.
//! Front triangles keep the planar orientation, so they face the camera; back triangles
//! are reversed. The result is a closed genus-0 manifold: the doubled disk.
//!
//! The seed comes from a Poisson problem on the planar mesh, `-Δu = 1` with `u = 0` on the
//! outline (uniform Laplacian: `u_i - mean_j u_j = ē_i² / 4` for mean incident edge length
//! `ē_i`, which is `-Δu · h² / 4` on a triangular lattice). For a disk of radius `R` centred
//! at `o`, `u = (R² - ρ²) / 4` and `∇u = -(p - o) / 2`, so `R² = 4u + 4|∇u|²` and the
//! stereographic map of the disk onto the hemisphere (which keeps the rim and is
//! conformal) is `p ↦ p - 2∇u s`, `z = R s` with `s = 2t / (1 - 2t)`, `t = u / R²`. The
//! seed applies exactly that at every vertex with its local `R` from `u` and `∇u` (vertex
//! gradients are area-weighted face gradients). A circle thus starts as the sphere, with
//! vertices spread nearly as the uniform Laplacian wants them (the first iteration moves
//! none by more than 4% of the radius; after a vertical lift of the planar mesh the
//! second iteration still moved vertices by 16% of the size), and any
//! outline gets a height that follows its local width (a strip of half-width `w` is `√2 w`
//! high in the middle). Without a seed the doubled disk is flat: its normals cancel along
//! the outline and every Laplacian magnitude is zero, a fixed point of the optimization.

use faer::linalg::solvers::Solve;
use faer::sparse::{SparseColMat, Triplet};
use faer::{Mat, Side};
use glam::DVec2;

use super::CreateError;
use super::plane::DrawingPlane;
use super::triangulate::PlanarMesh;
use crate::mesh::{Mesh, TriSoup, VertexId};
use crate::solve::SolveError;

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
    let seed = seed(planar)?;
    let mut positions = Vec::with_capacity(nb + 2 * ni);
    positions.extend(
        planar.points[..nb]
            .iter()
            .map(|&p| plane.world_from_plane(p, 0.0)),
    );
    for side in [1.0, -1.0] {
        positions
            .extend((nb..nb + ni).map(|i| plane.world_from_plane(seed[i].0, side * seed[i].1)));
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

/// The seed of every planar vertex: its moved plane position and its height (zero on the
/// outline); see the module docs.
fn seed(planar: &PlanarMesh) -> Result<Vec<(DVec2, f64)>, CreateError> {
    let u = poisson(planar)?;
    let gradients = vertex_gradients(planar, &u);
    Ok(planar
        .points
        .iter()
        .zip(&u)
        .zip(&gradients)
        .map(|((&p, &u), &g)| {
            let u = u.max(0.0);
            // The disk of radius R has u = (R² - ρ²) / 4 and ∇u = -p / 2 from its centre.
            let radius_squared = 4.0 * u + 4.0 * g.length_squared();
            if radius_squared <= 0.0 {
                return (p, 0.0);
            }
            let t = u / radius_squared;
            let stretch = 2.0 * t / (1.0 - 2.0 * t);
            (p - 2.0 * g * stretch, radius_squared.sqrt() * stretch)
        })
        .collect())
}

/// Area-weighted mean of the gradients of the piecewise-linear `u` over each vertex's faces.
fn vertex_gradients(planar: &PlanarMesh, u: &[f64]) -> Vec<DVec2> {
    let mut sums = vec![DVec2::ZERO; planar.points.len()];
    for t in &planar.triangles {
        let [a, b, c] = t.map(|i| planar.points[i as usize]);
        let [ua, ub, uc] = t.map(|i| u[i as usize]);
        // Twice the area times the gradient: Σ u_k perp(opposite edge), counter-clockwise.
        let weighted = ua * (c - b).perp() + ub * (a - c).perp() + uc * (b - a).perp();
        for &i in t {
            sums[i as usize] += weighted;
        }
    }
    let mut areas = vec![0.0; planar.points.len()];
    for t in &planar.triangles {
        let [a, b, c] = t.map(|i| planar.points[i as usize]);
        let double_area = (b - a).perp_dot(c - a);
        for &i in t {
            areas[i as usize] += double_area;
        }
    }
    sums.iter()
        .zip(&areas)
        .map(|(&s, &a)| if a > 0.0 { s / a } else { DVec2::ZERO })
        .collect()
}

/// The Poisson solution `u` of every planar vertex (zero on the outline).
///
/// The uniform-Laplacian rows `u_i - mean_j u_j = ē_i² / 4`, times the valence, are the
/// symmetric graph Laplacian with the outline as a Dirichlet boundary: positive definite,
/// with a one-ring pattern, so one sparse Cholesky solves it (a least-squares solve would
/// square it, at several times the cost).
fn poisson(planar: &PlanarMesh) -> Result<Vec<f64>, CreateError> {
    let n = planar.points.len();
    let nb = planar.n_boundary;
    let ni = n - nb;
    let mut u = vec![0.0; n];
    if ni == 0 {
        return Ok(u);
    }
    let neighbors = planar_neighbors(n, &planar.triangles);
    let mut entries = Vec::with_capacity(7 * ni);
    let mut rhs = Mat::<f64>::zeros(ni, 1);
    for i in nb..n {
        let ring = &neighbors[i];
        let p = planar.points[i];
        let mean_length = ring
            .iter()
            .map(|&j| p.distance(planar.points[j as usize]))
            .sum::<f64>()
            / ring.len() as f64;
        entries.push(Triplet::new(i - nb, i - nb, ring.len() as f64));
        entries.extend(
            ring.iter()
                .filter(|&&j| j as usize >= nb)
                .map(|&j| Triplet::new(i - nb, j as usize - nb, -1.0)),
        );
        rhs[(i - nb, 0)] = ring.len() as f64 * 0.25 * mean_length * mean_length;
    }
    let matrix = SparseColMat::<usize, f64>::try_new_from_triplets(ni, ni, &entries)
        .map_err(|err| CreateError::Solve(SolveError::Factorization(format!("{err:?}"))))?;
    let llt = matrix
        .sp_cholesky(Side::Lower)
        .map_err(|_| CreateError::Solve(SolveError::NotPositiveDefinite))?;
    let solution = llt.solve(&rhs);
    for i in nb..n {
        u[i] = solution[(i - nb, 0)];
    }
    Ok(u)
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
