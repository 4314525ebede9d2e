//! A box, axis-aligned in its own frame (SPEC §16's `box Min Max`): the slab method. The
//! line O + tD is inside slab i for t between (Min_i − O_i)/D_i and (Max_i − O_i)/D_i;
//! the box is the intersection of the three slabs, entered at the largest entry and left
//! at the smallest exit. A direction parallel to a slab keeps the whole line in it or out
//! of it. The outward normal at a surface point is that of the nearest face.

use super::Roots;
use glam::DVec3;

/// An axis-aligned box, Min < Max on each axis.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct AaBox {
    /// The low corner.
    pub min: DVec3,
    /// The high corner.
    pub max: DVec3,
}

impl AaBox {
    /// The box between the corners; `None` unless min < max on each axis, all finite.
    pub fn new(min: DVec3, max: DVec3) -> Option<AaBox> {
        (min.is_finite() && max.is_finite() && min.cmplt(max).all()).then_some(AaBox { min, max })
    }

    /// Where the line O + tD (any length of D) crosses the surface, ascending.
    #[inline]
    pub fn roots(&self, o: DVec3, d: DVec3) -> Roots {
        let mut near = f64::NEG_INFINITY;
        let mut far = f64::INFINITY;
        for i in 0..3 {
            let (lo, hi, oi, di) = (self.min[i], self.max[i], o[i], d[i]);
            if di == 0.0 {
                if oi < lo || oi > hi {
                    return Roots::NONE;
                }
                continue;
            }
            let (t0, t1) = ((lo - oi) / di, (hi - oi) / di);
            near = near.max(t0.min(t1));
            far = far.min(t0.max(t1));
        }
        if near > far || !near.is_finite() || !far.is_finite() {
            return Roots::NONE;
        }
        if near == far {
            Roots::one(near)
        } else {
            Roots::two(near, far)
        }
    }

    /// The outward unit normal of the face nearest to `p` (the first axis on a tie).
    pub fn normal(&self, p: DVec3) -> DVec3 {
        let mut best = (f64::INFINITY, DVec3::X);
        for i in 0..3 {
            let mut e = DVec3::ZERO;
            e[i] = 1.0;
            let (dlo, dhi) = ((p[i] - self.min[i]).abs(), (self.max[i] - p[i]).abs());
            if dlo < best.0 {
                best = (dlo, -e);
            }
            if dhi < best.0 {
                best = (dhi, e);
            }
        }
        best.1
    }

    /// True when `p` is inside or on the box.
    pub fn contains(&self, p: DVec3) -> bool {
        p.cmpge(self.min).all() && p.cmple(self.max).all()
    }

    /// Its corners.
    pub fn bounds(&self) -> (DVec3, DVec3) {
        (self.min, self.max)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn unit() -> AaBox {
        AaBox::new(DVec3::splat(-1.0), DVec3::splat(1.0)).unwrap()
    }

    #[test]
    fn hits_by_hand() {
        let b = unit();
        // From x = −5 along +x through the centre: in at 4, out at 6.
        let r = b.roots(DVec3::new(-5.0, 0.0, 0.0), DVec3::X);
        assert_eq!(r.as_slice(), &[4.0, 6.0]);
        assert_eq!(b.normal(DVec3::new(-1.0, 0.0, 0.0)), -DVec3::X);
        assert_eq!(b.normal(DVec3::new(0.2, 1.0, 0.3)), DVec3::Y);
        // Diagonal from (−3, −2, 0) along (1, 1, 0)/√2·√2: x enters at 2, y at 1 → in at 2;
        // x leaves at 4, y at 3 → out at 3.
        let r = b.roots(DVec3::new(-3.0, -2.0, 0.0), DVec3::new(1.0, 1.0, 0.0));
        assert_eq!(r.as_slice(), &[2.0, 3.0]);
        // Parallel to the x slab, outside it: miss; inside: slabs y and z decide.
        assert!(b.roots(DVec3::new(2.0, -5.0, 0.0), DVec3::Y).is_empty());
        assert_eq!(
            b.roots(DVec3::new(0.5, -5.0, 0.0), DVec3::Y).as_slice(),
            &[4.0, 6.0]
        );
        // From inside: one negative and one positive root.
        assert_eq!(b.roots(DVec3::ZERO, DVec3::Z).as_slice(), &[-1.0, 1.0]);
        // Passing beside it: miss.
        assert!(b.roots(DVec3::new(-5.0, 1.5, 0.0), DVec3::X).is_empty());
    }

    #[test]
    fn refuses_flat_boxes() {
        assert!(AaBox::new(DVec3::ZERO, DVec3::new(1.0, 0.0, 1.0)).is_none());
        assert!(AaBox::new(DVec3::ONE, DVec3::ZERO).is_none());
    }
}
