//! Shadow rays through the accelerator: what a ray from a surface point towards a light
//! lets through, exactly as `shading::transmission`'s linear scan answers (see the
//! parent module for the order of the product).

use super::shadow_cache::{self, Blocker};
use super::{Accel, ShapePrim, CROSSINGS_MAX, GLASS_LINEAR_MAX, NO_PART};
use crate::base::Color;
use crate::object::Object;
use crate::optics::Ray;
use crate::shapes::Shape;
use arrayvec::ArrayVec;
use glam::DVec3;

/// The transparent crossings of one shadow ray: (object, mesh triangle or `NO_PART`, t),
/// at most `CROSSINGS_MAX`.
/// An `ArrayVec`, so that no buffer is zeroed per ray (a zeroed array of 32 cost gears
/// 1.8 % of its instructions).
struct Crossings {
    buf: ArrayVec<(u32, u32, f64), CROSSINGS_MAX>,
    overflow: bool,
}

impl Crossings {
    #[inline]
    fn push(&mut self, i: u32, part: u32, t: f64) {
        if self.buf.try_push((i, part, t)).is_err() {
            self.overflow = true;
        }
    }
}

#[cfg(test)]
thread_local! {
    /// How many blockers this thread found beside a cached one (`Accel::shape_blocks`).
    pub(super) static HOLDER_FOUND: std::cell::Cell<usize> = const { std::cell::Cell::new(0) };
}

impl Accel {
    /// What a shadow ray from `p` along the unit `to_light` lets through over (t_min,
    /// dist): exactly `shading::transmission(objects, p, to_light, dist)`.
    ///
    /// Always inlined, as 46b440d's build inlined it on its own into `shading::direct`,
    /// its one caller then: `direct_rec` with a recorder made a second one, LLVM kept it
    /// out of line, and the call in the light loop (cold where the light buffer answers)
    /// cost `direct` 20 M instructions on the orbit at one thread (callgrind) in spills
    /// around it; where the buffer cannot answer it is the hot path itself.
    #[inline(always)]
    pub fn transmission(&self, objects: &[Object], p: DVec3, to_light: DVec3, dist: f64) -> Color {
        self.shadow(objects, None, p, to_light, dist)
    }

    /// `transmission` for a shadow ray towards the scene's point light number `light`:
    /// the same answer, found through the thread's shadow cache (`shadow_cache`) first
    /// where shadow rays walk a tree.
    #[inline(always)]
    pub fn transmission_to(
        &self,
        objects: &[Object],
        light: usize,
        p: DVec3,
        to_light: DVec3,
        dist: f64,
    ) -> Color {
        self.shadow(objects, Some(light), p, to_light, dist)
    }

    /// `transmission` for a shadow ray of an extension light, `key` naming the light and
    /// its point (`lights::ext_key`): the same answer, through the thread's shadow cache
    /// (its slots past the report's lights').
    #[inline]
    pub fn transmission_keyed(
        &self,
        objects: &[Object],
        key: usize,
        p: DVec3,
        to_light: DVec3,
        dist: f64,
    ) -> Color {
        self.shadow(
            objects,
            Some(shadow_cache::ext_slot(key)),
            p,
            to_light,
            dist,
        )
    }

    #[inline(always)]
    fn shadow(
        &self,
        objects: &[Object],
        light: Option<usize>,
        p: DVec3,
        to_light: DVec3,
        dist: f64,
    ) -> Color {
        let ray = Ray::new(p, to_light).with_t_min(self.t_min);
        for shape in &self.unbounded_opaque {
            if shape.hit(&ray, dist).is_some() {
                return Color::ZERO;
            }
        }
        let light = light.filter(|_| self.cached);
        if let Some(k) = light {
            if self.cached_blocks(k, &ray, dist) {
                return Color::ZERO;
            }
        }
        if self.glass_all.len() > GLASS_LINEAR_MAX {
            return self.transmission_collecting(objects, light, &ray, dist);
        }
        // Few transparent objects: the tree only looks for an opaque blocker ...
        if let Some(opaque) = self.tree.flat_opaque() {
            for prim in opaque {
                if prim.sphere.hit(&ray, dist).is_some() {
                    return Color::ZERO;
                }
            }
        } else {
            let mut blocker = Blocker::None;
            self.tree.traverse_any(&ray, dist, |prim, limit| {
                if prim.opaque && prim.sphere.hit(&ray, dist).is_some() {
                    blocker = Blocker::Sphere(*prim);
                    return None;
                }
                Some(limit)
            });
            if self.blocked(light, blocker) {
                return Color::ZERO;
            }
        }
        if !self.shapes.is_empty() && self.blocked(light, self.shapes_blocker(&ray, dist)) {
            return Color::ZERO;
        }
        // ... and the transparent ones are crossed in the linear scan's own loop.
        self.glass_linear(objects, &ray, dist)
    }

