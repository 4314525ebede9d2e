//! The model's own data (SPEC §18) on small files written here: OBJ `vt`, vertex colours
//! and `.mtl` with every key read, PLY `u v`, colours and `tristrips`; the colour shading
//! sees at a hit, by hand; and hostile files, each refused with its cause or warned about.

use super::*;
use crate::base::Color;
use crate::object::Highlight;
use crate::shapes::Transform;
use crate::texture::Texture;
use glam::DVec3;

fn write(dir: &tempfile::TempDir, name: &str, bytes: &[u8]) -> std::path::PathBuf {
    let p = dir.path().join(name);
    std::fs::write(&p, bytes).unwrap();
    p
}

fn load(dir: &tempfile::TempDir, name: &str, bytes: &[u8]) -> Result<Mesh, String> {
    let p = write(dir, name, bytes);
    Mesh::load(&p, &Transform::IDENTITY, Some(Shading::Flat)).map_err(|e| {
        e.to_string()
            .replace(&*dir.path().display().to_string(), "DIR")
    })
}

/// A 2×1 PNG: red, then blue.
fn two_pixels() -> Vec<u8> {
    let img = image::RgbImage::from_raw(2, 1, vec![255, 0, 0, 0, 0, 255]).unwrap();
    let mut png = Vec::new();
    img.write_to(&mut std::io::Cursor::new(&mut png), image::ImageFormat::Png)
        .unwrap();
    png
}

const MTL: &str = "newmtl shiny\nKa 0.1 0.1 0.1\nKd 0.5 0.25 1\nKs 0.3 0.6 0.9\nNs 40\n\
d 0.75\nNi 1.5\nillum 3\nnewmtl picture\nKd 1 1 1\nmap_Kd two.png\nTr 0.2\nillum 1\n";

#[test]
fn obj_coordinates_colours_and_every_mtl_key() {
    let dir = tempfile::tempdir().unwrap();
    write(&dir, "m.mtl", MTL.as_bytes());
    write(&dir, "two.png", &two_pixels());
    let obj = "mtllib m.mtl\nv 0 0 0 1 0.5 0\nv 1 0 0 1 1 1\nv 0 1 0 0 0 1\nv 1 1 0 1 1 1\n\
vt 0 0\nvt 1 0\nvt 0 1\nusemtl shiny\nf 1/1 2/2 3/3\nusemtl picture\nf 2/2 4/2 3/3\n";
    let m = load(&dir, "m.obj", obj.as_bytes()).unwrap();
    assert_eq!(m.uvs.len(), m.vertices.len());
    assert_eq!(m.colors[0], DVec3::new(1.0, 0.5, 0.0));
    assert_eq!(m.face_looks, vec![0, 1]);
    let shiny = &m.looks[0];
    assert_eq!(shiny.texture, Texture::Uniform(DVec3::new(0.5, 0.25, 1.0)));
    // Ks mean (0.3 + 0.6 + 0.9)/3 = 0.6: the highlight, and the mirror (illum 3);
    // Kt = 1 − d = 0.25, Ior = Ni.
    let mat = shiny.material;
    assert!((mat.kr - 0.6).abs() < 1e-15 && mat.kd == 1.0);
    assert_eq!((mat.kt, mat.ior), (0.25, 1.5));
    assert!(
        matches!(mat.highlight, Highlight::Phong { ks, shine } if (ks - 0.6).abs() < 1e-15 && shine == 40.0)
    );
    // The picture: Tr 0.2 (Kt 0.2), illum 1 (no highlight, no mirror), map_Kd on uv.
    let pic = &m.looks[1];
    assert!(matches!(&pic.texture, Texture::Image(i) if i.map == crate::texture::MapKind::Uv));
    assert!((pic.material.kt - 0.2).abs() < 1e-15 && pic.material.kr == 0.0);
    assert!(matches!(pic.material.highlight, Highlight::Phong { ks, .. } if ks == 0.0));
    // Ka is read past, and said so.
    assert!(
        m.warnings.iter().any(|w| w.contains("material keys Ka")),
        "{:?}",
        m.warnings
    );
}

