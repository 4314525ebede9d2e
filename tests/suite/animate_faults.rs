//! Faults a render farm meets: signals, output folders that are files or vanish, broken
//! pipes, full disks, and several processes writing one folder at once.

use crate::support;

use std::process::{Command, Stdio};
use std::time::{Duration, Instant};
use support::*;

/// Frames big enough that a run lasts a few seconds.
const SLOW: &str = "\n[render]\nwidth = 320\nheight = 240\nsamples = 3\n";

fn spawn(manifest: &std::path::Path, args: &[&str]) -> std::process::Child {
    spawn_animate(manifest, args)
}

/// Sends `sig` mid-run; checks the exit status, that no temporary file is left, that
/// finished frames are complete, and that `--resume` completes the same bytes.
fn interrupted_run_resumes(sig: &str, code: i32) {
    let (dir, manifest) = project(&circle_manifest(SLOW));
    let whole = dir.path().join("whole");
    render_into(&manifest, &whole, &[]);
    let mut child = spawn(&manifest, &[]);
    std::thread::sleep(Duration::from_millis(400));
    // `signal` first waits until animate catches it (a fixed sleep raced its start).
    signal(&child, sig);
    let sent = Instant::now();
    let status = child.wait().unwrap();
    let took = sent.elapsed();
    assert_eq!(status.code(), Some(code));
    assert!(took < Duration::from_secs(3), "took {took:?} to stop");
    let err = stderr_of(&mut child);
    assert!(
        err.contains("interrupted") && err.contains("--resume"),
        "{err}"
    );
    let frames = dir.path().join("frames");
    let temps: Vec<String> = entries(&frames)
        .into_iter()
        .filter(|n| n.ends_with(".tmp"))
        .collect();
    assert!(temps.is_empty(), "{temps:?}");
    let done = files(&frames);
    assert!(done.len() < 12, "the signal came too late to test anything");
    for (name, bytes) in &done {
        assert!(image::load_from_memory(bytes).is_ok(), "{name}");
    }
    animate().arg(&manifest).arg("--resume").assert().success();
    assert_eq!(files(&frames), files(&whole));
}

#[test]
fn sigint_stops_after_frames_in_flight_and_resume_completes() {
    interrupted_run_resumes("INT", 130);
}

#[test]
fn sigterm_stops_after_frames_in_flight_and_resume_completes() {
    interrupted_run_resumes("TERM", 143);
}

#[test]
fn output_folder_that_is_a_file() {
    let (dir, manifest) = project(&circle_manifest(""));
    let file = dir.path().join("taken");
    std::fs::write(&file, b"not a folder").unwrap();
    let out = animate()
        .arg(&manifest)
        .arg("-o")
        .arg(&file)
        .output()
        .unwrap();
    // An output location that cannot be used is bad input: nothing was rendered.
    assert_eq!(out.status.code(), Some(2));
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(
        err.contains("cannot use the output folder") && err.contains("taken"),
        "{err}"
    );
    assert_eq!(std::fs::read(&file).unwrap(), b"not a folder");
}

#[test]
fn unwritable_output_folder() {
    // Root ignores permission bits, so use a folder no one can create files in.
    let (_dir, manifest) = project(&circle_manifest(""));
    let out = animate()
        .arg(&manifest)
        .args(["-o", "/proc/animate-frames"])
        .output()
        .unwrap();
    assert_eq!(out.status.code(), Some(2));
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(err.contains("/proc/animate-frames"), "{err}");
}

#[test]
fn output_folder_vanishing_mid_run() {
    let (dir, manifest) = project(&circle_manifest(SLOW));
    let frames = dir.path().join("frames");
    let child = spawn(&manifest, &[]);
    // Wait for the first frame, then pull the folder away.
    let start = Instant::now();
    while files_or_none(&frames) == 0 && start.elapsed() < Duration::from_secs(20) {
        std::thread::sleep(Duration::from_millis(20));
    }
    std::fs::remove_dir_all(&frames).unwrap();
    let out = child.wait_with_output().unwrap();
    assert_eq!(out.status.code(), Some(1));
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(err.contains("frame "), "{err}");
}

fn files_or_none(dir: &std::path::Path) -> usize {
    std::fs::read_dir(dir)
        .map(|d| d.count())
        .unwrap_or(0)
        .saturating_sub(1)
}

