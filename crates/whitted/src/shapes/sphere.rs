//! The sphere, by the report's geometric method (IV.1.1).
//!
//! With OC from the ray origin to the centre and D the unit direction: OH = OC·D is the
//! distance to the foot of the perpendicular from the centre, CH² = OC² − OH², and the
//! ray meets the sphere when CH² ≤ R², at t = OH ∓ √(R² − CH²). The report also rejects
//! OH < 0; that shortcut is only right for an origin outside the sphere, so here it
//! applies only there (a refracted ray inside a glass sphere must still find its exit).

use super::Roots;
use crate::optics::Ray;
use glam::DVec3;

/// A sphere given by centre and radius (> 0).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Sphere {
    /// The centre.
    pub center: DVec3,
    /// The radius (> 0).
    pub radius: f64,
    radius2: f64,
    inv_radius: f64,
}

impl Sphere {
    /// The sphere of that centre and radius; the radius must be > 0 (the parser refuses others).
    pub fn new(center: DVec3, radius: f64) -> Sphere {
        Sphere {
            center,
            radius,
            radius2: radius * radius,
            inv_radius: 1.0 / radius,
        }
    }

    /// The roots of the ray with the sphere, in increasing order.
    #[inline]
    pub fn roots(&self, ray: &Ray) -> Roots {
        let oc = self.center - ray.origin;
        let oh = oc.dot(ray.dir);
        let oc2 = oc.length_squared();
        if oh < 0.0 && oc2 > self.radius2 {
            return Roots::NONE; // outside and moving away
        }
        let ch2 = oc2 - oh * oh;
        if ch2 > self.radius2 {
            return Roots::NONE;
        }
        let half = (self.radius2 - ch2).sqrt();
        Roots::two(oh - half, oh + half)
    }

    /// The first root with ray.t_min < t < t_max: `roots(ray).first_hit(t_max)` without
    /// building the `Roots` (the roots oh ∓ half are already in ascending order).
    #[inline(always)]
    pub fn hit(&self, ray: &Ray, t_max: f64) -> Option<f64> {
        let oc = self.center - ray.origin;
        let oh = oc.dot(ray.dir);
        let oc2 = oc.length_squared();
        if oh < 0.0 && oc2 > self.radius2 {
            return None;
        }
        let ch2 = oc2 - oh * oh;
        if ch2 > self.radius2 {
            return None;
        }
        let half = (self.radius2 - ch2).sqrt();
        let t0 = oh - half;
        if t0 > ray.t_min && t0 < t_max {
            return Some(t0);
        }
        let t1 = oh + half;
        if t1 > ray.t_min && t1 < t_max {
            return Some(t1);
        }
        None
    }

    /// Outward unit normal: CP / R.
    #[inline]
    pub fn normal(&self, p: DVec3) -> DVec3 {
        (p - self.center) * self.inv_radius
    }

    /// The smallest box around the sphere: its low and high corners, C ∓ (R, R, R).
    #[inline]
    pub fn bounds(&self) -> (DVec3, DVec3) {
        let r = DVec3::splat(self.radius);
        (self.center - r, self.center + r)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn sphere() -> Sphere {
        Sphere::new(DVec3::new(0.0, 0.0, -5.0), 2.0)
    }

    #[test]
    fn bounds_by_hand() {
        // Centre (0, 0, −5), radius 2: from (−2, −2, −7) to (2, 2, −3).
        let (lo, hi) = sphere().bounds();
        assert_eq!(
            (lo, hi),
            (DVec3::new(-2.0, -2.0, -7.0), DVec3::new(2.0, 2.0, -3.0))
        );
    }

    #[test]
    fn head_on_hit() {
        // OC = (0,0,−5), D = −z: OH = 5, CH² = 0, roots 5 ∓ 2.
        let r = Ray::new(DVec3::ZERO, -DVec3::Z);
        assert_eq!(sphere().roots(&r).as_slice(), &[3.0, 7.0]);
        let p = r.at(3.0);
        assert_eq!(sphere().normal(p), DVec3::Z);
    }

    #[test]
    fn off_axis_hit() {
        // Origin (1,0,0): OC = (−1,0,−5), OH = 5, OC² = 26, CH² = 1, roots 5 ∓ √3.
        let r = Ray::new(DVec3::X, -DVec3::Z);
        let roots = sphere().roots(&r);
        let s3 = 3f64.sqrt();
        assert!((roots.as_slice()[0] - (5.0 - s3)).abs() < 1e-12);
        assert!((roots.as_slice()[1] - (5.0 + s3)).abs() < 1e-12);
        let n = sphere().normal(r.at(5.0 - s3));
        assert!((n - DVec3::new(0.5, 0.0, s3 / 2.0)).length() < 1e-12, "{n}");
    }

    #[test]
    fn miss_beside_and_behind() {
        assert_eq!(
            sphere().roots(&Ray::new(DVec3::new(3.0, 0.0, 0.0), -DVec3::Z)),
            Roots::NONE
        );
        assert_eq!(
            sphere().roots(&Ray::new(DVec3::ZERO, DVec3::Z)),
            Roots::NONE
        );
    }

    #[test]
    fn tangent_ray_touches_once() {
        // Origin (2,0,0): CH² = 4 = R², a double root at t = 5.
        let r = Ray::new(DVec3::new(2.0, 0.0, 0.0), -DVec3::Z);
        assert_eq!(sphere().roots(&r).as_slice(), &[5.0, 5.0]);
    }

    #[test]
    fn hit_is_roots_first_hit() {
        let s = sphere();
        let mut k = 0u64;
        for ox in [-3.0, -2.0, -0.5, 0.0, 0.3, 2.0, 2.5] {
            for oz in [-9.0, -7.0, -5.0, -3.01, -3.0, 0.0, 4.0] {
                for dx in [-1.0, -0.4, 0.0, 0.2, 1.0] {
                    for dz in [-1.0, -0.3, 0.0, 0.5, 1.0] {
                        let Some(d) = DVec3::new(dx, 0.1 * (k % 3) as f64, dz).try_normalize()
                        else {
                            continue;
                        };
                        k += 1;
                        let r = Ray::new(DVec3::new(ox, 0.0, oz), d);
                        for t_max in [f64::INFINITY, 4.0, 1.0] {
                            assert_eq!(
                                s.hit(&r, t_max),
                                s.roots(&r).first_hit(r.t_min, t_max),
                                "{r:?}"
                            );
                        }
                    }
                }
            }
        }
        assert!(k > 1000);
    }

    #[test]
    fn origin_inside_finds_the_exit_even_moving_away_from_the_centre() {
        // Origin (0,0,−4) inside, moving +z (away from the centre): OH = −1 < 0, but the
        // exit at z = −3 is one unit ahead. Roots −1 − 2 = −3 and −1 + 2 = 1.
        let r = Ray::new(DVec3::new(0.0, 0.0, -4.0), DVec3::Z);
        assert_eq!(sphere().roots(&r).as_slice(), &[-3.0, 1.0]);
    }
}
