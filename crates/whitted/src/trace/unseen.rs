//! What camera rays do not see: the back faces of a glTF material that is not
//! `doubleSided` (SPEC §18). A camera ray that hits one is traced on past it, its
//! distances still the eye's (`alpha`'s walk); every other surface is two-sided. And
//! whether a secondary ray's hit needs that walk. Out of line and cold: only a glTF mesh
//! comes here.

use super::Tracer;
use crate::object::Object;
use crate::optics::Ray;

impl Tracer<'_> {
    /// Whether triangle `part` of mesh object `obj` is a back face that camera rays do
    /// not see (a glTF material that is not `doubleSided`; SPEC §18). Every other surface
    /// is two-sided.
    #[cold]
    #[inline(never)]
    pub(super) fn culled(&self, obj: &Object, part: u32, ray: &Ray) -> bool {
        let crate::shapes::Shape::Mesh(m) = &obj.shape else {
            return false;
        };
        let mesh = &self.scene.meshes[m.id as usize];
        if !mesh.single_sided {
            return false;
        }
        let [a, b, c] = mesh.corners(part);
        (b - a).cross(c - a).dot(ray.dir) > 0.0
    }

    /// Whether a secondary ray's hit on mesh object `obj` needs `alpha`'s walk: its mesh
    /// has coverage or an emissive texture (`Mesh::extra`).
    #[cold]
    #[inline(never)]
    pub(super) fn has_extra(&self, obj: &Object) -> bool {
        match &obj.shape {
            crate::shapes::Shape::Mesh(m) => self.scene.meshes[m.id as usize].extra.is_some(),
            _ => false,
        }
    }
}
