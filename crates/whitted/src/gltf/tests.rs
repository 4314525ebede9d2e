//! The reader on the Khronos samples kept in tests/data/gltf (their licences are in
//! tests/data/gltf/LICENSE.md), with values checked by hand against the files' JSON.

use super::*;
use std::path::PathBuf;

fn sample(name: &str) -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR"))
        .join("../../tests/data/gltf")
        .join(name)
}

fn rig(name: &str) -> Arc<Rig> {
    let path = sample(name);
    let bytes = std::fs::read(&path).unwrap();
    Model::read(&path, &bytes, Options::default()).unwrap().rig
}

#[test]
fn box_reads_its_24_vertices_and_12_triangles() {
    let rig = rig("Box.gltf");
    let prim = &rig.meshes[0][0];
    assert_eq!(prim.positions.len(), 24);
    assert_eq!(prim.normals.len(), 24);
    assert_eq!(prim.triangles.len(), 12);
}
