//! The mesh a curve is being embedded into, and the log of the edges it split on the way.

use glam::DVec3;

use crate::mesh::{FaceId, Mesh, VertexId};

/// A mesh under embedding: splits append vertices, so every input vertex keeps its id.
pub(super) struct Embedding {
    pub mesh: Mesh,
    /// Every edge split as `(a, b, new)`, in order.
    pub splits: Vec<(VertexId, VertexId, VertexId)>,
}

impl Embedding {
    pub fn new(mesh: &Mesh) -> Self {
        Self {
            mesh: mesh.clone(),
            splits: Vec::new(),
        }
    }

    /// Splits the edge `a`–`b` at `a + t (b − a)` and records it; returns the new vertex.
    pub fn split_edge(&mut self, a: VertexId, b: VertexId, t: f64) -> Option<VertexId> {
        let h = self.mesh.find_edge(a, b)?;
        let p = self.mesh.position(a).lerp(self.mesh.position(b), t);
        let m = self.mesh.split_edge(h, p);
        self.splits.push((a, b, m));
        Some(m)
    }

    /// Puts a vertex at the point with barycentric coordinates `bary` in face `f`: a corner
    /// within `snap` (in barycentric units) of it, else a point on an edge within `snap` of
    /// it, else a new interior vertex. Snapping avoids slivers.
    pub fn insert_point(&mut self, f: FaceId, bary: DVec3, snap: f64) -> Option<VertexId> {
        let corners = self.mesh.face_vertices(f);
        let bary = bary.max(DVec3::ZERO) / bary.max(DVec3::ZERO).element_sum();
        let nearest = bary.max_position();
        if bary[nearest] > 1.0 - snap {
            return Some(corners[nearest]);
        }
        let farthest = bary.min_position();
        if bary[farthest] < snap {
            let (i, j) = ((farthest + 1) % 3, (farthest + 2) % 3);
            let t = bary[j] / (bary[i] + bary[j]);
            return self.split_edge(corners[i], corners[j], t);
        }
        let [pa, pb, pc] = self.mesh.face_positions(f);
        Some(
            self.mesh
                .split_face(f, pa * bary.x + pb * bary.y + pc * bary.z),
        )
    }
}

#[cfg(test)]
mod tests {
    #![allow(clippy::unwrap_used)]

    use super::*;
    use crate::mesh::primitives::icosphere;

    #[test]
    fn splits_keep_a_valid_mesh_and_the_input_vertices() {
        let sphere = icosphere(1.0, 2);
        let mut embedding = Embedding::new(&sphere);
        let [a, b, _] = sphere.face_vertices(FaceId(5));
        let m = embedding.split_edge(a, b, 0.3).unwrap();
        embedding.insert_point(FaceId(7), DVec3::new(0.2, 0.3, 0.5), 0.1);
        let corner = embedding.insert_point(FaceId(0), DVec3::new(0.95, 0.04, 0.01), 0.1);
        assert_eq!(corner, Some(sphere.face_vertices(FaceId(0))[0]));
        assert_eq!(embedding.splits, vec![(a, b, m)]);
        let mesh = embedding.mesh;
        mesh.validate().unwrap();
        assert!(mesh.is_closed());
        assert_eq!(mesh.valence(m), 4);
        assert_eq!(&mesh.positions()[..sphere.n_vertices()], sphere.positions());
        assert_eq!(mesh.n_vertices(), sphere.n_vertices() + 2);
    }
}
