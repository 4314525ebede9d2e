//! The torus of SPEC §16 (`torus C Axis R r`): the points at distance r from the circle
//! of radius R about Axis through C, 0 < r < R.
//!
//! In the torus's own coordinates (origin C, y along Axis) a point p is on it when
//! (|p|² + R² − r²)² = 4R²(p_x² + p_z²). On the line p = o + s·d (|d| = 1), with
//! k = |o|² + R² − r² and b = o·d, this is the quartic
//! s⁴ + 4b s³ + (4b² + 2k − 4R²(d_x² + d_z²)) s² + (4bk − 8R²(o_x d_x + o_z d_z)) s
//! + k² − 4R²(o_x² + o_z²) = 0.
//!
//! Robustness, as POV-Ray does it: the origin is first moved along the line to the point
//! nearest the centre (a ray from far away would otherwise give coefficients of size
//! distance⁴ whose rounding swamps the roots), and only lines meeting the bounding sphere
//! of radius R + r are solved, on the sphere's chord. The quartic is then solved by root
//! isolation (`poly`), which brackets each root instead of trusting a closed formula:
//! grazing rays and rays from inside (where the four roots cluster or straddle 0) keep
//! their digits. The outward normal at p is (p − q)/r, q the nearest point of the circle.

use super::poly;
use super::Roots;
use glam::DVec3;

/// A torus around an axis.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Torus {
    /// The centre.
    pub center: DVec3,
    /// The unit axis.
    pub axis: DVec3,
    /// The radius of the tube's centre circle, R.
    pub major: f64,
    /// The tube's radius, 0 < r < R.
    pub minor: f64,
    /// Unit vectors across the axis: the torus's x and z.
    u: DVec3,
    v: DVec3,
}

impl Torus {
    /// The torus; `None` for a zero axis, radii outside 0 < r < R, or non-finite values.
    pub fn new(center: DVec3, axis: DVec3, major: f64, minor: f64) -> Option<Torus> {
        let axis = crate::scene::direction(axis)?.normalize();
        let ok = center.is_finite() && major.is_finite() && minor > 0.0 && minor < major;
        let (u, v) = axis.any_orthonormal_pair();
        ok.then_some(Torus {
            center,
            axis,
            major,
            minor,
            u,
            v,
        })
    }

    /// A world vector in the torus's coordinates (x = u, y = axis, z = v).
    #[inline]
    fn local(&self, w: DVec3) -> DVec3 {
        DVec3::new(w.dot(self.u), w.dot(self.axis), w.dot(self.v))
    }

    /// Where the line O + tD (unit D) crosses the surface, ascending, any sign.
    pub fn roots(&self, o: DVec3, d: DVec3) -> Roots {
        let (big, small) = (self.major, self.minor);
        let o = self.local(o - self.center);
        let d = self.local(d);
        // The chord of the bounding sphere: s = mid ± half.
        let bound = big + small;
        let mid = -o.dot(d);
        let near = o + mid * d;
        let half2 = bound * bound - near.length_squared();
        if half2 < 0.0 {
            return Roots::NONE;
        }
        let half = half2.sqrt();
        let o = near;
        let k = o.length_squared() + big * big - small * small;
        let b = o.dot(d);
        let r4 = 4.0 * big * big;
        let c = [
            k * k - r4 * (o.x * o.x + o.z * o.z),
            4.0 * b * k - 2.0 * r4 * (o.x * d.x + o.z * d.z),
            4.0 * b * b + 2.0 * k - r4 * (d.x * d.x + d.z * d.z),
            4.0 * b,
            1.0,
        ];
        // A hair wider than the chord, so that a root on the sphere itself is kept.
        let pad = 1e-9 * bound;
        let mut found = [0.0; 4];
        let n = poly::roots_in(&c, -half - pad, half + pad, &mut found);
        for s in &mut found[..n] {
            *s += mid;
        }
        Roots::from_slice(&found[..n])
    }

    /// The outward unit normal at a surface point `p`.
    pub fn normal(&self, p: DVec3) -> DVec3 {
        let w = p - self.center;
        let across = w - w.dot(self.axis) * self.axis;
        let ring = across.try_normalize().unwrap_or(self.u) * self.major;
        (w - ring).try_normalize().unwrap_or(self.axis)
    }

