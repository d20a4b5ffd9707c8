//! The editing region: the ROI plus two rings of static anchors, numbered locally.
//!
//! Only these vertices enter the system, so its size follows the ROI, not the mesh. Ring 1
//! (the anchors touching the ROI) gets Laplacian rows too, as Nealen pads the ROI with
//! anchor layers (§4.2): matching their Laplacian coordinates makes the edit blend into the
//! static part smoothly instead of creasing at the ROI border. Ring 2 only appears as
//! neighbours in ring 1's rows.

use crate::mesh::{Mesh, VertexId};

/// Marks a mesh vertex outside the region.
const OUTSIDE: u32 = u32::MAX;

/// Local numbering: ROI vertices first (in mesh order), then ring 1, then ring 2.
#[derive(Clone, Debug)]
pub(crate) struct Region {
    /// Mesh vertex of each local index.
    vertices: Vec<VertexId>,
    /// Local index of each mesh vertex, or [`OUTSIDE`].
    local_of: Vec<u32>,
    n_roi: usize,
    /// ROI plus ring 1: the vertices with a Laplacian row.
    n_rows: usize,
}

impl Region {
    /// The region of `roi` (one flag per mesh vertex).
    pub(crate) fn new(mesh: &Mesh, roi: &[bool]) -> Region {
        let mut region = Region {
            vertices: mesh.vertices().filter(|v| roi[v.index()]).collect(),
            local_of: vec![OUTSIDE; mesh.n_vertices()],
            n_roi: 0,
            n_rows: 0,
        };
        for (local, v) in region.vertices.iter().enumerate() {
            region.local_of[v.index()] = local as u32;
        }
        region.n_roi = region.vertices.len();
        region.add_ring(mesh, 0);
        region.n_rows = region.vertices.len();
        region.add_ring(mesh, region.n_roi);
        region
    }

    /// Adds the outside neighbours of local vertices `from..`.
    fn add_ring(&mut self, mesh: &Mesh, from: usize) {
        let end = self.vertices.len();
        for k in from..end {
            for u in mesh.vertex_neighbors(self.vertices[k]) {
                if self.local_of[u.index()] == OUTSIDE {
                    self.local_of[u.index()] = self.vertices.len() as u32;
                    self.vertices.push(u);
                }
            }
        }
    }

    /// Mesh vertices by local index.
    pub(crate) fn vertices(&self) -> &[VertexId] {
        &self.vertices
    }

    /// Number of ROI (free) vertices: local indices `0..n_roi`.
    pub(crate) fn n_roi(&self) -> usize {
        self.n_roi
    }

    /// Number of vertices with a Laplacian row: local indices `0..n_rows`.
    pub(crate) fn n_rows(&self) -> usize {
        self.n_rows
    }

    /// The local index of mesh vertex `v`, if it is in the region.
    pub(crate) fn local(&self, v: VertexId) -> Option<usize> {
        let local = *self.local_of.get(v.index())?;
        (local != OUTSIDE).then_some(local as usize)
    }

    /// The local index of a vertex known to be in the region (a row vertex's neighbour).
    pub(crate) fn local_unchecked(&self, v: VertexId) -> u32 {
        debug_assert_ne!(self.local_of[v.index()], OUTSIDE);
        self.local_of[v.index()]
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::mesh::primitives;

    #[test]
    fn rings_surround_the_roi() {
        // The centre vertex of a 6 x 6 grid: ring 1 is its 6 neighbours, ring 2 the next 12.
        let mesh = primitives::grid(6, 6, 1.0);
        let centre = 3 + 3 * 7;
        let mut roi = vec![false; mesh.n_vertices()];
        roi[centre] = true;
        let region = Region::new(&mesh, &roi);
        assert_eq!(region.n_roi(), 1);
        assert_eq!(region.n_rows(), 7);
        assert_eq!(region.vertices().len(), 19);
        assert_eq!(region.local(VertexId(centre as u32)), Some(0));
        assert_eq!(region.local(VertexId(0)), None);
        // Every neighbour of a row vertex has a local index.
        for &v in &region.vertices()[..region.n_rows()] {
            assert!(mesh.vertex_neighbors(v).all(|u| region.local(u).is_some()));
        }
    }
}
