//! The capped (or `open`) cylinder and truncated cone of SPEC §16 (`cylinder A B Radius`,
//! `cone A Ra B Rb`): NFF's open side (`Cone`, a cylinder when both radii agree) closed by
//! a disc at each end whose radius is not zero. Capped, it is a convex solid: its
//! crossings are the smallest and the largest of the side's and the caps'. The outward
//! normal at a point is the side's, or −axis / +axis on the nearer cap when the point is
//! closer to the cap's plane than to the side.

use super::{Cone, Roots};
use crate::optics::Ray;
use glam::DVec3;

/// A cylinder or truncated cone, with or without its end discs.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Capped {
    /// The side surface, from A (its base) to B (its apex).
    pub side: Cone,
    /// True when the end discs close it (not `open`).
    pub caps: bool,
}

impl Capped {
    /// The shape from A (radius ra) to B (radius rb); `None` when A = B, a radius is
    /// negative, both are 0, or a value is not finite.
    pub fn new(a: DVec3, ra: f64, b: DVec3, rb: f64, caps: bool) -> Option<Capped> {
        if ra < 0.0 || rb < 0.0 {
            return None;
        }
        Cone::new(a, ra, b, rb).map(|side| Capped { side, caps })
    }

    /// The crossing of the line with the cap at `center` (radius `r`), if any.
    #[inline]
    fn cap(&self, o: DVec3, d: DVec3, center: DVec3, r: f64) -> Option<f64> {
        let axis = self.side.axis();
        let den = d.dot(axis);
        if r <= 0.0 || den == 0.0 {
            return None;
        }
        let t = (center - o).dot(axis) / den;
        let p = o + t * d - center;
        (p.length_squared() <= r * r && t.is_finite()).then_some(t)
    }

    /// Where the line O + tD (unit D) crosses the surface, ascending, any sign.
    #[inline]
    pub fn roots(&self, o: DVec3, d: DVec3) -> Roots {
        let ray = Ray {
            origin: o,
            dir: d,
            t_min: 0.0,
        };
        let side = self.side.roots(&ray);
        if !self.caps {
            return side;
        }
        let c = &self.side;
        let caps = [
            self.cap(o, d, c.base, c.base_radius),
            self.cap(o, d, c.apex, c.apex_radius),
        ];
        let all = side
            .as_slice()
            .iter()
            .copied()
            .chain(caps.into_iter().flatten());
        let (lo, hi, n) = all.fold((f64::INFINITY, f64::NEG_INFINITY, 0), |(lo, hi, n), t| {
            (lo.min(t), hi.max(t), n + 1)
        });
        match n {
            0 => Roots::NONE,
            _ if lo == hi => Roots::one(lo),
            _ => Roots::two(lo, hi),
        }
    }

    /// The outward unit normal at a surface point `p`.
    pub fn normal(&self, p: DVec3) -> DVec3 {
        let c = &self.side;
        let axis = c.axis();
        if self.caps {
            let o = p - c.base;
            let s = o.dot(axis);
            let radial = (o - s * axis).length();
            let rho = c.base_radius + c.slope() * s;
            let k = c.slope();
            let to_side = (radial - rho).abs() / (1.0 + k * k).sqrt();
            let (to_base, to_apex) = (s.abs(), (s - c.height()).abs());
            if to_base.min(to_apex) < to_side {
                let (r, sign) = if to_base <= to_apex {
                    (c.base_radius, -1.0)
                } else {
                    (c.apex_radius, 1.0)
                };
                if r > 0.0 {
                    return sign * axis;
                }
            }
        }
        c.normal(p)
    }

    /// A box around it (the end circles' boxes, joined).
    pub fn bounds(&self) -> (DVec3, DVec3) {
        self.side.bounds()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn capped_cylinder_by_hand() {
        // Radius 1 around y from y = 0 to y = 2.
        let c = Capped::new(DVec3::ZERO, 1.0, DVec3::new(0.0, 2.0, 0.0), 1.0, true).unwrap();
        // Down the axis from y = 5: the top cap at t = 3, the bottom at t = 5.
        let r = c.roots(DVec3::new(0.0, 5.0, 0.0), -DVec3::Y);
        assert_eq!(r.as_slice(), &[3.0, 5.0]);
        assert_eq!(c.normal(DVec3::new(0.0, 2.0, 0.0)), DVec3::Y);
        assert_eq!(c.normal(DVec3::new(0.5, 0.0, 0.0)), -DVec3::Y);
        // Sideways at y = 1: the side at 4 and 6, normal −x where it enters.
        let r = c.roots(DVec3::new(-5.0, 1.0, 0.0), DVec3::X);
        assert_eq!(r.as_slice(), &[4.0, 6.0]);
        assert_eq!(c.normal(DVec3::new(-1.0, 1.0, 0.0)), -DVec3::X);
        // Slanted through the top cap and out of the side: from (0, 3, 0) along
        // (1, −1, 0)/√2 it meets y = 2 at t = √2 (x = 1, on the rim) …
        let d = DVec3::new(1.0, -1.0, 0.0).normalize();
        let r = c.roots(DVec3::new(-0.5, 3.0, 0.0), d);
        // … from x = −0.5: the cap at x = 0.5 (t = √2), the side x = 1 at y = 1.5 (t = 1.5√2).
        let s = 2f64.sqrt();
        assert!((r.as_slice()[0] - s).abs() < 1e-12 && (r.as_slice()[1] - 1.5 * s).abs() < 1e-12);
    }

    #[test]
    fn open_has_no_caps() {
        let c = Capped::new(DVec3::ZERO, 1.0, DVec3::new(0.0, 2.0, 0.0), 1.0, false).unwrap();
        assert!(c.roots(DVec3::new(0.0, 5.0, 0.0), -DVec3::Y).is_empty());
    }

    #[test]
    fn truncated_cone_by_hand() {
        // Radius 2 at y = 0 narrowing to 1 at y = 1.
        let c = Capped::new(DVec3::ZERO, 2.0, DVec3::Y, 1.0, true).unwrap();
        // Along x at y = 0.5: radius 1.5 there, side at 5 ∓ 1.5.
        let r = c.roots(DVec3::new(-5.0, 0.5, 0.0), DVec3::X);
        assert_eq!(r.as_slice(), &[3.5, 6.5]);
        // The side's normal leans up: (−1, 1, 0)/√2 at x = −1.5 (slope −1).
        let n = c.normal(DVec3::new(-1.5, 0.5, 0.0));
        assert!((n - DVec3::new(-1.0, 1.0, 0.0).normalize()).length() < 1e-12);
        // Up through x = 1.5 from below: the bottom cap (radius 2) at t = 5, the side at
        // y = 0.5 (radius 1.5) at t = 5.5.
        let r = c.roots(DVec3::new(1.5, -5.0, 0.0), DVec3::Y);
        assert_eq!(r.as_slice(), &[5.0, 5.5]);
        // A pointed cone (Rb = 0) has a single cap.
        let p = Capped::new(DVec3::ZERO, 1.0, DVec3::Y, 0.0, true).unwrap();
        assert_eq!(
            p.roots(DVec3::new(0.0, -1.0, 0.0), DVec3::Y).as_slice(),
            &[1.0, 2.0]
        );
        assert!(Capped::new(DVec3::ZERO, -1.0, DVec3::Y, 1.0, true).is_none());
    }
}
