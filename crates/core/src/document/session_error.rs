//! Why a session could not be read or replayed.

use super::CommandError;

/// Why a session could not be read or replayed.
#[derive(Debug, thiserror::Error)]
pub enum SessionError {
    /// The text is not JSON at all.
    #[error("The session is not valid JSON: {0}")]
    Json(#[from] serde_json::Error),
    /// The JSON is not a session object (wrong `"format"`, missing or unknown fields).
    #[error("This is not a Sketchmesh session: {0}.")]
    Format(String),
    /// The session was written by an incompatible version.
    #[error("The session has version {found}, but this Sketchmesh reads version {expected}.")]
    Version {
        /// The `"version"` value found, as JSON text.
        found: String,
        /// The version this build reads ([`super::SESSION_VERSION`]).
        expected: u64,
    },
    /// An op could not be parsed.
    #[error("op {index}: {message}")]
    Op {
        /// Zero-based position of the op in `"ops"`.
        index: usize,
        /// What is wrong with it.
        message: String,
    },
    /// An op parsed but was refused when replayed.
    #[error("op {index}: {source}")]
    Command {
        /// Zero-based position of the op in `"ops"`.
        index: usize,
        /// Why the editor refused it.
        source: CommandError,
    },
}
