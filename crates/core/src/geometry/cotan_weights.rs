//! Guarded, normalised cotangent weights of the one-rings in an editing region.
//!
//! Row `i` of the editing system is Nealen's Eq. 4.4, `x_i - Σ_j w_ij x_j = δ_i`, with the
//! cotangent weights of Eq. 4.3 normalised to `Σ_j w_ij = 1`, so every row has unit weight on
//! its own vertex whatever the local sampling. Before normalising, each angle's cotangent is
//! clamped to `±COT_MAX` (a needle angle below about 0.6 degrees would otherwise dominate its
//! row) and each edge weight `(cot α + cot β) / 2` to at least zero: the non-Delaunay edges
//! that make it negative would flip the sign of an ARAP covariance term. A vertex whose
//! weights all vanish falls back to uniform weights.

use glam::DVec3;

use crate::mesh::{Mesh, VertexId};

/// Largest cotangent magnitude used, `cot(0.57°)`.
const COT_MAX: f64 = 100.0;

/// Compressed one-rings: for row vertex `i`, `neighbors[start[i]..start[i + 1]]` are the local
/// indices of its neighbours and `weights[..]` their normalised cotangent weights.
#[derive(Clone, Debug, Default)]
pub(crate) struct OneRingWeights {
    start: Vec<u32>,
    neighbors: Vec<u32>,
    weights: Vec<f64>,
}

impl OneRingWeights {
    /// Weights for `rows` (mesh vertices, in local order), with neighbours numbered by
    /// `local_of`; every neighbour of a row vertex must have a local index.
    pub(crate) fn new(mesh: &Mesh, rows: &[VertexId], local_of: impl Fn(VertexId) -> u32) -> Self {
        let mut rings = OneRingWeights {
            start: Vec::with_capacity(rows.len() + 1),
            neighbors: Vec::with_capacity(7 * rows.len()),
            weights: Vec::with_capacity(7 * rows.len()),
        };
        rings.start.push(0);
        let mut ring_vertices = Vec::new();
        for &v in rows {
            ring_vertices.clear();
            ring_vertices.extend(mesh.vertex_neighbors(v));
            let first = rings.weights.len();
            rings.weights.resize(first + ring_vertices.len(), 0.0);
            let ring_weights = &mut rings.weights[first..];
            let slot = |u: VertexId| ring_vertices.iter().position(|&r| r == u);
            let p = mesh.position(v);
            for h in mesh.outgoing_halfedges(v) {
                // Face (v, j, k): the angle at k faces edge vj, the angle at j faces edge vk.
                let j = mesh.head(h);
                let k = mesh.tail(mesh.prev(h));
                let (pj, pk) = (mesh.position(j), mesh.position(k));
                if let (Some(sj), Some(sk)) = (slot(j), slot(k)) {
                    ring_weights[sj] += 0.5 * guarded_cot(p - pk, pj - pk);
                    ring_weights[sk] += 0.5 * guarded_cot(p - pj, pk - pj);
                }
            }
            ring_weights.iter_mut().for_each(|w| *w = w.max(0.0));
            let total: f64 = ring_weights.iter().sum();
            let n = ring_weights.len() as f64;
            for w in ring_weights.iter_mut() {
                *w = if total > 0.0 { *w / total } else { 1.0 / n };
            }
            rings
                .neighbors
                .extend(ring_vertices.iter().map(|&u| local_of(u)));
            rings.start.push(rings.weights.len() as u32);
        }
        rings
    }

    /// Number of row vertices.
    pub(crate) fn n_rows(&self) -> usize {
        self.start.len() - 1
    }

    /// `(neighbour local index, weight)` of row `i`.
    pub(crate) fn ring(&self, i: usize) -> impl Iterator<Item = (usize, f64)> + '_ {
        let range = self.start[i] as usize..self.start[i + 1] as usize;
        self.neighbors[range.clone()]
            .iter()
            .zip(&self.weights[range])
            .map(|(&j, &w)| (j as usize, w))
    }
}

/// The cotangent of the angle between `u` and `v`, clamped to `±COT_MAX`.
fn guarded_cot(u: DVec3, v: DVec3) -> f64 {
    let cos = u.dot(v);
    let sin = u.cross(v).length();
    if sin * COT_MAX <= cos.abs() {
        COT_MAX.copysign(cos)
    } else {
        cos / sin
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::mesh::{TriSoup, primitives};

    fn identity_rings(mesh: &Mesh) -> OneRingWeights {
        let rows: Vec<VertexId> = mesh.vertices().collect();
        OneRingWeights::new(mesh, &rows, |v| v.0)
    }

    #[test]
    fn flat_patch_weights_reproduce_the_centre() {
        // Interior rows of a flat mesh: Σ w_j p_j = p_i (linear precision), weights sum to 1.
        let mesh = primitives::grid(6, 5, 2.0);
        let rings = identity_rings(&mesh);
        let p = mesh.positions();
        for v in mesh.vertices().filter(|&v| !mesh.is_boundary_vertex(v)) {
            let ring: Vec<(usize, f64)> = rings.ring(v.index()).collect();
            let sum: f64 = ring.iter().map(|r| r.1).sum();
            let mean: DVec3 = ring.iter().map(|&(j, w)| w * p[j]).sum();
            assert!((sum - 1.0).abs() < 1e-14);
            assert!(
                (mean - p[v.index()]).length() < 1e-14,
                "{mean} vs {}",
                p[v.index()]
            );
        }
    }

    #[test]
    fn regular_sphere_weights_match_the_closed_form() {
        // An icosahedron's vertex: 5 equilateral faces, every weight 1/5.
        let mesh = primitives::icosphere(1.0, 0);
        let rings = identity_rings(&mesh);
        for (_, w) in rings.ring(0) {
            assert!((w - 0.2).abs() < 1e-14);
        }
    }

    #[test]
    fn needles_and_obtuse_edges_are_guarded() {
        // Vertex 2 lies almost on edge 01: angles near 0 and 180 degrees, and edge 01 gets
        // a negative cotangent sum.
        let soup = TriSoup {
            positions: vec![
                DVec3::ZERO,
                DVec3::new(2.0, 0.0, 0.0),
                DVec3::new(1.0, 1e-12, 0.0),
                DVec3::new(1.0, -1.0, 0.0),
            ],
            triangles: vec![[0, 1, 2], [0, 3, 1]],
        };
        let mesh = Mesh::from_soup(&soup).unwrap();
        let rings = identity_rings(&mesh);
        for i in 0..mesh.n_vertices() {
            let weights: Vec<f64> = rings.ring(i).map(|r| r.1).collect();
            assert!(
                weights.iter().all(|w| w.is_finite() && *w >= 0.0),
                "{weights:?}"
            );
            assert!((weights.iter().sum::<f64>() - 1.0).abs() < 1e-12);
        }
    }
}
