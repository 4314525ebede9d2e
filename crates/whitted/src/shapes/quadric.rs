//! General quadrics (report IV.1.3) and the infinite cylinder built from one (IV.1.4).
//!
//! F(x,y,z) = A·x² + B·y² + C·z² + D·xy + E·xz + F·yz + G·x + H·y + I·z + J = 0, written in
//! coordinates relative to `origin` (for a cylinder, its point on the axis), which keeps
//! the coefficients small and the roots exact far from the world origin. Putting the ray in
//! gives Aq·t² + Bq·t + Cq = 0 with the report's Aq, Bq, Cq; Aq ≈ 0 leaves the linear root
//! −Cq/Bq. The normal is the gradient of F, so "outward" is where F grows: for a cylinder,
//! away from the axis.
//!
//! A cylinder of unit axis a and radius r is |x|² − (a·x)² − r² = 0, i.e.
//! A = 1 − ax², B = 1 − ay², C = 1 − az², D = −2·ax·ay, E = −2·ax·az, F = −2·ay·az, J = −r².
//! With a = x̂ this is the report's y² + z² − 1 = 0 (B = C = 1, J = −1).

use super::Roots;
use crate::optics::Ray;
use glam::DVec3;

/// Below this |Aq| the equation is treated as linear (the ray runs along a ruling).
const LINEAR_EPS: f64 = 1e-12;

/// A quadric surface F = 0, F in coordinates relative to `origin`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Quadric {
    /// The point the coefficients' coordinates are measured from.
    pub origin: DVec3,
    /// The ten coefficients A, B, C, D, E, F, G, H, I, J of the report.
    pub coef: [f64; 10],
    /// A cylinder's unit axis as given (zero for a quadric given by its coefficients):
    /// the y of its cylindrical image map's frame (`texture::map`).
    pub axis: DVec3,
}

impl Quadric {
    /// The infinite cylinder of radius `radius` around the line through `point` along
    /// `axis` (any direction, not zero).
    pub fn cylinder(axis: DVec3, point: DVec3, radius: f64) -> Quadric {
        let a = axis.normalize();
        Quadric {
            origin: point,
            coef: [
                1.0 - a.x * a.x,
                1.0 - a.y * a.y,
                1.0 - a.z * a.z,
                -2.0 * a.x * a.y,
                -2.0 * a.x * a.z,
                -2.0 * a.y * a.z,
                0.0,
                0.0,
                0.0,
                -radius * radius,
            ],
            axis: a,
        }
    }

    /// F at a world point (negative inside a cylinder, zero on it).
    pub fn value(&self, p: DVec3) -> f64 {
        let [a, b, c, d, e, f, g, h, i, j] = self.coef;
        let p = p - self.origin;
        a * p.x * p.x
            + b * p.y * p.y
            + c * p.z * p.z
            + d * p.x * p.y
            + e * p.x * p.z
            + f * p.y * p.z
            + g * p.x
            + h * p.y
            + i * p.z
            + j
    }

    /// The roots of the ray with the surface, in increasing order.
    #[inline(always)]
    pub fn roots(&self, ray: &Ray) -> Roots {
        let [a, b, c, d, e, f, g, h, i, j] = self.coef;
        let o = ray.origin - self.origin;
        let v = ray.dir;
        // Axis-aligned quadrics (an x, y or z cylinder) have D..I = 0: their terms add
        // signed zeros to Aq, Bq and Cq, which leave a non-zero sum as it is. So when the
        // sums without them are non-zero (and J ≠ 0, and nothing is large enough to
        // overflow), the short form below gives the general form's Aq, Bq, Cq bit for bit;
        // otherwise (a zero Bq, whose sign `copysign` reads) the general form decides.
        // (Bits with the sign shifted out: zero exactly for ±0.)
        let zeros =
            (d.to_bits() | e.to_bits() | f.to_bits() | g.to_bits() | h.to_bits() | i.to_bits())
                << 1;
        if zeros == 0 && j != 0.0 {
            // No overflow, so the zero terms are zeros, not NaN from 0·∞ (a NaN coordinate
            // may pass: it makes both forms NaN alike).
            let tame = o.abs().max(v.abs()).max_element() < 1e150;
            let bq = 2.0 * (a * o.x * v.x + b * o.y * v.y + c * o.z * v.z);
            if tame && bq != 0.0 {
                let aq = a * v.x * v.x + b * v.y * v.y + c * v.z * v.z;
                let cq = a * o.x * o.x + b * o.y * o.y + c * o.z * o.z + j;
                return Self::solve(aq, bq, cq);
            }
        }
        self.roots_general(ray)
    }

