//! Ctrl-C within a frame: `animate` stops the frames in progress between rows, says at
//! once how many it stops, keeps the finished frames, and a second signal ends it at once.

mod support;

use std::process::Child;
use std::time::Duration;
use support::*;

/// Frames that take many seconds each (two threads): 1080p at 4×4 samples.
const HEAVY: &str = "\n[render]\nwidth = 1920\nheight = 1080\nsamples = 4\n";

fn spawn(manifest: &std::path::Path) -> Child {
    spawn_animate(manifest, &["--threads", "2"])
}

#[test]
fn sigint_stops_a_heavy_frame_between_rows_and_says_so() {
    let (dir, manifest) = project(&circle_manifest(HEAVY));
    let mut child = spawn(&manifest);
    std::thread::sleep(Duration::from_millis(1500));
    signal(&child, "INT");
    // Before: the frames in progress (about 10 s each here) had to finish first.
    let (code, took) = wait_within(&mut child, Duration::from_secs(5));
    assert_eq!(code, Some(130));
    assert!(took < Duration::from_secs(2), "took {took:?}");
    let err = stderr_of(&mut child);
    let line = err.lines().find(|l| l.contains("stopping: ")).unwrap_or("");
    let n: usize = line
        .split("stopping: ")
        .nth(1)
        .and_then(|rest| rest.split(' ').next())
        .and_then(|n| n.parse().ok())
        .unwrap_or_else(|| panic!("no `stopping: N frames in progress` line in:\n{err}"));
    assert!(n >= 1 && line.contains("in progress"), "{line}");
    // The stopped frames are not written, under a final name or a temporary one.
    let frames = dir.path().join("frames");
    let left = leftovers(&frames); // the run's folder lock stays
    assert!(left.is_empty(), "{left:?}");
}

#[test]
fn a_second_signal_ends_the_process_at_once() {
    // Rows of 16384 pixels at 16×16 samples take about a second each: after the first
    // signal the rows in progress still finish; the second ends the process now.
    let wide = "\n[render]\nwidth = 16384\nheight = 64\nsamples = 16\n";
    let (_dir, manifest) = project(&circle_manifest(wide));
    let mut child = spawn(&manifest);
    // Long enough for the run to be drawing rows (the folder lock and checks come first).
    std::thread::sleep(Duration::from_millis(2000));
    signal(&child, "TERM");
    std::thread::sleep(Duration::from_millis(100));
    signal(&child, "INT");
    let (code, took) = wait_within(&mut child, Duration::from_secs(5));
    assert_eq!(code, Some(130), "the second signal's 128 + 2");
    assert!(took < Duration::from_millis(500), "took {took:?}");
    let err = stderr_of(&mut child);
    assert!(err.contains("stopping: "), "{err}");
}
