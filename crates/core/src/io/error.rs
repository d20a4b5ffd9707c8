//! Why a glTF file could not be read: one sentence per problem, naming the part of the file.

/// Why a glTF file could not be read. Every message is a sentence a user can act on.
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
pub enum GltfError {
    /// The bytes are neither a GLB container nor glTF JSON, or the JSON breaks the schema.
    #[error("The file is not valid glTF: {0}.")]
    Parse(String),
    /// The file is larger than the import limit.
    #[error("The file is {bytes} bytes, more than the import limit of {limit} bytes.")]
    FileTooLarge {
        /// Size of the file.
        bytes: usize,
        /// The limit.
        limit: usize,
    },
    /// The file is glTF 1.0 or some other version.
    #[error("The file is glTF version {0}; only glTF 2.0 files can be imported.")]
    UnsupportedVersion(String),
    /// The file requires extensions this reader does not implement.
    #[error("The file requires the glTF extension(s) {0}, which Sketchmesh cannot read.")]
    UnsupportedExtensions(String),
    /// A buffer or image refers to a file that was not given with the glTF file.
    #[error(
        "{what} {index} refers to the file \"{uri}\", which was not given; open or drop it together with the .gltf file."
    )]
    MissingFile {
        /// "Buffer" or "Image".
        what: &'static str,
        /// Its index.
        index: usize,
        /// The URI as written in the file.
        uri: String,
    },
    /// A URI points at the network or an absolute path; nothing is ever fetched.
    #[error("{what} {index} refers to \"{uri}\", which Sketchmesh never downloads or opens.")]
    RemoteUri {
        /// "Buffer" or "Image".
        what: &'static str,
        /// Its index.
        index: usize,
        /// The URI as written in the file.
        uri: String,
    },
    /// A `data:` URI is not base64 data.
    #[error("Buffer {index} has a data URI that is not valid base64.")]
    BadDataUri {
        /// The buffer.
        index: usize,
    },
    /// The file declares embedded binary data (a buffer without URI) but has none.
    #[error(
        "The file declares geometry data but contains none (a buffer without a URI outside a .glb)."
    )]
    NoBinaryData,
    /// An accessor or its buffer view reaches past the end of the data.
    #[error("Accessor {index} reads past the end of its buffer.")]
    AccessorOutOfBounds {
        /// The accessor.
        index: usize,
    },
    /// An accessor has a form this reader does not handle.
    #[error("Accessor {index} is not supported: {reason}.")]
    UnsupportedAccessor {
        /// The accessor.
        index: usize,
        /// What is unsupported.
        reason: &'static str,
    },
    /// A position is NaN or infinite (in the data or after the node transforms).
    #[error("Accessor {index} holds a position that is not a finite number.")]
    NonFinitePosition {
        /// The POSITION accessor.
        index: usize,
    },
    /// A vertex index is not below the number of vertices.
    #[error("Mesh {mesh} uses vertex index {index}, but the primitive has only {count} vertices.")]
    IndexOutOfRange {
        /// The mesh.
        mesh: usize,
        /// The bad index.
        index: u32,
        /// The number of vertices in the primitive.
        count: usize,
    },
    /// The scene has more vertices (over all node instances) than the import limit.
    #[error("The scene has {count} {what}, more than the import limit of {limit}.")]
    TooMuchGeometry {
        /// "vertices" or "triangles".
        what: &'static str,
        /// How many the scene has.
        count: u64,
        /// The limit.
        limit: usize,
    },
    /// The node hierarchy is not a tree (a node is reached twice).
    #[error("Node {node} appears more than once in the scene's node tree.")]
    NodeReachedTwice {
        /// The node.
        node: usize,
    },
    /// Node extras under `"sketchmesh"` do not follow `docs/gltf-extras.md`.
    #[error("The Sketchmesh data on node {node} is malformed: {message}.")]
    BadExtras {
        /// The node.
        node: usize,
        /// What serde reported.
        message: String,
    },
    /// The default scene has no triangles, lines or points.
    #[error("The file has no triangles, lines or points to import.")]
    NothingToImport,
}
