//! The loaders on small files written here, fanning, frames, limits and errors, and the
//! smooth normal by hand.

use super::*;
use crate::shapes::Transform;
use glam::DVec3;

fn write(dir: &tempfile::TempDir, name: &str, bytes: &[u8]) -> std::path::PathBuf {
    let p = dir.path().join(name);
    std::fs::write(&p, bytes).unwrap();
    p
}

/// A unit square in z = 0 as one quad, with normals tilted apart.
const QUAD_OBJ: &str = "# a quad\nv 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\n\
vn -1 0 1\nvn 1 0 1\nvn 1 0 1\nvn -1 0 1\nf 1//1 2//2 3//3 4//4\n";

#[test]
fn obj_quad_is_fanned_and_smooth() {
    let dir = tempfile::tempdir().unwrap();
    let m = Mesh::load(
        &write(&dir, "q.obj", QUAD_OBJ.as_bytes()),
        &Transform::IDENTITY,
        None,
    )
    .unwrap();
    assert_eq!(m.triangles, vec![[0, 1, 2], [0, 2, 3]]);
    assert_eq!(m.normals.len(), 4);
    let s = std::f64::consts::FRAC_1_SQRT_2;
    assert!((m.normals[0] - DVec3::new(-s, 0.0, s)).length() < 1e-15);
}

#[test]
fn obj_without_normals_is_smooth_30_unless_flat() {
    let dir = tempfile::tempdir().unwrap();
    // One face: smooth 30 gives each corner the face's normal; `flat` keeps none.
    let src = "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n";
    let p = write(&dir, "t.OBJ", src.as_bytes());
    let m = Mesh::load(&p, &Transform::IDENTITY, None).unwrap();
    assert_eq!(m.normals, vec![DVec3::Z; 3]);
    assert_eq!(m.shape(0).normal(DVec3::new(0.2, 0.2, 0.0)), DVec3::Z);
    let m = Mesh::load(&p, &Transform::IDENTITY, Some(Shading::Flat)).unwrap();
    assert!(m.normals.is_empty());
    // A crease of 40°: split at 30 (two copies of the edge's vertices), joined at 45.
    let (s, c) = 40f64.to_radians().sin_cos();
    let src = format!(
        "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 {} {}\nf 1 2 3\nf 2 1 4\n",
        -c, s
    );
    let p = write(&dir, "crease.obj", src.as_bytes());
    let m = Mesh::load(&p, &Transform::IDENTITY, None).unwrap();
    assert_eq!(m.vertices.len(), 6);
    let m = Mesh::load(&p, &Transform::IDENTITY, Some(Shading::Smooth(45.0))).unwrap();
    assert_eq!(m.vertices.len(), 4);
}

#[test]
fn smooth_normal_by_hand() {
    // Corner normals (−1,0,1)/√2 at (0,0,0), (1,0,1)/√2 at (1,0,0) and (1,1,0); the
    // point (0.5, 0.25, 0) of the first triangle has barycentric u = 0.25 (towards B),
    // v = 0.25 (towards C), so weights 0.5, 0.25, 0.25: the sum is (0, 0, 1)/√2 → +z.
    let dir = tempfile::tempdir().unwrap();
    let m = Mesh::load(
        &write(&dir, "q.obj", QUAD_OBJ.as_bytes()),
        &Transform::IDENTITY,
        None,
    )
    .unwrap();
    let n = m.shape(0).normal(DVec3::new(0.5, 0.25, 0.0));
    assert!((n - DVec3::Z).length() < 1e-15, "{n}");
    // At (0.75, 0.25): u = 0.5, v = 0.25, weights 0.25, 0.5, 0.25: (0.5, 0, 1)/√2,
    // normalised (1, 0, 2)/√5.
    let n = m.shape(0).normal(DVec3::new(0.75, 0.25, 0.0));
    let want = DVec3::new(1.0, 0.0, 2.0) / 5f64.sqrt();
    assert!((n - want).length() < 1e-15, "{n}");
}

#[test]
fn frame_moves_vertices_and_normals() {
    let dir = tempfile::tempdir().unwrap();
    let f = Transform::new(
        DVec3::new(2.0, 1.0, 1.0),
        DVec3::ZERO,
        DVec3::new(0.0, 0.0, 5.0),
    )
    .unwrap();
    let m = Mesh::load(&write(&dir, "q.obj", QUAD_OBJ.as_bytes()), &f, None).unwrap();
    assert_eq!(m.vertices[2], DVec3::new(2.0, 1.0, 5.0));
    // (−1, 0, 1) by the inverse transpose diag(1/2, 1, 1): (−1/2, 0, 1), normalised.
    let want = DVec3::new(-0.5, 0.0, 1.0).normalize();
    assert!((m.normals[0] - want).length() < 1e-15);
}

#[test]
fn ascii_ply_with_a_pentagon() {
    let src = "ply\nformat ascii 1.0\nelement vertex 5\nproperty float x\nproperty float y\n\
property float z\nelement face 1\nproperty list uchar int vertex_indices\nend_header\n\
0 0 0\n1 0 0\n1.5 1 0\n0.5 1.5 0\n-0.5 1 0\n5 0 1 2 3 4\n";
    let dir = tempfile::tempdir().unwrap();
    let m = Mesh::load(
        &write(&dir, "p.ply", src.as_bytes()),
        &Transform::IDENTITY,
        None,
    )
    .unwrap();
    assert_eq!(m.triangles, vec![[0, 1, 2], [0, 2, 3], [0, 3, 4]]);
    // No normals in the file: smooth 30, and a flat pentagon's normal is its own.
    assert_eq!(m.normals, vec![DVec3::Z; 5]);
}

