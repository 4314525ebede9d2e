//! What decides a frame's bytes besides its scene and camera (`Settings`): size,
//! samples, motion blur, anti-aliasing, format, pixel version and view plane; recorded
//! in every frame's digest.

use crate::timeline::MotionBlur;
use serde::Serialize;
use whitted::output::ImageFormat;
use whitted::render::Adaptive;

/// Everything besides the scene and camera that decides a frame's bytes.
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
pub struct Settings {
    /// The frame's width in pixels.
    pub width: u32,
    /// The frame's height in pixels.
    pub height: u32,
    /// n of the n×n supersampling grid.
    pub samples: u32,
    /// The motion blur, if any.
    pub motion_blur: Option<MotionBlur>,
    /// Adaptive anti-aliasing, if set (left out of the digest's JSON when not, so that
    /// frames drawn before it existed stay up to date).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub antialias: Option<Adaptive>,
    /// The file format the frame is written in.
    pub format: ImageFormat,
    /// `PIXEL_VERSION` of the library that drew it.
    pub pixel_version: u32,
    /// The view plane's width and height and the roll, when they are not the report's
    /// (left out of the record then, so frames of the report's framing keep their digest).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub view: Option<[f64; 3]>,
}
