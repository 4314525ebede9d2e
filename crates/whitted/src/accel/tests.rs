//! The accelerator against the linear scans, bit for bit.

use super::*;
use crate::base::Color;
use crate::bump::Bump;
use crate::object::Material;
use crate::optics::Ray;
use crate::shading;
use crate::shapes::{Cone, SmoothTriangle, Triangle};
use crate::shapes::{Plane, Quadric, Sphere};
use crate::texture::Texture;
use glam::DVec3;

/// xorshift in −1..1, deterministic.
pub(super) struct Rng(pub(super) u64);
impl Rng {
    pub(super) fn next(&mut self) -> f64 {
        self.0 ^= self.0 << 13;
        self.0 ^= self.0 >> 7;
        self.0 ^= self.0 << 17;
        (self.0 >> 11) as f64 / (1u64 << 53) as f64 * 2.0 - 1.0
    }
    pub(super) fn vec(&mut self, s: f64) -> DVec3 {
        DVec3::new(self.next() * s, self.next() * s, self.next() * s)
    }
}

pub(super) fn object(shape: Shape, kt: f64, texture: Texture) -> Object {
    Object {
        shape,
        texture,
        material: Material {
            kd: 0.5,
            kr: 0.0,
            kt,
            ior: 1.5,
            bump: Bump::None,
            highlight: Default::default(),
        },
    }
}

/// `n` spheres (some of them twice, at the same place: ties), a floor, a tilted plane
/// and two cylinders; about a third of everything is transparent.
pub(super) fn scene(rng: &mut Rng, n: usize) -> Vec<Object> {
    let mut objects = Vec::new();
    for i in 0..n {
        let c = rng.vec(6.0);
        let r = 0.05 + rng.next().abs() * 1.5;
        let kt = if i % 11 == 5 {
            f64::NAN // in neither of the shadow loops
        } else if rng.next() > 0.3 {
            0.0
        } else {
            0.2 + rng.next().abs() * 0.7
        };
        let tex = if i % 4 == 0 {
            Texture::Checker(rng.vec(1.0).abs(), rng.vec(1.0).abs())
        } else {
            Texture::Uniform(rng.vec(1.0).abs())
        };
        objects.push(object(Shape::Sphere(Sphere::new(c, r)), kt, tex));
        if i % 7 == 3 {
            let tex = Texture::Uniform(rng.vec(1.0).abs());
            objects.push(object(Shape::Sphere(Sphere::new(c, r)), kt * 0.5, tex));
        }
    }
    let white = Texture::Uniform(Color::ONE);
    objects.push(object(
        Shape::Plane(Plane::new(DVec3::new(0.0, -6.0, 0.0), DVec3::Y)),
        0.0,
        white.clone(),
    ));
    objects.push(object(
        Shape::Plane(Plane::new(rng.vec(3.0), rng.vec(1.0))),
        0.6,
        white.clone(),
    ));
    objects.push(object(
        Shape::Quadric(Quadric::cylinder(DVec3::Y, rng.vec(4.0), 0.7)),
        0.0,
        white.clone(),
    ));
    objects.push(object(
        Shape::Quadric(Quadric::cylinder(rng.vec(1.0), rng.vec(4.0), 0.3)),
        0.5,
        white.clone(),
    ));
    objects
}

pub(super) fn linear_nearest(objects: &[Object], ray: &Ray) -> Option<(u64, usize)> {
    let mut best = None;
    let mut t_max = f64::INFINITY;
    for (i, obj) in objects.iter().enumerate() {
        if let Some(t) = obj.shape.hit(ray, t_max) {
            t_max = t;
            best = Some((t.to_bits(), i));
        }
    }
    best
}

pub(super) fn bits(c: Color) -> [u64; 3] {
    [c.x.to_bits(), c.y.to_bits(), c.z.to_bits()]
}

