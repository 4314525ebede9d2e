//! The report's pinhole camera (III.2), with a framing for other sizes, a field of view
//! and a roll.
//!
//! U = normalize(look_at − eye); world up H = (0,1,0), or (0,0,1) when U is parallel to
//! it; D = normalize(U × H) points right and H' = D × U up. The view plane sits at
//! distance 1.0. At the scene file's own size, and at any size of the same shape
//! (ResX:ResY), it is the report's 0.5 wide (`LargVue`) by 0.35 high (`LongVue`), so the
//! report's pictures keep every pixel. At a size of another shape the view's height
//! 0.35 holds and its width follows the picture with square pixels (0.35·W/H), so a
//! 1920×1080 frame shows round spheres instead of stretching the report's plane. A
//! `Lens` may set a vertical field of view (degrees: the plane is 2·tan(fov/2) high,
//! square pixels at any size) and a roll (degrees: positive banks the camera to the
//! right, so the picture turns counter-clockwise). Pixel (i, j) has i to the right and
//! j downwards; its centre is (i + 0.5, j + 0.5). `project` takes a world point back to
//! its (x, y) on the picture.
//!
//! ```toml
//! [camera]
//! fov = 30.0     # vertical, degrees, 0 < fov < 180 (default: the report's plane)
//! roll = 10.0    # degrees (default 0)
//! ```

use crate::optics::Ray;
use glam::DVec3;

mod aspect;
pub mod project;
pub mod thin_lens;
pub use aspect::NonSquare;
pub use thin_lens::ThinLens;

/// Distance from the eye to the view plane (`DistVue`).
pub const VIEW_DISTANCE: f64 = 1.0;
/// Width of the view plane (`LargVue`).
pub const VIEW_WIDTH: f64 = 0.5;
/// Height of the view plane (`LongVue`).
pub const VIEW_HEIGHT: f64 = 0.35;

/// The framing of a camera beyond its eye and look-at point: a vertical field of view
/// and a roll, both in degrees, and the world's up. The default is the report's plane
/// with no roll and y up.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Lens {
    /// The vertical field of view in degrees, 0 < fov < 180; `None`: the report's plane.
    pub fov: Option<f64>,
    /// The roll about the viewing direction in degrees; positive banks to the right.
    pub roll: f64,
    /// The world's up (H of SPEC §2): (0, 1, 0), or an NFF view's `up` (SPEC §17).
    pub up: DVec3,
    /// The field of view spans the outer pixel centres (NFF's `angle`) instead of the
    /// picture's edges.
    pub centres: bool,
}

impl Default for Lens {
    fn default() -> Lens {
        Lens {
            fov: None,
            roll: 0.0,
            up: DVec3::Y,
            centres: false,
        }
    }
}

/// The largest roll taken, in degrees (a thousand turns).
pub const MAX_ROLL: f64 = 360_000.0;

impl Lens {
    /// This scene lens with a user's field of view (which then spans the picture's
    /// edges) and roll.
    pub fn overridden(&self, fov: Option<f64>, roll: f64) -> Lens {
        Lens {
            fov: fov.or(self.fov),
            roll,
            up: self.up,
            centres: fov.is_none() && self.centres,
        }
    }

    /// Whether `fov` is a vertical field of view taken: strictly between 0 and 180 degrees.
    pub fn fov_ok(fov: f64) -> bool {
        fov > 0.0 && fov < 180.0
    }

    /// Whether `roll` is a roll taken: finite, at most `MAX_ROLL` degrees either way.
    pub fn roll_ok(roll: f64) -> bool {
        roll.abs() <= MAX_ROLL
    }