    /// The linear scan's loop over the transparent objects.
    #[inline(always)]
    fn glass_linear(&self, objects: &[Object], ray: &Ray, dist: f64) -> Color {
        let mut through = Color::ONE;
        if !self.glass_mesh {
            for &i in &self.glass_all {
                let obj = &objects[i as usize];
                for t in obj.shape.crossings(ray, dist) {
                    through *= obj.material.kt * obj.texture.color_at(ray.at(t));
                }
            }
            return through;
        }
        // The same loop, a transparent mesh's crossings found through the tree, each
        // triangle filtering by its own material and colour.
        for &i in &self.glass_all {
            let obj = &objects[i as usize];
            if let Shape::Mesh(m) = obj.shape {
                let mesh = &self.meshes[m.id as usize];
                let plain = mesh.plain(&obj.texture);
                for (t, k) in self.mesh_crossings(m.id, ray, dist) {
                    through *= if plain {
                        obj.material.kt * obj.texture.color_at(ray.at(t))
                    } else {
                        mesh.filter(k, ray.at(t), &obj.texture, &obj.material)
                    };
                }
                continue;
            }
            for t in obj.shape.crossings(ray, dist) {
                through *= obj.material.kt * obj.color_at(ray.at(t));
            }
        }
        through
    }

    /// Every crossing (t, triangle) of mesh `id`'s transparent triangles with
    /// ray.t_min < t < dist, ascending in t (then triangle).
    #[cold]
    fn mesh_crossings(&self, id: u32, ray: &Ray, dist: f64) -> Vec<(f64, u32)> {
        let mut ts = Vec::new();
        self.shapes_traverse_any(ray, dist, |prim, limit| {
            if prim.mesh == id && prim.glass {
                ts.extend(self.shape_hit(prim, ray, dist).map(|t| (t, prim.part)));
            }
            Some(limit)
        });
        ts.sort_by(|a, b| a.0.total_cmp(&b.0).then(a.1.cmp(&b.1)));
        ts
    }

    /// `transmission` for many transparent objects: one walk through the tree stops at an
    /// opaque blocker and collects the transparent crossings, which are then multiplied in
    /// object order (or, past `CROSSINGS_MAX` of them, crossed by `glass_linear`).
    #[inline(never)]
    fn transmission_collecting(
        &self,
        objects: &[Object],
        light: Option<usize>,
        ray: &Ray,
        dist: f64,
    ) -> Color {
        let mut found = Crossings {
            buf: ArrayVec::new(),
            overflow: false,
        };
        for &i in &self.unbounded_glass {
            for t in objects[i as usize].shape.crossings(ray, dist) {
                found.push(i, NO_PART, t);
            }
        }
        let mut blocker = Blocker::None;
        self.tree.traverse_any(ray, dist, |prim, limit| {
            if prim.opaque {
                if prim.sphere.hit(ray, dist).is_some() {
                    blocker = Blocker::Sphere(*prim);
                    return None;
                }
            } else if prim.glass && !found.overflow {
                for t in prim.sphere.roots(ray).crossings(ray.t_min, dist) {
                    found.push(prim.index, NO_PART, t);
                }
            }
            Some(limit)
        });
        if self.blocked(light, blocker) {
            return Color::ZERO;
        }
        if !self.shapes.is_empty() {
            self.shapes_traverse_any(
                ray,
                dist,
                #[inline(always)]
                |prim, limit| {
                    if prim.opaque {
                        if self.shape_hit(prim, ray, dist).is_some() {
                            blocker = Blocker::Shape(*prim, self.shapes.place(prim));
                            return None;
                        }
                    } else if prim.glass && !found.overflow {
                        self.shape_crossings(prim, ray, dist, &mut found);
                    }
                    Some(limit)
                },
            );
            if self.blocked(light, blocker) {
                return Color::ZERO;
            }
        }
        if found.overflow {
            return self.glass_linear(objects, ray, dist);
        }
        let crossings = &mut found.buf[..];
        // Insertion sort by object, then t: a mesh's triangles are met in the tree's
        // order; any other object's crossings come in t order already.
        let after = |a: &(u32, u32, f64), b: &(u32, u32, f64)| {
            a.0 > b.0 || (a.0 == b.0 && (a.2 > b.2 || (a.2 == b.2 && a.1 > b.1)))
        };
        for k in 1..crossings.len() {
            let mut j = k;
            while j > 0 && after(&crossings[j - 1], &crossings[j]) {
                crossings.swap(j - 1, j);
                j -= 1;
            }
        }
        let mut through = Color::ONE;
        for &(i, part, t) in crossings.iter() {
            let obj = &objects[i as usize];
            through *= match obj.shape {
                Shape::Mesh(m) if part != NO_PART => {
                    let mesh = &self.meshes[m.id as usize];
                    if mesh.plain(&obj.texture) {
                        obj.material.kt * obj.color_at(ray.at(t))
                    } else {
                        mesh.filter(part, ray.at(t), &obj.texture, &obj.material)
                    }
                }
                _ => obj.material.kt * obj.color_at(ray.at(t)),
            };
        }
        through
    }

