//! Building a timeline (`Timeline::new`): the manifest's camera, gaze and tracks bound to
//! the scene, every name resolved (the first refusal in the file is the one reported,
//! at its line and column), a loop's tracks checked to close, and then every value the
//! tracks produce checked against the bounds (`bounds`).

use super::target::{self, Kind, Target};
use super::{node, Gaze, LookAt, Motion, Play, Sequence, Timeline, Track, TrackSpec};
use crate::refusal::ManifestError;
use whitted::fileloc::FileLoc;
use whitted::scene::Scene;

/// A refusal of the manifest at `loc`.
pub(super) fn invalid(loc: &FileLoc, message: String) -> ManifestError {
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
