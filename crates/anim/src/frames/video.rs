//! `--video FILE`: ffmpeg, found on PATH, started with raw RGB frames on its standard
//! input:
//!
//! ```text
//! ffmpeg -y -loglevel error -f rawvideo -pix_fmt rgb24 -s WxH -r FPS -i - \
//!        -vf pad=ceil(iw/2)*2:ceil(ih/2)*2,scale=out_color_matrix=bt709:out_range=tv \
//!        [-c:v CODEC] [-crf N] -pix_fmt yuv420p BT.709 TAGS [-movflags +faststart] \
//!        .FILE.XXXXXX.EXT
//! ```
//!
//! The BT.709 matrix, tags and `faststart` are `tags`'.
//!
//! ffmpeg writes a hidden temporary beside FILE, renamed onto FILE when it succeeds: an
//! interrupted, killed or failing encode leaves the previous FILE as it was. An existing
//! FILE is replaced only when forced. A signal ends the run within a second even when
//! ffmpeg stopped reading (it is killed).
//!
//! yuv420p plays everywhere but needs even sizes, hence the one-pixel pad for odd ones.
//! The container and codec follow FILE's extension, as ffmpeg decides. Before any frame
//! renders, the target is checked: its folder must exist, and ffmpeg must be able to
//! write a one-frame file of that kind (a probe in a temporary folder); ffmpeg's own
//! words are the error. If ffmpeg stops while frames flow, its words are the error too,
//! not the broken pipe they cause.

use super::events::Reporter;
use super::pipeline::{render_to_stream, Summary};
use super::policy::{Encoding, Policy};
use crate::error::AnimError;
use crate::project::Animation;
use std::io::Read;
use std::path::Path;
use std::process::{Child, ChildStdin, Command, Stdio};
use std::sync::atomic::{AtomicBool, AtomicUsize, Ordering};
use std::sync::Mutex;
use std::thread::JoinHandle;
use std::time::Duration;
use whitted::output::ImageFormat;
use whitted_cmd::process::{after_stop, stopped};

/// How long a stop signal waits for the frames to stop flowing before ffmpeg is killed
/// (a stopped or stalled ffmpeg would otherwise hold the run forever).
const STOP_GRACE: Duration = Duration::from_millis(300);

/// Renders `frames` into the video `file` through ffmpeg; on a failure upstream ffmpeg is
/// stopped and the error returned.
pub fn render_to_video(
    anim: &Animation,
    frames: &[u32],
    file: &Path,
    policy: &Policy,
    reporter: &dyn Reporter,
    stop: &AtomicUsize,
) -> Result<Summary, AnimError> {
    check_target(file, policy.force)?;
    let fps = anim.manifest.fps;
    let ffmpeg = Ffmpeg::start(file, anim.width, anim.height, fps, &policy.encoding)?;
    ffmpeg.feed(stop, |input| {
        render_to_stream(anim, frames, input, ImageFormat::Raw, reporter, stop)
    })
}

