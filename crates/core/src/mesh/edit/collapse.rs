//! Collapsing an edge into one of its ends.

use crate::mesh::{HalfedgeId, INVALID, Mesh, VertexId};

impl Mesh {
    /// Collapses the edge of `h` by removing its end `r` (either one) with its one or two
    /// faces on the edge, which become tombstones; `r`'s edges join the other end `k`, which
    /// keeps its position.
    ///
    /// The caller checks the link condition (the ends share only the vertices opposite the
    /// edge) and that every vertex keeps a face: a collapse that breaks them breaks the mesh.
    pub fn collapse_edge(&mut self, h: HalfedgeId, r: VertexId) {
        let k = if self.tail(h) == r {
            self.head(h)
        } else {
            self.tail(h)
        };
        let t = self.twin[h.index()];
        // The kept vertex is on the boundary afterwards if either end was; the vertices
        // opposite the edge keep their status.
        let on_k = self.is_boundary_vertex(k) || self.is_boundary_vertex(r);
        let on_c = self.is_boundary_vertex(self.opposite_vertex(h));
        let on_d = t != INVALID && self.is_boundary_vertex(self.opposite_vertex(HalfedgeId(t)));
        // Renaming the tails of `r`'s outgoing half-edges renames it in every face.
        let start = self.vertex_halfedge(r);
        let mut g = start;
        loop {
            self.set_tail(g, k);
            match self.twin(self.prev(g)) {
                Some(u) if u != start => g = u,
                _ => break,
            }
        }
        self.kill_vertex(r);
        let (c, c_out, mut k_out) = self.remove_collapsed_face(h);
        if t != INVALID {
            let (d, d_out, k_out_d) = self.remove_collapsed_face(HalfedgeId(t));
            self.set_vertex_halfedge_on(d, d_out, on_d);
            k_out = k_out_d;
        }
        self.set_vertex_halfedge_on(c, c_out, on_c);
        self.set_vertex_halfedge_on(k, k_out, on_k);
    }

    /// Deletes the face of `h` (whose edge collapses, tails already renamed to the kept
    /// vertex `k`) and glues the twins of its two other edges; returns the face's third
    /// vertex `c`, a surviving half-edge leaving `c` and one leaving `k`.
    fn remove_collapsed_face(&mut self, h: HalfedgeId) -> (VertexId, HalfedgeId, HalfedgeId) {
        let (h1, h2) = (self.next(h), self.prev(h));
        let c = self.tail(h2);
        // `outer_1` runs c→k and `outer_2` k→c; at least one exists since `c` keeps a face.
        let (outer_1, outer_2) = (self.twin[h1.index()], self.twin[h2.index()]);
        self.link_twins(outer_1, outer_2);
        self.kill_face(self.face(h));
        let c_out = if outer_1 != INVALID {
            HalfedgeId(outer_1)
        } else {
            self.next(HalfedgeId(outer_2))
        };
        let k_out = if outer_2 != INVALID {
            HalfedgeId(outer_2)
        } else {
            self.next(HalfedgeId(outer_1))
        };
        (c, c_out, k_out)
    }
}

#[cfg(test)]
mod tests {
    use crate::mesh::{HalfedgeId, primitives};

    #[test]
    fn collapsing_an_edge_removes_a_vertex_and_two_faces() {
        let mut mesh = primitives::icosphere(1.0, 2);
        let (n_vertices, n_faces) = (mesh.n_vertices(), mesh.n_faces());
        let h = HalfedgeId(30);
        let (r, k) = (mesh.tail(h), mesh.head(h));
        let p_k = mesh.position(k);
        mesh.collapse_edge(h, r);
        mesh.validate().unwrap();
        assert!(!mesh.is_live_vertex(r) && mesh.is_live_vertex(k));
        assert!(!mesh.is_compact());
        let remap = mesh.compact();
        mesh.validate().unwrap();
        assert_eq!(mesh.n_vertices(), n_vertices - 1);
        assert_eq!(mesh.n_faces(), n_faces - 2);
        assert_eq!(remap.vertex(r), None);
        let k = remap.vertex(k).unwrap();
        assert_eq!(mesh.position(k), p_k);
        assert_eq!(mesh.genus(), Some(0));
        assert!(mesh.is_closed());
    }
}
