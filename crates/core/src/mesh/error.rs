//! Why a soup cannot become a mesh, or which invariant a mesh breaks.

/// Why a soup cannot become a [`Mesh`](super::Mesh), or which invariant a mesh breaks.
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
    /// A vertex belongs to no triangle; see [`TriSoup::remove_unreferenced_vertices`](super::TriSoup::remove_unreferenced_vertices).
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
