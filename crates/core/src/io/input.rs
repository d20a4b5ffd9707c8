//! What the importer is given: the files, and limits on what it accepts.

/// Limits that protect the page from files too large to edit.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct ImportLimits {
    /// Largest file accepted, in bytes.
    pub max_file_bytes: usize,
    /// Most vertices over all node instances.
    pub max_vertices: usize,
    /// Most triangles over all node instances.
    pub max_triangles: usize,
}

impl Default for ImportLimits {
    /// 512 MiB, 10 M vertices, 20 M triangles.
    fn default() -> Self {
        Self {
            max_file_bytes: 512 << 20,
            max_vertices: 10_000_000,
            max_triangles: 20_000_000,
        }
    }
}

/// A file given to the importer: its name (for matching URIs) and bytes.
#[derive(Clone, Copy, Debug)]
pub struct ImportFile<'a> {
    /// The file name, as picked or dropped.
    pub name: &'a str,
    /// Its contents.
    pub bytes: &'a [u8],
}
