//! [`Mesh::validate`]: every invariant of the half-edge arrays, checked from scratch.
//!
//! Like geometry-central's `validateConnectivity()`, this re-derives what it can instead of
//! trusting the stored arrays, so it catches bugs in future mutation code. It costs O(n log n)
//! and allocates; call it after each mutation in debug builds and in every test.

use super::{INVALID, Mesh, MeshError};

fn broken(sentence: String) -> MeshError {
    MeshError::InvalidConnectivity(sentence)
}

impl Mesh {
    /// Checks every invariant listed in the [module docs](crate::mesh).
    pub fn validate(&self) -> Result<(), MeshError> {
        self.validate_sizes()?;
        self.validate_triangles()?;
        if let Some(vertex) = self.positions.iter().position(|p| !p.is_finite()) {
            return Err(MeshError::NonFinitePosition {
                vertex: vertex as u32,
            });
        }
        self.validate_twins()?;
        self.validate_vertex_fans()
    }

    fn validate_sizes(&self) -> Result<(), MeshError> {
        if self.twin.len() != 3 * self.triangles.len() {
            return Err(broken(format!(
                "there are {} twins for {} half-edges.",
                self.twin.len(),
                3 * self.triangles.len()
            )));
        }
        if self.vertex_halfedge.len() != self.positions.len() {
            return Err(broken(format!(
                "there are {} vertex half-edges for {} vertices.",
                self.vertex_halfedge.len(),
                self.positions.len()
            )));
        }
        Ok(())
    }

    /// Live triangles are in range and have distinct corners; tombstones are whole, and
    /// there are as many as counted.
    fn validate_triangles(&self) -> Result<(), MeshError> {
        let (live, dead): (Vec<[u32; 3]>, Vec<[u32; 3]>) =
            self.triangles.iter().partition(|t| t[0] != INVALID);
        super::build::check_triangles(&live, self.n_vertices())?;
        if dead.iter().any(|t| t.iter().any(|&v| v != INVALID)) {
            return Err(broken(String::from("a deleted face keeps a corner.")));
        }
        if dead.len() != self.n_dead_faces as usize {
            return Err(broken(format!(
                "{} faces are deleted but {} are counted.",
                dead.len(),
                self.n_dead_faces
            )));
        }
        Ok(())
    }

    /// Twins pair opposite half-edges, and no directed edge occurs twice.
    fn validate_twins(&self) -> Result<(), MeshError> {
        let n_halfedges = self.n_halfedges() as u32;
        let is_live = |h: super::HalfedgeId| self.is_live_face(self.face(h));
        for h in (0..n_halfedges).map(super::HalfedgeId) {
            let Some(t) = self.twin(h) else { continue };
            if !is_live(h) {
                return Err(broken(format!("deleted half-edge {} has a twin.", h.0)));
            }
            if t.0 >= n_halfedges || t == h || !is_live(t) {
                return Err(broken(format!(
                    "half-edge {} has twin {}, which is not valid.",
                    h.0, t.0
                )));
            }
            if self.twin[t.index()] != h.0 {
                return Err(broken(format!(
                    "half-edge {} is the twin of {}, but not the reverse.",
                    t.0, h.0
                )));
            }
            if self.tail(t) != self.head(h) || self.head(t) != self.tail(h) {
                return Err(broken(format!(
                    "half-edges {} and {} are twins but not opposite.",
                    h.0, t.0
                )));
            }
        }
        let mut directed: Vec<(u32, u32)> = (0..n_halfedges)
            .map(super::HalfedgeId)
            .filter(|&h| is_live(h))
            .map(|h| (self.tail(h).0, self.head(h).0))
            .collect();
        directed.sort_unstable();
        if let Some(pair) = directed.windows(2).find(|pair| pair[0] == pair[1]) {
            let (a, b) = pair[0];
            return Err(broken(format!(
                "the edge from vertex {a} to {b} occurs twice."
            )));
        }
        Ok(())
    }

    /// Each vertex's half-edge leaves it, is a boundary half-edge on the boundary, and a walk
    /// from it visits every half-edge leaving the vertex (one fan).
    fn validate_vertex_fans(&self) -> Result<(), MeshError> {
        let mut n_outgoing = vec![0usize; self.n_vertices()];
        let mut is_boundary = vec![false; self.n_vertices()];
        for (h, &v) in self.triangles.as_flattened().iter().enumerate() {
            if v != INVALID {
                n_outgoing[v as usize] += 1;
                is_boundary[v as usize] |= self.twin[h] == INVALID;
            }
        }
        let mut n_dead = 0;
        for v in self.vertices() {
            let h = self.vertex_halfedge[v.index()];
            if h == INVALID && n_outgoing[v.index()] == 0 && n_dead < self.n_dead_vertices {
                // A tombstone: deleted with its last face.
                n_dead += 1;
                continue;
            }
            if h == INVALID {
                return Err(MeshError::IsolatedVertex { vertex: v.0 });
            }
            if h as usize >= self.n_halfedges() || self.tail(super::HalfedgeId(h)) != v {
                return Err(broken(format!(
                    "the half-edge of vertex {} does not leave it.",
                    v.0
                )));
            }
            if is_boundary[v.index()] && !self.is_boundary_vertex(v) {
                return Err(broken(format!(
                    "vertex {} is on the boundary but its half-edge is not a boundary half-edge.",
                    v.0
                )));
            }
            if self.outgoing_halfedges(v).count() != n_outgoing[v.index()] {
                return Err(MeshError::NonManifoldVertex { vertex: v.0 });
            }
        }
        if n_dead != self.n_dead_vertices {
            return Err(broken(format!(
                "{n_dead} vertices are deleted but {} are counted.",
                self.n_dead_vertices
            )));
        }
        Ok(())
    }
}

