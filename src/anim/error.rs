//! Everything that can stop `animate`, and the row of the exit-status table (`exit`) each
//! belongs to: bad input (manifest, scene, frame list, sizes, an output location or a tool
//! that cannot be used, a check that cannot run), a failure during the run (a frame that
//! could not be rendered or written, ffmpeg failing), or a signal. Messages say what is
//! wrong; they name no command-line flag (the binary adds hints).

use super::manifest::ManifestError;
use super::select::SelectError;
use crate::exit::Outcome;
use crate::fileloc::FileLoc;
use crate::output::OutputError;
use crate::scene::SceneError;
use std::path::PathBuf;

/// Why an animation run stopped.
#[derive(Debug, thiserror::Error)]
pub enum AnimError {
    #[error(transparent)]
    Manifest(#[from] ManifestError),
    #[error(transparent)]
    Scene(#[from] SceneError),
    #[error("{loc}: scene: cannot read {path}: {source}")]
    SceneFile {
        loc: FileLoc,
        path: String,
        #[source]
        source: std::io::Error,
    },
    #[error(transparent)]
    Select(#[from] SelectError),
    #[error("{0}")]
    Reference(String),
    #[error("{}: {width}×{height} frames are past the limit of 16384 a side and 2^26 pixels", .manifest.display())]
    Size {
        manifest: PathBuf,
        width: u32,
        height: u32,
    },
    #[error("frame {frame}: the camera is placed on the point it looks at")]
    Camera { frame: u32 },
    #[error("cannot use the output folder {dir}: {source}")]
    Folder {
        dir: PathBuf,
        #[source]
        source: std::io::Error,
    },
    #[error("frame {frame}: {source}")]
    Write {
        frame: u32,
        #[source]
        source: OutputError,
    },
    #[error("cannot write the frames to the output stream: {0}")]
    Stream(#[source] std::io::Error),
    #[error("ffmpeg was not found on PATH (install it, e.g. apt-get install ffmpeg, or stream raw frames into an encoder of your choice)")]
    FfmpegMissing,
    #[error("cannot make the video {path}: {reason}")]
    VideoTarget { path: PathBuf, reason: String },
    #[error("ffmpeg failed: {0}")]
    Ffmpeg(String),
    #[error("interrupted by signal {0}; finished frames are kept")]
    Interrupted(i32),
}

impl AnimError {
    /// The row of the exit-status table this error belongs to.
    pub fn outcome(&self) -> Outcome {
        match self {
            AnimError::Manifest(_)
            | AnimError::Scene(_)
            | AnimError::SceneFile { .. }
            | AnimError::Select(_)
            | AnimError::Reference(_)
            | AnimError::Size { .. }
            | AnimError::Camera { .. }
            | AnimError::Folder { .. }
            | AnimError::FfmpegMissing
            | AnimError::VideoTarget { .. } => Outcome::BadInput,
            AnimError::Write { .. } | AnimError::Stream(_) | AnimError::Ffmpeg(_) => {
                Outcome::Failed
            }
            AnimError::Interrupted(sig) => Outcome::Interrupted(*sig),
        }
    }

    /// The process exit status for this error.
    pub fn exit_code(&self) -> u8 {
        self.outcome().code()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn exit_codes() {
        assert_eq!(AnimError::Reference("x".into()).exit_code(), 2);
        assert_eq!(AnimError::Camera { frame: 3 }.exit_code(), 2);
        assert_eq!(AnimError::FfmpegMissing.exit_code(), 2);
        let folder = AnimError::Folder {
            dir: "x".into(),
            source: std::io::ErrorKind::NotFound.into(),
        };
        assert_eq!(folder.exit_code(), 2);
        assert_eq!(
            AnimError::Stream(std::io::ErrorKind::BrokenPipe.into()).exit_code(),
            1
        );
        assert_eq!(AnimError::Ffmpeg("x".into()).exit_code(), 1);
        assert_eq!(AnimError::Interrupted(2).exit_code(), 130);
        assert_eq!(AnimError::Interrupted(15).exit_code(), 143);
    }
}
