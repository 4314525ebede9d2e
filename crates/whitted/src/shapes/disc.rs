//! A flat disc with an optional centred hole (SPEC §16's `disc C N Radius Hole`): the
//! plane through C with normal N, kept where Hole ≤ |P − C| ≤ Radius. Two-sided; its
//! outward normal is N.

use super::Roots;
use glam::DVec3;

/// A disc (annulus when `hole` > 0).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Disc {
    /// The centre.
    pub center: DVec3,
    /// The unit normal.
    pub normal: DVec3,
    /// The outer radius, > 0.
    pub radius: f64,
    /// The hole's radius, 0 ≤ hole < radius.
    pub hole: f64,
}

impl Disc {
    /// The disc; `None` for a zero normal, a bad radius or hole, or non-finite values.
    pub fn new(center: DVec3, normal: DVec3, radius: f64, hole: f64) -> Option<Disc> {
        let n = crate::scene::direction(normal)?.normalize();
        let ok = center.is_finite() && radius.is_finite() && radius > 0.0;
        (ok && hole >= 0.0 && hole < radius).then_some(Disc {
            center,
            normal: n,
            radius,
            hole,
        })
    }

    /// Where the line O + tD crosses the disc (at most once).
    #[inline]
    pub fn roots(&self, o: DVec3, d: DVec3) -> Roots {
        let den = d.dot(self.normal);
        if den == 0.0 {
            return Roots::NONE;
        }
        let t = (self.center - o).dot(self.normal) / den;
        let r2 = (o + t * d - self.center).length_squared();
        if r2 <= self.radius * self.radius && r2 >= self.hole * self.hole && t.is_finite() {
            Roots::one(t)
        } else {
            Roots::NONE
        }
    }

    /// A box around the disc (the circle's extent along each axis).
    pub fn bounds(&self) -> (DVec3, DVec3) {
        let n2 = self.normal * self.normal;
        let span = (DVec3::ONE - n2).max(DVec3::ZERO).map(f64::sqrt) * self.radius;
        (self.center - span, self.center + span)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn hits_by_hand() {
        // Radius 2, hole 1, in the plane y = 1.
        let d = Disc::new(DVec3::Y, DVec3::new(0.0, 3.0, 0.0), 2.0, 1.0).unwrap();
        assert_eq!(d.normal, DVec3::Y);
        // Straight down at x = 1.5: through the ring at t = 4.
        let r = d.roots(DVec3::new(1.5, 5.0, 0.0), -DVec3::Y);
        assert_eq!(r.as_slice(), &[4.0]);
        // Through the hole (x = 0.5) and outside (x = 2.5): nothing.
        assert!(d.roots(DVec3::new(0.5, 5.0, 0.0), -DVec3::Y).is_empty());
        assert!(d.roots(DVec3::new(2.5, 5.0, 0.0), -DVec3::Y).is_empty());
        // Parallel to it: nothing.
        assert!(d.roots(DVec3::new(-5.0, 1.0, 0.0), DVec3::X).is_empty());
        let (lo, hi) = d.bounds();
        assert_eq!(
            (lo, hi),
            (DVec3::new(-2.0, 1.0, -2.0), DVec3::new(2.0, 1.0, 2.0))
        );
    }

    #[test]
    fn refuses_bad_fields() {
        assert!(Disc::new(DVec3::ZERO, DVec3::ZERO, 1.0, 0.0).is_none());
        assert!(Disc::new(DVec3::ZERO, DVec3::Y, 1.0, 1.0).is_none());
        assert!(Disc::new(DVec3::ZERO, DVec3::Y, 0.0, 0.0).is_none());
    }
}
