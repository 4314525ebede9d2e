//! A small scene of meshes scales the report's 0.01 epsilon with its size (SPEC §18):
//! a cube of side 0.05 on a mirror floor draws as its copy twenty times larger does,
//! its reflection whole down to the floor (with 0.01, a fifth of the cube, the reflected
//! rays near the contact pass its near face and meet the far one from inside), and
//! without acne on its faces.

use crate::support::render_scene;

/// A unit cube centred at the origin, as six quads.
fn cube() -> String {
    let mut text = String::new();
    for i in 0..8 {
        let c = [0, 1, 2].map(|k| if i >> k & 1 == 1 { 0.5 } else { -0.5 });
        text += &format!("v {} {} {}\n", c[0], c[1], c[2]);
    }
    for q in [
        "1 3 4 2", "5 6 8 7", "1 2 6 5", "3 7 8 4", "1 5 7 3", "2 4 8 6",
    ] {
        text += &format!("f {q}\n");
    }
    text
}

/// The scene at scale `k`: eye, look-at, light and the cube's size and place times k.
fn scene(k: f64) -> String {
    let v = |x: f64, y: f64, z: f64| format!("{} {} {}", x * k, y * k, z * k);
    format!(
        "64 48  {}  {}  0 0  0 1 0 1
0 0 0  0 1 0   1 0.8 0.8 0.8   0.5 0.5 0 1 0 0
{}  1 1 1  1
mesh \"cube.obj\"  1 0.9 0.3 0.2  0.7 0 0 1 0 0  fit {} pivot center rotate 0 30 0 translate {} flat
",
        v(0.0, 1.0, 4.0),
        v(0.0, 0.3, 0.0),
        v(3.0, 5.0, 4.0),
        k,
        v(0.0, 0.5, 0.0),
    )
}

/// The RGB pixels of a PNG's bytes.
fn rgb(png: &[u8]) -> Vec<u8> {
    image::load_from_memory(png).unwrap().to_rgb8().into_raw()
}

#[test]
fn a_tiny_cube_draws_as_its_copy_twenty_times_larger() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    std::fs::write(d.join("cube.obj"), cube()).unwrap();
    let big = rgb(&render_scene(d, &scene(1.0)).unwrap());
    let tiny = rgb(&render_scene(d, &scene(0.05)).unwrap());
    // Rounding may move an edge pixel; a wrong reflection or acne moves dozens.
    let off = (big.chunks(3).zip(tiny.chunks(3)))
        .filter(|(a, b)| a.iter().zip(*b).any(|(x, y)| x.abs_diff(*y) > 2))
        .count();
    assert!(off <= 3, "{off} of {} pixels differ", big.len() / 3);
    // The cube is in the picture, red, in both.
    let red = tiny
        .chunks(3)
        .filter(|p| p[0] > 2 * p[1].max(p[2]) && p[0] > 60)
        .count();
    assert!(red > 100, "{red} red pixels");
}
