//! Reliability, round four, the pipeline's points, each run through the built
//! `animate` and failing on the code before its fix: `clean` and runs that removed or
//! replaced files the tool did not write (`ownership`: point 1), a draft written over the
//! finals (`drafts`: point 6), hooks that held the run or its memory (`hooks`: point 5),
//! and the smaller ones of point 9 (`records`: a symlinked cost record, the draft folder of
//! `dir = "."`; `sharing`: two runs of one manifest; `estimate`: EXR passes).

use crate::support;

use std::time::Duration;
use support::*;

mod drafts;
mod estimate;
mod hooks;
mod ownership;
mod records;
mod sharing;

/// Long enough for a loaded two-core machine to render twelve 64×48 frames; the faults
/// guarded against never end at all.
pub(super) const PROMPT: Duration = Duration::from_secs(60);

pub(super) fn text(b: &[u8]) -> String {
    String::from_utf8_lossy(b).into_owned()
}

/// `animate ARGS` run to its end within `PROMPT`: (status, stdout, stderr).
pub(super) fn run(args: &[&dyn AsRef<std::ffi::OsStr>]) -> (Option<i32>, String, String) {
    let mut cmd = std::process::Command::new(assert_cmd::cargo::cargo_bin("animate"));
    for a in args {
        cmd.arg(a);
    }
    let out = output_within(&mut cmd, PROMPT);
    (out.status.code(), text(&out.stdout), text(&out.stderr))
}

/// Replaces `from` by `to` in the manifest at `path`.
pub(super) fn edit(path: &std::path::Path, from: &str, to: &str) {
    let before = std::fs::read_to_string(path).unwrap();
    assert!(before.contains(from), "{from:?} not in {before}");
    std::fs::write(path, before.replace(from, to)).unwrap();
}
