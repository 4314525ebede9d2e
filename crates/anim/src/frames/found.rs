//! What a run makes of the files already under the names of the frames it is asked for
//! (`pipeline::render_to_folder` looks at each once): up to date (`--resume`), another
//! manifest's, not the tool's at all, a final under a draft, or to render.

use super::owner;
use super::policy::Policy;
use super::provenance::{self, Inspection};
use super::status;
use crate::error::AnimError;
use crate::project::Animation;
use std::path::Path;

/// What a run makes of the file of a frame it is asked for.
pub(crate) enum Found {
    /// Up to date (`--resume`): left as it is.
    UpToDate,
    /// Recorded by this other manifest: not overwritten unless forced.
    Foreign(String),
    /// A sound image with no record, or a regular file that is no frame at all, which the
    /// tool did not write (a photo or notes under the frame's name): not overwritten
    /// unless forced.
    Unrecorded(std::path::PathBuf),
    /// A final frame of this manifest, which a draft would replace: not overwritten unless
    /// forced (a final replaces drafts freely).
    Final,
    /// Missing, stale or damaged, or the run is not told to look: to render.
    Render,
}

/// Looks once at frame `frame`'s file: whether `--resume` may skip it (its record the
/// digest the manifest now gives, and with `--verify` its pixels decode) and, if not,
/// whether it records another manifest than `ours`.
pub(crate) fn found(
    anim: &Animation,
    dir: &Path,
    frame: u32,
    policy: &Policy,
    ours: Option<&str>,
) -> Found {
    if !policy.resume && policy.force {
        return Found::Render;
    }
    // The frame's plan: its path; its states and digest only if `--resume` asks.
    let plan = anim.plan_in(dir, frame);
    let path = plan.path();
    let (format, w, h) = (anim.format(), anim.width, anim.height);
    let record = match provenance::inspect(path, format, w, h, false) {
        Inspection::Sound(record) => record,
        // Whatever is under a frame's name and is no frame of the format (a user's text, a
        // link, a FIFO) is not the tool's: replaced only with --force (the link, never its
        // target). A folder is left to the write, which refuses it.
        Inspection::Damaged(_)
            if !policy.force
                && std::fs::symlink_metadata(path).is_ok_and(|m| !m.is_dir())
                && !owner::looks_like_a_frame(anim, path, format) =>
        {
            return Found::Unrecorded(path.to_path_buf())
        }
        _ => return Found::Render,
    };
    if policy.resume
        && record.digest.as_deref() == Some(plan.digest())
        && (!policy.verify || provenance::decode(path, format, w, h).is_ok())
    {
        return Found::UpToDate;
    }
    let is_final = !record.pairs.iter().any(|(k, _)| k == provenance::DRAFT_KEY);
    match record.manifest {
        Some(m) if !policy.force && Some(m.as_str()) != ours => Found::Foreign(m),
        None if !policy.force => Found::Unrecorded(path.to_path_buf()),
        Some(_) if !policy.force && is_final && anim.manifest.draft.is_some() => Found::Final,
        _ => Found::Render,
    }
}

/// Refuses to overwrite frames recorded by another manifest than `anim`'s (`foreign`:
/// each frame and the manifest its file names).
pub(crate) fn refuse_foreign(dir: &Path, foreign: &[(u32, String)]) -> Result<(), AnimError> {
    match foreign.first() {
        None => Ok(()),
        Some((_, other)) => Err(AnimError::Foreign {
            dir: dir.to_path_buf(),
            other: other.clone(),
            frames: status::ranges(&foreign.iter().map(|(f, _)| *f).collect::<Vec<_>>()),
            count: foreign.len(),
        }),
    }
}
