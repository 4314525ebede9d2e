//! `raytrace SCENE --info` through the binary: the objects' world bounds after `fit`,
//! `pivot` and the record's frame (checked by hand), triangle counts, lights and camera;
//! the warnings for a camera inside an object and an object under a pixel; nothing drawn.

use crate::support::raytrace;

const BASE: &str = "64 48  0 2 5  0 0.5 0  0 0  0 1 0 1
0 0 0  0 1 0   1 0.8 0.8 0.8   1 0 0 1 0 0
4 8 6  1 1 1  1
";

const RED: &str = "1 0.9 0.3 0.2  0.7 0 0 1 0 0";

/// An axis-aligned cube from (10, 20, 30) with side 2, as six quads (12 triangles).
fn far_cube() -> String {
    let mut text = String::new();
    for i in 0..8 {
        let lo = [10.0, 20.0, 30.0];
        let c = [0, 1, 2].map(|k| lo[k] + if i >> k & 1 == 1 { 2.0 } else { 0.0 });
        text += &format!("v {} {} {}\n", c[0], c[1], c[2]);
    }
    for q in [
        "1 3 4 2", "5 6 8 7", "1 2 6 5", "3 7 8 4", "1 5 7 3", "2 4 8 6",
    ] {
        text += &format!("f {q}\n");
    }
    text
}

/// Runs `raytrace DIR/scene.txt --info ARGS`: exit code, stdout, stderr.
fn info(dir: &std::path::Path, records: &str, args: &[&str]) -> (Option<i32>, String, String) {
    std::fs::write(dir.join("far.obj"), far_cube()).unwrap();
    let scene = dir.join("scene.txt");
    std::fs::write(&scene, format!("{BASE}{records}")).unwrap();
    let out = raytrace()
        .arg(&scene)
        .arg("--info")
        .args(args)
        .output()
        .unwrap();
    let text = |b: &[u8]| String::from_utf8_lossy(b).replace(&*dir.display().to_string(), "DIR");
    (out.status.code(), text(&out.stdout), text(&out.stderr))
}

#[test]
fn bounds_after_fit_pivot_and_frame_by_hand() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    let records = format!(
        "mesh \"far.obj\" {RED} fit 1 pivot center rotate 0 90 0 translate 0 0.5 0 flat name cube
mesh \"far.obj\" {RED} flat
box -1 0 -1  1 2 1  {RED}  scale 0.5 1 2 translate 3 0 0
spot 0 5 0  0 0 0  1 1 1  1  20 30 1  name key
"
    );
    let (code, out, err) = info(d, &records, &[]);
    assert_eq!(code, Some(0), "{err}");
    assert_eq!(err, "", "no warning expected");
    // The cube fitted to 1, its centre at the origin, turned a quarter about y (still
    // the same box), lifted 0.5. The second keeps the file's place; the box is scaled
    // about the origin, then moved 3 along x.
    let want = "objects:
  #  name     kind   triangles  bounds (world)
  1  plane 1  plane  -          unbounded
  2  cube     mesh   12         [-0.5, 0, -0.5] to [0.5, 1, 0.5]
  3  mesh 2   mesh   12         [10, 20, 30] to [12, 22, 32]
  4  box 1    box    -          [2.5, 0, -2] to [3.5, 2, 2]
lights:
  #  name     kind   place
  1  light 1  point  at [4, 8, 6]
  2  key      spot   at [0, 5, 0]
camera: eye [0, 2, 5], look-at [0, 0.5, 0], 64×48 pixels, field of view 19.8525° vertical (28.0725° horizontal)
";
    assert_eq!(out, want);
    // Nothing was drawn: no picture beside the scene.
    assert!(!d.join("scene.png").exists());
    // At another size and field of view the camera line follows the command line.
    let (code, out, _) = info(d, &records, &["--size", "160x120", "--fov", "40"]);
    assert_eq!(code, Some(0));
    assert!(
        out.ends_with("160×120 pixels, field of view 40° vertical (51.774° horizontal)\n"),
        "{out}"
    );
}

#[test]
fn a_camera_inside_and_a_speck_are_warned_about() {
    let dir = tempfile::tempdir().unwrap();
    let records = format!(
        "mesh \"far.obj\" {RED} fit 20 pivot center flat name room
mesh \"far.obj\" {RED} fit 0.001 pivot center translate 0 0.5 0 flat name speck
"
    );
    let (code, out, err) = info(dir.path(), &records, &[]);
    assert_eq!(code, Some(0), "{err}");
    assert!(
        out.contains(
            "  3  speck    mesh   12         [-5e-4, 0.4995, -5e-4] to [5e-4, 0.5005, 5e-4]\n"
        ),
        "{out}"
    );
    // The eye (0, 2, 5) is inside the room's box, −10 to 10 on each axis.
    assert!(err.contains("raytrace: warning: the camera at [0, 2, 5] is inside the bounds of object 2 (room), [-10, -10, -10] to [10, 10, 10]"), "{err}");
    // The speck's diagonal √3/1000 at distance √27.25 = 5.2202, a pixel 0.35/48 there:
    // 0.0455 pixel.
    assert!(err.contains("raytrace: warning: object 3 (speck) would cover less than one pixel: its bounds' diagonal 0.0017 at distance 5.2202 spans 0.0455 pixel of the 48-pixel height"), "{err}");
    let (_, _, quiet) = info(dir.path(), &records, &["--quiet"]);
    assert_eq!(quiet, "");
}

#[test]
fn bad_scenes_and_options_are_refused() {
    let dir = tempfile::tempdir().unwrap();
    let (code, out, err) = info(dir.path(), "box 1 1 1  0 0 0  1 1 1 1  1 0 0 1 0 0\n", &[]);
    assert_eq!((code, out.as_str()), (Some(2), ""));
    assert!(err.contains("DIR/scene.txt:4:"), "{err}");
    let (code, _, err) = info(dir.path(), "", &["-o", "x.png"]);
    assert_eq!(code, Some(2));
    assert!(err.contains("--info") && err.contains("--out"), "{err}");
}
