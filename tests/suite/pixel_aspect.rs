//! A scene whose resolution is not of the report's view plane's shape
//! draws non-square pixels; both commands warn once, naming the fixes, and stay silent
//! on the report's own 4:3 and on square framings.

use crate::support::{animate, circle_manifest, raytrace, SCENE};

/// The support scene at `w`×`h` (its first line), written into `dir`.
fn scene_at(dir: &std::path::Path, w: u32, h: u32) -> std::path::PathBuf {
    let text = SCENE.replacen("64 48", &format!("{w} {h}"), 1);
    let text = text.replace("{EYE}", "0 2 8");
    let path = dir.join("scene.txt");
    std::fs::write(&path, text).unwrap();
    path
}

fn stderr(cmd: &mut assert_cmd::Command) -> String {
    let out = cmd.output().unwrap();
    assert!(out.status.success(), "{out:?}");
    String::from_utf8(out.stderr).unwrap()
}

#[test]
fn raytrace_warns_once_on_sixteen_by_nine_and_names_both_fixes() {
    let dir = tempfile::tempdir().unwrap();
    let scene = scene_at(dir.path(), 64, 36);
    let err = stderr(
        raytrace()
            .arg(&scene)
            .arg("-o")
            .arg(dir.path().join("a.png")),
    );
    assert_eq!(err.matches("not square").count(), 1, "{err}");
    // (0.5/64) / (0.35/36) = 0.8036; a square view is 0.35·64/36 = 0.6222 wide.
    assert!(err.contains("0.804") && err.contains("0.6222"), "{err}");
    assert!(
        err.contains("--fov 19.85") && err.contains("[camera] fov = 19.85"),
        "{err}"
    );
    // The fix it names silences it.
    let fixed = raytrace()
        .arg(&scene)
        .args(["--fov", "19.85", "-o"])
        .arg(dir.path().join("b.png"))
        .output()
        .unwrap();
    assert!(!String::from_utf8_lossy(&fixed.stderr).contains("not square"));
}

#[test]
fn the_reports_shape_and_another_size_are_silent() {
    let dir = tempfile::tempdir().unwrap();
    let scene = scene_at(dir.path(), 64, 48);
    let err = stderr(
        raytrace()
            .arg(&scene)
            .arg("-o")
            .arg(dir.path().join("a.png")),
    );
    assert!(!err.contains("not square"), "{err}");
    // A size of another shape than the file's: the plane follows it with square pixels.
    let scene = scene_at(dir.path(), 64, 36);
    let resized = raytrace()
        .arg(&scene)
        .args(["--size", "96x72", "-o"])
        .arg(dir.path().join("b.png"))
        .output()
        .unwrap();
    assert!(!String::from_utf8_lossy(&resized.stderr).contains("not square"));
}

#[test]
fn animate_warns_too_and_a_manifest_fov_silences_it() {
    let dir = tempfile::tempdir().unwrap();
    scene_at(dir.path(), 64, 36);
    let manifest = dir.path().join("a.toml");
    let text = circle_manifest("").replace("frames = 12", "frames = 1");
    std::fs::write(&manifest, &text).unwrap();
    let err = stderr(animate().arg(&manifest));
    assert_eq!(err.matches("not square").count(), 1, "{err}");
    let with_fov = text.replace("turns = 1.0", "turns = 1.0\nfov = 19.85");
    std::fs::write(&manifest, with_fov).unwrap();
    let err = stderr(animate().arg(&manifest).arg("--force"));
    assert!(!err.contains("not square"), "{err}");
}
