//! `animate clean` (frames past the end, killed runs' temporaries and free claim files,
//! only this manifest's unless forced) and `animate encode` (a complete folder into a video).

use super::emit;
use crate::error::AnimError;
use crate::frames::encode;
use crate::frames::events::Reporter;
use crate::frames::folder;
use crate::frames::pipeline::Summary;
use crate::frames::policy::{Encoding, Policy};
use crate::frames::status::ranges;
use crate::project::{Animation, Project};
use std::io::Write;
use std::path::PathBuf;
use std::sync::atomic::AtomicUsize;
use whitted::exit::Outcome;
use whitted::fileloc::shown;

/// What `animate clean` was asked.
#[derive(Clone, Debug, Default)]
pub struct CleanRequest {
    /// The frame folder instead of the manifest's.
    pub dir: Option<PathBuf>,
    /// Only say what would go.
    pub dry_run: bool,
    /// Also remove files past the end that are not this manifest's.
    pub force: bool,
}

/// Runs `animate clean`, saying what went (or would go) on `out`.
pub fn clean(
    project: &Project,
    request: &CleanRequest,
    out: &mut dyn Write,
) -> Result<Outcome, AnimError> {
    let anim = Animation::new(project)?;
    let dir = (request.dir.clone()).unwrap_or_else(|| project.manifest.output.dir.clone());
    let text = if request.dry_run {
        let past: Vec<u32> = folder::beyond(&anim, &dir).iter().map(|f| f.0).collect();
        let others = folder::not_ours(&anim, &dir).len();
        let refused = match (others, request.force) {
            (0, _) | (_, true) => String::new(),
            (n, false) => format!(" ({n} of them not this manifest's: removed only when forced)"),
        };
        format!(
            "{}: would remove {} frame(s) past the end ({}){refused}, {} temporary file(s) \
             and {} claim file(s) (those no run holds)\n",
            shown(&dir),
            past.len(),
            ranges(&past),
            folder::temporaries(&anim, &dir).len(),
            folder::claim_files(&anim, &dir)
        )
    } else {
        let cleaned = folder::clean(&anim, &dir, request.force)?;
        format!(
            "{}: removed {} frame(s) past the end ({}), {} temporary file(s) and {} claim \
             file(s)\n",
            shown(&dir),
            cleaned.beyond.len(),
            ranges(&cleaned.beyond),
            cleaned.temporaries,
            cleaned.claims
        )
    };
    emit(out, text.as_bytes())?;
    Ok(Outcome::Success)
}

/// What `animate encode` was asked.
#[derive(Clone, Debug, Default)]
pub struct EncodeRequest {
    /// The frame folder instead of the manifest's.
    pub dir: Option<PathBuf>,
    /// The video instead of the folder's path with `.mp4`.
    pub video: Option<PathBuf>,
    /// ffmpeg's options.
    pub encoding: Encoding,
    /// Replace an existing video.
    pub force: bool,
    /// Encode frames that are sound but mixed (drafts and finals, renderer versions,
    /// settings) instead of refusing the folder.
    pub allow_mixed: bool,
}

/// An encoded video: what was encoded from where into where.
#[derive(Clone, Debug)]
pub struct Encoded {
    /// The frames fed to ffmpeg.
    pub summary: Summary,
    /// The frame folder.
    pub dir: PathBuf,
    /// The video file.
    pub video: PathBuf,
}

/// Runs `animate encode`, telling `reporter` of each frame fed.
pub fn encode(
    project: &Project,
    request: &EncodeRequest,
    reporter: &dyn Reporter,
    stop: &AtomicUsize,
) -> Result<Encoded, AnimError> {
    let anim = Animation::new(project)?;
    let dir = (request.dir.clone()).unwrap_or_else(|| project.manifest.output.dir.clone());
    let video = (request.video.clone()).unwrap_or_else(|| encode::default_video(&dir));
    let policy = Policy {
        force: request.force,
        allow_mixed: request.allow_mixed,
        encoding: request.encoding.clone(),
        ..Policy::default()
    };
    let summary = encode::encode(&anim, &dir, &video, &policy, reporter, stop)?;
    Ok(Encoded {
        summary,
        dir,
        video,
    })
}
