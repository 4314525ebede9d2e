//! Tracks (SPEC §7) end to end: a tracked frame is the image `raytrace` draws of the
//! Scene.txt with that frame's value written in by hand; a motion-blurred frame is the
//! mean of its sub-frame stills; malformed tracks are refused at their line, exit 2,
//! before any frame.

use crate::support;

use support::*;

/// A still manifest of 3 frames over `scene.txt` with `tracks` appended.
fn still_manifest(tracks: &str) -> String {
    format!("scene = \"scene.txt\"\nframes = 3\n[output]\ndir = \"frames\"\n{tracks}")
}

/// One key at frame 0 and one at frame 2, linear: frame 1 is their exact midpoint.
fn two_keys(target: &str, a: &str, b: &str) -> String {
    format!("[[track]]\ntarget = \"{target}\"\nkeys = [{{ frame = 0, value = {a} }}, {{ frame = 2, value = {b} }}]\n")
}

/// Renders frame 1 of `manifest` and the still of `scene`; their pixels.
fn frame_and_still(manifest: &str, scene: &str) -> (Vec<u8>, Vec<u8>) {
    let (dir, path) = project(manifest);
    animate()
        .arg(&path)
        .args(["--frames", "1", "--quiet"])
        .assert()
        .success();
    let still = dir.path().join("still.txt");
    std::fs::write(&still, scene).unwrap();
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
fn every_kind_of_target_draws_the_still_with_the_value_written_in() {
    let base = scene_with_eye([0.0, 3.0, 8.0]);
    // target, key at frame 0, key at frame 2, the scene's text, the text at frame 1.
    let cases = [
        (
            "sphere 1 center",
            "[-1.5, 1.0, 0.0]",
            "[-0.5, 2.0, 0.0]",
            "1.0  -1.3 1 0",
            "1.0  -1 1.5 0",
        ),
        (
            "sphere 2 radius",
            "0.5",
            "1.0",
            "0.9   1.2 0.9 0.5",
            "0.75   1.2 0.9 0.5",
        ),
        (
            "plane 1 point",
            "[0.0, 0.0, 0.0]",
            "[0.0, -1.0, 0.0]",
            "0 0 0  0 1 0   2 1",
            "0 -0.5 0  0 1 0   2 1",
        ),
        (
            "plane 1 normal",
            "[0.0, 1.0, 0.0]",
            "[1.0, 1.0, 0.0]",
            "0 0 0  0 1 0   2 1",
            "0 0 0  0.5 1 0   2 1",
        ),
        (
            "cylinder 1 axis",
            "[0.0, 1.0, 0.0]",
            "[1.0, 1.0, 0.0]",
            "0 1 0  -2 0 -2  0.3",
            "0.5 1 0  -2 0 -2  0.3",
        ),
        (
            "cylinder 1 point",
            "[-2.0, 0.0, -2.0]",
            "[0.0, 0.0, -2.0]",
            "0 1 0  -2 0 -2  0.3",
            "0 1 0  -1 0 -2  0.3",
        ),
        (
            "cylinder 1 radius",
            "0.25",
            "0.75",
            "0 1 0  -2 0 -2  0.3",
            "0 1 0  -2 0 -2  0.5",
        ),
        (
            "sphere 1 color",
            "[0.0, 0.0, 0.5]",
            "[1.0, 0.5, 0.5]",
            "1 0.9 0.9 0.9",
            "1 0.5 0.25 0.5",
        ),
        (
            "sphere 3 color2",
            "[0.0, 0.0, 0.0]",
            "[1.0, 1.0, 0.5]",
            "0.3 0.15 0.05 0 0 0",
            "0.5 0.5 0.25 0 0 0",
        ),
        (
            "plane 1 color1",
            "[0.5, 0.0, 0.0]",
            "[0.5, 1.0, 1.0]",
            "2 1 1 1 1 0.1",
            "2 1 0.5 0.5 0.5 0.1",
        ),
        (
            "sphere 1 kr",
            "0.5",
            "1.0",
            "0.1 0.9 0 1 0 0",
            "0.1 0.75 0 1 0 0",
        ),
        (
            "sphere 2 kt",
            "0.5",
            "1.0",
            "0.1 0 0.9 1.5 0 0",
            "0.1 0 0.75 1.5 0 0",
        ),
        (
            "sphere 2 ior",
            "1.5",
            "2.5",
            "0.1 0 0.9 1.5 0 0",
            "0.1 0 0.9 2 0 0",
        ),
        (
            "sphere 3 kd",
            "0.5",
            "1.0",
            "0.8 0 0 1 0 0",
            "0.75 0 0 1 0 0",
        ),
        (
            "light 1 position",
            "[5.0, 10.0, 5.0]",
            "[-5.0, 10.0, 5.0]",
            "5 10 5  1 1 1  0.9",
            "0 10 5  1 1 1  0.9",
        ),
        (
            "light 2 color",
            "[0.0, 0.0, 1.0]",
            "[1.0, 1.0, 1.0]",
            "-6 8 4  0.6 0.6 0.8",
            "-6 8 4  0.5 0.5 1",
        ),
        (
            "light 1 intensity",
            "0.5",
            "1.0",
            "5 10 5  1 1 1  0.9",
            "5 10 5  1 1 1  0.75",
        ),
        ("fog distance", "20.0", "40.0", "2 40", "2 30"),
    ];
    for (target, a, b, from, to) in cases {
        assert_eq!(base.matches(from).count(), 1, "{target}: {from}");
        let by_hand = base.replacen(from, to, 1);
        let (frame, still) = frame_and_still(&still_manifest(&two_keys(target, a, b)), &by_hand);
        assert!(
            frame == still,
            "{target}: the tracked frame differs from the still"
        );
        // And the value did change the picture (the case tests something).
        let (_, untouched) = frame_and_still(&still_manifest(""), &base);
        assert!(frame != untouched, "{target}: the track changed nothing");
    }
}

#[test]
fn a_light_on_a_circle_and_a_camera_that_follows_a_moving_sphere() {
    // Frame 1 of 4: the light a quarter turn round (θ = 90°: +x side), the sphere half way.
    let tracks = "[camera]\nlook_at = \"sphere 1\"\n\
        [[track]]\ntarget = \"light 1 position\"\npath = \"circle\"\ncenter = [0.0, 0.0, 0.0]\nradius = 6.0\nheight = 10.0\n\
        [[track]]\ntarget = \"sphere 1 center\"\nkeys = [{ frame = 0, value = [-1.5, 1.0, 0.0] }, { frame = 2, value = [-0.5, 1.0, 0.0] }]\n";
    let manifest = still_manifest(tracks).replace("frames = 3", "frames = 4");
    let (frame, _) = frame_and_still(&manifest, &scene_with_eye([0.0, 3.0, 8.0]));
    let theta = std::f64::consts::FRAC_PI_2;
    let light = format!(
        "{:?} 10 {:?}  1 1 1  0.9",
        6.0 * theta.sin(),
        6.0 * theta.cos()
    );
    let by_hand = scene_with_eye([0.0, 3.0, 8.0])
        .replacen("0 1 0\n2 40", "-1 1 0\n2 40", 1)
        .replacen("1.0  -1.3 1 0", "1.0  -1 1 0", 1)
        .replacen("5 10 5  1 1 1  0.9", &light, 1);
    let (_, still) = frame_and_still(&still_manifest(""), &by_hand);
    assert!(frame == still);
}

#[test]
fn a_motion_blurred_frame_is_the_mean_of_its_sub_frame_stills() {
    // x moves 0.25 a frame; frame 2 with a one-frame shutter and 4 samples samples
    // t = 1.625, 1.875, 2.125, 2.375, so x = −1.09375, −1.03125, −0.96875, −0.90625.
    let tracks = "[render]\nmotion_blur = { shutter = 1.0, samples = 4 }\n\
        [[track]]\ntarget = \"sphere 1 center\"\nkeys = [{ frame = 0, value = [-1.5, 1.0, 0.0] }, { frame = 4, value = [-0.5, 1.0, 0.0] }]\n";
    let manifest = still_manifest(tracks).replace("frames = 3", "frames = 5");
    let (dir, path) = project(&manifest);
    animate()
        .arg(&path)
        .args(["--frames", "2", "--quiet"])
        .assert()
        .success();
    let blurred = pixels(&dir.path().join("frames/frame_0002.png"));
    let mut stills = Vec::new();
    for x in ["-1.09375", "-1.03125", "-0.96875", "-0.90625"] {
        let scene =
            scene_with_eye([0.0, 3.0, 8.0]).replacen("1.0  -1.3 1 0", &format!("1.0  {x} 1 0"), 1);
        let file = dir.path().join(format!("sub{x}.txt"));
        std::fs::write(&file, scene).unwrap();
        let out = dir.path().join(format!("sub{x}.png"));
        raytrace()
            .arg(&file)
            .arg("-o")
            .arg(&out)
            .arg("--quiet")
            .assert()
            .success();
        stills.push(pixels(&out));
    }
    let mut moved = false;
    for (i, &v) in blurred.iter().enumerate() {
        let mean = stills.iter().map(|s| f64::from(s[i])).sum::<f64>() / 4.0;
        assert!(
            (f64::from(v) - mean).abs() <= 1.0,
            "byte {i}: {v} against a mean of {mean}"
        );
        moved |= stills.iter().any(|s| s[i] != stills[0][i]);
    }
    assert!(moved, "the sub-frames should differ");
}

#[test]
fn malformed_tracks_are_refused_at_their_line_before_any_frame() {
    let key = "keys = [{ frame = 0, value = 1.0 }]";
    // The manifest text after `frames = 3\n[output]\ndir = "frames"\n` (line 5 on), the
    // expected `line:column` and a part of the message.
    let cases: Vec<(String, &str, &str)> = vec![
        (format!("[[track]]\ntarget = \"cube 1 radius\"\n{key}"), "6:10", "unknown kind `cube`"),
        (format!("[[track]]\ntarget = \"sphere 4 radius\"\n{key}"), "6:10", "sphere 4 does not exist: the scene has 3"),
        (format!("[[track]]\ntarget = \"sphere 1 normal\"\n{key}"), "6:10", "sphere has no field `normal`"),
        (format!("[[track]]\ntarget = \"sphere 1\"\n{key}"), "6:10", "KIND N FIELD"),
        ("[[track]]\ntarget = \"sphere 1 radius\"\nkeys = [{ frame = 0, value = [1.0, 2.0, 3.0] }]".into(), "6:10", "takes a number"),
        ("[[track]]\ntarget = \"sphere 1 center\"\nkeys = [{ frame = 0, value = 2.0 }]".into(), "6:10", "takes [x, y, z]"),
        ("[[track]]\ntarget = \"sphere 1 radius\"\nkeys = [{ frame = 0, value = 1.0 }, { frame = 2, value = -1.0 }]".into(), "7:19", "at frame 1 its value 0 is out of bounds: a radius must be greater than 0"),
        ("[[track]]\ntarget = \"sphere 1 color\"\nkeys = [{ frame = 0, value = [0.0, 0.5, 1.5] }]".into(), "7:19", "each colour channel must be from 0 to 1"),
        ("[[track]]\ntarget = \"plane 1 normal\"\nkeys = [{ frame = 0, value = [0.0, 1.0, 0.0] }, { frame = 2, value = [0.0, -1.0, 0.0] }]".into(), "7:19", "at frame 1 its value [0, 0, 0] is out of bounds: a normal or an axis must not have zero length"),
        ("[[track]]\ntarget = \"light 1 intensity\"\nkeys = [{ frame = 0, value = 2000.0 }]".into(), "7:19", "intensity must be from 0 to 1000"),
        ("[[track]]\ntarget = \"sphere 1 radius\"\nkeys = [{ frame = 2, value = 1.0 }, { frame = 1, value = 2.0 }]".into(), "7:47", "not after the previous key's frame 2"),
        ("[[track]]\ntarget = \"sphere 1 radius\"\nkeys = [{ frame = 3, value = 1.0 }]".into(), "7:19", "outside the sequence: frames run from 0 to 2"),
        ("[[track]]\ntarget = \"sphere 1 radius\"\ninterpolation = \"cubic\"\nkeys = [{ frame = 0, value = 1.0 }]".into(), "7:17", "unknown interpolation `cubic`, expected one of linear, smooth, step"),
        ("[[track]]\ntarget = \"sphere 1 radius\"\nkeys = [{ frame = 0, value = 1.0, ease = \"inout\" }]".into(), "7:42", "unknown ease `inout`, expected one of none, in, out, in-out"),
        ("[[track]]\ntarget = \"sphere 1 radius\"\nkeys = [{ frame = 0, value = \"big\" }]".into(), "7:30", "`value` must be a finite number or [x, y, z]"),
        ("[[track]]\ntarget = \"sphere 1 kd\"\npath = \"circle\"\ncenter = [0.0, 0.0, 0.0]\nradius = 1.0\nheight = 1.0".into(), "6:10", "is not a position"),
        ("[[track]]\ntarget = \"light 1 position\"\npath = \"circle\"\nradius = 1.0\nheight = 1.0".into(), "6:10", "a circle track needs `center`"),
        ("[[track]]\ntarget = \"sphere 1 radius\"".into(), "6:10", "a track needs `keys = [...]` or `path = \"circle\"`"),
        (format!("[[track]]\ntarget = \"sphere 1 radius\"\n{key}\n[[track]]\ntarget = \"sphere 1 radius\"\n{key}"), "9:10", "already animated by track 1"),
        (format!("[[track]]\ntarget = \"fog distance\"\n{key}\nspeed = 2"), "8:1", "unknown key `speed`"),
        ("[camera]\nlook_at = \"sphere 9\"".into(), "6:11", "look_at: sphere 9 does not exist"),
        ("[render]\nmotion_blur = { shutter = 1.5, samples = 4 }".into(), "6:27", "`shutter` is in frames and must be above 0 and at most 1"),
        ("[render]\nmotion_blur = { shutter = 0.5, samples = 0 }".into(), "6:42", "`samples` must be between 1 and 64"),
    ];
    assert!(cases.len() >= 15);
    let mut wrong = Vec::new();
    for (text, at, says) in cases {
        let (dir, path) = project(&still_manifest(&text));
        let out = animate().arg(&path).output().unwrap();
        let err = String::from_utf8_lossy(&out.stderr);
        let want = format!("{}:{at}: ", path.display());
        let ok = out.status.code() == Some(2)
            && err.contains(&want)
            && err.contains(says)
            && !dir.path().join("frames").exists();
        if !ok {
            wrong.push(format!(
                "{text}\n  wanted {at}: …{says}…, exit 2\n  got {:?}: {err}",
                out.status.code()
            ));
        }
    }
    assert!(wrong.is_empty(), "{}", wrong.join("\n"));
}