    /// A box around the torus: along axis i it reaches (R + r)·√(1 − a_i²) + r·|a_i|.
    pub fn bounds(&self) -> (DVec3, DVec3) {
        let a2 = self.axis * self.axis;
        let span = (DVec3::ONE - a2).max(DVec3::ZERO).map(f64::sqrt) * (self.major + self.minor)
            + self.axis.abs() * self.minor;
        (self.center - span, self.center + span)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn ring() -> Torus {
        // R = 2, r = 0.5 around the y axis through the origin.
        Torus::new(DVec3::ZERO, DVec3::Y, 2.0, 0.5).unwrap()
    }

    fn close(a: f64, b: f64) -> bool {
        (a - b).abs() < 1e-10
    }

    #[test]
    fn four_crossings_through_the_middle() {
        // Along x from x = −5: the tube is crossed at x = −2.5, −1.5, 1.5, 2.5.
        let r = ring().roots(DVec3::new(-5.0, 0.0, 0.0), DVec3::X);
        let want = [2.5, 3.5, 6.5, 7.5];
        assert_eq!(r.len(), 4, "{r:?}");
        for (t, w) in r.as_slice().iter().zip(want) {
            assert!(close(*t, w), "{r:?}");
        }
        assert!((ring().normal(DVec3::new(-2.5, 0.0, 0.0)) + DVec3::X).length() < 1e-15);
        assert!((ring().normal(DVec3::new(-1.5, 0.0, 0.0)) - DVec3::X).length() < 1e-15);
        assert!((ring().normal(DVec3::new(0.0, 0.5, 2.0)) - DVec3::Y).length() < 1e-15);
    }

    #[test]
    fn down_through_the_tube_and_the_hole() {
        // Down at x = 2 (the tube's centre line): in at y = 0.5, out at y = −0.5.
        let r = ring().roots(DVec3::new(2.0, 10.0, 0.0), -DVec3::Y);
        assert_eq!(r.len(), 2);
        assert!(
            close(r.as_slice()[0], 9.5) && close(r.as_slice()[1], 10.5),
            "{r:?}"
        );
        // Down the axis: through the hole, nothing.
        assert!(ring()
            .roots(DVec3::new(0.0, 10.0, 0.0), -DVec3::Y)
            .is_empty());
    }

    #[test]
    fn from_inside_the_tube() {
        // From the tube's centre (2, 0, 0) along +y: out at t = 0.5, and the other side
        // of the tube at −0.5 behind.
        let r = ring().roots(DVec3::new(2.0, 0.0, 0.0), DVec3::Y);
        assert_eq!(r.len(), 2);
        assert!(
            close(r.as_slice()[0], -0.5) && close(r.as_slice()[1], 0.5),
            "{r:?}"
        );
        // Along +x from there: out at 0.5, then the far side of the ring behind at −3.5, −4.5.
        let r = ring().roots(DVec3::new(2.0, 0.0, 0.0), DVec3::X);
        let want = [-4.5, -3.5, -0.5, 0.5];
        assert_eq!(r.len(), 4, "{r:?}");
        for (t, w) in r.as_slice().iter().zip(want) {
            assert!(close(*t, w), "{r:?}");
        }
    }

    #[test]
    fn grazing_rays() {
        // Along x at height y = r(1 − 1e-6) just under the top: it crosses the tube's top
        // twice near x = ±2, each pair 2·√(r² − y²) ≈ 1e-3 apart.
        let y = 0.5 * (1.0 - 1e-6);
        let r = ring().roots(DVec3::new(-5.0, y, 0.0), DVec3::X);
        assert_eq!(r.len(), 4, "{r:?}");
        let w = (0.25 - y * y).sqrt();
        let want = [3.0 - w, 3.0 + w, 7.0 - w, 7.0 + w];
        for (t, w) in r.as_slice().iter().zip(want) {
            assert!((t - w).abs() < 1e-7, "{r:?} vs {want:?}");
        }
        // Just above the top: nothing.
        assert!(ring()
            .roots(DVec3::new(-5.0, 0.5 + 1e-9, 0.0), DVec3::X)
            .is_empty());
        // From very far away the roots keep their digits (the origin is moved first).
        let r = ring().roots(DVec3::new(-1e6, 0.0, 0.0), DVec3::X);
        assert!(close(r.as_slice()[0], 1e6 - 2.5), "{r:?}");
    }

    #[test]
    fn bounds_and_bad_radii() {
        let (lo, hi) = ring().bounds();
        assert!((lo - DVec3::new(-2.5, -0.5, -2.5)).length() < 1e-15);
        assert!((hi - DVec3::new(2.5, 0.5, 2.5)).length() < 1e-15);
        assert!(Torus::new(DVec3::ZERO, DVec3::Y, 1.0, 1.0).is_none());
        assert!(Torus::new(DVec3::ZERO, DVec3::ZERO, 2.0, 1.0).is_none());
    }
}
