//! Everything that can stop `animate`, and the exit status each deserves: 2 for bad input
//! (manifest, scene, frame list, a folder of other frames), 1 for a frame that could not
//! be rendered or written, 128 + N for a run stopped by signal N (130 SIGINT, 143 SIGTERM).

use super::manifest::ManifestError;
use super::select::SelectError;
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
    #[error(transparent)]
    Select(#[from] SelectError),
    #[error("{0}")]
    Usage(String),
    #[error("{0}")]
    Reference(String),
    #[error("frame {frame}: the camera is placed on the point it looks at")]
    Camera { frame: u32 },
    #[error(
        "{dir} holds frames of another scene or other settings (its {record} differs); \
         use another folder, or --force to mix them"
    )]
    ForeignFrames { dir: PathBuf, record: &'static str },
    #[error("cannot use the frame folder {dir}: {source}")]
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
    #[error("{0}")]
    Ffmpeg(String),
    #[error("interrupted by signal {0}; finished frames are kept, `--resume` completes the run")]
    Interrupted(i32),
}

impl AnimError {
    /// The process exit status for this error.
    pub fn exit_code(&self) -> u8 {
        match self {
            AnimError::Manifest(_)
            | AnimError::Scene(_)
            | AnimError::Select(_)
            | AnimError::Usage(_)
            | AnimError::Reference(_)
            | AnimError::Camera { .. }
            | AnimError::ForeignFrames { .. } => 2,
            AnimError::Folder { .. }
            | AnimError::Write { .. }
            | AnimError::Stream(_)
            | AnimError::Ffmpeg(_) => 1,
            AnimError::Interrupted(sig) => (128 + sig).clamp(0, 255) as u8,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn exit_codes() {
        assert_eq!(AnimError::Usage("x".into()).exit_code(), 2);
        assert_eq!(AnimError::Camera { frame: 3 }.exit_code(), 2);
        assert_eq!(
            AnimError::Stream(std::io::ErrorKind::BrokenPipe.into()).exit_code(),
            1
        );
        assert_eq!(AnimError::Interrupted(2).exit_code(), 130);
        assert_eq!(AnimError::Interrupted(15).exit_code(), 143);
    }
}
