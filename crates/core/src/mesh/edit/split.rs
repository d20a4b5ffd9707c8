//! Splitting an edge or a face at a new vertex.

use glam::DVec3;

use crate::mesh::{FaceId, HalfedgeId, INVALID, Mesh, VertexId};

impl Mesh {
    /// Splits the edge of `h` at `p` into two edges and each of its (one or two) faces into
    /// two; returns the new vertex.
    ///
    /// Face `(a, b, c)` of `h = a→b` keeps its slots as `(a, m, c)` and gains `(m, b, c)`; the
    /// twin face `(b, a, d)` becomes `(m, a, d)` and gains `(b, m, d)`. Every other face and
    /// every half-edge id outside the two faces stays.
    pub fn split_edge(&mut self, h: HalfedgeId, p: DVec3) -> VertexId {
        let (h1, h2) = (self.next(h), self.prev(h));
        let (a, b, c) = (self.tail(h), self.head(h), self.tail(h2));
        let [on_a, on_b, on_c] = [a, b, c].map(|v| self.is_boundary_vertex(v));
        let t = self.twin[h.index()];
        let m = self.push_vertex(p);
        let outer_bc = self.twin[h1.index()];
        self.set_tail(h1, m);
        let g = self.push_face([m, b, c]);
        self.link_twins(g.0 + 1, outer_bc);
        self.link_twins(h1.0, g.0 + 2);
        if t != INVALID {
            let t = HalfedgeId(t);
            let t2 = self.prev(t);
            let d = self.tail(t2);
            let on_d = self.is_boundary_vertex(d);
            let outer_bd = self.twin[t2.index()];
            self.set_tail(t, m);
            let k = self.push_face([b, m, d]);
            self.link_twins(k.0 + 2, outer_bd);
            self.link_twins(t2.0, k.0 + 1);
            self.link_twins(g.0, k.0);
            self.set_vertex_halfedge_on(d, t2, on_d);
        }
        self.set_vertex_halfedge_on(m, g, t == INVALID);
        self.set_vertex_halfedge_on(b, HalfedgeId(g.0 + 1), on_b);
        self.set_vertex_halfedge_on(a, h, on_a);
        self.set_vertex_halfedge_on(c, h2, on_c);
        m
    }

    /// Splits face `f = (a, b, c)` at `p` into `(a, b, m)` (in `f`'s slots), `(b, c, m)` and
    /// `(c, a, m)`; returns the new vertex `m`.
    pub fn split_face(&mut self, f: FaceId, p: DVec3) -> VertexId {
        let h0 = HalfedgeId(3 * f.0);
        let (h1, h2) = (self.next(h0), self.prev(h0));
        let [a, b, c] = self.face_vertices(f);
        let [on_a, on_b, on_c] = [a, b, c].map(|v| self.is_boundary_vertex(v));
        let (outer_bc, outer_ca) = (self.twin[h1.index()], self.twin[h2.index()]);
        let m = self.push_vertex(p);
        self.set_tail(h2, m);
        let g = self.push_face([b, c, m]);
        let k = self.push_face([c, a, m]);
        self.link_twins(g.0, outer_bc);
        self.link_twins(k.0, outer_ca);
        self.link_twins(h1.0, g.0 + 2);
        self.link_twins(g.0 + 1, k.0 + 2);
        self.link_twins(k.0 + 1, h2.0);
        self.set_vertex_halfedge_on(m, h2, false);
        self.set_vertex_halfedge_on(a, h0, on_a);
        self.set_vertex_halfedge_on(b, g, on_b);
        self.set_vertex_halfedge_on(c, k, on_c);
        m
    }
}

#[cfg(test)]
mod tests {
    use glam::DVec3;

    use crate::mesh::{FaceId, HalfedgeId, VertexId, primitives};

    #[test]
    fn splitting_an_interior_edge_adds_one_vertex_two_faces_and_keeps_ids() {
        let mut mesh = primitives::icosphere(1.0, 1);
        let before = mesh.clone();
        let h = HalfedgeId(4);
        let (a, b) = (mesh.tail(h), mesh.head(h));
        let p = mesh.position(a).midpoint(mesh.position(b));
        let m = mesh.split_edge(h, p);
        mesh.validate().unwrap();
        assert_eq!(m, VertexId(before.n_vertices() as u32));
        assert_eq!(mesh.n_faces(), before.n_faces() + 2);
        assert_eq!(mesh.valence(m), 4);
        assert!(mesh.vertex_neighbors(m).any(|w| w == a));
        assert!(mesh.vertex_neighbors(m).any(|w| w == b));
        assert!(!mesh.vertex_neighbors(a).any(|w| w == b));
        assert_eq!(mesh.genus(), Some(0));
        assert_eq!(&mesh.positions()[..before.n_vertices()], before.positions());
    }

    #[test]
    fn splitting_a_boundary_edge_makes_a_boundary_vertex() {
        let mut mesh = primitives::grid(2, 2, 1.0);
        let h = (0..mesh.n_halfedges() as u32)
            .map(HalfedgeId)
            .find(|&h| mesh.is_boundary_halfedge(h))
            .unwrap();
        let m = mesh.split_edge(h, DVec3::new(0.5, -0.5, 0.0));
        mesh.validate().unwrap();
        assert!(mesh.is_boundary_vertex(m));
        assert_eq!(mesh.valence(m), 3);
        assert_eq!(mesh.boundary_loops()[0].len(), 9);
    }

    #[test]
    fn splitting_a_face_keeps_its_orientation() {
        let mut mesh = primitives::grid(1, 1, 1.0);
        let f = FaceId(0);
        let [a, b, c] = mesh.face_positions(f);
        let normal = (b - a).cross(c - a);
        let m = mesh.split_face(f, (a + b + c) / 3.0);
        mesh.validate().unwrap();
        assert_eq!(mesh.valence(m), 3);
        assert!(!mesh.is_boundary_vertex(m));
        for g in mesh.vertex_faces(m) {
            let [p, q, r] = mesh.face_positions(g);
            assert!((q - p).cross(r - p).dot(normal) > 0.0);
        }
        assert_eq!(mesh.n_faces(), 4);
    }
}
