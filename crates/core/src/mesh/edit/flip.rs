//! Flipping an interior edge to the other diagonal of its two triangles.

use crate::mesh::{HalfedgeId, Mesh};

impl Mesh {
    /// Flips the interior edge of `h = a→b` between faces `(a, b, c)` and `(b, a, d)` into the
    /// edge `c–d`, leaving faces `(a, d, c)` and `(b, c, d)` in the same slots; does nothing on
    /// the boundary. The caller checks that `c` and `d` are not already joined, which the flip
    /// would make a doubled edge.
    pub fn flip_edge(&mut self, h: HalfedgeId) {
        let Some(t) = self.twin(h) else { return };
        let (h1, h2, t1, t2) = (self.next(h), self.prev(h), self.next(t), self.prev(t));
        let (a, b, c, d) = (self.tail(h), self.head(h), self.tail(h2), self.tail(t2));
        let [on_a, on_b, on_c, on_d] = [a, b, c, d].map(|v| self.is_boundary_vertex(v));
        let [outer_bc, outer_ca, outer_ad, outer_db] =
            [h1, h2, t1, t2].map(|s| self.twin[s.index()]);
        for (slot, v) in [(h, d), (h1, c), (h2, a), (t, c), (t1, d), (t2, b)] {
            self.set_tail(slot, v);
        }
        self.link_twins(h1.0, outer_ca);
        self.link_twins(h2.0, outer_ad);
        self.link_twins(t1.0, outer_db);
        self.link_twins(t2.0, outer_bc);
        self.set_vertex_halfedge_on(a, h2, on_a);
        self.set_vertex_halfedge_on(b, t2, on_b);
        self.set_vertex_halfedge_on(c, h1, on_c);
        self.set_vertex_halfedge_on(d, t1, on_d);
    }
}

#[cfg(test)]
mod tests {
    use crate::mesh::{HalfedgeId, primitives};

    #[test]
    fn flipping_twice_restores_the_connectivity() {
        let mut mesh = primitives::icosphere(1.0, 1);
        let h = HalfedgeId(10);
        let t = mesh.twin(h).unwrap();
        let (c, d) = (mesh.tail(mesh.prev(h)), mesh.tail(mesh.prev(t)));
        let valences = [c, d].map(|v| mesh.valence(v));
        mesh.flip_edge(h);
        mesh.validate().unwrap();
        assert!(mesh.vertex_neighbors(c).any(|w| w == d));
        assert_eq!([c, d].map(|v| mesh.valence(v)), valences.map(|n| n + 1));
        mesh.flip_edge(h);
        mesh.validate().unwrap();
        assert!(!mesh.vertex_neighbors(c).any(|w| w == d));
        assert_eq!(mesh.genus(), Some(0));
    }
}
