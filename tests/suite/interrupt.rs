//! Ctrl-C within a frame: `animate` stops the frames in progress between rows, says at
//! once how many it stops, keeps the finished frames, and a second signal ends it at once.

use crate::support;

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
    let (code, took) = wait_within(&mut child, Duration::from_secs(60));
    assert_eq!(code, Some(130));
    timed(
        "SIGINT to the exit",
        took,
        Duration::from_secs(2),
        Duration::from_secs(6),
    );
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

/// The test scene with six more lights: every hit casts eight shadow rays, so a row of
/// 16384 pixels at 16×16 samples takes seconds (about 2.4 times the plain scene's).
fn heavy_scene() -> String {
    let mut text = scene_with_eye([0.0, 3.0, 8.0]).replacen("\n3 1 1 2\n", "\n3 1 1 8\n", 1);
    for (x, z) in [(8, 0), (-8, 0), (0, 8), (0, -8), (6, 6), (-6, -6)] {
        text.push_str(&format!("{x} 9 {z}  0.5 0.5 0.5  0.4\n"));
    }
    text
}

#[test]
fn a_second_signal_ends_the_process_at_once() {
    // Rows of 16384 pixels at 16×16 samples of a heavy scene take seconds each: after the
    // first signal the rows in progress still finish; the second ends the process now.
    let wide = "\n[render]\nwidth = 16384\nheight = 64\nsamples = 16\n";
    let (dir, manifest) = project(&circle_manifest(wide));
    std::fs::write(dir.path().join("scene.txt"), heavy_scene()).unwrap();
    // An attempt whose rows all finished between the two signals (the process then ends
    // 143 by itself) tests nothing: it is said and tried again.
    for attempt in 1..=3 {
        let mut child = spawn(&manifest);
        // Drawing rows: more than a second of CPU spent (the folder lock and checks cost
        // next to nothing).
        let drawing = poll_until(Duration::from_secs(60), || {
            cpu_time(child.id()) > Duration::from_millis(1500)
        });
        assert!(drawing.is_some(), "the run never started drawing rows");
        signal(&child, "TERM");
        std::thread::sleep(Duration::from_millis(10));
        if let Some(status) = child.try_wait().unwrap() {
            eprintln!("attempt {attempt}: the rows finished within 10 ms of SIGTERM ({status})");
            continue;
        }
        signal(&child, "INT");
        let (code, took) = wait_within(&mut child, Duration::from_secs(60));
        assert_eq!(code, Some(130), "the second signal's 128 + 2");
        timed(
            "the second signal to the exit",
            took,
            Duration::from_millis(500),
            Duration::from_secs(2),
        );
        let err = stderr_of(&mut child);
        assert!(err.contains("stopping: "), "{err}");
        return;
    }
    panic!("in three attempts the rows in progress always finished between the signals");
}
