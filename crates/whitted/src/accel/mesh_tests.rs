//! Meshes in the accelerator: the tree's nearest hit against the linear scan over every
//! triangle (smallest t, then object, then triangle), shadow rays through opaque and
//! glass meshes against a brute-force product, the same tree from one thread and many,
//! and the triangle test itself against a brute-force reference (plane hit and signed
//! areas) on random rays.

use super::tests::{object, Rng};
use super::*;
use crate::base::Color;
use crate::mesh::{Mesh, Raw};
use crate::optics::Ray;
use crate::shapes::{MeshRef, Transform, Triangle};
use crate::texture::Texture;
use glam::DVec3;
use proptest::prelude::*;

/// `n` random small triangles in a 4-unit cube, as one mesh.
pub(super) fn soup(n: usize, seed: u64) -> Mesh {
    let mut rng = Rng(seed);
    let mut raw = Raw::default();
    for k in 0..n as u32 {
        let c = rng.vec(2.0);
        for _ in 0..3 {
            raw.positions.push(c + rng.vec(0.3));
        }
        raw.triangles.push([3 * k, 3 * k + 1, 3 * k + 2]);
    }
    Mesh::from_raw(raw, &Transform::IDENTITY, Some(crate::mesh::Shading::Flat)).unwrap()
}

fn scene(meshes: &[Arc<Mesh>], kt: f64) -> (Vec<Object>, Accel) {
    let mut objects = vec![object(
        Shape::Sphere(crate::shapes::Sphere::new(DVec3::new(0.5, 0.0, 0.0), 0.7)),
        0.0,
        Texture::Uniform(Color::ONE),
    )];
    for (id, m) in meshes.iter().enumerate() {
        let (lo, hi) = m.extent();
        let shape = Shape::Mesh(MeshRef {
            id: id as u32,
            lo,
            hi,
        });
        objects.push(object(
            shape,
            kt,
            Texture::Uniform(Color::new(0.9, 0.5, 0.7)),
        ));
    }
    let accel = Accel::with_meshes(&objects, meshes, T_MIN);
    (objects, accel)
}

/// The linear scan: every triangle of every mesh, and the sphere.
fn brute(objects: &[Object], meshes: &[Arc<Mesh>], ray: &Ray) -> Option<Hit> {
    let mut best: Option<Hit> = None;
    let mut offer = |t: f64, index: usize, part: u32| {
        if best.is_none_or(|b| t < b.t || (t == b.t && (index, part) < (b.index, b.part))) {
            best = Some(Hit { t, index, part });
        }
    };
    for (i, o) in objects.iter().enumerate() {
        match &o.shape {
            Shape::Mesh(m) => {
                let mesh = &meshes[m.id as usize];
                for k in 0..mesh.triangles.len() as u32 {
                    if let Some(t) = mesh.hit(k, ray, f64::INFINITY) {
                        offer(t, i, k);
                    }
                }
            }
            s => {
                if let Some(t) = s.hit(ray, f64::INFINITY) {
                    offer(t, i, NO_PART);
                }
            }
        }
    }
    best
}

#[test]
fn nearest_hits_match_the_linear_scan() {
    let meshes = vec![Arc::new(soup(3000, 7)), Arc::new(soup(500, 11))];
    let (objects, accel) = scene(&meshes, 0.0);
    let mut rng = Rng(99);
    let mut hits = 0;
    for k in 0..2000 {
        let ray = Ray::new(rng.vec(3.0), rng.vec(1.0).normalize());
        let want = brute(&objects, &meshes, &ray);
        hits += usize::from(want.is_some_and(|h| h.part != NO_PART));
        assert_eq!(accel.nearest_hit(&ray), want, "ray {k}");
    }
    assert!(hits > 500, "only {hits} rays hit a triangle");
}

#[test]
fn shadow_rays_through_meshes_match_brute_force() {
    for kt in [0.0, 0.6] {
        let meshes = vec![Arc::new(soup(400, 5))];
        let (objects, accel) = scene(&meshes, kt);
        let mut rng = Rng(3);
        for k in 0..500 {
            let (p, d) = (rng.vec(3.0), rng.vec(1.0).normalize());
            let ray = Ray::new(p, d);
            let sphere = objects[0].shape.crossings(&ray, 4.0).count() > 0;
            let mut ts: Vec<f64> = (0..meshes[0].triangles.len() as u32)
                .filter_map(|t| meshes[0].hit(t, &ray, 4.0))
                .collect();
            ts.sort_by(f64::total_cmp);
            let want = if sphere || (kt == 0.0 && !ts.is_empty()) {
                Color::ZERO
            } else {
                let o = &objects[1];
                ts.iter().fold(Color::ONE, |c, &t| {
                    c * (o.material.kt * o.texture.color_at(ray.at(t)))
                })
            };
            assert_eq!(
                accel.transmission(&objects, p, d, 4.0),
                want,
                "kt {kt} ray {k}"
            );
        }
    }
}

#[test]
fn the_tree_is_the_same_on_any_thread_count() {
    let meshes = vec![Arc::new(soup(40_000, 21))];
    let build = |threads| {
        let pool = rayon::ThreadPoolBuilder::new()
            .num_threads(threads)
            .build()
            .unwrap();
        pool.install(|| scene(&meshes, 0.0).1)
    };
    let (one, four) = (build(1), build(4));
    assert_eq!(format!("{:?}", one.shapes), format!("{:?}", four.shapes));
    assert!(one.shapes.depth() > 5);
}

/// The reference: the ray's line meets the triangle's plane at t; the point is inside
/// when the three signed areas against the edges share the normal's sign.
fn reference(a: DVec3, b: DVec3, c: DVec3, ray: &Ray) -> Option<(f64, f64)> {
    let n = (b - a).cross(c - a);
    let dn = ray.dir.dot(n);
    if dn == 0.0 {
        return None;
    }
    let t = (a - ray.origin).dot(n) / dn;
    let p = ray.at(t);
    let w = [(a, b), (b, c), (c, a)].map(|(u, v)| (v - u).cross(p - u).dot(n) / n.length_squared());
    let margin = w.iter().fold(f64::INFINITY, |m, &x| m.min(x));
    Some((t, margin))
}

proptest! {
    #[test]
    fn triangle_test_agrees_with_the_reference(
        pts in prop::array::uniform9(-3.0f64..3.0),
        o in prop::array::uniform3(-6.0f64..6.0),
        d in prop::array::uniform3(-1.0f64..1.0),
    ) {
        let [a, b, c] = [0, 3, 6].map(|i| DVec3::new(pts[i], pts[i + 1], pts[i + 2]));
        prop_assume!(Triangle::new(a, b, c).is_some() && DVec3::from(d).length() > 0.1);
        prop_assume!((b - a).cross(c - a).length() > 0.05);
        let ray = Ray::new(DVec3::from(o), DVec3::from(d).normalize());
        let got = Triangle::uvt_of(a, b - a, c - a, &ray).map(|(_, _, t)| t);
        if let Some((t, margin)) = reference(a, b, c, &ray) {
            // Away from the edges (by a relative 1e-7 of the barycentric weights), the
            // two agree on hit or miss, and on t to 1e-9.
            if margin > 1e-7 {
                let got = got.expect("the reference hits inside");
                prop_assert!((got - t).abs() <= 1e-9 * (1.0 + t.abs()), "{got} vs {t}");
            } else if margin < -1e-7 {
                prop_assert!(got.is_none(), "hit outside: {got:?}");
            }
        }
    }
}
