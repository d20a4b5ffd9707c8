//! Zero crossings of the view function on edges, chained face to face into curves.
//!
//! Hertzmann and Zorin's smooth silhouettes: the per-vertex function `g` (see
//! [`view_function`]) is interpolated linearly along each edge; an edge whose ends differ in
//! sign holds one crossing at `t = g_a / (g_a − g_b)`. A face with a sign change has exactly
//! two such edges, and both faces of such an edge have a sign change, so the crossings form
//! curves that pass one face at a time: closed loops, or open chains that end on the mesh
//! boundary. A vertex with `g = 0` counts as front-facing, which keeps every crossing
//! strictly inside or at the start of its edge.

use glam::DVec3;

use crate::camera::Camera;
use crate::mesh::{FaceId, HalfedgeId, Mesh, VertexId};

/// Where the view function changes sign on an edge.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(super) struct Crossing {
    /// The edge, as the half-edge `edge[0] → edge[1]` the curve crossed.
    pub edge: [VertexId; 2],
    /// The crossing's parameter along the edge, in `[0, 1)`.
    pub t: f64,
    /// `lerp(p[edge[0]], p[edge[1]], t)`.
    pub world: DVec3,
}

/// One curve of crossings in walking order; a closed chain joins its last crossing to the
/// first.
#[derive(Clone, Debug, Default)]
pub(super) struct Chain {
    pub crossings: Vec<Crossing>,
    pub is_closed: bool,
}

/// `g(v) = n(v)·(v − eye)` for a perspective camera, `n(v)·forward` for an orthographic one:
/// negative where the surface faces the viewer, zero on the silhouette.
pub(super) fn view_function(mesh: &Mesh, normals: &[DVec3], camera: &Camera) -> Vec<f64> {
    match camera.ortho_height {
        Some(_) => {
            let forward = camera.forward();
            normals.iter().map(|n| n.dot(forward)).collect()
        }
        None => mesh
            .positions()
            .iter()
            .zip(normals)
            .map(|(&p, n)| n.dot(p - camera.eye))
            .collect(),
    }
}

/// Whether `g` puts a vertex on the back-facing side.
fn is_back(g: f64) -> bool {
    g > 0.0
}

/// The half-edges where the curve enters and leaves a face with a sign change.
///
/// Writing `v` for the corner whose sign differs from the other two, the curve runs from
/// the edge into `v` to the edge out of `v` when `v` faces away, and back otherwise. So the
/// front-facing side is always on the curve's left, seen from outside the surface, and the
/// face across the exit edge enters through its twin.
fn face_passage(mesh: &Mesh, g: &[f64], f: FaceId) -> Option<(HalfedgeId, HalfedgeId)> {
    let back = mesh.face_vertices(f).map(|v| is_back(g[v.index()]));
    let lone = match back {
        [a, b, c] if a == b && b == c => return None,
        [a, b, _] if a == b => 2,
        [a, _, c] if a == c => 1,
        _ => 0,
    };
    let out_of_lone = HalfedgeId(3 * f.0 + lone);
    let into_lone = mesh.prev(out_of_lone);
    Some(if back[lone as usize] {
        (into_lone, out_of_lone)
    } else {
        (out_of_lone, into_lone)
    })
}

fn crossing(mesh: &Mesh, g: &[f64], h: HalfedgeId) -> Crossing {
    let (a, b) = (mesh.tail(h), mesh.head(h));
    let (ga, gb) = (g[a.index()], g[b.index()]);
    let t = ga / (ga - gb);
    Crossing {
        edge: [a, b],
        t,
        world: mesh.position(a).lerp(mesh.position(b), t),
    }
}

/// All zero-crossing curves of `g` on `mesh`: open chains (from boundary to boundary) first,
/// then closed loops.
pub(super) fn contour_chains(mesh: &Mesh, g: &[f64]) -> Vec<Chain> {
    let passages: Vec<Option<(HalfedgeId, HalfedgeId)>> =
        mesh.faces().map(|f| face_passage(mesh, g, f)).collect();
    let mut is_visited = vec![false; mesh.n_faces()];
    let mut chains = Vec::new();
    // Open chains start in a face whose entry edge is on the boundary.
    let open_starts = mesh
        .faces()
        .filter(|f| passages[f.index()].is_some_and(|(enter, _)| mesh.twin(enter).is_none()));
    for start in open_starts.collect::<Vec<_>>() {
        chains.push(walk(mesh, g, &passages, &mut is_visited, start));
    }
    for start in mesh.faces() {
        if passages[start.index()].is_some() && !is_visited[start.index()] {
            chains.push(walk(mesh, g, &passages, &mut is_visited, start));
        }
    }
    chains
}

