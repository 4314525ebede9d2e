//! Many runs, one folder, through the built `animate`: two runs of one manifest started
//! into one folder share the frames (each frame rendered once, by the run that claims it),
//! the second says whose folder it shares, and a killed run's frames are taken over.

use crate::support;

use std::time::Duration;
use support::*;

/// Frames slow enough that two runs overlap.
const SLOW: &str = "\n[render]\nwidth = 320\nheight = 240\nsamples = 3\n";

/// `(rendered, by another run)` from a run's summary line.
fn counts(err: &str) -> (usize, usize) {
    let line = err
        .lines()
        .find(|l| l.contains(" rendered, "))
        .unwrap_or_else(|| panic!("no summary in {err}"));
    let words: Vec<&str> = line.split_whitespace().collect();
    let rendered = words[1].parse().unwrap();
    let elsewhere = line.find(" by another run").map_or(0, |end| {
        let count = line[..end].rsplit(' ').next().unwrap();
        count.parse().unwrap()
    });
    (rendered, elsewhere)
}

/// Waits until the run has claimed a frame in `frames` (its claims folder holds one).
fn until_claimed(frames: &std::path::Path) {
    let claims = frames.join(whitted_anim::frames::claim::CLAIMS);
    let seen = poll_until(Duration::from_secs(60), || {
        std::fs::read_dir(&claims).is_ok_and(|mut d| d.next().is_some())
    });
    assert!(seen.is_some(), "the first run never claimed a frame");
}

#[test]
fn two_runs_into_one_folder_render_each_frame_once() {
    let (dir, manifest) = project(&circle_manifest(SLOW));
    let frames = dir.path().join("frames");
    let mut first = spawn_animate(&manifest, &["--threads", "1"]);
    until_claimed(&frames);
    let mut second = spawn_animate(&manifest, &["--threads", "1"]);
    let (a, _) = wait_within(&mut first, Duration::from_secs(300));
    let (b, _) = wait_within(&mut second, Duration::from_secs(300));
    let (ea, eb) = (stderr_of(&mut first), stderr_of(&mut second));
    assert_eq!((a, b), (Some(0), Some(0)), "{ea}\n{eb}");
    let said = format!("sharing the folder with pid {}", first.id());
    assert!(eb.contains(&said), "{eb}");
    let ((ra, xa), (rb, xb)) = (counts(&ea), counts(&eb));
    assert_eq!(ra + rb, 12, "{ea}\n{eb}");
    assert_eq!((ra + xa, rb + xb), (12, 12), "{ea}\n{eb}");
    assert!(ra > 0 && rb > 0, "the runs did not overlap: {ea}\n{eb}");
    // Every frame is there, whole, and what the manifest gives.
    assert_eq!(files(&frames).len(), 12);
    animate().arg("status").arg(&manifest).assert().code(0);
}

#[test]
fn a_killed_runs_frames_are_taken_over() {
    let (dir, manifest) = project(&circle_manifest(SLOW));
    let frames = dir.path().join("frames");
    let mut first = spawn_animate(&manifest, &["--threads", "1"]);
    until_claimed(&frames);
    let mut second = spawn_animate(&manifest, &["--threads", "1"]);
    std::thread::sleep(Duration::from_millis(300));
    signal(&first, "KILL");
    let _ = first.wait();
    let (b, _) = wait_within(&mut second, Duration::from_secs(300));
    let eb = stderr_of(&mut second);
    assert_eq!(b, Some(0), "{eb}");
    assert_eq!(files(&frames).len(), 12, "{eb}");
    animate().arg("status").arg(&manifest).assert().code(0);
    // A later run alone shares with nobody.
    let out = animate().arg(&manifest).arg("--resume").output().unwrap();
    assert!(!String::from_utf8_lossy(&out.stderr).contains("sharing"));
}

#[test]
fn clean_removes_the_claim_files_no_run_holds() {
    let (dir, manifest) = project(&circle_manifest(""));
    animate().arg(&manifest).arg("-q").assert().success();
    let claims = dir
        .path()
        .join("frames")
        .join(whitted_anim::frames::claim::CLAIMS);
    let left = || {
        let mut names: Vec<String> = std::fs::read_dir(&claims)
            .map(|d| d.flatten().map(|e| e.file_name().into_string().unwrap()))
            .into_iter()
            .flatten()
            .collect();
        names.sort();
        names
    };
    assert_eq!(left().len(), 12);
    // Another pattern's claim is not this manifest's; one claim is held (by this test).
    std::fs::write(claims.join("other_0001.png.claim"), "").unwrap();
    let held = std::fs::File::options()
        .write(true)
        .open(claims.join("frame_0003.png.claim"))
        .unwrap();
    held.lock().unwrap();
    let out = animate()
        .args(["clean", "--dry-run"])
        .arg(&manifest)
        .output()
        .unwrap();
    let text = String::from_utf8_lossy(&out.stdout);
    assert!(
        text.contains("and 12 claim file(s) (those no run holds)"),
        "{text}"
    );
    assert_eq!(left().len(), 13);
    let out = animate().arg("clean").arg(&manifest).output().unwrap();
    let text = String::from_utf8_lossy(&out.stdout);
    assert!(out.status.success(), "{text}");
    assert!(
        text.contains("0 temporary file(s) and 11 claim file(s)"),
        "{text}"
    );
    assert_eq!(left(), ["frame_0003.png.claim", "other_0001.png.claim"]);
    drop(held);
    let out = animate().arg("clean").arg(&manifest).output().unwrap();
    let text = String::from_utf8_lossy(&out.stdout);
    assert!(text.contains("and 1 claim file(s)"), "{text}");
    assert_eq!(left(), ["other_0001.png.claim"]);
    // The frames are untouched, and a run claims again as before.
    animate().arg("status").arg(&manifest).assert().code(0);
    animate().arg(&manifest).arg("-q").assert().success();
}
