//! A track: one scene value over time (SPEC §7), through keys or along a circle.
//!
//! ```toml
//! [[track]]
//! target = "sphere 1 center"
//! interpolation = "smooth"       # linear (default) | smooth | step
//! ease = "in-out"                # none (default) | in | out | in-out
//! keys = [
//!   { frame = 0,  value = [0.0, 1.0, 0.0] },
//!   { frame = 40, value = [0.0, 4.0, 0.0], ease = "out" },   # the segment from this key
//!   { frame = 80, value = [0.0, 1.0, 0.0] },
//! ]
//!
//! [[track]]
//! target = "light 1 position"
//! path = "circle"                # center, radius, height, start_angle, turns: the camera's
//! center = [0.0, 0.0, 0.0]
//! radius = 8.0
//! height = 10.0
//! ```
//!
//! Between keys the segment's ease shapes u = (t − f0)/(f1 − f0); before the first key and
//! after the last the end value holds; `step` holds a key's value until the next key's
//! frame. `smooth` is the camera spline's centripetal Catmull-Rom through the key values
//! (numbers as `(x, 0, 0)`), with the open path's reflected end points.
//!
//! In a loop (`loop = true`, `value_looped`) the keys repeat every `frames` frames: after
//! the last key the value runs back to the first key's, arriving `frames` frames after the
//! first key (at frame `frames` for a first key at 0) with the last key's ease and
//! interpolation (`step` holds the last value until then); `smooth` is then the closed
//! curve, its neighbours wrapping around, as a closed camera spline's.

use super::camera::Circle;
use super::ease::{Ease, Interpolation};
use super::spline::curve_point;
use super::target::{Kind, Target};
use glam::DVec3;
use whitted::fileloc::FileLoc;

/// A key of a track: its frame, its value (a number as `(x, 0, 0)`), what was written
/// (number or vector), the ease of the segment it starts, and where it is in the manifest.
#[derive(Clone, Debug, PartialEq)]
pub struct TrackKey {
    /// The frame at which the track has exactly `value`.
    pub frame: u32,
    /// The value (a number as `(x, 0, 0)`).
    pub value: DVec3,
    /// Whether a number or a vector was written, checked against the target.
    pub kind: Kind,
    /// The ease from this key to the next.
    pub ease: Ease,
    /// Where the key is written in the manifest.
    pub loc: FileLoc,
}

/// How a track's value moves.
#[derive(Clone, Debug, PartialEq)]
pub enum Motion {
    /// Keys in strictly increasing frame order, at least one.
    Keys {
        /// How values go from key to key.
        interpolation: Interpolation,
        /// The keys.
        keys: Vec<TrackKey>,
    },
    /// A position on a circle, as the camera's.
    Circle(Circle),
}

/// A track as the manifest states it, before its target is resolved against a scene.
#[derive(Clone, Debug, PartialEq)]
pub struct TrackSpec {
    /// The target as written: `sphere 1 center`.
    pub target: String,
    /// Where `target` is written.
    pub loc: FileLoc,
    /// How its value moves over time.
    pub motion: Motion,
}

/// A track whose target is resolved.
#[derive(Clone, Debug, PartialEq)]
pub struct Track {
    /// The track as the manifest states it.
    pub spec: TrackSpec,
    /// The value of the scene it drives.
    pub target: Target,
}

impl Motion {
    /// The value at time `t` (frames, possibly fractional) of a `frames`-frame sequence.
    pub fn value_at(&self, t: f64, frames: u32) -> DVec3 {
        match self {
            Motion::Circle(circle) => circle.at(t, frames),
            Motion::Keys {
                interpolation,
                keys,
            } => {
                let Some(segment) = segment_at(keys, t) else {
                    let end = if t <= f64::from(keys[0].frame) {
                        &keys[0]
                    } else {
                        &keys[keys.len() - 1]
                    };
                    return end.value;
                };
                let (a, b) = (&keys[segment], &keys[segment + 1]);
                let u = (t - f64::from(a.frame)) / f64::from(b.frame - a.frame);
                between(*interpolation, keys, segment, a.ease.apply(u), false)
            }
        }
    }

    /// The value at time `t` of a `frames`-frame sequence that loops (`loop = true`): the
    /// keys repeat every `frames` frames, and after the last key the value runs back to
    /// the first key's, reaching it `frames` frames after the first key's frame (frame
    /// `frames` when the first key is at 0), with the last key's ease; `smooth` is the
    /// closed curve through the keys, so the join is as smooth as the rest. A circle is
    /// the same as `value_at`; one key holds.
    pub fn value_looped(&self, t: f64, frames: u32) -> DVec3 {
        let Motion::Keys {
            interpolation,
            keys,
        } = self
        else {
            return self.value_at(t, frames);
        };
        let n = keys.len();
        if n < 2 {
            return keys[0].value;
        }
        let (segment, u) = looped_segment(keys, t, frames);
        between(
            *interpolation,
            keys,
            segment,
            keys[segment].ease.apply(u),
            true,
        )
    }

