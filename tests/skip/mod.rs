//! Tests that need an outside tool (ffmpeg, Chromium, Slurm, llvm-profdata, …): when the
//! tool is missing, `skip` fails the test under CI (`CI` set) and otherwise prints
//! `SKIPPED <test>: <why>` on the process's real standard error and lets the test pass.
//! The harness captures `eprintln!` (it only shows with `--nocapture`), but not a direct
//! write to the standard error stream, so the line shows in the normal output of
//! `cargo test`, beside the `ok` of the test it skipped.

use std::io::Write;

/// Says that the running test skipped because of `why` (or fails it under CI). The test
/// is named by its thread, which the harness names after it.
pub fn skip(why: &str) {
    let name = std::thread::current()
        .name()
        .unwrap_or("a test")
        .to_string();
    let test = format!("{}::{name}", env!("CARGO_CRATE_NAME"));
    assert!(
        std::env::var_os("CI").is_none(),
        "CI must run {test}, but: {why}"
    );
    let line = format!("SKIPPED {test}: {why} (set CI=1 to make this a failure)\n");
    let _ = std::io::stderr().lock().write_all(line.as_bytes());
}
