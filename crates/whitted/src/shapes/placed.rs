//! The shapes of SPEC §16 that live in an object frame: a box, a capped or open cylinder
//! or cone, a disc, a torus, or a sphere that `scale` may have made an ellipsoid, each
//! with its `Transform` (scale, rotate, translate). A ray is carried into object space with
//! its direction renormalised (the object-space solvers take unit directions), and the
//! roots are scaled back, so t is the world's; normals go back by the inverse transpose.
//! Without modifiers the frame is the identity and is skipped.

use super::{AaBox, Capped, Disc, Roots, Sphere, Torus, Transform};
use crate::optics::Ray;
use glam::DVec3;

/// A shape in object space.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Local {
    /// A sphere (in a frame: an ellipsoid).
    Sphere(Sphere),
    /// A box, axis-aligned in object space.
    Box(AaBox),
    /// A cylinder or truncated cone, capped or open.
    Capped(Capped),
    /// A disc, with or without a hole.
    Disc(Disc),
    /// A torus.
    Torus(Torus),
}

impl Local {
    /// Where the line O + tD (unit D) crosses the surface, ascending, any sign.
    #[inline]
    pub fn roots(&self, o: DVec3, d: DVec3) -> Roots {
        match self {
            Local::Sphere(s) => s.roots(&Ray {
                origin: o,
                dir: d,
                t_min: 0.0,
            }),
            Local::Box(b) => b.roots(o, d),
            Local::Capped(c) => c.roots(o, d),
            Local::Disc(c) => c.roots(o, d),
            Local::Torus(t) => t.roots(o, d),
        }
    }

    /// The outward unit normal at a surface point, in object space.
    pub fn normal(&self, p: DVec3) -> DVec3 {
        match self {
            Local::Sphere(s) => s.normal(p),
            Local::Box(b) => b.normal(p),
            Local::Capped(c) => c.normal(p),
            Local::Disc(c) => c.normal,
            Local::Torus(t) => t.normal(p),
        }
    }

    /// A box around the shape, in object space.
    pub fn bounds(&self) -> (DVec3, DVec3) {
        match self {
            Local::Sphere(s) => s.bounds(),
            Local::Box(b) => b.bounds(),
            Local::Capped(c) => c.bounds(),
            Local::Disc(c) => c.bounds(),
            Local::Torus(t) => t.bounds(),
        }
    }
}

/// A shape and its frame.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Placed {
    /// The shape in object space.
    pub local: Local,
    /// Object space to world.
    pub frame: Transform,
    identity: bool,
}

impl Placed {
    /// `local` moved by `frame`.
    pub fn new(local: Local, frame: Transform) -> Placed {
        Placed {
            local,
            frame,
            identity: frame.is_identity(),
        }
    }

    /// Where the ray's line crosses the surface, ascending, any sign.
    #[inline]
    pub fn roots(&self, ray: &Ray) -> Roots {
        if self.identity {
            return self.local.roots(ray.origin, ray.dir);
        }
        let o = self.frame.point_to_local(ray.origin);
        let d = self.frame.vector_to_local(ray.dir);
        let len = d.length();
        if !(len > 0.0 && len.is_finite()) {
            return Roots::NONE;
        }
        self.local.roots(o, d / len).scaled(len)
    }

    /// The first crossing with ray.t_min < t < t_max.
    #[inline]
    pub fn hit(&self, ray: &Ray, t_max: f64) -> Option<f64> {
        self.roots(ray).first_hit(ray.t_min, t_max)
    }

    /// The outward unit normal at a surface point `p` (world).
    pub fn normal(&self, p: DVec3) -> DVec3 {
        if self.identity {
            return self.local.normal(p);
        }
        let n = self.local.normal(self.frame.point_to_local(p));
        self.frame.normal_to_world(n)
    }

    /// A world box around the shape.
    pub fn bounds(&self) -> (DVec3, DVec3) {
        self.frame.bounds_to_world(self.local.bounds())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_rotated_and_moved_box() {
        // The box [−1, 1]³ turned 45° about y and moved to x = 10: along x at z = 0 it
        // is entered at the corner x = 10 − √2 and left at 10 + √2.
        let b = AaBox::new(DVec3::splat(-1.0), DVec3::splat(1.0)).unwrap();
        let f = Transform::new(
            DVec3::ONE,
            DVec3::new(0.0, 45.0, 0.0),
            DVec3::new(10.0, 0.0, 0.0),
        );
        let p = Placed::new(Local::Box(b), f.unwrap());
        let r = p.roots(&Ray::new(DVec3::ZERO, DVec3::X));
        let s = 2f64.sqrt();
        assert!((r.as_slice()[0] - (10.0 - s)).abs() < 1e-12, "{r:?}");
        assert!((r.as_slice()[1] - (10.0 + s)).abs() < 1e-12, "{r:?}");
        // Along z at x = 10 − 0.5: a face turned towards (−1, 0, −1)/√2 (−z side first).
        let ray = Ray::new(DVec3::new(9.5, 0.0, -5.0), DVec3::Z);
        let t = p.hit(&ray, f64::INFINITY).unwrap();
        let n = p.normal(ray.at(t));
        assert!(
            (n - DVec3::new(-1.0, 0.0, -1.0).normalize()).length() < 1e-9,
            "{n}"
        );
    }

    #[test]
    fn a_scaled_sphere_is_an_ellipsoid() {
        // The unit sphere stretched to 3 along x: along x from −10, in at 7, out at 13;
        // the normal at (0, 1, 0)·… of the top is +y; at (3, 0, 0) it is +x.
        let s = Sphere::new(DVec3::ZERO, 1.0);
        let f = Transform::new(DVec3::new(3.0, 1.0, 1.0), DVec3::ZERO, DVec3::ZERO).unwrap();
        let p = Placed::new(Local::Sphere(s), f);
        let r = p.roots(&Ray::new(DVec3::new(-10.0, 0.0, 0.0), DVec3::X));
        assert!((r.as_slice()[0] - 7.0).abs() < 1e-12 && (r.as_slice()[1] - 13.0).abs() < 1e-12);
        assert!((p.normal(DVec3::new(3.0, 0.0, 0.0)) - DVec3::X).length() < 1e-15);
        // At (3cos θ, sin θ, 0) the normal is (cos θ/3, sin θ, 0), normalised.
        let th = 0.7f64;
        let n = p.normal(DVec3::new(3.0 * th.cos(), th.sin(), 0.0));
        let want = DVec3::new(th.cos() / 3.0, th.sin(), 0.0).normalize();
        assert!((n - want).length() < 1e-12);
        let (lo, hi) = p.bounds();
        assert!((lo - DVec3::new(-3.0, -1.0, -1.0)).length() < 1e-12);
        assert!((hi - DVec3::new(3.0, 1.0, 1.0)).length() < 1e-12);
    }
}
