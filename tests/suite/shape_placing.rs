//! `fit` and `pivot` on the bounded records other than meshes (SPEC §18's placing),
//! through `raytrace --info`: world bounds worked out by hand for a box, a sphere, a
//! torus and a CSG block; a plane and a block that holds one unbounded are located
//! errors.

use crate::support::raytrace;

const BASE: &str = "64 48  0 2 9  0 0.5 0  0 0  0 0 0 1
4 8 6  1 1 1  1
";

const RED: &str = "1 0.9 0.3 0.2  0.7 0 0 1 0 0";

/// `raytrace --info` of BASE and `records`: Ok(stdout) or Err(stderr) of an exit 2.
fn info(records: &str) -> Result<String, String> {
    let dir = tempfile::tempdir().unwrap();
    let scene = dir.path().join("scene.txt");
    std::fs::write(&scene, format!("{BASE}{records}")).unwrap();
    let out = raytrace().arg(&scene).arg("--info").output().unwrap();
    let text =
        |b: &[u8]| String::from_utf8_lossy(b).replace(&*dir.path().display().to_string(), "DIR");
    match out.status.code() {
        Some(0) => Ok(text(&out.stdout)),
        Some(2) => Err(text(&out.stderr)),
        code => panic!("exit {code:?}: {}", text(&out.stderr)),
    }
}

#[test]
fn bounded_records_are_fitted_and_pivoted_by_hand() {
    let records = format!(
        "box 10 20 30  12 22 32  {RED}  fit 1 pivot center translate 0 0.5 0
sphere 5 5 5 2  {RED}  fit 1
torus 0 0 0  0 1 0  2 0.5  {RED}  pivot 0 -0.5 0
difference
  box -1 -1 -1  1 1 1  {RED}
  sphere 0 0 0 1.3  {RED}
end  fit 4 pivot center translate 0 2 0
intersection
  sphere 0 0 0 1  {RED}
  plane 0 0 0  0 1 0  {RED}
end  fit 1
"
    );
    let out = info(&records).unwrap();
    // The box: side 2 → 1, its centre at the origin, lifted 0.5. The sphere: side 4 → 1
    // about its centre (5, 5, 5). The torus: its point (0, −0.5, 0) to the origin, so it
    // stands on y = 0. The block: its first box, side 2 → 4, centred, lifted 2.
    for want in [
        "  1  box 1     box     -          [-0.5, 0, -0.5] to [0.5, 1, 0.5]\n",
        "  2  sphere 1  sphere  -          [4.5, 4.5, 4.5] to [5.5, 5.5, 5.5]\n",
        "  3  torus 1   torus   -          [-2.5, 0, -2.5] to [2.5, 1, 2.5]\n",
        "  4  csg 1     csg     -          [-2, 0, -2] to [2, 4, 2]\n",
    ] {
        assert!(out.contains(want), "{want}in\n{out}");
    }
    // The half ball below the plane is bounded: its box is the ball's (the plane adds
    // no bound), side 2 fitted to 1 about the origin.
    let half = "  5  csg 2     csg     -          [-0.5, -0.5, -0.5] to [0.5, 0.5, 0.5]\n";
    assert!(out.contains(half), "{out}");
}

#[test]
fn unbounded_records_refuse_them_where_they_are() {
    let e = info(&format!("plane 0 0 0  0 1 0  {RED}  fit 1\n")).unwrap_err();
    assert!(
        e.contains("DIR/scene.txt:3:")
            && e.contains("'fit' does not apply to a plane: it is unbounded"),
        "{e}"
    );
    let block =
        format!("union\n  plane 0 0 0  0 1 0  {RED}\n  sphere 0 1 0 1  {RED}\nend pivot center\n");
    let e = info(&block).unwrap_err();
    assert!(
        e.contains("DIR/scene.txt:3:1:") && e.contains("this union is unbounded"),
        "{e}"
    );
}
