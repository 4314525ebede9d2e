//! STUB — being written. Camera paths of SPEC §5: circle and spline.

use super::spline::Spline;
use glam::DVec3;

/// Where the camera is on each frame.
#[derive(Clone, Debug, PartialEq)]
pub enum CameraPath {
    /// The report's orbit.
    Circle {
        center: DVec3,
        radius: f64,
        height: f64,
        /// Degrees; 0 puts the camera on the +z side of `center`.
        start_angle: f64,
        turns: f64,
        /// Defaults to `center`.
        look_at: Option<DVec3>,
    },
    Spline(Spline),
}

impl CameraPath {
    /// Eye and look-at point of frame `frame` of a `frames`-frame sequence;
    /// `scene_look_at` is the scene file's point, used when the path gives none.
    pub fn at(&self, frame: u32, frames: u32, scene_look_at: DVec3) -> (DVec3, DVec3) {
        let _ = (frame, frames, scene_look_at);
        todo!()
    }
}
