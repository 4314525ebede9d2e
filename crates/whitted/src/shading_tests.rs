//! Unit tests of `shading`: each term by hand, shadows through glass and opaque blockers.

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

fn white_light(at: DVec3) -> PointLight {
    PointLight {
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
    let t = transmission(std::slice::from_ref(&blocker), DVec3::ZERO, DVec3::Y, 5.0);
    assert_eq!(t, Color::ZERO);
    // A blocker beyond the light does not count.
    let t = transmission(std::slice::from_ref(&blocker), DVec3::ZERO, DVec3::Y, 1.5);
    assert_eq!(t, Color::ONE);
}

#[test]
fn glass_passes_kt_times_colour_per_crossing() {
    // Kt = 0.8, colour (1, 0.5, 0.5), crossed twice: (0.8·C)².
    let c = Color::new(1.0, 0.5, 0.5);
    let glass = ball(DVec3::new(0.0, 3.0, 0.0), 0.8, c);
    let t = transmission(std::slice::from_ref(&glass), DVec3::ZERO, DVec3::Y, 10.0);
    let want = Color::new(0.64, 0.16, 0.16);
    assert!((t - want).length() < 1e-12, "{t}");
    // The light inside the glass sphere: one crossing only.
    let t = transmission(std::slice::from_ref(&glass), DVec3::ZERO, DVec3::Y, 3.0);
    assert!((t - Color::new(0.8, 0.4, 0.4)).length() < 1e-12, "{t}");
}

#[test]
fn phong_weight_without_ks_is_the_same_bits_as_the_product() {
    // Ks = 0 skips the power; the product it replaces is +0 for every finite power of
    // max(0, V·R) in [0, 1 + ε], including the ones that underflow (Shine 100000).
    let vrs = [
        0.0,
        1e-300,
        1e-3,
        0.5,
        0.993,
        0.99999,
        1.0,
        1.0 + f64::EPSILON,
    ];
    for shine in [0.0, 1.0, 3.0827, 101.148, 100000.0] {
        for vr in vrs {
            for i in [0.25, 1.0, 3.5] {
                let skipped = super::phong(0.0, shine)(i, vr);
                let product = 0.0 * i * vr.powf(shine);
                assert_eq!(skipped.to_bits(), product.to_bits(), "{shine} {vr} {i}");
                let kept = super::phong(0.5, shine)(i, vr);
                assert_eq!(kept.to_bits(), (0.5 * i * vr.powf(shine)).to_bits());
            }
        }
    }
    // By hand: Ks 0.5, I 2, (V·R)^3 = 0.125.
    assert_eq!(super::phong(0.5, 3.0)(2.0, 0.5), 0.125);
}
