//! `animate status` (SPEC §8): which frames of a folder are up to date, stale or missing,
//! read from the frames' recorded provenance (`provenance::inspect`). A frame is up to
//! date when its file is a regular file, whole (PNG: every chunk's CRC; RAW: the SHA-256
//! of its bytes is the one its record names; JPEG, PPM: the end marker, the size), and
//! records the digest the manifest now gives it; with `verify` its image must also
//! decode. Anything else is stale. Files of frames past the end of the sequence (after
//! `frames` was lowered) are listed apart (`folder::beyond`).

use super::folder::beyond;
use super::provenance::{inspect, stamp, Inspection, Record, DRAFT_KEY};
use crate::project::{Animation, FramePlan};
use rayon::prelude::*;
use serde::Serialize;
use std::path::Path;

/// The state of one frame file.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize)]
#[serde(rename_all = "kebab-case")]
pub enum FrameState {
    /// The file is whole and records the digest the manifest now gives the frame.
    UpToDate,
    /// The file exists but is damaged, cut short, not a regular file, or its record is
    /// absent, foreign or different.
    Stale,
    /// No file of that name in the folder.
    Missing,
}

/// The state of frame `frame` in `dir` and, when stale, why.
fn examine(anim: &Animation, dir: &Path, frame: u32, verify: bool) -> (FrameState, String) {
    let plan = anim.plan_in(dir, frame);
    match inspect(plan.path(), anim.format(), anim.width, anim.height, verify) {
        Inspection::Missing => (FrameState::Missing, String::new()),
        Inspection::Sound(r) if r.digest.as_deref() == Some(plan.digest()) => {
            (FrameState::UpToDate, String::new())
        }
        Inspection::Sound(r) => (FrameState::Stale, changed(&plan, &r)),
        Inspection::Damaged(why) => (FrameState::Stale, format!("damaged: {why}")),
    }
}

/// What a sound frame's record says changed since it was rendered: the first stamp
/// entry that differs from the one the frame would carry now, or, when the stamp is the
/// same, what the digest alone covers.
fn changed(plan: &FramePlan, record: &Record) -> String {
    if record.digest.is_none() {
        return "it records no provenance".into();
    }
    let anim = plan.anim();
    let recorded = |key: &str| record.pairs.iter().find(|(k, _)| k == key).map(|p| &p.1);
    let now = stamp(plan);
    match (recorded(DRAFT_KEY), &anim.manifest.draft) {
        (Some(old), None) => return format!("it is a draft ({old}), now the final"),
        (None, Some(new)) => return format!("it is a final, now a draft ({new})"),
        (Some(old), Some(new)) if old != new => {
            return format!("it is a draft ({old}), now a draft ({new})")
        }
        _ => {}
    }
    for (key, value) in now.iter().skip(1) {
        let what = match key.as_str() {
            "whitted:manifest" => "the manifest was",
            "Software" => "the renderer was",
            "whitted:scene" => "the scene file was",
            "whitted:render" => "the render settings were",
            "whitted:camera" => "the camera was at",
            "whitted:frame" => "the frame was",
            _ => continue,
        };
        match recorded(key) {
            Some(old) if old != value => return format!("{what} {old}, now {value}"),
            _ => {}
        }
    }
    "the scene's values changed (the scene file or a track), or the framing (fov, roll) \
     or the pixel version"
        .into()
}

/// The frames of a folder by state, with their ranges.
#[derive(Clone, Debug, Default, PartialEq, Eq, Serialize)]
pub struct StatusReport {
    /// Frames whose files are up to date, ascending.
    pub up_to_date: Vec<u32>,
    /// Frames whose files are stale (to render again), ascending.
    pub stale: Vec<u32>,
    /// Frames with no file, ascending.
    pub missing: Vec<u32>,
    /// Frames past the end of the sequence that have a file in the folder, ascending.
    pub beyond: Vec<u32>,
    /// Why the stale frames are stale: each reason with its frames, in frame order.
    pub stale_why: Vec<(String, Vec<u32>)>,
}

impl StatusReport {
    /// Whether every frame is up to date.
    /// Whether every frame is up to date and no file of a frame past the end is left.
    pub fn complete(&self) -> bool {
        self.stale.is_empty() && self.missing.is_empty() && self.beyond.is_empty()
    }

