//! The recursive trace loop (report IV, SPEC §2): nearest hit, local lighting, then
//! reflection and refraction, with fog on primary rays.
//!
//! At a hit the shape's outward normal decides entering (V·N < 0) or leaving; bump
//! perturbs that normal, and it is flipped to face the ray to become the shading normal.
//! - reflection (Kr > 0): `+ Kr · trace(reflect(V, N))`;
//! - refraction (Kt > 0): η = 1/Ior entering, Ior leaving (the outside is always air);
//!   `+ Kt · C ⊙ trace(T)`, or `+ Kt · trace(reflect(V, N))` on total internal reflection;
//! - at most `MAX_DEPTH` bounces after the primary ray, and no secondary ray whose weight
//!   (the product of the Kr / Kt along its path) is below 1/256;
//! - a ray that hits nothing is the scene's background (black for a Scene.txt).
//!
//! The limits are the tracer's `Rules` (`crate::spd`): the report's by default, or the
//! SPD's testing procedure (depth 5 counting the eye ray, no weight cut-off, a reflection
//! ray off every transmitter), whose spawning is `spd`'s. Every ray starts past the
//! scene's epsilon (`Scene::t_min`).
//!
//! The passes (`crate::passes`) listen through `Record`: the camera ray's shading calls
//! its hooks (first hit, each term of the light split, fog). Every method is generic over
//! the recorder and the hooks sit behind `R::ACTIVE`, so the beauty-only path, which
//! passes `NoRecord`, compiles to the code it had before passes existed.

mod alpha;
mod count;
mod query;
pub mod rules;
mod surface;
mod unseen;
pub use count::RayCount;
#[cfg(test)]
pub(crate) use query::MADE;
pub use rules::Rules;
pub use surface::{facing, surface_at};

use crate::accel::{Accel, Hint, LightBuffer, NO_PART};
use crate::base::Color;
use crate::lights::SceneLight;
use crate::lights::{Clearance, Occluders};
use crate::object::{Highlight, Object};
use crate::optics::{reflect, refract, Ray};
pub use crate::record::{NoRecord, Record};
use crate::scene::Scene;
use crate::shading;
use glam::DVec3;
use std::sync::Arc;

/// Bounces allowed after the primary ray.
pub const MAX_DEPTH: u32 = 5;
/// Secondary rays weighing less than this are not traced.
pub const MIN_WEIGHT: f64 = 1.0 / 256.0;

/// Traces rays through one scene: everything prepared once per scene (and shared by every
/// frame of an animation) lives here — the acceleration structures of `accel`. The
/// structure is shared (`Arc`): frames whose tracks change only colours or lights draw
/// their own scene values through one structure built once (`with_accel`). The light
/// buffer depends on the lights, so every tracer builds its own (microseconds).
pub struct Tracer<'a> {
    pub(crate) scene: &'a Scene,
    accel: Arc<Accel>,
    lights: LightBuffer,
    /// The extension's lights (`scene::ext::build::lights` of the scene's records).
    ext_lights: Vec<SceneLight>,
    pub(crate) rules: Rules,
}

impl<'a> Tracer<'a> {
    /// The nearest hit as `trace_hit` takes it: t, the object, and the mesh triangle.
    #[inline]
    fn nearest_part(&self, ray: &Ray) -> Option<(f64, &'a Object, u32)> {
        let objects = &self.scene.objects;
        self.accel
            .nearest_hit(ray)
            .map(|h| (h.t, &objects[h.index], h.part))
    }

    /// The colour seen along a camera ray: the traced colour with the scene's fog, not
    /// clamped.
    pub fn primary(&self, ray: &Ray, count: &mut RayCount) -> Color {
        self.primary_in(None, ray, count)
    }

    /// `primary`, with the first hit (and that of its mirror reflection off a polished
    /// plane) looked up in the lists of its screen tile (`accel::TileView`: the same
    /// answers, found faster) when they are given and the ray leaves their eye.
    // Always inlined: the row loop's per-pixel call (see `render::draw_row`).
    #[inline(always)]
    pub fn primary_in(&self, tile: Option<Hint>, ray: &Ray, count: &mut RayCount) -> Color {
        self.primary_rec(tile, ray, count, &mut NoRecord)
    }

    /// `primary_in`, telling `rec` the first hit and the parts of the colour. Always
    /// inlined, like `shade_rec` and `direct_rec`: `primary_in` holds the beauty-only body
    /// again instead of calling this out of line (one instruction more a call), and LLVM
    /// then inlines it into render's row loop (11.7 M instructions fewer on the orbit at
    /// one thread, callgrind).
    #[inline(always)]
    pub fn primary_rec<R: Record>(
        &self,
        tile: Option<Hint>,
        ray: &Ray,
        count: &mut RayCount,
        rec: &mut R,
    ) -> Color {
        let c = self.primary_value(tile, ray, count, rec);
        if self.scene.linear {
            let shown = crate::base::srgb::display(c);
            rec.encoded(c, shown);
            return shown;
        }
        c
    }

