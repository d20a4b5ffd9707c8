//! Deleting faces, as a cut or a tunnel does before it closes or joins the openings.

use rustc_hash::FxHashSet;

use crate::mesh::{FaceId, HalfedgeId, Mesh, MeshError, VertexId};

impl Mesh {
    /// Deletes `faces` (tombstones until [`Mesh::compact`]); their edges shared with kept
    /// faces become boundary, and vertices left without a face are deleted too.
    ///
    /// Errors: [`MeshError::NonManifoldVertex`] when a vertex would keep two separate fans of
    /// faces (a bowtie), which a half-edge mesh cannot hold; nothing is changed then.
    pub fn delete_faces(&mut self, faces: &[FaceId]) -> Result<(), MeshError> {
        let doomed: FxHashSet<FaceId> = faces
            .iter()
            .copied()
            .filter(|&f| self.is_live_face(f))
            .collect();
        let mut touched: Vec<VertexId> =
            doomed.iter().flat_map(|&f| self.face_vertices(f)).collect();
        touched.sort_unstable();
        touched.dedup();
        let mut starts = Vec::with_capacity(touched.len());
        for &v in &touched {
            starts.push(self.surviving_fan_start(v, &doomed)?);
        }
        for &f in &doomed {
            for h in (3 * f.0..3 * f.0 + 3).map(HalfedgeId) {
                if let Some(t) = self.twin(h) {
                    self.twin[t.index()] = super::INVALID;
                }
            }
            self.kill_face(f);
        }
        for (v, start) in touched.into_iter().zip(starts) {
            match start {
                Some(h) => self.set_vertex_halfedge(v, h),
                None => self.kill_vertex(v),
            }
        }
        Ok(())
    }

    /// The clockwise-most outgoing half-edge of `v` whose face survives deleting `doomed`
    /// (the boundary one afterwards), or `None` when no face survives.
    ///
    /// Errors: [`MeshError::NonManifoldVertex`] when the survivors are not one fan.
    fn surviving_fan_start(
        &self,
        v: VertexId,
        doomed: &FxHashSet<FaceId>,
    ) -> Result<Option<HalfedgeId>, MeshError> {
        let fan: Vec<(HalfedgeId, bool)> = self
            .outgoing_halfedges(v)
            .map(|h| (h, !doomed.contains(&self.face(h))))
            .collect();
        let is_cyclic = !self.is_boundary_vertex(v);
        // A run of survivors starts where the face clockwise of a survivor is gone.
        let run_starts: Vec<HalfedgeId> = (0..fan.len())
            .filter(|&i| {
                let before = match i {
                    0 if is_cyclic => Some(fan[fan.len() - 1].1),
                    0 => None,
                    _ => Some(fan[i - 1].1),
                };
                fan[i].1 && before != Some(true)
            })
            .map(|i| fan[i].0)
            .collect();
        match run_starts.as_slice() {
            [] if fan.iter().all(|&(_, alive)| alive) => Ok(Some(self.vertex_halfedge(v))),
            [] => Ok(None),
            [start] => Ok(Some(*start)),
            _ => Err(MeshError::NonManifoldVertex { vertex: v.0 }),
        }
    }
}

#[cfg(test)]
mod tests {
    use crate::mesh::{FaceId, MeshError, VertexId, primitives};

    #[test]
    fn deleting_a_vertex_star_opens_one_hole() {
        let mut mesh = primitives::icosphere(1.0, 2);
        let star: Vec<FaceId> = mesh.vertex_faces(VertexId(0)).collect();
        mesh.delete_faces(&star).unwrap();
        mesh.validate().unwrap();
        assert!(!mesh.is_live_vertex(VertexId(0)));
        mesh.compact();
        mesh.validate().unwrap();
        assert_eq!(mesh.n_boundary_loops(), 1);
        assert_eq!(mesh.boundary_loops()[0].len(), star.len());
        assert_eq!(mesh.genus(), Some(0));
    }

    #[test]
    fn a_deletion_that_leaves_a_bowtie_is_refused_and_changes_nothing() {
        let mut mesh = primitives::icosphere(1.0, 1);
        let fan: Vec<FaceId> = mesh.vertex_faces(VertexId(0)).collect();
        // Two opposite faces of a six-face fan: the vertex keeps two separate pairs.
        let before = mesh.clone();
        let result = mesh.delete_faces(&[fan[0], fan[fan.len() / 2]]);
        assert_eq!(result, Err(MeshError::NonManifoldVertex { vertex: 0 }));
        assert_eq!(mesh, before);
    }
}