    /// `loc_at` in a loop (`value_looped`): the key that starts the segment, the last key
    /// for the closing one.
    pub fn loc_looped<'a>(&'a self, t: f64, frames: u32, track: &'a FileLoc) -> &'a FileLoc {
        match self {
            Motion::Keys { keys, .. } if keys.len() > 1 => {
                &keys[looped_segment(keys, t, frames).0].loc
            }
            _ => self.loc_at(t, track),
        }
    }

    /// The place in the manifest answerable for the value at `t`: the key that starts the
    /// segment (or the end key held), or `track` for a circle.
    pub fn loc_at<'a>(&'a self, t: f64, track: &'a FileLoc) -> &'a FileLoc {
        match self {
            Motion::Circle(_) => track,
            Motion::Keys { keys, .. } => match segment_at(keys, t) {
                Some(segment) => &keys[segment].loc,
                None if t <= f64::from(keys[0].frame) => &keys[0].loc,
                None => &keys[keys.len() - 1].loc,
            },
        }
    }
}

/// The time `t` of a loop of `frames` frames (widened to the keys' span should they span
/// more: a manifest's keys lie within its frames) brought into the first loop: the first key's frame to
/// that plus the period.
fn in_loop(keys: &[TrackKey], t: f64, frames: u32) -> (f64, f64) {
    let first = f64::from(keys[0].frame);
    let last = f64::from(keys[keys.len() - 1].frame);
    let period = f64::from(frames).max(last - first + 1.0);
    (first + (t - first).rem_euclid(period), period)
}

/// The segment and its parameter u ∈ [0, 1] of time `t` in a loop (two keys at least):
/// segment n − 1 is the closing one, from the last key back to the first.
fn looped_segment(keys: &[TrackKey], t: f64, frames: u32) -> (usize, f64) {
    let n = keys.len();
    let (t, period) = in_loop(keys, t, frames);
    let (first, last) = (f64::from(keys[0].frame), f64::from(keys[n - 1].frame));
    if t >= last {
        return (
            n - 1,
            ((t - last) / (first + period - last)).clamp(0.0, 1.0),
        );
    }
    let segment = segment_at(keys, t).unwrap_or(0);
    let (a, b) = (
        f64::from(keys[segment].frame),
        f64::from(keys[segment + 1].frame),
    );
    (segment, ((t - a) / (b - a)).clamp(0.0, 1.0))
}

/// The value at eased parameter `e` of segment `segment` (from key `segment` to the next,
/// the first after the last when `closed`).
fn between(
    interpolation: Interpolation,
    keys: &[TrackKey],
    segment: usize,
    e: f64,
    closed: bool,
) -> DVec3 {
    let (a, b) = (&keys[segment], &keys[(segment + 1) % keys.len()]);
    match interpolation {
        Interpolation::Step => a.value,
        Interpolation::Linear => a.value + (b.value - a.value) * e,
        Interpolation::Smooth => curve_point(keys, |k| k.value, closed, segment, e),
    }
}

