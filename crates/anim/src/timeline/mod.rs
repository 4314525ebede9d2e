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
//! Building a timeline resolves every track against the scene and checks every value it
//! will produce, at every time a frame of the sequence will sample, against the bounds of
//! SPEC §1; a refusal names the manifest's line and column, the track and the frame.

mod bounds;
mod camera;
mod ease;
pub mod node;
mod spline;
mod target;
mod track;

pub use camera::{CameraPath, Circle};
pub use ease::{Ease, Interpolation};
pub use spline::{coord_ok, Key, Spline, SplineError};
pub use target::{Field, Kind, Target};
pub use track::{Motion, Track, TrackKey, TrackSpec};

use crate::refusal::ManifestError;
use glam::DVec3;
use std::borrow::Cow;
use whitted::fileloc::FileLoc;
use whitted::scene::Scene;

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

fn invalid(loc: &FileLoc, message: String) -> ManifestError {
    ManifestError::Invalid {
        loc: loc.clone(),
        message,
    }
}

impl Timeline {
    /// Binds the manifest's camera and tracks (`Sequence::from(&manifest)`) to `base`, and
    /// checks every value they produce at every sampled time.
    pub fn new<'a>(
        base: Scene,
        sequence: impl Into<Sequence<'a>>,
    ) -> Result<Timeline, ManifestError> {
        let manifest: Sequence<'a> = sequence.into();
        // Of the names that do not resolve, the first in the file is reported.
        let mut refused: Option<ManifestError> = None;
        let mut refuse = |e: ManifestError| {
            let at = |e: &ManifestError| e.loc().map(|l| (l.line, l.column));
            if refused.as_ref().is_none_or(|r| at(&e) < at(r)) {
                refused = Some(e);
            }
        };
        let gaze = match manifest.look_at {
            None => Gaze::Path,
            Some(LookAt::Point(p)) => Gaze::Point(*p),
            Some(LookAt::Object { name, loc }) => match target::parse_subject(name, &base) {
                Ok(subject) => Gaze::Follow(subject),
                Err(m) => {
                    refuse(invalid(loc, format!("look_at: {m}")));
                    Gaze::Path
                }
            },
        };
        let mut tracks: Vec<Track> = Vec::with_capacity(manifest.tracks.len());
        let given = target::camera::Given {
            path: manifest.camera,
            look_at: manifest.look_at,
            fov: manifest.fov,
        };
        let mut nodes = Vec::new();
        for (n, spec) in manifest.tracks.iter().enumerate() {
            if let Some((name, field)) = node::parse(&spec.target) {
                let vectors = match &spec.motion {
                    Motion::Keys { keys, .. } => keys.iter().all(|k| k.kind == Kind::Vector),
                    Motion::Circle(_) => field == "translation",
                };
                match node::resolve(&name, &field, &base, n) {
                    Ok(_) if !vectors => refuse(invalid(
                        &spec.loc,
                        format!("track {}: a node's {field} takes [x, y, z] keys", n + 1),
                    )),
                    Ok(t) => nodes.push((t, spec.clone())),
                    Err(m) => refuse(invalid(&spec.loc, format!("track {}: {m}", n + 1))),
                }
                continue;
            }
            let track = match resolve(spec, &base) {
                Ok(track) => track,
                Err(m) => {
                    refuse(invalid(&spec.loc, m));
                    continue;
                }
            };
            if let Some(why) = target::camera::refusal(track.target.field, given) {
                refuse(invalid(&spec.loc, format!("track {}: {why}", n + 1)));
            }
            if manifest.looped {
                if let Err(m) = fits_a_loop(&spec.motion) {
                    refuse(invalid(&spec.loc, format!("track {}: {m}", n + 1)));
                }
            }
            if let Some(j) = tracks.iter().position(|t| t.target == track.target) {
                let message = format!(
                    "track {}: its target `{}` is already animated by track {}; one track per value",
                    n + 1,
                    spec.target,
                    j + 1
                );
                refuse(invalid(&spec.loc, message));
            }
            tracks.push(track);
        }
        let play = match &base.model {
            Some(model) => {
                let names = manifest.animation.map(|(n, _)| n);
                let playing = match model.select(names) {
                    Ok(p) => p,
                    Err(m) => {
                        let loc = manifest
                            .animation
                            .map(|(_, l)| l.clone())
                            .unwrap_or_default();
                        refuse(invalid(&loc, format!("[animation] name: {m}")));
                        Vec::new()
                    }
                };
                let moves = !nodes.is_empty()
                    || playing
                        .iter()
                        .any(|&c| !model.rig.clips[c].channels.is_empty());
                moves.then_some(Play {
                    playing,
                    fps: manifest.fps,
                    nodes,
                })
            }
            None => None,
        };
        if let Some(e) = refused {
            return Err(e);
        }
        let timeline = Timeline {
            play,
            base,
            frames: manifest.frames,
            camera: manifest.camera.cloned(),
            tracks,
            blur: manifest.blur,
            looped: manifest.looped,
            gaze,
        };
        timeline.check_values()?;
        timeline.check_records()?;
        Ok(timeline)
    }

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

/// Whether a track can loop: a circle's turns whole (keys lie within the sequence, so
/// within one loop, always).
fn fits_a_loop(motion: &Motion) -> Result<(), String> {
    match motion {
        Motion::Circle(c) if c.turns.fract() != 0.0 => Err(format!(
            "with loop = true a circle makes whole turns, found turns = {}",
            c.turns
        )),
        _ => Ok(()),
    }
}

/// A track's target resolved against `scene`, and its values' kind checked.
fn resolve(spec: &TrackSpec, scene: &Scene) -> Result<Track, String> {
    let target = Target::parse(&spec.target, scene)?;
    match &spec.motion {
        Motion::Circle(_) if !target.is_position() => {
            return Err(format!(
                "`{}` is not a position: only sphere center, plane or cylinder point, light position and the camera's position or look_at may follow a circle",
                spec.target
            ))
        }
        Motion::Keys { keys, .. } => {
            if let Some(key) = keys.iter().find(|k| k.kind != target.kind()) {
                let want = match target.kind() {
                    Kind::Number => "a number",
                    Kind::Vector => "[x, y, z]",
                };
                return Err(format!(
                    "`{}` takes {want}; the key at frame {} (line {}) gives another kind of value",
                    spec.target, key.frame, key.loc.line
                ));
            }
        }
        Motion::Circle(_) => {}
    }
    Ok(Track {
        spec: spec.clone(),
        target,
    })
}

#[cfg(test)]
mod loop_tests;
#[cfg(test)]
mod tests;
