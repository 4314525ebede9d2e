//! What a timeline is built from, as a manifest gives it: the sequence's length, the
//! camera path and its gaze (`LookAt`), the tracks, the motion blur (`MotionBlur`, whose
//! sub-frame times every frame samples) and a glTF scene's animations (`Play`).

use super::camera::CameraPath;
use super::node;
use super::track::TrackSpec;
use glam::DVec3;
use whitted::fileloc::FileLoc;

/// `[render] motion_blur`: each frame the mean of `samples` sub-frames spread over
/// `shutter` frames centred on it.
#[derive(Clone, Copy, Debug, PartialEq, serde::Serialize)]
pub struct MotionBlur {
    /// In frames, 0 < shutter ≤ 1.
    pub shutter: f64,
    /// Sub-frames averaged per frame, 1 to `MAX_BLUR_SAMPLES`.
    pub samples: u32,
}

impl MotionBlur {
    /// The values a `motion_blur` table leaves out take: a half-frame shutter (film's 180°)
    /// and 8 samples.
    pub const DEFAULT: MotionBlur = MotionBlur {
        shutter: 0.5,
        samples: 8,
    };

    /// t_k = frame + shutter·((k + ½)/samples − ½), k = 0..samples.
    pub fn times(&self, frame: u32) -> impl Iterator<Item = f64> + '_ {
        let n = f64::from(self.samples.max(1));
        (0..self.samples.max(1))
            .map(move |k| f64::from(frame) + self.shutter * ((f64::from(k) + 0.5) / n - 0.5))
    }
}

/// What the camera looks at, as the manifest gives it (`look_at`).
#[derive(Clone, Debug, PartialEq)]
pub enum LookAt {
    /// `[x, y, z]`: a fixed point.
    Point(DVec3),
    /// `"sphere 2"`, resolved against the scene by the timeline.
    Object {
        /// The text as written, `KIND N`.
        name: String,
        /// Where it is written, for errors found when resolving it.
        loc: FileLoc,
    },
}

/// What a timeline binds to a scene, as a manifest gives it (`From<&Manifest>`): the
/// sequence's length, the camera path and its gaze, the tracks and the motion blur.
#[derive(Clone, Copy, Debug)]
pub struct Sequence<'a> {
    /// The frame count.
    pub frames: u32,
    /// The camera's path; `None` keeps the scene file's eye.
    pub camera: Option<&'a CameraPath>,
    /// An object followed or, without a path, a point looked at.
    pub look_at: Option<&'a LookAt>,
    /// The tracks as written.
    pub tracks: &'a [TrackSpec],
    /// The motion blur, if any.
    pub blur: Option<MotionBlur>,
    /// `loop = true`: the end leads into the start (frame `frames` is frame 0).
    pub looped: bool,
    /// `[camera] fov`, which a `camera fov` track may not be beside.
    pub fov: Option<f64>,
    /// `[animation] name`: the glTF animations that play (every one for `None`), and
    /// where the table is written.
    pub animation: Option<(&'a [String], &'a FileLoc)>,
    /// Frames per second: a glTF animation's seconds are frames / fps.
    pub fps: f64,
}

/// What drives a glTF scene's frames: the animations that play, the time base, and the
/// tracks on its nodes (each with its spec, whose value is put in over the channel).
#[derive(Clone, Debug)]
pub struct Play {
    /// The animations that play (indices into the file's).
    pub playing: Vec<usize>,
    /// Frames per second.
    pub fps: f64,
    /// The node tracks.
    pub nodes: Vec<(node::NodeTrack, TrackSpec)>,
}
