//! Geometry: the shapes a Scene.txt can hold (sphere, plane, quadric cylinder), those an
//! NFF adds (triangle, smooth triangle, open cone), those the extension records add (box,
//! capped cylinder and cone, disc, torus, each in its own frame: `Placed`), and how a
//! ray meets them (report IV.1), and CSG blocks of those solids (`csg`, one object each,
//! shared behind an `Arc`: the only shape that is not a plain value).
//!
//! Every shape answers one question, `roots`: the parameters t (up to two, ascending, any
//! sign) where the ray's line crosses its surface. From that the tracer gets the nearest
//! hit (`hit`, t in (ray.t_min, t_max)) and the list of surface crossings a shadow ray makes
//! (`crossings`). `normal` gives the outward unit geometric normal at a surface point;
//! deciding entering or leaving, and flipping the normal to face the ray, is the tracer's
//! job (SPEC §2). A plane's "outward" side is the side its normal points to.
//!
//! Shapes are a closed enum, not trait objects, so the hot loop has no virtual calls.

mod aabox;
mod capped;
mod cone;
pub mod csg;
mod disc;
mod meshref;
mod placed;
mod plane;
mod poly;
mod quadric;
mod smooth;
mod sphere;
mod torus;
mod transform;
mod triangle;

pub use aabox::AaBox;
pub use capped::Capped;
pub use cone::Cone;
pub use csg::Csg;
pub use disc::Disc;
pub use meshref::MeshRef;
pub use placed::{Local, Placed};
pub use plane::Plane;
pub use quadric::Quadric;
pub use smooth::SmoothTriangle;
pub use sphere::Sphere;
pub use torus::Torus;
pub use transform::Transform;
pub use triangle::Triangle;

use crate::optics::Ray;
use glam::DVec3;
use std::sync::Arc;

/// Where a line crosses a surface: up to four parameters (a torus's), ascending.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Roots {
    t: [f64; 4],
    n: usize,
}

impl Roots {
    /// No root.
    pub const NONE: Roots = Roots { t: [0.0; 4], n: 0 };

    /// A single (double) root `t`.
    #[inline]
    pub fn one(t: f64) -> Roots {
        Roots {
            t: [t, t, 0.0, 0.0],
            n: 1,
        }
    }

    /// Two roots, stored in ascending order.
    #[inline]
    pub fn two(a: f64, b: f64) -> Roots {
        Roots {
            t: [a.min(b), a.max(b), 0.0, 0.0],
            n: 2,
        }
    }

    /// Up to four roots in any order (more are dropped), stored ascending; NaNs dropped.
    pub fn from_slice(ts: &[f64]) -> Roots {
        let mut r = Roots::NONE;
        for &t in ts.iter().filter(|t| !t.is_nan()).take(4) {
            r.t[r.n] = t;
            r.n += 1;
        }
        r.t[..r.n].sort_by(f64::total_cmp);
        r
    }

    /// The number of roots.
    pub fn len(&self) -> usize {
        self.n
    }

    /// True when the line misses the surface.
    pub fn is_empty(&self) -> bool {
        self.n == 0
    }

    /// Every root divided by `k` > 0 (a root of a line whose direction was scaled by k).
    #[inline]
    pub fn scaled(mut self, k: f64) -> Roots {
        for t in &mut self.t[..self.n] {
            *t /= k;
        }
        self
    }

    /// The roots as a slice, ascending.
    pub fn as_slice(&self) -> &[f64] {
        &self.t[..self.n]
    }

    /// Every root with t_min < t < t_max, ascending: the surface crossings of a shadow ray.
    #[inline]
    pub fn crossings(self, t_min: f64, t_max: f64) -> impl Iterator<Item = f64> {
        (0..self.n)
            .map(move |i| self.t[i])
            .filter(move |&t| t > t_min && t < t_max)
    }

    /// The first root with t_min < t < t_max, if any: what a ray hits.
    #[inline]
    pub fn first_hit(&self, t_min: f64, t_max: f64) -> Option<f64> {
        self.as_slice()
            .iter()
            .copied()
            .find(|&t| t > t_min && t < t_max)
    }
}

/// A surface of the scene. Not `Copy`: a CSG block is shared behind an `Arc`.
#[derive(Clone, Debug, PartialEq)]
pub enum Shape {
    /// A sphere (centre, radius).
    Sphere(Sphere),
    /// An infinite plane (point, normal).
    Plane(Plane),
    /// A general quadric; the parser's cylinders are quadrics.
    Quadric(Quadric),
    /// A triangle (NFF polygons are cut into them).
    Triangle(Triangle),
    /// A triangle with a normal per corner (NFF's `pp`).
    Smooth(SmoothTriangle),
    /// An open cone or cylinder of finite length (NFF's `c`).
    Cone(Cone),
    /// A shape of the extension records in its own frame (box, capped cylinder and cone,
    /// disc, torus, transformed sphere).
    Placed(Placed),
    /// A triangle mesh (SPEC §16's `mesh`): its triangles are the accelerator's
    /// primitives, not this shape's. It has no roots of its own (a ray meets a mesh
    /// through `accel::Accel`, and a hit is shaded as its triangle); its normal, never
    /// asked, is +z.
    Mesh(MeshRef),
    /// A CSG block of the extension records (one object of the scene).
    Csg(Arc<Csg>),
}

