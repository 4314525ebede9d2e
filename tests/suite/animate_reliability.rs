//! Faults around the frames, through the built `animate` and `raytrace`: endless and
//! non-regular inputs, stalled consumers, frames past a shortened sequence, one folder for
//! one manifest, a full disk, and the smaller faults of docs/reliability.md.

use crate::skip;
use crate::support;

use std::process::{Command, Stdio};
use std::time::{Duration, Instant};
use support::*;

/// Runs `cmd` with a deadline of `secs` seconds: a hang fails instead of blocking the suite.
fn within(cmd: &mut Command, secs: u64) -> std::process::Output {
    output_within(cmd, Duration::from_secs(secs))
}

fn animate_cmd() -> Command {
    Command::new(assert_cmd::cargo::cargo_bin("animate"))
}

#[test]
fn devices_fifos_and_huge_files_are_refused_with_the_limit() {
    let (dir, manifest) = project(&circle_manifest(""));
    let out = within(animate_cmd().arg("/dev/zero"), 10);
    let err = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(2), "{err}");
    assert!(
        err.contains("/dev/zero") && err.contains("not a regular file"),
        "{err}"
    );
    let fifo = dir.path().join("pipe.txt");
    mkfifo(&fifo);
    for scene in ["/dev/zero", "pipe.txt"] {
        let text = circle_manifest("").replace("scene.txt", scene);
        std::fs::write(&manifest, text).unwrap();
        let out = within(animate_cmd().arg(&manifest), 10);
        let err = String::from_utf8_lossy(&out.stderr);
        assert_eq!(out.status.code(), Some(2), "{err}");
        assert!(
            err.contains(":1:9: scene: cannot read") && err.contains("not a regular file"),
            "{err}"
        );
    }
    let out = within(
        Command::new(assert_cmd::cargo::cargo_bin("raytrace")).arg(&fifo),
        10,
    );
    assert_eq!(out.status.code(), Some(2));
    // A manifest past 16 MiB: refused, the limit stated, before it is read.
    let big = dir.path().join("big.toml");
    let file = std::fs::File::create(&big).unwrap();
    file.set_len((16 << 20) + 1).unwrap();
    let out = within(animate_cmd().arg(&big), 10);
    let err = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(2), "{err}");
    assert!(
        err.contains("larger than the limit of 16 MiB for a manifest"),
        "{err}"
    );
}

#[test]
fn status_does_not_follow_a_frame_into_a_device_or_fifo() {
    let (dir, manifest) = project(&circle_manifest(""));
    animate().arg(&manifest).arg("-q").assert().success();
    let frames = dir.path().join("frames");
    std::fs::remove_file(frames.join("frame_0001.png")).unwrap();
    std::os::unix::fs::symlink("/dev/zero", frames.join("frame_0001.png")).unwrap();
    std::fs::remove_file(frames.join("frame_0002.png")).unwrap();
    mkfifo(&frames.join("frame_0002.png"));
    let out = within(animate_cmd().arg("status").arg(&manifest), 10);
    let text = String::from_utf8_lossy(&out.stdout);
    assert_eq!(out.status.code(), Some(1), "{text}");
    assert!(text.contains("      stale:       2  1-2\n"), "{text}");
    // The link and the FIFO are not the tool's: --resume refuses them, naming the frames,
    // and leaves them; with --force it replaces them with frames (the rename replaces the
    // link and the FIFO, never the link's target).
    let out = within(animate_cmd().arg(&manifest).args(["--resume", "-q"]), 20);
    let err = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(2), "{err}");
    assert!(err.contains("--force"), "{err}");
    assert!(std::fs::symlink_metadata(frames.join("frame_0001.png"))
        .unwrap()
        .file_type()
        .is_symlink());
    let forced = ["--resume", "--force", "-q"];
    let out = within(animate_cmd().arg(&manifest).args(forced), 20);
    assert!(out.status.success());
    assert!(std::fs::symlink_metadata(frames.join("frame_0001.png"))
        .unwrap()
        .is_file());
}