#[test]
fn broken_pipe_on_stdout() {
    let (_dir, manifest) = project(&circle_manifest(""));
    let mut child = Command::new(assert_cmd::cargo::cargo_bin("animate"))
        .arg(&manifest)
        .args(["--stdout", "raw"])
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .unwrap();
    // Read one frame's worth, then close the pipe, as an ffmpeg that exits early.
    let mut stdout = child.stdout.take().unwrap();
    let mut first = vec![0u8; 64 * 48 * 3];
    std::io::Read::read_exact(&mut stdout, &mut first).unwrap();
    drop(stdout);
    let out = child.wait_with_output().unwrap();
    assert_eq!(out.status.code(), Some(1));
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(err.contains("output stream"), "{err}");
}

#[test]
fn full_disk_on_stdout() {
    let (_dir, manifest) = project(&circle_manifest(""));
    let full = std::fs::OpenOptions::new()
        .write(true)
        .open("/dev/full")
        .unwrap();
    let out = Command::new(assert_cmd::cargo::cargo_bin("animate"))
        .arg(&manifest)
        .args(["--stdout", "raw"])
        .stdout(full)
        .output()
        .unwrap();
    assert_eq!(out.status.code(), Some(1));
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(err.contains("No space left"), "{err}");
}

#[test]
fn four_shards_at_once_into_one_folder() {
    let (dir, manifest) = project(&circle_manifest(""));
    render_into(&manifest, &dir.path().join("single"), &[]);
    let shards: Vec<_> = (0..4)
        .map(|k| spawn(&manifest, &["--shard", &format!("{k}/4")]))
        .collect();
    // Every shard waited for before any assertion; a failing one says why.
    let failed: Vec<String> = (shards.into_iter().enumerate())
        .map(|(k, child)| (k, child.wait_with_output().unwrap()))
        .filter(|(_, out)| !out.status.success())
        .map(|(k, out)| {
            let err = String::from_utf8_lossy(&out.stderr);
            format!("shard {k}/4: {}\n{err}", out.status)
        })
        .collect();
    assert!(failed.is_empty(), "{}", failed.join("\n"));
    assert_eq!(
        files(&dir.path().join("frames")),
        files(&dir.path().join("single"))
    );
}

#[test]
fn two_resume_runs_racing_on_the_same_frames() {
    let (dir, manifest) = project(&circle_manifest(""));
    render_into(&manifest, &dir.path().join("single"), &[]);
    let racers: Vec<_> = (0..2).map(|_| spawn(&manifest, &["--resume"])).collect();
    for child in racers {
        assert!(child.wait_with_output().unwrap().status.success());
    }
    let frames = dir.path().join("frames");
    assert_eq!(files(&frames), files(&dir.path().join("single")));
    let temps: Vec<String> = entries(&frames)
        .into_iter()
        .filter(|n| n.ends_with(".tmp"))
        .collect();
    assert!(temps.is_empty(), "{temps:?}");
}

#[test]
fn memory_stays_flat_over_ten_thousand_frames() {
    // 10,000 small frames into a folder; the peak must not grow with the frame count.
    let manifest = circle_manifest("\n[render]\nwidth = 16\nheight = 12\n")
        .replace("frames = 12", "frames = 10000");
    let (dir, manifest) = project(&manifest);
    let (peak, status) = peak_kib_until_exit(spawn(&manifest, &["--quiet"]));
    assert!(status.success());
    assert_eq!(files(&dir.path().join("frames")).len(), 10000);
    assert!(peak > 0 && peak < 100 * 1024, "peak {peak} KiB");
}

#[test]
fn limits_are_refused_with_messages() {
    let cases = [
        ("frames = 12", "frames = 2000000", "frames"),
        (
            "format = \"png\"\n",
            "format = \"png\"\n[render]\nwidth = 16385\n",
            "width",
        ),
        (
            "format = \"png\"\n",
            "format = \"png\"\n[render]\nwidth = 16384\nheight = 16384\n",
            "pixels",
        ),
        (
            "format = \"png\"\n",
            "format = \"png\"\n[render]\nsamples = 64\n",
            "samples",
        ),
    ];
    for (from, to, word) in cases {
        let (_dir, manifest) = project(&circle_manifest("").replace(from, to));
        let out = animate().arg(&manifest).output().unwrap();
        let err = String::from_utf8_lossy(&out.stderr);
        assert_eq!(out.status.code(), Some(2), "{to}: {err}");
        assert!(err.contains(word), "{to}: {err}");
    }
}
