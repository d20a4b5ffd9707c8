//! A model's triangles as its file had them, beside the manifold mesh repaired from them.
//!
//! An imported soup (non-manifold edges, fins, triangles twice, pieces turned over) is
//! repaired into a manifold [`Mesh`] for the tools that need one (FiberMesh, the Laplacian
//! editors). The curve-handle tool (Blanco) and the export do not: they use the input as it
//! came. The repaired mesh knows, for each of its vertices, the input vertex it came from,
//! so moving either moves the other: the mesh's positions are written back into the input's
//! at export, and a curve handle moves the input and then the mesh. While the mesh keeps
//! the triangles it was repaired into, the export writes the input's triangles; an edit that
//! changes the mesh's triangles (a cut, a remesh) leaves only the mesh.

use std::sync::Arc;

use glam::DVec3;

use super::appearance::Appearance;
use crate::mesh::{Mesh, TriSoup};

/// The input's triangles and positions, and how the repaired mesh maps onto them.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct AsImported {
    /// The welded input: every triangle the file had, as it had it.
    pub soup: TriSoup,
    /// For each vertex of the repaired mesh, the input vertex it came from.
    pub vertex_source: Vec<u32>,
    /// The repaired mesh's triangles, to tell whether it still fits.
    pub mesh_triangles: Vec<[u32; 3]>,
    /// The file's look per input triangle corner, if it had one.
    pub appearance: Option<Arc<Appearance>>,
}

impl AsImported {
    /// Whether `mesh` is still the repaired mesh (same triangles; positions may differ).
    pub fn fits(&self, mesh: &Mesh) -> bool {
        self.mesh_triangles == mesh.triangles()
    }

    /// The input's positions with `mesh`'s written back: each input vertex the mesh kept
    /// takes the position of (the first) mesh vertex made from it.
    pub fn positions_of(&self, mesh: &Mesh) -> Vec<DVec3> {
        let mut positions = self.soup.positions.clone();
        let mut written = vec![false; positions.len()];
        for (&source, &p) in self.vertex_source.iter().zip(mesh.positions()) {
            if !std::mem::replace(&mut written[source as usize], true) {
                positions[source as usize] = p;
            }
        }
        positions
    }

    /// The mesh's positions read from moved input positions.
    pub fn mesh_positions(&self, positions: &[DVec3]) -> Vec<DVec3> {
        self.vertex_source
            .iter()
            .map(|&s| positions[s as usize])
            .collect()
    }
}
