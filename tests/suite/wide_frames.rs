//! Frames of another shape than the scene file's are not stretched: `raytrace --size`
//! and `[render] width/height` keep the view's height and give square pixels, so a
//! sphere's silhouette is as wide as it is tall; `fov` and `roll` frame the view.

use crate::support;

use std::path::Path;
use support::*;

/// The orbit's camera (640×480, eye (0, 3, 12) looking at (0, 1, 0)), no fog, one matte
/// sphere of radius 0.6 on the point looked at and one at `other` (ambient only: every
/// sphere pixel is coloured, the rest black).
fn scene(other: [f64; 3]) -> String {
    let [x, y, z] = other;
    format!(
        "640 480\n0 3 12\n0 1 0\n0 0\n2 0 0 0\n\
         0.6 0 1 0  1 1 1 1  1 0 0 1 0 0\n\
         0.3 {x} {y} {z}  1 1 0 1  1 0 0 1 0 0\n"
    )
}

/// The bounding box (x0, y0, x1, y1), inclusive, of the pixels where `select` holds.
fn bbox(path: &Path, select: impl Fn(&[u8]) -> bool) -> (u32, u32, u32, u32) {
    let img = image::open(path).unwrap().to_rgb8();
    let mut b = (u32::MAX, u32::MAX, 0, 0);
    for (x, y, p) in img.enumerate_pixels() {
        if select(&p.0) {
            b = (b.0.min(x), b.1.min(y), b.2.max(x), b.3.max(y));
        }
    }
    assert!(b.0 <= b.2, "nothing selected in {}", path.display());
    b
}

/// The white sphere on the point looked at.
fn white(p: &[u8]) -> bool {
    p[0] > 20 && p[1] > 20
}

/// Width and height in pixels of a box.
fn size(b: (u32, u32, u32, u32)) -> (i64, i64) {
    (i64::from(b.2 - b.0 + 1), i64::from(b.3 - b.1 + 1))
}

#[test]
fn raytrace_size_1920x1080_draws_round_spheres() {
    let dir = tempfile::tempdir().unwrap();
    let s = dir.path().join("s.txt");
    std::fs::write(&s, scene([40.0, 1.0, -40.0])).unwrap();
    let out = dir.path().join("hd.png");
    raytrace()
        .arg(&s)
        .args(["--size", "1920x1080", "-o"])
        .arg(&out)
        .assert()
        .success();
    let (w, h) = size(bbox(&out, white));
    // Before: the 0.5 × 0.35 plane stretched over 16:9 made it 1.24 times wider than tall.
    assert!((w - h).abs() <= 1, "sphere is {w}×{h} pixels");
    // Its height is the report's: 0.35 of plane over 1080 rows. The silhouette of a
    // sphere of radius r at distance d, centred, is 2·tan(asin(r/d)) high on the plane:
    // d = √(2² + 12²) = 12.1655, asin(0.6/d) = 0.049340, tan = 0.049380, so
    // 2·0.049380/0.35·1080 = 304.7 pixels.
    assert!((h - 305).abs() <= 1, "sphere is {h} pixels high");
}

#[test]
fn the_scene_shape_keeps_the_report_view_at_any_scale() {
    // 160×120 is the scene's 4:3: the report's picture, scaled (tests/golden relies on
    // it); a 4:3 sphere is 1.07 times taller than wide there, as in the report.
    let dir = tempfile::tempdir().unwrap();
    let s = dir.path().join("s.txt");
    std::fs::write(&s, scene([40.0, 1.0, -40.0])).unwrap();
    let small = dir.path().join("small.png");
    raytrace()
        .arg(&s)
        .args(["--size", "320x240", "-o"])
        .arg(&small)
        .assert()
        .success();
    let (w, h) = size(bbox(&small, white));
    // 2·0.049380 of plane: 0.5 wide over 320 columns = 63.2, 0.35 high over 240 = 67.7.
    assert!((w - 63).abs() <= 1 && (h - 68).abs() <= 1, "{w}×{h}");
}

