//! Rays through the surfaces a glTF material makes unusual (SPEC §18): back faces that
//! camera rays do not see (`doubleSided` false), coverage (`alphaMode` MASK and BLEND,
//! `mesh::extra`) and an emissive texture. Out of line and cold: only a hit on a mesh
//! that has one of them comes here (`Tracer::unusual`), never a report scene's.
//!
//! Along a ray the surfaces met are walked in order, each ray's distances still its own
//! (a hit is looked for past the last one, by the scene's epsilon):
//! - a surface the ray does not see (a culled back face, a masked-out point) is passed;
//! - a blended one adds α × its colour, and what lies behind it the rest (1 − α): the ray
//!   goes on unbent and unfiltered;
//! - the first solid one, or the background, ends the walk (so does `LAYERS` surfaces).
//!
//! A camera ray's passes hear the first surface it sees: its terms times α (`cover`),
//! and what lies behind it as a whole (`behind`), so the layers still sum to the beauty.

use super::{RayCount, Tracer};
use crate::accel::NO_PART;
use crate::base::Color;
use crate::mesh::extra::Seen;
use crate::object::Object;
use crate::optics::Ray;
use crate::record::{NoRecord, Record};
use crate::shapes::Shape;

/// The most surfaces a walk passes or blends before it gives up (black beyond), against
/// a pathological file.
const LAYERS: usize = 1024;

/// A hit as the camera walk holds it: t, the object's index and the triangle.
type Found = Option<(f64, usize, u32)>;

