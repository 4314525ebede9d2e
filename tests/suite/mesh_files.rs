//! The `mesh` record through the built `raytrace`: a mesh renders the same bytes on one
//! thread and on two, from OBJ and from binary PLY; a missing, malformed, empty or
//! degenerate mesh file is a located error (the record's file:line:column and the mesh
//! file's own location), exit 2, no image, no panic.

use crate::support::raytrace;
use std::path::Path;

/// Camera, floor, light; extension records follow.
const BASE: &str = "96 72  0 3 7  0 0.9 0  0 0  0 1 0 1
0 0 0  0 1 0   1 0.8 0.8 0.8   1 0 0 1 0 0
4 8 6  1 1 1  1
";

/// A pyramid of a square base (a quad, fanned) and four sides, with normals.
const PYRAMID: &str = "v -1 0 -1\nv 1 0 -1\nv 1 0 1\nv -1 0 1\nv 0 1.5 0\n\
vn -1 0.3 -1\nvn 1 0.3 -1\nvn 1 0.3 1\nvn -1 0.3 1\nvn 0 1 0\n\
f 1//1 2//2 3//3 4//4\nf 1//1 5//5 2//2\nf 2//2 5//5 3//3\nf 3//3 5//5 4//4\nf 4//4 5//5 1//1\n";

/// A binary PLY of the same pyramid (flat: no normals).
fn pyramid_ply() -> Vec<u8> {
    let mut b = b"ply\nformat binary_little_endian 1.0\nelement vertex 5\nproperty float x\n\
property float y\nproperty float z\nelement face 5\nproperty list uchar int vertex_indices\n\
end_header\n"
        .to_vec();
    for p in [
        [-1.0f32, 0.0, -1.0],
        [1.0, 0.0, -1.0],
        [1.0, 0.0, 1.0],
        [-1.0, 0.0, 1.0],
        [0.0, 1.5, 0.0],
    ] {
        p.iter().for_each(|c| b.extend(c.to_le_bytes()));
    }
    for f in [
        &[0i32, 1, 2, 3][..],
        &[0, 4, 1],
        &[1, 4, 2],
        &[2, 4, 3],
        &[3, 4, 0],
    ] {
        b.push(f.len() as u8);
        f.iter().for_each(|i| b.extend(i.to_le_bytes()));
    }
    b
}

fn render(dir: &Path, records: &str, threads: &str) -> std::process::Output {
    let scene = dir.join("scene.txt");
    std::fs::write(&scene, format!("{BASE}{records}")).unwrap();
    let out = dir.join(format!("out-{threads}.png"));
    raytrace()
        .arg(&scene)
        .arg("-o")
        .arg(&out)
        .args(["--threads", threads])
        .output()
        .unwrap()
}

#[test]
fn a_mesh_renders_the_same_bytes_on_one_and_two_threads() {
    let dir = tempfile::tempdir().unwrap();
    std::fs::create_dir(dir.path().join("models")).unwrap();
    std::fs::write(dir.path().join("models/pyramid.obj"), PYRAMID).unwrap();
    std::fs::write(dir.path().join("pyramid.ply"), pyramid_ply()).unwrap();
    let records = "mesh \"models/pyramid.obj\" 1 0.9 0.3 0.2  0.7 0.3 0 1 0 0 name tent translate -1.2 0 0\n\
                   mesh \"pyramid.ply\" 1 0.2 0.5 0.9  0.5 0 0.5 1.3 0 0 rotate 0 30 0 translate 1.2 0 0.5\n";
    let mut frames = Vec::new();
    for threads in ["1", "2"] {
        let out = render(dir.path(), records, threads);
        assert!(
            out.status.success(),
            "{}",
            String::from_utf8_lossy(&out.stderr)
        );
        frames.push(std::fs::read(dir.path().join(format!("out-{threads}.png"))).unwrap());
    }
    assert_eq!(frames[0], frames[1], "1 and 2 threads differ");
    // Both meshes are drawn: red and blue pixels in the picture.
    let img = image::load_from_memory(&frames[0]).unwrap().to_rgb8();
    let red = img
        .pixels()
        .filter(|p| p[0] > 2 * p[2] && p[0] > 60)
        .count();
    let blue = img
        .pixels()
        .filter(|p| p[2] > 2 * p[0] && p[2] > 60)
        .count();
    assert!(red > 200 && blue > 200, "red {red}, blue {blue}");
}

/// The error of a scene whose one record is `mesh "NAME"` with `NAME` holding `bytes`
/// (none: missing); checks exit 2, no image, no panic, the record's location.
fn error_of(name: &str, bytes: Option<&[u8]>) -> String {
    let dir = tempfile::tempdir().unwrap();
    if let Some(b) = bytes {
        std::fs::write(dir.path().join(name), b).unwrap();
    }
    let out = render(
        dir.path(),
        &format!("mesh \"{name}\" 1 1 1 1  1 0 0 1 0 0\n"),
        "1",
    );
    let stderr =
        String::from_utf8_lossy(&out.stderr).replace(&*dir.path().display().to_string(), "DIR");
    assert_eq!(out.status.code(), Some(2), "{stderr}");
    assert!(
        !dir.path().join("out-1.png").exists(),
        "an image was written"
    );
    assert!(!stderr.contains("panicked"), "{stderr}");
    assert!(stderr.contains("DIR/scene.txt:4:1"), "{stderr}");
    stderr
}

#[test]
fn bad_mesh_files_are_located_errors() {
    let e = error_of("gone.obj", None);
    assert!(e.contains("DIR/gone.obj: cannot read the mesh file"), "{e}");
    let e = error_of("bad.obj", Some(b"v 0 0 0\nv 1 0 0\nv 0 one 0\nf 1 2 3\n"));
    assert!(e.contains("DIR/bad.obj:3: malformed OBJ file"), "{e}");
    let e = error_of(
        "bad.ply",
        Some(
            b"ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\nproperty float y\n\
property float z\nelement face 1\nproperty list uchar int vertex_indices\nend_header\nz\n",
        ),
    );
    assert!(e.contains("DIR/bad.ply:10: malformed PLY file"), "{e}");
    let e = error_of("line.obj", Some(b"v 0 0 0\nv 1 1 1\nv 2 2 2\nf 1 2 3\n"));
    assert!(
        e.contains("DIR/line.obj: the mesh has no triangle of non-zero area"),
        "{e}"
    );
    let e = error_of("empty.ply", Some(b""));
    assert!(e.contains("DIR/empty.ply"), "{e}");
}
