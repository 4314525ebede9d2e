//! Why a manifest is refused (`ManifestError`): it cannot be read, a value is invalid at
//! `path:line:column`, or names are unknown. Both halves of reading an animation raise it:
//! `manifest`, which reads and checks the TOML, and `timeline`, which binds the values
//! read to the scene and checks every value a track produces. It lives apart from both so
//! that `timeline` does not depend on `manifest` (which builds its values from timeline's
//! types).
//!
//! ```text
//! anim/m.toml:7:10: track 1 (`sphere 1 radius`): at frame 3 its value -0.5 is out of bounds: …
//! ```

use whitted::fileloc::FileLoc;

/// Why a manifest could not be loaded.
#[derive(Debug, thiserror::Error)]
pub enum ManifestError {
    /// The file cannot be opened or read.
    #[error("{path}: cannot read the manifest: {source}")]
    Io {
        /// The manifest's path as given.
        path: String,
        /// The system's reason.
        #[source]
        source: std::io::Error,
    },
    /// The manifest is not TOML, not UTF-8, or a value has the wrong type or is out of
    /// its bounds.
    #[error("{loc}: {message}")]
    Invalid {
        /// Where the offending value (or table) is.
        loc: FileLoc,
        /// What is wrong and what was expected.
        message: String,
    },
    /// Every unknown key or table of the manifest, in file order (at least one): one
    /// `path:line:column: message` line each.
    #[error("{}", lines(.0))]
    Unknown(Vec<(FileLoc, String)>),
}

/// One `loc: message` line per entry.
fn lines(found: &[(FileLoc, String)]) -> String {
    let lines: Vec<String> = found
        .iter()
        .map(|(loc, message)| format!("{loc}: {message}"))
        .collect();
    lines.join("\n")
}

impl ManifestError {
    /// The location of an `Invalid` error, or of the first unknown name.
    pub fn loc(&self) -> Option<&FileLoc> {
        match self {
            ManifestError::Invalid { loc, .. } => Some(loc),
            ManifestError::Unknown(found) => found.first().map(|(loc, _)| loc),
            ManifestError::Io { .. } => None,
        }
    }
}