#[test]
fn a_signal_ends_a_run_whose_stdout_reader_never_reads() {
    let (dir, _) = project(&circle_manifest(""));
    let m = raw_manifest(dir.path(), "long.toml", 100_000, 8.0);
    let fifo = dir.path().join("out.fifo");
    mkfifo(&fifo);
    // Holding the FIFO open for reading and writing: the reader that never reads.
    let _held = std::fs::OpenOptions::new()
        .read(true)
        .write(true)
        .open(&fifo)
        .unwrap();
    for (sig, code) in [("TERM", 143), ("INT", 130)] {
        let out = std::fs::OpenOptions::new().write(true).open(&fifo).unwrap();
        let mut child = animate_cmd()
            .arg(&m)
            .args(["--stdout", "raw", "-q"])
            .stdout(out)
            .stderr(Stdio::piped())
            .spawn()
            .unwrap();
        std::thread::sleep(Duration::from_millis(700));
        signal(&child, sig);
        let (status, took) = wait_within(&mut child, Duration::from_secs(60));
        assert_eq!(status, Some(code), "SIG{sig}");
        // Within a second (the target); a run that waits for its reader never ends.
        timed(
            &format!("SIG{sig} to the exit"),
            took,
            Duration::from_secs(1),
            Duration::from_secs(10),
        );
        let err = stderr_of(&mut child);
        assert!(
            err.contains("cannot be resumed") && !err.contains("completes the run"),
            "{err}"
        );
    }
}

#[test]
fn frames_past_a_shortened_sequence_are_reported_and_cleaned() {
    let (dir, manifest) = project(&circle_manifest("").replace("frames = 12", "frames = 20"));
    animate().arg(&manifest).arg("-q").assert().success();
    let frames = dir.path().join("frames");
    // A killed run's temporary.
    std::fs::write(frames.join(".frame_0003.png.Ab12Cd.tmp"), b"half").unwrap();
    let ten = dir.path().join("ten.toml");
    std::fs::write(
        &ten,
        circle_manifest("").replace("frames = 12", "frames = 10"),
    )
    .unwrap();
    animate()
        .arg(&ten)
        .args(["-q", "--force"])
        .assert()
        .success();
    assert!(
        !frames.join(".frame_0003.png.Ab12Cd.tmp").exists(),
        "the run clears stale temporaries"
    );
    std::fs::write(frames.join(".frame_0004.png.Zz99Yy.tmp"), b"half").unwrap();
    let out = animate().arg("status").arg(&ten).output().unwrap();
    let text = String::from_utf8_lossy(&out.stdout);
    assert_eq!(out.status.code(), Some(1), "{text}");
    assert!(text.contains(" up to date:      10  0-9\n"), "{text}");
    assert!(text.contains("   past end:      10  10-19  ("), "{text}");
    // Frames 10-19 record anim.toml, not ten.toml: clean removes another manifest's
    // frames only when forced (reliability round three).
    let out = animate().arg("clean").arg(&ten).output().unwrap();
    assert_eq!(out.status.code(), Some(2));
    let out = animate()
        .arg("clean")
        .arg(&ten)
        .arg("--force")
        .output()
        .unwrap();
    let text = String::from_utf8_lossy(&out.stdout);
    assert!(out.status.success());
    assert!(
        text.contains("removed 10 frame(s) past the end (10-19), 1 temporary file(s) and "),
        "{text}"
    );
    assert_eq!(files(&frames).len(), 10);
    animate().arg("status").arg(&ten).assert().success();
}

#[test]
fn one_folder_one_run_and_no_overwriting_another_manifests_frames() {
    let (dir, _) = project(&circle_manifest(""));
    let a = raw_manifest(dir.path(), "a.toml", 4000, 8.0);
    let b = raw_manifest(dir.path(), "b.toml", 12, 9.0);
    let mut first = spawn_animate(&a, &[]);
    let frames = dir.path().join("frames");
    let start = Instant::now();
    while !frames.join(".whitted-record/frame_0000.raw.txt").exists() {
        assert!(start.elapsed() < Duration::from_secs(10));
        std::thread::sleep(Duration::from_millis(10));
    }
    let out = animate().arg(&b).output().unwrap();
    let err = String::from_utf8_lossy(&out.stderr);
    // Nor is the folder cleaned under a run, of another manifest or of the same one:
    // bad input (2), nothing removed.
    for m in [&b, &a] {
        let clean = animate().arg("clean").arg(m).output().unwrap();
        let said = String::from_utf8_lossy(&clean.stderr);
        assert_eq!(clean.status.code(), Some(2), "{said}");
        assert!(said.contains("is writing into"), "{said}");
    }
    // A second run of A's manifest shares the folder (as render-farm shards do).
    animate()
        .arg(&a)
        .args(["--frames", "3999", "-q"])
        .assert()
        .success();
    first.kill().unwrap();
    first.wait().unwrap();
    assert_eq!(out.status.code(), Some(2), "{err}");
    let holder = format!("pid {}, manifest ", first.id());
    assert!(
        err.contains("a run of another manifest is writing into")
            && err.contains(&holder)
            && err.contains("a.toml"),
        "{err}"
    );
    // A killed holder leaves no lock: B runs, but refuses A's frames without --force.
    let out = animate().arg(&b).output().unwrap();
    let err = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(2), "{err}");
    assert!(
        err.contains("rendered by another manifest (a.toml: frames 0-") && err.contains("--force"),
        "{err}"
    );
    animate().arg(&b).args(["--force", "-q"]).assert().success();
    // B's 12 frames are up to date; A's later ones are past B's end.
    let out = animate().arg("status").arg(&b).output().unwrap();
    let text = String::from_utf8_lossy(&out.stdout);
    assert_eq!(out.status.code(), Some(1), "{text}");
    assert!(
        text.contains(" up to date:      12  0-11\n") && text.contains("past end:"),
        "{text}"
    );
}

