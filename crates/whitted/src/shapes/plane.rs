//! The infinite plane (IV.1.2): N·X + D = 0, with t = −(N·O + D)/(N·Dir).
//!
//! Planes are two-sided: the tracer flips the normal towards the ray. A ray parallel to
//! the plane (|N·Dir| < 1e-12) misses it.

use super::Roots;
use crate::optics::Ray;
use glam::DVec3;

/// A plane through `point` with unit `normal`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Plane {
    /// A point of the plane.
    pub point: DVec3,
    normal: DVec3,
}

impl Plane {
    /// `normal` need not be unit; it must not be zero (the parser refuses that).
    pub fn new(point: DVec3, normal: DVec3) -> Plane {
        Plane {
            point,
            normal: normal.normalize(),
        }
    }

    /// The roots of the ray with the plane: one, or none for a ray parallel to it.
    #[inline]
    pub fn roots(&self, ray: &Ray) -> Roots {
        let denom = self.normal.dot(ray.dir);
        if denom.abs() < 1e-12 {
            return Roots::NONE;
        }
        // −(N·O + D) with D = −N·P is N·(P − O), which keeps precision far from the origin.
        Roots::one(self.normal.dot(self.point - ray.origin) / denom)
    }

    /// `roots(ray).first_hit(t_max)` without building the `Roots`.
    #[inline(always)]
    pub fn hit(&self, ray: &Ray, t_max: f64) -> Option<f64> {
        let denom = self.normal.dot(ray.dir);
        if denom.abs() < 1e-12 {
            return None;
        }
        let t = self.normal.dot(self.point - ray.origin) / denom;
        (t > ray.t_min && t < t_max).then_some(t)
    }

    /// The plane's unit normal, as given (not turned towards any ray).
    #[inline]
    pub fn normal(&self) -> DVec3 {
        self.normal
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn floor_hit_by_hand() {
        // Floor y = −1, normal given unnormalised. From (0,2,0) going (0,−0.6,0.8): t = 3/0.6 = 5.
        let p = Plane::new(DVec3::new(7.0, -1.0, 3.0), DVec3::new(0.0, 10.0, 0.0));
        let r = Ray::new(DVec3::new(0.0, 2.0, 0.0), DVec3::new(0.0, -0.6, 0.8));
        let t = p.roots(&r).as_slice()[0];
        assert!((t - 5.0).abs() < 1e-12);
        assert!((r.at(t) - DVec3::new(0.0, -1.0, 4.0)).length() < 1e-12);
        assert_eq!(p.normal(), DVec3::Y);
    }

    #[test]
    fn behind_and_parallel() {
        let p = Plane::new(DVec3::ZERO, DVec3::Y);
        // Going up from above: the root is negative, which `Shape::hit` rejects.
        let r = Ray::new(DVec3::new(0.0, 1.0, 0.0), DVec3::Y);
        assert_eq!(p.roots(&r).as_slice(), &[-1.0]);
        // Parallel: no root at all.
        let r = Ray::new(DVec3::new(0.0, 1.0, 0.0), DVec3::X);
        assert_eq!(p.roots(&r), Roots::NONE);
    }

    #[test]
    fn seen_from_below_too() {
        let p = Plane::new(DVec3::ZERO, DVec3::Y);
        let r = Ray::new(DVec3::new(0.0, -2.0, 0.0), DVec3::Y);
        assert_eq!(p.roots(&r).as_slice(), &[2.0]);
    }
}
