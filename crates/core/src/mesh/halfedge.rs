//! Half-edge navigation: index arithmetic within a face, twins across edges, and
//! counter-clockwise walks around a vertex.
//!
//! Around a vertex `v`, the previous half-edge of an outgoing half-edge ends at `v`, so its
//! twin leaves `v` in the next face counter-clockwise. A walk starting at
//! [`Mesh::vertex_halfedge`] therefore sees the whole fan: a boundary vertex's half-edge is the
//! clockwise-most one, and the walk stops at the other boundary edge.

use super::{FaceId, HalfedgeId, INVALID, Mesh, VertexId};

impl Mesh {
    /// The face a half-edge belongs to.
    pub fn face(&self, h: HalfedgeId) -> FaceId {
        FaceId(h.0 / 3)
    }

    /// The next half-edge around the same face.
    pub fn next(&self, h: HalfedgeId) -> HalfedgeId {
        HalfedgeId(if h.0 % 3 == 2 { h.0 - 2 } else { h.0 + 1 })
    }

    /// The previous half-edge around the same face.
    pub fn prev(&self, h: HalfedgeId) -> HalfedgeId {
        HalfedgeId(if h.0.is_multiple_of(3) {
            h.0 + 2
        } else {
            h.0 - 1
        })
    }

    /// The opposite half-edge, or `None` on the boundary.
    pub fn twin(&self, h: HalfedgeId) -> Option<HalfedgeId> {
        let t = self.twin[h.index()];
        (t != INVALID).then_some(HalfedgeId(t))
    }

    /// The vertex a half-edge starts from.
    pub fn tail(&self, h: HalfedgeId) -> VertexId {
        VertexId(self.triangles_flat()[h.index()])
    }

    /// The vertex a half-edge points to.
    pub fn head(&self, h: HalfedgeId) -> VertexId {
        self.tail(self.next(h))
    }

    /// The corner of `h`'s face that `h` does not touch.
    pub fn opposite_vertex(&self, h: HalfedgeId) -> VertexId {
        self.tail(self.prev(h))
    }

    /// The half-edge from `a` to `b`, if they are joined by an edge of a face on its left.
    pub fn find_halfedge(&self, a: VertexId, b: VertexId) -> Option<HalfedgeId> {
        self.outgoing_halfedges(a).find(|&h| self.head(h) == b)
    }

    /// A half-edge of the edge `a`–`b`, in either direction.
    pub fn find_edge(&self, a: VertexId, b: VertexId) -> Option<HalfedgeId> {
        self.find_halfedge(a, b)
            .or_else(|| self.find_halfedge(b, a))
    }

    /// One outgoing half-edge of `v`; on the boundary, the one with no twin.
    pub fn vertex_halfedge(&self, v: VertexId) -> HalfedgeId {
        HalfedgeId(self.vertex_halfedge[v.index()])
    }

    /// Whether a half-edge has no twin.
    pub fn is_boundary_halfedge(&self, h: HalfedgeId) -> bool {
        self.twin[h.index()] == INVALID
    }

    /// Whether `v` lies on the boundary (never for a deleted vertex).
    pub fn is_boundary_vertex(&self, v: VertexId) -> bool {
        let h = self.vertex_halfedge[v.index()];
        h != INVALID && self.twin[h as usize] == INVALID
    }

    /// Whether the mesh has no boundary edges.
    pub fn is_closed(&self) -> bool {
        self.twin.iter().all(|&t| t != INVALID)
    }

