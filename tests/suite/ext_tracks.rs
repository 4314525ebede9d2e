//! Tracks on the extension's records end to end: a tracked frame is the image `raytrace`
//! draws of the Scene.txt with that frame's value written into the record by hand (shapes,
//! a named object's frame, lights, their fade); a record pushed out of its bounds is
//! refused at the track's line with the frame, exit 2, before any frame is drawn.

use crate::support::*;

/// The report's part (one sphere, a floor, one light) and extension records.
const SCENE: &str = "96 72
0 3 8
0 1 0
0 0
1 1 0 1
0.6  0 2.6 0   1 0.9 0.9 0.9   0.7 0 0 1 0 0
0 0 0  0 1 0   2 1  0.9 0.9 0.9  0.4 0.4 0.4  0 0 0   0.8 0 0 1 0 0
6 8 6  1 1 1  0.5
box -2.5 0 -0.5  -1.5 1 0.5   1 0.8 0.2 0.2  0.7 0 0 1 0 0  name crate
torus 0 0.4 0  0 1 0  1 0.25   1 0.2 0.8 0.2  0.6 0 0 1 0 0
cone 2 0 0 0.6  2 1.5 0 0.1   1 0.2 0.3 0.9  0.6 0 0 1 0 0
spot -3 6 4  0 0 0  1 1 1 0.6  10 20 1  fade 8 2
area 3 6 3  1 0 0  0 0 1  2 2  1 1 1 0.4
";

/// Frame 1 of a 3-frame manifest whose track runs linearly from `a` (frame 0) to `b`
/// (frame 2), and the still of the scene with `from` replaced by `to`.
fn frame_and_still(target: &str, a: &str, b: &str, from: &str, to: &str) -> (Vec<u8>, Vec<u8>) {
    let dir = tempfile::tempdir().unwrap();
    std::fs::write(dir.path().join("scene.txt"), SCENE).unwrap();
    let manifest = dir.path().join("anim.toml");
    let text = format!(
        "scene = \"scene.txt\"\nframes = 3\n[output]\ndir = \"frames\"\n[[track]]\ntarget = \"{target}\"\nkeys = [{{ frame = 0, value = {a} }}, {{ frame = 2, value = {b} }}]\n"
    );
    std::fs::write(&manifest, text).unwrap();
    animate()
        .arg(&manifest)
        .args(["--frames", "1", "--quiet"])
        .assert()
        .success();
    assert_eq!(SCENE.matches(from).count(), 1, "{from}");
    let still = dir.path().join("still.txt");
    std::fs::write(&still, SCENE.replacen(from, to, 1)).unwrap();
    let out = dir.path().join("still.png");
    raytrace()
        .arg(&still)
        .arg("-o")
        .arg(&out)
        .arg("--quiet")
        .assert()
        .success();
    (
        pixels(&dir.path().join("frames/frame_0001.png")),
        pixels(&out),
    )
}

#[test]
fn every_kind_of_extension_target_draws_the_still_with_the_value_written_in() {
    let cases = [
        (
            "box 1 max",
            "[-1.5, 1.0, 0.5]",
            "[-0.5, 2.0, 0.5]",
            "-1.5 1 0.5",
            "-1 1.5 0.5",
        ),
        (
            "crate rotate",
            "[0.0, 0.0, 0.0]",
            "[0.0, 60.0, 0.0]",
            "name crate",
            "name crate rotate 0 30 0",
        ),
        ("torus 1 major", "1.0", "1.4", "1 0.25", "1.2 0.25"),
        (
            "torus 1 translate",
            "[0.0, 0.0, 0.0]",
            "[0.0, 1.0, 0.0]",
            "0 1 0  1 0.25   1 0.2 0.8 0.2  0.6 0 0 1 0 0",
            "0 1 0  1 0.25   1 0.2 0.8 0.2  0.6 0 0 1 0 0 translate 0 0.5 0",
        ),
        ("cone 1 rb", "0.1", "0.5", "1.5 0 0.1", "1.5 0 0.3"),
        ("spot 1 falloff", "20.0", "40.0", "10 20 1", "10 30 1"),
        (
            "spot 1 p",
            "[-3.0, 6.0, 4.0]",
            "[-1.0, 6.0, 4.0]",
            "spot -3 6 4",
            "spot -2 6 4",
        ),
        ("spot 1 distance", "8.0", "4.0", "fade 8 2", "fade 6 2"),
        (
            "area 1 a1",
            "[1.0, 0.0, 0.0]",
            "[3.0, 0.0, 0.0]",
            "1 0 0  0 0 1",
            "2 0 0  0 0 1",
        ),
        (
            "box 1 color",
            "[0.8, 0.2, 0.2]",
            "[0.2, 0.2, 0.8]",
            "1 0.8 0.2 0.2",
            "1 0.5 0.2 0.5",
        ),
    ];
    let mut wrong = Vec::new();
    for (target, a, b, from, to) in cases {
        let (frame, still) = frame_and_still(target, a, b, from, to);
        if frame != still {
            wrong.push(target);
        }
    }
    assert!(wrong.is_empty(), "frame 1 is not the still for {wrong:?}");
}

#[test]
fn a_record_pushed_out_of_its_bounds_is_refused_at_the_tracks_line() {
    let cases = [
        (
            "box 1 max",
            "[-1.5, 1.0, 0.5]",
            "[-3.5, 1.0, 0.5]",
            "at frame 1 the record is out of bounds: Min must be below Max",
        ),
        (
            "spot 1 radius",
            "10.0",
            "30.0",
            "Radius (20) must be below Falloff (20)",
        ),
        ("torus 1 minor", "0.25", "2.0", "`torus 1 minor`"),
        (
            "crate scale",
            "[1.0, 1.0, 1.0]",
            "[-1.0, 1.0, 1.0]",
            "scale cannot be 0",
        ),
    ];
    let mut wrong = Vec::new();
    for (target, a, b, says) in cases {
        let dir = tempfile::tempdir().unwrap();
        std::fs::write(dir.path().join("scene.txt"), SCENE).unwrap();
        let manifest = dir.path().join("anim.toml");
        let text = format!(
            "scene = \"scene.txt\"\nframes = 3\n[output]\ndir = \"frames\"\n[[track]]\ntarget = \"{target}\"\nkeys = [{{ frame = 0, value = {a} }}, {{ frame = 2, value = {b} }}]\n"
        );
        std::fs::write(&manifest, text).unwrap();
        let out = animate().arg(&manifest).output().unwrap();
        let err = String::from_utf8_lossy(&out.stderr);
        let at = format!("{}:7:", manifest.display());
        let ok = out.status.code() == Some(2)
            && err.contains(&at)
            && err.contains(says)
            && !dir.path().join("frames").exists();
        if !ok {
            wrong.push(format!(
                "{target}: wanted {says}, got {:?}: {err}",
                out.status.code()
            ));
        }
    }
    assert!(wrong.is_empty(), "{}", wrong.join("\n"));
}
