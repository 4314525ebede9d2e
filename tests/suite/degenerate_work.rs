//! Degenerate work (issue 57, point 4), through `raytrace`: a mesh of copies of one
//! triangle rendered about 9,000 times slower than as many distinct ones (every copy
//! shared one box: the tree could not split them and every ray tested them all); a
//! convex NFF polygon of N vertices was cut in time N² (40,000 vertices: 2.4 s).
//!
//! These compare times, which the project measures in benchmarks: each bound here is a
//! ratio or a budget far from both sides (the old code missed them by a factor of
//! hundreds), so that a loaded machine does not fail them. The figures themselves are
//! in docs/reliability.md. Inputs are generated into a temporary folder.

use crate::common::{raytrace_in, write_file};
use std::fmt::Write as _;
use std::path::Path;
use std::time::{Duration, Instant};

/// Triangles in each mesh: old code took about 8 s for the copies at 64×48.
const TRIANGLES: usize = 400_000;

/// Renders `scene` in `dir` at 64×48 on one thread: its wall time.
fn render(dir: &Path, scene: &str) -> Duration {
    let started = Instant::now();
    raytrace_in(dir)
        .args([scene, "-o", "out.png", "--quiet", "--threads", "1"])
        .assert()
        .success();
    started.elapsed()
}

/// A scene looking at the unit square's corner triangle, holding `mesh`.
fn mesh_scene(mesh: &str) -> String {
    format!(
        "64 48\n0.3 0.3 3\n0.3 0.3 0\n0 1\n0 0 0 1\n0 1 4  1 1 1  1\n\
         mesh \"{mesh}\"  1 0.8 0.6 0.2  0.8 0 0 1 0 0\n"
    )
}

#[test]
fn copies_of_one_triangle_cost_no_more_than_ten_times_distinct_triangles() {
    let dir = tempfile::tempdir().unwrap();
    // The copies: three vertices, TRIANGLES faces naming them.
    let mut same = String::from("v 0 0 0\nv 1 0 0\nv 0 1 0\n");
    same += &"f 1 2 3\n".repeat(TRIANGLES);
    // Distinct ones: a strip of small triangles over the same square, three vertices each.
    let mut distinct = String::with_capacity(TRIANGLES * 60);
    let side = (TRIANGLES as f64).sqrt().ceil() as usize;
    let h = 1.0 / side as f64;
    for k in 0..TRIANGLES {
        let (x, y) = ((k % side) as f64 * h, (k / side) as f64 * h);
        let _ = writeln!(
            distinct,
            "v {x} {y} 0\nv {} {y} 0\nv {x} {} 0",
            x + h,
            y + h
        );
    }
    for k in 0..TRIANGLES {
        let _ = writeln!(distinct, "f {} {} {}", 3 * k + 1, 3 * k + 2, 3 * k + 3);
    }
    write_file(dir.path(), "same.obj", same);
    write_file(dir.path(), "distinct.obj", distinct);
    write_file(dir.path(), "same.txt", mesh_scene("same.obj"));
    write_file(dir.path(), "distinct.txt", mesh_scene("distinct.obj"));
    let one = String::from("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
    write_file(dir.path(), "one.obj", one);
    write_file(dir.path(), "one.txt", mesh_scene("one.obj"));
    let t_distinct = render(dir.path(), "distinct.txt");
    let t_same = render(dir.path(), "same.txt");
    let ratio = t_same.as_secs_f64() / t_distinct.as_secs_f64();
    assert!(
        ratio <= 10.0,
        "{TRIANGLES} copies took {t_same:?}, as many distinct triangles {t_distinct:?}: {ratio:.1}x"
    );
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
fn a_convex_polygon_of_200_000_vertices_is_cut_in_linear_time() {
    // The walk tested every remaining vertex at every corner: 200,000 vertices would
    // take about a minute (2.4 s for 40,000, times 25). Cut as a fan: well under 5 s.
    let dir = tempfile::tempdir().unwrap();
    write_file(dir.path(), "big.nff", polygon_nff(200_000));
    let took = render(dir.path(), "big.nff");
    assert!(took < Duration::from_secs(5), "took {took:?}");
}