#[test]
fn the_colour_at_a_hit_by_hand() {
    let dir = tempfile::tempdir().unwrap();
    write(&dir, "m.mtl", MTL.as_bytes());
    write(&dir, "two.png", &two_pixels());
    let obj = "mtllib m.mtl\nv 0 0 0 1 0.5 0\nv 1 0 0 1 1 1\nv 0 1 0 0 0 1\nv 1 1 0 1 1 1\n\
vt 0 0\nvt 1 0\nvt 0 1\nusemtl shiny\nf 1/1 2/2 3/3\nusemtl picture\nf 2/2 4/2 3/3\n";
    let m = load(&dir, "m.obj", obj.as_bytes()).unwrap();
    let record = (Texture::Uniform(Color::ONE), m.looks[0].material);
    // Face 0 at its centroid: Kd (0.5, 0.25, 1) times the mean of the three vertex
    // colours ((1,0.5,0) + (1,1,1) + (0,0,1))/3 = (2/3, 1/2, 2/3).
    let c = DVec3::new(1.0, 1.0, 0.0) / 3.0;
    let hit = m.surface(0, c, &record.0, &record.1);
    let Texture::Uniform(got) = hit.texture else {
        panic!("{:?}", hit.texture)
    };
    assert!(
        (got - DVec3::new(1.0 / 3.0, 0.125, 2.0 / 3.0)).length() < 1e-12,
        "{got}"
    );
    // Face 1 (the file's vertices 2, 4, 3 with vt 2, 2, 3) at the point of weights
    // (0.3, 0.6, 0.1): (u, v) = 0.3·(1,0) + 0.6·(1,0) + 0.1·(0,1) = (0.9, 0.1). Bilinear
    // at x = 0.9·2 − 0.5 = 1.3 blends blue (0.7) and, wrapping, red (0.3): (0.3, 0, 0.7);
    // times the vertex colours 0.3·(1,1,1) + 0.6·(1,1,1) + 0.1·(0,0,1) = (0.9, 0.9, 1):
    // (0.27, 0, 0.7). The face's material is the file's.
    let p = 0.3 * m.vertices[1] + 0.6 * DVec3::new(1.0, 1.0, 0.0) + 0.1 * DVec3::Y;
    let hit = m.surface(1, p, &record.0, &record.1);
    let Texture::Uniform(got) = hit.texture else {
        panic!("{:?}", hit.texture)
    };
    assert!((got - DVec3::new(0.27, 0.0, 0.7)).length() < 1e-6, "{got}");
    assert_eq!(hit.material, m.looks[1].material);
}

#[test]
fn ply_coordinates_colours_and_strips() {
    let dir = tempfile::tempdir().unwrap();
    let ply = "ply\nformat ascii 1.0\nelement vertex 4\nproperty float x\nproperty float y\n\
property float z\nproperty float s\nproperty float t\nproperty uchar red\nproperty uchar green\n\
property uchar blue\nproperty float confidence\nelement tristrips 1\n\
property list int int vertex_indices\nelement edge 2\nproperty int vertex1\nproperty int vertex2\n\
end_header\n0 0 0 0 0 255 0 51 1\n1 0 0 1 0 255 255 255 1\n0 1 0 0 1 0 0 0 1\n1 1 0 1 1 0 0 0 1\n\
6 0 1 2 3 -1 -1\n0 1\n1 2\n";
    let m = load(&dir, "s.ply", ply.as_bytes()).unwrap();
    assert_eq!(m.triangles, vec![[0, 1, 2], [2, 1, 3]]);
    assert_eq!(m.uvs[3], [1.0, 1.0]);
    assert_eq!(m.colors[0], DVec3::new(1.0, 0.0, 0.2));
    let w = m.warnings.join("\n");
    assert!(
        w.contains("vertex property 'confidence'") && w.contains("element 'edge' (2 of them)"),
        "{w}"
    );
}