impl Shape {
    /// The line parameters where `ray` crosses the surface, ascending, any sign.
    #[inline(always)]
    pub fn roots(&self, ray: &Ray) -> Roots {
        match self {
            Shape::Sphere(s) => s.roots(ray),
            Shape::Plane(p) => p.roots(ray),
            Shape::Quadric(q) => q.roots(ray),
            Shape::Triangle(t) => t.roots(ray),
            Shape::Smooth(t) => t.roots(ray),
            Shape::Cone(c) => c.roots(ray),
            Shape::Placed(p) => p.roots(ray),
            Shape::Mesh(_) => Roots::NONE,
            Shape::Csg(c) => c.roots(ray),
        }
    }

    /// The nearest hit with ray.t_min < t < t_max, if any.
    #[inline(always)]
    pub fn hit(&self, ray: &Ray, t_max: f64) -> Option<f64> {
        match self {
            Shape::Sphere(s) => s.hit(ray, t_max),
            Shape::Plane(p) => p.hit(ray, t_max),
            Shape::Quadric(q) => q.hit(ray, t_max),
            Shape::Triangle(t) => t.hit(ray, t_max),
            Shape::Smooth(t) => t.hit(ray, t_max),
            Shape::Cone(c) => c.hit(ray, t_max),
            Shape::Placed(p) => p.hit(ray, t_max),
            Shape::Mesh(_) => None,
            Shape::Csg(c) => c.hit(ray, t_max),
        }
    }

    /// True for a shape that fits in a finite box; planes and quadric cylinders are
    /// infinite.
    #[inline]
    pub fn is_bounded(&self) -> bool {
        match self {
            Shape::Plane(_) | Shape::Quadric(_) => false,
            Shape::Csg(c) => c.bounds().is_some(),
            _ => true,
        }
    }

    /// The low and high corners of a box around a bounded shape; `None` for the
    /// infinite ones.
    pub fn bounds(&self) -> Option<(DVec3, DVec3)> {
        match self {
            Shape::Sphere(s) => Some(s.bounds()),
            Shape::Plane(_) | Shape::Quadric(_) => None,
            Shape::Triangle(t) => Some(t.bounds()),
            Shape::Smooth(t) => Some(t.flat.bounds()),
            Shape::Cone(c) => Some(c.bounds()),
            Shape::Placed(p) => Some(p.bounds()),
            Shape::Mesh(m) => Some((m.lo, m.hi)),
            Shape::Csg(c) => c.bounds(),
        }
    }

    /// Every crossing with ray.t_min < t < t_max (what a shadow ray passes through).
    #[inline]
    pub fn crossings(&self, ray: &Ray, t_max: f64) -> impl Iterator<Item = f64> {
        self.roots(ray).crossings(ray.t_min, t_max)
    }

    /// The outward unit normal at a point `p` of the surface. Always inlined: the mesh's
    /// arm made LLVM keep it out of line in the shading loop (+5 M instructions on the
    /// orbit at one thread, callgrind).
    #[inline(always)]
    pub fn normal(&self, p: DVec3) -> DVec3 {
        match self {
            Shape::Sphere(s) => s.normal(p),
            Shape::Plane(pl) => pl.normal(),
            Shape::Quadric(q) => q.normal(p),
            Shape::Triangle(t) => t.normal(),
            Shape::Smooth(t) => t.normal(p),
            Shape::Cone(c) => c.normal(p),
            Shape::Placed(pl) => pl.normal(p),
            Shape::Mesh(_) => DVec3::Z,
            Shape::Csg(c) => c.normal(p),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn hit_skips_roots_at_or_below_epsilon_and_beyond_t_max() {
        // A sphere of radius 1 around the origin, ray from inside along +x: roots −1 and 1.
        let s = Shape::Sphere(Sphere::new(DVec3::ZERO, 1.0));
        let r = Ray::new(DVec3::ZERO, DVec3::X);
        assert_eq!(s.hit(&r, f64::INFINITY), Some(1.0));
        assert_eq!(s.hit(&r, 0.5), None);
        // From a point on the surface the ray does not hit itself at t = 0.
        let r = Ray::new(DVec3::new(-1.0, 0.0, 0.0), DVec3::X);
        assert_eq!(s.hit(&r, f64::INFINITY), Some(2.0));
        assert_eq!(
            s.crossings(&r, f64::INFINITY).collect::<Vec<_>>(),
            vec![2.0]
        );
    }

    #[test]
    fn crossings_lists_both_sides() {
        let s = Shape::Sphere(Sphere::new(DVec3::new(0.0, 0.0, -5.0), 1.0));
        let r = Ray::new(DVec3::ZERO, -DVec3::Z);
        assert_eq!(s.crossings(&r, 100.0).collect::<Vec<_>>(), vec![4.0, 6.0]);
        assert_eq!(s.crossings(&r, 5.0).collect::<Vec<_>>(), vec![4.0]);
    }

    #[test]
    fn is_bounded_says_what_bounds_says() {
        // The project's scenes hold every kind of shape (planes and quadrics, meshes,
        // placed shapes, CSG trees with and without a box).
        let dir = concat!(env!("CARGO_MANIFEST_DIR"), "/../../scenes");
        let mut kinds = [0usize; 2];
        for name in [
            "new-shapes.txt",
            "meshes.txt",
            "csg-piece.txt",
            "showcase.txt",
        ] {
            let scene = crate::scene::Scene::load(&std::path::Path::new(dir).join(name))
                .expect("the project's scenes load");
            for o in &scene.objects {
                assert_eq!(o.shape.is_bounded(), o.shape.bounds().is_some(), "{name}");
                kinds[o.shape.is_bounded() as usize] += 1;
            }
        }
        assert!(kinds[0] > 0 && kinds[1] > 0, "{kinds:?}");
    }
}
