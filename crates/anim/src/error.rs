//! Everything that can stop `animate`, and the row of the exit-status table (`exit`) each
//! belongs to: bad input (manifest, scene, frame list, sizes, an output location or a tool
//! that cannot be used, a check that cannot run), a failure during the run (a frame that
//! could not be rendered or written, ffmpeg failing), or a signal. Messages say what is
//! wrong; they name no command-line flag (the binary adds hints).

use super::manifest::ManifestError;
use super::select::SelectError;
use std::path::PathBuf;
use whitted::exit::Outcome;
use whitted::fileloc::{shown, FileLoc};
use whitted::output::OutputError;
use whitted::scene::SceneError;

/// Why an animation run stopped.
#[derive(Debug, thiserror::Error)]
pub enum AnimError {
    /// The manifest cannot be read or is invalid (bad input).
    #[error(transparent)]
    Manifest(#[from] ManifestError),
    /// The scene the manifest names is invalid (bad input).
    #[error(transparent)]
    Scene(#[from] SceneError),
    /// The scene file the manifest names cannot be read; located at the manifest's
    /// `scene =` line (bad input).
    #[error("{loc}: scene: cannot read {}: {source}", shown(std::path::Path::new(.path)))]
    SceneFile {
        /// The manifest's `scene =` value.
        loc: FileLoc,
        /// The scene's path, resolved beside the manifest.
        path: String,
        /// The system's reason.
        #[source]
        source: std::io::Error,
    },
    /// The frame list or shard is bad (bad input).
    #[error(transparent)]
    Select(#[from] SelectError),
    /// A check's reference image is missing, unreadable or of another size than the
    /// frames (bad input: the check cannot run).
    #[error("{0}")]
    Reference(String),
    /// The frames would be larger than `MAX_SIDE` a side or `MAX_PIXELS` in all, e.g. after
    /// a `[render]` size override (bad input).
    #[error("{}: {width}×{height} frames are past the limit of 16384 a side and 2^26 pixels", shown(.manifest))]
    Size {
        /// The manifest that asks for this size.
        manifest: PathBuf,
        /// The asked width in pixels.
        width: u32,
        /// The asked height in pixels.
        height: u32,
    },
    /// Adaptive anti-aliasing at this depth and frame size could need more memory than
    /// `limits::MAX_ADAPTIVE_BYTES` (bad input, found before anything is allocated).
    #[error("{}: {source}", shown(.manifest))]
    Antialias {
        /// The manifest that asks for it.
        manifest: PathBuf,
        /// The size, the depth and the worst case.
        #[source]
        source: whitted::render::adaptive::AntialiasError,
    },
    /// At this frame the camera's eye coincides with its look-at point, so it has no
    /// direction (bad input, found before rendering); located at the manifest's
    /// `look_at` object, or its `[camera]` table.
    #[error("{loc}: frame {frame}: the camera is placed on the point it looks at")]
    Camera {
        /// The first frame where this happens.
        frame: u32,
        /// Where the manifest sets the camera.
        loc: FileLoc,
    },
    /// The output (or report) folder cannot be created or used (bad input).
    #[error(
        "cannot use the output folder {}: {}",
        shown(dir),
        folder_reason(dir, source)
    )]
    Folder {
        /// The folder.
        dir: PathBuf,
        /// The system's reason.
        #[source]
        source: std::io::Error,
    },
    /// A frame was rendered but could not be written (a failed run).
    #[error("frame {frame}: {source}")]
    Write {
        /// The frame's number.
        frame: u32,
        /// Why its file could not be written.
        #[source]
        source: OutputError,
    },
    /// A command's text could not be written to standard output (a full disk; a closed
    /// pipe is not an error) (a failed run).
    #[error("cannot write standard output: {0}")]
    Stdout(#[source] std::io::Error),
    /// A check's results could not be exported (bad input: the report's place).
    #[error(transparent)]
    Export(#[from] crate::check::export::ExportError),
    /// Writing frames to standard output failed, e.g. the reader closed the pipe (a
    /// failed run).
    #[error("cannot write the frames to the output stream: {0}")]
    Stream(#[source] std::io::Error),
    /// A video was asked for and no `ffmpeg` is on PATH (bad input, found before rendering).
    #[error("ffmpeg was not found on PATH (install it, e.g. apt-get install ffmpeg, or stream raw frames into an encoder of your choice)")]
    FfmpegMissing,
    /// The video file cannot be made: its folder is missing, it is a folder, or ffmpeg
    /// knows no container for its extension (bad input, found before rendering).
    #[error("cannot make the video {}: {reason}", shown(.path))]
    VideoTarget {
        /// The video path as given.
        path: PathBuf,
        /// Why, in words (ffmpeg's own where it gave one).
        reason: String,
    },
    /// ffmpeg could not be started, stopped reading, or exited with an error; the text is
    /// its own last words (a failed run).
    #[error("ffmpeg failed: {0}")]
    Ffmpeg(String),
    /// Another run holds the frame folder's lock (bad input: nothing was rendered).
    #[error("a run of another manifest is writing into {} ({holder}); wait for it to end, or write elsewhere", shown(.dir))]
    Busy {
        /// The frame folder.
        dir: PathBuf,
        /// What the holder wrote in the lock file: its pid, manifest and start time.
        holder: String,
    },
    /// Another run of the same manifest writes into the folder that `clean` was asked to
    /// clean (bad input: nothing was removed).
    #[error("{}: another run of this manifest is writing into the folder: clean when it has ended", shown(.dir))]
    InUse {
        /// The frame folder.
        dir: PathBuf,
    },
    /// Frames in the folder were recorded by another manifest, and would be overwritten
    /// (bad input: nothing was rendered).
    #[error("{} holds {count} frame(s) rendered by another manifest ({other}: frames {frames}); they would be overwritten", shown(.dir))]
    Foreign {
        /// The frame folder.
        dir: PathBuf,
        /// The file name of the manifest the frames record.
        other: String,
        /// Their ranges, render-farm style.
        frames: String,
        /// How many.
        count: usize,
    },
    /// A draft's run would write over final frames of its manifest (`-o` into the finals'
    /// folder; bad input: nothing was rendered).
    #[error("{} holds {count} final frame(s) of this manifest (frames {frames}); this draft ({draft}) would replace them", shown(.dir))]
    Finals {
        /// The frame folder.
        dir: PathBuf,
        /// Their ranges, render-farm style.
        frames: String,
        /// How many.
        count: usize,
        /// The draft's label.
        draft: String,
    },
    /// Files under the names a command would replace or remove are not this manifest's:
    /// another manifest's frames, or files with no record (bad input: nothing was done).
    #[error("{files}: {whose}, and would be {what}")]
    NotOurs {
        /// `replaced` or `removed`.
        what: String,
        /// The first file, and how many others.
        files: String,
        /// Whose the first one is, in words.
        whose: String,
    },
    /// An output would be written over one of the run's inputs, or over a file the tool
    /// did not write (bad input: nothing was written).
    #[error("{}: {why}; name another file", shown(.path))]
    Overwrite {
        /// The output as given.
        path: PathBuf,
        /// What it is.
        why: String,
    },
    /// The video file exists and would be replaced (bad input: nothing was rendered).
    #[error("the video {} exists and would be replaced", shown(.0))]
    VideoExists(PathBuf),
    /// The frame folder is not ready to encode (bad input: nothing was encoded).
    #[error("{} is not ready to encode: {why}", shown(.dir))]
    NotReady {
        /// The frame folder.
        dir: PathBuf,
        /// Which frames are stale, missing or past the end.
        why: String,
    },
    /// A draft's overrides cannot apply to this manifest (bad input).
    #[error("{0}")]
    Draft(String),
    /// The plot of `animate stats` could not be drawn or written (the run failed).
    #[error("cannot write the plot {}: {why}", shown(.path))]
    Plot {
        /// The plot's file.
        path: PathBuf,
        /// Why.
        why: String,
    },
    /// A job template cannot carry what it was asked (bad input: nothing was written).
    #[error("{0}")]
    Job(String),
    /// Standard output is closed, so streamed frames would go nowhere (bad input).
    #[error("standard output is closed: the frames would go nowhere")]
    StdoutClosed,
    /// The run was stopped by this signal number (2 SIGINT, 15 SIGTERM) after the frames
    /// in flight were finished.
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
            | AnimError::Antialias { .. }
            | AnimError::Camera { .. }
            | AnimError::Folder { .. }
            | AnimError::FfmpegMissing
            | AnimError::VideoTarget { .. }
            | AnimError::Busy { .. }
            | AnimError::InUse { .. }
            | AnimError::Foreign { .. }
            | AnimError::Finals { .. }
            | AnimError::NotOurs { .. }
            | AnimError::Overwrite { .. }
            | AnimError::Export(_)
            | AnimError::VideoExists(_)
            | AnimError::NotReady { .. }
            | AnimError::Draft(_)
            | AnimError::Job(_)
            | AnimError::StdoutClosed => Outcome::BadInput,
            AnimError::Write { .. }
            | AnimError::Stream(_)
            | AnimError::Stdout(_)
            | AnimError::Ffmpeg(_)
            | AnimError::Plot { .. } => Outcome::Failed,
            AnimError::Interrupted(sig) => Outcome::Interrupted(*sig),
        }
    }

    /// The process exit status for this error.
    pub fn exit_code(&self) -> u8 {
        self.outcome().code()
    }
}

/// Why a folder cannot be used, in words rather than the system's alone: a file in the
/// way, or a parent that does not take new folders.
fn folder_reason(dir: &std::path::Path, source: &std::io::Error) -> String {
    if dir.exists() && !dir.is_dir() {
        return format!("a file of that name is in the way ({source}); name a folder");
    }
    let parent = dir.parent().filter(|p| !p.as_os_str().is_empty());
    match (source.kind(), parent) {
        (std::io::ErrorKind::NotFound, Some(p)) if p.is_dir() => {
            format!("{} does not take new folders ({source})", shown(p))
        }
        (std::io::ErrorKind::NotFound, Some(p)) => {
            format!("cannot create it under {} ({source})", shown(p))
        }
        (std::io::ErrorKind::PermissionDenied, _) => {
            format!("no permission to create or write it ({source})")
        }
        _ => source.to_string(),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn exit_codes() {
        assert_eq!(AnimError::Reference("x".into()).exit_code(), 2);
        let loc = FileLoc::default();
        assert_eq!(AnimError::Camera { frame: 3, loc }.exit_code(), 2);
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
