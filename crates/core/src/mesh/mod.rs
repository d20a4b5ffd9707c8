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
//! - positions are finite.
//!
//! A current limitation: there is no mutation API yet (no edge flips, splits or deletion with
//! tombstones); techniques that change topology build a new [`TriSoup`] and call
//! [`Mesh::from_soup`].

mod build;
pub mod fixtures;
pub mod primitives;
mod soup;
mod topology;
mod validate;

use glam::DVec3;
use serde::{Deserialize, Serialize};

pub use soup::TriSoup;

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

/// Why a soup cannot become a [`Mesh`], or which invariant a mesh breaks.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum MeshError {
    /// More than two triangles share an edge.
    #[error("The edge between vertices {a} and {b} is shared by more than two triangles.")]
    NonManifoldEdge {
        /// One end of the edge.
        a: u32,
        /// The other end of the edge.
        b: u32,
    },
    /// Two triangles run along a shared edge in the same direction (flipped normals).
    #[error("Two triangles meet at the edge from vertex {a} to {b} with opposite orientations.")]
    InconsistentOrientation {
        /// Tail of the directed edge that occurs twice.
        a: u32,
        /// Head of the directed edge that occurs twice.
        b: u32,
    },
    /// The triangles around a vertex form more than one fan (a "bowtie").
    #[error("The triangles around vertex {vertex} do not form a single fan.")]
    NonManifoldVertex {
        /// The pinched vertex.
        vertex: u32,
    },
    /// A triangle refers to a vertex that does not exist.
    #[error("Triangle {face} refers to vertex {index}, but there are only {n_vertices} vertices.")]
    IndexOutOfRange {
        /// The offending triangle.
        face: u32,
        /// The index it uses.
        index: u32,
        /// The number of vertices.
        n_vertices: usize,
    },
    /// A triangle uses the same vertex twice.
    #[error("Triangle {face} uses the same vertex more than once.")]
    DegenerateTriangle {
        /// The offending triangle.
        face: u32,
    },
    /// A vertex belongs to no triangle; see [`TriSoup::remove_unreferenced_vertices`].
    #[error("Vertex {vertex} belongs to no triangle.")]
    IsolatedVertex {
        /// The unused vertex.
        vertex: u32,
    },
    /// A position is NaN or infinite.
    #[error("Vertex {vertex} has a position that is not a finite number.")]
    NonFinitePosition {
        /// The offending vertex.
        vertex: u32,
    },
    /// The stored arrays contradict each other; the sentence says how.
    #[error("The mesh connectivity is broken: {0}")]
    InvalidConnectivity(String),
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

    /// Number of vertices.
    pub fn n_vertices(&self) -> usize {
        self.positions.len()
    }

    /// Number of triangles.
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
        HalfedgeId(if h.0 % 3 == 0 { h.0 + 2 } else { h.0 - 1 })
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

    /// One outgoing half-edge of `v`; on the boundary, the one with no twin.
    pub fn vertex_halfedge(&self, v: VertexId) -> HalfedgeId {
        HalfedgeId(self.vertex_halfedge[v.index()])
    }

    /// Whether a half-edge has no twin.
    pub fn is_boundary_halfedge(&self, h: HalfedgeId) -> bool {
        self.twin[h.index()] == INVALID
    }

    /// Whether `v` lies on the boundary.
    pub fn is_boundary_vertex(&self, v: VertexId) -> bool {
        self.is_boundary_halfedge(self.vertex_halfedge(v))
    }

    /// Whether the mesh has no boundary edges.
    pub fn is_closed(&self) -> bool {
        self.twin.iter().all(|&t| t != INVALID)
    }

    /// Outgoing half-edges of `v`, counter-clockwise, starting at [`Mesh::vertex_halfedge`].
    pub fn outgoing_halfedges(&self, v: VertexId) -> OutgoingHalfedges<'_> {
        let start = self.vertex_halfedge(v);
        OutgoingHalfedges { mesh: self, start, current: Some(start) }
    }

    /// The one-ring of `v` in counter-clockwise order; on the boundary, from one boundary
    /// neighbour to the other.
    pub fn vertex_neighbors(&self, v: VertexId) -> impl Iterator<Item = VertexId> + '_ {
        let first = self.outgoing_halfedges(v).map(|h| self.head(h));
        // A boundary fan has one more neighbour than outgoing half-edges: the tail of the last
        // face's incoming half-edge, which has no outgoing twin.
        let last = self.is_boundary_vertex(v).then(|| {
            let last_out = self.outgoing_halfedges(v).last().unwrap_or(self.vertex_halfedge(v));
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

    /// Axis-aligned bounds `(min, max)`, or `None` for an empty mesh.
    pub fn bounding_box(&self) -> Option<(DVec3, DVec3)> {
        let first = *self.positions.first()?;
        Some(self.positions.iter().fold((first, first), |(lo, hi), &p| (lo.min(p), hi.max(p))))
    }

    fn triangles_flat(&self) -> &[u32] {
        self.triangles.as_flattened()
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
        self.current = self.mesh.twin(self.mesh.prev(h)).filter(|&t| t != self.start);
        Some(h)
    }
}

#[cfg(test)]
mod tests {
    use super::primitives;
    use super::*;

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
            assert!(a.cross(b).z > 0.0, "ring is not counter-clockwise: {ring:?}");
        }
    }

    #[test]
    fn one_ring_of_a_boundary_corner_runs_boundary_to_boundary() {
        let mesh = primitives::grid(2, 2, 2.0);
        for v in mesh.vertices().filter(|&v| v != VertexId(4)) {
            assert!(mesh.is_boundary_vertex(v));
            let ring: Vec<VertexId> = mesh.vertex_neighbors(v).collect();
            assert!(mesh.is_boundary_vertex(ring[0]) && mesh.is_boundary_vertex(ring[ring.len() - 1]));
            assert_eq!(ring.len(), mesh.vertex_faces(v).count() + 1);
        }
    }

    #[test]
    fn counts_and_bounds() {
        let mesh = primitives::icosphere(2.0, 1);
        assert_eq!((mesh.n_vertices(), mesh.n_edges(), mesh.n_faces()), (42, 120, 80));
        assert_eq!(mesh.triangle_indices().len(), 240);
        let (lo, hi) = mesh.bounding_box().unwrap();
        assert!((lo + DVec3::splat(2.0)).length() < 1e-12 && (hi - DVec3::splat(2.0)).length() < 1e-12);
        assert_eq!(Mesh::default().bounding_box(), None);
    }
}
