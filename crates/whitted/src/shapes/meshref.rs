//! A mesh as one object of the scene: which of the scene's meshes it is (`Scene::meshes`)
//! and its box. The triangles themselves are primitives of the accelerator's tree
//! (`accel`), which finds the triangle a ray hits and hands shading that triangle as a
//! shape of its own (`Mesh::shape`); so this shape answers no ray by itself: a mesh
//! object's `roots` are empty and its `normal` is never asked (see `Shape::Mesh`).

use glam::DVec3;

/// The handle of a mesh object: its index in the scene's meshes and its box.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct MeshRef {
    /// The index in `Scene::meshes`.
    pub id: u32,
    /// The low corner of the box around its triangles.
    pub lo: DVec3,
    /// The high corner.
    pub hi: DVec3,
}
