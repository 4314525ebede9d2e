//! Extreme sizes and coordinates, coincident surfaces, bump, fog, lights and coefficients at their limits.

use super::*;

// ---------------------------------------------------------------------------------------
// Scales
// ---------------------------------------------------------------------------------------

#[test]
fn coordinates_of_a_million() {
    let far = DVec3::splat(1e6);
    let s = room(
        SceneText::new(32, 24, far + DVec3::new(0.0, 3.0, 15.0), far + DVec3::Y),
        far,
    )
    .cylinder(
        DVec3::Y,
        far + DVec3::new(4.0, 0.0, -2.0),
        0.5,
        GREEN,
        &glass(1.3),
    );
    let img = check("far-room", &s);
    assert!(count_non_black(&img) > 100, "the far room is not visible");
    // Seen from a million units away.
    let s = room(
        SceneText::new(32, 24, DVec3::new(1e6, 1e6, 1e6), DVec3::Y),
        DVec3::ZERO,
    );
    check("far-eye", &s);
    // The eye at the origin, the scene a million units away.
    let s = room(SceneText::new(32, 24, DVec3::ZERO, far), far);
    check("far-scene", &s);
}

#[test]
fn radii_of_ten_to_the_minus_four() {
    let mut s = SceneText::new(33, 25, DVec3::new(0.0, 0.0, 1.0), DVec3::ZERO)
        .plane(DVec3::new(0.0, 0.0, -1.0), DVec3::Z, CHECKER, SHINY)
        .light(DVec3::new(0.0, 2.0, 2.0), 1.0);
    for (k, c) in [
        DVec3::ZERO,
        DVec3::new(0.02, 0.0, 0.0),
        DVec3::new(0.0, 0.98, 0.0),
        DVec3::new(0.0, 0.0, 0.985),
    ]
    .into_iter()
    .enumerate()
    {
        let mat = [
            MATTE.to_string(),
            glass(1.5),
            MIRROR.to_string(),
            glass(0.5),
        ][k]
            .clone();
        s = s
            .sphere(1e-4, c, RED, &mat)
            .cylinder(DVec3::new(1.0, 1.0, 0.0), c, 1e-4, GREEN, &mat);
    }
    check("tiny-radii", &s);
    // Tiny spheres a million units out, a light among them.
    let far = DVec3::splat(1e6);
    let mut s = SceneText::new(32, 24, far + DVec3::new(0.0, 0.0, 0.05), far)
        .light(far + DVec3::new(1e-4, 1e-4, 0.0), 1.0)
        .plane(far + DVec3::new(0.0, 0.0, -1.0), DVec3::Z, CHECKER, MATTE);
    for k in 0..10 {
        let c = far + DVec3::new(1e-3 * (k as f64 - 5.0), 2e-4 * k as f64, -1e-3 * k as f64);
        s = s.sphere(1e-4, c, RED, if k % 2 == 0 { MIRROR } else { MATTE });
    }
    check("tiny-and-far", &s);
}

#[test]
fn huge_objects() {
    let s = SceneText::new(32, 24, DVec3::new(0.0, 2.0, 10.0), DVec3::ZERO)
        .sphere(1e6, DVec3::new(0.0, -1e6, 0.0), CHECKER, SHINY)
        .sphere(1e9, DVec3::new(0.0, 0.0, -2e9), WHITE, MATTE)
        .cylinder(DVec3::X, DVec3::new(0.0, 0.0, -1e7), 1e6, GREEN, MIRROR)
        .sphere(1.0, DVec3::new(0.0, 1.0, 0.0), WHITE, &glass(1.5))
        .light(DVec3::new(0.0, 1e5, 1e5), 1.0);
    check("huge-objects", &s);
}

// ---------------------------------------------------------------------------------------
// Materials, coincidences, bump, fog, lights
// ---------------------------------------------------------------------------------------

