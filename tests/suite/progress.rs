//! Progress that moves: a warning with the predicted time before an enormous request
//! (both binaries), and `raytrace`'s bar stays off standard error when it is not a
//! terminal.

use crate::support;

use std::io::{BufRead, BufReader};
use std::process::{Command, Stdio};
use std::time::{Duration, Instant};
use support::*;

/// Runs `cmd` until a line of its standard error contains `want`, then stops it with
/// SIGINT; returns that line. The lines are read in a thread: if none has `want` within
/// 30 s (or the process ends first) the process is killed and the test fails with what it
/// printed, instead of waiting for a render that takes hours.
fn first_line_with(cmd: &mut Command, want: &str) -> String {
    let mut child = cmd
        .stderr(Stdio::piped())
        .stdout(Stdio::null())
        .spawn()
        .unwrap();
    let pipe = child.stderr.take().unwrap();
    let (send, lines) = std::sync::mpsc::channel();
    std::thread::spawn(move || {
        for line in BufReader::new(pipe).lines() {
            if send.send(line.unwrap()).is_err() {
                break;
            }
        }
    });
    let limit = Duration::from_secs(30);
    let start = Instant::now();
    let mut seen = String::new();
    let found = loop {
        let left = limit.saturating_sub(start.elapsed());
        match lines.recv_timeout(left) {
            Ok(line) if line.contains(want) => break Some(line),
            Ok(line) => {
                seen.push_str(&line);
                seen.push('\n');
            }
            Err(_) => break None, // the time ran out, or the process ended
        }
    };
    if found.is_some() {
        signal(&child, "INT");
    } else {
        let _ = child.kill();
    }
    let _ = child.wait();
    found.unwrap_or_else(|| {
        panic!(
            "no line with {want:?} within {limit:?} ({:?} waited) in:\n{seen}",
            start.elapsed()
        )
    })
}

#[test]
fn animate_warns_before_an_enormous_request_with_a_predicted_time() {
    // 10000 frames of 64×48 at 16×16 samples: 7 864 320 000 camera rays.
    let (_dir, manifest) = project(
        &circle_manifest("\n[render]\nsamples = 16\n").replace("frames = 12", "frames = 10000"),
    );
    let line = first_line_with(
        Command::new(assert_cmd::cargo::cargo_bin("animate")).arg(&manifest),
        "warning",
    );
    assert!(line.contains("7864320000 camera rays"), "{line}");
    assert!(line.contains("predicts about"), "{line}");
}

#[test]
fn raytrace_warns_before_an_enormous_image_and_keeps_a_pipe_clean() {
    let dir = tempfile::tempdir().unwrap();
    let scene = dir.path().join("s.txt");
    std::fs::write(&scene, scene_with_eye([0.0, 3.0, 8.0])).unwrap();
    // 8192×4096 at 4×4: 536 870 912 camera rays.
    let line = first_line_with(
        Command::new(assert_cmd::cargo::cargo_bin("raytrace"))
            .arg(&scene)
            .args(["--size", "8192x4096", "--samples", "4", "-o"])
            .arg(dir.path().join("big.png")),
        "warning",
    );
    assert!(line.contains("536870912 camera rays"), "{line}");
    assert!(line.contains("predicts about"), "{line}");
    // A small image casts no warning and draws no bar into a pipe: one summary line.
    let out = raytrace()
        .arg(&scene)
        .arg("-o")
        .arg(dir.path().join("small.png"))
        .output()
        .unwrap();
    let err = String::from_utf8_lossy(&out.stderr);
    assert_eq!(err.lines().count(), 1, "{err}");
    assert!(err.starts_with("raytrace: wrote"), "{err}");
}
