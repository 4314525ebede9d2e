//! `animate --video` and `--stdout raw` into a real ffmpeg, checked with ffprobe.
//! `.ci/run` installs ffmpeg; on a machine without it these tests say so and pass only
//! outside CI.

use crate::skip;
use crate::support;

use std::process::{Command, Stdio};
use support::*;

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
    if !skip::ffmpeg() {
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
    if !skip::ffmpeg() {
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
fn a_video_target_ffmpeg_cannot_write_is_refused_before_any_frame() {
    if !skip::ffmpeg() {
        return;
    }
    let (dir, manifest) = project(&circle_manifest(""));
    // An unknown container: ffmpeg's own reason, not a broken pipe; exit 2.
    let out = animate()
        .arg(&manifest)
        .arg("--video")
        .arg(dir.path().join("out.xyz"))
        .output()
        .unwrap();
    let err = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(2), "{err}");
    assert!(
        err.contains("cannot make the video") && err.contains("out.xyz"),
        "{err}"
    );
    assert!(err.contains("output format"), "{err}");
    assert!(
        !err.contains(" @ 0x"),
        "ffmpeg's addresses are noise: {err}"
    );
    assert!(!err.contains("Broken pipe"), "{err}");
    // A folder that does not exist.
    let missing = dir.path().join("no/such/dir/x.mp4");
    let out = animate()
        .arg(&manifest)
        .arg("--video")
        .arg(&missing)
        .output()
        .unwrap();
    let err = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(2), "{err}");
    assert!(err.contains("does not exist"), "{err}");
}

#[test]
fn a_missing_ffmpeg_is_bad_input_with_a_way_out() {
    let (dir, manifest) = project(&circle_manifest(""));
    let out = animate()
        .arg(&manifest)
        .arg("--video")
        .arg(dir.path().join("v.mp4"))
        .env("PATH", dir.path())
        .output()
        .unwrap();
    let err = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(2), "{err}");
    assert!(
        err.contains("ffmpeg was not found on PATH") && err.contains("--stdout raw"),
        "{err}"
    );
}

#[test]
fn raw_frames_come_with_the_ffmpeg_options_and_never_onto_a_terminal() {
    let (_dir, manifest) = project(&circle_manifest(""));
    let out = animate()
        .arg(&manifest)
        .args(["--stdout", "raw", "--frames", "0-1"])
        .output()
        .unwrap();
    assert!(out.status.success());
    assert_eq!(out.stdout.len(), 2 * 64 * 48 * 3);
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(
        err.contains("-f rawvideo -pix_fmt rgb24 -s 64x48 -r 12 -i -"),
        "{err}"
    );
    // On a terminal (a pseudo-terminal from `script`) binary output is refused.
    let bin = assert_cmd::cargo::cargo_bin("animate");
    let cmd = format!("{} {} --stdout raw", bin.display(), manifest.display());
    let Ok(out) = Command::new("script")
        .args(["-qec", &cmd, "/dev/null"])
        .stdin(Stdio::null())
        .output()
    else {
        eprintln!("script(1) not installed: skipping the terminal case");
        return;
    };
    let text = String::from_utf8_lossy(&out.stdout);
    assert_eq!(out.status.code(), Some(2), "{text}");
    assert!(
        text.contains("refusing to write binary frames to a terminal"),
        "{text}"
    );
}
