//! A world point to its place on the picture: the inverse of `Camera::ray`, with the same
//! corner and pixel steps, so a point drawn over a frame sits where the tracer puts it.
//!
//! d = P − eye; depth = d·U (U forward, the view plane at `VIEW_DISTANCE`); a point at
//! depth ≤ `NEAR` is behind the camera (or in its eye) and has no place. Otherwise
//! q = d·VIEW_DISTANCE/depth lies on the view plane and q − corner = x·step_x − y·step_y,
//! the steps orthogonal: x = (q − corner)·step_x/|step_x|², y = −(q − corner)·step_y/|step_y|².
//! (x, y) are in pixel units, (i + 0.5, j + 0.5) the centre of pixel (i, j), as `ray` takes
//! them; they may lie outside the picture.

use super::{Camera, VIEW_DISTANCE};
use glam::DVec3;

/// The smallest depth along the viewing direction a projected point may have: nearer,
/// it is behind the camera (or on its eye) and is not projected.
pub const NEAR: f64 = 1e-9;

impl Camera {
    /// Where `p` falls on the picture, in pixel units (`ray`'s (x, y)); `None` when it is
    /// not in front of the camera.
    pub fn project(&self, p: DVec3) -> Option<(f64, f64)> {
        let (_, _, forward) = self.basis();
        let d = p - self.eye;
        let depth = d.dot(forward);
        if depth.is_nan() || depth <= NEAR {
            return None;
        }
        let q = d * (VIEW_DISTANCE / depth) - self.corner;
        let x = q.dot(self.step_x) / self.step_x.length_squared();
        let y = -q.dot(self.step_y) / self.step_y.length_squared();
        (x.is_finite() && y.is_finite()).then_some((x, y))
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::camera::Lens;

    fn lens(fov: f64, roll: f64) -> Lens {
        Lens {
            fov: Some(fov),
            roll,
            ..Lens::default()
        }
    }

    #[test]
    fn by_hand() {
        // Eye (0, 0, 10) looking at the origin, fov 90° at 200×100: the plane is 2 high and
        // 4 wide at distance 1. (1, 0.5, 0) is 10 deep, at (0.1, 0.05) on the plane:
        // x = (0.1 + 2)/4·200 = 105, y = (1 − 0.05)/2·100 = 47.5.
        let eye = DVec3::new(0.0, 0.0, 10.0);
        let cam = Camera::framed(eye, DVec3::ZERO, (200, 100), (200, 100), &lens(90.0, 0.0));
        let (x, y) = cam.unwrap().project(DVec3::new(1.0, 0.5, 0.0)).unwrap();
        assert!(
            (x - 105.0).abs() < 1e-12 && (y - 47.5).abs() < 1e-12,
            "{x} {y}"
        );
    }

    #[test]
    fn behind_and_on_the_eye_have_no_place() {
        let eye = DVec3::new(0.0, 0.0, 10.0);
        let cam = Camera::new(eye, DVec3::ZERO, 64, 48).unwrap();
        assert_eq!(cam.project(DVec3::new(0.0, 0.0, 11.0)), None);
        assert_eq!(cam.project(eye), None);
        // Beside the eye, in the plane through it: depth 0, no place either.
        assert_eq!(cam.project(DVec3::new(3.0, 0.0, 10.0)), None);
        assert!(cam.project(DVec3::new(3.0, 0.0, 9.0)).is_some());
    }

    #[test]
    fn inverts_the_camera_rays() {
        // Any framing (report plane at another shape, a fov, a roll, an NFF up): the point
        // at any distance along the ray through (x, y) projects back to (x, y).
        let cams = [
            Camera::new(
                DVec3::new(3.0, 2.0, 7.0),
                DVec3::new(-1.0, 0.5, 0.0),
                64,
                48,
            ),
            Camera::framed(
                DVec3::new(0.0, 3.0, 12.0),
                DVec3::new(0.0, 1.0, 0.0),
                (640, 480),
                (1920, 1080),
                &Lens::default(),
            ),
            Camera::framed(
                DVec3::new(-2.0, 5.0, 1.0),
                DVec3::new(4.0, 0.0, -3.0),
                (320, 240),
                (320, 240),
                &lens(35.0, 23.0),
            ),
            Camera::framed(
                DVec3::ZERO,
                DVec3::new(0.0, 5.0, 1.0),
                (9, 9),
                (9, 9),
                &Lens {
                    up: DVec3::Z,
                    ..lens(60.0, -7.0)
                },
            ),
        ];
        for cam in cams.iter().map(|c| c.unwrap()) {
            for (x, y) in [(0.5, 0.5), (3.0, 4.0), (8.75, 0.25), (-20.0, 70.0)] {
                let r = cam.ray(x, y);
                for t in [0.01, 1.0, 37.5] {
                    let (px, py) = cam.project(r.origin + r.dir * t).unwrap();
                    assert!(
                        (px - x).abs() < 1e-8 && (py - y).abs() < 1e-8,
                        "({x}, {y}) at {t}: ({px}, {py})"
                    );
                }
            }
        }
    }
}
