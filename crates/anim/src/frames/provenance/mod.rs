//! What produced a frame (SPEC §8): a digest of everything that decides its pixels, and
//! readable facts in the style of Blender's stamp, carried by the frame file itself —
//! PNG `tEXt` chunks, a JPEG comment, PPM header comments — or, for RAW (no header), by a
//! small file per frame in the folder's hidden `.whitted-record/`, which also holds the
//! SHA-256 of the pixels it describes (`inspect` checks a frame against its record).
//!
//! The digest is SHA-256 over the pixel version, the settings and, for each time the
//! frame samples, the scene's values after tracks and the camera, every number by its
//! exact bits (`project::digest`); a frame's plan (`FramePlan`) makes it once. Frames
//! carry no render time, so that the same inputs give the same bytes on every run.

use crate::project::FramePlan;
use glam::DVec3;
use std::path::{Path, PathBuf};

/// The keyword of the digest in every format.
pub(crate) const DIGEST_KEY: &str = "whitted:digest";
/// The keyword of a draft's label (only drafts carry it).
pub const DRAFT_KEY: &str = "whitted:draft";
/// The hidden folder holding RAW frames' records.
pub(crate) const RAW_RECORDS: &str = ".whitted-record";

pub(crate) use crate::project::hex;

/// The metadata the plan's frame carries: the digest first, then the stamp.
pub(crate) fn stamp(plan: &FramePlan) -> Vec<(String, String)> {
    let (anim, frame, state) = (plan.anim(), plan.frame(), plan.own());
    let p = |v: DVec3| format!("({}, {}, {})", v.x, v.y, v.z);
    let s = anim.settings();
    let blur = match s.motion_blur {
        Some(b) => format!(", motion blur {} frame(s) x {}", b.shutter, b.samples),
        None => String::new(),
    };
    let mut pairs = vec![
        (DIGEST_KEY.into(), plan.digest().to_string()),
        (
            "Software".into(),
            format!("whitted {}", env!("CARGO_PKG_VERSION")),
        ),
        (
            "whitted:frame".into(),
            format!("{frame} of {}", anim.manifest.frames),
        ),
        ("whitted:manifest".into(), file_name(&anim.manifest.path)),
        ("whitted:scene".into(), file_name(&anim.manifest.scene)),
        (
            "whitted:camera".into(),
            format!("eye {} look-at {}", p(state.eye), p(state.look_at)),
        ),
        (
            "whitted:render".into(),
            match s.antialias {
                Some(a) => format!(
                    "{}x{}, adaptive anti-aliasing threshold {} depth {} measure {}{blur}",
                    s.width,
                    s.height,
                    a.threshold,
                    a.depth,
                    a.measure.name()
                ),
                None => format!(
                    "{}x{}, {}x{} sample(s) per pixel{blur}",
                    s.width, s.height, s.samples, s.samples
                ),
            },
        ),
    ];
    if let Some(draft) = &anim.manifest.draft {
        pairs.push((DRAFT_KEY.into(), draft.clone()));
    }
    pairs
}

/// A path's file name: the stamp names files, not the folders they were reached through,
/// so that a frame's bytes do not depend on how the manifest's path was spelled.
fn file_name(path: &Path) -> String {
    path.file_name().map_or_else(
        || path.display().to_string(),
        |n| n.to_string_lossy().into_owned(),
    )
}

/// Where a RAW frame's record lives.
pub(crate) fn raw_record_path(frame_path: &Path) -> PathBuf {
    let dir = frame_path.parent().unwrap_or(Path::new(""));
    let name = frame_path.file_name().unwrap_or_default().to_string_lossy();
    dir.join(RAW_RECORDS).join(format!("{name}.txt"))
}

mod inspect;
pub(crate) use inspect::{decode, inspect, pixels_line, Inspection, Record, MANIFEST_KEY};

#[cfg(test)]
mod tests;
