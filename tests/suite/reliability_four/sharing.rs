//! Point 9: two runs of one 400-frame manifest started a second apart reported 249 and
//! 199 frames rendered, 448 for 400. The counts were right: the second run rendered again
//! the frames the first had written before it joined (it took only frames written since
//! its own start for the other run's). Runs sharing a folder now count from when the
//! sharing began (`shared since` in the folder's lock), so together they render each frame
//! once.

use super::PROMPT;
use crate::support::*;
use std::time::Duration;

/// The frames a run's summary says it rendered.
fn rendered(err: &str) -> usize {
    let line = err
        .lines()
        .find(|l| l.contains(" rendered, "))
        .unwrap_or_else(|| panic!("no summary in {err}"));
    let words: Vec<&str> = line.split_whitespace().collect();
    words[1].parse().unwrap_or_else(|_| panic!("{line}"))
}

#[test]
fn two_runs_started_apart_render_each_frame_once() {
    let slow = "\n[render]\nwidth = 160\nheight = 120\nsamples = 2\n";
    let (dir, m) = project(&circle_manifest(slow).replace("frames = 12", "frames = 200"));
    let frames = dir.path().join("frames");
    let mut first = spawn_animate(&m, &["--threads", "1"]);
    // The second starts once the first has written frames of its own.
    let written = || {
        std::fs::read_dir(&frames).map_or(0, |d| {
            d.flatten()
                .filter(|e| e.file_name().to_string_lossy().ends_with(".png"))
                .count()
        })
    };
    let some = poll_until(PROMPT, || written() >= 8);
    assert!(some.is_some(), "the first run wrote no frames");
    let mut second = spawn_animate(&m, &["--threads", "1"]);
    let limit = Duration::from_secs(300);
    let (a, _) = wait_within(&mut first, limit);
    let (b, _) = wait_within(&mut second, limit);
    let (err_a, err_b) = (stderr_of(&mut first), stderr_of(&mut second));
    assert_eq!((a, b), (Some(0), Some(0)), "{err_a}\n{err_b}");
    assert!(
        err_b.contains("sharing the folder with pid"),
        "the first run had ended before the second started: {err_b}"
    );
    let (ra, rb) = (rendered(&err_a), rendered(&err_b));
    println!("two runs of 200 frames: {ra} + {rb} rendered");
    assert_eq!(ra + rb, 200, "{err_a}\n{err_b}");
    assert!(err_b.contains(" by another run"), "{err_b}");
    let out = animate().arg("status").arg(&m).output().unwrap();
    assert_eq!(
        out.status.code(),
        Some(0),
        "{}",
        String::from_utf8_lossy(&out.stdout)
    );
}
