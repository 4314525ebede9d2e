//! Direct lighting at a surface point (report IV.2, SPEC §2): ambient, Lambert diffuse,
//! phong-20 specular, and hard shadows through which glass lets coloured light pass.
//!
//! With C the object colour, N the shading normal (facing the ray, after bump), V the ray
//! direction, and for each light L the unit vector to it, Lc its colour and I its
//! intensity:
//! - ambient `0.2·C`;
//! - diffuse `Kd·I·max(0, N·L)·(C ⊙ Lc)`;
//! - specular `(1 − Kd)·I·max(0, V·R)^20·Lc`, R = L − 2(L·N)N (an NFF material's
//!   Phong highlight instead: `Ks·I·max(0, V·R)^Shine·Lc`, `Highlight::Phong`);
//! - a light with N·L ≤ 0 adds nothing; a light seen through objects is filtered by
//!   `Kt·C_obj` per surface crossing, and blocked by any opaque crossing.

use crate::base::Color;
use crate::lights::{LightSource, Occluders, PointLight};
use crate::object::{Highlight, Material, Object};
use crate::optics::Ray;
use crate::record::{NoRecord, Record};
use glam::DVec3;

/// The report's ambient light intensity.
pub const AMBIENT: f64 = 0.2;
/// The report's specular exponent.
pub const SHININESS: i32 = 20;

/// What a shadow ray from `p` towards a light `dist` away lets through: white when nothing
/// is in the way, black when an opaque object is, and the product of `Kt·C` over every
/// crossing of a transparent one. Shadow rays go straight (they are not bent).
pub fn transmission(objects: &[Object], p: DVec3, to_light: DVec3, dist: f64) -> Color {
    let ray = Ray::new(p, to_light);
    let mut through = Color::ONE;
    // Opaque blockers first: the common case ends at the first one found.
    for obj in objects.iter().filter(|o| o.material.kt <= 0.0) {
        if obj.shape.hit(&ray, dist).is_some() {
            return Color::ZERO;
        }
    }
    for obj in objects.iter().filter(|o| o.material.kt > 0.0) {
        for t in obj.shape.crossings(&ray, dist) {
            through *= obj.material.kt * obj.color_at(ray.at(t));
        }
    }
    through
}

/// The reference: a linear scan over the objects.
impl Occluders for [Object] {
    fn transmission(&self, p: DVec3, to_light: DVec3, dist: f64) -> Color {
        transmission(self, p, to_light, dist)
    }
}

/// The local colour at `p`: ambient plus each of the report's point lights' diffuse and
/// specular, shadowed (the extension's lights are added by `add_lights`).
/// `shadow_rays` counts the shadow rays cast. The beauty-only path's call, kept out of
/// line as it always was: `direct_rec` with the no-op recorder, whose hooks fold away.
#[allow(clippy::too_many_arguments)]
#[inline(never)]
pub fn direct<O: Occluders + ?Sized>(
    occluders: &O,
    lights: &[PointLight],
    p: DVec3,
    n: DVec3,
    v: DVec3,
    color: Color,
    material: &Material,
    shadow_rays: &mut u64,
) -> Color {
    direct_rec(
        occluders,
        lights,
        p,
        n,
        v,
        color,
        material,
        shadow_rays,
        &mut NoRecord,
    )
}

/// `direct`, telling `rec` the ambient term and each light's diffuse and specular terms
/// (times what the shadow rays let through: the transparent-shadow product and an area
/// light's mean go into the term they filter). Inlined into `direct` and into the passes'
/// shading both.
#[allow(clippy::too_many_arguments)]
#[inline(always)]
pub fn direct_rec<O: Occluders + ?Sized, R: Record>(
    occluders: &O,
    lights: &[PointLight],
    p: DVec3,
    n: DVec3,
    v: DVec3,
    color: Color,
    material: &Material,
    shadow_rays: &mut u64,
    rec: &mut R,
) -> Color {
    let kd = material.kd;
    let mut out = AMBIENT * color;
    if R::ACTIVE {
        rec.ambient(out);
    }
    // One loop per highlight, so that the report's is the code it always was (a match in
    // the loop cost the orbit 6 % of its instructions).
    match material.highlight {
        Highlight::Report => {
            let spec = |i: f64, vr: f64| (1.0 - kd) * i * vr.powi(SHININESS);
            out = lit(
                occluders,
                lights,
                At { p, n, v, color, kd },
                out,
                shadow_rays,
                rec,
                spec,
            );
        }
        // NFF's Phong term; a glTF material's highlight is one too (its tint and
        // emission are the tracer's to add, from `Scene::pbr`).
        Highlight::Phong { .. } | Highlight::Gltf { .. } => {
            let (ks, shine) = material.highlight.phong();
            let spec = phong(ks, shine);
            out = lit(
                occluders,
                lights,
                At { p, n, v, color, kd },
                out,
                shadow_rays,
                rec,
                spec,
            );
        }
    }
    out
}