const HEAD: &str = "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n\
property float z\n";

#[test]
fn hostile_ply_files_name_their_cause() {
    let dir = tempfile::tempdir().unwrap();
    let e = |body: &str| load(&dir, "h.ply", format!("{HEAD}{body}").as_bytes()).unwrap_err();
    let verts = "0 0 0\n1 0 0\n0 1 0\n";
    let face = "property list uchar int vertex_indices\nend_header\n";
    // 268 M empty faces: refused from the header, before one is read.
    let msg = e(&format!("element face 268435456\n{face}{verts}"));
    assert!(
        msg.contains("declares 268435456 faces, over the budget"),
        "{msg}"
    );
    let msg = e(&format!("end_header\n{verts}"));
    assert!(
        msg.contains("no face or tristrips element (points only)"),
        "{msg}"
    );
    let msg = e(&format!("element face 0\n{face}{verts}"));
    assert!(msg.contains("declares 0 faces"), "{msg}");
    let msg = e(&format!(
        "element face 1\nproperty list uchar float vertex_indices\nend_header\n{verts}3 0 1 2\n"
    ));
    assert!(msg.contains("list of floating-point numbers"), "{msg}");
    let msg = e(&format!(
        "element face 1\nproperty int vertex_indices\nend_header\n{verts}0\n"
    ));
    assert!(msg.contains("a single number, not a list"), "{msg}");
    let msg = e(&format!(
        "element face 1\n{face}0 0 0\nnan 0 0\n0 1 0\n3 0 1 2\n"
    ));
    // ASCII has no word for NaN: the crate refuses the line; binary can hold one.
    assert!(
        msg.contains("h.ply:11:") && msg.contains("'nan 0 0'"),
        "{msg}"
    );
    let mut bin = HEAD.replace("ascii", "binary_little_endian").into_bytes();
    bin.extend(b"element face 1\nproperty list uchar int vertex_indices\nend_header\n");
    for c in [0f32, 0.0, 0.0, f32::NAN, 0.0, 0.0, 0.0, 1.0, 0.0] {
        bin.extend(c.to_le_bytes());
    }
    bin.push(3);
    [0i32, 1, 2]
        .iter()
        .for_each(|i| bin.extend(i.to_le_bytes()));
    let msg = load(&dir, "nan.ply", &bin).unwrap_err();
    assert!(msg.contains("vertex 1 is at (NaN 0 0): not three"), "{msg}");
    let msg = e(&format!(
        "element face 1\n{face}0 0 0\n1e400 0 0\n0 1 0\n3 0 1 2\n"
    ));
    assert!(
        msg.contains("h.ply:11: ") && msg.contains("(inf 0 0)"),
        "{msg}"
    );
    let strips = "element tristrips 1\nproperty list int int vertex_indices\nend_header\n";
    let msg = e(&format!("{strips}{verts}3 -1 -1 -1\n"));
    assert!(
        msg.contains("no triangle: its 1 triangle strips hold no three vertices"),
        "{msg}"
    );
    let msg = e(&format!("element face 2\n{face}{verts}2 0 1\n1 2\n"));
    assert!(
        msg.contains("each of its 2 faces has fewer than three vertices"),
        "{msg}"
    );
}