#[cfg(test)]
mod tests {
    use crate::mesh::{HalfedgeId, Mesh, MeshError, TriSoup, VertexId, fixtures, primitives};
    use glam::DVec3;
    use proptest::prelude::*;

    #[test]
    fn every_fixture_is_valid() {
        for fixture in fixtures::all() {
            assert_eq!(fixture.mesh.validate(), Ok(()), "{}", fixture.name);
        }
    }

    #[test]
    fn detects_broken_arrays() {
        let good = primitives::icosphere(1.0, 1);

        let mut mesh = good.clone();
        mesh.twin[5] = mesh.twin[6];
        assert!(matches!(
            mesh.validate(),
            Err(MeshError::InvalidConnectivity(_))
        ));

        let mut mesh = good.clone();
        mesh.vertex_halfedge[3] = mesh.vertex_halfedge[4];
        assert!(matches!(
            mesh.validate(),
            Err(MeshError::InvalidConnectivity(_))
        ));

        let mut mesh = good.clone();
        mesh.positions_mut()[2].x = f64::INFINITY;
        assert_eq!(
            mesh.validate(),
            Err(MeshError::NonFinitePosition { vertex: 2 })
        );

        // Point a boundary vertex at one of its interior half-edges.
        let mut mesh = primitives::grid(2, 2, 1.0);
        let v = VertexId(1);
        let interior = (0..mesh.n_halfedges() as u32)
            .map(HalfedgeId)
            .find(|&h| mesh.tail(h) == v && !mesh.is_boundary_halfedge(h))
            .unwrap();
        mesh.vertex_halfedge[v.index()] = interior.0;
        assert!(matches!(
            mesh.validate(),
            Err(MeshError::InvalidConnectivity(_))
        ));
    }

    /// A random subset of a mesh's faces, with unused vertices dropped.
    fn face_subset(mesh: &Mesh, keep: &[bool]) -> TriSoup {
        let mut soup = mesh.to_soup();
        soup.triangles = soup
            .triangles
            .iter()
            .zip(keep.iter().cycle())
            .filter(|(_, k)| **k)
            .map(|(t, _)| *t)
            .collect();
        soup.remove_unreferenced_vertices();
        soup
    }

    fn check_subset(mesh: &Mesh, keep: &[bool]) -> Result<(), TestCaseError> {
        let soup = face_subset(mesh, keep);
        match Mesh::from_soup(&soup) {
            Ok(sub) => {
                prop_assert_eq!(sub.validate(), Ok(()));
                prop_assert_eq!(sub.to_soup(), soup);
                prop_assert!(sub.genus().is_some());
                let n_faces: usize = sub.connected_components().iter().map(Vec::len).sum();
                prop_assert_eq!(n_faces, sub.n_faces());
            }
            // Removing faces from a manifold can only pinch vertices into bowties.
            Err(err) => prop_assert!(matches!(err, MeshError::NonManifoldVertex { .. }), "{err}"),
        }
        Ok(())
    }

    proptest! {
        #[test]
        fn face_subsets_of_a_grid_build_valid_meshes_or_report_bowties(keep in prop::collection::vec(any::<bool>(), 72)) {
            check_subset(&primitives::grid(6, 6, 1.0), &keep)?;
        }

        #[test]
        fn face_subsets_of_a_sphere_build_valid_meshes_or_report_bowties(keep in prop::collection::vec(prop::bool::weighted(0.8), 80)) {
            check_subset(&primitives::icosphere(1.0, 1), &keep)?;
        }

        #[test]
        fn moving_vertices_keeps_a_mesh_valid(offsets in prop::collection::vec(-1.0..1.0f64, 42 * 3)) {
            let mut mesh = primitives::icosphere(1.0, 1);
            for (p, d) in mesh.positions_mut().iter_mut().zip(offsets.chunks(3)) {
                *p += DVec3::new(d[0], d[1], d[2]);
            }
            prop_assert_eq!(mesh.validate(), Ok(()));
        }
    }
}
