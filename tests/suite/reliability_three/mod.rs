//! Reliability, round three: the faults an attack on the tool found, each run
//! through the built binaries, worst first. Each test fails on the code before its fix:
//! a step that spun forever, sizes checked after the memory was taken, files that were
//! not the tool's removed or overwritten, broken pipes, cross-site requests to `view`,
//! EXR offset tables, OpenJD names, and the smaller ones (`bounds`: points 1-2;
//! `ownership`: 3-4; `pipes`: 5; `view`: 6 and 9, `tev`: 9's viewer that never reads; `exr_openjd`: 7-8), then the property
//! test of the validators (`properties`).

use crate::support;

use std::time::Duration;
use support::*;

mod bounds;
mod exr_openjd;
mod ownership;
mod pipes;
mod properties;
mod tev;
mod view;

/// Long enough for a loaded two-core machine to render twelve 64×48 frames; the fault
/// it guards against never ends at all.
pub(crate) const PROMPT: Duration = Duration::from_secs(60);

pub(crate) fn text(b: &[u8]) -> String {
    String::from_utf8_lossy(b).into_owned()
}

/// `animate ARGS` run to its end within `PROMPT`: (status, stdout, stderr).
pub(crate) fn run(args: &[&dyn AsRef<std::ffi::OsStr>]) -> (Option<i32>, String, String) {
    let mut cmd = std::process::Command::new(assert_cmd::cargo::cargo_bin("animate"));
    for a in args {
        cmd.arg(a);
    }
    let out = output_within(&mut cmd, PROMPT);
    (out.status.code(), text(&out.stdout), text(&out.stderr))
}
