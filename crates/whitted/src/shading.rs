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

use crate::object::{Highlight, Light, Material, Object};
use crate::optics::Ray;
use crate::record::{NoRecord, Record};
use crate::texture::Color;
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
            through *= obj.material.kt * obj.texture.color_at(ray.at(t));
        }
    }
    through
}

/// What stands between a point and a light: answers `transmission` queries.
pub trait Occluders {
    /// What a shadow ray from `p` along the unit `to_light` lets through over a distance
    /// `dist`, as the free function `transmission` defines it.
    fn transmission(&self, p: DVec3, to_light: DVec3, dist: f64) -> Color;

    /// The same, knowing that the ray goes to light number `light` of the scene along
    /// `to` = `to_light`·`dist` before normalisation (an implementation may keep
    /// per-light structures); by default, `transmission`.
    #[inline]
    fn transmission_to(
        &self,
        light: usize,
        p: DVec3,
        to: DVec3,
        to_light: DVec3,
        dist: f64,
    ) -> Color {
        let _ = (light, to);
        self.transmission(p, to_light, dist)
    }
}

/// The reference: a linear scan over the objects.
impl Occluders for [Object] {
    fn transmission(&self, p: DVec3, to_light: DVec3, dist: f64) -> Color {
        transmission(self, p, to_light, dist)
    }
}

