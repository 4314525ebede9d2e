//! The two orthographic views of the path plot and what is measured in them: the top view
//! looks down −y at the (x, z) plane, x to the right and +z down the page (so that the
//! camera of a circle's first frame, on the +z side, is at the bottom as if one stood
//! behind it); the side view looks along −z at the (x, y) plane, x to the right and y up,
//! as the first frame of the orbit sees the scene.
//!
//! A view's window is chosen to hold the camera path, the look-at points, the lights, the
//! tracked positions and every sphere no larger than that, padded by 8 %, then widened on
//! one axis so that a unit is as long across as up the page: objects keep their shapes.

use super::clip::{Rect, P2};
use glam::DVec3;
use whitted::shapes::Quadric;

/// Part of the extent added on each side.
const PADDING: f64 = 0.08;

#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum View {
    Top,
    Side,
}

impl View {
    /// The point's place in the view. The top view's vertical coordinate is −z, so that
    /// +z runs down the page (its tick labels are negated back).
    pub fn project(self, p: DVec3) -> P2 {
        match self {
            View::Top => (p.x, -p.z),
            View::Side => (p.x, p.y),
        }
    }

    /// The direction the view looks along (what projection drops).
    pub fn depth(self) -> DVec3 {
        match self {
            View::Top => DVec3::Y,
            View::Side => DVec3::Z,
        }
    }

    pub fn title(self) -> &'static str {
        match self {
            View::Top => "top view (x, z), looking down",
            View::Side => "side view (x, y), looking along -z",
        }
    }

    /// The name of the vertical axis.
    pub fn vertical(self) -> &'static str {
        match self {
            View::Top => "z",
            View::Side => "y",
        }
    }

    /// The tick label of vertical coordinate `v` (the world coordinate, not −z).
    pub fn vertical_label(self, v: f64) -> String {
        match self {
            View::Top => number(-v),
            View::Side => number(v),
        }
    }
}

/// A short decimal: up to two decimals, trailing zeros and a negative zero dropped.
pub fn number(x: f64) -> String {
    let s = format!("{:.2}", x + 0.0);
    let s = s.trim_end_matches('0').trim_end_matches('.');
    if s == "-0" {
        "0".to_string()
    } else {
        s.to_string()
    }
}

/// The bounding rectangle of `points` and of the discs (centre, radius) whose radius is
/// at most the points' extent, padded; at least one unit across.
pub fn extent(points: &[P2], discs: &[(P2, f64)]) -> Rect {
    let mut r = Rect {
        u: (f64::INFINITY, f64::NEG_INFINITY),
        v: (f64::INFINITY, f64::NEG_INFINITY),
    };
    let grow = |r: &mut Rect, (u, v): P2, rad: f64| {
        r.u = (r.u.0.min(u - rad), r.u.1.max(u + rad));
        r.v = (r.v.0.min(v - rad), r.v.1.max(v + rad));
    };
    points.iter().for_each(|&p| grow(&mut r, p, 0.0));
    let size = if points.is_empty() {
        f64::INFINITY
    } else {
        (r.u.1 - r.u.0).max(r.v.1 - r.v.0).max(1.0)
    };
    discs
        .iter()
        .filter(|(_, rad)| *rad <= size)
        .for_each(|&(c, rad)| grow(&mut r, c, rad));
    if !r.u.0.is_finite() {
        r = Rect {
            u: (-1.0, 1.0),
            v: (-1.0, 1.0),
        };
    }
    let pad = |(a, b): (f64, f64)| {
        let (mid, half) = ((a + b) / 2.0, ((b - a) / 2.0).max(0.5));
        let half = half * (1.0 + PADDING);
        (mid - half, mid + half)
    };
    Rect {
        u: pad(r.u),
        v: pad(r.v),
    }
}

/// `r` widened on one axis, about its centre, to the aspect of a `width`×`height`-pixel
/// plotting area, so that one unit spans as many pixels both ways.
pub fn fit(r: Rect, width: u32, height: u32) -> Rect {
    let (w, h) = (f64::from(width.max(1)), f64::from(height.max(1)));
    let per_pixel = ((r.u.1 - r.u.0) / w).max((r.v.1 - r.v.0) / h);
    let around = |(a, b): (f64, f64), pixels: f64| {
        let (mid, half) = ((a + b) / 2.0, per_pixel * pixels / 2.0);
        (mid - half, mid + half)
    };
    Rect {
        u: around(r.u, w),
        v: around(r.v, h),
    }
}

