//! The direction grids against the linear scans, bit for bit: the light buffer's shadow
//! queries against `shading::transmission`, the screen tiles' first hits (camera rays and
//! their reflections off a polished floor) against the linear nearest-hit scan, on random scenes (spheres with duplicates, planes, axis-aligned and
//! slanted cylinders, transparent objects, NaN Kt, a sky dome around everything) and on
//! rays grazing the silhouettes of the spheres and cylinders seen from the grid's centre.

use super::tests::{bits, linear_nearest, object, scene, Rng};
use super::{LightBuffer, TileView};
use crate::base::Color;
use crate::camera::Camera;
use crate::lights::PointLight;
use crate::object::Object;
use crate::optics::{reflect, Ray};
use crate::shading;
use crate::shapes::{Shape, Sphere};
use crate::texture::Texture;
use glam::DVec3;

/// `scene`, and for odd `n` an opaque dome of radius 500 around everything (a scale
/// that makes the margins wide; without it they are tight).
fn domed(rng: &mut Rng, n: usize) -> Vec<Object> {
    let mut objects = scene(rng, n);
    if n.is_multiple_of(2) {
        return objects;
    }
    let sky = Texture::Uniform(Color::new(0.7, 0.8, 0.95));
    objects.push(object(
        Shape::Sphere(Sphere::new(DVec3::ZERO, 500.0)),
        0.0,
        sky,
    ));
    objects
}

/// Points seen from `from` just inside or outside the silhouette of every sphere and
/// along the edges of every cylinder (nudged by a few 1e-9 of the radius), `far` beyond.
fn grazing(objects: &[Object], from: DVec3, rng: &mut Rng) -> Vec<DVec3> {
    let mut dirs = Vec::new();
    for o in objects {
        let (c, r) = match o.shape {
            Shape::Sphere(s) => (s.center, s.radius),
            Shape::Quadric(q) => (q.origin + rng.vec(3.0).project_onto(DVec3::Y), 0.35),
            Shape::Plane(_)
            | Shape::Triangle(_)
            | Shape::Smooth(_)
            | Shape::Cone(_)
            | Shape::Placed(_)
            | Shape::Mesh(_)
            | Shape::Csg(_) => continue,
        };
        let to = c - from;
        let side = to
            .any_orthonormal_vector()
            .lerp(to.cross(DVec3::X), rng.next());
        let edge = c + side.normalize() * r * (1.0 + rng.next() * 1e-9);
        dirs.push((edge - from).normalize());
    }
    dirs
}

#[test]
fn light_buffer_answers_as_the_linear_scan() {
    let mut answered = 0;
    for (seed, n) in [(3u64, 8usize), (41, 21), (977, 45), (12, 30)] {
        let mut rng = Rng(seed.wrapping_mul(0x9e37_79b9_7f4a_7c15) | 1);
        let objects = domed(&mut rng, n);
        assert!(objects.len() <= 64, "{}", objects.len());
        let lights: Vec<PointLight> = (0..4)
            .map(|k| PointLight {
                // One light inside a sphere (object 0), the others anywhere.
                position: if k == 0 {
                    match objects[0].shape {
                        Shape::Sphere(s) => s.center,
                        _ => unreachable!(),
                    }
                } else {
                    rng.vec(12.0)
                },
                color: Color::ONE,
                intensity: 1.0,
            })
            .collect();
        let buffer = LightBuffer::new(&objects, &lights);
        for (k, light) in lights.iter().enumerate() {
            let mut points: Vec<DVec3> = (0..3000).map(|_| rng.vec(10.0)).collect();
            // Points on the surfaces (where shadow rays start), far out on the floor, on
            // the dome, and beyond the grazing directions.
            for i in 0..3000 {
                let ray = Ray::new(rng.vec(9.0), rng.vec(1.0).normalize());
                if let Some(t) = linear_nearest(&objects, &ray) {
                    points.push(ray.at(f64::from_bits(t.0)));
                }
                if i % 10 == 0 {
                    points.push(DVec3::new(rng.next() * 1e6, -6.0, rng.next() * 1e6));
                }
            }
            for d in grazing(&objects, light.position, &mut rng) {
                for far in [5.0, 20.0, 300.0] {
                    points.push(light.position + d * far);
                }
            }
            // Points in a thin shell around the dome, where the buffer skips it: on it,
            // and just inside and outside, on both sides of where its entry reaches ε.
            if let Some(Shape::Sphere(dome)) = objects.last().map(|o| o.shape.clone()) {
                for e in [
                    -1e-6, 0.0, 1e-9, 1e-4, 1e-3, 2e-3, 2.5e-3, 3e-3, 5e-3, 9e-3, 0.01, 0.011,
                    0.02, 0.1,
                ] {
                    for _ in 0..40 {
                        let u = rng.vec(1.0).normalize();
                        points.push(dome.center + u * (dome.radius + e));
                    }
                }
            }
            for p in points {
                let to = light.position - p;
                let dist = to.length();
                if dist == 0.0 {
                    continue;
                }
                let l = to / dist;
                let want = shading::transmission(&objects, p, l, dist);
                if let Some(got) = buffer.transmission(k, &objects, p, to, l, dist) {
                    assert_eq!(
                        bits(got),
                        bits(want),
                        "light {k} from {p} to {}",
                        light.position
                    );
                    answered += 1;
                }
            }
        }
    }
    assert!(answered > 60_000, "{answered}");
}