/// The local colour at `p`: ambient plus each light's diffuse and specular, shadowed.
/// `shadow_rays` counts the shadow rays cast. The beauty-only path's call, kept out of
/// line as it always was: `direct_rec` with the no-op recorder, whose hooks fold away.
#[allow(clippy::too_many_arguments)]
#[inline(never)]
pub fn direct<O: Occluders + ?Sized>(
    occluders: &O,
    lights: &[Light],
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
/// (times what the shadow ray let through: the transparent-shadow product goes into the
/// term it filters). Inlined into `direct` and into the passes' shading both.
#[allow(clippy::too_many_arguments)]
#[inline(always)]
pub fn direct_rec<O: Occluders + ?Sized, R: Record>(
    occluders: &O,
    lights: &[Light],
    p: DVec3,
    n: DVec3,
    v: DVec3,
    color: Color,
    material: &Material,
    shadow_rays: &mut u64,
    rec: &mut R,
) -> Color {
    let kd = material.kd;
    // One loop per highlight, so that the report's is the code it always was (a match in
    // the loop cost the orbit 6 % of its instructions).
    match material.highlight {
        Highlight::Report => lit(
            occluders,
            lights,
            p,
            n,
            v,
            color,
            kd,
            shadow_rays,
            rec,
            |i, vr| (1.0 - kd) * i * vr.powi(SHININESS),
        ),
        Highlight::Phong { ks, shine } => lit(
            occluders,
            lights,
            p,
            n,
            v,
            color,
            kd,
            shadow_rays,
            rec,
            |i, vr| ks * i * vr.powf(shine),
        ),
    }
}

/// The light loop of `direct_rec`, with the specular weight `spec(I, max(0, V·R))`.
#[allow(clippy::too_many_arguments)]
#[inline(always)]
fn lit<O: Occluders + ?Sized, R: Record>(
    occluders: &O,
    lights: &[Light],
    p: DVec3,
    n: DVec3,
    v: DVec3,
    color: Color,
    kd: f64,
    shadow_rays: &mut u64,
    rec: &mut R,
    spec: impl Fn(f64, f64) -> f64,
) -> Color {
    let mut out = AMBIENT * color;
    if R::ACTIVE {
        rec.ambient(out);
    }
    for (k, light) in lights.iter().enumerate() {
        let to = light.position - p;
        let dist = to.length();
        if dist == 0.0 {
            continue; // a light on the surface itself lights nothing there
        }
        let l = to / dist;
        let nl = n.dot(l);
        if nl <= 0.0 {
            continue;
        }
        *shadow_rays += 1;
        let through = occluders.transmission_to(k, p, to, l, dist);
        if through == Color::ZERO {
            continue;
        }
        let diffuse = kd * light.intensity * nl * (color * light.color);
        // Computed even where it is ±0 (Kd = 1, V·R ≤ 0): a branch to skip it alternated
        // between the sky (Kd = 1) and the floor and cost more than the arithmetic.
        let r = l - 2.0 * l.dot(n) * n;
        let spec = spec(light.intensity, v.dot(r).max(0.0)) * light.color;
        if R::ACTIVE {
            rec.light(through * diffuse, through * spec);
        }
        out += through * (diffuse + spec);
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::bump::Bump;
    use crate::object::Material;
    use crate::shapes::{Shape, Sphere};
    use crate::texture::Texture;

    const NONE: &[Object] = &[];

    fn m(kd: f64, highlight: Highlight) -> Material {
        Material {
            kd,
            kr: 0.0,
            kt: 0.0,
            ior: 1.0,
            bump: Bump::None,
            highlight,
        }
    }

    fn white_light(at: DVec3) -> Light {
        Light {
            position: at,
            color: Color::ONE,
            intensity: 1.0,
        }
    }

    fn ball(center: DVec3, kt: f64, c: Color) -> Object {
        Object {
            shape: Shape::Sphere(Sphere::new(center, 1.0)),
            texture: Texture::Uniform(c),
            material: Material {
                kd: 1.0,
                kr: 0.0,
                kt,
                ior: 1.5,
                bump: Bump::None,
                highlight: Highlight::Report,
            },
        }
    }

    #[test]
    fn ambient_plus_lambert_by_hand() {
        // Light at 45° above a floor point, Kd = 1 (no specular): 0.2·C + cos45°·C.
        let c = Color::new(0.5, 1.0, 0.0);
        let light = white_light(DVec3::new(1.0, 1.0, 0.0));
        let v = DVec3::new(0.0, -1.0, 0.0);
        let mut n_rays = 0;
        let got = direct(
            NONE,
            &[light],
            DVec3::ZERO,
            DVec3::Y,
            v,
            c,
            &m(1.0, Highlight::Report),
            &mut n_rays,
        );
        let k = 0.2 + std::f64::consts::FRAC_1_SQRT_2;
        assert!((got - c * k).length() < 1e-12, "{got}");
        assert_eq!(n_rays, 1);
    }

    #[test]
    fn specular_by_hand() {
        // Kd = 0.5, light straight above, eye ray at 45°: R = L − 2(L·N)N = −y, V·R = 1/√2,
        // specular = 0.5·(1/√2)^20 = 0.5/1024; diffuse = 0.5·1·C; ambient 0.2·C.
        let c = Color::new(1.0, 0.0, 0.0);
        let s = std::f64::consts::FRAC_1_SQRT_2;
        let v = DVec3::new(s, -s, 0.0);
        let light = white_light(DVec3::new(0.0, 5.0, 0.0));
        let got = direct(
            NONE,
            &[light],
            DVec3::ZERO,
            DVec3::Y,
            v,
            c,
            &m(0.5, Highlight::Report),
            &mut 0,
        );
        let spec = 0.5 / 1024.0;
        let want = Color::new(0.2 + 0.5 + spec, spec, spec);
        assert!((got - want).length() < 1e-12, "{got}");
    }

    #[test]
    fn light_behind_the_surface_adds_nothing() {
        let c = Color::ONE;
        let light = white_light(DVec3::new(0.0, -5.0, 0.0));
        let got = direct(
            NONE,
            &[light],
            DVec3::ZERO,
            DVec3::Y,
            -DVec3::Y,
            c,
            &m(0.5, Highlight::Report),
            &mut 0,
        );
        assert_eq!(got, 0.2 * c);
    }

    #[test]
    fn phong_highlight_by_hand() {
        // Ks = 0.5, Shine = 3: light straight above, eye ray at 45° down, V·R = 1/√2:
        // specular 0.5·(1/√2)³ = 0.5/(2√2); Kd = 0 leaves the ambient 0.2·C.
        let c = Color::new(1.0, 0.0, 0.0);
        let s = std::f64::consts::FRAC_1_SQRT_2;
        let v = DVec3::new(s, -s, 0.0);
        let light = white_light(DVec3::new(0.0, 5.0, 0.0));
        let phong = Highlight::Phong {
            ks: 0.5,
            shine: 3.0,
        };
        let got = direct(
            NONE,
            &[light],
            DVec3::ZERO,
            DVec3::Y,
            v,
            c,
            &m(0.0, phong),
            &mut 0,
        );
        let spec = 0.5 / (2.0 * 2f64.sqrt());
        let want = Color::new(0.2 + spec, spec, spec);
        assert!((got - want).length() < 1e-12, "{got}");
    }

    #[test]
    fn opaque_blocker_casts_a_black_shadow() {
        let blocker = ball(DVec3::new(0.0, 3.0, 0.0), 0.0, Color::ONE);
        let t = transmission(&[blocker], DVec3::ZERO, DVec3::Y, 5.0);
        assert_eq!(t, Color::ZERO);
        // A blocker beyond the light does not count.
        let t = transmission(&[blocker], DVec3::ZERO, DVec3::Y, 1.5);
        assert_eq!(t, Color::ONE);
    }

    #[test]
    fn glass_passes_kt_times_colour_per_crossing() {
        // Kt = 0.8, colour (1, 0.5, 0.5), crossed twice: (0.8·C)².
        let c = Color::new(1.0, 0.5, 0.5);
        let glass = ball(DVec3::new(0.0, 3.0, 0.0), 0.8, c);
        let t = transmission(&[glass], DVec3::ZERO, DVec3::Y, 10.0);
        let want = Color::new(0.64, 0.16, 0.16);
        assert!((t - want).length() < 1e-12, "{t}");
        // The light inside the glass sphere: one crossing only.
        let t = transmission(&[glass], DVec3::ZERO, DVec3::Y, 3.0);
        assert!((t - Color::new(0.8, 0.4, 0.4)).length() < 1e-12, "{t}");
    }
}