/// Rays from inside the scene, from far away, along the axes (zero components), and
/// from points on the objects themselves (as secondary and shadow rays start).
fn check(objects: &[Object], rng: &mut Rng, rays: usize) -> (usize, usize) {
    let accel = Accel::new(objects);
    let (mut hits, mut shadowed) = (0, 0);
    for k in 0..rays {
        let scale: f64 = [1.0, 10.0, 1e3, 1e6][k % 4];
        let mut origin = rng.vec(8.0 * scale.min(10.0)) + rng.vec(scale);
        let mut dir = if k % 5 == 0 {
            let axes = [
                DVec3::X,
                DVec3::Y,
                DVec3::Z,
                -DVec3::X,
                -DVec3::Y,
                -DVec3::Z,
            ];
            axes[k / 5 % 6]
        } else {
            (rng.vec(1.0) - origin * 1e-3 / scale).normalize()
        };
        if k % 3 == 0 {
            // Start on the nearest surface, as secondary rays do.
            if let Some((t, _)) = accel.nearest(&Ray::new(origin, dir)) {
                origin += dir * t;
                dir = rng.vec(1.0).normalize();
            }
        }
        let ray = Ray::new(origin, dir);
        let want = linear_nearest(objects, &ray);
        let got = accel.nearest(&ray).map(|(t, i)| (t.to_bits(), i));
        assert_eq!(got, want, "{ray:?}");
        hits += want.is_some() as usize;
        let dist = [f64::INFINITY, 3.0, 30.0][k % 3];
        let want = shading::transmission(objects, origin, dir, dist);
        let got = accel.transmission(objects, origin, dir, dist);
        assert_eq!(bits(got), bits(want), "{ray:?} {dist}");
        shadowed += (want != Color::ONE) as usize;
    }
    (hits, shadowed)
}

#[test]
fn same_answers_as_the_linear_scans_small_scene() {
    let mut rng = Rng(0x1234_5678_9abc_def1);
    let objects = scene(&mut rng, 5);
    let (hits, shadowed) = check(&objects, &mut rng, 20_000);
    assert!(hits > 5000 && shadowed > 2000, "{hits} {shadowed}");
}

#[test]
fn same_answers_as_the_linear_scans_with_trees() {
    for (seed, n) in [(7u64, 40usize), (99, 300), (12345, 1000)] {
        let mut rng = Rng(seed.wrapping_mul(0x9e37_79b9_7f4a_7c15) | 1);
        let objects = scene(&mut rng, n);
        let accel = Accel::new(&objects);
        assert!(!accel.tree.is_flat());
        assert!(accel.glass_all.len() > GLASS_LINEAR_MAX);
        let (hits, shadowed) = check(&objects, &mut rng, 20_000);
        assert!(hits > 5000 && shadowed > 2000, "{hits} {shadowed}");
    }
}

#[test]
fn many_glass_crossings_fall_back_to_the_linear_order() {
    // 40 glass beads on a line: a shadow ray along it crosses 80 surfaces, more than
    // the tree query collects; the product must still be the linear one.
    let objects: Vec<Object> = (0..40)
        .map(|i| {
            let c = DVec3::new(i as f64 * 0.5, 0.0, 0.0);
            let tex = Texture::Uniform(Color::new(0.9, 0.95 + i as f64 * 1e-3, 0.99));
            object(Shape::Sphere(Sphere::new(c, 0.2)), 0.97, tex)
        })
        .collect();
    let accel = Accel::new(&objects);
    assert!(!accel.tree.is_flat());
    for (o, d) in [
        (DVec3::new(-1.0, 0.0, 0.0), DVec3::X),
        (DVec3::new(30.0, 0.01, 0.0), -DVec3::X),
        (
            DVec3::new(-1.0, 0.0, 0.1),
            DVec3::new(1.0, 0.0, -0.002).normalize(),
        ),
    ] {
        let want = shading::transmission(&objects, o, d, f64::INFINITY);
        assert_ne!(want, Color::ONE);
        assert_eq!(
            bits(accel.transmission(&objects, o, d, f64::INFINITY)),
            bits(want)
        );
        // And a few crossings only: the tree's own sorted product.
        let want = shading::transmission(&objects, o, d, 2.0);
        assert_eq!(bits(accel.transmission(&objects, o, d, 2.0)), bits(want));
    }
}