#[test]
fn refraction_indices_one_and_a_half() {
    for ior in [1.0, 0.5, 1e-3, 1e3] {
        let s = room(
            SceneText::new(32, 24, DVec3::new(0.0, 2.0, 8.0), DVec3::new(0.0, 1.0, 0.0)),
            DVec3::ZERO,
        )
        .sphere(1.2, DVec3::new(0.0, 1.2, 3.0), WHITE, &glass(ior))
        .cylinder(
            DVec3::Y,
            DVec3::new(-1.0, 0.0, 2.0),
            0.4,
            WHITE,
            &glass(ior),
        )
        .plane(
            DVec3::new(0.0, 0.0, 6.0),
            DVec3::new(0.0, 0.2, 1.0),
            WHITE,
            &glass(ior),
        );
        check(&format!("ior-{ior}"), &s);
    }
}

#[test]
fn two_coincident_planes_and_spheres_show_the_first() {
    let one = SceneText::new(
        32,
        24,
        DVec3::new(0.0, 3.0, 10.0),
        DVec3::new(0.0, 0.0, 0.0),
    )
    .plane(DVec3::ZERO, DVec3::Y, CHECKER, SHINY)
    .sphere(1.0, DVec3::new(0.0, 1.0, 0.0), RED, SHINY)
    .light(DVec3::new(-6.0, 8.0, 8.0), 1.0);
    // The same plane written twice (once with a flipped normal), the same sphere twice.
    let two = one
        .clone()
        .plane(DVec3::ZERO, DVec3::Y, GREEN, MIRROR)
        .sphere(1.0, DVec3::new(0.0, 1.0, 0.0), GREEN, MIRROR);
    let a = check("one-plane", &one);
    let b = check("coincident", &two);
    assert_eq!(
        a.frame, b.frame,
        "the first of coincident surfaces must win"
    );
    // Coincident glass: crossings of both count, and nothing breaks.
    let glassy = SceneText::new(32, 24, DVec3::new(0.0, 3.0, 10.0), DVec3::ZERO)
        .plane(DVec3::ZERO, DVec3::Y, CHECKER, &glass(1.5))
        .plane(DVec3::ZERO, DVec3::Y, WHITE, &glass(1.2))
        .sphere(1.0, DVec3::new(0.0, 1.0, 0.0), WHITE, &glass(1.5))
        .sphere(1.0, DVec3::new(0.0, 1.0, 0.0), RED, &glass(0.5))
        .light(DVec3::new(-6.0, 8.0, 8.0), 1.0);
    check("coincident-glass", &glassy);
    // The same plane written another way (another point, the normal flipped): which one
    // wins may change from pixel to pixel with rounding, but deterministically.
    let other = one
        .clone()
        .plane(DVec3::new(5.0, 0.0, -3.0), -DVec3::Y, GREEN, MIRROR);
    check("coincident-written-differently", &other);
}

#[test]
fn bump_with_huge_and_tiny_epsilon() {
    for eps in [1e300, -1e300, 1.7e308, 1e15, 1e6, 1e-300, 5e-324, 0.0] {
        for kind in [1, 2] {
            let mat = format!("0.6 0.3 0 1 {kind} {eps:?}");
            let gmat = format!("0.1 0.1 0.9 1.5 {kind} {eps:?}");
            let s = SceneText::new(
                32,
                24,
                DVec3::new(0.0, 3.0, 10.0),
                DVec3::new(0.0, 1.0, 0.0),
            )
            .plane(DVec3::ZERO, DVec3::Y, CHECKER, &mat)
            .sphere(1.0, DVec3::new(-1.2, 1.0, 0.0), RED, &mat)
            .sphere(1.0, DVec3::new(1.2, 1.0, 0.0), WHITE, &gmat)
            .cylinder(DVec3::Y, DVec3::new(0.0, 0.0, -3.0), 0.5, GREEN, &gmat)
            .light(DVec3::new(-6.0, 8.0, 8.0), 1.0);
            check(&format!("bump-{kind}-{eps:e}"), &s);
        }
    }
}