    /// The row loop's camera ray (`render::draw_row`, for a scene not in linear light):
    /// `primary_in` without the encoding check, so that the report's loop is the code it
    /// was.
    #[inline(always)]
    pub(crate) fn primary_raw(&self, tile: Option<Hint>, ray: &Ray, count: &mut RayCount) -> Color {
        self.primary_value(tile, ray, count, &mut NoRecord)
    }

    /// `primary_rec`'s colour before a linear-light scene's encoding.
    #[inline(always)]
    fn primary_value<R: Record>(
        &self,
        tile: Option<Hint>,
        ray: &Ray,
        count: &mut RayCount,
        rec: &mut R,
    ) -> Color {
        count.primary += 1;
        let ray = &ray.with_t_min(self.scene.t_min);
        let objects = &self.scene.objects;
        let hit = match tile.and_then(|h| h.nearest(objects, ray)) {
            Some(found) => found.map(|(t, i)| (t, i, NO_PART)),
            None => self.accel.nearest_hit(ray).map(|h| (h.t, h.index, h.part)),
        };
        self.primary_shade(hit, tile, ray, count, rec)
    }

    /// The colour of a camera ray whose first hit is `hit` (t, object, triangle).
    #[inline(always)]
    fn primary_shade<R: Record>(
        &self,
        hit: Option<(f64, usize, u32)>,
        tile: Option<Hint>,
        ray: &Ray,
        count: &mut RayCount,
        rec: &mut R,
    ) -> Color {
        let objects = &self.scene.objects;
        match hit {
            Some((t, i, part)) => {
                // A mesh is shaded as the triangle hit (the object itself otherwise).
                let surface;
                let obj = if part == NO_PART {
                    &objects[i]
                } else {
                    if self.unusual(&objects[i], part, ray) {
                        return self.primary_walk(hit, ray, count, rec);
                    }
                    surface = self.surface_of(&objects[i], part, ray.at(t));
                    &*surface
                };
                count.eye_hits += 1;
                // The tile's mirror lists answer for the reflection off that plane only.
                let mirror = tile.filter(|h| h.mirror_plane() == Some(i));
                if R::ACTIVE {
                    // The fog fraction once, for the recorder and the colour both.
                    rec.object(i, t);
                    let f = self.scene.fog.amount(t);
                    rec.fog(f);
                    let c = self.shade_rec(ray, t, obj, mirror, 0, 1.0, count, rec);
                    return self.scene.fog.apply_amount(c, f);
                }
                let c = self.shade(ray, t, obj, mirror, 0, 1.0, count);
                self.scene.fog.apply(c, t)
            }
            None => {
                let background = self.scene.background;
                if R::ACTIVE {
                    let f = self.scene.fog.amount(f64::INFINITY);
                    rec.fog(f);
                    rec.background(background);
                    return self.scene.fog.apply_amount(background, f);
                }
                self.scene.fog.apply(background, f64::INFINITY)
            }
        }
    }

    /// The colour along a secondary ray at recursion `depth` with path weight `weight`.
    #[inline]
    pub(crate) fn trace(&self, ray: &Ray, depth: u32, weight: f64, count: &mut RayCount) -> Color {
        self.trace_hit(ray, self.nearest_part(ray), depth, weight, count)
    }

    /// `trace`, its nearest hit already found.
    #[inline]
    fn trace_hit(
        &self,
        ray: &Ray,
        hit: Option<(f64, &Object, u32)>,
        depth: u32,
        weight: f64,
        count: &mut RayCount,
    ) -> Color {
        count.secondary += 1;
        match hit {
            Some((t, obj, NO_PART)) => self.shade(ray, t, obj, None, depth, weight, count),
            Some((t, obj, part)) => self.shade_part(ray, t, obj, part, depth, weight, count),
            None => self.scene.background,
        }
    }

    /// `shade` at a hit on triangle `part` of a mesh object (out of line: the report's
    /// scenes never come here).
    #[allow(clippy::too_many_arguments)]
    #[cold]
    #[inline(never)]
    fn shade_part(
        &self,
        ray: &Ray,
        t: f64,
        obj: &Object,
        part: u32,
        depth: u32,
        weight: f64,
        count: &mut RayCount,
    ) -> Color {
        if self.has_extra(obj) {
            return self.trace_walk(ray, t, obj, part, depth, weight, count);
        }
        let surface = self.surface_of(obj, part, ray.at(t));
        self.shade(ray, t, &surface, None, depth, weight, count)
    }

    /// The colour at the hit of `ray` on `obj` at `t`. `mirror`: the tile lists of a
    /// camera ray that hit their mirror plane, for its reflection ray. Not generic: the
    /// beauty-only path's code stays where it was.
    #[allow(clippy::too_many_arguments)]
    fn shade(
        &self,
        ray: &Ray,
        t: f64,
        obj: &Object,
        mirror: Option<Hint>,
        depth: u32,
        weight: f64,
        count: &mut RayCount,
    ) -> Color {
        self.shade_rec(ray, t, obj, mirror, depth, weight, count, &mut NoRecord)
    }