/// The segment i with keys[i].frame ≤ t < keys[i + 1].frame, or `None` outside the keys.
fn segment_at(keys: &[TrackKey], t: f64) -> Option<usize> {
    if keys.len() < 2 || t.is_nan() || t < f64::from(keys[0].frame) {
        return None;
    }
    let after = keys.partition_point(|k| f64::from(k.frame) <= t);
    (after < keys.len()).then(|| after - 1)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn key(frame: u32, x: f64, ease: Ease) -> TrackKey {
        TrackKey {
            frame,
            value: DVec3::new(x, 0.0, 0.0),
            kind: Kind::Number,
            ease,
            loc: FileLoc::default(),
        }
    }

    fn keys(interpolation: Interpolation, ease: Ease) -> Motion {
        Motion::Keys {
            interpolation,
            keys: vec![key(0, 1.0, ease), key(40, 4.0, ease), key(80, 1.0, ease)],
        }
    }

    fn at(m: &Motion, t: f64) -> f64 {
        m.value_at(t, 100).x
    }

    #[test]
    fn linear_at_keys_between_and_outside() {
        let m = keys(Interpolation::Linear, Ease::None);
        assert_eq!(at(&m, 0.0), 1.0);
        assert_eq!(at(&m, 40.0), 4.0);
        assert_eq!(at(&m, 80.0), 1.0);
        // u = 10/40 = 0.25: 1 + 3·0.25 = 1.75; on the way down u = 0.5: 4 − 3·0.5 = 2.5.
        assert_eq!(at(&m, 10.0), 1.75);
        assert_eq!(at(&m, 60.0), 2.5);
        // Fractional time: u = 0.3125 → 1 + 3·0.3125 = 1.9375.
        assert_eq!(at(&m, 12.5), 1.9375);
        // Before the first key and after the last the end values hold.
        assert_eq!(at(&m, -3.0), 1.0);
        assert_eq!(at(&m, 99.0), 1.0);
    }

    #[test]
    fn eases_shape_the_segment() {
        // u = 0.25 on 1 → 4: in 1 + 3·0.0625 = 1.1875; out 1 + 3·0.4375 = 2.3125;
        // in-out 1 + 3·0.15625 = 1.46875.
        assert_eq!(at(&keys(Interpolation::Linear, Ease::In), 10.0), 1.1875);
        assert_eq!(at(&keys(Interpolation::Linear, Ease::Out), 10.0), 2.3125);
        assert_eq!(at(&keys(Interpolation::Linear, Ease::InOut), 10.0), 1.46875);
    }

    #[test]
    fn a_key_eases_only_the_segment_it_starts() {
        let m = Motion::Keys {
            interpolation: Interpolation::Linear,
            keys: vec![
                key(0, 1.0, Ease::None),
                key(40, 4.0, Ease::Out),
                key(80, 1.0, Ease::None),
            ],
        };
        assert_eq!(at(&m, 10.0), 1.75); // first segment: no ease
                                        // Second segment, u = 0.25, out: 4 − 3·0.4375 = 2.6875.
        assert_eq!(at(&m, 50.0), 2.6875);
    }

    #[test]
    fn step_holds_until_the_next_key() {
        let m = keys(Interpolation::Step, Ease::None);
        assert_eq!(at(&m, 39.0), 1.0);
        assert_eq!(at(&m, 39.999), 1.0);
        assert_eq!(at(&m, 40.0), 4.0);
        assert_eq!(at(&m, 79.5), 4.0);
        assert_eq!(at(&m, 80.0), 1.0);
    }

    #[test]
    fn smooth_passes_through_the_keys_and_is_the_catmull_rom_between() {
        let m = keys(Interpolation::Smooth, Ease::None);
        assert_eq!(at(&m, 0.0), 1.0);
        assert_eq!(at(&m, 40.0), 4.0);
        assert_eq!(at(&m, 80.0), 1.0);
        // Symmetric keys 1, 4, 1: the curve is symmetric about frame 40, and rises above
        // the straight line before the peak (it arrives with zero slope there).
        for d in [5.0, 17.0, 33.0] {
            assert!((at(&m, 40.0 - d) - at(&m, 40.0 + d)).abs() < 1e-12, "{d}");
        }
        assert!(at(&m, 30.0) > 1.0 + 3.0 * 0.75);
        // Two keys: the phantom ends make a straight line, so smooth is linear.
        let two = Motion::Keys {
            interpolation: Interpolation::Smooth,
            keys: vec![key(0, 0.0, Ease::None), key(10, 10.0, Ease::None)],
        };
        assert!((two.value_at(3.0, 10).x - 3.0).abs() < 1e-12);
    }

    #[test]
    fn a_single_key_holds_everywhere() {
        let m = Motion::Keys {
            interpolation: Interpolation::Linear,
            keys: vec![key(5, 2.0, Ease::None)],
        };
        assert_eq!(at(&m, 0.0), 2.0);
        assert_eq!(at(&m, 50.0), 2.0);
    }

    #[test]
    fn circles_follow_the_camera_formula() {
        let m = Motion::Circle(Circle {
            center: DVec3::new(1.0, 0.0, 2.0),
            radius: 8.0,
            height: 10.0,
            start_angle: 0.0,
            turns: 1.0,
        });
        // Frame 0: +z side; a quarter of 100 frames: +x side.
        assert!(m.value_at(0.0, 100).distance(DVec3::new(1.0, 10.0, 10.0)) < 1e-12);
        assert!(m.value_at(25.0, 100).distance(DVec3::new(9.0, 10.0, 2.0)) < 1e-12);
        // Half a frame further: θ = 360°·25.5/100 = 91.8°.
        let theta = 91.8f64.to_radians();
        let want = DVec3::new(1.0 + 8.0 * theta.sin(), 10.0, 2.0 + 8.0 * theta.cos());
        assert!(m.value_at(25.5, 100).distance(want) < 1e-12);
    }

    #[test]
    fn the_place_answerable_for_a_value() {
        let mut m = keys(Interpolation::Linear, Ease::None);
        if let Motion::Keys { keys, .. } = &mut m {
            for (i, k) in keys.iter_mut().enumerate() {
                k.loc.line = 10 + i;
            }
        }
        let track = FileLoc::default();
        assert_eq!(m.loc_at(-1.0, &track).line, 10);
        assert_eq!(m.loc_at(39.0, &track).line, 10);
        assert_eq!(m.loc_at(40.0, &track).line, 11);
        assert_eq!(m.loc_at(95.0, &track).line, 12);
    }
}
