//! The render subcommand as a library call: which frames (`Selection`), where they go
//! (`Destination`: a folder, a stream or a video), whether up-to-date frames are kept,
//! and the checks made before any frame renders (cameras, the video target).

use super::events::Reporter;
use super::pipeline::{render_to_folder, render_to_stream, Summary};
pub use super::policy::{Encoding, Policy};
use super::select::select;
use super::video::render_to_video;
use crate::error::AnimError;
use crate::project::Animation;
use std::io::Write;
use std::path::PathBuf;
use std::sync::atomic::AtomicUsize;
use whitted::output::ImageFormat;

/// Where the frames of a run go.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum Destination {
    /// Files in a folder (the manifest's `[output] dir` unless told otherwise).
    Folder(PathBuf),
    /// Encoded one after another, in frame order, on a stream.
    Stream(ImageFormat),
    /// Through ffmpeg into a video file.
    Video(PathBuf),
}

impl Destination {
    /// The folder the frames go into (none for a stream or a video).
    pub fn folder(&self) -> PathBuf {
        match self {
            Destination::Folder(dir) => dir.clone(),
            _ => PathBuf::new(),
        }
    }

    /// Where the frames went, for the summary line.
    pub fn describe(&self) -> String {
        match self {
            Destination::Folder(p) | Destination::Video(p) => whitted::fileloc::shown(p),
            Destination::Stream(_) => "standard output".into(),
        }
    }
}

/// The frames of a run: a frame list and chunk `(index, count)` of it, over the whole
/// sequence.
pub fn frames_of(
    anim: &Animation,
    list: Option<&str>,
    shard: Option<(u32, u32)>,
) -> Result<Vec<u32>, AnimError> {
    Ok(select(anim.manifest.frames, list, shard)?)
}

/// The frames of a run: `frames_of`, or with `balance` the shard of equal predicted cost
/// (a 1/8-size pre-pass, traced on the current rayon pool like the render).
pub fn planned(
    anim: &Animation,
    list: Option<&str>,
    shard: Option<(u32, u32)>,
    balance: bool,
) -> Result<Vec<u32>, AnimError> {
    match balance {
        true => super::balance::select_balanced(anim, list, shard),
        false => frames_of(anim, list, shard),
    }
}

/// Renders `frames` of `anim` to `destination` (a stream writes into `stream`), keeping
/// and replacing what `policy` says.
pub fn render(
    anim: &Animation,
    frames: &[u32],
    destination: &Destination,
    policy: &Policy,
    stream: &mut dyn Write,
    reporter: &dyn Reporter,
    stop: &AtomicUsize,
) -> Result<Summary, AnimError> {
    anim.check_cameras(frames)?;
    match destination {
        Destination::Folder(dir) => render_to_folder(anim, frames, dir, policy, reporter, stop),
        Destination::Stream(format) => {
            render_to_stream(anim, frames, stream, *format, reporter, stop)
        }
        Destination::Video(file) => render_to_video(anim, frames, file, policy, reporter, stop),
    }
}

/// The options ffmpeg needs to read `--stdout raw` frames of `anim`.
pub fn ffmpeg_raw_input(anim: &Animation) -> String {
    format!(
        "-f rawvideo -pix_fmt rgb24 -s {}x{} -r {} -i -",
        anim.width, anim.height, anim.manifest.fps
    )
}
