//! Per-iteration geometry for the fair-surface optimization: vertex normals, vertex areas,
//! current Laplacian magnitudes and mean incident edge lengths, into reused buffers.
//!
//! Conventions (FiberMesh §3.3.2, with the Laplacian `L v_i = v_i - mean_j v_j` of
//! [`crate::geometry`]):
//! - `n_i` is the area-weighted normal (sum of face cross products, normalised). Where the
//!   faces cancel (a vertex on a fold of a flat doubled disk) it falls back to the
//!   direction of `L v_i`.
//! - The "area estimate" `A_i` is the mean squared length of the edges at `i`. A neighbour
//!   at distance `ℓ_j` on a sphere of radius `R` lies `ℓ_j² / 2R` below the tangent plane,
//!   so `L v_i · n_i = mean_j ℓ_j² / 2R` and `c'_i = L v_i · n_i / A_i = 1 / 2R = H / 2`
//!   exactly, for any valence and spacing. With the barycentric area instead, `c'` of a
//!   sphere would vary with valence (by 1.5× between the outline's valence-4 vertices and
//!   the lattice's valence 6), and smoothing those values would bend the sphere.
//! - The Laplacian magnitude `c'_i` is signed: positive on convex parts with outward
//!   normals, where `v_i` lies outside its neighbours' centroid. The position solve asks
//!   for `L v_i = A_i c_i n_i`, so a vertex keeps the normal part of its Laplacian and
//!   loses the tangential part, which evens out the sampling.

use glam::DVec3;

/// The neighbours of every vertex in compressed rows.
#[derive(Clone, Debug, Default)]
pub(crate) struct Rings {
    /// Start of each vertex's ring in `neighbors` (`n + 1` entries).
    pub start: Vec<u32>,
    /// Neighbour indices.
    pub neighbors: Vec<u32>,
}

impl Rings {
    /// The one-rings of a mesh, counter-clockwise.
    #[cfg(test)]
    pub(crate) fn of_mesh(mesh: &crate::mesh::Mesh) -> Rings {
        let mut rings = Rings {
            start: Vec::with_capacity(mesh.n_vertices() + 1),
            neighbors: Vec::new(),
        };
        rings.start.push(0);
        for v in mesh.vertices() {
            rings
                .neighbors
                .extend(mesh.vertex_neighbors(v).map(|u| u.0));
            rings.start.push(rings.neighbors.len() as u32);
        }
        rings
    }

    /// The rings of a graph on `n` vertices given by undirected edges.
    pub(crate) fn from_edges(n: usize, edges: impl IntoIterator<Item = [u32; 2]>) -> Rings {
        let mut directed: Vec<[u32; 2]> = edges
            .into_iter()
            .flat_map(|[a, b]| [[a, b], [b, a]])
            .collect();
        directed.sort_unstable();
        directed.dedup();
        let mut start = vec![0u32; n + 1];
        for &[a, _] in &directed {
            start[a as usize + 1] += 1;
        }
        for i in 0..n {
            start[i + 1] += start[i];
        }
        Rings {
            start,
            neighbors: directed.iter().map(|&[_, b]| b).collect(),
        }
    }

    /// The ring of vertex `i`.
    pub(crate) fn ring(&self, i: usize) -> &[u32] {
        &self.neighbors[self.start[i] as usize..self.start[i + 1] as usize]
    }

    /// Number of vertices.
    pub(crate) fn len(&self) -> usize {
        self.start.len() - 1
    }
}

/// Geometry measured on the current positions.
#[derive(Clone, Debug, Default)]
pub(crate) struct Measures {
    /// Unit vertex normals (zero where nothing defines one).
    pub normals: Vec<DVec3>,
    /// Area estimates: mean squared length of the edges at each vertex.
    pub areas: Vec<f64>,
    /// Current signed Laplacian magnitudes `c'_i`.
    pub magnitudes: Vec<f64>,
    /// Current mean length of the edges at each vertex.
    pub edge_lengths: Vec<f64>,
}

impl Measures {
    /// Buffers for `n` vertices.
    pub(crate) fn new(n: usize) -> Measures {
        Measures {
            normals: vec![DVec3::ZERO; n],
            areas: vec![0.0; n],
            magnitudes: vec![0.0; n],
            edge_lengths: vec![0.0; n],
        }
    }

    /// Measures `positions`; allocates nothing.
    pub(crate) fn update(&mut self, triangles: &[[u32; 3]], rings: &Rings, positions: &[DVec3]) {
        self.normals.fill(DVec3::ZERO);
        // Twice the summed area of the faces at each vertex, to detect cancelling normals.
        self.areas.fill(0.0);
        for t in triangles {
            let [a, b, c] = t.map(|i| positions[i as usize]);
            let cross = (b - a).cross(c - a);
            let double_area = cross.length();
            for &i in t {
                self.normals[i as usize] += cross;
                self.areas[i as usize] += double_area;
            }
        }
        for i in 0..rings.len() {
            let ring = rings.ring(i);
            let p = positions[i];
            let (mut sum, mut length, mut squared) = (DVec3::ZERO, 0.0, 0.0);
            for &j in ring {
                let q = positions[j as usize];
                sum += q;
                length += p.distance(q);
                squared += p.distance_squared(q);
            }
            let count = ring.len().max(1) as f64;
            let laplacian = p - sum / count;
            // Faces that cancel leave a sum far shorter than their areas.
            let is_degenerate = self.normals[i].length() <= 1e-6 * self.areas[i];
            let normal = if is_degenerate {
                laplacian
            } else {
                self.normals[i]
            };
            self.normals[i] = normal.normalize_or_zero();
            self.areas[i] = squared / count;
            self.magnitudes[i] = if self.areas[i] > 0.0 {
                laplacian.dot(self.normals[i]) / self.areas[i]
            } else {
                0.0
            };
            self.edge_lengths[i] = length / count;
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::mesh::primitives;

    #[test]
    fn rings_from_edges() {
        let rings = Rings::from_edges(4, [[0, 1], [1, 2], [2, 0], [1, 0]]);
        assert_eq!(rings.len(), 4);
        assert_eq!(rings.ring(0), &[1, 2]);
        assert_eq!(rings.ring(1), &[0, 2]);
        assert!(rings.ring(3).is_empty());
    }

    #[test]
    fn sphere_measures_match_closed_forms() {
        // On a sphere the normals are radial and every magnitude is 1 / 2r, whatever the
        // valence (the icosphere has valence 5 and 6) and the uneven spacing.
        let radius = 2.0;
        let mesh = primitives::icosphere(radius, 4);
        let mut m = Measures::new(mesh.n_vertices());
        m.update(mesh.triangles(), &Rings::of_mesh(&mesh), mesh.positions());
        for (p, n) in mesh.positions().iter().zip(&m.normals) {
            assert!(n.dot(p.normalize()) > 0.999);
        }
        let mean = m.magnitudes.iter().sum::<f64>() / m.magnitudes.len() as f64;
        assert!(
            m.magnitudes
                .iter()
                .all(|&c| c > 0.0 && (c - mean).abs() < 0.25 * mean)
        );
        let mean_length = m.edge_lengths.iter().sum::<f64>() / m.edge_lengths.len() as f64;
        assert!((mean_length - 0.15).abs() < 0.03, "{mean_length}");
    }
}
