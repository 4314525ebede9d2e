//! What camera rays do not see: the back faces of a glTF material that is not
//! `doubleSided` (SPEC §18). A camera ray that hits one is traced on past it, its
//! distances still the eye's; every other surface is two-sided. Out of line and cold:
//! only a glTF mesh comes here.

use super::{RayCount, Tracer};
use crate::accel::NO_PART;
use crate::base::Color;
use crate::object::Object;
use crate::optics::Ray;
use crate::record::Record;

impl Tracer<'_> {
    /// A camera ray's colour past a back face it does not see at `t` (out of line: only
    /// a glTF mesh comes here).
    #[cold]
    #[inline(never)]
    pub(super) fn primary_past<R: Record>(
        &self,
        t: f64,
        ray: &Ray,
        count: &mut RayCount,
        rec: &mut R,
    ) -> Color {
        let hit = self.past_culled(ray, t);
        self.primary_shade(hit, None, ray, count, rec)
    }

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

    /// The first hit of a camera ray past back faces it does not see: the same ray, its
    /// hits counted only past the one culled (distances stay the eye's).
    #[cold]
    #[inline(never)]
    fn past_culled(&self, ray: &Ray, mut t: f64) -> Option<(f64, usize, u32)> {
        let objects = &self.scene.objects;
        // A bound on the surfaces passed, against a pathological file.
        for _ in 0..1024 {
            let further = ray.with_t_min(t + self.scene.t_min);
            let h = self.accel.nearest_hit(&further)?;
            if h.part == NO_PART || !self.culled(&objects[h.index], h.part, ray) {
                return Some((h.t, h.index, h.part));
            }
            t = h.t;
        }
        None
    }
}
