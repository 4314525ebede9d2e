//! Cameras and lights inside objects, on the eye and on the image's centre.

use super::*;

// ---------------------------------------------------------------------------------------
// Inside objects
// ---------------------------------------------------------------------------------------

#[test]
fn camera_inside_an_opaque_sphere_sees_only_its_ambient_inside() {
    let colour = DVec3::new(0.8, 0.2, 0.2);
    let s = SceneText::new(
        32,
        24,
        DVec3::new(0.5, 0.3, -0.2),
        DVec3::new(0.0, 0.0, -3.0),
    )
    .sphere(5.0, DVec3::ZERO, RED, MATTE)
    .plane(DVec3::new(0.0, -10.0, 0.0), DVec3::Y, CHECKER, MATTE)
    .light(DVec3::new(10.0, 10.0, 10.0), 1.0)
    .light(DVec3::new(-20.0, 3.0, 0.0), 1.0);
    let img = check("inside-opaque", &s);
    // Every light is outside: the shadow ray from a point of the inner wall leaves through
    // the sphere, and is blocked, except where its chord inside is shorter than the
    // report's epsilon (t > 0.01): at N·L < 0.01/(2R). There a sliver of diffuse light
    // leaks, at most Σ I·N·L = 2·0.01/10 on top of the ambient 0.2 (a property of the
    // epsilon, SPEC §2). Kd = 1: no specular; everything is a multiple of C.
    for j in 0..24 {
        for i in 0..32 {
            let c = img.at(i, j);
            let k = c.x / colour.x;
            assert!(close(c, k * colour), "({i},{j}) {c}");
            assert!((0.2 - 1e-12..=0.2 + 0.002).contains(&k), "({i},{j}) {c}");
        }
    }
}

#[test]
fn camera_inside_a_glass_sphere() {
    for ior in [1.5, 1.0, 0.5, 2.4] {
        let s = SceneText::new(
            32,
            24,
            DVec3::new(0.0, 0.5, 1.0),
            DVec3::new(0.0, 0.0, -5.0),
        )
        .sphere(3.0, DVec3::ZERO, WHITE, &glass(ior))
        .sphere(1.0, DVec3::new(0.0, 0.0, -6.0), RED, SHINY)
        .plane(DVec3::new(0.0, -4.0, 0.0), DVec3::Y, CHECKER, MATTE)
        .light(DVec3::new(5.0, 8.0, 5.0), 1.0);
        let img = check(&format!("inside-glass-{ior}"), &s);
        assert!(count_non_black(&img) > 0);
    }
}

#[test]
fn camera_inside_a_cylinder_and_inside_a_glass_cylinder() {
    for mat in [MATTE.to_string(), glass(1.3), glass(0.5)] {
        let s = SceneText::new(
            32,
            24,
            DVec3::new(0.2, 0.0, 0.0),
            DVec3::new(0.0, 1.0, -4.0),
        )
        .cylinder(DVec3::new(0.0, 0.3, 1.0), DVec3::ZERO, 2.0, MARBLE, &mat)
        .sphere(0.5, DVec3::new(0.0, 0.0, -5.0), RED, SHINY)
        .light(DVec3::new(0.0, 0.0, 3.0), 1.0)
        .light(DVec3::new(8.0, 8.0, 8.0), 1.0);
        check("inside-cylinder", &s);
    }
}

#[test]
fn a_light_inside_an_opaque_sphere_lights_nothing() {
    let base = SceneText::new(
        32,
        24,
        DVec3::new(0.0, 3.0, 10.0),
        DVec3::new(0.0, 1.0, 0.0),
    )
    .sphere(1.0, DVec3::new(0.0, 1.0, 0.0), RED, SHINY)
    .plane(DVec3::ZERO, DVec3::Y, CHECKER, SHINY);
    let dark = check("no-light", &base);
    let lit = check(
        "light-inside",
        &base
            .clone()
            .light(DVec3::new(0.0, 1.0, 0.0), 1.0)
            .light(DVec3::new(0.3, 1.2, -0.1), 5.0),
    );
    assert_eq!(dark.frame, lit.frame);
}

#[test]
fn a_light_inside_glass_and_lights_on_surfaces() {
    let s = SceneText::new(
        32,
        24,
        DVec3::new(0.0, 3.0, 10.0),
        DVec3::new(0.0, 1.0, 0.0),
    )
    .sphere(1.0, DVec3::new(0.0, 1.0, 0.0), WHITE, &glass(1.5))
    .sphere(1.0, DVec3::new(2.5, 1.0, 0.0), RED, SHINY)
    .plane(DVec3::ZERO, DVec3::Y, CHECKER, SHINY)
    .cylinder(DVec3::Y, DVec3::new(-2.5, 0.0, 0.0), 0.5, GREEN, MATTE)
    // Inside the glass, on its centre.
    .light(DVec3::new(0.0, 1.0, 0.0), 1.0)
    // Exactly on the floor, on the red sphere, on the cylinder.
    .light(DVec3::ZERO, 1.0)
    .light(DVec3::new(2.5, 2.0, 0.0), 1.0)
    .light(DVec3::new(-2.0, 1.0, 0.0), 1.0);
    let img = check("light-in-glass", &s);
    assert!(count_non_black(&img) > 0);
}

#[test]
fn a_light_at_the_eye_and_on_the_image_centre() {
    // Odd sizes put a pixel centre exactly on the view axis.
    let eye = DVec3::new(0.0, 5.0, 0.0);
    let s = SceneText::new(33, 25, eye, DVec3::ZERO)
        .plane(DVec3::ZERO, DVec3::Y, CHECKER, SHINY)
        .sphere(1.0, DVec3::new(2.0, 1.0, 0.0), RED, MIRROR)
        .light(eye, 1.0)
        .light(DVec3::ZERO, 1.0);
    check("light-at-eye", &s);
}
