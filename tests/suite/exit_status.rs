//! Every row of the exit-status table (`whitted::exit`, README "Exit status") through the
//! built binaries, for `raytrace` and `animate`. Most rows already have a test beside the
//! feature they belong to; this file adds the rows and causes that had none, and this
//! table says where each one is tested:
//!
//! | status | cause | raytrace | animate |
//! |---|---|---|---|
//! | 0 | a render | raytrace_cli::quiet_prints_nothing_and_the_default_reports_the_render | animate_cli (every `render_into`), farm_slurm |
//! | 0 | `check`: every frame passes | | animate_check::bless_then_check_passes |
//! | 0 | `status`: all up to date | | animate_provenance (`status_json` → `Some(0)`) |
//! | 1 | a frame cannot be written mid-run | raytrace_cli::a_failed_write_after_rendering_is_status_1_and_names_the_file | animate_faults::output_folder_vanishing_mid_run |
//! | 1 | the output stream fails | | animate_faults::broken_pipe_on_stdout, full_disk_on_stdout |
//! | 1 | ffmpeg fails at the end | | here: ffmpeg_failing_at_the_end_is_status_1 |
//! | 1 | `check`: a frame fails | | animate_check::a_changed_block_fails_and_names_the_frame |
//! | 1 | `status`: stale or missing frames | | animate_provenance (`status_json` → `Some(1)`) |
//! | 2 | a bad argument (clap) | raytrace_cli::bad_sample_and_thread_counts_are_refused | here: a_bad_argument_or_manifest_is_2_for_every_subcommand; animate_cli::bad_frame_lists_and_shards_exit_2 |
//! | 2 | a bad manifest (located) | | here: a_bad_argument_or_manifest_is_2_for_every_subcommand; newcomer |
//! | 2 | a bad scene, with file:line:col | malformed_scenes::every_malformed_scene_is_refused_by_the_binary | newcomer::animate_reports_the_count_of_its_base_scene_too |
//! | 2 | a scene file that cannot be read | malformed_scenes::a_missing_scene_file_is_named | here: a_scene_file_that_cannot_be_read_is_2_at_the_manifest_line |
//! | 2 | an output that cannot be used | raytrace_cli::an_output_in_a_missing_folder_is_bad_input_and_leaves_nothing (missing folder, a folder), malformed_scenes::an_unknown_output_extension_is_refused | animate_faults::output_folder_that_is_a_file, unwritable_output_folder; animate_ffmpeg::a_video_target_ffmpeg_cannot_write_is_refused_before_any_frame (missing folder, unknown container); animate_preview::bad_input_gets_a_located_error (preview folder a file) |
//! | 2 | ffmpeg missing from PATH | | animate_ffmpeg::a_missing_ffmpeg_is_bad_input_with_a_way_out |
//! | 2 | a check that cannot run | | animate_check::missing_reference_exits_2, reference_of_another_size_exits_2, no_check_section_and_no_frames_exits_2 |
//! | 130 | SIGINT mid-run | here: raytrace_stopped_by_a_signal_is_128_plus_n | animate_faults::sigint_stops_after_frames_in_flight_and_resume_completes |
//! | 143 | SIGTERM mid-run | here: raytrace_stopped_by_a_signal_is_128_plus_n | animate_faults::sigterm_stops_after_frames_in_flight_and_resume_completes |

use crate::support;

use std::os::unix::fs::PermissionsExt;
use std::process::{Command, Stdio};
use std::time::Duration;
use support::*;

/// The status and standard error of a finished command.
fn run(cmd: &mut assert_cmd::Command) -> (Option<i32>, String) {
    let out = cmd.output().unwrap();
    (
        out.status.code(),
        String::from_utf8_lossy(&out.stderr).into_owned(),
    )
}

