//! The triangle, one side of the NFF's polygons (a polygon of n vertices is cut into
//! n − 2 of them by `scene::nff::polygon`), by Möller and Trumbore's method (1997).
//!
//! With E1 = B − A, E2 = C − A, P = D × E2 and det = E1·P, a ray O + tD meets the
//! plane of the triangle at barycentric coordinates u = (O − A)·P / det,
//! v = D·Q / det (Q = (O − A) × E1) and t = E2·Q / det; it hits the triangle when u ≥ 0,
//! v ≥ 0 and u + v ≤ 1 (the edges count, so that a ray along an edge shared by two
//! triangles of one polygon meets at least one of them; the tracer's order decides).
//! A ray in the triangle's plane (det = 0) misses it. The outward normal is
//! E1 × E2 normalised: counter-clockwise vertices face the viewer, as NFF says.

use super::Roots;
use crate::optics::Ray;
use glam::DVec3;

/// A triangle given by its corners.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Triangle {
    /// The first corner.
    pub a: DVec3,
    /// B − A.
    pub e1: DVec3,
    /// C − A.
    pub e2: DVec3,
    normal: DVec3,
}

impl Triangle {
    /// The triangle A, B, C; `None` when its corners are not finite or lie on a line.
    pub fn new(a: DVec3, b: DVec3, c: DVec3) -> Option<Triangle> {
        let (e1, e2) = (b - a, c - a);
        let normal = e1.cross(e2).try_normalize()?;
        (a.is_finite() && e1.is_finite() && e2.is_finite()).then_some(Triangle {
            a,
            e1,
            e2,
            normal,
        })
    }

    /// The three corners.
    pub fn vertices(&self) -> [DVec3; 3] {
        [self.a, self.a + self.e1, self.a + self.e2]
    }

    /// Where the ray's line crosses the triangle (one root, any sign), or none.
    #[inline]
    pub fn roots(&self, ray: &Ray) -> Roots {
        match self.uvt(ray) {
            Some((_, _, t)) => Roots::one(t),
            None => Roots::NONE,
        }
    }

    /// The barycentric (u, v) and the line parameter t where the ray's line meets the
    /// triangle (edges included), if it does.
    #[inline]
    pub fn uvt(&self, ray: &Ray) -> Option<(f64, f64, f64)> {
        Triangle::uvt_of(self.a, self.e1, self.e2, ray)
    }

    /// `uvt` of the triangle A, A + E1, A + E2 given by its corner and edges (a mesh's
    /// triangles, stored as vertex indices, are tested through this without a `Triangle`).
    #[inline(always)]
    pub fn uvt_of(a: DVec3, e1: DVec3, e2: DVec3, ray: &Ray) -> Option<(f64, f64, f64)> {
        let p = ray.dir.cross(e2);
        let det = e1.dot(p);
        if det == 0.0 || !det.is_finite() {
            return None;
        }
        let inv = 1.0 / det;
        let s = ray.origin - a;
        let u = s.dot(p) * inv;
        if !(0.0..=1.0).contains(&u) {
            return None;
        }
        let q = s.cross(e1);
        let v = ray.dir.dot(q) * inv;
        if v < 0.0 || u + v > 1.0 {
            return None;
        }
        Some((u, v, e2.dot(q) * inv))
    }

    /// The hit with `ray.t_min` < t < t_max, if any.
    #[inline]
    pub fn hit(&self, ray: &Ray, t_max: f64) -> Option<f64> {
        self.roots(ray).first_hit(ray.t_min, t_max)
    }

    /// The outward unit normal, (B − A) × (C − A) normalised.
    #[inline]
    pub fn normal(&self) -> DVec3 {
        self.normal
    }

    /// The barycentric coordinates (u, v) of a point `p` of the triangle's plane:
    /// p = A + u·E1 + v·E2.
    pub fn barycentric(&self, p: DVec3) -> (f64, f64) {
        let d = p - self.a;
        let (d00, d01, d11) = (
            self.e1.dot(self.e1),
            self.e1.dot(self.e2),
            self.e2.dot(self.e2),
        );
        let (d20, d21) = (d.dot(self.e1), d.dot(self.e2));
        let den = d00 * d11 - d01 * d01;
        ((d11 * d20 - d01 * d21) / den, (d00 * d21 - d01 * d20) / den)
    }