    /// `roots(ray).first_hit(t_max)`, inlined.
    #[inline(always)]
    pub fn hit(&self, ray: &Ray, t_max: f64) -> Option<f64> {
        self.roots(ray).first_hit(ray.t_min, t_max)
    }

    /// The report's general form, term by term.
    #[inline(never)]
    fn roots_general(&self, ray: &Ray) -> Roots {
        let [a, b, c, d, e, f, g, h, i, _] = self.coef;
        let o = ray.origin - self.origin;
        let v = ray.dir;
        let aq = a * v.x * v.x
            + b * v.y * v.y
            + c * v.z * v.z
            + d * v.x * v.y
            + e * v.x * v.z
            + f * v.y * v.z;
        let bq = 2.0 * (a * o.x * v.x + b * o.y * v.y + c * o.z * v.z)
            + d * (o.x * v.y + o.y * v.x)
            + e * (o.x * v.z + v.x * o.z)
            + f * (o.y * v.z + v.y * o.z)
            + g * v.x
            + h * v.y
            + i * v.z;
        // Cq is F at the ray's origin, the same sum in the same order as `value`.
        let cq = self.value(ray.origin);
        Self::solve(aq, bq, cq)
    }

    /// The roots of Aq·t² + Bq·t + Cq = 0.
    #[inline(always)]
    fn solve(aq: f64, bq: f64, cq: f64) -> Roots {
        if aq.abs() < LINEAR_EPS {
            if bq.abs() < LINEAR_EPS {
                return Roots::NONE;
            }
            return Roots::one(-cq / bq);
        }
        let disc = bq * bq - 4.0 * aq * cq;
        if disc < 0.0 {
            return Roots::NONE;
        }
        // The cancellation-free form of (−Bq ∓ √disc) / 2Aq.
        let q = -0.5 * (bq + disc.sqrt().copysign(bq));
        if q == 0.0 {
            return Roots::two(0.0, 0.0);
        }
        Roots::two(q / aq, cq / q)
    }

