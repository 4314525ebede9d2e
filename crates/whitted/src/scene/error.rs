//! Scene.txt errors: every one carries the file, line and column of the offending token
//! (a `FileLoc`, after pbrt-v4) and says what was expected and where in the structure it
//! was ("sphere 3 of 4, field Radius").

pub use crate::fileloc::FileLoc;

/// Why a scene could not be loaded.
#[derive(Debug, thiserror::Error)]
pub enum SceneError {
    /// The file cannot be opened or read (missing, a folder, no permission).
    #[error("{path}: cannot read the scene file: {source}")]
    Io {
        /// The scene's path as given.
        path: String,
        /// The system's reason.
        #[source]
        source: std::io::Error,
    },
    /// A token is missing, is not a number, or is out of its range.
    #[error("{loc}: {message} ({context})")]
    Syntax {
        /// Where the offending token is (or the end of the file, when one is missing).
        loc: FileLoc,
        /// What was expected and found, e.g. "expected a number, found `x`".
        message: String,
        /// Where in the structure: "sphere 3 of 4, field Radius".
        context: String,
    },
    /// A glTF file's refusal (it names the file and the JSON path).
    #[error(transparent)]
    Gltf(crate::gltf::error::GltfError),
}

impl SceneError {
    /// The location of a syntax error, if it is one.
    pub fn loc(&self) -> Option<&FileLoc> {
        match self {
            SceneError::Syntax { loc, .. } => Some(loc),
            SceneError::Io { .. } | SceneError::Gltf(_) => None,
        }
    }
}
