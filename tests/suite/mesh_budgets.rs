//! Issue 57's mesh files that passed every limit and still took gigabytes, through
//! `raytrace`: a 256 MiB binary PLY whose header claims 268 M faces (empty lists: the
//! zero bytes after the header), and an OBJ of more empty `f` lines than the triangle
//! budget, are refused from their counts before anything is allocated for them; an OBJ
//! with an error on its last line of a million is located without parsing the file again.

use crate::support::raytrace;

const BASE: &str = "64 48  0 1 5  0 0.9 0  0 0  0 1 0 1
0 0 0  0 1 0   1 0.8 0.8 0.8   1 0 0 1 0 0
4 8 6  1 1 1  1
";

/// `raytrace` on a scene whose one record draws `name`: exit code and stderr.
fn refuse(dir: &std::path::Path, name: &str) -> String {
    let scene = dir.join("scene.txt");
    let record = format!("mesh \"{name}\" 1 1 1 1  0.7 0 0 1 0 0\n");
    std::fs::write(&scene, format!("{BASE}{record}")).unwrap();
    let png = dir.join("out.png");
    let out = raytrace().arg(&scene).arg("-o").arg(&png).output().unwrap();
    let stderr = String::from_utf8_lossy(&out.stderr).replace(&*dir.display().to_string(), "DIR");
    assert_eq!(out.status.code(), Some(2), "{stderr}");
    assert!(!png.exists() && !stderr.contains("panicked"), "{stderr}");
    stderr
}

#[test]
fn a_ply_claiming_268_million_faces_is_refused_from_its_header() {
    let dir = tempfile::tempdir().unwrap();
    let path = dir.path().join("empty-faces.ply");
    let header = "ply\nformat binary_little_endian 1.0\nelement vertex 3\nproperty float x\n\
property float y\nproperty float z\nelement face 268435456\n\
property list uchar int vertex_indices\nend_header\n";
    let mut bytes = header.as_bytes().to_vec();
    for c in [0f32, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 1.0, 0.0] {
        bytes.extend(c.to_le_bytes());
    }
    std::fs::write(&path, &bytes).unwrap();
    // The rest of 256 MiB is zeros (sparse on disk): 268 M faces of empty lists.
    let file = std::fs::OpenOptions::new().write(true).open(&path).unwrap();
    file.set_len(256 << 20).unwrap();
    let e = refuse(dir.path(), "empty-faces.ply");
    assert!(
        e.contains("DIR/empty-faces.ply: malformed PLY file: the header declares 268435456 faces, over the budget of 4194304 triangles a mesh"),
        "{e}"
    );
}

#[test]
fn an_obj_of_more_empty_faces_than_the_budget_is_refused_from_its_count() {
    let dir = tempfile::tempdir().unwrap();
    let mut text = b"v 0 0 0\nv 1 0 0\nv 0 1 0\n".to_vec();
    text.extend(b"f\n".repeat(4_200_000));
    std::fs::write(dir.path().join("empty.obj"), text).unwrap();
    let e = refuse(dir.path(), "empty.obj");
    assert!(
        e.contains("the file has 4200000 'f', 'l' and 'p' lines fanning into 0 triangles, over the budget of 4194304 triangles"),
        "{e}"
    );
}

#[test]
fn an_error_on_the_last_of_a_million_lines_is_located() {
    let dir = tempfile::tempdir().unwrap();
    let mut text = String::from("v 0 0 0\nv 1 0 0\nv 0 1 0\n");
    text += &"f 1 2 3\n".repeat(999_996);
    text += "f 1 2 x\n";
    std::fs::write(dir.path().join("late.obj"), text).unwrap();
    let e = refuse(dir.path(), "late.obj");
    assert!(
        e.contains("DIR/late.obj:1000000: malformed OBJ file: face parse error"),
        "{e}"
    );
}