    /// Notes the crossings of a transparent primitive of the shapes' tree.
    #[inline]
    fn shape_crossings(&self, prim: &ShapePrim, ray: &Ray, dist: f64, found: &mut Crossings) {
        if prim.mesh == ShapePrim::SOLO {
            for t in self.solo[prim.part as usize].crossings(ray, dist) {
                found.push(prim.index, NO_PART, t);
            }
        } else if prim.mesh == ShapePrim::SPHERE {
            let roots = self.spheres[prim.part as usize].roots(ray);
            for t in roots.crossings(ray.t_min, dist) {
                found.push(prim.index, NO_PART, t);
            }
        } else if let Some(t) = self.shape_hit(prim, ray, dist) {
            let part = if prim.mesh == ShapePrim::TRI {
                NO_PART
            } else {
                prim.part
            };
            found.push(prim.index, part, t);
        }
    }

    /// An opaque shape of the second tree that blocks the ray before `dist`, if any.
    #[inline(never)]
    fn shapes_blocker(&self, ray: &Ray, dist: f64) -> Blocker {
        let mut blocker = Blocker::None;
        self.shapes_traverse_any(
            ray,
            dist,
            #[inline(always)]
            |prim, limit| {
                if prim.opaque && self.shape_hit(prim, ray, dist).is_some() {
                    blocker = Blocker::Shape(*prim, self.shapes.place(prim));
                    return None;
                }
                Some(limit)
            },
        );
        blocker
    }

    /// Whether the thread's last blocker of the ray's light blocks this ray too: the
    /// same exact test the walk would run on it. One that does not is forgotten, so
    /// that the rays of a lit stretch pay only the look-up (on the SPD's tree, keeping
    /// it cost 6 % more instructions than no cache at all).
    #[inline(always)]
    fn cached_blocks(&self, light: usize, ray: &Ray, dist: f64) -> bool {
        let blocks = match shadow_cache::get(self.id, light) {
            Blocker::None => return false,
            Blocker::Sphere(p) => p.sphere.hit(ray, dist).is_some(),
            Blocker::Shape(p, at) => self.shape_blocks(light, p, at, ray, dist),
        };
        if !blocks {
            shadow_cache::put(self.id, light, Blocker::None);
        }
        blocks
    }

    /// Whether the cached shape `p` (at `at` in the shapes' tree's order) or an opaque
    /// primitive in the other leaves of the node that holds its leaf blocks the ray; a
    /// new blocker found there becomes the light's cached one.
    ///
    /// Out of line with the cached primitive's own test: inlined into `cached_blocks`,
    /// it moved the registers of `shading::direct`, and the orbit, which has no shape,
    /// counted 1 % more instructions.
    #[inline(never)]
    fn shape_blocks(&self, light: usize, p: ShapePrim, at: u32, ray: &Ray, dist: f64) -> bool {
        if self.shape_hit(&p, ray, dist).is_some() {
            return true;
        }
        let mut blocker = Blocker::None;
        self.shapes_holder(at as usize, ray, dist, |prim, limit| {
            if prim.opaque && self.shape_hit(prim, ray, dist).is_some() {
                blocker = Blocker::Shape(*prim, self.shapes.place(prim));
                return None;
            }
            Some(limit)
        });
        #[cfg(test)]
        HOLDER_FOUND.with(|n| n.set(n.get() + !matches!(blocker, Blocker::None) as usize));
        self.blocked(Some(light), blocker)
    }

    /// Whether a walk found `blocker`; if so, it becomes the light's cached one.
    #[inline(always)]
    fn blocked(&self, light: Option<usize>, blocker: Blocker) -> bool {
        if matches!(blocker, Blocker::None) {
            return false;
        }
        if let Some(k) = light {
            shadow_cache::put(self.id, k, blocker);
        }
        true
    }
}
