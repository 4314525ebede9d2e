//! Degenerate work, through `raytrace`: a mesh of copies of one triangle (every copy
//! shared one box, so the tree could not split them and every ray tested them all) and
//! a convex NFF polygon of many vertices (once cut in time N²). What they cost is
//! measured by the `degenerate` group of `cargo bench --bench tracer` (copies against
//! distinct triangles, 40,000 against 200,000 vertices), never by a timed test; here
//! the copies must draw what one triangle draws, and the large polygon must render.
//! Inputs are generated into a temporary folder.

use crate::common::{raytrace_in, write_file};
use std::fmt::Write as _;
use std::path::Path;

/// Triangles in each mesh: old code took about 8 s for the copies at 64×48.
const TRIANGLES: usize = 400_000;

/// Renders `scene` in `dir` at its size into `out.png`, on one thread.
fn render(dir: &Path, scene: &str) {
    raytrace_in(dir)
        .args([scene, "-o", "out.png", "--quiet", "--threads", "1"])
        .assert()
        .success();
}

/// A scene looking at the unit square's corner triangle, holding `mesh`.
fn mesh_scene(mesh: &str) -> String {
    format!(
        "64 48\n0.3 0.3 3\n0.3 0.3 0\n0 1\n0 0 0 1\n0 1 4  1 1 1  1\n\
         mesh \"{mesh}\"  1 0.8 0.6 0.2  0.8 0 0 1 0 0\n"
    )
}

#[test]
fn copies_of_one_triangle_draw_one_triangle() {
    let dir = tempfile::tempdir().unwrap();
    // The copies: three vertices, TRIANGLES faces naming them.
    let mut same = String::from("v 0 0 0\nv 1 0 0\nv 0 1 0\n");
    same += &"f 1 2 3\n".repeat(TRIANGLES);
    write_file(dir.path(), "same.obj", same);
    write_file(dir.path(), "same.txt", mesh_scene("same.obj"));
    let one = String::from("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
    write_file(dir.path(), "one.obj", one);
    write_file(dir.path(), "one.txt", mesh_scene("one.obj"));
    render(dir.path(), "same.txt");
    // And the copies draw exactly what one of them draws.
    let copies = std::fs::read(dir.path().join("out.png")).unwrap();
    render(dir.path(), "one.txt");
    let single = std::fs::read(dir.path().join("out.png")).unwrap();
    assert!(
        copies == single,
        "the copies draw another picture than one triangle"
    );
}

/// An NFF scene of one convex polygon of `n` vertices on a circle, facing the camera.
fn polygon_nff(n: usize) -> String {
    let mut s = String::from(
        "v\nfrom 0 0 5\nat 0 0 0\nup 0 1 0\nangle 40\nhither 1\nresolution 16 16\n\
         l 0 0 5\nf 1 0.5 0.2 1 0 0 0 0\n",
    );
    let _ = writeln!(s, "p {n}");
    for i in 0..n {
        let a = std::f64::consts::TAU * i as f64 / n as f64;
        let _ = writeln!(s, "{} {} 0", a.cos(), a.sin());
    }
    s
}

#[test]
fn a_convex_polygon_of_200_000_vertices_renders() {
    // The walk tested every remaining vertex at every corner (about a minute for this
    // one); cut as a fan it is read at once (`cargo bench --bench tracer degenerate`).
    let dir = tempfile::tempdir().unwrap();
    write_file(dir.path(), "big.nff", polygon_nff(200_000));
    render(dir.path(), "big.nff");
    let png = image::open(dir.path().join("out.png")).unwrap().to_rgb8();
    // The disc of radius 1 at distance 5 under 40 degrees fills the centre, lit: its
    // orange (1, 0.5, 0.2), red above green above blue, against the black background.
    let [r, g, b] = png.get_pixel(8, 8).0;
    assert!(r > 100 && r > g && g > b, "{:?}", [r, g, b]);
}