/// Refuses a video target whose folder is missing, that exists (unless `force`), or
/// whose kind ffmpeg cannot write.
pub fn check_target(file: &Path, force: bool) -> Result<(), AnimError> {
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
    if !force && std::fs::symlink_metadata(file).is_ok() {
        return Err(AnimError::VideoExists(file.to_path_buf()));
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

/// A running ffmpeg that encodes what is written to its standard input into a hidden
/// temporary file beside the video (`.NAME.XXXXXX.EXT`, the extension kept so that ffmpeg
/// picks the same container), renamed onto the video's name only once ffmpeg succeeded.
pub(crate) struct Ffmpeg {
    child: Mutex<Child>,
    stdin: Option<ChildStdin>,
    stderr: Option<JoinHandle<String>>,
    temp: tempfile::TempPath,
    file: std::path::PathBuf,
}

impl Ffmpeg {
    /// Starts ffmpeg writing (a temporary beside) `file` from `width`×`height` RGB frames
    /// at `fps`, encoded as `encoding` says.
    pub fn start(
        file: &Path,
        width: u32,
        height: u32,
        fps: f64,
        encoding: &Encoding,
    ) -> Result<Ffmpeg, AnimError> {
        let ext = file.extension().map_or("".into(), |e| e.to_string_lossy());
        let temp = whitted::output::temp_beside_as(file, &format!(".{ext}"))
            .map_err(|e| AnimError::VideoTarget {
                path: file.to_path_buf(),
                reason: format!("cannot create a file in its folder: {e}"),
            })?
            .into_temp_path();
        let mut cmd = Command::new("ffmpeg");
        cmd.args(["-y", "-nostdin", "-loglevel", "error", "-f", "rawvideo"])
            .args(["-pix_fmt", "rgb24", "-s", &format!("{width}x{height}")])
            .args(["-r", &fps.to_string(), "-i", "-"]);
        let pix_fmt = encoding.pix_fmt.as_deref().unwrap_or("yuv420p");
        let pad = "pad=ceil(iw/2)*2:ceil(ih/2)*2";
        match super::tags::filter(pix_fmt) {
            Some(scale) => cmd.args(["-vf", &format!("{pad},{scale}")]),
            None => cmd.args(["-vf", pad]),
        };
        if let Some(codec) = &encoding.codec {
            cmd.args(["-c:v", codec]);
        }
        if let Some(crf) = encoding.crf {
            cmd.args(["-crf", &crf.to_string()]);
        }
        let mut child = cmd
            .args(["-pix_fmt", pix_fmt])
            .args(super::tags::options(pix_fmt, &ext))
            .arg(&temp)
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
        Ok(Ffmpeg {
            stdin: child.stdin.take(),
            child: Mutex::new(child),
            stderr,
            temp,
            file: file.to_path_buf(),
        })
    }

    /// Runs `work` with the pipe into ffmpeg, then finishes the video. A signal in `stop`
    /// ends it within `STOP_GRACE` whatever ffmpeg does: if the frames have not stopped
    /// flowing by then (ffmpeg stopped or stalled), ffmpeg is killed, which ends the
    /// write. On any failure the temporary file is removed and the video left as it was.
    pub fn feed(
        mut self,
        stop: &AtomicUsize,
        work: impl FnOnce(&mut ChildStdin) -> Result<Summary, AnimError>,
    ) -> Result<Summary, AnimError> {
        let done = AtomicBool::new(false);
        let Some(mut input) = self.stdin.take() else {
            return Err(AnimError::Ffmpeg("its input is closed".into()));
        };
        let child = &self.child;
        let result = std::thread::scope(|s| {
            s.spawn(|| {
                after_stop(stop, &done, STOP_GRACE, |_| {
                    if let Ok(mut c) = child.lock() {
                        let _ = c.kill();
                    }
                })
            });
            let result = work(&mut input);
            done.store(true, Ordering::SeqCst);
            result
        });
        drop(input);
        match (result, stopped(stop)) {
            (Ok(summary), None) => self.finish().map(|()| summary),
            (_, Some(sig)) => {
                self.abort();
                Err(AnimError::Interrupted(sig))
            }
            (Err(AnimError::Stream(e)), None) => Err(self.failure(e)),
            (Err(e), None) => {
                self.abort();
                Err(e)
            }
        }
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

    fn wait(&self) -> std::io::Result<std::process::ExitStatus> {
        match self.child.lock() {
            Ok(mut c) => c.wait(),
            Err(_) => Err(std::io::Error::other("ffmpeg's handle was poisoned")),
        }
    }

    /// Waits for ffmpeg to finish the file, then renames it onto the video's name.
    fn finish(mut self) -> Result<(), AnimError> {
        let status = self
            .wait()
            .map_err(|e| AnimError::Ffmpeg(format!("waiting for it: {e}")))?;
        let words = self.words();
        if !status.success() {
            return Err(AnimError::Ffmpeg(format!("{status}: {words}")));
        }
        let file = self.file.clone();
        self.temp
            .persist(&file)
            .map_err(|e| AnimError::VideoTarget {
                path: file.clone(),
                reason: format!("cannot rename the finished video onto it: {}", e.error),
            })
    }

    /// The error when writing into ffmpeg failed: ffmpeg's own words if it has ended.
    fn failure(mut self, e: std::io::Error) -> AnimError {
        let _ = self.wait();
        let words = self.words();
        if words.is_empty() {
            AnimError::Stream(e)
        } else {
            AnimError::Ffmpeg(words)
        }
    }

    /// Stops ffmpeg after a failure upstream, without waiting for a finished file; the
    /// temporary file goes with `self`.
    fn abort(self) {
        if let Ok(mut c) = self.child.lock() {
            let _ = c.kill();
            let _ = c.wait();
        }
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
