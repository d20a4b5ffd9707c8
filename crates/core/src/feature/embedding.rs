//! Embedding a sketch in the mesh (§4.4.1 steps 3–4): the path's vertices go onto the
//! sketch, each on its own tangent plane, and the surface around relaxes.
//!
//! Relaxation solves, in least squares over the path and [`RELAX_RINGS`] rings around it,
//! uniform Laplacians equal to the cotangent ones (Eq. 4.5: the cotangent coordinate keeps
//! the shape, the uniform operator evens the triangles), positional rows pulling each path
//! vertex to its place on the sketch, and averaging rows (Eq. 4.6) that let the path's
//! inner vertices slide along it to even spacing. Nealen warns that this tangential
//! regularization drifts over large regions; a few rings are what the path's moves
//! disturb.

use glam::{DVec2, DVec3};

use super::Sketch;
use crate::curve::polyline::{closest_point, cumulative_lengths};
use crate::geometry::OneRingWeights;
use crate::mesh::{Mesh, VertexId};
use crate::solve::{Prefactored, SolveError, Triplets};

/// Rings of vertices around the path that relax with it; the next ring holds still.
const RELAX_RINGS: usize = 3;

/// Weight of a path vertex's positional row against its Laplacian row (1): the path lands
/// on the sketch to a small fraction of a pixel.
const POSITION_WEIGHT: f64 = 10.0;

/// Weight of an inner path vertex's averaging row (Eq. 4.6).
const AVERAGE_WEIGHT: f64 = 1.0;

/// Where each vertex of `path` goes: the sketch's point nearest its screen position, lifted
/// back to 3D on the vertex's tangent plane (`normals` are unit vertex normals). A plane
/// seen edge-on keeps the vertex's depth instead.
pub(super) fn on_sketch(
    mesh: &Mesh,
    normals: &[DVec3],
    sketch: &Sketch,
    points: &[DVec2],
    path: &[VertexId],
) -> Vec<DVec3> {
    let cumulative = cumulative_lengths(points);
    path.iter()
        .map(|&v| {
            let p = mesh.position(v);
            let Some(screen) = sketch.camera.screen_from_world(p, sketch.viewport) else {
                return p;
            };
            let target = closest_point(points, &cumulative, screen.truncate()).point;
            let (origin, dir) = sketch.camera.ray_in_world(target, sketch.viewport);
            let n = normals[v.index()];
            let along = dir.dot(n);
            if along.abs() > 1e-3 {
                origin + dir * ((p - origin).dot(n) / along)
            } else {
                origin + dir * ((p - origin).dot(dir))
            }
        })
        .collect()
}

/// The mesh's positions with `path` moved to `targets` and the rings around it relaxed;
/// only vertices `region` allows move.
///
/// Errors: a relaxation that cannot be solved (a path whose surroundings hold no fixed
/// vertex).
pub(super) fn relax(
    mesh: &Mesh,
    region: &[bool],
    path: &[VertexId],
    targets: &[DVec3],
) -> Result<Vec<DVec3>, SolveError> {
    let (locals, n_free) = relaxed_vertices(mesh, region, path);
    let mut local_of = vec![u32::MAX; mesh.n_vertices()];
    for (i, v) in locals.iter().enumerate() {
        local_of[v.index()] = i as u32;
    }
    let rings = OneRingWeights::new(mesh, &locals[..n_free], |v| local_of[v.index()]);
    let position = |i: usize| mesh.position(locals[i]);
    let n_path = path.len();
    let n_rows = n_free + n_path + n_path.saturating_sub(2);
    let mut triplets = Triplets::with_capacity(n_rows, locals.len(), 8 * n_free);
    let mut rhs = Vec::with_capacity(n_rows);
    for i in 0..n_free {
        let ring: Vec<(usize, f64)> = rings.ring(i).collect();
        let inverse_valence = 1.0 / ring.len() as f64;
        triplets.push(i, i, 1.0);
        for &(j, _) in &ring {
            triplets.push(i, j, -inverse_valence);
        }
        let cotan_delta = position(i) - ring.iter().map(|&(j, w)| w * position(j)).sum::<DVec3>();
        rhs.push(cotan_delta);
    }
    let local = |v: VertexId| local_of[v.index()] as usize;
    for (&v, &target) in path.iter().zip(targets) {
        triplets.push(rhs.len(), local(v), POSITION_WEIGHT);
        rhs.push(POSITION_WEIGHT * target);
    }
    for w in path.windows(3) {
        let row = rhs.len();
        triplets.push(row, local(w[1]), AVERAGE_WEIGHT);
        triplets.push(row, local(w[0]), -0.5 * AVERAGE_WEIGHT);
        triplets.push(row, local(w[2]), -0.5 * AVERAGE_WEIGHT);
        rhs.push(DVec3::ZERO);
    }
    let fixed: Vec<bool> = (0..locals.len()).map(|i| i >= n_free).collect();
    let fixed_values: Vec<DVec3> = (0..locals.len()).map(position).collect();
    let mut solver = Prefactored::new(&triplets.build(), &fixed)?;
    let mut solved = vec![DVec3::ZERO; locals.len()];
    solver.solve(&rhs, &fixed_values, &mut solved)?;
    let mut positions = mesh.positions().to_vec();
    for (v, p) in locals[..n_free].iter().zip(solved) {
        positions[v.index()] = p;
    }
    Ok(positions)
}

