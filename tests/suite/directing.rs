//! Directing a camera, through `animate`: a spline key's `ease` paces the segment it
//! starts (frame 5 of keys 0 → 10 eased "in" is frame 2.5 of the even path, which is
//! frame 5 of the same keys at 0 → 20), and is refused, located, where the path is timed
//! by arc length; a key's `time = "2s"` (camera or track) is the frame `fps` makes of it,
//! the nearest, and a bad one is refused at its place.

use crate::support;

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

#[test]
fn a_camera_key_eases_its_segment() {
    let dir = eye_folder();
    let d = dir.path();
    // Eased in: u = 5/10 → e = 0.25 = 5/20 of the even path over 0 → 20.
    let eased = frame_of(d, "in", &spline(11, 10, ", ease = \"in\"", ""), 5);
    let even = frame_of(d, "even", &spline(21, 20, "", ""), 5);
    assert!(
        eased == even,
        "ease in at frame 5 is not the even path at u = 0.25"
    );
    let half = frame_of(d, "half", &spline(21, 20, "", ""), 10);
    assert!(eased != half, "the ease changed nothing");
    // Eased out: 1 − (1 − 0.5)² = 0.75 = 15/20.
    let out = frame_of(d, "out", &spline(11, 10, ", ease = \"out\"", ""), 5);
    assert!(out == frame_of(d, "even15", &spline(21, 20, "", ""), 15));
    // The keys' own frames are kept: frame 10 is the last key's position either way.
    let end = frame_of(d, "in10", &spline(11, 10, ", ease = \"in\"", ""), 10);
    assert!(end == frame_of(d, "even20", &spline(21, 20, "", ""), 20));
}

#[test]
fn ease_with_constant_speed_is_refused_at_its_key() {
    let dir = eye_folder();
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

#[test]
fn keys_in_seconds_are_the_frames_fps_makes_of_them() {
    let dir = eye_folder();
    let d = dir.path();
    // A spline key at "2s" at 5 fps is frame 10; at 10 fps "1s" is frame 10 too.
    let frames = spline(11, 10, "", "");
    let at_5fps = frames.replace("frames = 11", "frames = 11\nfps = 5");
    let seconds = at_5fps.replace("frame = 10,", "time = \"2s\",");
    assert!(seconds.contains("time = \"2s\""));
    let want = frame_of(d, "frames", &frames, 5);
    assert!(frame_of(d, "seconds", &seconds, 5) == want);
    let at_10fps = seconds
        .replace("fps = 5", "fps = 10")
        .replace("\"2s\"", "\"1s\"");
    assert!(frame_of(d, "seconds10", &at_10fps, 5) == want);
    // A track key at "0.75s" at 4 fps is frame 3 (round(3.0)); "0.625s" is 2.5: frame 3.
    let track = |when: &str| {
        format!(
            "scene = \"scene.txt\"\nframes = 6\nfps = 4\n\n[[track]]\ntarget = \"sphere 1 radius\"\n\
             keys = [{{ frame = 0, value = 1.0 }}, {{ {when}, value = 1.6 }}]\n\n\
             [output]\ndir = \"out\"\n"
        )
    };
    let want = frame_of(d, "t-frames", &track("frame = 3"), 2);
    assert!(frame_of(d, "t-seconds", &track("time = \"0.75s\""), 2) == want);
    assert!(frame_of(d, "t-half", &track("time = \"0.625s\""), 2) == want);
    assert!(frame_of(d, "t-earlier", &track("frame = 2"), 2) != want);
}

#[test]
fn bad_times_are_refused_where_they_are() {
    let dir = eye_folder();
    let m = dir.path().join("m.toml");
    let base = spline(11, 10, "", "").replace("frames = 11", "frames = 11\nfps = 10");
    for (edit, want) in [
        (
            "frame = 10, time = \"1s\",",
            "m.toml:9:24: a key gives `frame` or `time`, not both",
        ),
        (
            "time = \"1.5\",",
            "m.toml:9:12: expected a time in seconds such as \"2.5s\" (at least 0), found \"1.5\"",
        ),
        (
            "time = \"9s\",",
            "m.toml:9:12: key time 9s is frame 90 at 10 fps, outside the sequence: frames run from 0 to 10",
        ),
        (
            "",
            "m.toml:9:3: a key needs `frame = N` or `time = \"2.5s\"` (seconds)",
        ),
    ] {
        let text = base.replace("frame = 10,", edit);
        std::fs::write(&m, &text).unwrap();
        let out = animate().arg(&m).output().unwrap();
        assert_eq!(out.status.code(), Some(2), "{text}");
        let err = String::from_utf8_lossy(&out.stderr);
        assert!(err.contains(want), "{want}\n{err}");
    }
}
