//! `animate` end to end: frame names, equality with `raytrace`, thread counts, shards,
//! streams, resume, kills, and located manifest errors.

use crate::support;

use std::f64::consts::TAU;
use support::*;

#[test]
fn renders_every_frame_under_its_name() {
    let (dir, manifest) = project(&circle_manifest(""));
    animate().arg(&manifest).assert().success();
    let frames = files(&dir.path().join("frames"));
    let names: Vec<&str> = frames.iter().map(|(n, _)| n.as_str()).collect();
    let want: Vec<String> = (0..12).map(|i| format!("frame_{i:04}.png")).collect();
    assert_eq!(names, want);
    // Each frame records what made it (SPEC §8).
    let png = std::fs::read(dir.path().join("frames/frame_0005.png")).unwrap();
    assert!(png.windows(14).any(|w| w == b"whitted:digest"));
    let img = image::open(dir.path().join("frames/frame_0005.png")).unwrap();
    assert_eq!((img.width(), img.height()), (64, 48));
}

#[test]
fn frame_k_is_the_still_raytrace_draws_with_that_camera() {
    let (dir, manifest) = project(&circle_manifest(""));
    animate().arg(&manifest).assert().success();
    for k in [0u32, 3, 7] {
        // SPEC §5: θ = 360°·k/12, eye = (r·sin θ, 3, r·cos θ) around (0, 1, 0).
        let theta = TAU * k as f64 / 12.0;
        let eye = [8.0 * theta.sin(), 3.0, 8.0 * theta.cos()];
        let still = dir.path().join(format!("still{k}.txt"));
        std::fs::write(&still, scene_with_eye(eye)).unwrap();
        let out = dir.path().join(format!("still{k}.png"));
        raytrace()
            .arg(&still)
            .arg("-o")
            .arg(&out)
            .assert()
            .success();
        let frame = dir.path().join(format!("frames/frame_{k:04}.png"));
        // The same pixels; the frame file also carries its provenance.
        assert_eq!(pixels(&out), pixels(&frame), "frame {k}");
    }
}

#[test]
fn one_thread_draws_the_same_bytes_as_all() {
    let (dir, manifest) = project(&circle_manifest(""));
    render_into(&manifest, &dir.path().join("one"), &["--threads", "1"]);
    render_into(&manifest, &dir.path().join("all"), &[]);
    render_into(&manifest, &dir.path().join("three"), &["--threads", "3"]);
    let one = files(&dir.path().join("one"));
    assert_eq!(one.len(), 12);
    assert_eq!(one, files(&dir.path().join("all")));
    assert_eq!(one, files(&dir.path().join("three")));
}

#[test]
fn three_shards_make_the_full_run() {
    let (dir, manifest) = project(&circle_manifest(""));
    render_into(&manifest, &dir.path().join("full"), &[]);
    for k in 0..3 {
        let shard = format!("{k}/3");
        render_into(&manifest, &dir.path().join("sharded"), &["--shard", &shard]);
        // Each shard adds exactly its 4 contiguous frames.
        assert_eq!(files(&dir.path().join("sharded")).len(), 4 * (k + 1));
    }
    assert_eq!(
        files(&dir.path().join("sharded")),
        files(&dir.path().join("full"))
    );
}

#[test]
fn frame_subsets_render_what_the_full_run_would() {
    let (dir, manifest) = project(&circle_manifest(""));
    render_into(&manifest, &dir.path().join("full"), &[]);
    render_into(&manifest, &dir.path().join("some"), &["--frames", "2-4,9"]);
    let some = files(&dir.path().join("some"));
    let full = files(&dir.path().join("full"));
    let names: Vec<&str> = some.iter().map(|(n, _)| n.as_str()).collect();
    assert_eq!(
        names,
        [
            "frame_0002.png",
            "frame_0003.png",
            "frame_0004.png",
            "frame_0009.png"
        ]
    );
    for f in &some {
        assert!(full.contains(f), "{}", f.0);
    }
}