/// The vertices that relax (the path first, then up to [`RELAX_RINGS`] rings of `region`
/// around it) and, after them, their neighbours that hold still; and how many relax.
fn relaxed_vertices(mesh: &Mesh, region: &[bool], path: &[VertexId]) -> (Vec<VertexId>, usize) {
    let mut seen = vec![false; mesh.n_vertices()];
    let mut locals: Vec<VertexId> = Vec::new();
    for &v in path {
        if !std::mem::replace(&mut seen[v.index()], true) {
            locals.push(v);
        }
    }
    let mut ring_start = 0;
    for _ in 0..RELAX_RINGS {
        let ring_end = locals.len();
        for k in ring_start..ring_end {
            for w in mesh.vertex_neighbors(locals[k]) {
                if region[w.index()] && !std::mem::replace(&mut seen[w.index()], true) {
                    locals.push(w);
                }
            }
        }
        ring_start = ring_end;
    }
    let n_free = locals.len();
    for k in 0..n_free {
        for w in mesh.vertex_neighbors(locals[k]) {
            if !std::mem::replace(&mut seen[w.index()], true) {
                locals.push(w);
            }
        }
    }
    (locals, n_free)
}

#[cfg(test)]
mod tests {
    use glam::DVec2;

    use super::*;
    use crate::camera::Camera;
    use crate::geometry::vertex_normals;
    use crate::mesh::primitives;

    #[test]
    fn path_vertices_land_on_the_sketch_on_their_tangent_planes() {
        let mesh = primitives::icosphere(1.0, 3);
        let normals = vertex_normals(&mesh);
        let camera = Camera {
            eye: DVec3::new(0.3, 0.4, 4.0),
            ..Camera::default()
        };
        let viewport = DVec2::new(800.0, 600.0);
        let points: Vec<DVec2> = (0..=60)
            .map(|i| {
                DVec2::new(
                    300.0 + 3.0 * f64::from(i),
                    280.0 + 20.0 * (0.1 * f64::from(i)).sin(),
                )
            })
            .collect();
        let sketch = Sketch {
            camera,
            viewport,
            points: points.clone(),
            region: None,
        };
        // The front vertices near the sketch, in any order: each lands on it.
        let path: Vec<VertexId> = mesh
            .vertices()
            .filter(|&v| {
                let s = camera
                    .screen_from_world(mesh.position(v), viewport)
                    .unwrap();
                normals[v.index()].z > 0.5
                    && crate::curve::polyline::distance_to_polyline(s.truncate(), &points) < 30.0
            })
            .collect();
        assert!(path.len() > 5);
        let targets = on_sketch(&mesh, &normals, &sketch, &points, &path);
        for (&v, &t) in path.iter().zip(&targets) {
            let s = camera.screen_from_world(t, viewport).unwrap().truncate();
            let off = crate::curve::polyline::distance_to_polyline(s, &points);
            assert!(off < 1e-6, "{off} px off the sketch");
            let plane = (t - mesh.position(v)).dot(normals[v.index()]);
            assert!(plane.abs() < 1e-12, "{plane} off the tangent plane");
        }
    }
}