#[test]
fn fov_sets_the_vertical_view_and_roll_turns_the_picture() {
    let dir = tempfile::tempdir().unwrap();
    let s = dir.path().join("s.txt");
    // The small magenta sphere to the right of the point looked at (+x is right).
    std::fs::write(&s, scene([2.0, 1.0, 0.0])).unwrap();
    let out = dir.path().join("fov.png");
    raytrace()
        .arg(&s)
        .args(["--size", "400x300", "--fov", "20", "-o"])
        .arg(&out)
        .assert()
        .success();
    // fov 20°: the plane is 2·tan(10°) = 0.352654 high; 2·0.049380/0.352654·300 = 84.0.
    let (w, h) = size(bbox(&out, white));
    assert!((h - 84).abs() <= 1 && (w - h).abs() <= 1, "{w}×{h}");
    let magenta = |p: &[u8]| p[0] > 20 && p[1] < 10 && p[2] > 20;
    let m = bbox(&out, magenta);
    assert!(
        m.0 > 250,
        "unrolled, the magenta sphere is on the right: {m:?}"
    );
    // Rolled 90° (banking right), what was on the right is at the top.
    let rolled = dir.path().join("roll.png");
    raytrace()
        .arg(&s)
        .args(["--size", "400x300", "--fov", "20", "--roll", "90", "-o"])
        .arg(&rolled)
        .assert()
        .success();
    let m = bbox(&rolled, magenta);
    assert!(m.3 < 120 && m.0 > 150 && m.2 < 250, "rolled: {m:?}");
}

#[test]
fn a_manifest_1920x1080_of_the_orbit_draws_round_spheres_and_fov_is_a_camera_key() {
    let dir = tempfile::tempdir().unwrap();
    std::fs::write(dir.path().join("s.txt"), scene([40.0, 1.0, -40.0])).unwrap();
    let manifest = |camera: &str| {
        format!(
            "scene = \"s.txt\"\nframes = 250\n[camera]\npath = \"circle\"\n\
             center = [0.0, 1.0, 0.0]\nradius = 12.0\nheight = 3.0\n{camera}\n\
             [render]\nwidth = 1920\nheight = 1080\n"
        )
    };
    let path = dir.path().join("hd.toml");
    std::fs::write(&path, manifest("")).unwrap();
    render_into(&path, &dir.path().join("hd"), &["--frames", "0,62"]);
    for frame in ["frame_0000.png", "frame_0062.png"] {
        let (w, h) = size(bbox(&dir.path().join("hd").join(frame), white));
        assert!(
            (w - h).abs() <= 1 && (h - 305).abs() <= 1,
            "{frame}: {w}×{h}"
        );
    }
    // fov = 20: 2·0.049380/0.352654·1080 = 302.4 pixels high.
    std::fs::write(&path, manifest("fov = 20.0\nroll = 0.0")).unwrap();
    render_into(&path, &dir.path().join("fov"), &["--frames", "0"]);
    let (w, h) = size(bbox(&dir.path().join("fov/frame_0000.png"), white));
    assert!(
        (w - h).abs() <= 1 && (h - 302).abs() <= 1,
        "fov 20: {w}×{h}"
    );
    // Out of range: refused at the value.
    std::fs::write(&path, manifest("fov = 180.0")).unwrap();
    let out = animate().arg(&path).output().unwrap();
    assert_eq!(out.status.code(), Some(2));
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(
        err.contains("hd.toml:8:7") && err.contains("`fov`"),
        "{err}"
    );
}

#[test]
fn a_record_of_the_stretched_view_is_stale_and_the_report_view_keeps_its_digest() {
    // The view is part of a frame's record when it is not the report's, so 16:9 frames
    // drawn before this change are re-rendered by --resume; 4:3 frames are not.
    let dir = tempfile::tempdir().unwrap();
    std::fs::write(dir.path().join("s.txt"), scene([40.0, 1.0, -40.0])).unwrap();
    let base = "scene = \"s.txt\"\nframes = 2\n";
    let path = dir.path().join("a.toml");
    std::fs::write(&path, format!("{base}[camera]\nroll = 0.0\n")).unwrap();
    render_into(&path, &dir.path().join("f"), &[]);
    std::fs::write(&path, format!("{base}[camera]\nroll = 5.0\n")).unwrap();
    let out = animate()
        .args(["status"])
        .arg(&path)
        .arg("-o")
        .arg(dir.path().join("f"))
        .output()
        .unwrap();
    assert_eq!(
        out.status.code(),
        Some(1),
        "a roll makes the frames stale: {out:?}"
    );
    // The report's view has no field of view and no roll (`fov` has no value that is the
    // report's plane): frames drawn with no [camera] keep their digest when the manifest
    // spells the default roll out.
    std::fs::write(&path, base).unwrap();
    render_into(&path, &dir.path().join("g"), &[]);
    std::fs::write(&path, format!("{base}[camera]\nroll = 0.0\n")).unwrap();
    let out = animate()
        .args(["status"])
        .arg(&path)
        .arg("-o")
        .arg(dir.path().join("g"))
        .output()
        .unwrap();
    assert_eq!(
        out.status.code(),
        Some(0),
        "roll = 0.0 is the report's view, the frames are up to date: {out:?}"
    );
}