/// Follows the curve from `start` until it leaves the mesh or comes back to `start`.
fn walk(
    mesh: &Mesh,
    g: &[f64],
    passages: &[Option<(HalfedgeId, HalfedgeId)>],
    is_visited: &mut [bool],
    start: FaceId,
) -> Chain {
    let mut chain = Chain::default();
    let mut f = start;
    while let Some((enter, exit)) = passages[f.index()] {
        if f == start && mesh.twin(enter).is_none() {
            chain.crossings.push(crossing(mesh, g, enter));
        }
        is_visited[f.index()] = true;
        chain.crossings.push(crossing(mesh, g, exit));
        let Some(across) = mesh.twin(exit) else {
            break;
        };
        f = mesh.face(across);
        if f == start {
            chain.is_closed = true;
            break;
        }
        // Each face has one way in and one way out, so only `start` can be seen twice.
        debug_assert!(!is_visited[f.index()], "a contour curve crossed itself");
    }
    chain
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::geometry::vertex_normals;
    use crate::mesh::primitives::{grid, icosphere, torus};

    fn chains_for(mesh: &Mesh, camera: &Camera) -> (Vec<f64>, Vec<Chain>) {
        let g = view_function(mesh, &vertex_normals(mesh), camera);
        let chains = contour_chains(mesh, &g);
        (g, chains)
    }

    #[test]
    fn sphere_has_one_closed_loop_through_every_sign_change() {
        let sphere = icosphere(1.0, 3);
        let (g, chains) = chains_for(&sphere, &Camera::default());
        assert_eq!(chains.len(), 1);
        assert!(chains[0].is_closed);
        let n_sign_changes = sphere
            .faces()
            .filter(|&f| face_passage(&sphere, &g, f).is_some())
            .count();
        assert_eq!(chains[0].crossings.len(), n_sign_changes);
        for c in &chains[0].crossings {
            let [a, b] = c.edge.map(|v| g[v.index()]);
            assert!(a * b <= 0.0 && a != b && (0.0..1.0).contains(&c.t));
            let interpolated = (1.0 - c.t) * a + c.t * b;
            assert!(interpolated.abs() < 1e-12);
        }
    }

    #[test]
    fn consecutive_crossings_share_a_face() {
        let mesh = torus(1.0, 0.4, 40, 20);
        let camera = Camera {
            eye: DVec3::new(0.5, -3.0, 2.0),
            ..Camera::default()
        };
        let (_, chains) = chains_for(&mesh, &camera);
        assert!(chains.len() >= 2);
        for chain in &chains {
            assert!(chain.is_closed);
            let n = chain.crossings.len();
            for i in 0..n {
                let (p, q) = (chain.crossings[i], chain.crossings[(i + 1) % n]);
                // Two edges of one triangle share exactly one vertex.
                let shared = p.edge.iter().filter(|v| q.edge.contains(v)).count();
                assert_eq!(shared, 1, "{p:?} {q:?}");
            }
        }
    }

    #[test]
    fn open_chains_end_on_the_boundary() {
        // A wavy sheet z = cos(2x)/2 seen obliquely along (2, 0, −1)/√5: g = 0 where
        // sin 2x = 1/2, on the line x = π/12 that runs across the sheet in y.
        let mut sheet = grid(40, 20, 2.0);
        for p in sheet.positions_mut() {
            p.z = 0.5 * (2.0 * p.x).cos();
        }
        let forward = DVec3::new(2.0, 0.0, -1.0).normalize();
        let camera = Camera {
            eye: -8.0 * forward,
            ortho_height: Some(3.0),
            ..Camera::default()
        };
        let (_, chains) = chains_for(&sheet, &camera);
        assert_eq!(chains.len(), 1);
        for chain in &chains {
            assert!(!chain.is_closed);
            for c in &chain.crossings {
                assert!(
                    (c.world.x - std::f64::consts::PI / 12.0).abs() < 0.02,
                    "{c:?}"
                );
            }
            for end in [
                chain.crossings[0],
                chain.crossings[chain.crossings.len() - 1],
            ] {
                let [a, b] = end.edge;
                assert!(sheet.is_boundary_vertex(a) && sheet.is_boundary_vertex(b));
            }
        }
    }
}
