//! `--video FILE`: ffmpeg, found on PATH, started with raw RGB frames on its standard
//! input:
//!
//! ```text
//! ffmpeg -y -loglevel error -f rawvideo -pix_fmt rgb24 -s WxH -r FPS -i - \
//!        -vf pad=ceil(iw/2)*2:ceil(ih/2)*2 -pix_fmt yuv420p FILE
//! ```
//!
//! yuv420p plays everywhere but needs even sizes, hence the one-pixel pad for odd ones.
//! The container and codec follow FILE's extension, as ffmpeg decides. Before any frame
//! renders, the target is checked: its folder must exist, and ffmpeg must be able to
//! write a one-frame file of that kind (a probe in a temporary folder); ffmpeg's own
//! words are the error. If ffmpeg stops while frames flow, its words are the error too,
//! not the broken pipe they cause.

use super::events::Reporter;
use super::pipeline::{render_to_stream, Summary};
use crate::anim::error::AnimError;
use crate::anim::project::Animation;
use crate::output::ImageFormat;
use std::io::Read;
use std::path::Path;
use std::process::{Child, ChildStdin, Command, Stdio};
use std::sync::atomic::AtomicUsize;
use std::thread::JoinHandle;

/// Renders `frames` into the video `file` through ffmpeg; on a failure upstream ffmpeg is
/// stopped and the error returned.
pub fn render_to_video(
    anim: &Animation,
    frames: &[u32],
    file: &Path,
    reporter: &dyn Reporter,
    stop: &AtomicUsize,
) -> Result<Summary, AnimError> {
    check_target(file)?;
    let fps = anim.manifest.fps;
    let mut ffmpeg = Ffmpeg::start(file, anim.width, anim.height, fps)?;
    let result = ffmpeg
        .input()
        .and_then(|input| render_to_stream(anim, frames, input, ImageFormat::Raw, reporter, stop));
    match result {
        Ok(summary) => ffmpeg.finish().map(|()| summary),
        Err(AnimError::Stream(e)) => Err(ffmpeg.failure(e)),
        Err(e) => {
            ffmpeg.abort();
            Err(e)
        }
    }
}

/// Refuses a video target whose folder is missing or whose kind ffmpeg cannot write.
pub fn check_target(file: &Path) -> Result<(), AnimError> {
    let refuse = |reason: String| AnimError::VideoTarget {
        path: file.to_path_buf(),
        reason,
    };
    let folder = match file.parent() {
        Some(d) if !d.as_os_str().is_empty() => d,
        _ => Path::new("."),
    };
    if !folder.is_dir() {
        return Err(refuse(format!(
            "the folder {} does not exist",
            folder.display()
        )));
    }
    if file.is_dir() {
        return Err(refuse("it is a folder".into()));
    }
    let ext = file.extension().and_then(|e| e.to_str()).unwrap_or("");
    let probe_dir = tempfile::tempdir().map_err(|e| refuse(e.to_string()))?;
    let probe = probe_dir.path().join(format!("probe.{ext}"));
    let output = Command::new("ffmpeg")
        .args(["-nostdin", "-v", "error", "-f", "lavfi", "-i"])
        .args([
            "color=c=black:s=16x16:r=1",
            "-frames:v",
            "1",
            "-pix_fmt",
            "yuv420p",
        ])
        .arg(&probe)
        .stdin(Stdio::null())
        .stdout(Stdio::null())
        .output()
        .map_err(spawn_error)?;
    if output.status.success() {
        return Ok(());
    }
    let words = String::from_utf8_lossy(&output.stderr);
    let words = words.replace(&probe.display().to_string(), &file.display().to_string());
    Err(refuse(format!("ffmpeg cannot write it: {}", plain(&words))))
}

/// ffmpeg's lines without their `[context @ 0x…]` prefixes, joined by "; ".
fn plain(words: &str) -> String {
    words
        .lines()
        .map(|l| match (l.starts_with('['), l.find("] ")) {
            (true, Some(end)) => &l[end + 2..],
            _ => l,
        })
        .map(str::trim)
        .filter(|l| !l.is_empty())
        .collect::<Vec<_>>()
        .join("; ")
}

fn spawn_error(e: std::io::Error) -> AnimError {
    if e.kind() == std::io::ErrorKind::NotFound {
        AnimError::FfmpegMissing
    } else {
        AnimError::Ffmpeg(format!("cannot start ffmpeg: {e}"))
    }
}

/// A running ffmpeg that encodes what is written to its standard input.
pub(crate) struct Ffmpeg {
    child: Child,
    stderr: Option<JoinHandle<String>>,
}

impl Ffmpeg {
    /// Starts ffmpeg writing `file` from `width`×`height` RGB frames at `fps`.
    pub fn start(file: &Path, width: u32, height: u32, fps: f64) -> Result<Ffmpeg, AnimError> {
        let mut child = Command::new("ffmpeg")
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
            .stderr(Stdio::piped())
            .spawn()
            .map_err(spawn_error)?;
        let stderr = child.stderr.take().map(|mut pipe| {
            std::thread::spawn(move || {
                let mut text = String::new();
                let _ = pipe.read_to_string(&mut text);
                text
            })
        });
        Ok(Ffmpeg { child, stderr })
    }

    /// The pipe into ffmpeg.
    pub fn input(&mut self) -> Result<&mut ChildStdin, AnimError> {
        self.child
            .stdin
            .as_mut()
            .ok_or_else(|| AnimError::Ffmpeg("its input is closed".into()))
    }

    /// What ffmpeg printed, once it has ended.
    fn words(&mut self) -> String {
        plain(
            &self
                .stderr
                .take()
                .and_then(|h| h.join().ok())
                .unwrap_or_default(),
        )
    }

    /// Closes the input and waits for ffmpeg to finish the file.
    pub fn finish(mut self) -> Result<(), AnimError> {
        drop(self.child.stdin.take());
        let status = self
            .child
            .wait()
            .map_err(|e| AnimError::Ffmpeg(format!("waiting for it: {e}")))?;
        let words = self.words();
        if status.success() {
            Ok(())
        } else {
            Err(AnimError::Ffmpeg(format!("{status}: {words}")))
        }
    }

    /// The error when writing into ffmpeg failed: ffmpeg's own words if it has ended.
    fn failure(mut self, e: std::io::Error) -> AnimError {
        drop(self.child.stdin.take());
        let _ = self.child.wait();
        let words = self.words();
        if words.is_empty() {
            AnimError::Stream(e)
        } else {
            AnimError::Ffmpeg(words)
        }
    }

    /// Stops ffmpeg after a failure upstream, without waiting for a finished file.
    pub fn abort(mut self) {
        drop(self.child.stdin.take());
        let _ = self.child.kill();
        let _ = self.child.wait();
    }
}

#[cfg(test)]
mod tests {
    #[test]
    fn ffmpeg_words_without_addresses() {
        let words = "[NULL @ 0x5651ebd30a40] Unable to find a suitable output format for 'a.xyz'\na.xyz: Invalid argument\n";
        assert_eq!(
            super::plain(words),
            "Unable to find a suitable output format for 'a.xyz'; a.xyz: Invalid argument"
        );
    }
}
