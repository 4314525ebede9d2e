//! The camera as a track's target, through `animate`: `camera position`, `camera look_at`
//! and `camera fov` tracks give, at a frame between two keys, exactly the picture of a
//! still camera placed at the interpolated value; beside a `[camera]` that already gives
//! the value (a path's positions, a `look_at`, a `fov`) a track is refused at its line,
//! and a `look_at` track moves what a spline path without look-at points looks at.

use crate::support;

use support::*;

/// A 5-frame manifest over `scene.txt`: `camera` as its `[camera]` table's lines (none
/// when empty), then one track of `target` from `a` at frame 0 to `b` at frame 4.
fn tracked(camera: &str, target: &str, a: &str, b: &str) -> String {
    let table = match camera {
        "" => String::new(),
        c => format!("[camera]\n{c}\n"),
    };
    format!(
        "scene = \"scene.txt\"\nframes = 5\n{table}\n[[track]]\ntarget = \"{target}\"\n\
         keys = [{{ frame = 0, value = {a} }}, {{ frame = 4, value = {b} }}]\n"
    )
}

/// A one-frame manifest over `scene_file` with `camera` as its `[camera]` lines.
fn still(scene_file: &str, camera: &str) -> String {
    format!("scene = \"{scene_file}\"\nframes = 1\n[camera]\n{camera}\n")
}

#[test]
fn a_camera_position_track_is_the_still_camera_at_its_value() {
    let dir = eye_folder();
    let d = dir.path();
    let m = tracked("", "camera position", "[0.0, 3.0, 8.0]", "[8.0, 3.0, 0.0]");
    let tracked = frame_of(d, "tracked", &m, 2);
    // Half-way: (4, 3, 4), exactly.
    std::fs::write(d.join("at.txt"), scene_with_eye([4.0, 3.0, 4.0])).unwrap();
    let by_hand = frame_of(d, "still", &still("at.txt", ""), 0);
    assert!(tracked == by_hand, "frame 2 is not the camera at (4, 3, 4)");
    let start = frame_of(d, "tracked0", &m, 0);
    assert!(start != tracked, "the track moved nothing");
}

#[test]
fn a_look_at_track_and_a_fov_track_are_the_table_values_at_that_frame() {
    let dir = eye_folder();
    let d = dir.path();
    let m = tracked("", "camera look_at", "[0.0, 1.0, 0.0]", "[2.0, 1.0, 0.0]");
    let by_hand = frame_of(
        d,
        "look",
        &still("scene.txt", "look_at = [1.0, 1.0, 0.0]"),
        0,
    );
    assert!(frame_of(d, "look_track", &m, 2) == by_hand);
    let m = tracked("", "camera fov", "30.0", "50.0");
    let by_hand = frame_of(d, "fov", &still("scene.txt", "fov = 40.0"), 0);
    assert!(frame_of(d, "fov_track", &m, 2) == by_hand);
    assert!(
        frame_of(d, "fov_track0", &m, 0) != by_hand,
        "the fov changed nothing"
    );
}

#[test]
fn a_look_at_track_steers_a_spline_path_without_look_at_points() {
    let dir = eye_folder();
    let d = dir.path();
    let path = "path = \"spline\"\nkeys = [{ frame = 0, position = [0.0, 3.0, 8.0] }, \
                { frame = 4, position = [8.0, 3.0, 0.0] }]";
    let m = tracked(path, "camera look_at", "[0.0, 1.0, 0.0]", "[2.0, 1.0, 0.0]");
    let with_point = format!("{path}\nlook_at = [1.0, 1.0, 0.0]");
    let by_hand = tracked(&with_point, "sphere 1 kd", "0.1", "0.1");
    assert!(frame_of(d, "spline_track", &m, 2) == frame_of(d, "spline_point", &by_hand, 2));
}

#[test]
fn a_track_beside_what_the_camera_table_gives_is_refused_at_its_line() {
    let dir = eye_folder();
    let circle = "path = \"circle\"\ncenter = [0.0, 1.0, 0.0]\nradius = 8.0\nheight = 3.0";
    let cases = [
        (
            tracked(
                circle,
                "camera position",
                "[0.0, 3.0, 8.0]",
                "[8.0, 3.0, 0.0]",
            ),
            "the camera's position is the `[camera] path = \"circle\"`'s",
        ),
        (
            tracked(
                circle,
                "camera look_at",
                "[0.0, 1.0, 0.0]",
                "[2.0, 1.0, 0.0]",
            ),
            "looks at its centre",
        ),
        (
            tracked(
                "look_at = \"sphere 1\"",
                "camera look_at",
                "[0.0, 1.0, 0.0]",
                "[1.0, 1.0, 0.0]",
            ),
            "`[camera] look_at` already says",
        ),
        (
            tracked("fov = 40.0", "camera fov", "30.0", "50.0"),
            "`[camera] fov` already gives",
        ),
        (
            tracked("", "camera fov", "30.0", "180.0"),
            "the fov is the vertical field of view",
        ),
        (
            tracked("", "camera zoom", "30.0", "50.0"),
            "the camera has no field `zoom`",
        ),
    ];
    for (n, (manifest, why)) in cases.iter().enumerate() {
        let path = dir.path().join(format!("m{n}.toml"));
        std::fs::write(&path, manifest).unwrap();
        let out = animate().arg(&path).arg("-q").output().unwrap();
        let err = String::from_utf8_lossy(&out.stderr);
        assert_eq!(out.status.code(), Some(2), "{manifest}\n{err}");
        assert!(err.contains(why), "{why:?} not in {err}");
        // Located in the manifest, at the track (its table's or a key's line).
        let track_line = manifest.lines().position(|l| l == "[[track]]").unwrap() + 1;
        let line: usize = err
            .split(&format!("m{n}.toml:"))
            .nth(1)
            .and_then(|rest| rest.split(':').next())
            .and_then(|l| l.parse().ok())
            .unwrap_or_else(|| panic!("no location in {err}"));
        assert!(line >= track_line, "{err}");
        assert!(!out.status.success() && !dir.path().join(format!("m{n}-frames")).exists());
    }
}
