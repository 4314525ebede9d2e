//! `animate --video` and `--stdout raw` into a real ffmpeg, checked with ffprobe.
//! `.ci/run` installs ffmpeg; on a machine without it these tests say so and pass only
//! outside CI.

mod support;

use std::process::{Command, Stdio};
use support::*;

fn have_ffmpeg() -> bool {
    let found = Command::new("ffprobe").arg("-version").output().is_ok()
        && Command::new("ffmpeg").arg("-version").output().is_ok();
    if !found {
        assert!(std::env::var_os("CI").is_none(), "CI must install ffmpeg");
        eprintln!("ffmpeg/ffprobe not installed: skipping");
    }
    found
}

/// The number of video frames ffprobe counts in `file`.
fn frame_count(file: &std::path::Path) -> u32 {
    let out = Command::new("ffprobe")
        .args(["-v", "error", "-select_streams", "v:0", "-count_frames"])
        .args([
            "-show_entries",
            "stream=nb_read_frames,width,height",
            "-of",
            "csv=p=0",
        ])
        .arg(file)
        .output()
        .unwrap();
    let text = String::from_utf8_lossy(&out.stdout);
    let fields: Vec<&str> = text.trim().split(',').collect();
    assert_eq!(&fields[..2], &["64", "48"], "{text}");
    fields[2].parse().unwrap()
}

#[test]
fn video_flag_makes_an_mp4_with_every_frame() {
    if !have_ffmpeg() {
        return;
    }
    let (dir, manifest) = project(&circle_manifest(""));
    let mp4 = dir.path().join("orbit.mp4");
    animate()
        .arg(&manifest)
        .arg("--video")
        .arg(&mp4)
        .assert()
        .success();
    assert_eq!(frame_count(&mp4), 12);
}

#[test]
fn stdout_raw_piped_into_ffmpeg() {
    if !have_ffmpeg() {
        return;
    }
    let (dir, manifest) = project(&circle_manifest(""));
    let mp4 = dir.path().join("piped.mp4");
    let bin = assert_cmd::cargo::cargo_bin("animate");
    let mut producer = Command::new(bin)
        .arg(&manifest)
        .args(["--stdout", "raw"])
        .stdout(Stdio::piped())
        .spawn()
        .unwrap();
    let status = Command::new("ffmpeg")
        .args([
            "-y",
            "-loglevel",
            "error",
            "-f",
            "rawvideo",
            "-pix_fmt",
            "rgb24",
        ])
        .args(["-s", "64x48", "-r", "12", "-i", "-", "-pix_fmt", "yuv420p"])
        .arg(&mp4)
        .stdin(producer.stdout.take().unwrap())
        .status()
        .unwrap();
    assert!(status.success());
    assert!(producer.wait().unwrap().success());
    assert_eq!(frame_count(&mp4), 12);
}

#[test]
fn missing_ffmpeg_is_a_clear_error() {
    let (dir, manifest) = project(&circle_manifest(""));
    let out = animate()
        .arg(&manifest)
        .arg("--video")
        .arg(dir.path().join("x.mp4"))
        .env("PATH", dir.path())
        .output()
        .unwrap();
    assert_ne!(out.status.code(), Some(0));
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(err.contains("ffmpeg was not found on PATH"), "{err}");
}
