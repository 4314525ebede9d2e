//! `loop = true`: frame N is frame 0, tracks run back to their first key with the last
//! key's ease, a spline camera path closes, motion blur samples across the join, and the
//! join is as smooth as the rest of the path (finite differences).

use super::*;
use crate::manifest::Manifest;
use crate::refusal::ManifestError;
use std::path::Path;
use whitted::scene::{ObjectSpec, ShapeSpec};

const SCENE: &str = "8 6  0 2 10  0 1 0  1 30  2 1 0 1
1.0  0 1 0   1 0.9 0.1 0.1   0.7 0.3 0 1 0 0
0.5  2 0.5 0   1 0.2 0.2 0.9   0.8 0 0 1 0 0
0 0 0  0 1 0   2 1 1 1 1 0 0 0 0 0 0   0.9 0 0 1 0 0
5 10 5  1 1 1  0.9";

/// 81 frames, looping.
fn looped(manifest: &str) -> Result<Timeline, ManifestError> {
    let text = format!("scene = \"s.txt\"\nframes = 81\nloop = true\n{manifest}");
    let m = Manifest::parse(&text, Path::new("m.toml"))?;
    Timeline::new(Scene::parse(SCENE, "s.txt").unwrap(), &m)
}

fn track(interpolation: &str, last_ease: &str) -> String {
    format!(
        "[[track]]
target = \"sphere 1 center\"
interpolation = \"{interpolation}\"
keys = [
  {{ frame = 0, value = [0.0, 1.0, 0.0] }},
  {{ frame = 30, value = [2.0, 4.0, 1.0] }},
  {{ frame = 60, value = [-1.0, 2.0, 3.0], ease = \"{last_ease}\" }},
]
"
    )
}

const SPLINE: &str = "[camera]
path = \"spline\"
look_at = [0.0, 1.0, 0.0]
keys = [
  { frame = 0,  position = [0.0, 3.0, 12.0] },
  { frame = 25, position = [10.0, 6.0, 0.0] },
  { frame = 55, position = [0.0, 2.0, -12.0] },
]
";

fn center(t: &Timeline, time: f64) -> DVec3 {
    match t.at(time).scene.specs[0] {
        ObjectSpec::Record(ShapeSpec::Sphere { center, .. }) => center,
        _ => unreachable!(),
    }
}

/// The angle (radians) the path turns at `time`, between its directions just before and
/// just after (finite differences of step h): near 0 where the path is smooth.
fn kink(path: &dyn Fn(f64) -> DVec3, time: f64) -> f64 {
    let h = 1e-4;
    let before = path(time) - path(time - h);
    let after = path(time + h) - path(time);
    before.angle_between(after)
}

#[test]
fn frame_n_is_frame_0_for_every_interpolation_and_the_camera() {
    for interpolation in ["linear", "smooth", "step"] {
        let t = looped(&format!("{SPLINE}{}", track(interpolation, "in"))).unwrap();
        let (a, b) = (t.at(0.0), t.at(81.0));
        assert_eq!(center(&t, 81.0), center(&t, 0.0), "{interpolation}");
        assert!(
            a.eye.distance(b.eye) < 1e-9,
            "{interpolation}: {} {}",
            a.eye,
            b.eye
        );
        assert_eq!(a.look_at, b.look_at);
        // The plot draws the path through frame N, closed.
        let drawn = &t.tracked_positions()[0].1;
        assert_eq!((drawn.len(), drawn[81]), (82, drawn[0]));
        // Two loops on, the same again.
        assert!(center(&t, 162.0 + 7.5).distance(center(&t, 7.5)) < 1e-12);
    }
}

#[test]
fn a_track_runs_back_to_its_first_key_with_the_last_keys_ease() {
    // Closing segment 60 → 81 from (-1, 2, 3) to (0, 1, 0); at 70.5, u = 0.5.
    let t = looped(&track("linear", "none")).unwrap();
    assert_eq!(center(&t, 70.5), DVec3::new(-0.5, 1.5, 1.5));
    // The last key's ease `in`: e = u² = 0.25 → (-1, 2, 3) + (1, -1, -3)·0.25.
    let t = looped(&track("linear", "in")).unwrap();
    assert_eq!(center(&t, 70.5), DVec3::new(-0.75, 1.75, 2.25));
    // Step holds the last key's value until the loop ends.
    let t = looped(&track("step", "none")).unwrap();
    assert_eq!(center(&t, 80.9), DVec3::new(-1.0, 2.0, 3.0));
    assert_eq!(center(&t, 81.0), DVec3::new(0.0, 1.0, 0.0));
    // Without the loop the last value holds (the old behaviour).
    let text = format!(
        "scene = \"s.txt\"\nframes = 81\n{}",
        track("linear", "none")
    );
    let m = Manifest::parse(&text, Path::new("m.toml")).unwrap();
    let open = Timeline::new(Scene::parse(SCENE, "s.txt").unwrap(), &m).unwrap();
    assert_eq!(center(&open, 70.5), DVec3::new(-1.0, 2.0, 3.0));
}

#[test]
fn the_join_is_as_smooth_as_the_rest() {
    // A smooth track and a spline camera: at the join (frame 81 ≡ 0) the path turns no
    // more than at the keys inside the loop, which is not at all (both are C¹ curves).
    let t = looped(&format!("{SPLINE}{}", track("smooth", "none"))).unwrap();
    let centre = |time: f64| center(&t, time);
    let eye = |time: f64| t.at(time).eye;
    let inside = [
        kink(&centre, 30.0),
        kink(&centre, 60.0),
        kink(&eye, 25.0),
        kink(&eye, 55.0),
    ];
    let joins = [kink(&centre, 81.0), kink(&centre, 0.0), kink(&eye, 81.0)];
    let most = inside.iter().fold(0.0f64, |a, &b| a.max(b));
    for join in joins {
        assert!(
            join < 1e-3 && join <= most + 1e-4,
            "join {join}, inside {inside:?}"
        );
    }
    // The test can fail: a linear track turns at its keys and at the join, and without
    // the loop a spline stops at its last key and a held track at its end.
    let t = looped(&track("linear", "none")).unwrap();
    assert!(kink(&|time| center(&t, time), 81.0) > 0.5);
    assert!(kink(&|time| center(&t, time), 30.0) > 0.5);
}

#[test]
fn motion_blur_at_frame_0_samples_the_end_of_the_loop() {
    let blur = "[render]\nmotion_blur = { shutter = 1.0, samples = 4 }\n";
    let t = looped(&format!("{}{blur}", track("linear", "none"))).unwrap();
    let times = t.times(0);
    assert_eq!(times, vec![-0.375, -0.125, 0.125, 0.375]);
    // Before frame 0 is the closing segment's end, not the first key held.
    assert_eq!(center(&t, -0.375), center(&t, 80.625));
    assert_ne!(center(&t, -0.375), center(&t, 0.0));
    // The last frame's sub-frames run on towards frame 81 = frame 0.
    let last = t.times(80);
    assert!(last.iter().all(|&s| s > 79.0 && s < 81.0));
}

#[test]
fn what_cannot_loop_is_refused_at_its_line() {
    let circle = "[camera]\npath = \"circle\"\ncenter = [0.0, 1.0, 0.0]\nradius = 8.0\nheight = 3.0\nturns = 1.5\n";
    let e = looped(circle).unwrap_err().to_string();
    assert!(
        e.starts_with("m.toml:3:8: loop = true: the camera's circle must make whole turns"),
        "{e}"
    );
    let track = "[[track]]\ntarget = \"light 1 position\"\npath = \"circle\"\ncenter = [0.0, 0.0, 0.0]\nradius = 8.0\nheight = 10.0\nturns = 0.25\n";
    let e = looped(track).unwrap_err().to_string();
    assert!(
        e.contains("track 1: with loop = true a circle makes whole turns, found turns = 0.25"),
        "{e}"
    );
    // A whole number of turns loops, as it always did.
    assert!(looped(&circle.replace("1.5", "2.0")).is_ok());
}
