//! Triangle half-edge mesh on flat arrays (corner-table form).
//!
//! Half-edge `h = 3 * face + k` runs from corner `k` of its face to corner `k + 1 (mod 3)`, so
//! `next`, `prev` and `face` are index arithmetic and never stored. The stored connectivity is
//! the triangle index buffer itself (`corner_vertex`, the tail of each half-edge), `twin`
//! (`u32::MAX` on a boundary) and one outgoing half-edge per vertex. Positions live in their own
//! `Vec`, so geometry can change every frame while connectivity stays fixed. Why a half-edge mesh
//! and not an indexed face set with adjacency tables: edits stay local, and tables would go
//! stale (see `style.md`, "Mesh data structure").
//!
//! Invariants (checked by [`Mesh::validate`]):
//! - every face has three distinct vertices, every vertex has at least one face;
//! - `twin` is an involution pairing `a -> b` with `b -> a`, and no directed edge occurs twice
//!   (the mesh is an oriented 2-manifold with boundary);
//! - every vertex has one fan of faces, and the vertex's half-edge is its boundary half-edge when
//!   it lies on the boundary, so a counter-clockwise walk from it visits the whole one-ring;
//! - positions are finite;
//! - a deleted face (a tombstone left by a collapse or a deletion, see [`edit`]) has invalid
//!   corners and twins, a deleted vertex an invalid half-edge, and no live face uses it.
//!
//! This is the one mesh of the crate: [`edit`] changes its topology in place (splits, flips,
//! collapses, deletions, fills, new components), so remeshing, curve embedding and the
//! topology operations all work on it. A document keeps each model behind an `Arc` and
//! clones a mesh only when an op changes it, so snapshots for undo stay cheap.

mod build;
pub mod edit;
mod error;
pub mod fixtures;
mod halfedge;
mod mirror;
mod paths;
pub mod primitives;
pub mod remesh;
mod repair;
mod soup;
mod topology;
mod validate;

use glam::DVec3;
use serde::{Deserialize, Serialize};

pub(crate) use build::MeshParts;
pub use edit::Remap;
pub use error::MeshError;
pub use halfedge::OutgoingHalfedges;
pub(crate) use paths::{distances_within, shortest_paths};
pub use repair::{RepairReport, Repaired, make_manifold};
pub use soup::{TriSoup, count_components};

/// Marks a missing half-edge: the twin of a boundary half-edge.
pub(crate) const INVALID: u32 = u32::MAX;

/// Index of a vertex in a [`Mesh`] or [`TriSoup`].
#[derive(Copy, Clone, PartialEq, Eq, Hash, Debug, PartialOrd, Ord, Serialize, Deserialize)]
pub struct VertexId(pub u32);

/// Index of a triangle in a [`Mesh`] or [`TriSoup`].
#[derive(Copy, Clone, PartialEq, Eq, Hash, Debug, PartialOrd, Ord, Serialize, Deserialize)]
pub struct FaceId(pub u32);

/// Index of a half-edge: `3 * face + corner`, running from that corner to the next one.
#[derive(Copy, Clone, PartialEq, Eq, Hash, Debug, PartialOrd, Ord, Serialize, Deserialize)]
pub struct HalfedgeId(pub u32);

impl VertexId {
    /// The id as an index into per-vertex arrays.
    pub fn index(self) -> usize {
        self.0 as usize
    }
}

impl FaceId {
    /// The id as an index into per-face arrays.
    pub fn index(self) -> usize {
        self.0 as usize
    }
}

impl HalfedgeId {
    /// The id as an index into per-half-edge arrays.
    pub fn index(self) -> usize {
        self.0 as usize
    }
}

/// A triangle half-edge mesh; see the module docs for the layout and invariants.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Mesh {
    positions: Vec<DVec3>,
    /// The index buffer: `triangles[f][k]` is the tail of half-edge `3 f + k`.
    triangles: Vec<[u32; 3]>,
    /// Opposite half-edge, or [`INVALID`] on the boundary.
    twin: Vec<u32>,
    /// One outgoing half-edge per vertex; the boundary one for boundary vertices.
    vertex_halfedge: Vec<u32>,
    /// Deleted vertices and faces still holding a slot; see [`edit`].
    n_dead_vertices: u32,
    n_dead_faces: u32,
}

