//! Why an STL or OBJ file could not be written: one sentence per problem.

/// Why an export was refused. Every message is a sentence the app and the CLI show as is.
#[derive(Clone, Debug, PartialEq, Eq, thiserror::Error)]
pub enum ExportError {
    /// No model of the document has a triangle.
    #[error("The document has no triangles to write to {format}.")]
    EmptyDocument {
        /// "STL" or "OBJ".
        format: &'static str,
    },
    /// The model asked for has no triangle.
    #[error("The model \"{name}\" has no triangles to write to {format}.")]
    EmptyModel {
        /// The model's name, as the export would write it.
        name: String,
        /// "STL" or "OBJ".
        format: &'static str,
    },
    /// The model asked for does not exist.
    #[error("There is no model {index}: the document has {count} models.")]
    NoSuchModel {
        /// The index asked for.
        index: usize,
        /// How many models there are.
        count: usize,
    },
}
