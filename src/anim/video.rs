//! `--video FILE`: ffmpeg, found on PATH, started with raw RGB frames on its standard
//! input:
//!
//! ```text
//! ffmpeg -y -loglevel error -f rawvideo -pix_fmt rgb24 -s WxH -r FPS -i - \
//!        -vf pad=ceil(iw/2)*2:ceil(ih/2)*2 -pix_fmt yuv420p FILE
//! ```
//!
//! yuv420p plays everywhere but needs even sizes, hence the one-pixel pad for odd ones.
//! The container and codec follow FILE's extension, as ffmpeg decides.

use super::error::AnimError;
use super::pipeline::{render_to_stream, Animation, Summary};
use crate::output::ImageFormat;
use indicatif::ProgressBar;
use std::path::Path;
use std::process::{Child, ChildStdin, Command, Stdio};
use std::sync::atomic::AtomicUsize;

/// Renders `frames` into the video `file` through ffmpeg; on a failure upstream ffmpeg is
/// stopped and the error returned.
pub fn render_to_video(
    anim: &Animation,
    frames: &[u32],
    file: &Path,
    progress: &ProgressBar,
    stop: &AtomicUsize,
) -> Result<Summary, AnimError> {
    let fps = anim.manifest.fps;
    let mut ffmpeg = Ffmpeg::start(file, anim.width, anim.height, fps)?;
    let result = ffmpeg
        .input()
        .and_then(|input| render_to_stream(anim, frames, input, ImageFormat::Raw, progress, stop));
    match result {
        Ok(summary) => ffmpeg.finish().map(|()| summary),
        Err(e) => {
            ffmpeg.abort();
            Err(e)
        }
    }
}

/// A running ffmpeg that encodes what is written to its standard input.
pub struct Ffmpeg {
    child: Child,
}

impl Ffmpeg {
    /// Starts ffmpeg writing `file` from `width`×`height` RGB frames at `fps`.
    pub fn start(file: &Path, width: u32, height: u32, fps: f64) -> Result<Ffmpeg, AnimError> {
        let child = Command::new("ffmpeg")
            .args(["-y", "-nostdin", "-loglevel", "error", "-f", "rawvideo"])
            .args(["-pix_fmt", "rgb24", "-s", &format!("{width}x{height}")])
            .args(["-r", &fps.to_string(), "-i", "-"])
            .args([
                "-vf",
                "pad=ceil(iw/2)*2:ceil(ih/2)*2",
                "-pix_fmt",
                "yuv420p",
            ])
            .arg(file)
            .stdin(Stdio::piped())
            .stdout(Stdio::null())
            .spawn()
            .map_err(|e| {
                let why = if e.kind() == std::io::ErrorKind::NotFound {
                    "ffmpeg was not found on PATH: install it (apt-get install ffmpeg), \
                     or pipe --stdout raw into an encoder of your choice"
                        .to_string()
                } else {
                    format!("cannot start ffmpeg: {e}")
                };
                AnimError::Ffmpeg(why)
            })?;
        Ok(Ffmpeg { child })
    }

    /// The pipe into ffmpeg.
    pub fn input(&mut self) -> Result<&mut ChildStdin, AnimError> {
        self.child
            .stdin
            .as_mut()
            .ok_or_else(|| AnimError::Ffmpeg("ffmpeg's input is closed".into()))
    }

    /// Closes the input and waits for ffmpeg to finish the file.
    pub fn finish(mut self) -> Result<(), AnimError> {
        drop(self.child.stdin.take());
        let status = self
            .child
            .wait()
            .map_err(|e| AnimError::Ffmpeg(format!("waiting for ffmpeg: {e}")))?;
        if status.success() {
            Ok(())
        } else {
            Err(AnimError::Ffmpeg(format!("ffmpeg failed ({status})")))
        }
    }

    /// Stops ffmpeg after a failure upstream, without waiting for a finished file.
    pub fn abort(mut self) {
        drop(self.child.stdin.take());
        let _ = self.child.kill();
        let _ = self.child.wait();
    }
}
