//! Rays tangent to, along and parallel to the shapes; looking straight up and down.

use super::*;

#[test]
fn rays_tangent_to_spheres() {
    let base = SceneText::new(32, 24, DVec3::new(0.0, 1.0, 8.0), DVec3::new(0.0, 1.0, 0.0))
        .plane(DVec3::ZERO, DVec3::Y, CHECKER, SHINY)
        .light(DVec3::new(-6.0, 8.0, 8.0), 0.9)
        .light(DVec3::new(6.0, 2.0, 3.0), 0.5);
    let camera = base.camera();
    let mut s = base.clone();
    let mats = [
        MATTE.to_string(),
        MIRROR.to_string(),
        glass(1.5),
        glass(0.5),
    ];
    let mut grazing = 0;
    // Spheres whose silhouettes pass exactly through pixel centres on a diagonal.
    for (k, step) in (0..16u32).enumerate() {
        let (i, j) = (2 * step, (3 * step) % 24);
        let ray = camera.ray(i as f64 + 0.5, j as f64 + 0.5);
        let r = 0.05 + 0.03 * step as f64;
        let side = if step % 2 == 0 { DVec3::Y } else { DVec3::X };
        let c = ray.at(4.0 + 0.2 * step as f64) + r * perpendicular(ray.dir, side);
        // Read back as the parser will (the text round-trips exactly).
        let sphere = Sphere::new(c, r);
        let roots = sphere.roots(&ray);
        if let [t0, t1] = roots.as_slice() {
            if (t1 - t0).abs() < 1e-3 {
                grazing += 1;
            }
        } else if roots.as_slice().is_empty() {
            grazing += 1; // missed by a rounding error: still a grazing ray
        }
        let tex = [RED, WOOD, PERLIN, WHITE][k % 4];
        s = s.sphere(r, c, tex, &mats[k % mats.len()]);
    }
    assert_eq!(grazing, 16, "the spheres are not tangent to their rays");
    check("tangent-spheres", &s);
}

#[test]
fn rays_tangent_to_cylinders() {
    let base = SceneText::new(32, 24, DVec3::new(0.0, 1.0, 8.0), DVec3::new(0.0, 1.0, 0.0))
        .plane(DVec3::ZERO, DVec3::Y, CHECKER, SHINY)
        .light(DVec3::new(-6.0, 8.0, 8.0), 0.9);
    let camera = base.camera();
    let mut s = base.clone();
    let axes = [
        DVec3::Y,
        DVec3::X,
        DVec3::new(1.0, 1.0, 0.0),
        DVec3::new(0.3, -1.0, 0.7),
    ];
    let mats = [
        MATTE.to_string(),
        glass(1.5),
        MIRROR.to_string(),
        glass(1.0),
    ];
    for step in 0..8u32 {
        let (i, j) = (1 + 4 * step, 2 + 3 * step);
        let ray = camera.ray(i as f64 + 0.5, j as f64 + 0.5);
        let axis = axes[step as usize % axes.len()].normalize();
        let r = 0.1 + 0.05 * step as f64;
        // The common perpendicular of the ray and the axis has length r: a tangent line.
        let p = ray.at(3.0 + 0.5 * step as f64) + r * perpendicular(ray.dir, axis);
        let q = Quadric::cylinder(axis, p, r);
        match q.roots(&ray).as_slice() {
            [t0, t1] => assert!((t1 - t0).abs() < 1e-3, "not tangent: {t0} {t1}"),
            [] => {}
            one => panic!("a single root {one:?} for a tangent ray"),
        }
        s = s.cylinder(axis, p, r, GREEN, &mats[step as usize % mats.len()]);
    }
    check("tangent-cylinders", &s);
}

#[test]
fn rays_along_a_cylinders_axis() {
    // The camera on the axis, looking along it; odd sizes put the centre ray on the axis.
    for axis in [DVec3::Z, DVec3::Y, DVec3::new(1.0, 1.0, 1.0)] {
        let a = axis.normalize();
        let eye = 5.0 * a;
        let s = SceneText::new(33, 25, eye, -5.0 * a)
            .cylinder(axis, DVec3::ZERO, 1.0, CHECKER, SHINY)
            .cylinder(axis, DVec3::new(3.0, 0.0, 0.0), 0.5, WHITE, &glass(1.5))
            .light(DVec3::new(0.0, 0.5, 0.0), 1.0)
            .light(eye, 0.5);
        let img = check("along-axis", &s);
        assert!(count_non_black(&img) > 0);
    }
}

#[test]
fn rays_along_a_cylinders_surface() {
    // The camera on the cylinder itself, looking along a ruling.
    let s = SceneText::new(
        33,
        25,
        DVec3::new(1.0, 0.0, 5.0),
        DVec3::new(1.0, 0.0, -5.0),
    )
    .cylinder(DVec3::Z, DVec3::ZERO, 1.0, CHECKER, MIRROR)
    .cylinder(DVec3::Z, DVec3::new(2.0, 0.0, 0.0), 1.0, WHITE, &glass(1.5))
    .light(DVec3::new(0.0, 3.0, 0.0), 1.0);
    check("along-surface", &s);
}

#[test]
fn rays_parallel_to_a_plane() {
    // The camera in the floor plane, and in a slanted plane; odd sizes put a row of pixel
    // centres in the plane.
    let s = SceneText::new(
        33,
        25,
        DVec3::new(0.0, 0.0, 5.0),
        DVec3::new(0.0, 0.0, -5.0),
    )
    .plane(DVec3::ZERO, DVec3::Y, CHECKER, MIRROR)
    .plane(DVec3::ZERO, DVec3::new(1.0, 1e-13, 0.0), WHITE, &glass(1.5))
    .sphere(1.0, DVec3::new(0.0, 0.0, -4.0), RED, SHINY)
    .light(DVec3::new(0.0, 0.0, 0.0), 1.0)
    .light(DVec3::new(3.0, 3.0, 3.0), 1.0);
    check("in-the-plane", &s);
    // A slanted plane through the origin; the eye is a point of it (projected onto it),
    // looking along it.
    let n = DVec3::new(0.3, 1.0, -0.2).normalize();
    let eye = DVec3::X - n * n.dot(DVec3::X);
    let look = eye + perpendicular(n, DVec3::X) * 7.0;
    let s = SceneText::new(33, 25, eye, look)
        .plane(DVec3::ZERO, n, MARBLE, SHINY)
        .light(DVec3::new(0.0, 5.0, 0.0), 1.0);
    check("in-a-slanted-plane", &s);
}

#[test]
fn looking_straight_up_and_down() {
    for (eye, look) in [
        (DVec3::new(0.0, 10.0, 0.0), DVec3::ZERO),
        (DVec3::new(0.0, -10.0, 0.0), DVec3::ZERO),
        (DVec3::new(1e-12, 10.0, 0.0), DVec3::ZERO),
    ] {
        check(
            "vertical-camera",
            &room(SceneText::new(32, 24, eye, look), DVec3::ZERO),
        );
    }
}