impl Mesh {
    /// Vertex positions, indexed by [`VertexId::index`].
    pub fn positions(&self) -> &[DVec3] {
        &self.positions
    }

    /// Mutable positions: geometry may change, the number of vertices and the topology may not.
    pub fn positions_mut(&mut self) -> &mut [DVec3] {
        &mut self.positions
    }

    /// Position of one vertex.
    pub fn position(&self, v: VertexId) -> DVec3 {
        self.positions[v.index()]
    }

    /// Number of vertices (slots, deleted ones included, until [`Mesh::compact`]).
    pub fn n_vertices(&self) -> usize {
        self.positions.len()
    }

    /// Number of triangles (slots, deleted ones included, until [`Mesh::compact`]).
    pub fn n_faces(&self) -> usize {
        self.triangles.len()
    }

    /// Number of half-edges (three per face; boundary edges have one).
    pub fn n_halfedges(&self) -> usize {
        self.twin.len()
    }

    /// Number of undirected edges: interior edges count once, boundary edges once.
    pub fn n_edges(&self) -> usize {
        let n_boundary = self.twin.iter().filter(|&&t| t == INVALID).count();
        (self.n_halfedges() + n_boundary) / 2
    }

    /// The triangles as vertex index triples, counter-clockwise seen from outside.
    pub fn triangles(&self) -> &[[u32; 3]] {
        &self.triangles
    }

    /// Flat index buffer, three indices per face, for the GPU and glTF.
    pub fn triangle_indices(&self) -> &[u32] {
        self.triangles.as_flattened()
    }

    /// All vertex ids.
    pub fn vertices(&self) -> impl ExactSizeIterator<Item = VertexId> + use<> {
        (0..self.n_vertices() as u32).map(VertexId)
    }

    /// All face ids.
    pub fn faces(&self) -> impl ExactSizeIterator<Item = FaceId> + use<> {
        (0..self.n_faces() as u32).map(FaceId)
    }

    /// The three corners of a face, counter-clockwise.
    pub fn face_vertices(&self, f: FaceId) -> [VertexId; 3] {
        self.triangles[f.index()].map(VertexId)
    }

    /// The three corner positions of a face.
    pub fn face_positions(&self, f: FaceId) -> [DVec3; 3] {
        self.triangles[f.index()].map(|v| self.positions[v as usize])
    }

    /// Mean length of the undirected edges (0 for a mesh without faces).
    pub fn mean_edge_length(&self) -> f64 {
        let (mut sum, mut n) = (0.0, 0usize);
        for h in (0..self.n_halfedges() as u32).map(HalfedgeId) {
            // Each edge once: from its lower half-edge, or its only one on the boundary.
            if self.twin(h).is_none_or(|t| h < t) {
                sum += self
                    .position(self.tail(h))
                    .distance(self.position(self.head(h)));
                n += 1;
            }
        }
        if n == 0 { 0.0 } else { sum / n as f64 }
    }

    /// Axis-aligned bounds `(min, max)`, or `None` for an empty mesh.
    pub fn bounding_box(&self) -> Option<(DVec3, DVec3)> {
        let first = *self.positions.first()?;
        Some(
            self.positions
                .iter()
                .fold((first, first), |(lo, hi), &p| (lo.min(p), hi.max(p))),
        )
    }

    fn triangles_flat(&self) -> &[u32] {
        self.triangles.as_flattened()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn counts_and_bounds() {
        let mesh = primitives::icosphere(2.0, 1);
        assert_eq!(
            (mesh.n_vertices(), mesh.n_edges(), mesh.n_faces()),
            (42, 120, 80)
        );
        assert_eq!(mesh.triangle_indices().len(), 240);
        let (lo, hi) = mesh.bounding_box().unwrap();
        assert!(
            (lo + DVec3::splat(2.0)).length() < 1e-12 && (hi - DVec3::splat(2.0)).length() < 1e-12
        );
        assert_eq!(Mesh::default().bounding_box(), None);
    }
}