    /// Outward unit normal: the normalised gradient of F at `p`.
    #[inline]
    pub fn normal(&self, p: DVec3) -> DVec3 {
        let [a, b, c, d, e, f, g, h, i, _] = self.coef;
        let p = p - self.origin;
        DVec3::new(
            2.0 * a * p.x + d * p.y + e * p.z + g,
            2.0 * b * p.y + d * p.x + f * p.z + h,
            2.0 * c * p.z + e * p.x + f * p.y + i,
        )
        .normalize_or_zero()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn report_cylinder_coefficients() {
        let q = Quadric::cylinder(DVec3::new(3.0, 0.0, 0.0), DVec3::ZERO, 1.0);
        assert_eq!(
            q.coef,
            [0.0, 1.0, 1.0, -0.0, -0.0, -0.0, 0.0, 0.0, 0.0, -1.0]
        );
    }

    #[test]
    fn vertical_cylinder_hit_by_hand() {
        // Axis y through (0,0,−5), radius 1; ray from the origin along −z: t = 4 and 6.
        let q = Quadric::cylinder(DVec3::Y, DVec3::new(0.0, 0.0, -5.0), 1.0);
        let r = Ray::new(DVec3::ZERO, -DVec3::Z);
        assert_eq!(q.roots(&r).as_slice(), &[4.0, 6.0]);
        assert_eq!(q.normal(r.at(4.0)), DVec3::Z);
        assert_eq!(q.normal(r.at(6.0)), -DVec3::Z);
    }

    #[test]
    fn slanted_axis_hit_by_hand() {
        // Axis (1,1,0)/√2 through the origin, radius 1. A ray from (0,0,5) along −z meets
        // the axis line at the origin at right angles: roots 5 ∓ 1.
        let q = Quadric::cylinder(DVec3::new(1.0, 1.0, 0.0), DVec3::ZERO, 1.0);
        let r = Ray::new(DVec3::new(0.0, 0.0, 5.0), -DVec3::Z);
        let roots = q.roots(&r);
        assert!((roots.as_slice()[0] - 4.0).abs() < 1e-12);
        assert!((roots.as_slice()[1] - 6.0).abs() < 1e-12);
        // A ray along x at height z = 0 crosses the slanted cylinder where the distance to
        // the axis, |y − x|/√2 for a point (x, 0, 0) ... = |x|/√2, equals 1: x = ±√2.
        let r = Ray::new(DVec3::new(-10.0, 0.0, 0.0), DVec3::X);
        let roots = q.roots(&r);
        let s2 = 2f64.sqrt();
        assert!(
            (roots.as_slice()[0] - (10.0 - s2)).abs() < 1e-9,
            "{roots:?}"
        );
        assert!(
            (roots.as_slice()[1] - (10.0 + s2)).abs() < 1e-9,
            "{roots:?}"
        );
        // Normal at (−√2, 0, 0): away from the axis, (−1, 1, 0)/√2.
        let n = q.normal(DVec3::new(-s2, 0.0, 0.0));
        assert!((n - DVec3::new(-1.0, 1.0, 0.0).normalize()).length() < 1e-12);
    }

    #[test]
    fn miss_tangent_and_inside() {
        let q = Quadric::cylinder(DVec3::Y, DVec3::ZERO, 1.0);
        // Passes at distance 2 from the axis: miss.
        let r = Ray::new(DVec3::new(2.0, 0.0, 5.0), -DVec3::Z);
        assert_eq!(q.roots(&r), Roots::NONE);
        // Tangent at x = 1: double root at t = 5.
        let r = Ray::new(DVec3::new(1.0, 0.0, 5.0), -DVec3::Z);
        assert_eq!(q.roots(&r).as_slice(), &[5.0, 5.0]);
        // Origin on the axis: one root behind, one ahead.
        let r = Ray::new(DVec3::new(0.0, 3.0, 0.0), DVec3::X);
        assert_eq!(q.roots(&r).as_slice(), &[-1.0, 1.0]);
    }

    #[test]
    fn ray_along_the_axis_never_hits() {
        let q = Quadric::cylinder(DVec3::Y, DVec3::ZERO, 1.0);
        for o in [
            DVec3::ZERO,
            DVec3::new(0.5, -3.0, 0.0),
            DVec3::new(5.0, 0.0, 0.0),
        ] {
            assert_eq!(q.roots(&Ray::new(o, DVec3::Y)), Roots::NONE);
        }
    }

    /// The short form for axis-aligned quadrics gives the general form's roots bit for
    /// bit, on random rays and on the awkward ones: direction components ±0, origins on
    /// the axis (Bq = ±0, where the sign of zero picks the root formula), tangents.
    #[test]
    fn axis_aligned_short_form_is_bit_exact() {
        let mut state = 0x9e3779b97f4a7c15u64;
        let mut rnd = move || {
            state ^= state << 13;
            state ^= state >> 7;
            state ^= state << 17;
            (state >> 11) as f64 / (1u64 << 53) as f64 * 2.0 - 1.0
        };
        let pick = |x: f64, k: u64| match k % 5 {
            0 => 0.0,
            1 => -0.0,
            2 => x.round(),
            _ => x,
        };
        let bits = |r: Roots| {
            let s = r.as_slice();
            (s.len(), s.iter().map(|t| t.to_bits()).collect::<Vec<_>>())
        };
        let mut k = 0u64;
        let mut tested = 0;
        for axis in [DVec3::X, DVec3::Y, DVec3::Z, -DVec3::Y] {
            for _ in 0..4000 {
                k += 1;
                let point = DVec3::new(pick(rnd() * 5.0, k), rnd() * 3.0, pick(rnd(), k / 3));
                let q = Quadric::cylinder(axis, point, 0.1 + rnd().abs());
                let o = DVec3::new(
                    pick(rnd() * 8.0, k / 5),
                    pick(rnd() * 8.0, k / 7),
                    pick(rnd() * 8.0, k / 11),
                );
                let o = if k.is_multiple_of(13) {
                    q.origin + axis * rnd()
                } else {
                    o
                };
                let d = DVec3::new(pick(rnd(), k / 2), pick(rnd(), k / 17), pick(rnd(), k / 19));
                let Some(d) = d.try_normalize() else { continue };
                let r = Ray::new(o, d);
                assert_eq!(bits(q.roots(&r)), bits(q.roots_general(&r)), "{q:?} {r:?}");
                tested += 1;
            }
        }
        assert!(tested > 10000);
    }

    #[test]
    fn linear_case_of_a_general_quadric() {
        // Paraboloid y = x² + z², i.e. x² + z² − y = 0: a vertical ray meets it once.
        let q = Quadric {
            origin: DVec3::ZERO,
            coef: [1.0, 0.0, 1.0, 0.0, 0.0, 0.0, 0.0, -1.0, 0.0, 0.0],
            axis: DVec3::ZERO,
        };
        let r = Ray::new(DVec3::new(1.0, 10.0, 1.0), -DVec3::Y);
        // Aq = 0, Bq = −H·(−1)... = 1, Cq = 1 + 1 − 10 = −8: t = 8, at y = 2 = 1 + 1.
        assert_eq!(q.roots(&r).as_slice(), &[8.0]);
        assert_eq!(q.value(r.at(8.0)), 0.0);
    }
}
