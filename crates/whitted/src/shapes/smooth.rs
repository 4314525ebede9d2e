//! The smooth triangle, NFF's `pp` patch: a triangle (`Triangle`, the same hits) whose
//! normal at a point is the corners' normals weighted by the point's barycentric
//! coordinates, (1 − u − v)·N_A + u·N_B + v·N_C, normalised (Phong's interpolation, as
//! POV-Ray's `smooth_triangle`). Where the weighted sum vanishes (opposed corner
//! normals), the flat normal stands in.

use super::{Roots, Triangle};
use crate::optics::Ray;
use glam::DVec3;

/// A triangle with a normal per corner.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SmoothTriangle {
    /// The flat triangle: where rays hit.
    pub flat: Triangle,
    /// The unit normals at A, B and C.
    pub normals: [DVec3; 3],
}

impl SmoothTriangle {
    /// The triangle A, B, C with normals (any non-zero length) at its corners; `None`
    /// when the triangle is degenerate or a normal is zero or not finite.
    pub fn new(corners: [DVec3; 3], normals: [DVec3; 3]) -> Option<SmoothTriangle> {
        let flat = Triangle::new(corners[0], corners[1], corners[2])?;
        let [a, b, c] = normals;
        Some(SmoothTriangle {
            flat,
            normals: [a.try_normalize()?, b.try_normalize()?, c.try_normalize()?],
        })
    }

    /// Where the ray's line crosses the triangle.
    #[inline]
    pub fn roots(&self, ray: &Ray) -> Roots {
        self.flat.roots(ray)
    }

    /// The hit with `ray.t_min` < t < t_max, if any.
    #[inline]
    pub fn hit(&self, ray: &Ray, t_max: f64) -> Option<f64> {
        self.flat.hit(ray, t_max)
    }

    /// The interpolated unit normal at a point `p` of the triangle.
    pub fn normal(&self, p: DVec3) -> DVec3 {
        let (u, v) = self.flat.barycentric(p);
        let [a, b, c] = self.normals;
        ((1.0 - u - v) * a + u * b + v * c)
            .try_normalize()
            .unwrap_or(self.flat.normal())
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use proptest::prelude::*;

    fn patch() -> SmoothTriangle {
        // The right triangle of side 2 in z = 0 with normals tilted towards −x at A,
        // +x at B and straight up at C.
        let s = std::f64::consts::FRAC_1_SQRT_2;
        SmoothTriangle::new(
            [
                DVec3::ZERO,
                DVec3::new(2.0, 0.0, 0.0),
                DVec3::new(0.0, 2.0, 0.0),
            ],
            [DVec3::new(-1.0, 0.0, 1.0), DVec3::new(s, 0.0, s), DVec3::Z],
        )
        .unwrap()
    }

    #[test]
    fn normals_by_hand() {
        let p = patch();
        let s = std::f64::consts::FRAC_1_SQRT_2;
        // At the corners, the corners' own (normalised) normals.
        assert!((p.normal(DVec3::ZERO) - DVec3::new(-s, 0.0, s)).length() < 1e-15);
        assert!((p.normal(DVec3::new(0.0, 2.0, 0.0)) - DVec3::Z).length() < 1e-15);
        // Half-way along AB (u = 0.5, v = 0): (−s + s, 0, s + s)/2 normalised = +z.
        assert!((p.normal(DVec3::new(1.0, 0.0, 0.0)) - DVec3::Z).length() < 1e-15);
        // Hits are the flat triangle's.
        let r = Ray::new(DVec3::new(0.5, 0.5, 2.0), -DVec3::Z);
        assert_eq!(p.hit(&r, f64::INFINITY), Some(2.0));
        // Opposed normals cancel at the midpoint of AB: the flat normal stands in.
        let q = SmoothTriangle::new(
            [
                DVec3::ZERO,
                DVec3::new(2.0, 0.0, 0.0),
                DVec3::new(0.0, 2.0, 0.0),
            ],
            [DVec3::X, -DVec3::X, DVec3::Z],
        )
        .unwrap();
        assert_eq!(q.normal(DVec3::new(1.0, 0.0, 0.0)), DVec3::Z);
    }

    proptest! {
        /// Against the reference: the normal is the unit vector along the corners'
        /// normals weighted by the areas of the sub-triangles opposite them.
        #[test]
        fn normal_matches_area_weights(u in 0.0f64..1.0, v in 0.0f64..1.0) {
            // The square's upper half folded onto the triangle: no case is rejected.
            let (u, v) = if u + v > 1.0 { (1.0 - u, 1.0 - v) } else { (u, v) };
            let p = patch();
            let [a, b, c] = p.flat.vertices();
            let x = a + u * (b - a) + v * (c - a);
            let area = |p: DVec3, q: DVec3, r: DVec3| (q - p).cross(r - p).length();
            let total = area(a, b, c);
            let w = [area(x, b, c) / total, area(a, x, c) / total, area(a, b, x) / total];
            let want = (w[0] * p.normals[0] + w[1] * p.normals[1] + w[2] * p.normals[2])
                .normalize();
            prop_assert!((p.normal(x) - want).length() < 1e-9);
        }
    }
}
