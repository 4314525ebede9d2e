//! Reliability, round four, the pipeline's points, each run through the built
//! `animate` and failing on the code before its fix: `clean` and runs that removed or
//! replaced files the tool did not write (`ownership`: point 1), a draft written over the
//! finals (`drafts`: point 6), hooks that held the run or its memory (`hooks`: point 5),
//! and the smaller ones of point 9 (`records`: a symlinked cost record, the draft folder of
//! `dir = "."`; `sharing`: two runs of one manifest; `estimate`: EXR passes).

mod drafts;
mod estimate;
mod hooks;
mod ownership;
mod records;
mod sharing;

// The same deadline and runner as round three's.
pub(super) use crate::reliability_three::{run, text, PROMPT};

/// Replaces `from` by `to` in the manifest at `path`.
pub(super) fn edit(path: &std::path::Path, from: &str, to: &str) {
    let before = std::fs::read_to_string(path).unwrap();
    assert!(before.contains(from), "{from:?} not in {before}");
    std::fs::write(path, before.replace(from, to)).unwrap();
}
