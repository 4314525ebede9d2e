//! Tests that need an outside tool (ffmpeg, Chromium, Slurm, llvm-profdata, …): when the
//! tool is missing, `skip` fails the test under CI (`CI` set) and otherwise prints
//! `SKIPPED <test>: <why>` on the process's real standard error and lets the test pass.
//! The harness captures `eprintln!` (it only shows with `--nocapture`), but not a direct
//! write to the standard error stream, so the line shows in the normal output of
//! `cargo test`, beside the `ok` of the test it skipped. `have`, `which` and the finders
//! of the usual tools below skip that way when what they look for is missing.

// Each test crate uses its own subset of these helpers.
#![allow(dead_code)]

use std::io::Write;

/// Says that the running test skipped because of `why` (or fails it under CI). The test
/// is named by its thread, which the harness names after it.
pub fn skip(why: &str) {
    // The harness names the thread `module::test` (the module is the subject's file).
    let test = std::thread::current()
        .name()
        .unwrap_or("a test")
        .to_string();
    assert!(
        std::env::var_os("CI").is_none(),
        "CI must run {test}, but: {why}"
    );
    let line = format!("SKIPPED {test}: {why} (set CI=1 to make this a failure)\n");
    let _ = std::io::stderr().lock().write_all(line.as_bytes());
}

/// Whether `program args` runs; when not, the test skips (or fails under CI). With no
/// arguments only "it starts" is asked (`exrheader` alone prints its usage and exits 1);
/// with arguments it must also exit 0 (`python3 -c 'import mmh3'`, `ffmpeg -version`).
pub fn have(program: &str, args: &[&str]) -> bool {
    let ok = std::process::Command::new(program)
        .args(args)
        .stdin(std::process::Stdio::null())
        .output()
        .is_ok_and(|o| args.is_empty() || o.status.success());
    if !ok {
        skip(&format!("{program} {} is not available", args.join(" ")));
    }
    ok
}

/// `name` from PATH, else the first of `fallbacks` that is a file; when none is, the test
/// skips (or fails under CI) and this is `None`.
pub fn which(name: &str, fallbacks: &[&str]) -> Option<std::path::PathBuf> {
    let on_path = std::env::var_os("PATH").and_then(|paths| {
        std::env::split_paths(&paths)
            .map(|dir| dir.join(name))
            .find(|p| p.is_file())
    });
    let found = on_path.or_else(|| {
        fallbacks
            .iter()
            .map(std::path::PathBuf::from)
            .find(|p| p.is_file())
    });
    if found.is_none() {
        skip(&format!("{name} not found on PATH nor at {fallbacks:?}"));
    }
    found
}

/// Debian's `chromium` (PATH, else /usr/bin), or `None` after the test skipped.
pub fn chromium() -> Option<std::path::PathBuf> {
    which("chromium", &["/usr/bin/chromium"])
}

/// Whether both `ffmpeg` and `ffprobe` run; when not, the test skipped.
pub fn ffmpeg() -> bool {
    have("ffprobe", &["-version"]) && have("ffmpeg", &["-version"])
}