    /// `shade`, telling `rec` the parts of the colour (the camera ray's; the rays spawned
    /// here are traced with `NoRecord`).
    #[allow(clippy::too_many_arguments)]
    #[inline(always)]
    fn shade_rec<R: Record>(
        &self,
        ray: &Ray,
        t: f64,
        obj: &Object,
        mirror: Option<Hint>,
        depth: u32,
        weight: f64,
        count: &mut RayCount,
        rec: &mut R,
    ) -> Color {
        let p = ray.at(t);
        let v = ray.dir;
        // A CSG block shades with the leaf the ray met (its texture and material).
        let (obj, outward) = surface_at(obj, ray, p);
        let m = &obj.material;
        let c = obj.color_at(p);
        let (n, entering) = facing(obj, outward, p, v);
        if R::ACTIVE {
            rec.surface(p, n, c);
        }

        let lights = &self.scene.lights;
        // The beauty-only path calls `direct`, the function it always called.
        let mut out = if R::ACTIVE {
            shading::direct_rec(self, lights, p, n, v, c, m, &mut count.shadow, rec)
        } else {
            shading::direct(self, lights, p, n, v, c, m, &mut count.shadow)
        };
        if !self.ext_lights.is_empty() {
            let ext = &self.ext_lights[..];
            let shadow = &mut count.shadow;
            out = shading::add_lights(self, ext, out, p, n, v, c, m, shadow, rec);
            // A glTF material's emission (a glTF scene always has such lights).
            if let Highlight::Gltf { look, .. } = m.highlight {
                let e = self.scene.pbr[look as usize].emission;
                if R::ACTIVE {
                    rec.emission(e);
                }
                out += e;
            }
        }
        if depth >= self.rules.max_depth {
            return out;
        }
        if self.rules.spd {
            return out + self.spawn_spd(ray, p, n, c, obj, entering, depth, count);
        }
        let min_weight = self.rules.min_weight;
        if m.kr > 0.0 && weight * m.kr >= min_weight {
            count.reflect += 1;
            let r = ray.spawn(p, reflect(v, n).normalize());
            let objects = &self.scene.objects;
            let found = mirror.and_then(|h| h.mirrored(objects, &r));
            let hit = match found {
                Some(found) => found.map(|(t, i)| (t, &objects[i], NO_PART)),
                None => self.nearest_part(&r),
            };
            let mut reflected = m.kr * self.trace_hit(&r, hit, depth + 1, weight * m.kr, count);
            if let Highlight::Gltf { look, .. } = m.highlight {
                reflected *= self.scene.pbr[look as usize].tint;
            }
            if R::ACTIVE {
                rec.reflection(reflected);
            }
            out += reflected;
        }
        if m.kt > 0.0 && weight * m.kt >= min_weight {
            let eta = if entering { 1.0 / m.ior } else { m.ior };
            // Counted as a refraction ray whether it leaves or is totally reflected.
            count.refract += 1;
            let through = match refract(v, n, eta) {
                Some(dir) => {
                    let r = ray.spawn(p, dir.normalize());
                    m.kt * c * self.trace(&r, depth + 1, weight * m.kt, count)
                }
                None => {
                    let r = ray.spawn(p, reflect(v, n).normalize());
                    m.kt * self.trace(&r, depth + 1, weight * m.kt, count)
                }
            };
            if R::ACTIVE {
                rec.transmission(through);
            }
            out += through;
        }
        out
    }
}

impl Occluders for Tracer<'_> {
    #[inline]
    fn transmission(&self, p: DVec3, to_light: DVec3, dist: f64) -> Color {
        Tracer::transmission(self, p, to_light, dist)
    }

    /// Through the light buffer when it can answer, else the full query. Always inlined:
    /// it is the light loop's body in `shading::direct` and in `direct_rec` both (with two
    /// callers LLVM stops inlining it on its own, +8 % instructions on the orbit).
    #[inline(always)]
    fn transmission_to(
        &self,
        light: usize,
        p: DVec3,
        to: DVec3,
        to_light: DVec3,
        dist: f64,
    ) -> Color {
        let objects = &self.scene.objects;
        match self
            .lights
            .transmission(light, objects, p, to, to_light, dist)
        {
            Some(c) => c,
            None => self
                .accel
                .transmission_to(objects, light, p, to_light, dist),
        }
    }

    /// Through the shadow cache's slot of `key` (an extension light's ray).
    #[inline]
    fn transmission_keyed(&self, key: usize, p: DVec3, to_light: DVec3, dist: f64) -> Color {
        self.accel
            .transmission_keyed(&self.scene.objects, key, p, to_light, dist)
    }

    #[inline]
    fn clearance(&self, p: DVec3, corners: &[DVec3; 4]) -> Clearance {
        self.accel.clearance(p, corners)
    }

    #[inline]
    fn transmission_unbounded(&self, p: DVec3, to_light: DVec3, dist: f64) -> Color {
        self.accel.transmission_unbounded(p, to_light, dist)
    }
}
