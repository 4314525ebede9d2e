//! Videos that are never lost and folders encoded without rendering again, through the
//! built `animate` and a real ffmpeg: `--video` writes a temporary beside its file and
//! renames it on success, refuses to replace a video unless `--force`, takes `--codec`
//! and `--crf`, and ends within a second of a signal even when ffmpeg is stopped;
//! `animate encode` checks the folder is complete and up to date first. Without ffmpeg
//! these tests say "skipped" and pass, except under CI.

use crate::skip;
use crate::support;

use std::process::{Command, Stdio};
use std::time::Duration;
use support::*;

/// `codec_name,nb_read_frames` of the video's first stream, as ffprobe counts them.
fn probe(file: &std::path::Path) -> String {
    let out = Command::new("ffprobe")
        .args(["-v", "error", "-select_streams", "v:0", "-count_frames"])
        .args([
            "-show_entries",
            "stream=codec_name,nb_read_frames",
            "-of",
            "csv=p=0",
        ])
        .arg(file)
        .output()
        .unwrap();
    String::from_utf8_lossy(&out.stdout).trim().to_string()
}

/// The hidden temporaries of a video (`.v.mp4.XXXX`) in `dir`.
fn hidden(dir: &std::path::Path) -> Vec<String> {
    entries(dir)
        .into_iter()
        .filter(|n| n.starts_with('.') && n.contains(".mp4."))
        .collect()
}

#[test]
fn an_interrupted_or_stopped_video_leaves_the_previous_one_whole() {
    if !skip::ffmpeg() {
        return;
    }
    let (dir, manifest) = project(&circle_manifest(""));
    let video = dir.path().join("v.mp4");
    animate()
        .arg(&manifest)
        .arg("--video")
        .arg(&video)
        .arg("-q")
        .assert()
        .success();
    let good = std::fs::read(&video).unwrap();
    // Not replaced without --force, and nothing rendered.
    let out = animate()
        .arg(&manifest)
        .arg("--video")
        .arg(&video)
        .output()
        .unwrap();
    let err = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(2), "{err}");
    assert!(
        err.contains("exists and would be replaced") && err.contains("--force"),
        "{err}"
    );
    let long = dir.path().join("long.toml");
    std::fs::write(
        &long,
        circle_manifest("").replace("frames = 12", "frames = 100000"),
    )
    .unwrap();
    for (sig, code, stop_ffmpeg) in [("INT", 130, false), ("TERM", 143, true)] {
        let mut child = Command::new(assert_cmd::cargo::cargo_bin("animate"))
            .arg(&long)
            .arg("--video")
            .arg(&video)
            .args(["--force", "-q"])
            .stderr(Stdio::piped())
            .spawn()
            .unwrap();
        std::thread::sleep(Duration::from_millis(800));
        let mut stopped = Vec::new();
        if stop_ffmpeg {
            // The encoder (`ffmpeg … -f rawvideo … -i -`), not the short probe before it.
            let found = poll_until(Duration::from_secs(30), || {
                stopped = children(child.id())
                    .into_iter()
                    .filter(|&c| cmdline(c).contains("rawvideo"))
                    .collect();
                !stopped.is_empty()
            });
            assert!(found.is_some(), "animate never started its ffmpeg encoder");
            for &c in &stopped {
                signal_pid(c, "STOP");
            }
            std::thread::sleep(Duration::from_millis(300));
        }
        signal(&child, sig);
        let (status, took) = wait_within(&mut child, Duration::from_secs(60));
        let err = stderr_of(&mut child);
        assert_eq!(status, Some(code), "SIG{sig}: {err}");
        // Within a second (the target); waiting for a stopped ffmpeg or for the 100000
        // frames would never end.
        timed(
            &format!("SIG{sig} to the exit (ffmpeg stopped: {stop_ffmpeg})"),
            took,
            Duration::from_secs(1),
            Duration::from_secs(10),
        );
        assert!(
            err.contains("cannot be resumed") && !err.contains("completes the run"),
            "{err}"
        );
        assert_eq!(
            std::fs::read(&video).unwrap(),
            good,
            "SIG{sig}: the previous video changed"
        );
        assert_eq!(hidden(dir.path()), Vec::<String>::new(), "SIG{sig}");
        // The stopped encoder did not outlive the run.
        for pid in stopped {
            let gone = poll_until(Duration::from_secs(10), || !alive(pid));
            assert!(
                gone.is_some(),
                "SIG{sig}: the stopped ffmpeg {pid} is still there"
            );
        }
    }
}