#[test]
fn hostile_obj_files_name_their_cause() {
    let dir = tempfile::tempdir().unwrap();
    let e = |s: &str| load(&dir, "h.obj", s.as_bytes()).unwrap_err();
    let tri = "v 0 0 0\nv 1 0 0\nv 0 1 0\n";
    // A byte-order mark is read past.
    let m = load(
        &dir,
        "bom.obj",
        format!("\u{feff}{tri}f 1 2 3\n").as_bytes(),
    )
    .unwrap();
    assert_eq!(m.triangles.len(), 1);
    assert!(e(tri).contains("no triangle: the OBJ file has no faces ('f' lines)"));
    let msg = e(&format!("{tri}f\nf 1 2\n"));
    assert!(
        msg.contains("each of its 2 'f' lines has fewer than three corners"),
        "{msg}"
    );
    let msg = e(&format!("{tri}vt 0 0\nf 1/1 2/1 3/1\nf 1/1 2/2 3/1\n"));
    assert!(
        msg.contains("h.obj:6:")
            && msg.contains("texture coordinate (vt) index 2 is past the list"),
        "{msg}"
    );
    let msg = e(&format!("{tri}f 1 2 3\nf 1 2 4\n"));
    assert!(
        msg.contains("h.obj:5:") && msg.contains("vertex index 4 is past the list"),
        "{msg}"
    );
    let msg = e("v 0 0 0\nv 1e400 0 0\nv 0 1 0\nf 1 2 3\n");
    assert!(
        msg.contains("h.obj:2:") && msg.contains("not a finite number"),
        "{msg}"
    );
    let msg = e("v 0 0 0\nv 1 0 0\nv 0 one 0\nf 1 2 3\n");
    assert!(
        msg.contains("h.obj:3: malformed OBJ file: position parse error"),
        "{msg}"
    );
    // A missing .mtl or map_Kd, and what is read past: warnings that name them.
    let src = format!("mtllib gone.mtl\n{tri}s 1\nl 1 2\nf 1 2 3\n");
    let m = load(&dir, "w.obj", src.as_bytes()).unwrap();
    let w = m.warnings.join("\n");
    assert!(w.contains("mtllib 'gone.mtl' cannot be read"), "{w}");
    assert!(w.contains("w.obj:5: not used: 1 's' statement(s)"), "{w}");
    assert!(w.contains("1 'l' and 'p' lines"), "{w}");
    write(&dir, "m.mtl", b"newmtl a\nKd 1 0 0\nmap_Kd nowhere.png\n");
    let src = format!("mtllib m.mtl\n{tri}vt 0 0\nusemtl a\nf 1/1 2/1 3/1\n");
    let m = load(&dir, "x.obj", src.as_bytes()).unwrap();
    assert!(
        m.warnings
            .iter()
            .any(|w| w.contains("map_Kd 'nowhere.png' cannot be read")),
        "{:?}",
        m.warnings
    );
    assert_eq!(m.looks[0].texture, Texture::Uniform(DVec3::X));
    // A usemtl of a name no .mtl defines: named once, with its first line.
    let src = format!("mtllib m.mtl\n{tri}usemtl b\nf 1 2 3\nusemtl b\nf 1 2 3\n");
    let m = load(&dir, "y.obj", src.as_bytes()).unwrap();
    let w: Vec<&String> = m.warnings.iter().filter(|w| w.contains("usemtl")).collect();
    assert_eq!(w.len(), 1, "{:?}", m.warnings);
    assert!(
        w[0].contains("y.obj:5: usemtl 'b' names no material"),
        "{}",
        w[0]
    );
    // A usemtl before the mtllib that defines it: tobj leaves its faces the record's.
    let src = format!(
        "{tri}usemtl a
f 1 2 3
mtllib m.mtl
"
    );
    let m = load(&dir, "z.obj", src.as_bytes()).unwrap();
    let w: Vec<&String> = m.warnings.iter().filter(|w| w.contains("usemtl")).collect();
    assert_eq!(w.len(), 1, "{:?}", m.warnings);
    assert!(
        w[0].contains("z.obj:4: usemtl 'a' comes before every mtllib line"),
        "{}",
        w[0]
    );
    assert!(
        m.face_looks.iter().all(|&k| k == RECORD_LOOK),
        "{:?}",
        m.face_looks
    );
}