#[test]
fn stdout_raw_is_the_frames_pixels_in_order() {
    let (dir, manifest) = project(&circle_manifest(""));
    animate().arg(&manifest).assert().success();
    let out = animate()
        .arg(&manifest)
        .args(["--stdout", "raw"])
        .output()
        .unwrap();
    assert!(out.status.success());
    assert_eq!(out.stdout.len(), 12 * 64 * 48 * 3);
    let mut want = Vec::new();
    for k in 0..12 {
        want.extend(pixels(&dir.path().join(format!("frames/frame_{k:04}.png"))));
    }
    assert!(
        out.stdout == want,
        "the stream differs from the frame files"
    );
}

#[test]
fn stdout_ppm_and_png_streams() {
    let (_dir, manifest) = project(&circle_manifest(""));
    let out = animate()
        .arg(&manifest)
        .args(["--stdout", "ppm", "--frames", "0-1"])
        .output()
        .unwrap();
    assert!(out.status.success());
    let header = b"P6\n64 48\n255\n";
    assert_eq!(out.stdout.len(), 2 * (header.len() + 64 * 48 * 3));
    assert!(out.stdout.starts_with(header));
    let out = animate()
        .arg(&manifest)
        .args(["--stdout", "png", "--frames", "0"])
        .output()
        .unwrap();
    assert!(out.status.success());
    let img = image::load_from_memory(&out.stdout).unwrap();
    assert_eq!((img.width(), img.height()), (64, 48));
}

#[test]
fn resume_renders_only_missing_frames() {
    let (dir, manifest) = project(&circle_manifest(""));
    animate().arg(&manifest).assert().success();
    let frames = dir.path().join("frames");
    let before = files(&frames);
    for k in [1, 6, 11] {
        std::fs::remove_file(frames.join(format!("frame_{k:04}.png"))).unwrap();
    }
    // Date a kept frame back so that re-rendering it would show.
    let kept = frames.join("frame_0000.png");
    let old = std::time::SystemTime::UNIX_EPOCH + std::time::Duration::from_secs(1 << 30);
    std::fs::File::options()
        .write(true)
        .open(&kept)
        .unwrap()
        .set_modified(old)
        .unwrap();
    let out = animate().arg(&manifest).arg("--resume").output().unwrap();
    assert!(out.status.success());
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(err.contains("3 frames rendered, 9 up to date in"), "{err}");
    assert_eq!(std::fs::metadata(&kept).unwrap().modified().unwrap(), old);
    assert_eq!(files(&frames), before);
}

#[test]
fn resume_renders_again_the_frames_of_a_changed_scene() {
    let (dir, manifest) = project(&circle_manifest(""));
    animate()
        .arg(&manifest)
        .args(["--frames", "0-3"])
        .assert()
        .success();
    let scene = dir.path().join("scene.txt");
    let edited = std::fs::read_to_string(&scene)
        .unwrap()
        .replace("2 40", "2 30");
    std::fs::write(&scene, edited).unwrap();
    let out = animate().arg(&manifest).arg("--resume").output().unwrap();
    assert_eq!(out.status.code(), Some(0));
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(
        err.contains("12 frames rendered, 0 up to date in "),
        "{err}"
    );
    // Nothing stale is left: the folder is a fresh render of the edited scene.
    render_into(&manifest, &dir.path().join("fresh"), &[]);
    assert_eq!(
        files(&dir.path().join("frames")),
        files(&dir.path().join("fresh"))
    );
}

#[test]
fn a_killed_run_leaves_only_complete_frames_and_resume_finishes_it() {
    // Big enough frames that the kill lands mid-run.
    let extra = "\n[render]\nwidth = 320\nheight = 240\nsamples = 2\n";
    let (dir, manifest) = project(&circle_manifest(extra));
    render_into(&manifest, &dir.path().join("whole"), &[]);
    let bin = assert_cmd::cargo::cargo_bin("animate");
    let mut child = std::process::Command::new(bin)
        .arg(&manifest)
        .stderr(std::process::Stdio::null())
        .spawn()
        .unwrap();
    std::thread::sleep(std::time::Duration::from_millis(300));
    child.kill().unwrap(); // SIGKILL: no chance to clean up
    child.wait().unwrap();
    let frames = dir.path().join("frames");
    for (name, bytes) in files(&frames) {
        let img = image::load_from_memory(&bytes);
        assert!(img.is_ok(), "{name} is not a complete PNG");
    }
    animate().arg(&manifest).arg("--resume").assert().success();
    assert_eq!(files(&frames), files(&dir.path().join("whole")));
}