    /// The view plane's width and height (at distance 1.0) for an image of `size`
    /// pixels of a scene whose own size is `native`: the report's 0.5 × 0.35 at the
    /// native shape without a field of view, else square pixels, 0.35 (or the field of
    /// view's 2·tan(fov/2)) high.
    pub fn plane(&self, native: (u32, u32), size: (u32, u32)) -> (f64, f64) {
        let (w, h) = (u64::from(size.0.max(1)), u64::from(size.1.max(1)));
        let (nw, nh) = (u64::from(native.0.max(1)), u64::from(native.1.max(1)));
        let height = match self.fov {
            // Between the outer pixel centres: h − 1 pixels span the angle.
            Some(fov) if self.centres && h > 1 => {
                2.0 * (fov.to_radians() / 2.0).tan() * h as f64 / (h - 1) as f64
            }
            Some(fov) => 2.0 * (fov.to_radians() / 2.0).tan(),
            None if w * nh == h * nw => return (VIEW_WIDTH, VIEW_HEIGHT),
            None => VIEW_HEIGHT,
        };
        (height * w as f64 / h as f64, height)
    }
}

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
    /// The view plane's width and height at distance 1.0 (`Lens::plane`).
    plane: (f64, f64),
}

impl Camera {
    /// A camera at `eye` looking at `look_at`. `None` when the two points coincide (or are
    /// not finite), because then there is no direction to look in.
    pub fn new(eye: DVec3, look_at: DVec3, width: u32, height: u32) -> Option<Camera> {
        Camera::with_plane(
            eye,
            look_at,
            (width, height),
            (VIEW_WIDTH, VIEW_HEIGHT),
            0.0,
            DVec3::Y,
        )
    }

    /// A camera for an image of `size` pixels of a scene whose own size is `native`,
    /// framed by `lens` (`Lens::plane`, then the roll).
    pub fn framed(
        eye: DVec3,
        look_at: DVec3,
        native: (u32, u32),
        size: (u32, u32),
        lens: &Lens,
    ) -> Option<Camera> {
        let plane = lens.plane(native, size);
        Camera::with_plane(eye, look_at, size, plane, lens.roll, lens.up)
    }

    /// A camera whose view plane is `plane` = (width, height) at distance 1.0, turned by
    /// `roll` degrees about the viewing direction.
    fn with_plane(
        eye: DVec3,
        look_at: DVec3,
        (width, height): (u32, u32),
        (plane_w, plane_h): (f64, f64),
        roll: f64,
        up: DVec3,
    ) -> Option<Camera> {
        let to = look_at - eye;
        // |to|² under- or overflows for a tiny or huge `to`: scaled first, it normalises.
        let u = to
            .try_normalize()
            .or_else(|| (to / to.abs().max_element()).try_normalize())?;
        // |U × H| is the sine of the angle between them: below 1e-9 they are parallel,
        // and z (y for a world whose up is z) stands in.
        let h = up.try_normalize().unwrap_or(DVec3::Y);
        let across = u.cross(h);
        let mut right = if across.length() > 1e-9 {
            across.normalize()
        } else {
            let alt = if h.z.abs() > 0.9 { DVec3::Y } else { DVec3::Z };
            u.cross(alt).normalize()
        };
        let mut up = right.cross(u);
        if roll != 0.0 {
            // Banking right: the right vector dips towards −up, up leans towards right.
            let (s, c) = roll.to_radians().sin_cos();
            (right, up) = (right * c - up * s, up * c + right * s);
        }
        let corner = VIEW_DISTANCE * u + (plane_h / 2.0) * up - (plane_w / 2.0) * right;
        Some(Camera {
            eye,
            corner,
            step_x: right * (plane_w / width as f64),
            step_y: up * (plane_h / height as f64),
            plane: (plane_w, plane_h),
        })
    }

    /// The eye position.
    pub fn eye(&self) -> DVec3 {
        self.eye
    }

    /// The view plane's width and height at distance `VIEW_DISTANCE`: the report's
    /// 0.5 × 0.35, or the framing's (`Lens::plane`).
    pub fn plane(&self) -> (f64, f64) {
        self.plane
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

    /// The parallel ray of an orthographic view through image point (x, y): it leaves
    /// the view plane's point there, moved to the eye's plane and scaled so that the
    /// image's height spans `height` (a glTF camera's 2·ymag), along the viewing axis.
    pub fn parallel_ray(&self, x: f64, y: f64, height: f64) -> Ray {
        let d = self.corner + self.step_x * x - self.step_y * y;
        // step_x points right and step_y up the image: their cross product points back.
        let forward = self.step_y.cross(self.step_x).normalize();
        let offset = d - d.dot(forward) * forward;
        let k = height / self.plane.1;
        Ray::new(self.eye + k * offset, forward)
    }
}

#[cfg(test)]
mod tests;
