//! STUB — being written. The animation manifest (SPEC §5).

use super::path::CameraPath;
use std::path::{Path, PathBuf};

/// The frame file format of `[output] format`.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum FrameFormat {
    Png,
    Jpeg,
    Ppm,
    Raw,
}

/// `[output]`, paths resolved.
#[derive(Clone, Debug, PartialEq)]
pub struct OutputSpec {
    /// The frame folder, resolved against the manifest's folder.
    pub dir: PathBuf,
    /// The name pattern, `####` standing for the zero-padded frame number.
    pub name: String,
    pub format: FrameFormat,
    pub jpeg_quality: u8,
}

impl OutputSpec {
    /// The file name (no folder) of frame `frame` of a `frames`-frame sequence, with the
    /// format's extension.
    pub fn file_name(&self, frame: u32, frames: u32) -> String {
        let _ = (frame, frames);
        todo!()
    }
}

/// `[render]`: optional overrides of the scene file.
#[derive(Clone, Debug, PartialEq, Default)]
pub struct RenderSpec {
    pub width: Option<u32>,
    pub height: Option<u32>,
    /// n for an n×n grid per pixel; 1 when not given.
    pub samples: u32,
}

/// `[check]`, paths resolved.
#[derive(Clone, Debug, PartialEq)]
pub struct CheckSpec {
    pub frames: Vec<u32>,
    pub references: PathBuf,
    pub fail: u8,
    pub fail_percent: f64,
    pub hard_fail: u8,
}

/// A parsed and validated manifest.
#[derive(Clone, Debug, PartialEq)]
pub struct Manifest {
    /// The manifest file itself.
    pub path: PathBuf,
    /// The base scene, resolved against the manifest's folder.
    pub scene: PathBuf,
    pub frames: u32,
    pub fps: f64,
    pub camera: CameraPath,
    pub output: OutputSpec,
    pub render: RenderSpec,
    pub check: Option<CheckSpec>,
}

/// Why a manifest could not be loaded.
#[derive(Debug, thiserror::Error)]
pub enum ManifestError {
    #[error("{path}: cannot read the manifest: {source}")]
    Io {
        path: String,
        #[source]
        source: std::io::Error,
    },
    #[error("{path}:{line}:{column}: {message}")]
    Invalid {
        path: String,
        line: usize,
        column: usize,
        message: String,
    },
}

impl Manifest {
    pub fn load(path: &Path) -> Result<Manifest, ManifestError> {
        let _ = path;
        todo!()
    }

    /// Parses manifest text; `path` is where it came from (for errors and relative paths).
    pub fn parse(src: &str, path: &Path) -> Result<Manifest, ManifestError> {
        let _ = (src, path);
        todo!()
    }
}
