//! The thin lens of the `focus Aperture Distance Samples` record (SPEC §16): a lens of
//! diameter Aperture centred at the eye, in focus on the plane at Distance along the
//! view axis U. A camera sample's pinhole ray (from the eye along d) meets that plane at
//! F = eye + d·Distance/(d·U); its n × n lens samples are the cell centres
//! (a, b) = (2(i + ½)/n − 1, 2(j + ½)/n − 1) mapped to the unit disc by Shirley's
//! concentric map, then to the lens points eye + (Aperture/2)·(x·D + y·H') (D right, H'
//! up); each lens ray runs from its lens point towards F. Deterministic.
//!
//! The renderer's side (every camera sample becoming its lens samples, each clamped
//! before the mean) is not wired in yet: this module is the lens's arithmetic.

use super::Camera;
use crate::optics::Ray;
use crate::scene::ext::Focus;
use glam::DVec3;
use std::f64::consts::FRAC_PI_4;

/// Shirley and Chiu's concentric map of the square −1..1² onto the unit disc.
pub fn concentric(a: f64, b: f64) -> (f64, f64) {
    if a == 0.0 && b == 0.0 {
        return (0.0, 0.0);
    }
    let (r, phi) = if a.abs() > b.abs() {
        (a, FRAC_PI_4 * (b / a))
    } else {
        (b, 2.0 * FRAC_PI_4 - FRAC_PI_4 * (a / b))
    };
    (r * phi.cos(), r * phi.sin())
}

/// The lens of one camera.
#[derive(Clone, Debug, PartialEq)]
pub struct ThinLens {
    eye: DVec3,
    /// The unit view axis U.
    forward: DVec3,
    /// The distance of the plane in focus along U.
    distance: f64,
    /// The lens points, i major, j minor.
    points: Vec<DVec3>,
}

impl ThinLens {
    /// The lens that `focus` puts on `camera`.
    pub fn new(camera: &Camera, focus: &Focus) -> ThinLens {
        let (right, up, forward) = camera.basis();
        let eye = camera.eye();
        let n = focus.samples.max(1);
        let half = focus.aperture / 2.0;
        let mut points = Vec::with_capacity((n * n) as usize);
        for i in 0..n {
            for j in 0..n {
                let a = 2.0 * (f64::from(i) + 0.5) / f64::from(n) - 1.0;
                let b = 2.0 * (f64::from(j) + 0.5) / f64::from(n) - 1.0;
                let (x, y) = concentric(a, b);
                points.push(eye + half * (x * right + y * up));
            }
        }
        ThinLens {
            eye,
            forward,
            distance: focus.distance,
            points,
        }
    }

    /// The lens points (Samples² of them).
    pub fn points(&self) -> &[DVec3] {
        &self.points
    }

    /// Where the pinhole ray along the unit `dir` from the eye meets the plane in focus.
    pub fn focal_point(&self, dir: DVec3) -> DVec3 {
        self.eye + dir * (self.distance / dir.dot(self.forward))
    }

    /// The lens rays of the pinhole ray `pinhole` (from the eye), in lens-point order.
    pub fn rays<'a>(&'a self, pinhole: &Ray) -> impl Iterator<Item = Ray> + 'a {
        let f = self.focal_point(pinhole.dir);
        self.points
            .iter()
            .map(move |&q| Ray::new(q, (f - q).normalize()))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn concentric_map_by_hand() {
        // The square's edges go to the circle, its centre to the centre.
        assert_eq!(concentric(0.0, 0.0), (0.0, 0.0));
        let (x, y) = concentric(1.0, 0.0);
        assert!((x - 1.0).abs() < 1e-15 && y.abs() < 1e-15);
        // (1, 1): r = 1, φ = π/4.
        let (x, y) = concentric(1.0, 1.0);
        let s = std::f64::consts::FRAC_1_SQRT_2;
        assert!((x - s).abs() < 1e-15 && (y - s).abs() < 1e-15);
        // (0.5, −0.25): r = 0.5, φ = (π/4)·(−0.5) = −π/8.
        let (x, y) = concentric(0.5, -0.25);
        let phi = -std::f64::consts::PI / 8.0;
        assert!((x - 0.5 * phi.cos()).abs() < 1e-15 && (y - 0.5 * phi.sin()).abs() < 1e-15);
        // (0, −0.5): the second branch, r = −0.5, φ = π/2: (0, −0.5).
        let (x, y) = concentric(0.0, -0.5);
        assert!(x.abs() < 1e-15 && (y + 0.5).abs() < 1e-15);
    }

    #[test]
    fn lens_points_and_rays_meet_on_the_focal_plane() {
        // Eye at the origin looking down −z: D = +x, H' = +y, U = −z.
        let cam = Camera::new(DVec3::ZERO, DVec3::new(0.0, 0.0, -1.0), 4, 3).unwrap();
        let focus = Focus {
            aperture: 0.5,
            distance: 8.0,
            samples: 2,
        };
        let lens = ThinLens::new(&cam, &focus);
        // The cells (±½, ±½) map to the disc points (±½·cos π/4, ±½·sin π/4), times the
        // lens radius 0.25.
        let k = 0.25 * 0.5 * std::f64::consts::FRAC_1_SQRT_2;
        assert_eq!(lens.points().len(), 4);
        let want = [(-k, -k), (-k, k), (k, -k), (k, k)];
        for (p, (x, y)) in lens.points().iter().zip(want) {
            assert!((*p - DVec3::new(x, y, 0.0)).length() < 1e-15, "{p}");
        }
        // A pinhole ray at an angle: its focal point is 8 along −z, and every lens ray
        // goes through it.
        let dir = DVec3::new(0.3, -0.1, -1.0).normalize();
        let f = lens.focal_point(dir);
        assert!((f.z + 8.0).abs() < 1e-12 && (f - dir * f.length()).length() < 1e-12);
        for r in lens.rays(&Ray::new(DVec3::ZERO, dir)) {
            let t = (f - r.origin).length();
            assert!((r.at(t) - f).length() < 1e-12);
        }
    }
}