#[test]
fn fog_with_tiny_distances_is_all_white() {
    for kind in [1, 2, 3] {
        for d in [1e-300, 5e-324, 1e-9] {
            let s = room(
                SceneText::new(32, 24, DVec3::new(0.0, 3.0, 15.0), DVec3::Y),
                DVec3::ZERO,
            )
            .fog(kind, d);
            let img = check(&format!("fog-{kind}-{d:e}"), &s);
            for (k, c) in img.colours.iter().enumerate() {
                assert!(close(*c, DVec3::ONE), "fog {kind} {d:e}: pixel {k} is {c}");
            }
        }
    }
}

#[test]
fn fog_with_huge_distances_changes_nothing_visible() {
    let clear = room(
        SceneText::new(32, 24, DVec3::new(0.0, 3.0, 15.0), DVec3::Y),
        DVec3::ZERO,
    );
    let plain = check("no-fog", &clear);
    for kind in [1, 2, 3] {
        for d in [1e300, 1.7e308] {
            let img = check(&format!("fog-{kind}-{d:e}"), &clear.clone().fog(kind, d));
            // Only the background (no hit, infinitely far) turns white.
            for (k, (a, b)) in plain.colours.iter().zip(&img.colours).enumerate() {
                if *a != DVec3::ZERO || *b != DVec3::ONE {
                    let px = |f: &Frame| f.pixels[3 * k..3 * k + 3].to_vec();
                    assert_eq!(
                        px(&plain.frame),
                        px(&img.frame),
                        "fog {kind} {d:e} pixel {k}"
                    );
                }
            }
        }
    }
}

#[test]
fn no_light_at_all() {
    let s = SceneText::new(32, 24, DVec3::new(0.0, 3.0, 15.0), DVec3::Y)
        .plane(DVec3::ZERO, DVec3::Y, CHECKER, MATTE)
        .sphere(1.0, DVec3::new(0.0, 1.0, 0.0), RED, MATTE)
        .cylinder(DVec3::Y, DVec3::new(3.0, 0.0, 0.0), 0.5, GREEN, MATTE);
    let img = check("no-light", &s);
    // Ambient only: every hit pixel is 0.2·C of one of the colours.
    for c in &img.colours {
        let c = *c;
        let ok = [
            DVec3::ZERO,
            DVec3::new(0.8, 0.2, 0.2),
            DVec3::new(0.2, 0.8, 0.3),
            DVec3::splat(0.9),
            DVec3::splat(0.2),
        ]
        .iter()
        .any(|&k| c == DVec3::ZERO || close(c, 0.2 * k));
        assert!(ok, "{c}");
    }
    check(
        "no-light-rich",
        &SceneText {
            lights: Vec::new(),
            ..room(
                SceneText::new(32, 24, DVec3::new(0.0, 3.0, 15.0), DVec3::Y),
                DVec3::ZERO,
            )
        },
    );
}

#[test]
fn fifty_lights() {
    let mut s = room(
        SceneText::new(32, 24, DVec3::new(0.0, 3.0, 15.0), DVec3::Y),
        DVec3::ZERO,
    )
    .cylinder(
        DVec3::Y,
        DVec3::new(4.0, 0.0, -2.0),
        0.5,
        GREEN,
        &glass(1.3),
    );
    for k in 0..49 {
        let a = k as f64 * 0.7;
        let p = DVec3::new(8.0 * a.cos(), 0.5 + (k % 7) as f64, 8.0 * a.sin());
        s = s.light(p, 0.05);
    }
    assert_eq!(s.lights.len(), 50);
    check("fifty-lights", &s);
}