impl Tracer<'_> {
    /// Whether a camera ray's hit on triangle `part` of `obj` needs the walk: a back
    /// face it does not see, or a mesh with coverage or an emissive texture.
    #[cold]
    #[inline(never)]
    pub(super) fn unusual(&self, obj: &Object, part: u32, ray: &Ray) -> bool {
        let Shape::Mesh(m) = &obj.shape else {
            return false;
        };
        let mesh = &self.scene.meshes[m.id as usize];
        mesh.extra.is_some() || self.culled(obj, part, ray)
    }

    /// What the camera ray `ray` does at the hit `found`.
    fn seen_by_camera(&self, (t, i, part): (f64, usize, u32), ray: &Ray) -> Seen {
        let obj = &self.scene.objects[i];
        if part == NO_PART {
            return Seen::Solid;
        }
        if self.culled(obj, part, ray) {
            return Seen::Skip;
        }
        self.seen_on(obj, part, ray, t)
    }

    /// What any ray does at its hit at `t` on triangle `part` of mesh object `obj`.
    fn seen_on(&self, obj: &Object, part: u32, ray: &Ray, t: f64) -> Seen {
        match &obj.shape {
            Shape::Mesh(m) => self.scene.meshes[m.id as usize].seen(part, ray.at(t)),
            _ => Seen::Solid,
        }
    }

    /// An emissive texture's colour at the hit at `t` on triangle `part` of `obj`.
    fn emission_on(&self, obj: &Object, part: u32, ray: &Ray, t: f64) -> Color {
        match &obj.shape {
            Shape::Mesh(m) if part != NO_PART => {
                self.scene.meshes[m.id as usize].emission_at(part, ray.at(t))
            }
            _ => Color::ZERO,
        }
    }

    /// The camera ray's colour from its hit `(t, i, part)` on, through the surfaces it
    /// passes or blends.
    #[cold]
    #[inline(never)]
    pub(super) fn primary_walk<R: Record>(
        &self,
        mut found: Found,
        ray: &Ray,
        count: &mut RayCount,
        rec: &mut R,
    ) -> Color {
        // The first surface's share (`None` until it is met), what lies behind it, and
        // the weight left for what lies further.
        let mut front: Option<Color> = None;
        let (mut behind, mut w) = (Color::ZERO, 1.0);
        for _ in 0..LAYERS {
            let seen = found.map_or(Seen::Solid, |h| self.seen_by_camera(h, ray));
            let alpha = match seen {
                Seen::Skip => {
                    found = self.camera_past(found, ray);
                    continue;
                }
                Seen::Solid => 1.0,
                Seen::Blend(a) => a,
            };
            if front.is_none() {
                if R::ACTIVE && alpha < 1.0 {
                    rec.cover(alpha);
                }
                let c = self.primary_surface(found, ray, alpha, count, rec);
                if alpha >= 1.0 {
                    return c;
                }
                front = Some(alpha * c);
            } else {
                let c = self.primary_surface(found, ray, w * alpha, count, &mut NoRecord);
                behind += w * alpha * c;
            }
            w *= 1.0 - alpha;
            if alpha >= 1.0 {
                break;
            }
            found = self.camera_past(found, ray);
        }
        if R::ACTIVE {
            rec.behind(behind);
        }
        front.unwrap_or(Color::ZERO) + behind
    }

    /// The first hit of a camera ray past `found` (none past a miss).
    fn camera_past(&self, found: Found, ray: &Ray) -> Found {
        let (t, _, _) = found?;
        let further = ray.with_t_min(t + self.scene.t_min);
        let h = self.accel.nearest_hit(&further)?;
        Some((h.t, h.index, h.part))
    }

    /// A camera ray's colour at the surface `found` (the background at none), shaded as
    /// at any hit, with `weight` as its path weight, plus an emissive texture there.
    fn primary_surface<R: Record>(
        &self,
        found: Found,
        ray: &Ray,
        weight: f64,
        count: &mut RayCount,
        rec: &mut R,
    ) -> Color {
        let Some((t, i, part)) = found else {
            return self.primary_shade(None, None, ray, count, rec);
        };
        let obj = &self.scene.objects[i];
        let surface = self.surface_of(obj, part, ray.at(t));
        count.eye_hits += 1;
        let e = self.emission_on(obj, part, ray, t);
        if R::ACTIVE {
            rec.object(i, t);
            let f = self.scene.fog.amount(t);
            rec.fog(f);
            rec.emission(e);
            let c = self.shade_rec(ray, t, &surface, None, 0, weight, count, rec) + e;
            return self.scene.fog.apply_amount(c, f);
        }
        let c = self.shade(ray, t, &surface, None, 0, weight, count) + e;
        self.scene.fog.apply(c, t)
    }

    /// A secondary ray's colour from its hit at `t` on triangle `part` of `obj` on,
    /// through the surfaces it passes or blends (`depth` and `weight` as `trace`'s).
    #[cold]
    #[inline(never)]
    #[allow(clippy::too_many_arguments)]
    pub(super) fn trace_walk(
        &self,
        ray: &Ray,
        t: f64,
        obj: &Object,
        part: u32,
        depth: u32,
        weight: f64,
        count: &mut RayCount,
    ) -> Color {
        let mut out = Color::ZERO;
        let mut w = 1.0;
        let mut hit = Some((t, obj, part));
        for _ in 0..LAYERS {
            let Some((t, obj, part)) = hit else {
                return out + w * self.scene.background;
            };
            let alpha = match self.seen_on(obj, part, ray, t) {
                Seen::Skip => 0.0,
                Seen::Solid => 1.0,
                Seen::Blend(a) => a,
            };
            if alpha > 0.0 {
                let k = weight * w * alpha;
                let c = match part {
                    NO_PART => self.shade(ray, t, obj, None, depth, k, count),
                    _ => {
                        let surface = self.surface_of(obj, part, ray.at(t));
                        let e = self.emission_on(obj, part, ray, t);
                        self.shade(ray, t, &surface, None, depth, k, count) + e
                    }
                };
                out += w * alpha * c;
                w *= 1.0 - alpha;
                if alpha >= 1.0 {
                    return out;
                }
            }
            hit = self.nearest_part(&ray.with_t_min(t + self.scene.t_min));
        }
        out
    }
}