#[test]
fn smaller_faults() {
    let (dir, manifest) = project(&circle_manifest(""));
    // raytrace does not write its image over the scene it reads.
    let scene = dir.path().join("s.png");
    std::fs::copy(dir.path().join("scene.txt"), &scene).unwrap();
    let before = std::fs::read(&scene).unwrap();
    let out = raytrace().arg(&scene).output().unwrap();
    assert_eq!(out.status.code(), Some(2));
    assert_eq!(std::fs::read(&scene).unwrap(), before);
    // A closed standard output is an error, not a silent success.
    let out = Command::new("sh")
        .arg("-c")
        .arg("exec \"$0\" \"$1\" --stdout raw -q >&-")
        .arg(assert_cmd::cargo::cargo_bin("animate"))
        .arg(&manifest)
        .output()
        .unwrap();
    let err = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(2), "{err}");
    assert!(err.contains("standard output is closed"), "{err}");
    // fps has a lower bound.
    std::fs::write(
        &manifest,
        circle_manifest("").replace("fps = 12", "fps = 5e-324"),
    )
    .unwrap();
    let out = animate().arg(&manifest).output().unwrap();
    let err = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(2), "{err}");
    assert!(
        err.contains("`fps` must be a number from 0.01 to 1000"),
        "{err}"
    );
    // A 1 MB token is cut in the message.
    let token = "x".repeat(1 << 20);
    std::fs::write(dir.path().join("t.txt"), format!("{token} 48\n")).unwrap();
    let out = raytrace().arg(dir.path().join("t.txt")).output().unwrap();
    let err = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(2));
    assert!(
        err.len() < 400 && err.contains("… (1048576 characters)"),
        "{}",
        &err[..err.len().min(400)]
    );
}

#[test]
fn a_full_disk_names_the_frame_and_leaves_no_temporary() {
    let (dir, manifest) = project(&circle_manifest("\n[render]\nwidth = 320\nheight = 240\n"));
    let mnt = dir.path().join("small");
    std::fs::create_dir(&mnt).unwrap();
    let mounted = Command::new("mount")
        .args(["-t", "tmpfs", "-o", "size=256k", "tmpfs"])
        .arg(&mnt)
        .stderr(Stdio::null())
        .status()
        .is_ok_and(|s| s.success());
    if !mounted {
        skip::skip("cannot mount a small tmpfs here (not root?); CI runs as root");
        return;
    }
    let out = animate()
        .arg(&manifest)
        .arg("-o")
        .arg(&mnt)
        .args(["-q", "--threads", "1"])
        .output()
        .unwrap();
    let err = String::from_utf8_lossy(&out.stderr);
    let left: Vec<String> = entries(&mnt)
        .into_iter()
        .filter(|n| n.ends_with(".tmp"))
        .collect();
    let _ = Command::new("umount").arg(&mnt).status();
    assert_eq!(out.status.code(), Some(1), "{err}");
    assert!(
        err.contains("No space left on device") && err.contains("/small/frame_00"),
        "{err}"
    );
    assert!(left.is_empty(), "{left:?}");
}

#[test]
fn a_manifest_read_through_dev_stdin_is_the_file_behind_it() {
    // `animate status /dev/stdin < m.toml` is m.toml's status: its scene and its frame
    // folder beside it, not `/dev/stdin-frames`.
    let (dir, manifest) = project(&circle_manifest(""));
    animate()
        .arg(&manifest)
        .args(["-q", "--frames", "0-3"])
        .assert()
        .success();
    let out = Command::new(assert_cmd::cargo::cargo_bin("animate"))
        .args(["status", "/dev/stdin"])
        .stdin(std::fs::File::open(&manifest).unwrap())
        .output()
        .unwrap();
    let text = String::from_utf8_lossy(&out.stdout);
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(
        !text.contains("/dev/stdin-frames") && !err.contains("/dev/"),
        "{text}{err}"
    );
    assert!(text.contains(" up to date:       4  0-3\n"), "{text}{err}");
    assert_eq!(
        out.status.code(),
        Some(1),
        "frames 4-11 are missing: {text}"
    );
    let folder = std::fs::canonicalize(dir.path().join("frames")).unwrap();
    assert!(text.contains(&folder.display().to_string()), "{text}");
}
