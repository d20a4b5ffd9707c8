//! The part of a surface near some vertices, measured along its edges: where a local edit
//! may move the surface (the region a pull preview solves, see
//! [`super::FairSurface::new_regional`]).

use crate::mesh::{Mesh, VertexId, shortest_paths};

/// The vertices within `radius` of `seeds` along mesh edges (Dijkstra over edge lengths),
/// as a mask with one entry per vertex. Seeds outside the mesh are ignored.
pub fn region_around(mesh: &Mesh, seeds: &[VertexId], radius: f64) -> Vec<bool> {
    nearest_vertices(mesh, seeds, radius, usize::MAX).mask
}

/// A region of a mesh and how far it reaches.
#[derive(Clone, Debug, PartialEq)]
pub struct Region {
    /// One entry per vertex: whether it is in the region.
    pub mask: Vec<bool>,
    /// Every vertex nearer than this (along edges) to the seeds is in the region:
    /// infinite when the region holds the seeds' whole connected part.
    pub reach: f64,
}

/// [`region_around`] holding at most `max_vertices` vertices, the nearest: for a region
/// whose solve must stay within a time budget whatever the mesh's resolution.
pub fn nearest_vertices(
    mesh: &Mesh,
    seeds: &[VertexId],
    radius: f64,
    max_vertices: usize,
) -> Region {
    let seeds: Vec<u32> = seeds.iter().map(|v| v.0).collect();
    let mut mask = vec![false; mesh.n_vertices()];
    let mut n_settled = 0;
    let mut reach = f64::INFINITY;
    shortest_paths(
        mesh.n_vertices(),
        &seeds,
        radius,
        |v| {
            let p = mesh.position(VertexId(v));
            mesh.vertex_neighbors(VertexId(v))
                .map(move |w| (w.0, p.distance(mesh.position(w))))
        },
        |v, d| {
            mask[v as usize] = true;
            n_settled += 1;
            let is_full = n_settled >= max_vertices;
            if is_full {
                reach = d;
            }
            is_full
        },
    );
    let reach = if reach.is_finite() || radius.is_infinite() {
        reach
    } else {
        radius
    };
    Region { mask, reach }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::mesh::primitives;

    #[test]
    fn region_grows_with_the_radius_and_holds_the_seed() {
        let mesh = primitives::icosphere(1.0, 3);
        let count = |r: f64| {
            region_around(&mesh, &[VertexId(0)], r)
                .iter()
                .filter(|&&x| x)
                .count()
        };
        assert_eq!(count(0.0), 1);
        let (small, large) = (count(0.3), count(1.0));
        assert!(1 < small && small < large && large < mesh.n_vertices());
        assert_eq!(count(10.0), mesh.n_vertices());
        // Every vertex in the region is within the radius in space as well.
        let p = mesh.position(VertexId(0));
        let region = region_around(&mesh, &[VertexId(0)], 0.3);
        assert!(
            mesh.vertices()
                .filter(|v| region[v.index()])
                .all(|v| mesh.position(v).distance(p) <= 0.3 + 1e-12)
        );
    }

    #[test]
    fn a_vertex_budget_keeps_the_nearest_vertices() {
        let mesh = primitives::icosphere(1.0, 3);
        let whole = nearest_vertices(&mesh, &[VertexId(0)], f64::INFINITY, usize::MAX);
        assert!(whole.mask.iter().all(|&x| x));
        assert_eq!(whole.reach, f64::INFINITY);
        let budget = 100;
        let region = nearest_vertices(&mesh, &[VertexId(0)], f64::INFINITY, budget);
        assert_eq!(region.mask.iter().filter(|&&x| x).count(), budget);
        assert!(region.reach > 0.0 && region.reach.is_finite());
        // It is the ball that reaches as far: every vertex nearer is in, none farther.
        let ball = region_around(&mesh, &[VertexId(0)], region.reach);
        let below = region_around(&mesh, &[VertexId(0)], 0.999 * region.reach);
        for v in 0..mesh.n_vertices() {
            assert!(
                !below[v] || region.mask[v],
                "a nearer vertex {v} is missing"
            );
            assert!(
                !region.mask[v] || ball[v],
                "vertex {v} lies beyond the reach"
            );
        }
        // Within the budget, the radius decides.
        let small = nearest_vertices(&mesh, &[VertexId(0)], 0.3, budget);
        assert_eq!(small.mask, region_around(&mesh, &[VertexId(0)], 0.3));
        assert_eq!(small.reach, 0.3);
    }
}
