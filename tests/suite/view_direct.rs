//! `animate view`'s directing aids through HTTP: `/api/camera` (a frame's camera as a
//! manifest key, which pasted into a spline manifest renders the very same frame) and
//! `/api/paths` (the camera's and a tracked sphere's paths projected with the frame's
//! camera, against a projection computed by hand).

use crate::support;
use crate::view_common;

use serde_json::Value;
use support::*;
use view_common::*;

/// The lines of a camera snippet that are not comments.
fn keys(text: &str) -> Vec<&str> {
    text.lines().filter(|l| !l.starts_with('#')).collect()
}

#[test]
fn a_copied_camera_key_renders_the_same_frame() {
    // A 12-frame circle of radius 8 about (0, 1, 0) at height 3 with a fov: frame 5 is at
    // 150°, (8·sin 150°, 3, 8·cos 150°) = (4, 3, −6.928…), looking at the centre.
    let fov = "fov = 41.25\n";
    let manifest = circle_manifest("").replace("turns = 1.0\n", &format!("turns = 1.0\n{fov}"));
    let (dir, path) = project(&manifest);
    let v = Viewer::start(&path, &[]);
    let (status, k5) = v.json("/api/camera?n=5");
    assert_eq!(status, 200, "{k5}");
    let p = &k5["position"];
    let want = [4.0, 3.0, 8.0 * 150f64.to_radians().cos()];
    for (i, w) in want.iter().enumerate() {
        assert!((p[i].as_f64().unwrap() - w).abs() < 1e-12, "{k5}");
    }
    assert_eq!(k5["look_at"], serde_json::json!([0.0, 1.0, 0.0]));
    assert_eq!(
        (k5["fov"].as_f64(), &k5["fov_tracked"]),
        (Some(41.25), &Value::Bool(false))
    );
    let text = k5["text"].as_str().unwrap();
    assert!(
        text.starts_with("# the camera of frame 5 of anim.toml, a key of [camera] path = \"spline\"\n{ frame = 5, position = [")
            && text.ends_with("# fov = 41.25: [camera]'s, every frame\n"),
        "{text}"
    );
    // Frames 5 and 9's keys pasted into a spline of the same fov: the manifest reader
    // takes them, and frame 5 renders byte for byte as the circle's frame 5.
    let (_, k9) = v.json("/api/camera?n=9");
    let spline = format!(
        "scene = \"scene.txt\"\nframes = 12\n\n[camera]\npath = \"spline\"\n{fov}keys = [\n  {}\n  {}\n]\n",
        keys(text)[0],
        keys(k9["text"].as_str().unwrap())[0]
    );
    let circle = frame_of(dir.path(), "circle", &manifest, 5);
    let pasted = frame_of(dir.path(), "pasted", &spline, 5);
    assert!(circle == pasted, "the pasted key draws another picture");
    // And not by chance: frame 6 of the circle is another picture.
    assert!(frame_of(dir.path(), "circle6", &manifest, 6) != circle);
    // Bad frames get the routes' 400.
    let (status, why) = v.json("/api/camera?n=12");
    assert_eq!(
        (status, why["error"].as_str()),
        (400, Some("`n` = 12 is out of range: expected 0 to 11"))
    );
    let (status, _) = v.json("/api/paths?n=x");
    assert_eq!(status, 400);
}

#[test]
fn paths_are_projected_with_the_frame_s_camera() {
    // Four frames of a circle of radius 10 about the origin at height 0, fov 90°, at
    // 200×100: the view plane is 4 × 2 at distance 1, so a point (X, Y) of the plane is
    // at x = (X + 2)/4·200, y = (1 − Y)/2·100. Frame 0's eye is (0, 0, 10), looking at
    // the origin; frames 1-3 sit at (10, 0, 0), (0, 0, −10), (−10, 0, 0), on the plane at
    // (1, 0), (0, 0), (−1, 0); frame 0's own eye has no place. Sphere 1 moves from
    // (0, 2, 0) to (3, 2, −3): at frame f (f, 2, −f), depth 10 + f, on the plane at
    // (f, 2)/(10 + f).
    let m = "scene = \"scene.txt\"\nframes = 4\n\n[render]\nwidth = 200\nheight = 100\n\n\
             [camera]\npath = \"circle\"\ncenter = [0.0, 0.0, 0.0]\nradius = 10.0\nheight = 0.0\n\
             fov = 90.0\n\n[[track]]\ntarget = \"sphere 1 center\"\n\
             keys = [{ frame = 0, value = [0.0, 2.0, 0.0] }, { frame = 3, value = [3.0, 2.0, -3.0] }]\n";
    let (_dir, path) = project(m);
    let v = Viewer::start(&path, &[]);
    let (status, got) = v.json("/api/paths?n=0");
    assert_eq!(status, 200, "{got}");
    assert_eq!(
        (got["width"].as_u64(), got["height"].as_u64()),
        (Some(200), Some(100))
    );
    let paths = got["paths"].as_array().unwrap();
    assert_eq!(paths.len(), 2, "{got}");
    let points = |p: &Value| -> Vec<Vec<f64>> {
        p["segments"]
            .as_array()
            .unwrap()
            .iter()
            .flat_map(|s| s.as_array().unwrap().iter())
            .map(|q| {
                q.as_array()
                    .unwrap()
                    .iter()
                    .map(|c| c.as_f64().unwrap())
                    .collect()
            })
            .collect()
    };
    let near = |a: &[Vec<f64>], b: &[[f64; 3]]| {
        a.len() == b.len()
            && a.iter()
                .zip(b)
                .all(|(p, q)| p.iter().zip(q).all(|(x, y)| (x - y).abs() < 1e-9))
    };
    assert_eq!(paths[0]["name"], "camera");
    assert_eq!(paths[0]["segments"].as_array().unwrap().len(), 1);
    let camera = [[150.0, 50.0, 1.0], [100.0, 50.0, 2.0], [50.0, 50.0, 3.0]];
    assert!(near(&points(&paths[0]), &camera), "{}", paths[0]);
    assert!(paths[0]["at"].is_null());
    assert_eq!(paths[1]["name"], "sphere 1 center");
    let sphere: Vec<[f64; 3]> = (0..4)
        .map(|f| {
            let (f, d) = (f64::from(f), 10.0 + f64::from(f));
            [(f / d + 2.0) * 50.0, (1.0 - 2.0 / d) * 50.0, f]
        })
        .collect();
    assert!(near(&points(&paths[1]), &sphere), "{}", paths[1]);
    assert_eq!(paths[1]["at"], serde_json::json!([100.0, 40.0]));
    // Seen from frame 1's eye (10, 0, 0) the camera's path is split where it passes
    // behind: frame 0 alone, then frames 2 and 3.
    let (_, got) = v.json("/api/paths?n=1");
    let frames: Vec<Vec<u64>> = got["paths"][0]["segments"]
        .as_array()
        .unwrap()
        .iter()
        .map(|s| {
            s.as_array()
                .unwrap()
                .iter()
                .map(|p| p[2].as_f64().unwrap() as u64)
                .collect()
        })
        .collect();
    assert_eq!(frames, [vec![0], vec![2, 3]]);
}
