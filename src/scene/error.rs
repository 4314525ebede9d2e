//! Scene.txt errors: every one carries the file, line and column of the offending token
//! (a `FileLoc`, after pbrt-v4) and says what was expected and where in the structure it
//! was ("sphere 3 of 4, field Radius").

pub use crate::fileloc::FileLoc;

/// Why a scene could not be loaded.
#[derive(Debug, thiserror::Error)]
pub enum SceneError {
    #[error("{path}: cannot read the scene file: {source}")]
    Io {
        path: String,
        #[source]
        source: std::io::Error,
    },
    #[error("{loc}: {message} ({context})")]
    Syntax {
        loc: FileLoc,
        message: String,
        /// Where in the structure: "sphere 3 of 4, field Radius".
        context: String,
    },
}

impl SceneError {
    /// The location of a syntax error, if it is one.
    pub fn loc(&self) -> Option<&FileLoc> {
        match self {
            SceneError::Syntax { loc, .. } => Some(loc),
            SceneError::Io { .. } => None,
        }
    }
}
