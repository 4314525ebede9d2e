//! A model's own data (SPEC §18) through `raytrace` and against POV-Ray 3.7: an OBJ card
//! with `vt` coordinates under the `uv` image map (POV-Ray: `mesh2` with `uv_vectors` and
//! a `uv_mapping` image), a PLY quad with `red green blue` vertex colours (POV-Ray:
//! `mesh2` with a `texture_list` per vertex), and an OBJ whose `.mtl` gives the colour
//! and a `map_Kd` picture, and whose `d` filters the shadow rays crossing its faces.
//! Bound as the other mesh comparisons.

use crate::image_povray::texture_picture;
use crate::mesh_povray::compare;
use crate::support::raytrace;

/// A card 1.8 wide and 1.5 high standing at z = 0, its image twice across (u 0..2).
const CARD: &str = "v -1.9 0.2 0\nv -0.1 0.2 0\nv -0.1 1.7 0\nv -1.9 1.7 0\n\
vt 0 0\nvt 2 0\nvt 2 1\nvt 0 1\nf 1/1 2/2 3/3 4/4\n";

const POV_CARD: &str =
    "mesh2 { vertex_vectors { 4, <-1.9, 0.2, 0>, <-0.1, 0.2, 0>, <-0.1, 1.7, 0>, <-1.9, 1.7, 0> }