#[test]
fn raytrace_stopped_by_a_signal_is_128_plus_n() {
    let dir = tempfile::tempdir().unwrap();
    std::fs::write(
        dir.path().join("scene.txt"),
        scene_with_eye([0.0, 3.0, 8.0]),
    )
    .unwrap();
    for (sig, code) in [("INT", 130), ("TERM", 143)] {
        // 3200×2400 at 4×4 samples on one thread: many seconds of work.
        let mut child = Command::new(assert_cmd::cargo::cargo_bin("raytrace"))
            .current_dir(dir.path())
            .args(["scene.txt", "-o", "big.png", "--size", "3200x2400"])
            .args(["--samples", "4", "--threads", "1", "-q"])
            .stderr(Stdio::null())
            .spawn()
            .unwrap();
        std::thread::sleep(Duration::from_millis(300));
        // `signal` waits until raytrace catches the signal (a fixed sleep raced its start).
        signal(&child, sig);
        let (status, took) = wait_within(&mut child, Duration::from_secs(60));
        assert_eq!(status, Some(code), "SIG{sig}");
        timed(
            &format!("SIG{sig} to the exit"),
            took,
            Duration::from_secs(2),
            Duration::from_secs(10),
        );
        assert_eq!(entries(dir.path()), ["scene.txt"], "SIG{sig}: files left");
    }
}

#[test]
fn ffmpeg_failing_at_the_end_is_status_1() {
    // A stand-in ffmpeg first on PATH: it passes the target probe (`-f lavfi`), reads every
    // frame, then fails as an encoder that cannot finish its file would.
    let (dir, manifest) = project(&circle_manifest(""));
    let bin = dir.path().join("bin");
    std::fs::create_dir(&bin).unwrap();
    let fake = bin.join("ffmpeg");
    std::fs::write(
        &fake,
        "#!/bin/sh\ncase \"$*\" in *lavfi*) exit 0;; esac\ncat > /dev/null\n\
         echo 'stand-in: cannot finish the file' >&2\nexit 1\n",
    )
    .unwrap();
    std::fs::set_permissions(&fake, std::fs::Permissions::from_mode(0o755)).unwrap();
    let path = format!("{}:/usr/bin:/bin", bin.display());
    let video = dir.path().join("v.mp4");
    let (code, err) = run(animate()
        .arg(&manifest)
        .arg("--video")
        .arg(&video)
        .env("PATH", path));
    assert_eq!(code, Some(1), "{err}");
    assert!(
        err.contains("ffmpeg failed") && err.contains("stand-in: cannot finish the file"),
        "{err}"
    );
    assert!(!err.contains("Broken pipe"), "{err}");
}

#[test]
fn a_bad_argument_or_manifest_is_2_for_every_subcommand() {
    let (dir, manifest) = project(&circle_manifest("\n[render]\nsamplse = 2\n"));
    let m = manifest.to_str().unwrap();
    let located = format!("{m}:19:1: render: unknown key `samplse`");
    let out = dir.path().join("out");
    let o = out.to_str().unwrap();
    for sub in [
        &[][..],
        &["status"],
        &["check"],
        &["bless"],
        &["preview", "-o", o],
    ] {
        let (code, err) = run(animate().args(sub).arg(m));
        assert_eq!(code, Some(2), "{sub:?}: {err}");
        assert!(err.contains(&located), "{sub:?}: {err}");
        let (code, err) = run(animate().args(sub).arg(m).arg("--no-such-option"));
        assert_eq!(code, Some(2), "{sub:?}: {err}");
        assert!(err.contains("--no-such-option"), "{sub:?}: {err}");
    }
    assert!(!out.exists() && !dir.path().join("frames").exists());
}

#[test]
fn a_scene_file_that_cannot_be_read_is_2_at_the_manifest_line() {
    let (dir, manifest) = project(&circle_manifest(""));
    std::fs::remove_file(dir.path().join("scene.txt")).unwrap();
    let (code, err) = run(animate().arg(&manifest));
    assert_eq!(code, Some(2), "{err}");
    let at = format!("{}:1:", manifest.display());
    assert!(err.contains(&at) && err.contains("scene.txt"), "{err}");
}
