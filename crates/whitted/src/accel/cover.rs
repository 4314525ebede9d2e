//! Shadow rays through a glTF mesh with coverage (`alphaMode` MASK or BLEND,
//! `mesh::extra`; SPEC §18). Such a mesh never blocks a shadow ray by itself: it is
//! crossed like a transparent object, every triangle kept (no copy merged), and each
//! crossing lets through what its point's alpha lets — all of the light where MASK
//! leaves the point out, (1 − α)·white + α·own through a BLEND point, `own` being what
//! the triangle's surface lets through by itself (Kt·C, black when opaque). Every other
//! object keeps its flags and its factor.

use super::{is_glass, is_opaque, Accel};
use crate::base::Color;
use crate::mesh::Mesh;
use crate::object::Object;
use crate::shapes::Shape;
use glam::DVec3;
use std::sync::Arc;

/// Whether `o` is a mesh with coverage.
fn covered(o: &Object, meshes: &[Arc<Mesh>]) -> bool {
    match &o.shape {
        Shape::Mesh(m) => meshes.get(m.id as usize).is_some_and(|m| m.has_coverage()),
        _ => false,
    }
}

/// Whether shadow rays cross `o` (Kt > 0, or a mesh with coverage) and whether they
/// stop at it (Kt ≤ 0 and no coverage).
pub(super) fn flags(o: &Object, meshes: &[Arc<Mesh>]) -> (bool, bool) {
    let covered = covered(o, meshes);
    (is_glass(o) || covered, is_opaque(o) && !covered)
}

/// Whether one of `objects` is a mesh with coverage.
pub(super) fn any(objects: &[Object], meshes: &[Arc<Mesh>]) -> bool {
    objects.iter().any(|o| covered(o, meshes))
}

impl Accel {
    /// What a shadow ray keeps crossing triangle `part` of mesh `id` (object `obj`) at
    /// `p`: Kt·C of the object, or on a mesh with coverage what the point's alpha lets
    /// through (`Mesh::shadow_through`) of the triangle's own Kt·C.
    pub(super) fn crossing(&self, obj: &Object, id: u32, part: u32, p: DVec3) -> Color {
        let mesh = &self.meshes[id as usize];
        if !mesh.has_coverage() {
            return obj.material.kt * obj.texture.color_at(p);
        }
        let surface = mesh.surface(part, p, &obj.texture, &obj.material);
        let kt = surface.material.kt;
        let own = if kt > 0.0 {
            kt * surface.texture.color_at(p)
        } else {
            Color::ZERO
        };
        mesh.shadow_through(part, p, own)
    }
}