    /// Outgoing half-edges of `v`, counter-clockwise, starting at [`Mesh::vertex_halfedge`].
    pub fn outgoing_halfedges(&self, v: VertexId) -> OutgoingHalfedges<'_> {
        let start = self.vertex_halfedge(v);
        OutgoingHalfedges {
            mesh: self,
            start,
            // A deleted vertex has no half-edges.
            current: (start.0 != INVALID).then_some(start),
        }
    }

    /// The one-ring of `v` in counter-clockwise order; on the boundary, from one boundary
    /// neighbour to the other.
    pub fn vertex_neighbors(&self, v: VertexId) -> impl Iterator<Item = VertexId> + '_ {
        let first = self.outgoing_halfedges(v).map(|h| self.head(h));
        // A boundary fan has one more neighbour than outgoing half-edges: the tail of the last
        // face's incoming half-edge, which has no outgoing twin.
        let last = self.is_boundary_vertex(v).then(|| {
            let last_out = self
                .outgoing_halfedges(v)
                .last()
                .unwrap_or(self.vertex_halfedge(v));
            self.tail(self.prev(last_out))
        });
        first.chain(last)
    }

    /// Faces around `v`, counter-clockwise.
    pub fn vertex_faces(&self, v: VertexId) -> impl Iterator<Item = FaceId> + '_ {
        self.outgoing_halfedges(v).map(|h| self.face(h))
    }

    /// Number of edges at `v`.
    pub fn valence(&self, v: VertexId) -> usize {
        self.vertex_neighbors(v).count()
    }
}

/// Iterator over the outgoing half-edges of a vertex; see [`Mesh::outgoing_halfedges`].
#[derive(Clone, Debug)]
pub struct OutgoingHalfedges<'a> {
    mesh: &'a Mesh,
    start: HalfedgeId,
    current: Option<HalfedgeId>,
}

impl Iterator for OutgoingHalfedges<'_> {
    type Item = HalfedgeId;

    fn next(&mut self) -> Option<HalfedgeId> {
        let h = self.current?;
        // Counter-clockwise: the previous half-edge ends at our vertex; its twin leaves it.
        self.current = self
            .mesh
            .twin(self.mesh.prev(h))
            .filter(|&t| t != self.start);
        Some(h)
    }
}

#[cfg(test)]
mod tests {
    use crate::mesh::{FaceId, HalfedgeId, VertexId, primitives};

    #[test]
    fn navigation_is_index_arithmetic() {
        let mesh = primitives::icosphere(1.0, 0);
        let h = HalfedgeId(7);
        assert_eq!(mesh.face(h), FaceId(2));
        assert_eq!(mesh.next(h), HalfedgeId(8));
        assert_eq!(mesh.next(HalfedgeId(8)), HalfedgeId(6));
        assert_eq!(mesh.prev(HalfedgeId(6)), HalfedgeId(8));
        assert_eq!(mesh.next(mesh.prev(h)), h);
        let t = mesh.twin(h).unwrap();
        assert_eq!(mesh.tail(t), mesh.head(h));
        assert_eq!(mesh.head(t), mesh.tail(h));
    }

    #[test]
    fn one_ring_of_an_interior_grid_vertex_is_ordered() {
        // 2 x 2 cells: vertex 4 is the centre, with neighbours on a counter-clockwise cycle.
        let mesh = primitives::grid(2, 2, 2.0);
        let centre = VertexId(4);
        let ring: Vec<VertexId> = mesh.vertex_neighbors(centre).collect();
        assert_eq!(ring.len(), 6);
        assert!(!mesh.is_boundary_vertex(centre));
        let p = mesh.position(centre);
        for pair in ring.windows(2) {
            let a = mesh.position(pair[0]) - p;
            let b = mesh.position(pair[1]) - p;
            assert!(
                a.cross(b).z > 0.0,
                "ring is not counter-clockwise: {ring:?}"
            );
        }
    }

    #[test]
    fn one_ring_of_a_boundary_corner_runs_boundary_to_boundary() {
        let mesh = primitives::grid(2, 2, 2.0);
        for v in mesh.vertices().filter(|&v| v != VertexId(4)) {
            assert!(mesh.is_boundary_vertex(v));
            let ring: Vec<VertexId> = mesh.vertex_neighbors(v).collect();
            assert!(
                mesh.is_boundary_vertex(ring[0]) && mesh.is_boundary_vertex(ring[ring.len() - 1])
            );
            assert_eq!(ring.len(), mesh.vertex_faces(v).count() + 1);
        }
    }
}