uv_vectors { 4, <0, 0>, <2, 0>, <2, 1>, <0, 1> }
face_indices { 2, <0, 1, 2>, <0, 2, 3> }
uv_mapping pigment { image_map { png \"tex.png\" gamma 1.0 } } Fin(0.7) }
";

/// A quad to the right with a colour at each corner, as an ASCII PLY.
const QUAD_PLY: &str = "ply\nformat ascii 1.0\nelement vertex 4\nproperty float x\n\
property float y\nproperty float z\nproperty uchar red\nproperty uchar green\nproperty uchar blue\n\
element face 1\nproperty list uchar int vertex_indices\nend_header\n\
0.1 0.2 0 255 0 0\n1.9 0.2 0 0 255 0\n1.9 1.7 0 0 0 255\n0.1 1.7 0 255 255 0\n4 0 1 2 3\n";

const POV_QUAD: &str = "#declare C = array[4] { <1, 0, 0>, <0, 1, 0>, <0, 0, 1>, <1, 1, 0> }
mesh2 { vertex_vectors { 4, <0.1, 0.2, 0>, <1.9, 0.2, 0>, <1.9, 1.7, 0>, <0.1, 1.7, 0> }
texture_list { 4, #for (I, 0, 3) texture { pigment { rgb C[I] } Fin(0.7) } #end }
face_indices { 2, <0, 1, 2>, 0, 1, 2, <0, 2, 3>, 0, 2, 3 } }
";

#[test]
fn uv_coordinates_and_vertex_colours_match_mesh2() {
    let mut png = Vec::new();
    texture_picture()
        .write_to(&mut std::io::Cursor::new(&mut png), image::ImageFormat::Png)
        .unwrap();
    crate::support::povray::assert_close(compare(
        &[
            ("card.obj", CARD.as_bytes().to_vec()),
            ("quad.ply", QUAD_PLY.as_bytes().to_vec()),
            ("tex.png", png),
        ],
        "mesh \"card.obj\" 3 \"tex.png\" uv nearest 1  0.7 0 0 1 0 0\n\
         mesh \"quad.ply\" 1 1 1 1  0.7 0 0 1 0 0\n",
        &format!("{POV_CARD}{POV_QUAD}"),
    ));
}

const BASE: &str = "64 48  0 1 5  0 0.9 0  0 0  0 1 0 1
0 0 0  0 1 0   1 0.8 0.8 0.8   1 0 0 1 0 0
4 8 6  1 1 1  1
";

/// Runs `raytrace` on `records` in `dir`: exit code, stderr (the folder as DIR), and the
/// picture when one was written.
fn run(dir: &std::path::Path, records: &str) -> (i32, String, Option<image::RgbImage>) {
    let scene = dir.join("scene.txt");
    std::fs::write(&scene, format!("{BASE}{records}")).unwrap();
    let png = dir.join("out.png");
    let _ = std::fs::remove_file(&png);
    let out = raytrace().arg(&scene).arg("-o").arg(&png).output().unwrap();
    let stderr = String::from_utf8_lossy(&out.stderr).replace(&*dir.display().to_string(), "DIR");
    assert!(!stderr.contains("panicked"), "{stderr}");
    let img = png.exists().then(|| image::open(&png).unwrap().to_rgb8());
    (out.status.code().unwrap_or(-1), stderr, img)
}

#[test]
fn an_mtl_colours_its_faces_and_a_map_kd_paints_them() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    // A 1×1 green picture for map_Kd, a red Kd for the other material.
    image::RgbImage::from_pixel(1, 1, image::Rgb([0, 255, 0]))
        .save(d.join("green.png"))
        .unwrap();
    std::fs::write(
        d.join("two.mtl"),
        "newmtl red\nKd 1 0 0\nKs 0 0 0\nillum 1\nnewmtl pic\nKd 1 1 1\nmap_Kd green.png\nillum 1\n",
    )
    .unwrap();
    let obj = "mtllib two.mtl\nv -1.5 0.2 0\nv -0.1 0.2 0\nv -0.1 1.6 0\nv -1.5 1.6 0\n\
v 0.1 0.2 0\nv 1.5 0.2 0\nv 1.5 1.6 0\nv 0.1 1.6 0\nvt 0 0\n\
usemtl red\nf 1/1 2/1 3/1 4/1\nusemtl pic\nf 5/1 6/1 7/1 8/1\n";
    std::fs::write(d.join("two.obj"), obj).unwrap();
    // The record is blue: the file's materials replace it on both faces.
    let (code, stderr, img) = run(d, "mesh \"two.obj\" 1 0 0 1  0.7 0 0 1 0 0\n");
    assert_eq!(code, 0, "{stderr}");
    let img = img.unwrap();
    let (left, right) = (img.get_pixel(18, 24), img.get_pixel(46, 24));
    assert!(
        left[0] > 100 && left[1] < 30 && left[2] < 30,
        "left {left:?}"
    );
    assert!(
        right[1] > 100 && right[0] < 30 && right[2] < 30,
        "right {right:?}"
    );
    assert!(!stderr.contains("warning"), "{stderr}");
}

#[test]
fn the_uv_map_needs_coordinates_and_hostile_files_are_named() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    texture_picture().save(d.join("tex.png")).unwrap();
    let tri = "v 0 0 0\nv 1 0 0\nv 0 1 0\n";
    std::fs::write(d.join("plain.obj"), format!("{tri}f 1 2 3\n")).unwrap();
    let uv = "3 \"tex.png\" uv nearest 1  0.7 0 0 1 0 0";
    let (code, e, img) = run(d, &format!("sphere 0 1 0 1 {uv}\n"));
    assert!(code == 2 && img.is_none(), "{e}");
    assert!(
        e.contains("DIR/scene.txt:4:")
            && e.contains("the uv map takes a mesh's own texture coordinates: a sphere has none"),
        "{e}"
    );
    let (code, e, _) = run(d, &format!("mesh \"plain.obj\" {uv}\n"));
    assert!(
        code == 2
            && e.contains("DIR/scene.txt:4:1")
            && e.contains("plain.obj: the uv map needs the file's texture coordinates"),
        "{e}"
    );
    // An index past the vertices, a vt index past its list: located in the OBJ.
    let errors = [
        ("far.obj", format!("{tri}f 1 2 3\nf 1 2 9\n"), "DIR/far.obj:5: malformed OBJ file: the vertex index 9 is past the list (3 in the file)"),
        ("vt.obj", format!("{tri}vt 0 0\nf 1/1 2/1 3/2\n"), "DIR/vt.obj:5: malformed OBJ file: the texture coordinate (vt) index 2 is past the list (1 in the file)"),
        ("strips.ply", "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty float z\nelement tristrips 1\nproperty list int int vertex_indices\nend_header\n0 0 0\n1 0 0\n0 1 0\n4 -1 -1 -1 -1\n".to_string(), "DIR/strips.ply: the mesh has no triangle: its 1 triangle strips hold no three vertices in a row"),
    ];
    for (name, text, want) in errors {
        std::fs::write(d.join(name), text).unwrap();
        let (code, e, img) = run(d, &format!("mesh \"{name}\" 1 1 1 1  0.7 0 0 1 0 0\n"));
        assert!(
            code == 2 && img.is_none() && e.contains(want),
            "{name}: {e}"
        );
    }
    // A missing .mtl and a missing map_Kd: warnings that name them, and a picture.
    std::fs::write(d.join("m.mtl"), "newmtl a\nKd 1 0 0\nmap_Kd gone.png\n").unwrap();
    let obj = format!("mtllib gone.mtl\nmtllib m.mtl\n{tri}vt 0 0\nusemtl a\nf 1/1 2/1 3/1\n");
    std::fs::write(d.join("w.obj"), obj).unwrap();
    let (code, e, img) = run(d, "mesh \"w.obj\" 1 1 1 1  0.7 0 0 1 0 0\n");
    assert!(code == 0 && img.is_some(), "{e}");
    assert!(
        e.contains("raytrace: warning: DIR/w.obj: mtllib 'gone.mtl' cannot be read"),
        "{e}"
    );
    assert!(
        e.contains("raytrace: warning: DIR/w.obj: material 'a': map_Kd 'gone.png' cannot be read"),
        "{e}"
    );
}

/// A floor seen from the report's camera, lit by one light behind and above the camera;
/// the mesh record `mesh` (if any) hangs out of view between them, its shadow covering
/// the bottom of the picture.
fn shadow_scene(dir: &std::path::Path, mesh: &str) -> image::RgbImage {
    let scene = dir.join("shadow.txt");
    std::fs::write(
        &scene,
        format!(
            "64 48  0 1 5  0 0.9 0  0 0  0 1 0 1
0 0 0  0 1 0   1 0.8 0.8 0.8   1 0 0 1 0 0
0 10 10  1 1 1  1
{mesh}"
        ),
    )
    .unwrap();
    let png = dir.join("shadow.png");
    let out = raytrace().arg(&scene).arg("-o").arg(&png).output().unwrap();
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    image::open(&png).unwrap().to_rgb8()
}

#[test]
fn a_faces_own_d_filters_the_shadow_rays_that_cross_it() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    // A 2 × 2 card at y = 5 over z 4..6: its shadow from (0, 10, 10) covers the floor
    // from z = −2 to 2, x = −2 to 2 (the picture's bottom rows).
    let card = "v -1 5 4\nv 1 5 4\nv 1 5 6\nv -1 5 6\nusemtl m\nf 1 2 3 4\n";
    let mtl = |d: &str| format!("newmtl m\nKd 1 0 0\nKs 0 0 0\nillum 1\nd {d}\n");
    std::fs::write(d.join("card.obj"), format!("mtllib card.mtl\n{card}")).unwrap();
    // The record is opaque: only the file's `d` can let light through.
    let record = "mesh \"card.obj\" 1 1 1 1  0.7 0 0 1 0 0\n";
    let lit = shadow_scene(d, "");
    std::fs::write(d.join("card.mtl"), mtl("1")).unwrap();
    let dark = shadow_scene(d, record);
    std::fs::write(d.join("card.mtl"), mtl("0.5")).unwrap();
    let red = shadow_scene(d, record);
    let (x, y) = (32, 45);
    let (l, k, r) = (
        lit.get_pixel(x, y),
        dark.get_pixel(x, y),
        red.get_pixel(x, y),
    );
    assert!(
        l[1] > k[1] + 60,
        "the card shadows the floor: lit {l:?}, dark {k:?}"
    );
    // Kt = 1 − d = 0.5 and colour (1, 0, 0): the lights' terms halve in red, vanish in
    // green and blue; ambient stays.
    let half = (u16::from(l[0]) + u16::from(k[0])) / 2;
    assert!(
        u16::from(r[0]).abs_diff(half) <= 1,
        "red {r:?}: want {half} of lit {l:?}, dark {k:?}"
    );
    assert_eq!(
        (r[1], r[2]),
        (k[1], k[2]),
        "green and blue as in the full shadow"
    );
}