#[test]
fn grazing_rays_from_far_away_find_what_the_linear_scan_finds() {
    // Rays aimed at the silhouettes of small spheres from up to 1e7 away: the sphere
    // test's rounding makes some of these hit although the exact line misses (or the
    // reverse); the widened boxes must let the tree see every one of those hits.
    let mut rng = Rng(0xdead_beef_cafe_f00d);
    let objects: Vec<Object> = (0..200)
        .map(|_| {
            let c = rng.vec(20.0);
            let r = 0.01 + rng.next().abs() * 0.2;
            object(
                Shape::Sphere(Sphere::new(c, r)),
                0.0,
                Texture::Uniform(Color::ONE),
            )
        })
        .collect();
    let accel = Accel::new(&objects);
    let mut hits = 0;
    for k in 0..40_000 {
        let Shape::Sphere(s) = objects[k % objects.len()].shape else {
            unreachable!()
        };
        let far = [1e3, 1e5, 1e7][k % 3];
        let origin = s.center + rng.vec(1.0).normalize() * far;
        let to_centre = (s.center - origin).normalize();
        // A point on the silhouette, nudged in or out by a few ulps of the distance.
        let side = to_centre
            .any_orthonormal_vector()
            .lerp(to_centre.cross(DVec3::X), rng.next());
        let edge = s.center + side.normalize() * s.radius * (1.0 + rng.next() * 1e-9);
        let ray = Ray::new(origin, (edge - origin).normalize());
        let want = linear_nearest(&objects, &ray);
        let got = accel.nearest(&ray).map(|(t, i)| (t.to_bits(), i));
        assert_eq!(got, want, "{ray:?}");
        hits += want.is_some() as usize;
        let want = shading::transmission(&objects, origin, ray.dir, f64::INFINITY);
        let got = accel.transmission(&objects, origin, ray.dir, f64::INFINITY);
        assert_eq!(bits(got), bits(want));
    }
    assert!(hits > 10_000, "{hits}");
}

#[test]
fn equal_t_keeps_the_first_object_in_file_order() {
    // Twenty copies of one sphere, then twenty more elsewhere: any copy may be found
    // first in the tree, the answer must be object 0.
    let mut objects = Vec::new();
    for i in 0..20 {
        let tex = Texture::Uniform(Color::splat(i as f64 / 20.0));
        objects.push(object(
            Shape::Sphere(Sphere::new(DVec3::ZERO, 1.0)),
            0.0,
            tex,
        ));
    }
    for i in 0..20 {
        let c = DVec3::new(5.0 + i as f64, 0.0, 0.0);
        objects.push(object(
            Shape::Sphere(Sphere::new(c, 0.5)),
            0.0,
            Texture::Uniform(Color::ONE),
        ));
    }
    let accel = Accel::new(&objects);
    assert!(!accel.tree.is_flat());
    let ray = Ray::new(DVec3::new(0.0, 0.0, 5.0), -DVec3::Z);
    assert_eq!(accel.nearest(&ray), Some((4.0, 0)));
}

#[test]
fn same_answers_as_the_linear_scans_with_triangles_and_cones() {
    // An NFF's shapes beside spheres: triangles (some sharing edges, some duplicated:
    // ties), smooth triangles and cones, a third glass. With 400 of them the spheres
    // join their tree (`shares_tree`); with 8, the spheres keep a tree of their own and
    // the shapes are a flat list.
    for (shapes, shared) in [(400, true), (8, false)] {
        let mut rng = Rng(0x0bad_cafe_1234_5678);
        let objects = with_shapes(scene(&mut rng, 60), &mut rng, shapes);
        let accel = Accel::new(&objects);
        assert_eq!(accel.tree.is_empty(), shared);
        assert_eq!(accel.spheres.is_empty(), !shared);
        assert_eq!(accel.shapes.is_flat(), !shared);
        let (hits, shadowed) = check(&objects, &mut rng, 20_000);
        assert!(hits > 5000 && shadowed > 2000, "{hits} {shadowed}");
    }
}

/// `objects` and `n` random triangles, smooth triangles and cones after them.
pub(super) fn with_shapes(mut objects: Vec<Object>, rng: &mut Rng, n: usize) -> Vec<Object> {
    for i in 0..n {
        let a = rng.vec(6.0);
        let (b, c) = (a + rng.vec(1.5), a + rng.vec(1.5));
        let kt = if i % 3 == 0 { 0.6 } else { 0.0 };
        let white = Texture::Uniform(Color::splat(0.9));
        let shape = match i % 4 {
            0 | 1 => Triangle::new(a, b, c).map(Shape::Triangle),
            2 => SmoothTriangle::new([a, b, c], [rng.vec(1.0), rng.vec(1.0), rng.vec(1.0)])
                .map(Shape::Smooth),
            _ => Cone::new(a, rng.next().abs(), b, rng.next().abs() * 0.5).map(Shape::Cone),
        };
        if let Some(shape) = shape {
            objects.push(object(shape.clone(), kt, white.clone()));
            if i % 9 == 0 {
                objects.push(object(shape, kt, white.clone()));
            }
            if let (0, Some(t)) = (i % 4, Triangle::new(a, c, a + rng.vec(1.5))) {
                objects.push(object(Shape::Triangle(t), kt, white)); // shares the edge a–c
            }
        }
    }
    objects
}
