//! The surface a hit shades: for a CSG block, the leaf the ray met (its texture and
//! material) and the block's outward normal there (reversed on a difference's cut
//! surface); for any other object, the object and its shape's normal. Then the normal
//! shading uses: turned to face the ray, bump applied, and whether the ray enters.
//! What `Tracer::shade_rec` lights and `pick` answers. A mesh object is first
//! turned into the triangle the accelerator hit (`Tracer::surface_of`).

use super::Tracer;
use crate::object::Object;
use crate::optics::Ray;
use crate::shapes::Shape;
use glam::DVec3;
use std::borrow::Cow;

impl Tracer<'_> {
    /// The object as shading sees it at a hit at `p` on `part`: a mesh object becomes
    /// its triangle `part` (with the texture and material there: `Mesh::surface`); any
    /// other is itself.
    #[inline]
    pub fn surface_of<'o>(&self, obj: &'o Object, part: u32, p: DVec3) -> Cow<'o, Object> {
        match self.accel.surface(obj, part, p) {
            Some(surface) => Cow::Owned(surface),
            None => Cow::Borrowed(obj),
        }
    }
}

/// What shades the hit `p` of `ray` on `obj`, and the outward normal there: `obj` and its
/// shape's normal, or for a CSG block the leaf the ray met (its texture and material)
/// and the block's normal (reversed on a difference's cut surface).
#[inline(always)]
pub fn surface_at<'o>(obj: &'o Object, ray: &Ray, p: DVec3) -> (&'o Object, DVec3) {
    if let Shape::Csg(csg) = &obj.shape {
        if let Some(s) = csg.surface(ray, f64::INFINITY) {
            return (s.leaf, s.normal);
        }
    }
    (obj, obj.shape.normal(p))
}

/// The shading normal at `p` for a ray along `v` from the outward normal, and whether
/// the ray enters the object: V·N < 0 decides entering, bump perturbs the normal, and it
/// is turned to face the ray.
#[inline(always)]
pub fn facing(obj: &Object, outward: DVec3, p: DVec3, v: DVec3) -> (DVec3, bool) {
    let entering = v.dot(outward) < 0.0;
    let bumped = obj.material.bump.apply(outward, p);
    (if entering { bumped } else { -bumped }, entering)
}
