//! The nearest-hit query: the smallest t over the unbounded shapes, the spheres' tree
//! and the shapes' tree, with the linear scan's order on equal t (the parent module
//! says which), and the surface a mesh hit is shaded as.

use super::{Accel, Hit, ShapePrim, NO_PART};
use crate::object::Object;
use crate::optics::Ray;
use crate::shapes::{Shape, Triangle};
use glam::DVec3;

impl Accel {
    /// The hit of a shapes' tree primitive with ray.t_min < t < t_max, if any.
    #[inline(always)]
    pub(super) fn shape_hit(&self, prim: &ShapePrim, ray: &Ray, t_max: f64) -> Option<f64> {
        if prim.mesh == ShapePrim::TRI {
            let [a, e1, e2] = self.tris[prim.part as usize];
            let (_, _, t) = Triangle::uvt_of(a, e1, e2, ray)?;
            (t > ray.t_min && t < t_max).then_some(t)
        } else if prim.mesh == ShapePrim::SPHERE {
            self.spheres[prim.part as usize].hit(ray, t_max)
        } else if prim.mesh == ShapePrim::SOLO {
            self.solo[prim.part as usize].hit(ray, t_max)
        } else {
            // `Mesh::hit`'s test on the same numbers, read in the tree's order.
            let [a, e1, e2] = self.mesh_tris[prim.slot as usize];
            let (_, _, t) = Triangle::uvt_of(a, e1, e2, ray)?;
            (t > ray.t_min && t < t_max).then_some(t)
        }
    }

    /// The nearest hit (t, object index), as the linear scan finds it (a mesh counting
    /// as one object).
    #[inline]
    pub fn nearest(&self, ray: &Ray) -> Option<(f64, usize)> {
        self.nearest_hit(ray).map(|h| (h.t, h.index))
    }

    /// The nearest hit with, on a mesh, its triangle: the smallest t, then the object
    /// that comes first in the file, then (two triangles of a mesh at one t: an edge)
    /// the triangle that comes first in its file. Kept out of line: its callers (camera
    /// and secondary rays) stay small, and the compiler's choice otherwise changed with
    /// unrelated edits (2 % of the 10,000-sphere frame either way).
    #[inline(never)]
    pub fn nearest_hit(&self, ray: &Ray) -> Option<Hit> {
        let mut best_t = f64::INFINITY;
        let mut best_i = u32::MAX;
        for &(i, ref shape) in &self.unbounded {
            if let Some(t) = shape.hit(ray, f64::INFINITY) {
                if t < best_t || (t == best_t && i < best_i) {
                    best_t = t;
                    best_i = i;
                }
            }
        }
        self.tree.traverse(ray, best_t, |prim, limit| {
            if let Some(t) = prim.sphere.hit(ray, f64::INFINITY) {
                if t < best_t || (t == best_t && prim.index < best_i) {
                    best_t = t;
                    best_i = prim.index;
                    return Some(t);
                }
            }
            Some(limit)
        });
        let mut best_part = NO_PART;
        if !self.shapes.is_empty() {
            self.shapes_traverse(
                ray,
                best_t,
                #[inline(always)]
                |prim, limit| {
                    if let Some(t) = self.shape_hit(prim, ray, f64::INFINITY) {
                        let part = if prim.is_own() { NO_PART } else { prim.part };
                        if t < best_t || (t == best_t && (prim.index, part) < (best_i, best_part)) {
                            best_t = t;
                            best_i = prim.index;
                            best_part = part;
                            return Some(t);
                        }
                    }
                    Some(limit)
                },
            );
        }
        (best_i != u32::MAX).then_some(Hit {
            t: best_t,
            index: best_i as usize,
            part: best_part,
        })
    }

    /// The object a hit at `p` on `part` of mesh object `obj` is shaded as: that triangle
    /// (smooth where its mesh has normals) with its texture and material
    /// (`Mesh::surface`); `None` when `obj` is not a mesh or `part` is `NO_PART`.
    pub fn surface(&self, obj: &Object, part: u32, p: DVec3) -> Option<Object> {
        match &obj.shape {
            Shape::Mesh(m) if part != NO_PART => {
                let mesh = self.meshes.get(m.id as usize)?;
                ((part as usize) < mesh.triangles.len())
                    .then(|| mesh.surface(part, p, &obj.texture, &obj.material))
            }
            _ => None,
        }
    }
}
