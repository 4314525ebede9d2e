//! Faces on a tile boundary of an image map (issue 57, point 8), through `raytrace`: the
//! top face of a box from y 0 to 1 under a `planar` map of Size 1 (v is exactly 1 there)
//! and a cylinder's cap at a multiple of its `cylindrical` map's Size showed noise, the
//! hit points' rounding picking rows from both ends of the image. Each face now shows the
//! row on its solid's side, at every pixel: the image's top row on a top face.

use crate::common::{raytrace_in, write_file};

/// A 2×2 picture: the top row red, the bottom row blue.
fn rows_picture(dir: &std::path::Path) {
    let img = image::RgbImage::from_fn(2, 2, |_, j| {
        if j == 0 {
            image::Rgb([255, 0, 0])
        } else {
            image::Rgb([0, 0, 255])
        }
    });
    img.save(dir.join("rows.png")).unwrap();
}

/// Renders `object` (one extension record) seen from `eye` at 48×36, looking at (0, 1, 0)
/// with a light at the camera: (pixels that are mostly red, pixels that are mostly blue).
/// The eyes are ones where the old reading speckled (74 and 12 blue pixels).
fn red_and_blue(eye: &str, object: &str) -> (usize, usize) {
    let dir = tempfile::tempdir().unwrap();
    rows_picture(dir.path());
    let scene = format!("48 36\n{eye}\n0 1 0\n0 1\n0 0 0 1\n{eye}  1 1 1  1\n{object}\n");
    write_file(dir.path(), "scene.txt", scene);
    raytrace_in(dir.path())
        .args(["scene.txt", "-o", "out.png", "--quiet"])
        .assert()
        .success();
    let img = image::open(dir.path().join("out.png")).unwrap().to_rgb8();
    let (mut red, mut blue) = (0, 0);
    for p in img.pixels() {
        let [r, _, b] = p.0;
        if r > 40 && r > 4 * b {
            red += 1;
        } else if b > 40 && b > 4 * r {
            blue += 1;
        }
    }
    (red, blue)
}

#[test]
fn a_box_top_on_a_tile_boundary_shows_one_row() {
    // The camera sees only the top face (y = 1 = 1·Size).
    let (red, blue) = red_and_blue(
        "0.3 2.7 3.1",
        "box -1 0 -1  1 1 1   3 \"rows.png\" planar nearest 1   1 0 0 1 0 0",
    );
    assert!(
        red > 1000,
        "the top face is not drawn red: {red} red pixels"
    );
    assert_eq!(blue, 0, "the top face speckles: {blue} blue of {red} red");
}

#[test]
fn a_cylinder_cap_at_a_multiple_of_size_shows_one_row() {
    // The top cap at s = 2 = 2·Size, wider than the view.
    let (red, blue) = red_and_blue(
        "1.7 3.3 2.9",
        "cylinder 0 -1 0  0 1 0  3   3 \"rows.png\" cylindrical nearest 1   1 0 0 1 0 0",
    );
    assert!(red > 1000, "the cap is not drawn red: {red} red pixels");
    assert_eq!(blue, 0, "the cap speckles: {blue} blue of {red} red");
}

#[test]
fn a_face_off_the_boundary_is_unchanged() {
    // The top face at y = 0.75 with Size 1 reads row ⌊0.25·2⌋ = 0, red, as before.
    let (red, blue) = red_and_blue(
        "0 6 4",
        "box -100 0 -100  100 0.75 100   3 \"rows.png\" planar nearest 1   1 0 0 1 0 0",
    );
    assert!(red > 1000 && blue == 0, "{red} red, {blue} blue");
}
