//! `animate encode MANIFEST [-o VIDEO] [--codec C] [--crf N] [--pix-fmt F] [--force]`: a
//! frame folder that is already rendered, turned into a video without rendering again.
//! The folder must be complete and up to date first (`status`: every frame of the
//! manifest present, whole and recording the inputs the manifest now gives it); then
//! each frame is decoded in turn (one frame in memory at a time) and piped into ffmpeg
//! at the manifest's fps, exactly as `--video` pipes freshly rendered ones, into a
//! temporary beside VIDEO renamed on success. VIDEO defaults to the folder's path with
//! `.mp4` (`out/orbit` → `out/orbit.mp4`).

use super::events::{Event, Reporter};
use super::pipeline::Summary;
use super::policy::Policy;
use super::status::{ranges, status};
use super::video::{check_target, Ffmpeg};
use crate::error::AnimError;
use crate::project::Animation;
use std::io::Write;
use std::path::{Path, PathBuf};
use std::sync::atomic::AtomicUsize;
use std::time::Instant;
use whitted::output::read_rgb;
use whitted_cmd::process::stopped;

/// The video `encode` makes of `dir` when none is named: `dir` + `.mp4`.
pub fn default_video(dir: &Path) -> PathBuf {
    let mut name = dir.as_os_str().to_owned();
    name.push(".mp4");
    PathBuf::from(name)
}

/// Refuses a folder that is not complete and up to date, saying what is not, frame by
/// frame: missing frames, broken ones (damaged, cut short, of another size), and mixed
/// ones (drafts among finals, another renderer, other settings), the last only unless
/// `allow_mixed`.
fn ready(anim: &Animation, dir: &Path, allow_mixed: bool) -> Result<(), AnimError> {
    let all: Vec<u32> = (0..anim.manifest.frames).collect();
    let report = status(anim, dir, &all, false);
    let mut why = Vec::new();
    if !report.missing.is_empty() {
        why.push(format!("missing {}", ranges(&report.missing)));
    }
    let mut mixed = false;
    for (reason, frames) in &report.stale_why {
        let broken = reason.starts_with("damaged");
        if broken || !allow_mixed {
            why.push(format!("{} {} ({reason})", kind(reason), ranges(frames)));
            mixed |= !broken;
        }
    }
    if why.is_empty() {
        return Ok(());
    }
    let hint = match mixed {
        true => "`--allow-mixed` encodes mixed frames anyway; `animate MANIFEST --resume` renders them again",
        false => "`animate MANIFEST --resume` completes it",
    };
    Err(AnimError::NotReady {
        dir: dir.to_path_buf(),
        why: format!("frames {} ({hint})", why.join("; ")),
    })
}

/// What a stale frame's reason makes it, in the refusal's words.
fn kind(reason: &str) -> &'static str {
    if reason.starts_with("damaged") {
        "broken"
    } else if reason.contains("draft") {
        "drafts mixed with finals"
    } else if reason.starts_with("the renderer was") {
        "of another renderer version"
    } else {
        "stale"
    }
}

/// The RGB bytes of frame `frame`'s file in `dir` (`output::read_rgb`).
fn pixels(anim: &Animation, dir: &Path, frame: u32) -> Result<Vec<u8>, AnimError> {
    let path = anim.frame_path(dir, frame);
    read_rgb(&path, anim.format(), anim.width, anim.height).map_err(|e| AnimError::NotReady {
        dir: dir.to_path_buf(),
        why: format!("{}: {e}", path.display()),
    })
}

/// Encodes the frames of `dir` into `video` (see the module's documentation).
pub fn encode(
    anim: &Animation,
    dir: &Path,
    video: &Path,
    policy: &Policy,
    reporter: &dyn Reporter,
    stop: &AtomicUsize,
) -> Result<Summary, AnimError> {
    let _lock = super::lock::lock(dir, &anim.manifest.path)?;
    ready(anim, dir, policy.allow_mixed)?;
    check_target(video, policy.force)?;
    let (w, h, fps) = (anim.width, anim.height, anim.manifest.fps);
    let ffmpeg = Ffmpeg::start(video, w, h, fps, &policy.encoding)?;
    let frames = anim.manifest.frames;
    ffmpeg.feed(stop, |input| {
        reporter.event(Event::Started {
            total: frames as usize,
            skipped: 0,
        });
        for frame in 0..frames {
            if let Some(sig) = stopped(stop) {
                return Err(AnimError::Interrupted(sig));
            }
            let start = Instant::now();
            let rgb = pixels(anim, dir, frame)?;
            input.write_all(&rgb).map_err(AnimError::Stream)?;
            reporter.event(Event::Finished {
                frame,
                seconds: start.elapsed().as_secs_f64(),
                rays: Default::default(),
            });
        }
        Ok(Summary {
            rendered: frames as usize,
            ..Summary::default()
        })
    })
}

#[cfg(test)]
mod tests {
    #[test]
    fn the_default_video_is_beside_the_folder() {
        let v = super::default_video(std::path::Path::new("out/orbit"));
        assert_eq!(v, std::path::PathBuf::from("out/orbit.mp4"));
    }
}