#[test]
fn bad_manifests_give_located_errors() {
    let cases = [
        (circle_manifest("colour = 3\n"), "anim.toml:", "colour"),
        (
            circle_manifest("").replace("radius = 8.0", "radius = \"big\""),
            "anim.toml:8:",
            "radius",
        ),
        (
            circle_manifest("").replace("frames = 12", "frames = 0"),
            "anim.toml:2:",
            "frames",
        ),
    ];
    for (text, location, word) in cases {
        let (_dir, manifest) = project(&text);
        let out = animate().arg(&manifest).output().unwrap();
        assert_eq!(out.status.code(), Some(2), "{text}");
        let err = String::from_utf8_lossy(&out.stderr);
        assert!(err.contains(location) && err.contains(word), "{err}");
    }
}

#[test]
fn a_broken_base_scene_reports_its_own_location() {
    let (dir, manifest) = project(&circle_manifest(""));
    let scene = dir.path().join("scene.txt");
    let broken = std::fs::read_to_string(&scene)
        .unwrap()
        .replacen("1.0  -1.3", "-1.0  -1.3", 1);
    std::fs::write(&scene, broken).unwrap();
    let out = animate().arg(&manifest).output().unwrap();
    assert_eq!(out.status.code(), Some(2));
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(
        err.contains("scene.txt:6:1:") && err.contains("sphere 1 of 3, field Radius"),
        "{err}"
    );
    assert!(!dir.path().join("frames").exists());
}

#[test]
fn bad_frame_lists_and_shards_exit_2() {
    let (_dir, manifest) = project(&circle_manifest(""));
    for args in [
        ["--frames", "12"],
        ["--frames", "3-1x0"],
        ["--shard", "3/3"],
        ["--shard", "x"],
    ] {
        let out = animate().arg(&manifest).args(args).output().unwrap();
        assert_eq!(out.status.code(), Some(2), "{args:?}");
    }
}

#[test]
fn a_camera_key_has_one_name_in_every_message() {
    let spline = |keys: &str| {
        format!(
            "scene = \"scene.txt\"\nframes = 12\n[camera]\npath = \"spline\"\nkeys = [{keys}]\n[output]\ndir = \"frames\"\n"
        )
    };
    let order = spline("{ frame = 0, position = [0, 3, 8] }, { frame = 5, position = [4, 3, 4] }, { frame = 3, position = [0, 3, -8] }");
    let type_error =
        spline("{ frame = 0, position = [0, 3, 8] }, { frame = 5, position = [4, true, 4] }");
    for (text, name) in [
        (order, "camera.keys[2]: frame 3"),
        (type_error, "camera.keys[1].position[1]: "),
    ] {
        let (_dir, manifest) = project(&text);
        let out = animate().arg(&manifest).output().unwrap();
        let err = String::from_utf8_lossy(&out.stderr);
        assert_eq!(out.status.code(), Some(2), "{err}");
        assert!(err.contains(name), "{name}: {err}");
    }
}

#[test]
fn odd_selections_get_plain_answers() {
    let (_dir, manifest) = project(&circle_manifest(""));
    // A negative frame is the frame list's error, not clap's "unexpected argument".
    let out = animate()
        .arg(&manifest)
        .args(["--frames", "-1"])
        .output()
        .unwrap();
    let err = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(2), "{err}");
    assert!(
        err.contains("--frames \"-1\"") && !err.contains("unexpected argument"),
        "{err}"
    );
    // A shard with no frames says so and succeeds.
    let out = animate()
        .arg(&manifest)
        .args(["--shard", "15/20"])
        .output()
        .unwrap();
    let err = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(0), "{err}");
    assert!(
        err.contains("this selection has no frames (12 in all)"),
        "{err}"
    );
    assert!(err.contains("0 frames rendered, 0 up to date"), "{err}");
}
