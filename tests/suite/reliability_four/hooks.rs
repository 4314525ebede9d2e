//! Point 5: a hook that never ended held the run, and one SIGTERM did not stop it (a
//! second left the hook running, orphaned); a hook that left a child in the background
//! held the run until the child ended (the run waited for the pipe); a hook's output was
//! kept whole in memory. Now hooks end with the run (their whole process group), the run
//! waits for the process, keeps a bounded tail, and `--hook-timeout` bounds a hook.

use super::{text, PROMPT};
use crate::support::*;
use std::path::Path;
use std::process::{Command, Stdio};
use std::time::Duration;

/// The pids a hook wrote into `file`, once it has written `n` of them.
fn pids(file: &Path, n: usize) -> Vec<u32> {
    let mut found = Vec::new();
    let seen = poll_until(PROMPT, || {
        let text = std::fs::read_to_string(file).unwrap_or_default();
        found = text.lines().filter_map(|l| l.trim().parse().ok()).collect();
        found.len() >= n
    });
    assert!(seen.is_some(), "the hook never wrote its pids");
    found
}

/// `animate ARGS` in the background, standard output dropped, standard error into `log`.
fn start(args: &[&dyn AsRef<std::ffi::OsStr>], log: &Path) -> std::process::Child {
    let mut cmd = Command::new(assert_cmd::cargo::cargo_bin("animate"));
    for a in args {
        cmd.arg(a);
    }
    let err = std::fs::File::create(log).unwrap();
    cmd.stdout(Stdio::null()).stderr(err).spawn().unwrap()
}

#[test]
fn one_sigterm_ends_a_run_whose_hook_never_ends_and_the_hooks_group() {
    let (dir, m) = project(&circle_manifest(""));
    let file = dir.path().join("pids");
    // The hook, and a child of its own in the background: neither ever ends by itself.
    let hook = format!(
        "sh -c 'sleep 1000 & echo $! >> {0}; echo $$ >> {0}; wait'",
        file.display()
    );
    let log = dir.path().join("err.log");
    for (option, hook) in [("--on-frame", &hook), ("--on-done", &hook)] {
        let _ = std::fs::remove_file(&file);
        let mut child = start(&[&m, &"-q", &"--frames", &"0-1", &option, hook], &log);
        let hooks = pids(&file, 2);
        signal(&child, "TERM");
        let (code, _) = wait_within(&mut child, Duration::from_secs(20));
        let err = std::fs::read_to_string(&log).unwrap();
        assert_eq!(code, Some(143), "{option}: {err}");
        assert!(
            err.contains("stopped with the run by signal 15: its process group was ended"),
            "{option}: {err}"
        );
        // Neither the hook nor its child outlives the run.
        let gone = poll_until(Duration::from_secs(5), || !hooks.iter().any(|&p| alive(p)));
        assert!(gone.is_some(), "{option}: {hooks:?} still running");
    }
}

#[test]
fn a_hook_that_leaves_a_child_in_the_background_does_not_hold_the_run() {
    let (dir, m) = project(&circle_manifest(""));
    let file = dir.path().join("pids");
    let hook = format!(
        "sh -c 'sleep 120 & echo $! >> {}; echo started'",
        file.display()
    );
    let log = dir.path().join("err.log");
    let mut child = start(
        &[&m, &"-q", &"--frames", &"0-2", &"--on-frame", &hook],
        &log,
    );
    let (code, took) = wait_within(&mut child, Duration::from_secs(100));
    let background = pids(&file, 3);
    for &p in &background {
        let _ = Command::new("kill").arg(p.to_string()).status();
    }
    let err = std::fs::read_to_string(&log).unwrap();
    assert_eq!(code, Some(0), "{err}");
    // Before: each hook held the run for its child's 120 s.
    assert!(took < Duration::from_secs(60), "{took:?}");
    assert_eq!(err.matches("started\n").count(), 3, "{err}");
}

#[test]
fn a_hook_printing_300_mb_costs_the_run_a_bounded_tail() {
    let (dir, m) = project(&circle_manifest(""));
    let hook =
        "sh -c 'yes 0123456789abcdefghijklmnopqrstuvwxyz | head -c 300000000; echo the last line'";
    let log = dir.path().join("err.log");
    let child = start(&[&m, &"-q", &"--frames", &"0", &"--on-done", &hook], &log);
    let (peak_kib, status) = peak_kib_until_exit(child);
    let err = std::fs::read_to_string(&log).unwrap();
    assert_eq!(status.code(), Some(0), "{}", &err[..err.len().min(300)]);
    // Before: the 300 MB kept whole, then copied into text (over 600 MB).
    println!(
        "peak memory with 300 MB of hook output: {} MiB (target < 200)",
        peak_kib / 1024
    );
    assert!(peak_kib < 200 * 1024, "{peak_kib} KiB");
    assert!(
        err.ends_with("the last line\n"),
        "{}",
        &err[err.len() - 200..]
    );
    assert!(err.contains(" bytes before these were not kept]"));
    assert!(err.len() < 100_000, "{} bytes shown", err.len());
}

#[test]
fn hook_timeout_ends_a_hook_and_its_group_and_fails_the_run() {
    let (dir, m) = project(&circle_manifest(""));
    let file = dir.path().join("pids");
    let hook = format!(
        "sh -c 'sleep 1000 & echo $! >> {0}; echo $$ >> {0}; echo waiting; wait'",
        file.display()
    );
    let mut cmd = Command::new(assert_cmd::cargo::cargo_bin("animate"));
    cmd.arg(&m).args([
        "-q",
        "--frames",
        "0-1",
        "--hook-timeout",
        "0.5",
        "--on-frame",
        &hook,
    ]);
    let out = output_within(&mut cmd, PROMPT);
    let err = text(&out.stderr);
    assert_eq!(out.status.code(), Some(1), "{err}");
    let said = "--on-frame hook for frame 0 failed (ran past --hook-timeout 0.5 s: its process \
                group was ended), printing:\n    waiting";
    assert!(err.contains(said), "{err}");
    assert!(err.contains("hook for frame 1 failed (ran past"), "{err}");
    let hooks = pids(&file, 4);
    let gone = poll_until(Duration::from_secs(5), || !hooks.iter().any(|&p| alive(p)));
    assert!(gone.is_some(), "{hooks:?} still running");
    // The frames are rendered all the same.
    assert!(dir.path().join("frames/frame_0001.png").is_file());
    let mut bad = Command::new(assert_cmd::cargo::cargo_bin("animate"));
    bad.arg(&m)
        .args(["--hook-timeout", "0", "--on-done", "true"]);
    let out = output_within(&mut bad, PROMPT);
    assert_eq!(out.status.code(), Some(2));
    assert!(
        text(&out.stderr).contains("more than 0"),
        "{}",
        text(&out.stderr)
    );
}
