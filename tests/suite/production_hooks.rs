//! Hooks through the built `animate`: `--on-frame CMD` after each frame (in the run's
//! order of frames, with ANIMATE_FRAME, ANIMATE_PATH, ANIMATE_STATE), `--on-done CMD`
//! after the run (ANIMATE_RENDERED, ANIMATE_FAILED, ANIMATE_EXIT); words split as a shell
//! would, never run by one; a failing hook is reported with its output, the render goes
//! on, and the run ends with status 1.

use crate::support;

use support::*;

/// A hook that appends its frame's variables to `log`.
fn frame_logger(log: &std::path::Path) -> String {
    format!(
        "sh -c 'echo $ANIMATE_FRAME $ANIMATE_STATE $(basename $ANIMATE_PATH) >> \"$0\"' {}",
        log.display()
    )
}

/// A hook that appends the run's variables to `log`.
fn done_logger(log: &std::path::Path) -> String {
    format!(
        "sh -c 'echo $ANIMATE_RENDERED $ANIMATE_FAILED $ANIMATE_EXIT >> \"$0\"' {}",
        log.display()
    )
}

fn read(path: &std::path::Path) -> String {
    std::fs::read_to_string(path).unwrap_or_default()
}

#[test]
fn frame_hooks_run_in_the_runs_order_and_see_up_to_date_frames() {
    let (dir, manifest) = project(&circle_manifest(""));
    let (log, done) = (dir.path().join("frames.log"), dir.path().join("done.log"));
    let out = animate()
        .arg(&manifest)
        .args(["-q", "--threads", "2", "--frames", "9,3,6,0,1"])
        .args(["--on-frame", &frame_logger(&log)])
        .args(["--on-done", &done_logger(&done)])
        .output()
        .unwrap();
    stdout_ok(out);
    let said = "9 rendered frame_0009.png\n3 rendered frame_0003.png\n6 rendered frame_0006.png\n\
                0 rendered frame_0000.png\n1 rendered frame_0001.png\n";
    assert_eq!(read(&log), said);
    assert_eq!(read(&done), "5 0 0\n");
    // Again with --resume: the five are up to date, the others rendered, in frame order.
    std::fs::remove_file(&log).unwrap();
    animate()
        .arg(&manifest)
        .args(["-q", "--threads", "2", "--resume", "--frames", "0-5"])
        .args(["--on-frame", &frame_logger(&log)])
        .args(["--on-done", &done_logger(&done)])
        .assert()
        .success();
    let states: Vec<String> = read(&log)
        .lines()
        .map(|l| l[..l.rfind(' ').unwrap()].into())
        .collect();
    let expected = [
        "0 up-to-date",
        "1 up-to-date",
        "2 rendered",
        "3 up-to-date",
        "4 rendered",
        "5 rendered",
    ];
    assert_eq!(states, expected);
    assert_eq!(read(&done), "5 0 0\n3 0 0\n");
}

#[test]
fn a_failing_hook_is_reported_and_the_render_goes_on_to_status_1() {
    let (dir, manifest) = project(&circle_manifest(""));
    let done = dir.path().join("done.log");
    let hook = "sh -c 'if [ $ANIMATE_FRAME = 5 ]; then echo oops; echo \"on err\" >&2; exit 7; fi'";
    let out = animate()
        .arg(&manifest)
        .args(["-q", "--on-frame", hook, "--on-done", &done_logger(&done)])
        .output()
        .unwrap();
    let err = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(1), "{err}");
    let said = "animate: --on-frame hook for frame 5 failed (exit status 7), printing:\n    oops\n    on err\n";
    assert!(err.contains(said), "{err}");
    assert_eq!(files(&dir.path().join("frames")).len(), 12);
    // The run's hook is told the status the run ends with.
    assert_eq!(read(&done), "12 0 1\n");
    // A failing --on-done alone also makes the status 1; words are not a shell's.
    let out = animate()
        .arg(&manifest)
        .args([
            "-q",
            "--resume",
            "--on-done",
            "sh -c 'echo $0 \"$1\"; exit 3' $HOME 'a;b'",
        ])
        .output()
        .unwrap();
    let err = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(1), "{err}");
    assert!(
        err.contains("animate: --on-done hook failed (exit status 3), printing:\n    $HOME a;b"),
        "{err}"
    );
}

#[test]
fn a_failed_frame_is_hooked_as_failed_and_the_run_hook_counts_it() {
    let (dir, manifest) = project(&circle_manifest(""));
    let frames = dir.path().join("frames");
    // A folder under frame 2's name: its file cannot be written.
    std::fs::create_dir_all(frames.join("frame_0002.png")).unwrap();
    let (log, done) = (dir.path().join("frames.log"), dir.path().join("done.log"));
    let out = animate()
        .arg(&manifest)
        .args(["-q", "--threads", "1", "--frames", "0-3"])
        .args([
            "--on-frame",
            &frame_logger(&log),
            "--on-done",
            &done_logger(&done),
        ])
        .output()
        .unwrap();
    assert_eq!(
        out.status.code(),
        Some(1),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let said = "0 rendered frame_0000.png\n1 rendered frame_0001.png\n2 failed frame_0002.png\n";
    assert_eq!(read(&log), said);
    assert_eq!(read(&done), "2 1 1\n");
}

#[test]
fn bad_hooks_are_refused_before_anything_renders() {
    let (dir, manifest) = project(&circle_manifest(""));
    let out = animate()
        .arg(&manifest)
        .args(["--on-done", "echo 'open"])
        .output()
        .unwrap();
    assert_eq!(out.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&out.stderr).contains("a quote that does not close"));
    let out = animate()
        .arg(&manifest)
        .args(["--stdout", "ppm", "--on-frame", "true"])
        .output()
        .unwrap();
    assert_eq!(out.status.code(), Some(2));
    assert!(!dir.path().join("frames").exists());
}
