//! Dropping tombstones, and appending another mesh as a new component.

use crate::mesh::{FaceId, INVALID, Mesh, VertexId};

/// Where [`Mesh::compact`] moved each vertex and face: `None` for deleted ones.
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct Remap {
    vertices: Vec<Option<VertexId>>,
    faces: Vec<Option<FaceId>>,
}

impl Remap {
    /// The new id of old vertex `v`, or `None` if it was deleted.
    pub fn vertex(&self, v: VertexId) -> Option<VertexId> {
        self.vertices.get(v.index()).copied().flatten()
    }

    /// The new id of old face `f`, or `None` if it was deleted.
    pub fn face(&self, f: FaceId) -> Option<FaceId> {
        self.faces.get(f.index()).copied().flatten()
    }

    /// The new id of every old vertex, in old order.
    pub fn vertices(&self) -> &[Option<VertexId>] {
        &self.vertices
    }
}

impl Mesh {
    /// Drops the tombstones, keeping the order of the live vertices and faces, and returns
    /// where each one went. Each vertex's starting half-edge is chosen afresh as
    /// [`Mesh::from_soup`] chooses it, so the result's navigation depends only on its
    /// positions and triangles, not on the edits that made them.
    pub fn compact(&mut self) -> Remap {
        let mut vertices = vec![None; self.n_vertices()];
        let mut n_live = 0u32;
        for v in self.vertices() {
            if self.is_live_vertex(v) {
                vertices[v.index()] = Some(VertexId(n_live));
                self.positions[n_live as usize] = self.positions[v.index()];
                n_live += 1;
            }
        }
        self.positions.truncate(n_live as usize);
        let mut faces = vec![None; self.n_faces()];
        let mut n_live = 0u32;
        for f in self.faces() {
            if self.is_live_face(f) {
                faces[f.index()] = Some(FaceId(n_live));
                n_live += 1;
            }
        }
        let new_halfedge = |h: u32| faces[h as usize / 3].map_or(INVALID, |f| 3 * f.0 + h % 3);
        for (old, new) in faces.iter().enumerate() {
            let Some(new) = new.map(|f| f.index()) else {
                continue;
            };
            let corners =
                self.triangles[old].map(|v| vertices[v as usize].map_or(INVALID, |v| v.0));
            self.triangles[new] = corners;
            for k in 0..3 {
                let t = self.twin[3 * old + k];
                self.twin[3 * new + k] = if t == INVALID {
                    INVALID
                } else {
                    new_halfedge(t)
                };
            }
        }
        self.triangles.truncate(n_live as usize);
        self.twin.truncate(3 * n_live as usize);
        self.vertex_halfedge = vec![INVALID; self.positions.len()];
        self.assign_vertex_halfedges();
        self.n_dead_vertices = 0;
        self.n_dead_faces = 0;
        Remap { vertices, faces }
    }

    /// Appends `other` as new components; returns the ids its first vertex and face got.
    /// Nothing joins it to what is there: merging is the caller's next edit.
    pub fn add_component(&mut self, other: &Mesh) -> (VertexId, FaceId) {
        let (v0, f0) = (self.n_vertices() as u32, self.n_faces() as u32);
        let shift = |base: u32| move |i: u32| if i == INVALID { INVALID } else { i + base };
        self.positions.extend_from_slice(&other.positions);
        self.triangles
            .extend(other.triangles.iter().map(|t| t.map(shift(v0))));
        self.twin
            .extend(other.twin.iter().map(|&t| shift(3 * f0)(t)));
        self.vertex_halfedge
            .extend(other.vertex_halfedge.iter().map(|&h| shift(3 * f0)(h)));
        self.n_dead_vertices += other.n_dead_vertices;
        self.n_dead_faces += other.n_dead_faces;
        (VertexId(v0), FaceId(f0))
    }
}

#[cfg(test)]
mod tests {
    use glam::DVec3;

    use crate::mesh::{Mesh, primitives};

    #[test]
    fn compacting_a_compact_mesh_gives_the_mesh_built_from_its_soup() {
        let mut mesh = primitives::torus(2.0, 0.5, 12, 6);
        mesh.flip_edge(crate::mesh::HalfedgeId(7));
        let rebuilt = Mesh::from_soup(&mesh.to_soup()).unwrap();
        mesh.compact();
        assert_eq!(mesh, rebuilt);
    }

    #[test]
    fn an_added_component_keeps_both_shapes() {
        let mut mesh = primitives::icosphere(1.0, 1);
        let mut other = primitives::torus(3.0, 1.0, 8, 4);
        other
            .positions_mut()
            .iter_mut()
            .for_each(|p| *p += DVec3::X * 9.0);
        let (v0, f0) = mesh.add_component(&other);
        mesh.validate().unwrap();
        assert_eq!((v0.0, f0.0), (42, 80));
        assert_eq!(mesh.n_components(), 2);
        assert_eq!(mesh.genus(), Some(1));
        assert_eq!(mesh.position(v0), other.position(crate::mesh::VertexId(0)));
    }
}
