//! Why a glTF file could not be read: every message names the file and, where the fault
//! is in the document, its JSON path (`accessors[3].count`), or the line and column of
//! a JSON syntax error.

/// A glTF file's refusal.
#[derive(Debug, thiserror::Error)]
pub enum GltfError {
    /// The file, or a file it names, cannot be read.
    #[error("{path}: cannot read {what}: {source}")]
    Io {
        /// The file as resolved.
        path: String,
        /// "the glTF file", "buffers[0]'s file", …
        what: String,
        /// The system's reason.
        #[source]
        source: std::io::Error,
    },
    /// Not JSON glTF 2.0 or GLB, or the crate's validation refused it.
    #[error("{file}{at}: not a valid glTF 2.0 file: {message}")]
    Document {
        /// The glTF file.
        file: String,
        /// `:line:column` for a JSON syntax error, else empty.
        at: String,
        /// The reason.
        message: String,
    },
    /// Something at a place of the document is wrong.
    #[error("{file}: {path}: {message}")]
    At {
        /// The glTF file.
        file: String,
        /// The JSON path: `accessors[3].count`, `nodes[2].skin`.
        path: String,
        /// What is wrong.
        message: String,
    },
}

/// A refusal at `path` of `file`'s document.
pub fn at(file: &str, path: impl Into<String>, message: impl Into<String>) -> GltfError {
    GltfError::At {
        file: file.to_string(),
        path: path.into(),
        message: message.into(),
    }
}
