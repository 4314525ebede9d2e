//! Acceleration structures, built once per scene (in `Tracer::new`) and shared by every
//! frame and thread: a BVH over the bounded objects (spheres) and plain lists of the
//! unbounded ones (planes, cylinders), which every query tests.
//!
//! Every query answers exactly what the linear scans over `Scene::objects` answer, bit for
//! bit (the linear versions are kept as the reference, and the tests compare them):
//! - `nearest`: the hit with the smallest t, and on equal t the object that comes first in
//!   the file, as the linear scan (which only replaces its best on a strictly smaller t)
//!   keeps it;
//! - `transmission`: black when an opaque object blocks the shadow ray, otherwise the
//!   product of `Kt·C` over the crossings of transparent objects, multiplied in object
//!   order and, within an object, in t order — the linear scan's order, so that the
//!   rounding of the product is the same.

mod bvh;
mod dirgrid;
mod lightbuf;
mod tiles;

pub use bvh::{Bvh, Prim};
pub use dirgrid::DirGrid;
pub use lightbuf::LightBuffer;
pub use tiles::{Hint, TileView};

use crate::object::Object;
use crate::optics::Ray;
use crate::shapes::Shape;
use crate::texture::Color;
use glam::DVec3;

/// Up to this many transparent objects, shadow rays test them all in order after the
/// tree, as the linear scan does; past it they collect the crossings the tree finds.
const GLASS_LINEAR_MAX: usize = 4;
/// Crossings a shadow ray collects before it gives up and falls back to the linear loop
/// over every transparent object (no allocation either way).
const CROSSINGS_MAX: usize = 32;

/// The scene's objects sorted for fast ray queries.
#[derive(Clone, Debug, Default)]
pub struct Accel {
    /// Every bounded object: nearest hits, and shadow rays (which stop at the first
    /// opaque hit, and note the transparent crossings on the way).
    tree: Bvh,
    /// Unbounded objects, in object order, with their indices.
    unbounded: Vec<(u32, Shape)>,
    unbounded_opaque: Vec<Shape>,
    unbounded_glass: Vec<u32>,
    /// Every object with Kt > 0, in object order.
    glass_all: Vec<u32>,
}

/// Kt > 0: shadow rays cross it (the linear scan's second loop).
fn is_glass(o: &Object) -> bool {
    o.material.kt > 0.0
}

/// Kt ≤ 0: it stops shadow rays (the linear scan's first loop). Not simply `!is_glass`:
/// an object with a NaN Kt is in neither loop.
fn is_opaque(o: &Object) -> bool {
    o.material.kt <= 0.0
}

/// The transparent crossings of one shadow ray: (object, t), at most `CROSSINGS_MAX`.
struct Crossings {
    buf: [(u32, f64); CROSSINGS_MAX],
    n: usize,
    overflow: bool,
}

impl Crossings {
    #[inline]
    fn push(&mut self, i: u32, t: f64) {
        if self.n < CROSSINGS_MAX {
            self.buf[self.n] = (i, t);
            self.n += 1;
        } else {
            self.overflow = true;
        }
    }
}

impl Accel {
    /// Builds the accelerator over `objects` (a BVH over the spheres from 13 spheres up, the
    /// unbounded shapes in a flat list).
    pub fn new(objects: &[Object]) -> Accel {
        let prims: Vec<Prim> = objects
            .iter()
            .enumerate()
            .filter_map(|(i, o)| match o.shape {
                Shape::Sphere(sphere) => Some(Prim {
                    sphere,
                    index: i as u32,
                    glass: is_glass(o),
                    opaque: is_opaque(o),
                }),
                _ => None,
            })
            .collect();
        let unbounded = |keep: &dyn Fn(&Object) -> bool| -> Vec<(u32, Shape)> {
            objects
                .iter()
                .enumerate()
                .filter(|(_, o)| !o.shape.is_bounded() && keep(o))
                .map(|(i, o)| (i as u32, o.shape))
                .collect()
        };
        Accel {
            tree: Bvh::build(prims),
            unbounded: unbounded(&|_| true),
            unbounded_opaque: unbounded(&is_opaque).into_iter().map(|(_, s)| s).collect(),
            unbounded_glass: unbounded(&is_glass).into_iter().map(|(i, _)| i).collect(),
            glass_all: (0..objects.len() as u32)
                .filter(|&i| is_glass(&objects[i as usize]))
                .collect(),
        }
    }

    /// The nearest hit (t, object index), as the linear scan finds it. Kept out of line:
    /// its callers (camera and secondary rays) stay small, and the compiler's choice
    /// otherwise changed with unrelated edits (2 % of the 10,000-sphere frame either way).
    #[inline(never)]
    pub fn nearest(&self, ray: &Ray) -> Option<(f64, usize)> {
        let mut best_t = f64::INFINITY;
        let mut best_i = u32::MAX;
        for &(i, ref shape) in &self.unbounded {
            if let Some(t) = shape.hit(ray, f64::INFINITY) {
                if t < best_t || (t == best_t && i < best_i) {
                    best_t = t;
                    best_i = i;
                }
            }
        }
        self.tree.traverse(ray, best_t, |prim, limit| {
            if let Some(t) = prim.sphere.hit(ray, f64::INFINITY) {
                if t < best_t || (t == best_t && prim.index < best_i) {
                    best_t = t;
                    best_i = prim.index;
                    return Some(t);
                }
            }
            Some(limit)
        });
        (best_i != u32::MAX).then_some((best_t, best_i as usize))
    }