#[test]
fn binary_ply_with_normals() {
    let mut b = b"ply\nformat binary_little_endian 1.0\nelement vertex 3\nproperty double x\n\
property double y\nproperty double z\nproperty float nx\nproperty float ny\nproperty float nz\n\
element face 1\nproperty list uchar uint vertex_indices\nend_header\n"
        .to_vec();
    for p in [[0.0f64, 0.0, 0.0], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0]] {
        p.iter().for_each(|c| b.extend(c.to_le_bytes()));
        [0.0f32, 0.0, 2.0]
            .iter()
            .for_each(|c| b.extend(c.to_le_bytes()));
    }
    b.push(3);
    [0u32, 1, 2].iter().for_each(|i| b.extend(i.to_le_bytes()));
    let dir = tempfile::tempdir().unwrap();
    let m = Mesh::load(&write(&dir, "b.ply", &b), &Transform::IDENTITY, None).unwrap();
    assert_eq!(m.triangles, vec![[0, 1, 2]]);
    assert_eq!(m.normals, vec![DVec3::Z; 3]);
}

fn error(name: &str, bytes: &[u8]) -> String {
    let dir = tempfile::tempdir().unwrap();
    let p = write(&dir, name, bytes);
    Mesh::load(&p, &Transform::IDENTITY, None)
        .unwrap_err()
        .to_string()
        .replace(&*dir.path().display().to_string(), "DIR")
}

#[test]
fn errors_name_the_file_and_line() {
    let e = error("bad.obj", b"v 0 0 0\nv 1 0 0\nv 0 1 0\nv 1 x 0\nf 1 2 3\n");
    assert_eq!(e, "DIR/bad.obj:4: malformed OBJ file: position parse error");
    let e = error("far.obj", b"v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 7\n");
    assert!(e.starts_with("DIR/far.obj:4: malformed OBJ file"), "{e}");
    let e = error(
        "bad.ply",
        b"ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\nproperty float y\n\
property float z\nelement face 1\nproperty list uchar int vertex_indices\nend_header\nq\n",
    );
    assert!(e.starts_with("DIR/bad.ply:10: malformed PLY file"), "{e}");
    let e = error(
        "idx.ply",
        b"ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\n\
property float y\nproperty float z\nelement face 1\nproperty list uchar int vertex_indices\n\
end_header\n0 0 0\n1 0 0\n0 1 0\n3 0 1 3\n",
    );
    assert_eq!(
        e,
        "DIR/idx.ply:13: malformed PLY file: face 0: vertex index 3 out of range (3 vertices)"
    );
    let e = error("flat.obj", b"v 0 0 0\nv 1 0 0\nv 2 0 0\nf 1 2 3\n");
    assert_eq!(
        e,
        "DIR/flat.obj: the mesh has no triangle of non-zero area (its 1 triangles are all degenerate)"
    );
    let e = error("m.stl", b"solid\n");
    assert!(e.contains("unknown mesh format"), "{e}");
    let dir = tempfile::tempdir().unwrap();
    let e = Mesh::load(&dir.path().join("gone.obj"), &Transform::IDENTITY, None).unwrap_err();
    assert!(
        e.to_string()
            .contains("gone.obj: cannot read the mesh file"),
        "{e}"
    );
}

#[test]
fn the_triangle_limit_holds() {
    let mut raw = Raw::default();
    let face: Vec<u32> = (0..3).collect();
    for _ in 0..MAX_MESH_TRIANGLES {
        raw.triangles.push([0, 1, 2]);
    }
    assert!(!raw.over_limit());
    raw.fan(&face, 3).unwrap();
    assert!(raw.over_limit());
}

#[test]
fn fit_and_pivot_by_hand() {
    // A box from (10, 10, 10) to (14, 12, 11): centre (12, 11, 10.5), largest side 4.
    let raw = || Raw {
        positions: vec![
            DVec3::new(10.0, 10.0, 10.0),
            DVec3::new(14.0, 10.0, 10.0),
            DVec3::new(14.0, 12.0, 11.0),
        ],
        triangles: vec![[0, 1, 2]],
        ..Raw::default()
    };
    let at = |placing: Placing| {
        let mut r = raw();
        place(&mut r, &placing).unwrap();
        r.positions
    };
    // fit 2: f = 0.5 about the centre: (10,10,10) → (12,11,10.5) + 0.5·(−2,−1,−0.5).
    let p = at(Placing {
        fit: Some(2.0),
        pivot: None,
    });
    assert_eq!(p[0], DVec3::new(11.0, 10.5, 10.25));
    // pivot center: the centre at the origin, then f: (10,10,10) → 0.5·(−2,−1,−0.5).
    let p = at(Placing {
        fit: Some(2.0),
        pivot: Some(Pivot::Center),
    });
    assert_eq!(p[0], DVec3::new(-1.0, -0.5, -0.25));
    // pivot at the bottom corner's middle (12, 10, 10), no fit: p − q.
    let q = DVec3::new(12.0, 10.0, 10.0);
    let p = at(Placing {
        fit: None,
        pivot: Some(Pivot::Point(q)),
    });
    assert_eq!(p[2], DVec3::new(2.0, 2.0, 1.0));
    // Nothing asked: the file's own units, untouched.
    assert_eq!(at(Placing::default()), raw().positions);
    let mut flat = Raw {
        positions: vec![DVec3::ONE; 3],
        triangles: vec![[0, 1, 2]],
        ..Raw::default()
    };
    assert!(place(
        &mut flat,
        &Placing {
            fit: Some(1.0),
            pivot: None
        }
    )
    .is_err());
}
