//! Area lights' shafts through the accelerator: what may stand between a surface point
//! and a light's quadrilateral (`Accel::clearance`, from `bvh::shaft`'s tests of the
//! trees' boxes, of the triangles in the leaves they meet and of the planes), and the
//! shadow ray of a shaft that only unbounded objects can stop.

use super::{Accel, Shaft, ShapePrim};
use crate::base::Color;
use crate::lights::Clearance;
use crate::optics::Ray;
use crate::shapes::Shape;
use glam::DVec3;

impl Accel {
    /// What stands between `p` and the quadrilateral `corners` (an area light's grid
    /// lies in it): `Unknown` with any transparent object in the scene or where a box of
    /// either tree meets the shaft (`bvh::shaft`) and is not a leaf of triangles each
    /// of which every ray misses (`Shaft::misses_triangle`); else `Open` when no
    /// unbounded opaque object can be met either (only planes are asked:
    /// `Shaft::misses_plane`), and `Unbounded` when one may, which
    /// `transmission_unbounded` then asks ray by ray.
    pub fn clearance(&self, p: DVec3, corners: &[DVec3; 4]) -> Clearance {
        if !self.glass_all.is_empty() {
            return Clearance::Unknown;
        }
        let Some(shaft) = Shaft::new(p, corners) else {
            return Clearance::Unknown;
        };
        // A leaf of triangles is asked triangle by triangle; any other shape is "met".
        let triangles = |prims: &[ShapePrim]| {
            prims.iter().all(|prim| {
                let [a, e1, e2] = if prim.mesh == ShapePrim::TRI {
                    self.tris[prim.part as usize]
                } else if prim.is_own() {
                    return false;
                } else {
                    self.mesh_tris[prim.slot as usize]
                };
                shaft.misses_triangle(a, e1, e2, self.t_min)
            })
        };
        if !(self.tree.shaft_clear(&shaft, |_| false) && self.shapes.shaft_clear(&shaft, triangles))
        {
            return Clearance::Unknown;
        }
        let missed = |shape: &Shape| match shape {
            Shape::Plane(pl) => shaft.misses_plane(pl.point, pl.normal(), self.t_min),
            _ => false,
        };
        if self.unbounded_opaque.iter().all(missed) {
            Clearance::Open
        } else {
            Clearance::Unbounded
        }
    }

    /// `transmission` for a ray in a shaft without bounded objects: the unbounded opaque
    /// objects alone, as `shadow` tests them first; past them, with no transparent
    /// object and nothing bounded in the way, `shadow` lets everything through. (The
    /// loop is written out in both: one helper shared with `shadow`, inlined, still
    /// moved the registers of `shading::direct` and cost the orbit 0.6 % more
    /// instructions, 1,071.2 M against 1,077.3 M.)
    #[inline]
    pub fn transmission_unbounded(&self, p: DVec3, to_light: DVec3, dist: f64) -> Color {
        let ray = Ray::new(p, to_light).with_t_min(self.t_min);
        for shape in &self.unbounded_opaque {
            if shape.hit(&ray, dist).is_some() {
                return Color::ZERO;
            }
        }
        Color::ONE
    }
}
