//! Values over time: the one answer to "what is frame t?". A `Timeline` holds the base
//! scene, the camera (a `circle` or `spline` path from `camera` and `spline`, or the scene
//! file's eye held still; looking at a point or following an object) and the tracks
//! (`track`, `target`, `ease`), and `Timeline::at(t)` gives the scene with every track's
//! value at time t put in and the camera's eye and look-at point there. Times are in
//! frames and may be fractional (motion blur samples between frames, `MotionBlur`).
//!
//! A looping sequence (`loop = true`) repeats every `frames` frames: frame `frames` is
//! frame 0, tracks run from their last key back to their first (`Motion::value_looped`),
//! and motion blur's sub-frames before frame 0 are the end of the loop.
//!
//! Building a timeline (`bind`) resolves every track against the scene and checks every
//! value it will produce, at every time a frame of the sequence will sample, against the
//! bounds of SPEC §1 (`bounds`); a refusal names the manifest's line and column, the
//! track and the frame. What it is built from, as a manifest gives it, is `sequence`.

mod bind;
mod bounds;
mod camera;
mod ease;
pub mod node;
mod sequence;
mod spline;
mod target;
mod track;

pub use camera::{CameraPath, Circle};
pub use ease::{Ease, Interpolation};
pub use sequence::{LookAt, MotionBlur, Play, Sequence};
pub use spline::{coord_ok, Key, Spline, SplineError};
pub use target::{Field, Kind, Target};
pub use track::{Motion, Track, TrackKey, TrackSpec};

use glam::DVec3;
use std::borrow::Cow;
use whitted::scene::Scene;

/// What the camera looks at when the path does not say.
#[derive(Clone, Debug, PartialEq)]
enum Gaze {
    /// The path's own look-at point (or the scene file's).
    Path,
    /// A fixed point (a still camera's `look_at = [x, y, z]`).
    Point(DVec3),
    /// An object or light, followed: its kind and index.
    Follow(target::Subject),
}

/// The scene and camera of every time of a sequence.
#[derive(Clone, Debug)]
pub struct Timeline {
    /// The scene as its file gives it; tracks change copies of it.
    pub base: Scene,
    /// The sequence's frame count (the time base of circles and closed splines).
    pub frames: u32,
    /// The camera's path; `None` keeps the scene file's eye.
    pub camera: Option<CameraPath>,
    /// The tracks, resolved against `base`, in manifest order.
    pub tracks: Vec<Track>,
    /// The motion blur, if the manifest asks for it.
    pub blur: Option<MotionBlur>,
    /// Whether the sequence loops: tracks run from their last key back to their first
    /// (`Motion::value_looped`), a spline camera path is closed by the manifest.
    pub looped: bool,
    /// A glTF scene's animations and node tracks, when it has any: every time is posed
    /// again from the file.
    pub play: Option<Play>,
    gaze: Gaze,
}

/// Frame t: the scene with the tracks' values put in, and the camera.
#[derive(Clone, Debug)]
pub struct Snapshot<'a> {
    /// The scene at that time (borrowed from the base when no track changes it).
    pub scene: Cow<'a, Scene>,
    /// The camera's position.
    pub eye: DVec3,
    /// The point the camera looks at.
    pub look_at: DVec3,
}

impl Timeline {
    /// The times frame `frame` samples: the frame itself, or its motion-blur sub-frames.
    pub fn times(&self, frame: u32) -> Vec<f64> {
        match &self.blur {
            Some(blur) => blur.times(frame).collect(),
            None => vec![f64::from(frame)],
        }
    }

    /// Whether some track changes what rays hit, so that frames need their own
    /// acceleration structure; otherwise one, built from the base scene, serves all.
    pub fn moves_geometry(&self) -> bool {
        self.play.is_some() || self.tracks.iter().any(|t| t.target.moves_geometry())
    }

    /// The glTF scene posed at time `t` (frames): the animations at t / fps seconds, the
    /// node tracks' values put in over them.
    fn posed(&self, play: &Play, t: f64) -> Scene {
        let Some(model) = &self.base.model else {
            return self.base.clone();
        };
        let puts: Vec<whitted::gltf::Put> = (play.nodes.iter())
            .map(|(n, spec)| {
                let v = match self.looped {
                    true => spec.motion.value_looped(t, self.frames),
                    false => spec.motion.value_at(t, self.frames),
                };
                n.put(v)
            })
            .collect();
        // The same file posed at load time: only a fault found then can fail here.
        model
            .scene_at(t / play.fps, &play.playing, &puts)
            .unwrap_or_else(|_| self.base.clone())
    }

    /// Frame t: the scene with every track's value at t, and the camera there.
    pub fn at(&self, t: f64) -> Snapshot<'_> {
        let mut scene = match &self.play {
            Some(play) => Cow::Owned(self.posed(play, t)),
            None => Cow::Borrowed(&self.base),
        };
        if !self.tracks.is_empty() {
            let owned = scene.to_mut();
            for track in &self.tracks {
                track.target.apply(owned, self.value(track, t));
            }
        }
        let (eye, path_look) = match &self.camera {
            Some(path) => path.at_about(t, self.frames, scene.look_at, self.base.lens.up),
            None => (scene.eye, scene.look_at),
        };
        let look_at = match &self.gaze {
            Gaze::Path => path_look,
            Gaze::Point(p) => *p,
            Gaze::Follow(subject) => target::subject_point(*subject, &scene),
        };
        Snapshot {
            scene,
            eye,
            look_at,
        }
    }

    /// A track's value at time `t`, in a loop when the sequence loops.
    pub fn value(&self, track: &Track, t: f64) -> DVec3 {
        match self.looped {
            true => track.spec.motion.value_looped(t, self.frames),
            false => track.spec.motion.value_at(t, self.frames),
        }
    }

    /// The frames a plot of the paths draws: every frame, and frame `frames` (which is
    /// frame 0) when the sequence loops, so that the drawn path closes.
    pub fn plotted_frames(&self) -> u32 {
        self.frames + u32::from(self.looped)
    }

    /// The position a track gives over the sequence, for plots: `(frame, point)` of each
    /// track whose target is a position, at every frame of `plotted_frames`.
    pub fn tracked_positions(&self) -> Vec<(String, Vec<DVec3>)> {
        self.tracks
            .iter()
            // The camera's own position is drawn as the camera's path.
            .filter(|t| t.target.is_position() && t.target.field != Field::CameraPosition)
            .map(|t| {
                let points = (0..self.plotted_frames())
                    .map(|f| self.value(t, f64::from(f)))
                    .collect();
                (t.spec.target.clone(), points)
            })
            .collect()
    }
}

#[cfg(test)]
mod loop_tests;
#[cfg(test)]
mod tests;
