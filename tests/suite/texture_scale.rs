//! `texture_scale`, through `animate`: the support scene's world made twice as large
//! (every point, radius, light and the fog's distance doubled: exact in binary) with its
//! wood and checker textures at `texture_scale` 2 is the original picture, byte for
//! byte; scale 1 is the file's own picture; a one-colour object is refused at the track.

use crate::support;

use support::*;

/// The support scene (eye at (0, 3, 8)) with everything doubled.
const DOUBLED: &str = "\
64 48
0 6 16
0 2 0
2 80
3 1 1 2
2.0  -2.6 2 0   1 0.9 0.9 0.9                                0.1 0.9 0 1 0 0
1.8   2.4 1.8 1.0   1 1 1 1                                0.1 0 0.9 1.5 0 0
1.2   0 1.2 -3.0   2 3 0.6 0.4 0.2 0.3 0.15 0.05 0 0 0     0.8 0 0 1 0 0
0 0 0  0 1 0   2 1 1 1 1 0.1 0.1 0.1 0 0 0                 0.9 0 0 1 0 0
0 1 0  -4 0 -4  0.6   1 0.2 0.5 0.8                        0.7 0 0 1 0 0
10 20 10  1 1 1  0.9
-12 16 8  0.6 0.6 0.8  0.6
";

/// A one-frame manifest over `scene_file` with `tracks` appended.
fn manifest(scene_file: &str, tracks: &str) -> String {
    format!("scene = \"{scene_file}\"\nframes = 1\n{tracks}")
}

/// A track holding `target` at `value`.
fn held(target: &str, value: f64) -> String {
    format!("\n[[track]]\ntarget = \"{target}\"\nkeys = [{{ frame = 0, value = {value:?} }}]\n")
}

#[test]
fn a_world_twice_as_large_with_patterns_at_scale_two_is_the_same_picture() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    std::fs::write(d.join("scene.txt"), scene_with_eye([0.0, 3.0, 8.0])).unwrap();
    std::fs::write(d.join("doubled.txt"), DOUBLED).unwrap();
    let original = frame_of(d, "original", &manifest("scene.txt", ""), 0);
    // Sphere 3 is wood, plane 1 the checker floor.
    let both = held("sphere 3 texture_scale", 2.0) + &held("plane 1 texture_scale", 2.0);
    let scaled = frame_of(d, "scaled", &manifest("doubled.txt", &both), 0);
    assert!(
        scaled == original,
        "the doubled world at scale 2 is another picture"
    );
    let unscaled = frame_of(d, "unscaled", &manifest("doubled.txt", ""), 0);
    assert!(unscaled != original, "doubling the world changed nothing");
    // Scale 1 is the file's own texture.
    let one = held("sphere 3 texture_scale", 1.0);
    assert!(frame_of(d, "one", &manifest("scene.txt", &one), 0) == original);
}

#[test]
fn a_scale_of_a_one_colour_texture_or_below_zero_is_refused_at_the_track() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    std::fs::write(d.join("scene.txt"), scene_with_eye([0.0, 3.0, 8.0])).unwrap();
    for (n, (track, why, at)) in [
        (
            held("sphere 1 texture_scale", 2.0),
            "no pattern to scale",
            "m0.toml:5:",
        ),
        (
            held("sphere 3 texture_scale", -1.0),
            "greater than 0",
            "m1.toml:6:",
        ),
    ]
    .into_iter()
    .enumerate()
    {
        let path = d.join(format!("m{n}.toml"));
        std::fs::write(&path, manifest("scene.txt", &track)).unwrap();
        let out = animate().arg(&path).output().unwrap();
        let err = String::from_utf8_lossy(&out.stderr);
        assert_eq!(out.status.code(), Some(2), "{err}");
        assert!(
            err.contains(why) && err.contains(at),
            "{why:?} at {at} not in {err}"
        );
    }
}

#[test]
fn a_new_scale_makes_the_frame_stale() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    std::fs::write(d.join("scene.txt"), scene_with_eye([0.0, 3.0, 8.0])).unwrap();
    let path = d.join("m.toml");
    let status = |scale: f64| {
        let text = manifest("scene.txt", &held("sphere 3 texture_scale", scale));
        std::fs::write(&path, text + "[output]\ndir = \"out\"\n").unwrap();
        let out = animate().arg("status").arg(&path).output().unwrap();
        out.status.code()
    };
    status(2.0);
    animate().arg(&path).arg("-q").assert().success();
    assert_eq!(status(2.0), Some(0), "rendered at 2: up to date");
    assert_eq!(status(3.0), Some(1), "a scale of 3: stale");
    assert_eq!(status(1.0), Some(1), "a scale of 1 (no scale): stale");
}