    fn rows(&self) -> [(&'static str, &Vec<u32>); 3] {
        [
            ("up to date", &self.up_to_date),
            ("stale", &self.stale),
            ("missing", &self.missing),
        ]
    }

    /// The report for people: the folder, then a row per state with count and ranges.
    pub fn table(&self, dir: &Path) -> String {
        let total = self.up_to_date.len() + self.stale.len() + self.missing.len();
        let mut out = format!("{}: {total} frame(s)\n", whitted::fileloc::shown(dir));
        for (what, list) in self.rows() {
            out += &format!("{what:>11}: {:>7}  {}\n", list.len(), ranges(list));
            if what == "stale" {
                for (why, frames) in &self.stale_why {
                    out += &format!("{:>22}{}: {why}\n", "", ranges(frames));
                }
            }
        }
        if !self.beyond.is_empty() {
            let list = &self.beyond;
            out += &format!(
                "{:>11}: {:>7}  {}  (frames past the end of the sequence; `animate clean` removes them)\n",
                "past end",
                list.len(),
                ranges(list)
            );
        }
        out
    }

    /// The report for scripts: counts and ranges of each state.
    pub fn json(&self, dir: &Path) -> serde_json::Value {
        let mut doc = serde_json::json!({
            "folder": dir,
            "frames": self.up_to_date.len() + self.stale.len() + self.missing.len(),
            "complete": self.complete(),
        });
        for (what, list) in self.rows() {
            let key = what.replace(' ', "_");
            doc[&key] = ranges(list).into();
            doc[format!("{key}_count")] = list.len().into();
        }
        let why: Vec<serde_json::Value> = self
            .stale_why
            .iter()
            .map(|(why, frames)| serde_json::json!({ "frames": ranges(frames), "why": why }))
            .collect();
        doc["stale_why"] = why.into();
        doc["past_end"] = ranges(&self.beyond).into();
        doc["past_end_count"] = self.beyond.len().into();
        doc
    }
}

/// The state of each frame of `frames` in `dir`, in their order, read in parallel;
/// `verify` decodes every image too.
pub fn states(anim: &Animation, dir: &Path, frames: &[u32], verify: bool) -> Vec<FrameState> {
    examined(anim, dir, frames, verify)
        .into_iter()
        .map(|(state, _)| state)
        .collect()
}

/// `examine` of each frame of `frames`, in their order, in parallel.
fn examined(
    anim: &Animation,
    dir: &Path,
    frames: &[u32],
    verify: bool,
) -> Vec<(FrameState, String)> {
    frames
        .par_iter()
        .map(|&f| examine(anim, dir, f, verify))
        .collect()
}

/// The state of every frame of `frames` in `dir`, read in parallel, and the frames past
/// the end of the sequence that have files there; `verify` decodes every image too.
pub fn status(anim: &Animation, dir: &Path, frames: &[u32], verify: bool) -> StatusReport {
    let states = examined(anim, dir, frames, verify);
    let mut report = StatusReport {
        beyond: beyond(anim, dir).into_iter().map(|(f, _)| f).collect(),
        ..StatusReport::default()
    };
    for (&f, (state, why)) in frames.iter().zip(states) {
        match state {
            FrameState::UpToDate => report.up_to_date.push(f),
            FrameState::Stale => {
                report.stale.push(f);
                match report.stale_why.iter_mut().find(|(w, _)| *w == why) {
                    Some((_, list)) => list.push(f),
                    None => report.stale_why.push((why, vec![f])),
                }
            }
            FrameState::Missing => report.missing.push(f),
        }
    }
    report
}

/// Frames as inclusive ranges, render-farm style: `0-9,12,20-24` (`-` for none).
pub fn ranges(frames: &[u32]) -> String {
    if frames.is_empty() {
        return "-".into();
    }
    let mut parts = Vec::new();
    let mut start = frames[0];
    let mut prev = frames[0];
    for &f in &frames[1..] {
        if f != prev + 1 {
            parts.push(range(start, prev));
            start = f;
        }
        prev = f;
    }
    parts.push(range(start, prev));
    parts.join(",")
}

fn range(a: u32, b: u32) -> String {
    if a == b {
        a.to_string()
    } else {
        format!("{a}-{b}")
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_table_and_the_json() {
        let r = StatusReport {
            up_to_date: vec![0, 1, 2],
            stale: vec![5],
            missing: vec![3, 4],
            beyond: vec![],
            stale_why: vec![("damaged: cut short".into(), vec![5])],
        };
        let table = r.table(Path::new("f"));
        assert!(table.starts_with("f: 6 frame(s)\n"), "{table}");
        assert!(table.contains(" up to date:       3  0-2\n"), "{table}");
        assert!(table.contains("    missing:       2  3-4\n"), "{table}");
        let why = "      stale:       1  5\n                      5: damaged: cut short\n";
        assert!(table.contains(why), "{table}");
        let doc = r.json(Path::new("f"));
        assert_eq!(
            (doc["stale"].as_str(), doc["missing_count"].as_u64()),
            (Some("5"), Some(2))
        );
        assert_eq!(doc["complete"], false);
        let past = StatusReport {
            up_to_date: vec![0],
            beyond: vec![1, 2],
            ..StatusReport::default()
        };
        assert!(!past.complete());
        assert!(past
            .table(Path::new("f"))
            .contains("   past end:       2  1-2  ("));
        assert_eq!(past.json(Path::new("f"))["past_end"], "1-2");
    }

    #[test]
    fn ranges_like_a_render_farm() {
        assert_eq!(ranges(&[]), "-");
        assert_eq!(ranges(&[3]), "3");
        assert_eq!(ranges(&[0, 1, 2, 5, 7, 8]), "0-2,5,7-8");
        assert_eq!(ranges(&[9, 10]), "9-10");
    }
}