/// The Phong weight `Ks·I·max(0, V·R)^Shine`, and none where Ks = 0: NFF's matte
/// surfaces are written `Ks 0, Shine 100000`, whose power underflows on the C library's
/// slow path (4 % of the tree database's time in `xflow` alone) only to be multiplied by
/// zero. The same bits either way: `0·I·x` is +0 for the finite, non-negative `x` a
/// power of `max(0, V·R)` gives, and `diffuse + 0` is `diffuse`.
#[inline(always)]
fn phong(ks: f64, shine: f64) -> impl Fn(f64, f64) -> f64 {
    move |i, vr| {
        if ks == 0.0 {
            0.0
        } else {
            ks * i * vr.powf(shine)
        }
    }
}

/// The surface point being lit: where, its shading normal, the ray direction, its colour
/// and Kd (built in each arm of a highlight's match and passed by value: one built
/// before the match and lent to both arms stayed in memory, +10.8 M instructions on the
/// orbit).
#[derive(Clone, Copy)]
struct At {
    p: DVec3,
    n: DVec3,
    v: DVec3,
    color: Color,
    kd: f64,
}

/// `out` plus each of `lights`' diffuse and specular at `p`, shadowed, telling `rec` each
/// term: the extension's lights (`scene::ext::build::lights`), after `direct_rec`. Out of
/// line and called only when a scene has such lights: a test for them inside `direct`
/// cost the orbit (which has none) 2.2 % more instructions.
#[allow(clippy::too_many_arguments)]
#[inline(never)]
pub fn add_lights<O: Occluders + ?Sized, L: LightSource, R: Record>(
    occluders: &O,
    lights: &[L],
    out: Color,
    p: DVec3,
    n: DVec3,
    v: DVec3,
    color: Color,
    material: &Material,
    shadow_rays: &mut u64,
    rec: &mut R,
) -> Color {
    let kd = material.kd;
    match material.highlight {
        Highlight::Report => {
            let spec = |i: f64, vr: f64| (1.0 - kd) * i * vr.powi(SHININESS);
            lit(
                occluders,
                lights,
                At { p, n, v, color, kd },
                out,
                shadow_rays,
                rec,
                spec,
            )
        }
        Highlight::Phong { .. } | Highlight::Gltf { .. } => {
            let (ks, shine) = material.highlight.phong();
            let spec = phong(ks, shine);
            lit(
                occluders,
                lights,
                At { p, n, v, color, kd },
                out,
                shadow_rays,
                rec,
                spec,
            )
        }
    }
}

/// The light loop of `direct_rec` over one list of lights, adding to `out`, with the
/// specular weight `spec(I, max(0, V·R))`.
#[inline(always)]
fn lit<O: Occluders + ?Sized, L: LightSource, R: Record>(
    occluders: &O,
    lights: &[L],
    at: At,
    mut out: Color,
    shadow_rays: &mut u64,
    rec: &mut R,
    spec: impl Fn(f64, f64) -> f64,
) -> Color {
    let At { p, n, v, color, kd } = at;
    for (k, light) in lights.iter().enumerate() {
        // None on the light itself (it lights nothing there) or outside a spot's cone.
        let Some(inc) = light.incident(p) else {
            continue;
        };
        let l = inc.l;
        let nl = n.dot(l);
        if nl <= 0.0 {
            continue;
        }
        let through = light.shadow(k, occluders, p, &inc, shadow_rays);
        if through == Color::ZERO {
            continue;
        }
        let lc = light.color();
        let diffuse = kd * inc.intensity * nl * (color * lc);
        // Computed even where it is ±0 (Kd = 1, V·R ≤ 0): a branch to skip it alternated
        // between the sky (Kd = 1) and the floor and cost more than the arithmetic.
        let r = l - 2.0 * l.dot(n) * n;
        let spec = spec(inc.intensity, v.dot(r).max(0.0)) * lc;
        if R::ACTIVE {
            rec.light(through * diffuse, through * spec);
        }
        out += through * (diffuse + spec);
    }
    out
}

#[cfg(test)]
#[path = "shading_tests.rs"]
mod tests;
