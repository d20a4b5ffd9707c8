//! Closing a hole: a fan of triangles over a boundary loop.

use crate::mesh::{FaceId, HalfedgeId, Mesh};

impl Mesh {
    /// Fills the boundary loop through the boundary half-edge `h`: a loop of three with one
    /// triangle, a longer one with a fan around a new vertex at the loop's centroid. Returns
    /// the new faces. The fan is only topology: a caller that wants a nice cap (a cut's flat
    /// cap, say) remeshes and optimizes it.
    ///
    /// Does nothing and returns no face when `h` is not a boundary half-edge.
    pub fn fill_boundary_loop(&mut self, h: HalfedgeId) -> Vec<FaceId> {
        if !self.is_boundary_halfedge(h) {
            return Vec::new();
        }
        let mut rim = vec![h];
        let mut g = self.vertex_halfedge(self.head(h));
        while g != h {
            rim.push(g);
            g = self.vertex_halfedge(self.head(g));
        }
        let first_face = self.n_faces() as u32;
        if let [a_b, b_c, c_a] = rim[..] {
            let (a, b, c) = (self.tail(a_b), self.tail(b_c), self.tail(c_a));
            let f = self.push_face([a, c, b]);
            self.link_twins(f.0, c_a.0);
            self.link_twins(f.0 + 1, b_c.0);
            self.link_twins(f.0 + 2, a_b.0);
        } else {
            let centroid = rim
                .iter()
                .map(|&e| self.position(self.tail(e)))
                .sum::<glam::DVec3>()
                / rim.len() as f64;
            let m = self.push_vertex(centroid);
            // Face k = (b, a, m) over rim edge a→b; its edge m→b meets face k+1's b→m.
            let n = rim.len() as u32;
            for &edge in &rim {
                let f = self.push_face([self.head(edge), self.tail(edge), m]);
                self.link_twins(f.0, edge.0);
            }
            for k in 0..n {
                let (f, g) = (3 * (first_face + k), 3 * (first_face + (k + 1) % n));
                self.link_twins(f + 2, g + 1);
            }
            self.set_vertex_halfedge_on(m, HalfedgeId(3 * first_face + 2), false);
        }
        for edge in rim {
            let v = self.tail(edge);
            self.set_vertex_halfedge_on(v, edge, false);
        }
        (first_face..self.n_faces() as u32).map(FaceId).collect()
    }
}

#[cfg(test)]
mod tests {
    use crate::mesh::{FaceId, HalfedgeId, VertexId, primitives};

    fn first_boundary_halfedge(mesh: &crate::mesh::Mesh) -> HalfedgeId {
        (0..mesh.n_halfedges() as u32)
            .map(HalfedgeId)
            .find(|&h| mesh.is_live_face(mesh.face(h)) && mesh.is_boundary_halfedge(h))
            .unwrap()
    }

    #[test]
    fn filling_the_hole_of_a_vertex_star_closes_the_sphere() {
        let mut mesh = primitives::icosphere(1.0, 2);
        let star: Vec<FaceId> = mesh.vertex_faces(VertexId(3)).collect();
        mesh.delete_faces(&star).unwrap();
        let faces = mesh.fill_boundary_loop(first_boundary_halfedge(&mesh));
        assert_eq!(faces.len(), star.len());
        mesh.validate().unwrap();
        mesh.compact();
        assert!(mesh.is_closed());
        assert_eq!(mesh.genus(), Some(0));
    }

    #[test]
    fn a_three_edge_hole_gets_one_triangle() {
        let mut mesh = primitives::icosphere(1.0, 1);
        mesh.delete_faces(&[FaceId(5)]).unwrap();
        let faces = mesh.fill_boundary_loop(first_boundary_halfedge(&mesh));
        assert_eq!(faces.len(), 1);
        mesh.validate().unwrap();
        mesh.compact();
        assert!(mesh.is_closed());
        assert_eq!(mesh.n_faces(), 80);
    }

    #[test]
    fn an_open_grid_closes_into_a_disk_pair() {
        let mut mesh = primitives::grid(3, 3, 1.0);
        mesh.fill_boundary_loop(first_boundary_halfedge(&mesh));
        mesh.validate().unwrap();
        assert!(mesh.is_closed());
        assert_eq!(mesh.euler_characteristic(), 2);
    }
}