/// The axis (unit, largest component positive), a point on it and the radius of a
/// quadric that is a cylinder as `Quadric::cylinder` builds them; `None` for any other.
pub fn cylinder(q: &Quadric) -> Option<(DVec3, DVec3, f64)> {
    let [a, b, c, d, e, f, g, h, i, j] = q.coef;
    let sum = a + b + c;
    if g != 0.0 || h != 0.0 || i != 0.0 || j >= 0.0 || (sum - 2.0).abs() > 1e-9 {
        return None;
    }
    let mag = DVec3::new(1.0 - a, 1.0 - b, 1.0 - c).max(DVec3::ZERO);
    let mag = DVec3::new(mag.x.sqrt(), mag.y.sqrt(), mag.z.sqrt());
    // Off-diagonal terms are −2·ai·aj: the signs relative to the largest component.
    let axis = if mag.x >= mag.y && mag.x >= mag.z {
        DVec3::new(mag.x, -d.signum() * mag.y, -e.signum() * mag.z)
    } else if mag.y >= mag.z {
        DVec3::new(-d.signum() * mag.x, mag.y, -f.signum() * mag.z)
    } else {
        DVec3::new(-e.signum() * mag.x, -f.signum() * mag.y, mag.z)
    };
    Some((axis.normalize(), q.origin, (-j).sqrt()))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn projections_put_plus_z_down_the_top_view() {
        let p = DVec3::new(1.0, 2.0, 3.0);
        assert_eq!(View::Top.project(p), (1.0, -3.0));
        assert_eq!(View::Side.project(p), (1.0, 2.0));
        assert_eq!(View::Top.vertical_label(-3.0), "3");
        assert_eq!(View::Side.vertical_label(2.5), "2.5");
        assert_eq!(number(-0.0), "0");
        assert_eq!(number(-0.001), "0");
        assert_eq!(number(12.0), "12");
    }

    #[test]
    fn extent_pads_and_skips_discs_larger_than_the_scene() {
        // Points span u 0..10, v 0..4; a sky dome of radius 1000 is left out, a disc of
        // radius 1 at (10, 4) is in: u −0..11, v 0..5, then 8 % of the half-size each side.
        let r = extent(
            &[(0.0, 0.0), (10.0, 4.0)],
            &[((0.0, 0.0), 1000.0), ((10.0, 4.0), 1.0)],
        );
        let close = |a: f64, b: f64| (a - b).abs() < 1e-12;
        assert!(close(r.u.0, 5.5 - 5.5 * 1.08) && close(r.u.1, 5.5 + 5.5 * 1.08));
        assert!(close(r.v.0, 2.5 - 2.5 * 1.08) && close(r.v.1, 2.5 + 2.5 * 1.08));
        // One point: a unit square around it, padded.
        let r = extent(&[(3.0, 3.0)], &[]);
        assert!(close(r.u.1 - r.u.0, 1.08));
    }

    #[test]
    fn fit_gives_both_axes_the_same_units_per_pixel() {
        let fitted = |u, v, width, height| {
            let r = fit(Rect { u, v }, width, height);
            (r.u, r.v)
        };
        // 20 × 10 units into 400 × 400 pixels: 0.05 units a pixel, v widened to 20.
        assert_eq!(
            fitted((0.0, 20.0), (0.0, 10.0), 400, 400),
            ((0.0, 20.0), (-5.0, 15.0))
        );
        // 10 × 10 into 400 × 200: 0.05 a pixel, u widened to 20 around 5.
        assert_eq!(
            fitted((0.0, 10.0), (0.0, 10.0), 400, 200),
            ((-5.0, 15.0), (0.0, 10.0))
        );
    }

    #[test]
    fn cylinders_are_recovered_from_their_quadric() {
        let q = Quadric::cylinder(DVec3::new(0.0, 2.0, 0.0), DVec3::new(1.0, 0.0, -1.0), 0.3);
        let (axis, point, r) = cylinder(&q).unwrap();
        assert!((axis - DVec3::Y).length() < 1e-12);
        assert_eq!(point, DVec3::new(1.0, 0.0, -1.0));
        assert!((r - 0.3).abs() < 1e-12);
        // A slanted axis keeps its signs (up to the whole sign).
        let a = DVec3::new(1.0, -2.0, 2.0) / 3.0;
        let (axis, _, _) = cylinder(&Quadric::cylinder(a, DVec3::ZERO, 1.0)).unwrap();
        assert!((axis + a).length() < 1e-12 || (axis - a).length() < 1e-12);
        // Not a cylinder: a sphere-like quadric.
        let mut q = Quadric::cylinder(DVec3::X, DVec3::ZERO, 1.0);
        q.coef[0] = 1.0;
        assert!(cylinder(&q).is_none());
    }
}