    /// The smallest box around the triangle.
    pub fn bounds(&self) -> (DVec3, DVec3) {
        let [a, b, c] = self.vertices();
        (a.min(b).min(c), a.max(b).max(c))
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use proptest::prelude::*;

    fn tri() -> Triangle {
        // The right triangle (0,0,0), (2,0,0), (0,2,0) in the plane z = 0, normal +z.
        Triangle::new(
            DVec3::ZERO,
            DVec3::new(2.0, 0.0, 0.0),
            DVec3::new(0.0, 2.0, 0.0),
        )
        .unwrap()
    }

    #[test]
    fn hits_by_hand() {
        let t = tri();
        assert_eq!(t.normal(), DVec3::Z);
        // Straight down from z = 3 onto (0.5, 0.5): t = 3, u = v = 0.25.
        let r = Ray::new(DVec3::new(0.5, 0.5, 3.0), -DVec3::Z);
        assert_eq!(t.uvt(&r), Some((0.25, 0.25, 3.0)));
        assert_eq!(t.hit(&r, f64::INFINITY), Some(3.0));
        assert_eq!(t.hit(&r, 2.0), None);
        // From below, going up: the line still crosses at t = 3 (one-sided shading is
        // the tracer's business, not the shape's).
        let r = Ray::new(DVec3::new(0.5, 0.5, -3.0), DVec3::Z);
        assert_eq!(t.hit(&r, f64::INFINITY), Some(3.0));
        // Beyond the hypotenuse x + y = 2: (1.5, 1.0) misses.
        let r = Ray::new(DVec3::new(1.5, 1.0, 3.0), -DVec3::Z);
        assert_eq!(t.hit(&r, f64::INFINITY), None);
        // On the hypotenuse (1, 1): the edge counts.
        let r = Ray::new(DVec3::new(1.0, 1.0, 3.0), -DVec3::Z);
        assert_eq!(t.hit(&r, f64::INFINITY), Some(3.0));
        // In the plane: no hit.
        let r = Ray::new(DVec3::new(-1.0, 0.5, 0.0), DVec3::X);
        assert_eq!(t.hit(&r, f64::INFINITY), None);
        // At 45°: from (0.5, 0.5 − 3, 3) along (0, 1, −1)/√2 reaches (0.5, 0.5, 0) at 3√2.
        let d = DVec3::new(0.0, 1.0, -1.0).normalize();
        let r = Ray::new(DVec3::new(0.5, -2.5, 3.0), d);
        let t45 = t.hit(&r, f64::INFINITY).unwrap();
        assert!((t45 - 3.0 * 2f64.sqrt()).abs() < 1e-12, "{t45}");
    }

    #[test]
    fn barycentric_and_bounds_by_hand() {
        let t = tri();
        assert_eq!(t.barycentric(DVec3::new(0.5, 1.0, 0.0)), (0.25, 0.5));
        assert_eq!(t.bounds(), (DVec3::ZERO, DVec3::new(2.0, 2.0, 0.0)));
        assert!(Triangle::new(DVec3::ZERO, DVec3::X, 2.0 * DVec3::X).is_none());
    }

    /// The brute-force reference: the line meets the plane at t = N·(A − O)/N·D, and the
    /// point is inside when it lies on the inner side of all three edges (signed areas).
    fn reference(t: &Triangle, r: &Ray) -> Option<f64> {
        let [a, b, c] = t.vertices();
        let n = (b - a).cross(c - a);
        let den = n.dot(r.dir);
        if den == 0.0 {
            return None;
        }
        let tt = n.dot(a - r.origin) / den;
        let p = r.at(tt);
        let inside = [(a, b), (b, c), (c, a)]
            .iter()
            .all(|&(x, y)| (y - x).cross(p - x).dot(n) >= 0.0);
        inside.then_some(tt)
    }

    fn v3(r: f64) -> impl Strategy<Value = DVec3> {
        (-r..r, -r..r, -r..r).prop_map(|(x, y, z)| DVec3::new(x, y, z))
    }

    proptest! {
        #[test]
        fn agrees_with_the_plane_and_edge_reference(
            a in v3(3.0), b in v3(3.0), c in v3(3.0), o in v3(10.0), d in v3(1.0)
        ) {
            let Some(t) = Triangle::new(a, b, c) else { return Ok(()) };
            let Some(d) = d.try_normalize() else { return Ok(()) };
            let r = Ray::new(o, d);
            let got = t.uvt(&r).map(|(_, _, t)| t);
            let want = reference(&t, &r);
            match (got, want) {
                (Some(g), Some(w)) => prop_assert!((g - w).abs() <= 1e-7 * (1.0 + w.abs())),
                (None, None) => {}
                _ => {
                    // Only near an edge may the two roundings disagree: the point where
                    // the line meets the plane is within 1e-6 of an edge.
                    let [a, b, c] = t.vertices();
                    let n = t.normal();
                    let den = n.dot(d);
                    prop_assume!(den.abs() > 1e-6);
                    let p = r.at(n.dot(a - o) / den);
                    let near = [(a, b), (b, c), (c, a)].iter().any(|&(x, y)| {
                        let e = y - x;
                        let s = ((p - x).dot(e) / e.dot(e)).clamp(0.0, 1.0);
                        (x + e * s - p).length() < 1e-6 * (1.0 + p.length())
                    });
                    prop_assert!(near, "{got:?} {want:?}");
                }
            }
        }
    }
}
