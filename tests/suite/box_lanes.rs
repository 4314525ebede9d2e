//! The tree's box tests give the same bytes in either lanes, through the built binary:
//! the Stanford bunny (a mesh of 69,451 triangles, so a deep eight-wide tree and the
//! triangle packets) and the repository's NFF still life (spheres, a cone, polygons),
//! drawn with the lanes this processor chooses and with `WHITTED_LANES=narrow`, on one
//! and two threads. `accel::bvh::lanes_tests` holds the lanes' own property test.

use crate::shipped;
use crate::support::raytrace;
use std::path::Path;

/// The PNG's bytes of `scene` drawn at `size` on `threads` threads, `narrow` or not.
fn draw(dir: &Path, scene: &Path, size: &str, threads: &str, narrow: bool) -> Vec<u8> {
    let out = dir.join(format!("{threads}-{narrow}.png"));
    let mut cmd = raytrace();
    cmd.arg(scene)
        .args(["--size", size, "--threads", threads, "-q", "-o"])
        .arg(&out);
    if narrow {
        cmd.env("WHITTED_LANES", "narrow");
    } else {
        cmd.env_remove("WHITTED_LANES");
    }
    let run = cmd.output().unwrap();
    assert!(
        run.status.success(),
        "{}",
        String::from_utf8_lossy(&run.stderr)
    );
    std::fs::read(&out).unwrap()
}

fn same_in_both_lanes(scene: &Path, size: &str) {
    let dir = tempfile::tempdir().unwrap();
    let wide = draw(dir.path(), scene, size, "2", false);
    assert_eq!(
        wide,
        draw(dir.path(), scene, size, "1", true),
        "{}",
        scene.display()
    );
    assert_eq!(
        wide,
        draw(dir.path(), scene, size, "2", true),
        "{}",
        scene.display()
    );
}

#[test]
fn the_bunny_is_the_same_in_either_lanes() {
    same_in_both_lanes(&shipped::root().join("scenes/bunny.txt"), "240x180");
}

#[test]
fn the_nff_still_life_is_the_same_in_either_lanes() {
    same_in_both_lanes(
        &shipped::root().join("tests/data/nff/still-life.nff"),
        "160x120",
    );
}
