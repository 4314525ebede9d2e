//! Adaptive anti-aliasing end to end (SPEC §15): `raytrace --aa adaptive[:T[:D]]` and
//! `[render] antialias` through `animate`: the same bytes on any thread count, across
//! three shards and a resumed run, settings in the digest, bad values refused.

use crate::support;

use std::path::Path;
use support::*;

const AA: &str = "[render]\nantialias = { mode = \"adaptive\", threshold = 0.1, depth = 3 }\n";

fn write_scene(dir: &Path) -> std::path::PathBuf {
    let scene = dir.join("scene.txt");
    std::fs::write(&scene, scene_with_eye([0.0, 3.0, 8.0])).unwrap();
    scene
}

/// `raytrace SCENE ARGS -o OUT` in `dir`: its standard error.
fn raytrace_ok(dir: &Path, args: &[&str], out: &str) -> String {
    let o = raytrace()
        .current_dir(dir)
        .arg("scene.txt")
        .args(args)
        .args(["-o", out])
        .output()
        .unwrap();
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    String::from_utf8_lossy(&o.stderr).into_owned()
}

#[test]
fn raytrace_adaptive_is_the_same_on_one_and_two_threads_and_differs_from_the_grid() {
    let dir = tempfile::tempdir().unwrap();
    write_scene(dir.path());
    let d = dir.path();
    let one = raytrace_ok(d, &["--aa", "adaptive:0.4:2", "--threads", "1"], "one.png");
    raytrace_ok(
        d,
        &["--aa", "adaptive:0.4:2:edge", "--threads", "2"],
        "two.png",
    );
    raytrace_ok(d, &["--aa", "adaptive", "--threads", "2"], "default.png");
    raytrace_ok(d, &[], "plain.png");
    let (a, b) = (pixels(&d.join("one.png")), pixels(&d.join("two.png")));
    assert_eq!(a, b);
    assert_eq!(a, pixels(&d.join("default.png")));
    assert_ne!(a, pixels(&d.join("plain.png")));
    assert!(one.contains("adaptive 0.4 depth 2 edge"), "{one}");
    // POV-Ray's measure at the same threshold draws other pixels.
    raytrace_ok(d, &["--aa", "adaptive:0.4:2:sum"], "sum.png");
    assert_ne!(a, pixels(&d.join("sum.png")));
    // Depth 0 casts exactly the (64+1)·(48+1) corner rays.
    let corners = raytrace_ok(d, &["--aa", "adaptive:0.1:0"], "corners.png");
    assert_ne!(a, pixels(&d.join("corners.png")));
    assert!(
        corners.contains(&format!(
            "{:.3} camera rays/px",
            65.0 * 49.0 / (64.0 * 48.0)
        )),
        "{corners}"
    );
}

#[test]
fn raytrace_refuses_bad_adaptive_settings() {
    let dir = tempfile::tempdir().unwrap();
    write_scene(dir.path());
    for (args, says) in [
        (&["--aa", "adaptive:5"][..], "threshold must be"),
        (&["--aa", "adaptive:0.1:9"], "depth must be"),
        (&["--aa", "grid"], "expected adaptive"),
        (
            &["--aa", "adaptive", "--samples", "2"],
            "cannot be used with",
        ),
    ] {
        let o = raytrace()
            .current_dir(dir.path())
            .arg("scene.txt")
            .args(args)
            .args(["-o", "x.png"])
            .output()
            .unwrap();
        assert_eq!(o.status.code(), Some(2), "{args:?}");
        let err = String::from_utf8_lossy(&o.stderr);
        assert!(err.contains(says), "{args:?}: {err}");
        assert!(!dir.path().join("x.png").exists());
    }
}

#[test]
fn animate_adaptive_frames_are_the_same_whole_sharded_and_threaded() {
    let (dir, manifest) = project(&circle_manifest(AA));
    let full = dir.path().join("full");
    render_into(&manifest, &full, &["--threads", "1"]);
    let farm = dir.path().join("farm");
    for k in 0..3 {
        let shard = format!("{k}/3");
        render_into(&manifest, &farm, &["--shard", &shard, "--threads", "2"]);
    }
    assert_eq!(files(&farm), files(&full));
    // Grid frames differ from adaptive ones.
    let grid = dir.path().join("grid");
    std::fs::write(&manifest, circle_manifest("")).unwrap();
    render_into(&manifest, &grid, &[]);
    assert_ne!(files(&grid), files(&full));
}

/// `animate status MANIFEST -o OUT`: its exit status.
fn status(manifest: &Path, out: &Path) -> Option<i32> {
    let o = animate()
        .arg("status")
        .arg(manifest)
        .arg("-o")
        .arg(out)
        .output()
        .unwrap();
    o.status.code()
}

#[test]
fn the_settings_are_part_of_the_digest() {
    let (dir, manifest) = project(&circle_manifest(AA));
    let out = dir.path().join("out");
    render_into(&manifest, &out, &[]);
    assert_eq!(status(&manifest, &out), Some(0));
    let stamp =
        String::from_utf8_lossy(&std::fs::read(out.join("frame_0000.png")).unwrap()).into_owned();
    assert!(stamp.contains("adaptive anti-aliasing threshold 0.1 depth 3 measure edge"));
    for other in [
        AA.replace("threshold = 0.1", "threshold = 0.2"),
        AA.replace("depth = 3", "depth = 2"),
        String::new(),
    ] {
        std::fs::write(&manifest, circle_manifest(&other)).unwrap();
        assert_eq!(status(&manifest, &out), Some(1), "{other}");
    }
    // A resumed run after a change redraws the frames as a fresh run would.
    std::fs::write(
        &manifest,
        circle_manifest(&AA.replace("depth = 3", "depth = 2")),
    )
    .unwrap();
    render_into(&manifest, &out, &["--resume"]);
    assert_eq!(status(&manifest, &out), Some(0));
    let fresh = dir.path().join("fresh");
    render_into(&manifest, &fresh, &[]);
    assert_eq!(files(&out), files(&fresh));
}

#[test]
fn check_and_motion_blur_render_adaptively() {
    let blur = format!("{AA}motion_blur = {{ shutter = 0.5, samples = 2 }}\n");
    let check = "[check]\nframes = [0, 5]\nreferences = \"refs\"\n";
    let (dir, manifest) = project(&circle_manifest(&format!("{blur}{check}")));
    animate().arg("bless").arg(&manifest).assert().success();
    let (code, out, err) = support::check(&manifest, &[]);
    assert_eq!(code, Some(0), "{out}{err}");
    // The blessed frame is a motion-blurred adaptive one: unlike the unblurred frame.
    let still = dir.path().join("still");
    std::fs::write(&manifest, circle_manifest(AA)).unwrap();
    render_into(&manifest, &still, &["--frames", "0"]);
    assert_ne!(
        pixels(&dir.path().join("refs/frame_0000.png")),
        pixels(&still.join("frame_0000.png"))
    );
}

#[test]
fn manifest_refusals_are_located() {
    let bad = AA.replace("threshold = 0.1", "threshold = -1.0");
    let (_dir, manifest) = project(&circle_manifest(&bad));
    let o = animate().arg(&manifest).output().unwrap();
    assert_eq!(o.status.code(), Some(2));
    let err = String::from_utf8_lossy(&o.stderr);
    assert!(
        err.contains("anim.toml:18:") && err.contains("threshold must be"),
        "{err}"
    );
}