    /// What a shadow ray from `p` along the unit `to_light` lets through over (T_MIN,
    /// dist): exactly `shading::transmission(objects, p, to_light, dist)`.
    ///
    /// Always inlined, as 46b440d's build inlined it on its own into `shading::direct`,
    /// its one caller then: `direct_rec` with a recorder made a second one, LLVM kept it
    /// out of line, and the call in the light loop (cold where the light buffer answers)
    /// cost `direct` 20 M instructions on the orbit at one thread (callgrind) in spills
    /// around it; where the buffer cannot answer it is the hot path itself.
    #[inline(always)]
    pub fn transmission(&self, objects: &[Object], p: DVec3, to_light: DVec3, dist: f64) -> Color {
        let ray = Ray::new(p, to_light);
        for shape in &self.unbounded_opaque {
            if shape.hit(&ray, dist).is_some() {
                return Color::ZERO;
            }
        }
        if self.glass_all.len() > GLASS_LINEAR_MAX {
            return self.transmission_collecting(objects, &ray, dist);
        }
        // Few transparent objects: the tree only looks for an opaque blocker ...
        if let Some(opaque) = self.tree.flat_opaque() {
            for prim in opaque {
                if prim.sphere.hit(&ray, dist).is_some() {
                    return Color::ZERO;
                }
            }
        } else {
            let mut blocked = false;
            self.tree.traverse(&ray, dist, |prim, limit| {
                if prim.opaque && prim.sphere.hit(&ray, dist).is_some() {
                    blocked = true;
                    return None;
                }
                Some(limit)
            });
            if blocked {
                return Color::ZERO;
            }
        }
        // ... and the transparent ones are crossed in the linear scan's own loop.
        self.glass_linear(objects, &ray, dist)
    }

    /// The linear scan's loop over the transparent objects.
    #[inline(always)]
    fn glass_linear(&self, objects: &[Object], ray: &Ray, dist: f64) -> Color {
        let mut through = Color::ONE;
        for &i in &self.glass_all {
            let obj = &objects[i as usize];
            for t in obj.shape.crossings(ray, dist) {
                through *= obj.material.kt * obj.texture.color_at(ray.at(t));
            }
        }
        through
    }

    /// `transmission` for many transparent objects: one walk through the tree stops at an
    /// opaque blocker and collects the transparent crossings, which are then multiplied in
    /// object order (or, past `CROSSINGS_MAX` of them, crossed by `glass_linear`).
    #[inline(never)]
    fn transmission_collecting(&self, objects: &[Object], ray: &Ray, dist: f64) -> Color {
        let mut found = Crossings {
            buf: [(0, 0.0); CROSSINGS_MAX],
            n: 0,
            overflow: false,
        };
        for &i in &self.unbounded_glass {
            for t in objects[i as usize].shape.crossings(ray, dist) {
                found.push(i, t);
            }
        }
        let mut blocked = false;
        self.tree.traverse(ray, dist, |prim, limit| {
            if prim.opaque {
                if prim.sphere.hit(ray, dist).is_some() {
                    blocked = true;
                    return None;
                }
            } else if prim.glass && !found.overflow {
                for t in prim.sphere.roots(ray).crossings(dist) {
                    found.push(prim.index, t);
                }
            }
            Some(limit)
        });
        if blocked {
            return Color::ZERO;
        }
        if found.overflow {
            return self.glass_linear(objects, ray, dist);
        }
        let crossings = &mut found.buf[..found.n];
        // Stable insertion sort by object: each object's crossings stay in t order.
        for k in 1..crossings.len() {
            let mut j = k;
            while j > 0 && crossings[j - 1].0 > crossings[j].0 {
                crossings.swap(j - 1, j);
                j -= 1;
            }
        }
        let mut through = Color::ONE;
        for &(i, t) in crossings.iter() {
            let obj = &objects[i as usize];
            through *= obj.material.kt * obj.texture.color_at(ray.at(t));
        }
        through
    }
}

#[cfg(test)]
mod grid_tests;

#[cfg(test)]
mod tests {
    use super::*;
    use crate::bump::Bump;
    use crate::object::Material;
    use crate::shading;
    use crate::shapes::{Plane, Quadric, Sphere};
    use crate::texture::Texture;

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
            white,
        ));
        objects.push(object(
            Shape::Plane(Plane::new(rng.vec(3.0), rng.vec(1.0))),
            0.6,
            white,
        ));
        objects.push(object(
            Shape::Quadric(Quadric::cylinder(DVec3::Y, rng.vec(4.0), 0.7)),
            0.0,
            white,
        ));
        objects.push(object(
            Shape::Quadric(Quadric::cylinder(rng.vec(1.0), rng.vec(4.0), 0.3)),
            0.5,
            white,
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
}
