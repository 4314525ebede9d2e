//! `fit Size` and `pivot` on mesh records (SPEC §18's placing) through `raytrace`: a cube
//! written far from the origin at twice the size, fitted and pivoted, draws the same
//! bytes as the unit cube written at the origin and placed by the same `rotate` and
//! `translate`; a bad Size, and either modifier on another record, are located errors.

use crate::support::render_scene;

const BASE: &str = "64 48  0 2 5  0 0.5 0  0 0  0 1 0 1
0 0 0  0 1 0   1 0.8 0.8 0.8   1 0 0 1 0 0
4 8 6  1 1 1  1
";

/// An axis-aligned cube from `lo` with side `s`, as six quads.
fn cube(lo: [f64; 3], s: f64) -> String {
    let mut text = String::new();
    for i in 0..8 {
        let c = [0, 1, 2].map(|k| lo[k] + if i >> k & 1 == 1 { s } else { 0.0 });
        text += &format!("v {} {} {}\n", c[0], c[1], c[2]);
    }
    for q in [
        [1, 3, 4, 2],
        [5, 6, 8, 7],
        [1, 2, 6, 5],
        [3, 7, 8, 4],
        [1, 5, 7, 3],
        [2, 4, 8, 6],
    ] {
        text += &format!("f {} {} {} {}\n", q[0], q[1], q[2], q[3]);
    }
    text
}

/// The PNG bytes of `records`, or the stderr of a refusal (exit 2, no image).
fn render(dir: &std::path::Path, records: &str) -> Result<Vec<u8>, String> {
    std::fs::write(dir.join("far.obj"), cube([10.0, 20.0, 30.0], 2.0)).unwrap();
    std::fs::write(dir.join("unit.obj"), cube([-0.5, -0.5, -0.5], 1.0)).unwrap();
    render_scene(dir, &format!("{BASE}{records}"))
}

const RED: &str = "1 0.9 0.3 0.2  0.7 0 0 1 0 0";

#[test]
fn a_far_cube_fitted_and_pivoted_draws_as_the_unit_cube() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    let place = "rotate 0 30 0 translate 0 0.5 0 flat";
    let want = render(d, &format!("mesh \"unit.obj\" {RED} {place}\n")).unwrap();
    let centred = format!("mesh \"far.obj\" {RED} fit 1 pivot center {place}\n");
    assert_eq!(render(d, &centred).unwrap(), want);
    // Its pivot at the middle of the bottom face, in the file's units: the cube sits on
    // the floor without the translate's lift.
    let bottom = format!("mesh \"far.obj\" {RED} pivot 11 20 31 fit 1 rotate 0 30 0 flat\n");
    assert_eq!(render(d, &bottom).unwrap(), want);
    // Without pivot the fitted cube stays where the file put it: not in the picture.
    let stays = format!("mesh \"far.obj\" {RED} fit 1 {place}\n");
    assert_ne!(render(d, &stays).unwrap(), want);
    let e = render(d, &format!("mesh \"far.obj\" {RED} fit 0\n")).unwrap_err();
    assert!(
        e.contains("DIR/scene.txt:4:") && e.contains("Size must be greater than 0"),
        "{e}"
    );
    let e = render(d, &format!("plane 0 1 0  0 1 0 {RED} pivot center\n")).unwrap_err();
    assert!(
        e.contains("DIR/scene.txt:4:")
            && e.contains("'pivot' does not apply to a plane: it is unbounded"),
        "{e}"
    );
}
