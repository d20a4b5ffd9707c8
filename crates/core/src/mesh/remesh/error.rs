//! Why remeshing refused.

use crate::mesh::MeshError;

/// Why remeshing refused; the input is never changed.
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
pub enum RemeshError {
    /// The target edge length is zero, negative or not a number.
    #[error("The surface could not be remeshed: the target edge length must be a positive number.")]
    InvalidTargetEdge,
    /// The target edge length is so small the mesh would have too many vertices.
    #[error(
        "The surface could not be remeshed: the target edge length would make about {expected_vertices} vertices, too many to handle."
    )]
    TargetTooSmall {
        /// Vertices expected at the target edge length.
        expected_vertices: u64,
    },
    /// A chain refers to a vertex the mesh does not have.
    #[error(
        "The surface could not be remeshed: control curve {chain} refers to vertex {vertex}, which the mesh does not have."
    )]
    VertexOutOfRange {
        /// Index of the chain.
        chain: usize,
        /// The missing vertex.
        vertex: u32,
    },
    /// Two consecutive chain vertices are not joined by a mesh edge.
    #[error(
        "The surface could not be remeshed: control curve {chain} jumps from vertex {a} to vertex {b}, which no mesh edge joins."
    )]
    NotAnEdgeChain {
        /// Index of the chain.
        chain: usize,
        /// The vertex before the jump.
        a: u32,
        /// The vertex after the jump.
        b: u32,
    },
    /// A closed chain has fewer than three vertices.
    #[error(
        "The surface could not be remeshed: control curve {chain} is closed but has fewer than three vertices."
    )]
    ClosedChainTooShort {
        /// Index of the chain.
        chain: usize,
    },
    /// The region mask does not have one entry per vertex.
    #[error(
        "The surface could not be remeshed: the region has {found} entries for {expected} vertices."
    )]
    RegionMismatch {
        /// Vertices of the mesh.
        expected: usize,
        /// Entries of the region.
        found: usize,
    },
    /// The result broke a mesh invariant; a bug, reported rather than returned broken.
    #[error("The surface could not be remeshed: the result was not a valid mesh. {0}")]
    InvalidResult(MeshError),
}