#[test]
fn facing_mirrors_and_lossless_glass_stop_at_the_depth_limit() {
    let s = SceneText::new(32, 24, DVec3::new(0.0, 1.0, 0.0), DVec3::new(1.0, 1.2, 0.3))
        .plane(DVec3::new(3.0, 0.0, 0.0), DVec3::X, WHITE, "0 1 0 1 0 0")
        .plane(DVec3::new(-3.0, 0.0, 0.0), DVec3::X, WHITE, "0 1 0 1 0 0")
        .plane(
            DVec3::new(0.0, -1.0, 0.0),
            DVec3::Y,
            CHECKER,
            "0 1 1 1.5 0 0",
        )
        .sphere(1.0, DVec3::new(1.0, 1.0, 1.0), WHITE, "0 1 1 1.5 0 0")
        .sphere(0.5, DVec3::new(-1.0, 1.0, -1.0), WHITE, "0 1 1 0.5 0 0")
        .light(DVec3::new(0.0, 5.0, 0.0), 1.0);
    check("mirrors", &s);
}

#[test]
fn coefficients_outside_zero_to_one_are_refused() {
    // Colours, Kd, Kr and Kt are 0..1 and intensities 0..1000 (docs/decisions.md): past
    // that, sums of light could overflow into NaN, so the parser refuses them, located.
    let base = |texture: &str, material: &str, intensity: f64| {
        SceneText::new(
            32,
            24,
            DVec3::new(0.0, 3.0, 10.0),
            DVec3::new(0.0, 1.0, 0.0),
        )
        .sphere(1.0, DVec3::new(0.0, 1.0, 0.0), texture, material)
        .light(DVec3::new(6.0, 8.0, 8.0), intensity)
        .text()
    };
    for (src, field) in [
        (base("1 -1 0 0", "0.5 0 0 1 0 0", 1.0), "field R"),
        (base("1 5 5 5", "0.5 0 0 1 0 0", 1.0), "field R"),
        (base("1 1 1 1", "-2 0 0 1 0 0", 1.0), "field Kd"),
        (base("1 1 1 1", "0.5 3 0 1 0 0", 1.0), "field Kr"),
        (base("1 1 1 1", "0.5 0 4 1.5 0 0", 1.0), "field Kt"),
        (base("1 1 1 1", "0.5 0 0 1 0 0", -1.0), "field Intensity"),
        (base("1 1 1 1", "0.5 0 0 1 0 0", 1e4), "field Intensity"),
    ] {
        let err = Scene::parse(&src, "odd.txt").unwrap_err().to_string();
        assert!(
            err.starts_with("odd.txt:") && err.contains(field),
            "{err}\n{src}"
        );
    }
    // The edges of the ranges are fine, and render finite.
    let s = SceneText::new(
        32,
        24,
        DVec3::new(0.0, 3.0, 10.0),
        DVec3::new(0.0, 1.0, 0.0),
    )
    .plane(DVec3::ZERO, DVec3::Y, "1 1 0 0.5", "1 1 0 1 0 0")
    .sphere(1.0, DVec3::new(-1.2, 1.0, 0.0), "1 0 0 0", "0 0 1 1 0 0")
    .sphere(1.0, DVec3::new(1.2, 1.0, 0.0), "1 1 1 1", "1 1 1 1.5 1 0.3")
    .light(DVec3::new(-6.0, 8.0, 8.0), 0.0)
    .light(DVec3::new(6.0, 8.0, 8.0), 1000.0);
    check("edge-coefficients", &s);
}

#[test]
fn a_ray_from_inside_a_tiny_sphere_never_makes_a_nan_normal() {
    // Direct check of the building blocks on the most degenerate rays.
    let s = Sphere::new(DVec3::ZERO, 1e-4);
    for dir in [DVec3::X, DVec3::new(1.0, 1.0, 1.0).normalize()] {
        let r = Ray::new(DVec3::ZERO, dir);
        for t in s.roots(&r).as_slice() {
            assert!(t.is_finite());
            assert!(s.normal(r.at(*t)).is_finite());
        }
    }
    let q = Quadric::cylinder(DVec3::Y, DVec3::ZERO, 1e-4);
    assert!(q.normal(DVec3::new(0.0, 5.0, 0.0)).is_finite());
}