/// A camera ray's tile lists, and those of its reflection off the polished floor, give
/// the linear scan's first hit, bit for bit, for random sub-pixel samples of every pixel.
#[test]
fn tile_lists_answer_as_the_linear_scan() {
    let (mut direct, mut mirrored) = (0, 0);
    for (seed, n) in [(5u64, 6usize), (64, 25), (1000, 45), (77, 12)] {
        let mut rng = Rng(seed.wrapping_mul(0x9e37_79b9_7f4a_7c15) | 1);
        let mut objects = domed(&mut rng, n);
        let floor = objects
            .iter()
            .position(|o| matches!(o.shape, Shape::Plane(_)))
            .expect("a floor");
        objects[floor].material.kr = 0.2;
        let Shape::Plane(plane) = objects[floor].shape else {
            unreachable!()
        };
        for scale in [1.0, 10.0, 1e4] {
            // Eyes above the floor (y = −6), looking down at the scene.
            let eye = rng.vec(scale) * DVec3::new(1.0, 0.0, 1.0) + DVec3::Y * scale.max(8.0);
            let camera = Camera::new(eye, rng.vec(3.0), 48, 36).expect("a camera");
            let view = TileView::new(&camera, 48, 36, &objects).expect("tiles");
            for j in 0..36 {
                for i in 0..48 {
                    let hint = view.hint(i, j);
                    for _ in 0..3 {
                        let (x, y) = (
                            f64::from(i) + rng.next().abs(),
                            f64::from(j) + rng.next().abs(),
                        );
                        let ray = camera.ray(x, y);
                        let want = linear_nearest(&objects, &ray);
                        let got = hint.nearest(&objects, &ray).expect("a camera ray");
                        assert_eq!(got.map(|(t, i)| (t.to_bits(), i)), want, "{ray:?}");
                        direct += 1;
                        let Some((t, _)) = got.filter(|&(_, k)| k == floor) else {
                            continue;
                        };
                        // The reflection ray exactly as the tracer makes it.
                        let r = Ray::new(ray.at(t), reflect(ray.dir, -plane.normal()).normalize());
                        if let Some(got) = hint.mirrored(&objects, &r) {
                            let want = linear_nearest(&objects, &r);
                            assert_eq!(got.map(|(t, i)| (t.to_bits(), i)), want, "{r:?}");
                            mirrored += 1;
                        }
                    }
                }
            }
            // Another origin: not the lists' to answer.
            let hint = view.hint(0, 0);
            assert!(hint
                .nearest(&objects, &Ray::new(eye + DVec3::X, DVec3::Y))
                .is_none());
        }
    }
    assert!(direct > 60_000 && mirrored > 5_000, "{direct} {mirrored}");
}