#[test]
fn encode_checks_the_folder_then_makes_the_video_with_the_options() {
    if !skip::ffmpeg() {
        return;
    }
    let (dir, manifest) = project(&circle_manifest(""));
    animate()
        .arg(&manifest)
        .args(["--frames", "0-5", "-q"])
        .assert()
        .success();
    let video = dir.path().join("frames.mp4");
    let out = animate().arg("encode").arg(&manifest).output().unwrap();
    let err = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(2), "{err}");
    assert!(
        err.contains("not ready to encode: frames missing 6-11"),
        "{err}"
    );
    assert!(!video.exists());
    animate()
        .arg(&manifest)
        .args(["--resume", "-q"])
        .assert()
        .success();
    animate()
        .arg("encode")
        .arg(&manifest)
        .args(["--codec", "libx264", "--crf", "30", "-q"])
        .assert()
        .success();
    assert_eq!(probe(&video), "h264,12");
    let first = std::fs::read(&video).unwrap();
    animate().arg("encode").arg(&manifest).assert().code(2);
    // Another codec, forced over the first video.
    animate()
        .arg("encode")
        .arg(&manifest)
        .args(["--codec", "mpeg4", "--force", "-q"])
        .assert()
        .success();
    assert_eq!(probe(&video), "mpeg4,12");
    assert_ne!(std::fs::read(&video).unwrap(), first);
    // A stale frame is refused.
    let png = dir.path().join("frames/frame_0004.png");
    let mut bytes = std::fs::read(&png).unwrap();
    let n = bytes.len();
    bytes[n / 2] ^= 1;
    std::fs::write(&png, bytes).unwrap();
    let out = animate()
        .arg("encode")
        .arg(&manifest)
        .arg("--force")
        .output()
        .unwrap();
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(err.contains("frames broken 4 (damaged: "), "{err}");
    // The same options on --video.
    let other = dir.path().join("crf.mkv");
    animate()
        .arg(&manifest)
        .arg("--video")
        .arg(&other)
        .args(["--codec", "libx264", "--crf", "40", "-q"])
        .assert()
        .success();
    assert_eq!(probe(&other), "h264,12");
    animate()
        .arg(&manifest)
        .args(["--crf", "20"])
        .assert()
        .code(2);
}

#[test]
fn encode_and_verify_read_ppm_raw_and_exr_folders_as_their_pictures() {
    if !skip::ffmpeg() {
        return;
    }
    // The PNG folder's frames are the pictures every other format must give back.
    let three = circle_manifest("").replace("frames = 12", "frames = 3");
    let (dir, manifest) = project(&three);
    animate().arg(&manifest).arg("-q").assert().success();
    let want: Vec<u8> = (0..3)
        .flat_map(|f| pixels(&dir.path().join(format!("frames/frame_{f:04}.png"))))
        .collect();
    // Lossless in and out (FFV1, planar RGB), so the video holds the frames' bytes.
    let lossless = ["--codec", "ffv1", "--pix-fmt", "gbrp", "-q"];
    for format in ["ppm", "raw", "exr"] {
        let text = three.replace("format = \"png\"", &format!("format = \"{format}\""));
        std::fs::write(&manifest, text).unwrap();
        animate().arg(&manifest).arg("-q").assert().success();
        let out = animate()
            .args(["status", "--verify"])
            .arg(&manifest)
            .output()
            .unwrap();
        let text = String::from_utf8_lossy(&out.stdout);
        assert_eq!(out.status.code(), Some(0), "{format}: {text}");
        let video = dir.path().join(format!("{format}.mkv"));
        let out = animate()
            .arg("encode")
            .arg(&manifest)
            .arg("-o")
            .arg(&video)
            .args(lossless)
            .output()
            .unwrap();
        let err = String::from_utf8_lossy(&out.stderr);
        assert_eq!(out.status.code(), Some(0), "{format}: {err}");
        assert_eq!(probe(&video), "ffv1,3", "{format}");
        assert!(
            decoded(&video) == want,
            "{format}: not the PNG frames' pixels"
        );
    }
}

#[test]
fn the_video_gets_the_permissions_of_a_frame() {
    use std::os::unix::fs::PermissionsExt;
    if !skip::ffmpeg() {
        return;
    }
    let two = circle_manifest("").replace("frames = 12", "frames = 2");
    let (dir, manifest) = project(&two);
    animate().arg(&manifest).arg("-q").assert().success();
    animate()
        .arg("encode")
        .arg(&manifest)
        .arg("-q")
        .assert()
        .success();
    let mode = |p: &std::path::Path| std::fs::metadata(p).unwrap().permissions().mode() & 0o777;
    let frame = mode(&dir.path().join("frames/frame_0000.png"));
    // Not tempfile's private 0600: what the umask leaves of 0666, as for a frame.
    assert_eq!(mode(&dir.path().join("frames.mp4")), frame);
    assert_ne!(
        frame & 0o044,
        0,
        "the umask of the test leaves frames readable"
    );
}
