//! Directing a camera, through `animate`: a spline key's `ease` paces the segment it
//! starts (frame 5 of keys 0 → 10 eased "in" is frame 2.5 of the even path, which is
//! frame 5 of the same keys at 0 → 20), and is refused, located, where the path is timed
//! by arc length.

use crate::support;

use std::path::Path;
use support::*;

/// A spline manifest over `scene.txt`: two keys at frames 0 and `end`, the first with
/// `first` appended, `extra` added to `[camera]`.
fn spline(frames: u32, end: u32, first: &str, extra: &str) -> String {
    format!(
        "scene = \"scene.txt\"\nframes = {frames}\n\n[camera]\npath = \"spline\"\n{extra}\
         keys = [\n  {{ frame = 0, position = [0.0, 3.0, 8.0]{first} }},\n  \
         {{ frame = {end}, position = [8.0, 2.0, 0.0] }},\n]\n\n[output]\ndir = \"out\"\n"
    )
}

/// Frame `frame` of `manifest` (written into `dir` as `name.toml`), as pixels.
fn frame(dir: &Path, name: &str, manifest: &str, frame: u32) -> Vec<u8> {
    let path = dir.join(format!("{name}.toml"));
    std::fs::write(&path, manifest).unwrap();
    let out = dir.join(name);
    animate()
        .arg(&path)
        .args(["--frames", &frame.to_string(), "-q", "-o"])
        .arg(&out)
        .assert()
        .success();
    pixels(&out.join(format!("frame_{frame:04}.png")))
}

#[test]
fn a_camera_key_eases_its_segment() {
    let dir = tempfile::tempdir().unwrap();
    std::fs::write(
        dir.path().join("scene.txt"),
        scene_with_eye([0.0, 3.0, 8.0]),
    )
    .unwrap();
    let d = dir.path();
    // Eased in: u = 5/10 → e = 0.25 = 5/20 of the even path over 0 → 20.
    let eased = frame(d, "in", &spline(11, 10, ", ease = \"in\"", ""), 5);
    let even = frame(d, "even", &spline(21, 20, "", ""), 5);
    assert!(
        eased == even,
        "ease in at frame 5 is not the even path at u = 0.25"
    );
    let half = frame(d, "half", &spline(21, 20, "", ""), 10);
    assert!(eased != half, "the ease changed nothing");
    // Eased out: 1 − (1 − 0.5)² = 0.75 = 15/20.
    let out = frame(d, "out", &spline(11, 10, ", ease = \"out\"", ""), 5);
    assert!(out == frame(d, "even15", &spline(21, 20, "", ""), 15));
    // The keys' own frames are kept: frame 10 is the last key's position either way.
    let end = frame(d, "in10", &spline(11, 10, ", ease = \"in\"", ""), 10);
    assert!(end == frame(d, "even20", &spline(21, 20, "", ""), 20));
}

#[test]
fn ease_with_constant_speed_is_refused_at_its_key() {
    let dir = tempfile::tempdir().unwrap();
    std::fs::write(
        dir.path().join("scene.txt"),
        scene_with_eye([0.0, 3.0, 8.0]),
    )
    .unwrap();
    let m = dir.path().join("m.toml");
    let text = spline(11, 10, ", ease = \"in\"", "constant_speed = true\n");
    std::fs::write(&m, &text).unwrap();
    let out = animate().arg(&m).output().unwrap();
    assert_eq!(out.status.code(), Some(2));
    let err = String::from_utf8_lossy(&out.stderr);
    // The first key is on line 8, from column 3.
    assert!(err.contains("m.toml:8:3:"), "{err}");
    assert!(
        err.contains("camera.keys[0]: `ease` paces the segment"),
        "{err}"
    );
    let text = spline(11, 10, ", ease = \"sideways\"", "");
    std::fs::write(&m, &text).unwrap();
    let out = animate().arg(&m).output().unwrap();
    assert_eq!(out.status.code(), Some(2));
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(
        err.contains("unknown ease `sideways`, expected one of none, in, out, in-out"),
        "{err}"
    );
}
