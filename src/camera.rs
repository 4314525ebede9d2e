//! The report's pinhole camera (III.2), fixed by SPEC §2.
//!
//! U = normalize(look_at − eye); world up H = (0,1,0), or (0,0,1) when U is parallel to
//! it; D = normalize(U × H) points right and H' = D × U up. The view plane sits at
//! distance 1.0 and is 0.5 wide (`LargVue`) by 0.35 high (`LongVue`) whatever the
//! resolution, so pixels are not square unless ResX/ResY = 0.5/0.35, as in the report.
//! Pixel (i, j) has i to the right and j downwards; its centre is (i + 0.5, j + 0.5).

use crate::optics::Ray;
use glam::DVec3;

/// Distance from the eye to the view plane (`DistVue`).
pub const VIEW_DISTANCE: f64 = 1.0;
/// Width of the view plane (`LargVue`).
pub const VIEW_WIDTH: f64 = 0.5;
/// Height of the view plane (`LongVue`).
pub const VIEW_HEIGHT: f64 = 0.35;

/// A camera placed for one image of `width` × `height` pixels.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Camera {
    eye: DVec3,
    /// Direction to the top-left corner of the view plane (not normalised).
    corner: DVec3,
    /// Step of one pixel to the right.
    step_x: DVec3,
    /// Step of one pixel down.
    step_y: DVec3,
}

impl Camera {
    /// A camera at `eye` looking at `look_at`. `None` when the two points coincide (or are
    /// not finite), because then there is no direction to look in.
    pub fn new(eye: DVec3, look_at: DVec3, width: u32, height: u32) -> Option<Camera> {
        let to = look_at - eye;
        // |to|² under- or overflows for a tiny or huge `to`: scaled first, it normalises.
        let u = to
            .try_normalize()
            .or_else(|| (to / to.abs().max_element()).try_normalize())?;
        // |U × H| is the sine of the angle between them: below 1e-9 they are parallel.
        let across = u.cross(DVec3::Y);
        let right = if across.length() > 1e-9 {
            across.normalize()
        } else {
            u.cross(DVec3::Z).normalize()
        };
        let up = right.cross(u);
        let corner = VIEW_DISTANCE * u + (VIEW_HEIGHT / 2.0) * up - (VIEW_WIDTH / 2.0) * right;
        Some(Camera {
            eye,
            corner,
            step_x: right * (VIEW_WIDTH / width as f64),
            step_y: up * (VIEW_HEIGHT / height as f64),
        })
    }

    /// The eye position.
    pub fn eye(&self) -> DVec3 {
        self.eye
    }

    /// The camera's unit axes: right (D), up (H') and forward (U).
    pub fn basis(&self) -> (DVec3, DVec3, DVec3) {
        let right = self.step_x.normalize();
        let up = self.step_y.normalize();
        (right, up, up.cross(right))
    }

    /// The primary ray through the image point (x, y) in pixel units: (i + 0.5, j + 0.5)
    /// is the centre of pixel (i, j).
    #[inline]
    pub fn ray(&self, x: f64, y: f64) -> Ray {
        let dir = self.corner + self.step_x * x - self.step_y * y;
        Ray::new(self.eye, dir.normalize())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn close(a: DVec3, b: DVec3) -> bool {
        (a - b).length() < 1e-12
    }

    #[test]
    fn centre_pixel_looks_straight_ahead() {
        // 2×2 image: the centre of the image is the corner shared by the four pixels.
        let cam = Camera::new(DVec3::ZERO, -DVec3::Z, 2, 2).unwrap();
        let r = cam.ray(1.0, 1.0);
        assert!(close(r.dir, -DVec3::Z), "{}", r.dir);
        assert_eq!(r.origin, DVec3::ZERO);
    }

    #[test]
    fn corner_pixel_by_hand() {
        // 640×480 looking down −z: D = +x, H' = +y. Pixel (0,0) centre:
        // x = −0.25 + 0.5·0.5/640 = −0.24960937500, y = 0.175 − 0.35·0.5/480 = 0.17463541666…
        let cam = Camera::new(DVec3::ZERO, -DVec3::Z, 640, 480).unwrap();
        let r = cam.ray(0.5, 0.5);
        let raw = DVec3::new(-0.2496093750, 0.175 - 0.35 * 0.5 / 480.0, -1.0);
        assert!(close(r.dir, raw.normalize()), "{}", r.dir);
        // Bottom-right pixel mirrors it: the image is not mirrored left-right.
        let r = cam.ray(639.5, 479.5);
        let raw = DVec3::new(0.2496093750, -(0.175 - 0.35 * 0.5 / 480.0), -1.0);
        assert!(close(r.dir, raw.normalize()), "{}", r.dir);
    }

    #[test]
    fn looking_down_falls_back_to_z_up() {
        let cam = Camera::new(DVec3::new(0.0, 10.0, 0.0), DVec3::ZERO, 4, 4).unwrap();
        let r = cam.ray(2.0, 2.0);
        assert!(close(r.dir, -DVec3::Y));
        // U = −y, fallback H = +z: D = U × H = (−y) × z = −x, H' = D × U = (−x) × (−y) = +z.
        // The top-left pixel therefore leans towards +x and +z.
        let tl = cam.ray(0.5, 0.5).dir;
        assert!(tl.x > 0.0 && tl.z > 0.0, "{tl}");
        let cam = Camera::new(DVec3::ZERO, DVec3::new(0.0, 5.0, 0.0), 4, 4).unwrap();
        assert!(close(cam.ray(2.0, 2.0).dir, DVec3::Y));
    }

    #[test]
    fn eye_on_target_is_refused() {
        assert!(Camera::new(DVec3::ONE, DVec3::ONE, 4, 4).is_none());
    }

    #[test]
    fn rays_are_unit() {
        let cam = Camera::new(
            DVec3::new(3.0, 2.0, 7.0),
            DVec3::new(-1.0, 0.5, 0.0),
            64,
            48,
        )
        .unwrap();
        for (x, y) in [(0.5, 0.5), (63.5, 0.5), (10.0, 40.0)] {
            assert!((cam.ray(x, y).dir.length() - 1.0).abs() < 1e-12);
        }
    }
}
